//! The family over $K$ at a critical value $r$: exact arithmetic in $E = K(r) = K[t]/(h)$,
//! $h$ the minimal polynomial of $r$ over $K$, marked at $r$; the eigenvalues of $A(r)$ with
//! multiplicities and Jordan blocks; the imaginary-axis confirmations.
//!
//! Jordan blocks of a repeated square-free factor $s$ of $P(x, r)$ (multiplicity $m$): for
//! $\deg s = 1$ from the ranks of $s(A)^k$ ([`block_sizes`]); for $\deg s > 1$ the nullity
//! $\nu$ of $s(A)$ decides the cases where every root of $s$ has the same structure:
//! $\nu = m \deg s$ (all blocks of size 1) or $\nu = \deg s$ (one block of size $m$);
//! other cases are refused (`Unsupported`), never guessed.
//!
//! Imaginary axis. Over a real $K$ the pairs $\pm\lambda$ are the roots $u = \lambda^2$ of
//! $g = \gcd(E, O)$, $P = E(x^2) + x O(x^2)$, and an imaginary pair is a negative root $u$,
//! counted by Sturm's theorem with exact signs in $E$ ([`sign_at_real_root`]). Over
//! $\mathbb{Q}(i)$, $E = L(i)$ with $L = \mathbb{Q}(r)$ real: $P(iy) = U(y) + i V(y)$ with
//! $U, V \in L[y]$, and an eigenvalue $iy$ on the axis ($y \ne 0$ real) is a nonzero real root
//! of $\gcd(U, V)$, counted by Sturm's theorem with the signs of $L$.

