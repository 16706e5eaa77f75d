//! System file → typed system over the file's ground field, for library users and the CLI.
//!
//! | entry point | does |
//! |---|---|
//! | [`load_system_str`] | text (JSON or TOML, see [`SystemFormat`]) → [`LoadedSystem`] |
//! | [`load_system_path`] | a file (format from the extension) → [`LoadedSystem`] |
//!
//! Code that works on a loaded system is written once, generic over `K: Field`, as a
//! `crate::api::SystemVisitor`, and dispatched by `crate::api::System::run`, the one `match`
//! over the ground fields outside this file's typing step ([`type_file`]). Adding a ground
//! field means: a new [`Ground`] variant from the reader, a variant of [`TypedAny`], one arm
//! in `type_file` and one in `api::System::run`.
//!
//! Every failure is an [`InputError`]: one line naming the file (and key, row, column when
//! they apply); the command line prints it and exits with status 2.
//!
//! # Examples
//! ```
//! use exactlti::io::{SystemFormat, load_system_str};
//!
//! let text = "A = [[0, 1], [-2, -0.5]]\nB = [[0], [1]]\nC = [[1, 0]]\nD = [[0]]\n";
//! let sys = load_system_str(text, SystemFormat::Toml, "two.toml").unwrap();
//! assert_eq!(sys.rational().unwrap().ss.a.get(1, 1).to_string(), "-1/2");
//!
//! let e = load_system_str(r#"{"A": [[1, "k"]]}"#, SystemFormat::Json, "x.json").unwrap_err();
//! assert_eq!(e.to_string(), "x.json: key A, row 1, column 2: unknown parameter 'k'");
//! ```

use super::keys::SignalNames;
use super::subst::SymbolicOptions;
use super::{
    Ground, InputError, MatrixEntries, SystemFile, parse_system_json, parse_system_toml,
    read_system_file,
};
use crate::error::Error;
use crate::field::{Field, Q, QuadraticField};
use crate::matrix::Matrix;
use crate::multibody::{Assembly, Model, assemble};
use crate::ratfunc::RatFuncField;
use crate::realization::descriptor_to_standard;
use crate::system::{Descriptor, StateSpace};
use std::any::Any;
use std::path::Path;

pub use super::read::SystemFormat;

/// A system over its ground field `K`, as given and (when possible) in standard form.
#[derive(Clone, Debug)]
pub struct TypedSystem<K: Field> {
    /// The descriptor system `E x' = A x + B u` when the file gives `E`.
    pub descriptor: Option<Descriptor<K>>,
    /// The matrix `A` as the file gives it (of the first-order form built from the
    /// second-order keys when there is no `A`).
    pub a_raw: Matrix<K>,
    /// The standard state-space form (from `A`..`D`, the second-order keys, or the
    /// descriptor converted by [`descriptor_to_standard`]).
    pub ss: StateSpace<K>,
}

impl<K: Field> TypedSystem<K> {
    /// The same system with its matrices carried by the field value `k` (entries cloned):
    /// over Q(p), a field with a fresh condition log.
    pub fn in_field(&self, k: &K) -> Self {
        self.map(k, &|e| e.clone())
    }

    /// The same system over the field `l`, every entry carried by `f`.
    pub fn map<L: Field>(&self, l: &L, f: &dyn Fn(&K::Elem) -> L::Elem) -> TypedSystem<L> {
        let m = |x: &Matrix<K>| x.map(l, f);
        TypedSystem {
            descriptor: self.descriptor.as_ref().map(|d| Descriptor {
                e: m(&d.e),
                a: m(&d.a),
                b: m(&d.b),
                c: m(&d.c),
                d: m(&d.d),
            }),
            a_raw: m(&self.a_raw),
            ss: StateSpace {
                a: m(&self.ss.a),
                b: m(&self.ss.b),
                c: m(&self.ss.c),
                d: m(&self.ss.d),
            },
        }
    }
}

/// A typed system over one of the supported ground fields.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)]
#[non_exhaustive]
pub enum TypedAny {
    /// Every entry rational.
    Rational(TypedSystem<Q>),
    /// Entries in one quadratic field $\mathbb{Q}(\sqrt d)$.
    Quadratic(TypedSystem<QuadraticField>),
    /// Entries in $\mathbb{Q}(p_1, \dots, p_k)$ (symbolic parameters).
    RatFunc(TypedSystem<RatFuncField>),
}

