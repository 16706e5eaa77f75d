//! Interconnection of LTI systems, exactly, with python-control's conventions.
//!
//! Every operation is written once, generic over the field `K` and over the kind of system
//! ([`Blocks`]: standard $(A, B, C, D)$ or descriptor $(E, A, B, C, D)$): the result's
//! matrices are block matrices of the parts' matrices, with $E = \mathrm{diag}(E_1, E_2)$
//! when either part is a descriptor system. Nothing is rounded and no state is dropped; the
//! exact minimal realization of the result is [`crate::realization::minimal`].
//!
//! | entry point | signal flow | transfer matrix computed |
//! |---|---|---|
//! | [`series`]`(g1, g2)` | $u \to G_1 \to G_2 \to y$ | $G_2 G_1$ (python-control `series(G1, G2) = G2 * G1`) |
//! | [`parallel`]`(g1, g2)` | same input, outputs added | $G_1 + G_2$ |
//! | [`feedback`]`(g, k, sign)` | $u = r + \sigma K y$, $\sigma = -1$ (default) or $+1$ | $(I - \sigma G K)^{-1} G$ |
//! | [`append`]`(systems)` | side by side | $\mathrm{diag}(G_1, G_2, \dots)$ |
//! | [`connect::close`]`(g, routing)` | $u = K y + E r$, $z = F y$ (signal names, made into 0/1 matrices by the caller) | $F (I - G K)^{-1} G E$ |
//! | [`static_gain`]`(K)` | no states, $y = K u$ | $K$ |
//! | [`verify`] | exact check of the identity above | |
//!
//! A feedback loop whose algebraic part $I - \sigma D_2 D_1$ is singular is ill-posed and
//! refused with [`crate::Error::IllPosed`].

mod append;
mod check;
pub(crate) mod connect;
mod feedback;
mod parallel;
mod series;

pub use append::append;
pub use check::{Interconnection, verify};
pub use feedback::feedback;
pub use parallel::parallel;
pub use series::series;

use super::{Descriptor, StateSpace};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// The sign $\sigma$ of a feedback loop $u = r + \sigma K y$.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Sign {
    /// $\sigma = -1$ (python-control's default `sign=-1`).
    #[default]
    Negative,
    /// $\sigma = +1$.
    Positive,
}

impl Sign {
    /// $\sigma$ as an element of `k`.
    pub fn value<K: Field>(self, k: &K) -> K::Elem {
        match self {
            Sign::Negative => k.from_i64(-1),
            Sign::Positive => k.one(),
        }
    }
    /// `-1` or `1`, as python-control's `sign`.
    pub fn as_i64(self) -> i64 {
        match self {
            Sign::Negative => -1,
            Sign::Positive => 1,
        }
    }
}

/// The matrices of a system, borrowed: `e` is `None` for a standard system ($E = I$).
#[derive(Clone, Copy, Debug)]
pub struct BlocksRef<'a, K: Field> {
    pub e: Option<&'a Matrix<K>>,
    pub a: &'a Matrix<K>,
    pub b: &'a Matrix<K>,
    pub c: &'a Matrix<K>,
    pub d: &'a Matrix<K>,
}

/// The matrices of a result.
#[derive(Clone, Debug)]
pub struct Parts<K: Field> {
    pub e: Option<Matrix<K>>,
    pub a: Matrix<K>,
    pub b: Matrix<K>,
    pub c: Matrix<K>,
    pub d: Matrix<K>,
}

/// A system given by block matrices: [`StateSpace`] and [`Descriptor`].
pub trait Blocks<K: Field>: Sized {
    /// The matrices.
    fn blocks(&self) -> BlocksRef<'_, K>;
    /// A system of this kind from matrices.
    ///
    /// # Errors
    /// Shape errors; for [`StateSpace`], `Invalid` when `e` is given.
    fn from_parts(p: Parts<K>) -> Result<Self>;
}

impl<K: Field> Blocks<K> for StateSpace<K> {
    fn blocks(&self) -> BlocksRef<'_, K> {
        BlocksRef {
            e: None,
            a: &self.a,
            b: &self.b,
            c: &self.c,
            d: &self.d,
        }
    }
    fn from_parts(p: Parts<K>) -> Result<Self> {
        if p.e.is_some() {
            return Err(Error::Invalid(
                "a standard state-space system has no E matrix".into(),
            ));
        }
        StateSpace::new(p.a, p.b, p.c, p.d)
    }
}

impl<K: Field> Blocks<K> for Descriptor<K> {
    fn blocks(&self) -> BlocksRef<'_, K> {
        BlocksRef {
            e: Some(&self.e),
            a: &self.a,
            b: &self.b,
            c: &self.c,
            d: &self.d,
        }
    }
    fn from_parts(p: Parts<K>) -> Result<Self> {
        let n = p.a.nrows();
        let e =
            p.e.unwrap_or_else(|| Matrix::identity(p.a.field().clone(), n));
        Descriptor::new(e, p.a, p.b, p.c, p.d)
    }
}

impl<K: Field> BlocksRef<'_, K> {
    fn field(&self) -> &K {
        self.a.field()
    }
    fn n(&self) -> usize {
        self.a.nrows()
    }
    fn e_or_identity(&self) -> Matrix<K> {
        match self.e {
            Some(e) => e.clone(),
            None => Matrix::identity(self.field().clone(), self.n()),
        }
    }
}

