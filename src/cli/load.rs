//! From a validated [`SystemFile`] to typed systems over its ground field.

use super::Failure;
use crate::field::{Field, Q, QuadraticField};
use crate::io::{Ground, MatrixEntries, SystemFile, parse_system_json, read_system_file};
use crate::matrix::Matrix;
use crate::realization::descriptor_to_standard;
use crate::system::{Descriptor, StateSpace};
use std::path::Path;

/// A system over its ground field, as given and (when possible) in standard form.
#[derive(Clone, Debug)]
pub struct Typed<K: Field> {
    /// `E` when the file gives a descriptor system.
    pub descriptor: Option<Descriptor<K>>,
    /// The matrix `A` as the file gives it (of the first-order form built from the
    /// second-order keys when there is no `A`).
    pub a_raw: Matrix<K>,
    /// The standard state-space form (from `A`..`D`, the second-order keys, or the
    /// descriptor converted by [`descriptor_to_standard`]).
    pub ss: StateSpace<K>,
}

/// A loaded system file.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)]
pub enum Loaded {
    Q(SystemFile, Typed<Q>),
    Quadratic(SystemFile, Typed<QuadraticField>),
}

impl Loaded {
    pub fn file(&self) -> &SystemFile {
        match self {
            Loaded::Q(f, _) | Loaded::Quadratic(f, _) => f,
        }
    }
    /// The rational system, or a clear refusal naming the field.
    ///
    /// # Errors
    /// Exit 2 with a message when the file is over Q(sqrt d).
    pub fn rational(&self, what: &str) -> Result<&Typed<Q>, Failure> {
        match self {
            Loaded::Q(_, t) => Ok(t),
            Loaded::Quadratic(f, _) => Err(Failure {
                code: 2,
                message: format!(
                    "{}: {what} needs rational matrices; this file's entries lie in {}",
                    f.path, f.ground
                ),
            }),
        }
    }
}

fn entries_q(m: &MatrixEntries) -> Matrix<Q> {
    Matrix::from_vec(
        Q,
        m.nrows,
        m.ncols,
        m.data.iter().map(|x| x.a.clone()).collect(),
    )
}

fn entries_k(k: &QuadraticField, m: &MatrixEntries) -> Matrix<QuadraticField> {
    Matrix::from_vec(
        k.clone(),
        m.nrows,
        m.ncols,
        m.data.iter().map(|x| x.to_quadratic()).collect(),
    )
}

fn typed<K: Field>(
    f: &SystemFile,
    conv: impl Fn(&MatrixEntries) -> Matrix<K>,
) -> Result<Typed<K>, Failure> {
    let fail = |e: crate::error::Error| Failure {
        code: 2,
        message: format!("{}: {e}", f.path),
    };
    let get = |m: &Option<MatrixEntries>| m.as_ref().map(&conv);
    if let Some(a) = get(&f.a) {
        let b = get(&f.b).expect("validated");
        let c = get(&f.c).expect("validated");
        let d = get(&f.d).expect("validated");
        if let Some(e) = get(&f.e) {
            let desc = Descriptor::new(e, a, b, c, d).map_err(fail)?;
            let sf = descriptor_to_standard(&desc).map_err(fail)?;
            return Ok(Typed {
                a_raw: desc.a.clone(),
                descriptor: Some(desc),
                ss: sf.system,
            });
        }
        let ss = StateSpace::new(a, b, c, d).map_err(fail)?;
        return Ok(Typed {
            a_raw: ss.a.clone(),
            descriptor: None,
            ss,
        });
    }
    let (m, l, k, ff) = (get(&f.m), get(&f.l), get(&f.k), get(&f.f));
    let (Some(m), Some(l), Some(k), Some(ff)) = (m, l, k, ff) else {
        return Err(Failure {
            code: 2,
            message: format!(
                "{}: the file gives neither A nor the second-order keys M, L, K, F",
                f.path
            ),
        });
    };
    let ss = StateSpace::from_second_order(&m, &l, &k, &ff, get(&f.c).as_ref(), get(&f.d).as_ref())
        .map_err(|e| match e {
            crate::error::Error::Singular => Failure {
                code: 2,
                message: format!("{}: key M: the mass matrix is singular", f.path),
            },
            e => fail(e),
        })?;
    Ok(Typed {
        a_raw: ss.a.clone(),
        descriptor: None,
        ss,
    })
}

/// Types a JSON system given as text (for built-in examples).
///
/// # Errors
/// Exit 2 with the reader's message.
pub fn load_text(text: &str, name: &str) -> Result<Loaded, Failure> {
    type_file(parse_system_json(text, name)?)
}

/// Reads and types a system file.
///
/// # Errors
/// Exit 2 with the reader's one-line message.
pub fn load_system(path: &Path) -> Result<Loaded, Failure> {
    type_file(read_system_file(path)?)
}

fn type_file(f: SystemFile) -> Result<Loaded, Failure> {
    match f.ground.clone() {
        Ground::Rational => {
            let t = typed(&f, entries_q)?;
            Ok(Loaded::Q(f, t))
        }
        Ground::Quadratic(k) => {
            let t = typed(&f, |m| entries_k(&k, m))?;
            Ok(Loaded::Quadratic(f, t))
        }
    }
}
