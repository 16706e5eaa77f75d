//! The eigenvalues of a [`super::JordanForm`] as values, one list for every base field:
//! [`Eigenvalue`] holds, per root of an irreducible factor $g$ of $\chi_A$ over $F$, what the
//! root is ([`EigenValue`]) with its algebraic multiplicity $\mu$, geometric multiplicity
//! $\gamma$ and Jordan block sizes (largest first), where
//! $$\sum_{\theta} \mu_\theta = n, \qquad \gamma_\theta = \#\text{blocks}, \qquad
//! \mu_\theta = \textstyle\sum \text{blocks}, \qquad
//! \operatorname{rank}(A - \theta I)^k = n - \sum_b \min(b, k)$$
//! (the last per root $\theta$, over a field containing it; over $\mathbb{Q}(p)$ generically,
//! off the form's conditions).
//!
//! * Over a number field ($\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$) every root is
//!   a certified algebraic number ([`EigenValue::Number`]: minimal polynomial over
//!   $\mathbb{Q}$ and an isolating region); the fields of [`Certified`] are read through the
//!   eigenvalue itself (`e.minpoly`, `e.approx`, `e.number`: [`NumberEigen`]).
//! * Over $\mathbb{Q}(p_1, \dots, p_k)$ a root of a linear factor is an element of the field
//!   ([`EigenValue::InField`], a rational function of the parameters); the roots of an
//!   irreducible factor of degree $d \ge 2$ are one entry with that factor, their minimal
//!   polynomial over $\mathbb{Q}(p)$ ([`EigenValue::RootOf`]; a primary block of size
//!   $d \mu$ in $J$).
//!
//! Questions about the real embedding (is the eigenvalue real? the sign of its real part,
//! i.e. stability) have typed answers ([`Decided`]): exact over a number field; over
//! $\mathbb{Q}(p)$ (real parameters) an element of the field is real, and the sign of a
//! rational function that is not constant, or the realness of a root of a factor of degree
//! $\ge 2$, is [`Decided::NotInSymbols`] -- never a guess from sample points.

use crate::algebraic::AlgebraicNumber;
use crate::error::Result;
use crate::field::{Field, Q, QuadraticField};
use crate::poly::Poly;
use std::cmp::Ordering;

/// A certified algebraic number: an eigenvalue over a number field.
#[derive(Clone, Debug, PartialEq)]
pub struct Certified {
    /// Minimal polynomial over $\mathbb{Q}$ (for the component's factor over $\mathbb{Q}$,
    /// the factor itself). Its exact display (rational, closed form up to degree 2 and
    /// biquadratics, else `root of ... near ...`) is made in the reports from it and
    /// [`Certified::approx`] (`report::sections::eigenvalue_text`).
    pub minpoly: Poly<Q>,
    /// Approximation `(re, im)`, read off the certified region of [`Certified::number`]
    /// (relative error about $2^{-60}$); exactly `0.0` parts for real and purely imaginary
    /// roots.
    pub approx: (f64, f64),
    /// The certified algebraic number (minimal polynomial and isolating region).
    pub number: AlgebraicNumber,
}

/// What an eigenvalue is, as a value of its base field's kind (module docs).
#[derive(Clone, Debug, PartialEq)]
pub enum EigenValue<F: Field> {
    /// A certified algebraic number (number fields).
    Number(Box<Certified>),
    /// An element of the base field: the root $-g_0$ of a linear factor $x + g_0$
    /// (over $\mathbb{Q}(p)$).
    InField(F::Elem),
    /// The roots of a monic irreducible factor $g$ of degree $\ge 2$ over the base field
    /// (over $\mathbb{Q}(p)$): $g$ is their minimal polynomial over $F$.
    RootOf(Poly<F>),
}

/// A typed answer to a question about the real embedding of an eigenvalue.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Decided<T> {
    /// Decided exactly.
    Exactly(T),
    /// Not decided in symbols: the answer depends on the parameters' values (over
    /// $\mathbb{Q}(p)$); give them values (`--at`) to decide it.
    NotInSymbols,
}

impl<T> Decided<T> {
    /// The exact answer, if decided.
    pub fn exactly(self) -> Option<T> {
        match self {
            Decided::Exactly(t) => Some(t),
            Decided::NotInSymbols => None,
        }
    }
}

/// One eigenvalue entry of a [`super::JordanForm`]: one root (number fields) or one
/// irreducible factor's roots (over $\mathbb{Q}(p)$, degree $\ge 2$), with its structure.
#[derive(Clone, Debug, PartialEq)]
pub struct Eigenvalue<F: Field = Q> {
    /// What the eigenvalue is (private: over a number field it is always
    /// [`EigenValue::Number`], which [`NumberEigen`]'s dereference relies on; read it with
    /// [`Eigenvalue::value`]).
    value: EigenValue<F>,
    /// Index into [`super::JordanForm::components`] and root index within it.
    pub component: usize,
    pub root: usize,
    /// Index $k$ of the root's symbol `r<k>` in per-root displays (1-based position in
    /// [`super::JordanForm::eigenvalues`]).
    pub index: usize,
    /// Algebraic multiplicity of each root ($\mu$: the factor's multiplicity in $\chi_A$).
    pub algebraic_multiplicity: usize,
    /// Geometric multiplicity of each root (the number of its Jordan blocks).
    pub geometric_multiplicity: usize,
    /// Jordan block sizes of each root, largest first.
    pub blocks: Vec<usize>,
}