/// `E = diag(E_1, E_2, ...)` when some part has an `E`, else `None`.
fn joint_e<K: Field>(parts: &[BlocksRef<'_, K>]) -> Option<Matrix<K>> {
    if parts.iter().all(|p| p.e.is_none()) {
        return None;
    }
    let k = parts.first()?.field().clone();
    let es: Vec<Matrix<K>> = parts.iter().map(BlocksRef::e_or_identity).collect();
    Some(Matrix::block_diag(k, &es))
}

/// The 2 x 2 block matrix `[[m11, m12], [m21, m22]]` (zero-sized blocks allowed).
fn grid2<K: Field>(
    m11: &Matrix<K>,
    m12: &Matrix<K>,
    m21: &Matrix<K>,
    m22: &Matrix<K>,
) -> Result<Matrix<K>> {
    let top = m11.hstack(m12)?;
    let bottom = m21.hstack(m22)?;
    top.vstack(&bottom)
}

/// Both parts over the same field, or `FieldMismatch`.
fn same_field<K: Field>(p: &BlocksRef<'_, K>, q: &BlocksRef<'_, K>) -> Result<()> {
    if p.field() == q.field() {
        Ok(())
    } else {
        Err(Error::FieldMismatch)
    }
}

/// A system without states: $y = K u$ (python-control converts a gain this way).
pub fn static_gain<K: Field>(k: Matrix<K>) -> StateSpace<K> {
    let f = k.field().clone();
    StateSpace {
        a: Matrix::zeros(f.clone(), 0, 0),
        b: Matrix::zeros(f.clone(), 0, k.ncols()),
        c: Matrix::zeros(f, k.nrows(), 0),
        d: k,
    }
}

impl<K: Field> Descriptor<K> {
    /// The standard system as a descriptor system with $E = I$.
    pub fn from_standard(s: &StateSpace<K>) -> Self {
        Descriptor {
            e: Matrix::identity(s.field().clone(), s.nstates()),
            a: s.a.clone(),
            b: s.b.clone(),
            c: s.c.clone(),
            d: s.d.clone(),
        }
    }
}

/// One of the interconnections, for callers that choose it at run time (command line,
/// Python).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Operation {
    /// [`series`] of two parts.
    Series,
    /// [`parallel`] of two parts.
    Parallel,
    /// [`feedback`] of two parts (the system, then the feedback path).
    Feedback(Sign),
    /// [`append`] of one or more parts.
    Append,
}

impl Operation {
    /// `series`, `parallel`, `feedback`, `append`.
    pub fn name(self) -> &'static str {
        match self {
            Operation::Series => "series",
            Operation::Parallel => "parallel",
            Operation::Feedback(_) => "feedback",
            Operation::Append => "append",
        }
    }
    /// The transfer matrix of the result in terms of the parts' ($G_1, G_2$; $G, K$).
    pub fn identity(self) -> &'static str {
        match self {
            Operation::Series => "G = G2 G1",
            Operation::Parallel => "G = G1 + G2",
            Operation::Feedback(Sign::Negative) => "G_fb = (I + G K)^-1 G",
            Operation::Feedback(Sign::Positive) => "G_fb = (I - G K)^-1 G",
            Operation::Append => "G = diag(G1, G2, ...)",
        }
    }
}

impl<'a, S> Interconnection<'a, S> {
    /// The interconnection `op` of `parts`.
    ///
    /// # Errors
    /// `Invalid` when `op` takes two parts and `parts` has another length.
    pub fn of(op: Operation, parts: &'a [S]) -> Result<Self> {
        if let Operation::Append = op {
            return Ok(Interconnection::Append(parts));
        }
        let [a, b] = parts else {
            return Err(Error::Invalid(format!(
                "{} takes two systems, got {}",
                op.name(),
                parts.len()
            )));
        };
        Ok(match op {
            Operation::Series => Interconnection::Series(a, b),
            Operation::Parallel => Interconnection::Parallel(a, b),
            Operation::Feedback(sign) => Interconnection::Feedback(a, b, sign),
            Operation::Append => Interconnection::Append(parts),
        })
    }
    /// Computes the interconnection (check it with [`verify`]).
    ///
    /// # Errors
    /// Every error of the operation.
    pub fn compute<K: Field>(&self) -> Result<S>
    where
        S: Blocks<K>,
    {
        match *self {
            Interconnection::Series(a, b) => series(a, b),
            Interconnection::Parallel(a, b) => parallel(a, b),
            Interconnection::Feedback(a, b, sign) => feedback(a, b, sign),
            Interconnection::Append(list) => append(list),
        }
    }
}

/// The interconnection `op` of `parts` and its exact check ([`verify`]).
///
/// # Errors
/// `Invalid` when `op` takes two parts and `parts` has another length (or `append` gets
/// none); every error of the operation.
pub fn interconnect<K: Field, S: Blocks<K>>(op: Operation, parts: &[S]) -> Result<(S, bool)> {
    let c = Interconnection::of(op, parts)?;
    let r = c.compute()?;
    let ok = verify(&c, &r);
    Ok((r, ok))
}
