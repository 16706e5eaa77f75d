//! Exact Jordan decomposition over $\mathbb{Q}$: eigenvalues as algebraic numbers, Jordan
//! chains, the complex and the real Jordan form, the closed-form free response.
//!
//! For $A \in \mathbb{Q}^{n \times n}$ with $\chi_A = \prod_p p^{m_p}$ ($p$ irreducible
//! over $\mathbb{Q}$) the module computes, for each $p$, in $K_p = \mathbb{Q}\[t\]/(p)$:
//! $$A V_p = V_p J_p, \qquad W_p A = J_p W_p, \qquad W_p V_p = I,$$
//! with $J_p$ the Jordan matrix of the generic root $t$. The Jordan form of $A$ is
//! $A = T J T^{-1}$ with $T = [\sigma_j(V_p)]_{p,j}$, $J = \operatorname{diag}
//! (\sigma_j(J_p))$, $\sigma_j: t \mapsto \theta_j$ running over the roots of $p$
//! (Galois conjugation: chains are computed once per factor, never per root).
//!
//! # Exact presentation of `J` and `T`
//! Each root's columns are exact in one field, displayed as follows:
//! * $\deg p = 1$: rationals;
//! * $\deg p = 2$: $\mathbb{Q}(\sqrt f)$, e.g. `-1 + i`, `1/2 + sqrt(5)/2`;
//! * $\deg p \ge 3$: polynomials in the root's symbol `r<k>` ($k$ = 1-based eigenvalue
//!   index), i.e. elements of $\mathbb{Q}(r_k)$; the report lists each `r<k>` with its
//!   minimal polynomial and approximation.
//!
//! When all columns lie in one field ($\mathbb{Q}$, $\mathbb{Q}(i)$ or one
//! $\mathbb{Q}(\sqrt f)$), [`JordanForm::single_field`] returns $J$, $T$ as one exact
//! matrix pair. Verification is per component (which covers every conjugate root, and
//! implies that $T$ is invertible: each $V_p$ has full column rank by $W_p V_p = I$, and
//! generalized eigenspaces of distinct eigenvalues are independent).
//!
//! | entry point | computes |
//! |---|---|
//! | [`jordan`] | [`JordanForm`]: components, eigenvalues, verification |
//! | [`JordanForm::eigenvalues`] | [`Eigenvalue`]: the eigenvalues as values over every base field (certified numbers; over $\mathbb{Q}(p)$ elements of the field or an irreducible factor), typed answers about the real embedding ([`Decided`]) |
//! | [`JordanForm::real_form`] | [`RealJordanForm`]: $2 \times 2$ blocks $[[a, b], [-b, a]]$, real $T$ |
//! | [`JordanForm::free_response`] | [`FreeResponse`]: $e^{At} = \sum t^k e^{\theta t} G_{\theta,k}$ |
//! | [`JordanForm::report`] | JSON keys of the CLI contract (`eigenvalues`, `J`, `T`, `verified`) |
//! | [`chains::jordan_chains`] | chains of one eigenvalue over any field |
//!
//! Eigenvalues are certified algebraic numbers ([`Eigenvalue::number`]: minimal polynomial
//! and an isolating interval or box found in exact arithmetic); their `f64` approximations
//! are read off the refined regions, mark the embeddings $t \mapsto \theta_j$ and never
//! enter exact arithmetic. The real/complex/purely-imaginary split is exact.

pub mod chains;
pub(crate) mod coeffs;
pub mod decompose;
pub mod derivation;
pub mod eigenvalue;
pub mod fields;
mod jordan_field;
pub mod normalize;
pub mod over_qp;
pub mod pair_field;
pub mod primary;
pub mod qp_form;
pub mod real;
pub mod real_quadratic;
pub mod real_steps;
pub(crate) mod realfield;
pub mod response;
mod roots;
mod simple;
pub mod steps;

