//! Exact Jordan decomposition over a quadratic field $K = \mathbb{Q}(\alpha)$, $\alpha = i$ or
//! $\sqrt d$ (the matrices the reader types as `QQ(i)` / `QQ(sqrt(d))`).
//!
//! # Design
//! For $A \in K^{n \times n}$, $\chi_A \in K\[x\]$ is factored over $K$ into $\prod g^{e}$
//! with Trager's norm method ([`eigen::factor_over_k`], the existing
//! [`crate::algebraic::factor_over_number_field`]). For each factor $g$ the chains are
//! computed once, for the generic root $t$, in the **relative** extension
//! $E = K\[t\]/(g)$ ([`RelField`], a [`crate::field::Field`], so the generic
//! [`super::chains::jordan_chains`] applies): $A V = V J_t$, $W A = J_t W$, $W V = I$ are
//! checked exactly in $E$. No absolute primitive element of $E$ over $\mathbb{Q}$ is
//! needed: the eigenvalues' certified form comes from their minimal polynomial over
//! $\mathbb{Q}$, $m = g$ or $g \bar g$, and an exact choice of which roots of $m$ are
//! roots of $g$ ([`eigen::roots_of_factor`]).
//!
//! **Embeddings.** The eigenvalues of $A$ are the roots $\theta_j$ of $g$ under the
//! embeddings of $E$ that keep $\alpha$ at its value in $K$ ($i$, or $\sqrt d > 0$). The
//! embeddings sending $\alpha \mapsto -\alpha$ give the eigenvalues of $\bar A$ (the Galois
//! conjugate matrix), never of $A$: for the triangular $A$ with diagonal $i, 2i$ the
//! eigenvalues are $i, 2i$, not $-i$. Each $\theta_j$ marks $E$ at that root
//! ([`JordanFormK::root_field`]): $t \mapsto \theta_j$ carries the chains to those of
//! $\theta_j$ (conjugation over $K$, never a per-root computation).
//!
//! A matrix whose entries all lie in $\mathbb{Q}$ keeps the rational code path
//! ([`super::jordan`]): callers dispatch on that (see `jordan_quadratic`).
//!
//! # Presentation
//! Eigenvalues display like the rational ones (closed form when $\deg m \le 2$, e.g.
//! `2 + sqrt(6)`, else `root of m near ...`). The columns of $\theta_j$ lie in $E$ at
//! $\theta_j$: for $\deg g = 1$ in $K$ itself (all linear: one matrix over $K$); for a
//! rational quadratic $g$ with roots $a_0 \pm s\sqrt f$ as `u + v*sqrt(f)`, $u, v \in K$;
//! otherwise as polynomials in the root's symbol `r<k>` with coefficients in $K$.
//!
//! Over a real $K$ the real Jordan form ([`real`]) writes each complex pair in its real field
//! $K(\operatorname{Re}\theta, \operatorname{Im}\theta)$ ([`pair_field`]) when that is
//! small, else in the compact form; [`response`] gives the free response $e^{At}x_0$.

pub mod eigen;
pub mod pair_field;
pub mod real;
pub mod response;

pub use real::RealFormK;
/// $E = K\[t\]/(g)$ over a quadratic field $K$: the generic extension.
pub type RelField = crate::algebraic::Ext<QuadraticField>;
/// An element of a [`RelField`].
pub type RelElem = crate::algebraic::ExtElem<crate::field::Quadratic>;

use crate::error::Result;
use crate::field::QuadraticField;
use crate::matrix::Matrix;
use crate::poly::Poly;

/// The data of one irreducible factor $g$ of $\chi_A$ over $K$, in $E = K\[t\]/(g)$: the
/// generic [`crate::jordan::primary::Component`].
pub type ComponentK = crate::jordan::primary::Component<QuadraticField>;

/// The exact Jordan decomposition of a matrix over $K$: the generic
/// [`crate::jordan::JordanForm`].
pub type JordanFormK = crate::jordan::JordanForm<QuadraticField>;

/// One irreducible factor $g$ over $K$, its multiplicity, the minimal polynomial over
/// $\mathbb{Q}$ of its roots and the certified roots of $g$.
pub type FactorRoots = crate::jordan::decompose::FactorRoots<QuadraticField>;