use super::super::approx::approx_roots;
use super::super::imaginary::real_roots_by_sign;
use super::super::roots::{rational_near, sign_at_root};
use super::super::structure::block_sizes;
use super::super::value::value_over_k;
use super::super::{EigenvalueAt, FactorAt};
use super::KFamily;
use super::roots_k::{sign_at_real_root, split_parts};
use crate::algebraic::{AlgebraicNumber, Ext, NumberField};
use crate::error::{Error, Result};
use crate::field::{Field, Quadratic, QuadraticField, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::study::bivar::BiPolyOver;
use num_complex::Complex;
use num_traits::{One, Zero};

/// $E = K(r)$.
pub type RootField = Ext<QuadraticField>;

/// The family at a critical value.
pub struct AtRoot {
    pub e: RootField,
    /// $P(x, r)$, monic.
    pub p: Poly<RootField>,
    pub eigenvalues: Vec<EigenvalueAt>,
    pub repeated: bool,
}

/// The family at the real root `r` with minimal polynomial `h` over $K$.
///
/// # Errors
/// A pole or singular pencil at `r` (not expected: those are singular values); the
/// refused Jordan case of the module docs; `Verification` when $\deg P(x, r) \ne$ the order
/// of $A(r)$.
pub fn at_root(
    fam: &KFamily,
    p: &BiPolyOver<QuadraticField>,
    r: &AlgebraicNumber,
    h: &Poly<QuadraticField>,
) -> Result<AtRoot> {
    let e = Ext::with_var(h, (r.approx().0, 0.0), "t");
    let t = e.generator();
    let theta = e.from_base(&Quadratic::new(Rational::zero(), Rational::one()));
    let pe = p.at_in(&e, &t, &|c| e.from_base(c));
    if pe.is_zero() {
        return Err(Error::Singular);
    }
    let pe = pe.monic();
    let a = fam.state_matrix_in(&e, &theta, &t)?;
    if a.nrows() != pe.deg() || a.charpoly()? != pe {
        return Err(Error::Verification(format!(
            "P(x, {}) is not the characteristic polynomial of A at {}",
            fam.param,
            r.value_string()
        )));
    }
    let mut eigenvalues = vec![];
    let mut repeated = false;
    for (s, m) in pe.squarefree() {
        repeated |= m > 1;
        let blocks = blocks_of(&a, &s, m)?;
        let factor = (m > 1).then(|| FactorAt::K(s.clone()));
        let value = if m > 1 && s.deg() == 1 {
            Some(value_over_k(&e, &e.neg(&s.monic().coeff(0)), r)?)
        } else {
            None
        };
        for z in approx_roots_of(&s)? {
            eigenvalues.push(EigenvalueAt {
                approx: (z.re, z.im),
                multiplicity: m,
                blocks: blocks.clone(),
                factor: factor.clone(),
                value: value.clone(),
            });
        }
    }
    eigenvalues.sort_by(|x, y| {
        x.approx
            .0
            .total_cmp(&y.approx.0)
            .then(x.approx.1.total_cmp(&y.approx.1))
    });
    Ok(AtRoot {
        e,
        p: pe,
        eigenvalues,
        repeated,
    })
}

/// Jordan blocks of each root of the square-free factor `s` of multiplicity `m`.
fn blocks_of<F: Field>(a: &Matrix<F>, s: &Poly<F>, m: usize) -> Result<Vec<usize>> {
    if m == 1 || s.deg() == 1 {
        return block_sizes(a, s, m);
    }
    let nullity = a.nrows() - a.eval_poly(s)?.rank();
    if nullity == m * s.deg() {
        Ok(vec![1; m])
    } else if nullity == s.deg() {
        Ok(vec![m])
    } else {
        Err(Error::Unsupported(format!(
            "Jordan blocks of the roots of {s} (multiplicity {m}, nullity {nullity}): roots of one square-free factor with different structures"
        )))
    }
}

/// Approximate roots of `s` (companion matrix in complex floating point).
pub fn approx_roots_of<F: Field>(s: &Poly<F>) -> Result<Vec<Complex<f64>>> {
    let f = s.field().clone();
    let s = s.monic();
    let n = s.deg();
    let comp = Matrix::from_fn(f.clone(), n, n, |i, j| {
        if j == n - 1 {
            f.neg(&s.coeff(i))
        } else if i == j + 1 {
            f.one()
        } else {
            f.zero()
        }
    });
    let c = crate::float::to_cmatrix(&comp)?;
    c.eigenvalues()
        .map(|v| v.iter().copied().collect())
        .ok_or_else(|| Error::Limit("complex eigenvalues did not converge".into()))
}

/// Over a real $K$: is there an imaginary pair $\pm i\omega$ at `r`? `Ok(Ok(omega))` (the
/// smallest, approximate; existence exact) or `Ok(Err(reason))`.
pub fn imaginary_pair_k(
    at: &AtRoot,
    k: &QuadraticField,
    r: &AlgebraicNumber,
) -> Result<std::result::Result<f64, String>> {
    let e = &at.e;
    let cs = at.p.coeffs();
    let even = Poly::new(e.clone(), cs.iter().step_by(2).cloned().collect());
    let odd = Poly::new(e.clone(), cs.iter().skip(1).step_by(2).cloned().collect());
    let g = strip_zero_roots(&even.gcd(&odd));
    if g.degree().unwrap_or(0) == 0 {
        return Ok(Err(
            "no pair adds up to zero (or a double zero eigenvalue)".into()
        ));
    }
    let sign = |x: &<RootField as Field>::Elem| {
        let (pa, pb) = split_parts(&x.0);
        sign_at_real_root(k, (&pa, &pb), r)
    };
    if real_roots_by_sign(&g, &sign)?.0 == 0 {
        return Ok(Err(
            "pairs adding up to zero are not imaginary (real pairs or complex quadruples)".into(),
        ));
    }
    let omega = approx_roots_of(&g)?
        .iter()
        .filter(|u| u.re < 0.0)
        .map(|u| (-u.re).sqrt())
        .fold(f64::INFINITY, f64::min);
    Ok(Ok(omega))
}

/// Over $\mathbb{Q}(i)$: is an eigenvalue $i\omega$, $\omega \ne 0$ real, on the imaginary
/// axis at `r`? `Ok(Ok(|omega|))` (the smallest, approximate; existence exact) or
/// `Ok(Err(reason))`.
pub fn imaginary_eigenvalue_i(
    at: &AtRoot,
    r: &AlgebraicNumber,
) -> Result<std::result::Result<f64, String>> {
    let l: NumberField = r.to_number_field();
    let f = r.minpoly();
    let to_l = |p: &Poly<crate::field::Q>| l.from_poly(&p.rem(f));
    // P(iy) = sum_j p_j i^j y^j, p_j = alpha_j + i beta_j (alpha, beta in L)
    let (mut u, mut v) = (vec![], vec![]);
    for (j, c) in at.p.coeffs().iter().enumerate() {
        let (pa, pb) = split_parts(&c.0);
        let (al, be) = (to_l(&pa), to_l(&pb));
        let (re, im) = match j % 4 {
            0 => (al, be),
            1 => (l.neg(&be), al),
            2 => (l.neg(&al), l.neg(&be)),
            _ => (be, l.neg(&al)),
        };
        u.push(re);
        v.push(im);
    }
    let g = Poly::new(l.clone(), u).gcd(&Poly::new(l.clone(), v));
    let g = strip_zero_roots(&g);
    if g.degree().unwrap_or(0) == 0 {
        return Ok(Err(
            "no eigenvalue on the imaginary axis (but one mirrored by another)".into(),
        ));
    }
    let (neg, pos) = real_roots_by_sign(&g, &|x| sign_at_root(&l, x, r))?;
    if neg + pos == 0 {
        return Ok(Err(
            "no eigenvalue on the imaginary axis (but one mirrored by another)".into(),
        ));
    }
    let v0 = rational_near(r)?;
    let omega = approx_roots(&l, &g, &v0)?
        .iter()
        .filter(|y| y.im.abs() <= 1e-9 * (1.0 + y.re.abs()))
        .map(|y| y.re.abs())
        .fold(f64::INFINITY, f64::min);
    Ok(Ok(omega))
}

/// `g` without its roots at 0.
fn strip_zero_roots<F: Field>(g: &Poly<F>) -> Poly<F> {
    let f = g.field();
    let zeros = g.coeffs().iter().take_while(|c| f.is_zero(c)).count();
    Poly::new(
        f.clone(),
        g.coeffs()[zeros.min(g.coeffs().len())..].to_vec(),
    )
}
