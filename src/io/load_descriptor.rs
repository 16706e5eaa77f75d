//! Loading for the descriptor-level commands (`pencil`, `ctrb`, `obsv`, `tf`,
//! `minreal --descriptor`, `zeros` with `E`): a system file as a descriptor system, improper
//! or not (the standard-form typing of [`super::load`] refuses improper ones), or a transfer
//! matrix given under the key `G` (rational functions in `s` over $\mathbb{Q}$, parameters
//! allowed), realized exactly and minimally.
//!
//! | entry point | does |
//! |---|---|
//! | [`load_descriptor_path`] | a file → [`LoadedDescriptor`] |
//! | [`LoadedDescriptor::run`] | calls a [`DescriptorVisitor`] over the concrete field |

use super::transfer_key::realize_g;
use super::{FromScalars, Ground, InputError, SystemFile};
use crate::field::{Q, QuadraticField};
use crate::matrix::Matrix;
use crate::realization::{Realize, TransferRealization};
use crate::system::Descriptor;
use crate::system::transfer::TransferMatrix;
use std::path::Path;

/// A descriptor system over one of the ground fields.
#[derive(Clone, Debug)]
#[non_exhaustive]
pub enum DescriptorAny {
    Rational(Descriptor<Q>),
    Quadratic(Descriptor<QuadraticField>),
}

/// A loaded descriptor system; `transfer` when the file gave `G`.
#[derive(Clone, Debug)]
pub struct LoadedDescriptor {
    pub path: String,
    pub system: DescriptorAny,
    /// Whether the file gave `E` (a descriptor system) rather than $E = I$.
    pub has_e: bool,
    /// The transfer matrix and its minimal realization, for a `G` file.
    pub transfer: Option<GivenTransfer<Q>>,
    /// A rectangular pencil `(A, E)` (a file with only `A`, `E` and a non-square `A`, over
    /// $\mathbb{Q}$): only `pencil` accepts it; `system` is then empty.
    pub pencil: Option<(Matrix<Q>, Matrix<Q>)>,
    /// The channel names the file gives (a model file: its actuators and sensors).
    pub signals: super::SignalNames,
}

/// A file's transfer matrix `G` and its minimal realization (over the file's field).
pub type GivenTransfer<K> = (TransferMatrix<K>, TransferRealization<K>);

/// Work on a loaded descriptor system, generic over the field; `transfer`: the file's `G`
/// and its realization, typed over the system's field (a `G` file is read over
/// $\mathbb{Q}$).
pub trait DescriptorVisitor {
    type Output;
    fn visit<K: super::GroundField>(
        self,
        loaded: &LoadedDescriptor,
        sys: &Descriptor<K>,
        transfer: Option<&GivenTransfer<K>>,
    ) -> Self::Output;
}

impl LoadedDescriptor {
    pub fn run<V: DescriptorVisitor>(&self, v: V) -> V::Output {
        match &self.system {
            DescriptorAny::Rational(s) => v.visit(self, s, self.transfer.as_ref()),
            DescriptorAny::Quadratic(s) => v.visit(self, s, None),
        }
    }
}

fn descriptor_of<K: FromScalars>(f: &SystemFile, k: &K) -> Result<Descriptor<K>, InputError> {
    let fail = |e: crate::Error| InputError::file(&f.path, e.to_string());
    let get = |m: &Option<super::MatrixEntries>| m.as_ref().map(|m| k.matrix_from_entries(m));
    if let (Some(a), Some(b), Some(c), Some(d)) = (get(&f.a), get(&f.b), get(&f.c), get(&f.d)) {
        let e = get(&f.e).unwrap_or_else(|| Matrix::identity(k.clone(), a.nrows()));
        return Descriptor::new(e, a, b, c, d).map_err(fail);
    }
    let (m, l, kk, ff) = (get(&f.m), get(&f.l), get(&f.k), get(&f.f));
    let (Some(m), Some(l), Some(kk), Some(ff)) = (m, l, kk, ff) else {
        return Err(InputError::file(
            &f.path,
            "the file gives neither A nor M, L, K, F",
        ));
    };
    let ss = crate::system::StateSpace::from_second_order(
        &m,
        &l,
        &kk,
        &ff,
        get(&f.c).as_ref(),
        get(&f.d).as_ref(),
    )
    .map_err(fail)?;
    let n = ss.nstates();
    Descriptor::new(Matrix::identity(k.clone(), n), ss.a, ss.b, ss.c, ss.d).map_err(fail)
}

