//! [`System`]: a system over its exact field, loaded once, and the one `match` over the
//! ground fields of the crate ([`System::run`]).
//!
//! The field of a system is decided when it is read, from what the file says, never by
//! looking at its text: a file keeps parameters as symbols when it has a `symbols` key or a
//! parameter whose value is `null`, or when [`Options`] name them (`--symbolic`); `--at`
//! gives values first. Everything else is typed over $\mathbb{Q}$ or one quadratic field
//! $\mathbb{Q}(\sqrt d)$ by the ordinary reader ([`crate::io::load_system_str`]).
//!
//! Code that works on a system is written once, generic over `K: Field`, as a
//! [`SystemVisitor`]; a visitor that does something else over $\mathbb{Q}(p_1, \dots, p_k)$
//! (a result with `field` and `conditions`) overrides [`SystemVisitor::visit_symbolic`].
//!
//! # Examples
//! ```
//! use exactlti::api::{Options, System, SystemVisitor};
//! use exactlti::field::Field;
//! use exactlti::api::GroundField;
//! use exactlti::io::{SystemFile, SystemFormat, TypedSystem};
//!
//! struct Order;
//! impl SystemVisitor for Order {
//!     type Output = (usize, String);
//!     fn visit<K: GroundField>(self, _f: &SystemFile, t: &TypedSystem<K>) -> Self::Output {
//!         (t.ss.nstates(), t.ss.a.field().to_string())
//!     }
//! }
//! let text = r#"{"parameters": {"m": null}, "A": [[0, 1], ["-1/m", 0]], "B": [[0], [1]]}"#;
//! let sys = System::from_text(text, SystemFormat::Json, "x.json", &Options::default()).unwrap();
//! assert_eq!(sys.run(Order), (2, "QQ(m)".to_string()));
//! let at = Options::from_args(None, Some("m=2")).unwrap();
//! let sys = System::from_text(text, SystemFormat::Json, "x.json", &at).unwrap();
//! assert_eq!(sys.run(Order), (2, "QQ".to_string()));
//! ```

use crate::field::Field;
use crate::io::GroundField;
use crate::io::symbolic::{declares_symbols, load_symbolic_str};
use crate::io::{
    Ground, InputError, LoadedSystem, SystemFile, SystemFormat, TypedAny, TypedSystem,
    load_system_str,
};
use crate::ratfunc::RatFuncField;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// How a system is read: `--symbolic` (parameters kept as symbols) and `--at` (values given
/// before the computation), typed once for both front ends.
pub use crate::io::symbolic::SymbolicOptions as Options;

/// A system over its exact ground field, with its file (name, parameters, signal names).
#[derive(Clone, Debug)]
pub struct System {
    loaded: LoadedSystem,
    path: PathBuf,
    /// Read from the file at `path` (not from text or matrices).
    from_file: bool,
    /// The text it was read from, to read it again with other values ([`System::with_values`]).
    source: Option<Arc<Source>>,
}

/// The text of a system and how it was read.
#[derive(Debug)]
struct Source {
    text: String,
    format: SystemFormat,
    name: String,
    opts: Options,
}

/// Work on a system, written once for every ground field `K`.
pub trait SystemVisitor: Sized {
    type Output;
    /// Runs on the system over its concrete field.
    fn visit<K: GroundField>(self, file: &SystemFile, sys: &TypedSystem<K>) -> Self::Output;
    /// Runs on a system over $\mathbb{Q}(p_1, \dots, p_k)$ (default: as [`Self::visit`]).
    fn visit_symbolic(self, file: &SystemFile, sys: &TypedSystem<RatFuncField>) -> Self::Output {
        self.visit(file, sys)
    }
}

impl From<LoadedSystem> for System {
    fn from(loaded: LoadedSystem) -> Self {
        let path = PathBuf::from(&loaded.file.path);
        System {
            loaded,
            path,
            from_file: false,
            source: None,
        }
    }
}

impl System {
    /// Reads the file at `path` once (JSON, or TOML by its extension) with `opts`.
    ///
    /// # Errors
    /// An unreadable file and every error of [`System::from_text`], named by the path.
    pub fn open(path: &Path, opts: &Options) -> Result<Self, InputError> {
        Self::open_with(path, opts, false)
    }

    /// [`System::open`], where a file with only `D` is the static gain $y = D u$ (a system
    /// without states; `dcgain`, interconnections).
    ///
    /// # Errors
    /// As [`System::open`].
    pub fn open_or_gain(path: &Path, opts: &Options) -> Result<Self, InputError> {
        Self::open_with(path, opts, true)
    }

    fn open_with(path: &Path, opts: &Options, gain: bool) -> Result<Self, InputError> {
        let text = crate::io::read_text(path)?;
        let format = SystemFormat::of(path, &text);
        let name = path.display().to_string();
        let text = if gain {
            crate::io::combine::gain_text(&text, format, &name).unwrap_or(text)
        } else {
            text
        };
        let mut s = Self::from_text(&text, format, &name, opts)?;
        s.path = path.to_path_buf();
        s.from_file = true;
        Ok(s)
    }