pub use chains::{Chains, jordan_block_matrix, jordan_chains};
pub use decompose::{EigenField, eigenvalues_over, jordan_over};
pub use eigenvalue::{Certified, Decided, EigenValue, Eigenvalue, NumberEigen};
pub use jordan_field::{EigenVisitor, JordanField};
pub use primary::{Component, PrimaryComponent, Restriction};
pub use qp_form::jordan_qp;
pub use real::{CompactPair, RealBlock, RealEntries, RealJordanForm, RealNote};
pub use response::{FreeResponse, ResponseTerm, StateResponse};
#[cfg(test)]
pub(crate) use roots::certified_roots;

use crate::algebraic::{Ext, ExtElem, NfElem, NumberField};
use crate::error::Result;
use crate::field::ElemDisplay;
use crate::field::{Field, Q};
use crate::matrix::Matrix;
use crate::poly::Poly;
use primary::named_field;
use roots::radical_text;

/// An embedding of a component field $E = F\[t\]/(g)$ into an eigenvalue's display field.
pub type Embedding<'a, F = Q> =
    Box<dyn Fn(&ExtElem<<F as Field>::Elem>) -> ExtElem<<F as Field>::Elem> + 'a>;

/// $J$ and $T$ over one extension of the base field ([`JordanForm::single_field`]).
pub type JPair<F> = (Matrix<Ext<F>>, Matrix<Ext<F>>);

/// The columns of one eigenvalue, exact in one field.
#[derive(Clone, Debug, PartialEq)]
pub struct RootColumns<F: Field = Q> {
    /// Index into [`JordanForm::eigenvalues`].
    pub eigenvalue: usize,
    /// The field the entries lie in (marked at this root; displays with its symbol).
    pub field: Ext<F>,
    /// $\sigma_j(V_p)$ ($n \times m$).
    pub v: Matrix<Ext<F>>,
    /// $\sigma_j(J_p)$ ($m \times m$).
    pub j: Matrix<Ext<F>>,
}

/// The exact Jordan decomposition of a matrix over $F$ ($\mathbb{Q}$ by default,
/// $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$: [`jordan_over`]).
#[derive(Clone, Debug, PartialEq)]
pub struct JordanForm<F: Field = Q> {
    /// The input matrix.
    pub a: Matrix<F>,
    /// $\chi_A(x) = \det(xI - A)$.
    pub charpoly: Poly<F>,
    /// One component per irreducible factor of $\chi_A$ over $F$.
    pub components: Vec<Component<F>>,
    /// The eigenvalues as values, component by component ([`eigenvalue`]): over a number
    /// field every root as a certified algebraic number; over $\mathbb{Q}(p)$ one entry per
    /// irreducible factor (an element of $\mathbb{Q}(p)$, or the roots of a factor of
    /// degree $\ge 2$ given by that factor).
    pub eigenvalues: Vec<Eigenvalue<F>>,
    /// Elements of $F$ the result assumes nonzero (over $\mathbb{Q}(p)$: irreducible
    /// polynomials in the parameters, sorted: [`qp_form::jordan_qp`]); empty over a number
    /// field, where nothing is assumed.
    pub conditions: Vec<F::Elem>,
    /// Every component's identities held exactly and the dimensions add up to $n$ (over
    /// $\mathbb{Q}(p)$ also $A T = T J$ for the primary form and $\det T \ne 0$).
    pub verified: bool,
}

/// Exact Jordan decomposition of a square rational matrix.
///
/// # Errors
/// `NotSquare` for a non-square input; `Unsupported` when the characteristic polynomial
/// cannot be factored; `Limit` from root isolation; `Verification` if an internal identity
/// fails.
///
/// # Examples
/// ```
/// use exactlti::{jordan::jordan, qmat};
/// let jf = jordan(&qmat![[-2, 0, 0], [0, 0, 1], [0, -2, -2]]).unwrap();
/// use exactlti::report::sections::eigenvalue_text;
/// let values: Vec<String> = jf.eigenvalues.iter().map(eigenvalue_text).collect();
/// assert_eq!(values, ["-2", "-1 + i", "-1 - i"]);
/// assert!(jf.verified);
/// ```
pub fn jordan(a: &Matrix<Q>) -> Result<JordanForm> {
    jordan_over(a)
}

