//! Typed loading of a system file over the public `exactlti::io` reader.
//!
//! The library's command line keeps its own copy private; this mirrors it (same steps, same
//! messages: `NAME: <library error>`), so a system built from Python is typed exactly as the
//! same data in a file given to the command line.

use exactlti::Error;
use exactlti::field::{Field, Q, QuadraticField};
use exactlti::io::{Ground, MatrixEntries, SystemFile};
use exactlti::matrix::Matrix;
use exactlti::realization::descriptor_to_standard;
use exactlti::system::{Descriptor, StateSpace};

/// A system over its ground field, as given and in standard form.
#[derive(Clone, Debug)]
pub struct Typed<K: Field> {
    /// The descriptor system when `E` was given.
    pub descriptor: Option<Descriptor<K>>,
    /// `A` as given (of the first-order form built from second-order keys).
    pub a_raw: Matrix<K>,
    /// Standard state-space form.
    pub ss: StateSpace<K>,
}

/// A typed system over one of the supported ground fields.
pub enum Loaded {
    Q(SystemFile, Typed<Q>),
    Quadratic(SystemFile, Typed<QuadraticField>),
}

fn typed<K: Field>(
    f: &SystemFile,
    conv: impl Fn(&MatrixEntries) -> Matrix<K>,
) -> Result<Typed<K>, String> {
    let fail = |e: Error| format!("{}: {e}", f.path);
    let get = |m: &Option<MatrixEntries>| m.as_ref().map(&conv);
    let missing = |k: &str| format!("{}: key {k}: missing", f.path);
    if let Some(a) = get(&f.a) {
        let b = get(&f.b).ok_or_else(|| missing("B"))?;
        let c = get(&f.c).ok_or_else(|| missing("C"))?;
        let d = get(&f.d).ok_or_else(|| missing("D"))?;
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
    let (Some(m), Some(l), Some(k), Some(ff)) = (get(&f.m), get(&f.l), get(&f.k), get(&f.f))
    else {
        return Err(format!(
            "{}: the file gives neither A nor the second-order keys M, L, K, F",
            f.path
        ));
    };
    let ss = StateSpace::from_second_order(&m, &l, &k, &ff, get(&f.c).as_ref(), get(&f.d).as_ref())
        .map_err(|e| match e {
            Error::Singular => format!("{}: key M: the mass matrix is singular", f.path),
            e => fail(e),
        })?;
    Ok(Typed {
        a_raw: ss.a.clone(),
        descriptor: None,
        ss,
    })
}

/// Types a validated file over its ground field.
pub fn type_file(f: SystemFile) -> Result<Loaded, String> {
    match f.ground.clone() {
        Ground::Rational => {
            let t = typed(&f, |m| {
                Matrix::from_vec(Q, m.nrows, m.ncols, m.data.iter().map(|x| x.a.clone()).collect())
            })?;
            Ok(Loaded::Q(f, t))
        }
        Ground::Quadratic(k) => {
            let t = typed(&f, |m| {
                Matrix::from_vec(
                    k.clone(),
                    m.nrows,
                    m.ncols,
                    m.data.iter().map(|x| x.to_quadratic()).collect(),
                )
            })?;
            Ok(Loaded::Quadratic(f, t))
        }
    }
}