/// A validated system file together with its typed system.
#[derive(Clone, Debug)]
pub struct LoadedSystem {
    /// The validated file (parameters, entries as exact scalars, ground field, name, path).
    pub file: SystemFile,
    /// The typed system over the file's ground field.
    pub system: TypedAny,
}

impl LoadedSystem {
    /// The system over $\mathbb{Q}$, or `None` when the file's field is larger.
    pub fn rational(&self) -> Option<&TypedSystem<Q>> {
        match &self.system {
            TypedAny::Rational(t) => Some(t),
            _ => None,
        }
    }
    /// The file's ground field.
    pub fn ground(&self) -> &Ground {
        &self.file.ground
    }
}

/// The same system seen over $\mathbb{Q}$ when `K` is [`Q`] (a type test, no conversion).
pub fn as_rational<K: Field + 'static>(sys: &TypedSystem<K>) -> Option<&TypedSystem<Q>> {
    (sys as &dyn Any).downcast_ref::<TypedSystem<Q>>()
}

/// Loads a system from text in the given format; `name` is only used in messages.
///
/// # Errors
/// Every error of the reader ([`parse_system_json`], [`parse_system_toml`]) and of typing:
/// a singular mass matrix, a descriptor system that is not regular or not proper, a file
/// with neither `A` nor `M`, `L`, `K`, `F`.
pub fn load_system_str(
    text: &str,
    format: SystemFormat,
    name: &str,
) -> Result<LoadedSystem, InputError> {
    if super::model_file::is_model_text(text, format) {
        return load_model_str(text, format, name, &Default::default());
    }
    let file = match format {
        SystemFormat::Json => parse_system_json(text, name)?,
        SystemFormat::Toml => parse_system_toml(text, name)?,
    };
    type_file(file)
}

/// Reads and loads a system file (`.toml` as TOML, `.json` or text starting with `{` as
/// JSON).
///
/// # Errors
/// An unreadable file, and every error of [`load_system_str`].
pub fn load_system_path(path: &Path) -> Result<LoadedSystem, InputError> {
    // a model file (top-level `bodies`) is assembled into its descriptor system
    if let Ok(text) = super::read_text(path) {
        let format = SystemFormat::of(path, &text);
        if super::model_file::is_model_text(&text, format) {
            let shown = path.display().to_string();
            return load_model_str(&text, format, &shown, &Default::default());
        }
    }
    type_file(read_system_file(path)?)
}

/// Types a validated file over its ground field.
///
/// # Errors
/// As [`load_system_str`] after parsing.
pub fn type_file(file: SystemFile) -> Result<LoadedSystem, InputError> {
    let system = match &file.ground {
        Ground::Rational => TypedAny::Rational(typed(&file, &Q)?),
        Ground::Quadratic(k) => TypedAny::Quadratic(typed(&file, k)?),
        Ground::RatFunc(k) => TypedAny::RatFunc(typed(&file, k)?),
    };
    Ok(LoadedSystem { file, system })
}

/// Converts exact scalars into elements of a ground field.
pub trait FromScalars: Field {
    /// The matrix with the same entries over `self`.
    fn matrix_from_entries(&self, m: &MatrixEntries) -> Matrix<Self>;
}

impl FromScalars for Q {
    fn matrix_from_entries(&self, m: &MatrixEntries) -> Matrix<Q> {
        Matrix::from_vec(
            Q,
            m.nrows,
            m.ncols,
            m.data.iter().map(|x| x.a.clone()).collect(),
        )
    }
}

impl FromScalars for QuadraticField {
    fn matrix_from_entries(&self, m: &MatrixEntries) -> Matrix<QuadraticField> {
        Matrix::from_vec(
            self.clone(),
            m.nrows,
            m.ncols,
            m.data.iter().map(|x| x.to_quadratic()).collect(),
        )
    }
}

impl FromScalars for RatFuncField {
    fn matrix_from_entries(&self, m: &MatrixEntries) -> Matrix<RatFuncField> {
        Matrix::from_vec(
            self.clone(),
            m.nrows,
            m.ncols,
            m.data.iter().map(|x| self.from_rational(&x.a)).collect(),
        )
    }
}