/// Reads a system file or a `G` file as a descriptor system.
///
/// # Errors
/// An unreadable or invalid file (one line naming file, key, row and column), a `G` entry
/// that does not parse, a transfer matrix that cannot be realized.
pub fn load_descriptor_path(path: &Path) -> Result<LoadedDescriptor, InputError> {
    let name = path.display().to_string();
    let text = super::read_text(path)?;
    let raw = super::raw::from_text(&text, super::read::SystemFormat::of(path, &text), &name)?;
    if let super::raw::Raw::Table(entries) = &raw
        && entries.iter().any(|(k, _)| k == "bodies")
    {
        let format = super::read::SystemFormat::of(path, &text);
        return model_descriptor(&text, format, &name);
    }
    if let super::raw::Raw::Table(entries) = &raw {
        super::keys::check_keys(&name, &super::keys::keys_of(entries))?;
    }
    if let super::raw::Raw::Table(entries) = &raw {
        if let Some((_, g)) = entries.iter().find(|(k, _)| k == "G") {
            let format = super::read::SystemFormat::of(path, &text);
            if super::symbolic::declares_symbols(&text, format, &name) {
                // G over Q(p) is the symbolic reader's: its error names the entry
                let opts = super::symbolic::SymbolicOptions::default();
                return Err(
                    match super::symbolic::load_symbolic_str(&text, format, &name, &opts) {
                        Err(e) => e,
                        Ok(_) => InputError::file(
                            &name,
                            "this command reads G over Q only: give the symbols values (--at)",
                        ),
                    },
                );
            }
            let params = entries.iter().find(|(k, _)| k == "parameters");
            let params = params.map(|(_, p)| p.to_json());
            // inputs, outputs and the sample time of G (a G file names no states); with a
            // sample time G is written in z
            let signals = super::keys::SignalNames {
                states: None,
                ..super::keys::SignalNames::read(&name, entries)?
            };
            let var = if signals.dt.is_some() { "z" } else { "s" };
            let mut loaded =
                if super::transfer_key::realize_mode(&name, entries)? == Realize::AsWritten {
                    load_g_as_written(&name, &g.to_json(), params.as_ref(), var)?
                } else {
                    load_g(&name, &g.to_json(), params.as_ref(), var)?
                };
            loaded.signals = signals;
            return Ok(loaded);
        }
        if let Some(l) = rectangular_pencil(&name, entries)? {
            return Ok(l);
        }
    }
    let f = super::system_file::validate(raw, &name)?;
    let has_e = f.e.is_some();
    let system = match &f.ground {
        Ground::Rational => DescriptorAny::Rational(descriptor_of(&f, &Q)?),
        Ground::Quadratic(k) => DescriptorAny::Quadratic(descriptor_of(&f, k)?),
        Ground::RatFunc(k) => {
            return Err(InputError::file(&name, super::refusal("this command", k)));
        }
    };
    Ok(LoadedDescriptor {
        path: name,
        system,
        has_e,
        transfer: None,
        pencil: None,
        signals: f.signals.clone(),
    })
}