    /// The same system read again from its text with values for parameters (`--at`, added
    /// to those it was read with; a value makes a symbol a number).
    ///
    /// # Errors
    /// A system given by its matrices (it has no text to read again); the readers' errors
    /// (an unknown name, a value that is not a number).
    pub fn with_values(&self, at: &[(String, String)]) -> Result<Self, InputError> {
        let Some(src) = &self.source else {
            return Err(InputError::file(
                &self.loaded.file.path,
                "a system given by its matrices has no parameters to give values",
            ));
        };
        let mut opts = src.opts.clone();
        for (n, v) in at {
            opts.at.retain(|(m, _)| m != n);
            opts.at.push((n.clone(), v.clone()));
            if let Some(list) = opts.symbolic.as_mut() {
                list.retain(|m| m != n);
            }
        }
        let mut s = Self::from_text(&src.text, src.format, &src.name, &opts)?;
        s.path = self.path.clone();
        s.from_file = self.from_file;
        Ok(s)
    }

    /// Reads a system from text (`name` is used in messages).
    ///
    /// # Errors
    /// Every error of the readers: a bad key, row, column or entry (named), an unknown name
    /// in `--symbolic` / `--at`, a singular mass matrix, a descriptor that is not regular.
    pub fn from_text(
        text: &str,
        format: SystemFormat,
        name: &str,
        opts: &Options,
    ) -> Result<Self, InputError> {
        let loaded = if opts.is_empty() && !declares_symbols(text, format, name) {
            load_system_str(text, format, name)?
        } else {
            load_symbolic_str(text, format, name, opts)?
        };
        let source = Source {
            text: text.to_string(),
            format,
            name: name.to_string(),
            opts: opts.clone(),
        };
        Ok(System {
            loaded,
            path: PathBuf::from(name),
            from_file: false,
            source: Some(Arc::new(source)),
        })
    }

    /// A system given by its matrices over their field (`name` is used in messages): no
    /// parameters, no signal names.
    pub fn from_typed(name: &str, system: TypedAny) -> Self {
        let ground = match &system {
            TypedAny::Rational(_) => Ground::Rational,
            TypedAny::Quadratic(t) => Ground::Quadratic(t.ss.a.field().clone()),
            TypedAny::RatFunc(t) => Ground::RatFunc(t.a_raw.field().clone()),
        };
        let file =
            SystemFile::without_matrices(name, ground, Default::default(), Default::default());
        System::from(LoadedSystem { file, system })
    }

    /// A system given by its matrices over any ground field of the crate ($\mathbb{Q}$,
    /// $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(p_1, \dots, p_k)$); `None` for another field.
    pub fn from_field<K: Field + 'static>(name: &str, system: TypedSystem<K>) -> Option<Self> {
        let b: Box<dyn std::any::Any> = Box::new(system);
        let any = match b.downcast::<TypedSystem<crate::field::Q>>() {
            Ok(t) => TypedAny::Rational(*t),
            Err(b) => match b.downcast::<TypedSystem<crate::field::QuadraticField>>() {
                Ok(t) => TypedAny::Quadratic(*t),
                Err(b) => TypedAny::RatFunc(*b.downcast::<TypedSystem<RatFuncField>>().ok()?),
            },
        };
        Some(Self::from_typed(name, any))
    }

    /// A system given by its matrices over a ground field of the crate (the field's own
    /// [`GroundField::into_any`]: no type probing).
    pub fn from_ground<K: GroundField>(name: &str, system: TypedSystem<K>) -> Self {
        Self::from_typed(name, K::into_any(system))
    }

    /// The built-in example of `analyze` without a file (sliding masses).
    ///
    /// # Errors
    /// An unknown name in `opts`.
    pub fn builtin(opts: &Options) -> Result<Self, InputError> {
        Self::from_text(
            super::BUILTIN_EXAMPLE,
            SystemFormat::Json,
            "built-in:sliding-masses.json",
            opts,
        )
    }

    /// Runs `v` over the system's concrete ground field: the one dispatch point from a
    /// system's field to generic code.
    pub fn run<V: SystemVisitor>(&self, v: V) -> V::Output {
        let f = &self.loaded.file;
        match &self.loaded.system {
            TypedAny::Rational(t) => v.visit(f, t),
            TypedAny::Quadratic(t) => v.visit(f, t),
            TypedAny::RatFunc(t) => v.visit_symbolic(f, t),
        }
    }

    /// The file as read (name, parameters, signal names, ground field).
    pub fn file(&self) -> &SystemFile {
        &self.loaded.file
    }
    /// The path (or name) the system was read from.
    pub fn path(&self) -> &Path {
        &self.path
    }
    /// Whether the system was read from the file at [`System::path`].
    pub fn from_file(&self) -> bool {
        self.from_file
    }
    /// The ground field.
    pub fn ground(&self) -> &Ground {
        &self.loaded.file.ground
    }
    /// The loaded system (typed over its field).
    pub fn loaded(&self) -> &LoadedSystem {
        &self.loaded
    }
    /// The sample time of a discrete-time system (file key `dt`); `None`: continuous.
    pub fn dt(&self) -> Option<&crate::field::Rational> {
        self.loaded.file.signals.dt.as_ref()
    }
    /// Number of states of the system as typed.
    pub fn nstates(&self) -> usize {
        match &self.loaded.system {
            TypedAny::Rational(t) => t.ss.nstates(),
            TypedAny::Quadratic(t) => t.ss.nstates(),
            TypedAny::RatFunc(t) => t.ss.nstates(),
        }
    }
    /// The same system with other signal names and sample time (`states` names are kept
    /// only when their count fits).
    pub fn with_signals(mut self, signals: crate::io::SignalNames) -> Self {
        self.loaded.file.signals = signals;
        self
    }
}