fn typed<K: FromScalars>(f: &SystemFile, k: &K) -> Result<TypedSystem<K>, InputError> {
    let get = |key: &str| {
        let m = match key {
            "A" => &f.a,
            "B" => &f.b,
            "C" => &f.c,
            "D" => &f.d,
            "E" => &f.e,
            "M" => &f.m,
            "L" => &f.l,
            "K" => &f.k,
            _ => &f.f,
        };
        m.as_ref().map(|m| k.matrix_from_entries(m))
    };
    typed_from(&f.path, &get)
}

/// Builds the typed system from the matrices by key (`A`..`E`, `M`, `L`, `K`, `F`).
pub(crate) fn typed_from<K: Field>(
    path: &str,
    get: &dyn Fn(&str) -> Option<Matrix<K>>,
) -> Result<TypedSystem<K>, InputError> {
    let fail = |e: Error| InputError::file(path, e.to_string());
    let missing = |key: &str| InputError::key(path, key, "missing");
    if let Some(a) = get("A") {
        let b = get("B").ok_or_else(|| missing("B"))?;
        let c = get("C").ok_or_else(|| missing("C"))?;
        let d = get("D").ok_or_else(|| missing("D"))?;
        if let Some(e) = get("E") {
            let desc = Descriptor::new(e, a, b, c, d).map_err(fail)?;
            let sf = descriptor_to_standard(&desc).map_err(fail)?;
            return Ok(TypedSystem {
                a_raw: desc.a.clone(),
                descriptor: Some(desc),
                ss: sf.system,
            });
        }
        let ss = StateSpace::new(a, b, c, d).map_err(fail)?;
        return Ok(TypedSystem {
            a_raw: ss.a.clone(),
            descriptor: None,
            ss,
        });
    }
    let (m, l, kk, ff) = (get("M"), get("L"), get("K"), get("F"));
    let (Some(m), Some(l), Some(kk), Some(ff)) = (m, l, kk, ff) else {
        return Err(InputError::file(
            path,
            "the file gives neither A nor the second-order keys M, L, K, F",
        ));
    };
    let ss = StateSpace::from_second_order(&m, &l, &kk, &ff, get("C").as_ref(), get("D").as_ref())
        .map_err(|e| match e {
            Error::Singular => InputError::key(path, "M", "the mass matrix is singular"),
            e => fail(e),
        })?;
    Ok(TypedSystem {
        a_raw: ss.a.clone(),
        descriptor: None,
        ss,
    })
}

/// Reads, assembles and types a model file: the descriptor system of the model, in
/// standard form as every system file.
///
/// # Errors
/// Every error of [`super::model_file::read_model_str`]; an assembly that fails (a zero axis, an irrational
/// actuator length, loads without equilibrium), named by the file.
pub fn load_model_str(
    text: &str,
    format: SystemFormat,
    name: &str,
    opts: &SymbolicOptions,
) -> Result<LoadedSystem, InputError> {
    match super::model_file::read_model_str(text, format, name, opts)? {
        super::model_file::ModelAny::Rational(m) => {
            loaded(name, &m, Ground::Rational, TypedAny::Rational)
        }
        super::model_file::ModelAny::RatFunc(m) => {
            let g = Ground::RatFunc(m.field.clone());
            loaded(name, &m, g, TypedAny::RatFunc)
        }
    }
}

fn loaded<K: Field>(
    name: &str,
    m: &Model<K>,
    ground: Ground,
    wrap: impl Fn(TypedSystem<K>) -> TypedAny,
) -> Result<LoadedSystem, InputError> {
    let a: Assembly<K> = assemble(m).map_err(|e| InputError::file(name, e.to_string()))?;
    let d = a.descriptor.clone();
    let sf = descriptor_to_standard(&d).map_err(|e| InputError::file(name, e.to_string()))?;
    let states = sf
        .states
        .as_ref()
        .map(|st| st.iter().map(|&i| a.state_names[i].clone()).collect());
    let typed = TypedSystem {
        a_raw: d.a.clone(),
        descriptor: Some(d),
        ss: sf.system,
    };
    let signals = SignalNames {
        inputs: Some(a.input_names.clone()),
        outputs: Some(a.output_names.clone()),
        states,
    };
    let mut extra = serde_json::Map::new();
    extra.insert("descriptor_states".into(), a.state_names.clone().into());
    let mut file = SystemFile::without_matrices(name, ground, extra, signals);
    file.name = m.name.clone();
    Ok(LoadedSystem {
        file,
        system: wrap(typed),
    })
}