/// The eigenvalues of $A$ over $K$ without chains: per irreducible factor $g$ of
/// $\chi_A$ over $K$ (multiplicity $e$), $g$, $e$, the minimal polynomial over
/// $\mathbb{Q}$ and the certified roots of $g$ (see [`eigen::roots_of_factor`]).
///
/// # Errors
/// `NotSquare`; those of the factorization and root isolation.
pub fn eigenvalues_over_k(
    a: &Matrix<QuadraticField>,
) -> Result<(Poly<QuadraticField>, Vec<FactorRoots>)> {
    a.check_square("jordan")?;
    let chi = a.charpoly()?;
    let out = <QuadraticField as crate::jordan::EigenField>::eigen_factors(&chi)?;
    Ok((chi, out))
}

/// Exact Jordan decomposition of a square matrix over a quadratic field (module docs).
///
/// # Errors
/// `NotSquare`; `Limit` from the factorization or root isolation; `Verification` if an
/// internal identity fails.
///
/// # Examples
/// ```
/// use exactlti::field::{Field, Quadratic, QuadraticField, Rational};
/// use exactlti::jordan::over_k::jordan_over_k;
/// use exactlti::matrix::Matrix;
/// let k = QuadraticField::gaussian();
/// let q = |a: i64, b: i64| Quadratic::new(Rational::from_integer(a.into()), Rational::from_integer(b.into()));
/// // the Hermitian [[1, 2+i], [2-i, 3]]: eigenvalues 2 +- sqrt(6)
/// let a = Matrix::from_rows(k, vec![vec![q(1, 0), q(2, 1)], vec![q(2, -1), q(3, 0)]]).unwrap();
/// let jf = jordan_over_k(&a).unwrap();
/// let values: Vec<&str> = jf.eigenvalues.iter().map(|e| e.value.as_str()).collect();
/// assert_eq!(values, ["2 + sqrt(6)", "2 - sqrt(6)"]);
/// assert!(jf.verified);
/// ```
pub fn jordan_over_k(a: &Matrix<QuadraticField>) -> Result<JordanFormK> {
    crate::jordan::jordan_over(a)
}

impl JordanFormK {
    /// $E$ of eigenvalue `ev`'s component marked at that eigenvalue (display symbol
    /// `r<k>`, or the radical for a rational quadratic factor).
    pub fn root_field(&self, ev: usize) -> RelField {
        let e = &self.eigenvalues[ev];
        let c = &self.components[e.component];
        let radical = if c.factor.deg() == 2 && c.minpoly.deg() == 2 {
            super::roots::quadratic_roots(&c.minpoly).map(|(a0, s, f)| {
                let positive = if num_traits::Signed::is_negative(&f) {
                    e.approx.1 > 0.0
                } else {
                    e.approx.0 > crate::field::rational_to_f64(&a0)
                };
                (a0, if positive { s } else { -s }, f)
            })
        } else {
            None
        };
        c.field.marked(e.approx, &e.symbol, radical)
    }
    /// Per eigenvalue: its field, $\sigma_j(V)$ ($n \times m$) and $\sigma_j(J_t)$.
    pub fn root_columns(&self) -> Vec<(RelField, Matrix<RelField>, Matrix<RelField>)> {
        (0..self.eigenvalues.len())
            .map(|ev| {
                let c = &self.components[self.eigenvalues[ev].component];
                let f = self.root_field(ev);
                let v = c.chains.map(&f, |x| x.clone());
                let j = c.jordan_matrix().map(&f, |x| x.clone());
                (f, v, j)
            })
            .collect()
    }
    /// $J$ and $T$ over $K$ when every eigenvalue lies in $K$ (all factors linear).
    pub fn single_field(&self) -> Option<(Matrix<QuadraticField>, Matrix<QuadraticField>)> {
        if self.components.iter().any(|c| c.factor.deg() != 1) {
            return None;
        }
        let k = self.base().clone();
        let n = self.n();
        let mut t = Matrix::zeros(k.clone(), n, n);
        let mut j = Matrix::zeros(k.clone(), n, n);
        let mut off = 0;
        for (f, v, jj) in self.root_columns() {
            let m = v.ncols();
            let b = |x: &RelElem| f.to_base(x).expect("a linear factor's field is K");
            for r in 0..n {
                for q in 0..m {
                    t.set(r, off + q, b(v.get(r, q)));
                }
            }
            for r in 0..m {
                for q in 0..m {
                    j.set(off + r, off + q, b(jj.get(r, q)));
                }
            }
            off += m;
        }
        Some((j, t))
    }
}