/// Jordan decomposition of a matrix over a quadratic field $\mathbb{Q}(\sqrt d)$ (or
/// $\mathbb{Q}(i)$).
///
/// A matrix whose entries are all rational is decomposed exactly by [`jordan`]. A matrix
/// with irrational entries is decomposed over $K$ by [`jordan_over`] (components over the
/// relative fields $K\[t\]/(g)$); this function refuses it with a typed error pointing there.
///
/// # Errors
/// `Unsupported` for an entry outside $\mathbb{Q}$; those of [`jordan`] otherwise.
///
/// # Examples
/// ```
/// use exactlti::field::{Field, QuadraticField};
/// use exactlti::jordan::jordan_quadratic;
/// use exactlti::matrix::Matrix;
/// let k = QuadraticField::new(2).unwrap();
/// let a = Matrix::from_fn(k.clone(), 2, 2, |i, j| k.from_i64((i + 2 * j) as i64));
/// assert!(jordan_quadratic(&a).unwrap().verified);
/// let b = Matrix::from_fn(k.clone(), 2, 2, |i, j| if i == j { k.gen_elem() } else { k.zero() });
/// assert!(jordan_quadratic(&b).is_err());
/// ```
pub fn jordan_quadratic(a: &Matrix<crate::field::QuadraticField>) -> Result<JordanForm> {
    let k = a.field();
    let mut rows = Vec::with_capacity(a.nrows());
    for i in 0..a.nrows() {
        let mut row = Vec::with_capacity(a.ncols());
        for j in 0..a.ncols() {
            let Some(q) = k.to_rational(a.get(i, j)) else {
                return Err(crate::error::Error::Unsupported(format!(
                    "Jordan form over {k}: entry ({}, {}) = {} is not rational; the \
                     decomposition over {k} is jordan::jordan_over",
                    i + 1,
                    j + 1,
                    k.fmt_elem(a.get(i, j))
                )));
            };
            row.push(q);
        }
        rows.push(row);
    }
    if a.nrows() == 0 {
        a.check_square("jordan")?;
        return jordan(&Matrix::zeros(Q, 0, 0));
    }
    jordan(&Matrix::from_rows(Q, rows)?)
}

/// Maps an element $c_0 + c_1 t$ of $\mathbb{Q}[t]/(p)$, $\deg p = 2$, to
/// $\mathbb{Q}(\sqrt f)$ at the root $t = a_0 + s\sqrt f$.
pub(crate) fn quadratic_image(
    x: &NfElem,
    a0: &crate::field::Rational,
    s: &crate::field::Rational,
) -> NfElem {
    use num_traits::Zero;
    let c0 =
        x.0.first()
            .cloned()
            .unwrap_or_else(crate::field::Rational::zero);
    let c1 =
        x.0.get(1)
            .cloned()
            .unwrap_or_else(crate::field::Rational::zero);
    let mut v = vec![&c0 + &c1 * a0, &c1 * s];
    while v.last().is_some_and(|c| c.is_zero()) {
        v.pop();
    }
    crate::algebraic::ExtElem(v)
}

/// $\mathbb{Q}(\sqrt f)$ as a marked number field displayed with the radical.
pub(crate) fn quadratic_field(f: &num_bigint::BigInt) -> NumberField {
    use num_traits::{Signed, ToPrimitive};
    let m = Poly::new(
        Q,
        vec![
            crate::field::Rational::from_integer(-f),
            num_traits::Zero::zero(),
            num_traits::One::one(),
        ],
    );
    let r = f.abs().to_f64().unwrap_or(f64::MAX).sqrt();
    let root = if f.is_negative() { (0.0, r) } else { (r, 0.0) };
    named_field(&m, root, &radical_text(f))
}