/// The structure of one eigenvalue entry: component, root, 1-based index, algebraic
/// multiplicity, block sizes (largest first).
pub(crate) type Structure = (usize, usize, usize, usize, Vec<usize>);

impl<F: Field> Eigenvalue<F> {
    /// A certified root (number fields).
    pub(crate) fn number(c: Certified, s: Structure) -> Self {
        Self::with(EigenValue::Number(Box::new(c)), s)
    }
    fn with(value: EigenValue<F>, (component, root, index, mu, blocks): Structure) -> Self {
        Eigenvalue {
            value,
            component,
            root,
            index,
            algebraic_multiplicity: mu,
            geometric_multiplicity: blocks.len(),
            blocks,
        }
    }
    /// What the eigenvalue is.
    pub fn value(&self) -> &EigenValue<F> {
        &self.value
    }
    /// The name `r<k>` of the root's variable in the fields it is written in.
    pub fn symbol(&self) -> String {
        format!("r{}", self.index)
    }
    /// How many eigenvalues (with multiplicity) the entry stands for: $\mu$ for a root,
    /// $d \mu$ for the roots of a factor of degree $d$ ([`EigenValue::RootOf`]).
    pub fn count(&self) -> usize {
        match &self.value {
            EigenValue::RootOf(g) => g.deg() * self.algebraic_multiplicity,
            _ => self.algebraic_multiplicity,
        }
    }
    /// Is the eigenvalue real? Exact for a certified number; an element of $\mathbb{Q}(p)$
    /// is real (the parameters are real); the roots of a factor of degree $\ge 2$ over
    /// $\mathbb{Q}(p)$: not decided in symbols.
    pub fn is_real(&self) -> Decided<bool> {
        match &self.value {
            EigenValue::Number(c) => Decided::Exactly(c.number.is_real()),
            EigenValue::InField(_) => Decided::Exactly(true),
            EigenValue::RootOf(_) => Decided::NotInSymbols,
        }
    }
    /// The sign of $\operatorname{Re}\theta$ (`Less`: in the open left half-plane), in
    /// `k`, the base field: exact for a certified number and for a constant element of
    /// $\mathbb{Q}(p)$; not decided in symbols otherwise.
    ///
    /// # Errors
    /// `Limit` when the real part of a certified number is too large to compute.
    pub fn re_sign(&self, k: &F) -> Result<Decided<Ordering>> {
        Ok(match &self.value {
            EigenValue::Number(c) => {
                let zero = AlgebraicNumber::from_rational(&num_traits::Zero::zero());
                let re = if c.number.is_real() {
                    c.number.clone()
                } else {
                    c.number.try_re()?
                };
                match re.partial_cmp(&zero) {
                    Some(o) => Decided::Exactly(o),
                    None => Decided::NotInSymbols,
                }
            }
            EigenValue::InField(x) => match k.to_rational(x) {
                Some(q) => Decided::Exactly(q.cmp(&num_traits::Zero::zero())),
                None => Decided::NotInSymbols,
            },
            EigenValue::RootOf(_) => Decided::NotInSymbols,
        })
    }
}

impl Eigenvalue<crate::ratfunc::RatFuncField> {
    /// An eigenvalue in $\mathbb{Q}(p)$ (a linear factor).
    pub(crate) fn in_field(x: crate::ratfunc::RatFunc, s: Structure) -> Self {
        Self::with(EigenValue::InField(x), s)
    }
    /// The roots of an irreducible factor `g` of degree $\ge 2$ over $\mathbb{Q}(p)$.
    pub(crate) fn root_of(g: Poly<crate::ratfunc::RatFuncField>, s: Structure) -> Self {
        Self::with(EigenValue::RootOf(g), s)
    }
}

/// The number fields, whose eigenvalues are certified algebraic numbers: an
/// [`Eigenvalue`] over them reads as its [`Certified`] root (`e.approx`, `e.minpoly`,
/// `e.number`). Sealed: implemented for $\mathbb{Q}$ and the quadratic fields, whose
/// eigenvalues are only ever made by [`Eigenvalue::number`].
pub trait NumberEigen: Field + sealed::Sealed {}
impl NumberEigen for Q {}
impl NumberEigen for QuadraticField {}

mod sealed {
    pub trait Sealed {}
    impl Sealed for crate::field::Q {}
    impl Sealed for crate::field::QuadraticField {}
}

impl<F: NumberEigen> std::ops::Deref for Eigenvalue<F> {
    type Target = Certified;
    fn deref(&self) -> &Certified {
        match &self.value {
            EigenValue::Number(c) => c.as_ref(),
            // the constructors of the other kinds exist only over Q(p), not a NumberEigen
            _ => unreachable!("an eigenvalue over a number field is a certified number"),
        }
    }
}