/// A file with only `A` (non-square) and optionally `E`: a rectangular pencil. Its
/// matrices are read by the same reader as every system file's (arrays of rows or
/// MATLAB-style strings, entries over `parameters`).
fn rectangular_pencil(
    name: &str,
    entries: &[(String, super::raw::Raw)],
) -> Result<Option<LoadedDescriptor>, InputError> {
    let has = |k: &str| entries.iter().any(|(n, _)| n == k);
    if !has("A") || ["B", "C", "D", "M", "L", "K", "F"].iter().any(|k| has(k)) {
        return Ok(None);
    }
    let (ms, _) = super::system_file::matrices_of_table(name, entries, &["A", "E"])?;
    let [Some(a), e] = <[Option<super::MatrixEntries>; 2]>::try_from(ms).expect("two keys") else {
        return Ok(None);
    };
    if a.nrows == a.ncols {
        return Ok(None);
    }
    let Some(e) = e else {
        return Err(InputError::key(
            name,
            "E",
            "a non-square A needs E of the same shape",
        ));
    };
    if (e.nrows, e.ncols) != (a.nrows, a.ncols) {
        return Err(InputError::key(
            name,
            "E",
            format!("must be {}x{} like A", a.nrows, a.ncols),
        ));
    }
    let rational = |key: &str, m: &super::MatrixEntries| match m.to_rational_rows() {
        Some(_) => Ok(Q.matrix_from_entries(m)),
        None => Err(InputError::key(
            name,
            key,
            "a rectangular pencil must have rational entries",
        )),
    };
    let (a, e) = (rational("A", &a)?, rational("E", &e)?);
    let z = |r, c| Matrix::zeros(Q, r, c);
    Ok(Some(LoadedDescriptor {
        path: name.to_string(),
        system: DescriptorAny::Rational(
            Descriptor::new(z(0, 0), z(0, 0), z(0, 0), z(0, 0), z(0, 0)).expect("empty system"),
        ),
        has_e: true,
        transfer: None,
        pencil: Some((a, e)),
        signals: Default::default(),
    }))
}

fn load_g(
    name: &str,
    g: &serde_json::Value,
    params: Option<&serde_json::Value>,
    var: &str,
) -> Result<LoadedDescriptor, InputError> {
    let (tm, r) = realize_g(name, g, params, var)?;
    let has_e = r.minimal.infinite_order > 0;
    Ok(LoadedDescriptor {
        path: name.to_string(),
        system: DescriptorAny::Rational(r.minimal.system.clone()),
        has_e,
        transfer: Some((tm, r)),
        pencil: None,
        signals: Default::default(),
    })
}

/// A `G` file with `realize = "as_written"`: the realization keeping every written
/// denominator, as a standard system ($E = I$).
fn load_g_as_written(
    name: &str,
    g: &serde_json::Value,
    params: Option<&serde_json::Value>,
    var: &str,
) -> Result<LoadedDescriptor, InputError> {
    let ss = super::transfer_key::realize_g_as_written(name, g, params, var)?;
    let n = ss.nstates();
    let system = Descriptor::new(Matrix::identity(Q, n), ss.a, ss.b, ss.c, ss.d)
        .map_err(|e| InputError::file(name, e.to_string()))?;
    Ok(LoadedDescriptor {
        path: name.to_string(),
        system: DescriptorAny::Rational(system),
        has_e: false,
        transfer: None,
        pencil: None,
        signals: Default::default(),
    })
}

/// A model file as a descriptor system over $\mathbb{Q}$ (for the descriptor-level
/// commands).
///
/// # Errors
/// As [`super::load::load_model_str`]; a model with symbols (these commands refuse $\mathbb{Q}(p)$).
pub fn model_descriptor(
    text: &str,
    format: super::read::SystemFormat,
    name: &str,
) -> Result<LoadedDescriptor, InputError> {
    match super::model_file::read_model_str(text, format, name, &Default::default())? {
        super::model_file::ModelAny::Rational(m) => {
            let a = crate::multibody::assemble(&m)
                .map_err(|e| InputError::file(name, e.to_string()))?;
            Ok(LoadedDescriptor {
                path: name.to_string(),
                system: DescriptorAny::Rational(a.descriptor),
                has_e: true,
                transfer: None,
                pencil: None,
                signals: super::SignalNames {
                    inputs: Some(a.input_names),
                    outputs: Some(a.output_names),
                    states: Some(a.state_names),
                    dt: None,
                },
            })
        }
        super::model_file::ModelAny::RatFunc(m) => Err(InputError::file(
            name,
            super::refusal("this command", &m.field),
        )),
    }
}