impl<F: Field> JordanForm<F> {
    /// Size of $A$.
    pub fn n(&self) -> usize {
        self.a.nrows()
    }
    /// The base field $F$.
    pub fn base(&self) -> &F {
        self.a.field()
    }
    /// The exact terms $G_{\theta,k}$ of $e^{At}$, one set per component. A component
    /// without chains (a factor of degree $\ge 2$ of [`jordan_qp`]) gets them here
    /// ([`Component::compute`]); should that fail its terms are missing and
    /// [`FreeResponse::verify`] says so.
    pub fn free_response(&self) -> FreeResponse<crate::algebraic::Ext<F>>
    where
        F: 'static,
    {
        let made: Vec<Option<Component<F>>> = self
            .components
            .iter()
            .map(|c| {
                let (g, m, r) = (&c.factor, c.multiplicity, c.roots.clone());
                let compute = || Component::compute(&self.a, g, m, c.minpoly.clone(), r, true);
                (!c.has_chains()).then(compute).and_then(|x| x.ok())
            })
            .collect();
        let comps = self.components.iter().zip(&made).map(|(c, m)| {
            let c = m.as_ref().unwrap_or(c);
            // still without chains: no terms (the verification then fails)
            let blocks: &[usize] = if c.has_chains() { &c.blocks } else { &[] };
            (&c.field, blocks, &c.chains, &c.left_chains)
        });
        FreeResponse::from_chains(self.n(), comps)
    }
}

impl<F: EigenField> JordanForm<F> {
    /// The exact field of eigenvalue `ev` (marked at that root, displayed as in the module
    /// docs) and the embedding $\sigma_j$ of the component field into it
    /// ([`EigenField::root_field`]).
    pub fn root_map(&self, ev: usize) -> (Ext<F>, Embedding<'_, F>) {
        F::root_field(self, ev)
    }
    /// The columns of each eigenvalue, exact in the field described in the module docs.
    pub fn root_columns(&self) -> Vec<RootColumns<F>> {
        (0..self.eigenvalues.len())
            .map(|ev| {
                let c = &self.components[self.eigenvalues[ev].component];
                let (field, f) = self.root_map(ev);
                RootColumns {
                    eigenvalue: ev,
                    v: c.chains.map(&field, &f),
                    j: c.jordan_matrix().map(&field, &f),
                    field,
                }
            })
            .collect()
    }
    /// $J$ and $T$ as exact matrices over one field, when every eigenvalue lies in one
    /// field: $F$ itself (all factors linear; then over $F$ as an extension of degree 1) or
    /// one quadratic field over $\mathbb{Q}$ ($\mathbb{Q}(i)$, $\mathbb{Q}(\sqrt f)$).
    pub fn single_field(&self) -> Option<JPair<F>> {
        let cols = self.root_columns();
        let mut field: Option<Ext<F>> = None;
        for c in &cols {
            if c.field.degree() > 1 {
                if field.as_ref().is_some_and(|f| *f != c.field) {
                    return None;
                }
                field = Some(c.field.clone());
            }
        }
        let field =
            field.unwrap_or_else(|| Ext::with_var(&Poly::x(self.base().clone()), (0.0, 0.0), "t"));
        let n = self.n();
        let mut t = Matrix::zeros(field.clone(), n, n);
        let mut j = Matrix::zeros(field.clone(), n, n);
        let mut off = 0;
        for c in &cols {
            let m = c.v.ncols();
            let to = |x: &ExtElem<F::Elem>| match c.field.degree() {
                1 => field.from_base(&c.field.to_base(x).expect("degree 1")),
                _ => x.clone(),
            };
            t.set_block(0, off, &c.v.map(&field, to));
            j.set_block(off, off, &c.j.map(&field, to));
            off += m;
        }
        Some((j, t))
    }
}
