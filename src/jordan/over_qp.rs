//! $\mathbb{Q}(p_1, \dots, p_k)$ as a base field of the generic Jordan components: the
//! irreducible factors of $\chi_A$ over $\mathbb{Q}(p)$ with the conditions under which the
//! structure is the generic one, and one [`Component`] per factor in
//! $E = \mathbb{Q}(p)\[t\]/(g)$ ([`Component::compute`], the code $\mathbb{Q}$ uses).
//!
//! **Characteristic polynomial.** $\chi_A$ by [`crate::matrix::params::charpoly_ratfunc`]
//! (evaluation/interpolation over $\mathbb{Z}\lbrack p\rbrack$), denominators cleared, then
//! factored in $\mathbb{Z}\lbrack p, x\rbrack$ by [`crate::mpoly::factor()`] (irreducible over
//! $\mathbb{Q}(p)$ by Gauss's lemma); factors free of $x$ are dropped.
//!
//! **Conditions** recorded in the field's log (irreducible polynomials in $p$ assumed
//! nonzero): the leading coefficient in $x$ of every factor (the denominators of the
//! eigenvalues); the discriminant in $x$ of every factor of degree $\ge 2$ (its roots stay
//! distinct); the resultant in $x$ of every pair of factors (distinct eigenvalues stay
//! distinct). The eliminations of the components add their pivots.

use super::primary::{Component, Restriction, restriction_of};
use crate::algebraic::Ext;
use crate::error::{Error, Result};
use crate::matrix::Matrix;
use crate::matrix::nullspace_from_rref;
use crate::matrix::params::charpoly_ratfunc;
use crate::matrix::params::rref_params;
use crate::mpoly::factor::cmp_poly;
use crate::mpoly::resultant::{discriminant, resultant};
use crate::mpoly::{MAX_VARS, MPoly, factor};
use crate::poly::Poly;
use crate::ratfunc::{RatFunc, RatFuncField, Reason, Structure};

/// Largest matrix the decomposition over $\mathbb{Q}(p)$ accepts (expression swell grows
/// fast with `n`).
pub const MAX_N: usize = 24;

/// One irreducible factor of $\chi_A$ over $\mathbb{Q}(p)$.
#[derive(Clone, Debug, PartialEq)]
pub struct QpFactor {
    /// In $\mathbb{Z}\lbrack p, x\rbrack$ ($x$ is the last variable): primitive, irreducible,
    /// positive leading coefficient.
    pub factor: MPoly,
    /// The factor made monic over $\mathbb{Q}(p)$ (low degree first).
    pub monic: Poly<RatFuncField>,
    /// Multiplicity in $\chi_A$.
    pub multiplicity: usize,
}

/// $\chi_A$ over $\mathbb{Q}(p)$ and its irreducible factors (module docs).
#[derive(Clone, Debug)]
pub struct QpCharpoly {
    /// $\chi_A(x) = \det(xI - A)$, monic, low degree first.
    pub charpoly: Poly<RatFuncField>,
    /// $\chi_A$ with cleared denominators in $\mathbb{Z}\lbrack p, x\rbrack$ (`x` last).
    pub integral: MPoly,
    /// Sorted by degree, then multiplicity (descending), then the factor.
    pub factors: Vec<QpFactor>,
}

/// Drops the last variable (which must not occur).
pub(crate) fn drop_last(f: &MPoly) -> MPoly {
    let n = f.nvars() - 1;
    let map: Vec<usize> = (0..n).collect();
    f.remap(n, &map)
}

/// `c` in the field, for a polynomial of `nv + 1` variables free of the last one.
fn coeff_to_field(k: &RatFuncField, c: &MPoly) -> RatFunc {
    k.from_mpoly(drop_last(c))
}

/// The factorization of $\chi_A$ over $\mathbb{Q}(p)$ with its conditions recorded in
/// `a`'s field (module docs).
///
/// # Errors
/// `NotSquare`; `Limit` for more than [`MAX_N`] rows, more than `MAX_VARS - 1` parameters,
/// or from the interpolation and factorization budgets.
pub fn charpoly_factors(a: &Matrix<RatFuncField>) -> Result<QpCharpoly> {
    a.check_square("jordan")?;
    let n = a.nrows();
    if n > MAX_N {
        return Err(Error::Limit(format!(
            "jordan over QQ(p): at most {MAX_N} states (this matrix has {n})"
        )));
    }
    let k = a.field();
    let nv = k.nvars();
    if nv + 1 > MAX_VARS {
        return Err(Error::Limit(format!(
            "jordan over QQ(p): at most {} parameters",
            MAX_VARS - 1
        )));
    }
    let chi = charpoly_ratfunc(a)?;
    // clear denominators: F = L chi in Z[p][x], x = variable nv
    let integral = integral(&chi);
    let fz = if n == 0 {
        vec![]
    } else {
        factor(&integral)?.factors
    };
    let mut facs: Vec<(MPoly, usize)> = fz.into_iter().filter(|(g, _)| g.deg(nv) > 0).collect();
    facs.sort_by(|(f, e), (g, d)| {
        f.deg(nv)
            .cmp(&g.deg(nv))
            .then(d.cmp(e))
            .then_with(|| cmp_poly(f, g))
    });
    for (i, (f, _)) in facs.iter().enumerate() {
        let why = |s| Reason::StructureChange(s);
        k.record_because(&drop_last(&f.lc_in(nv)), why(Structure::FactorDegree));
        if f.deg(nv) >= 2 {
            let d = drop_last(&discriminant(f, nv));
            k.record_because(&d, why(Structure::RepeatedEigenvalue));
        }
        for (g, _) in &facs[i + 1..] {
            let r = drop_last(&resultant(f, g, nv));
            k.record_because(&r, why(Structure::EigenvaluesMeet));
        }
    }
    let factors = facs
        .into_iter()
        .map(|(f, e)| {
            let d = f.deg(nv) as usize;
            let coeffs = f.to_univariate(nv);
            let lc = coeff_to_field(k, &coeffs[d]);
            let monic = coeffs
                .iter()
                .map(|c| {
                    k.div_unrecorded(&coeff_to_field(k, c), &lc)
                        .expect("nonzero leading coefficient")
                })
                .collect();
            QpFactor {
                factor: f,
                monic: Poly::new(k.clone(), monic),
                multiplicity: e,
            }
        })
        .collect();
    Ok(QpCharpoly {
        charpoly: chi,
        integral,
        factors,
    })
}

/// One [`Component`] per factor of $\chi_A$ over $\mathbb{Q}(p)$: chains of $A - \theta I$
/// over $\mathbb{Q}(p)$ for an eigenvalue $\theta \in \mathbb{Q}(p)$, else chains of the
/// primary block (the restriction of $A$ to $\ker g(A)^e$) over $E = \mathbb{Q}(p)\[t\]/(g)$.
/// Conditions (factor data and pivots) go to `a`'s field.
///
/// # Errors
/// Those of [`charpoly_factors`]; `Verification` when a kernel contradicts the
/// multiplicities.
pub fn components_qp(
    a: &Matrix<RatFuncField>,
) -> Result<(QpCharpoly, Vec<Component<RatFuncField>>)> {
    let cp = charpoly_factors(a)?;
    let comps = cp
        .factors
        .iter()
        .map(|f| Component::compute(a, &f.monic, f.multiplicity, None, vec![], true))
        .collect::<Result<Vec<_>>>()?;
    Ok((cp, comps))
}

/// The component of a simple factor `g` (multiplicity 1) as its primary block over
/// $\mathbb{Q}(p)$, without chains over $E$: the restriction $A_g$ of $A$ to $\ker g(A)$
/// ($u$ its canonical basis, $A u = u A_g$) and the projector $P$ along $\operatorname{im}
/// g(A)$ ($P u = I$, $P A = A_g P$); both null spaces from the fraction-free RREF
/// ([`rref_params`], no gcd per operation). No restriction when $\deg g = n$ ($A$ itself).
/// A minimal realization needs nothing more: $(A_g, P B, C u)$ is the component's part of
/// $C (sI - A)^{-1} B$, minimal as soon as $P B \ne 0$ and $C u \ne 0$ ($g$ irreducible: the
/// only invariant subspaces of $A_g$ are $0$ and everything).
///
/// # Errors
/// `Verification` when a null space does not have dimension $\deg g$.
pub fn simple_primary_component(
    a: &Matrix<RatFuncField>,
    g: &Poly<RatFuncField>,
) -> Result<Component<RatFuncField>> {
    let (n, d) = (a.nrows(), g.deg());
    let restriction = if d < n {
        let ga = a.eval_poly(&g.monic())?;
        let null = |m: &Matrix<RatFuncField>| {
            let (r, piv) = rref_params(m);
            nullspace_from_rref(&r, &piv)
        };
        let (u, l) = (null(&ga), null(&ga.transpose()));
        if u.ncols() != d || l.ncols() != d {
            return Err(Error::Verification(format!(
                "jordan over QQ(p): dim ker g(A) = {} (left {}), expected {d}",
                u.ncols(),
                l.ncols()
            )));
        }
        let ap = restriction_of(a, &u)?;
        let lt = l.transpose();
        let proj = lt.try_mul(&u)?.inverse()?.try_mul(&lt)?;
        Some(Restriction {
            u,
            ap,
            proj: Some(proj),
        })
    } else {
        None
    };
    let field = Ext::with_var(g, (0.0, 0.0), "t");
    Ok(Component {
        factor: g.clone(),
        minpoly: None,
        multiplicity: 1,
        roots: vec![],
        blocks: vec![1],
        kernel_dims: vec![1],
        chains: Matrix::zeros(field.clone(), n, 0),
        left_chains: Matrix::zeros(field.clone(), 0, n),
        field,
        restriction,
    })
}

/// The real Jordan form over $\mathbb{Q}(p)$: eigenvalues in $\mathbb{Q}(p)$ with their
/// chains, the pair of each quadratic factor in its real form
/// ([`super::real_quadratic::quadratic_real`], `w<k>` for the $k$-th pair) with the sign
/// condition that makes it a complex pair.
#[derive(Clone, Debug)]
pub struct QpRealForm {
    /// The input matrix (in the fresh field holding this computation's conditions).
    pub a: Matrix<RatFuncField>,
    pub charpoly: QpCharpoly,
    pub components: Vec<Component<RatFuncField>>,
    /// Per component: the real form of a quadratic factor, `None` for a linear one.
    pub pairs: Vec<Option<super::real_quadratic::QuadraticReal<RatFuncField>>>,
    /// Every component's identities and every pair's $A T = T J_{\mathbb R}$ held exactly.
    pub verified: bool,
}

/// [`QpRealForm`] of a square matrix over $\mathbb{Q}(p)$.
///
/// # Errors
/// Those of [`components_qp`]; `Unsupported` for an irreducible factor of degree $\ge 3$:
/// its roots are not $\alpha \pm i\omega$ with $\alpha \in \mathbb{Q}(p)$ and $\omega^2 \in
/// \mathbb{Q}(p)$, so no real form with entries in $\mathbb{Q}(p)$ adjoined one square root
/// exists for them.
pub fn real_form_qp(a_in: &Matrix<RatFuncField>) -> Result<QpRealForm> {
    let k = a_in.field().fresh();
    let n = a_in.nrows();
    let a = Matrix::from_vec(k, n, a_in.ncols(), a_in.as_slice().to_vec());
    let (charpoly, components) = components_qp(&a)?;
    let mut pairs = vec![];
    let mut verified = true;
    for c in &components {
        verified &= c.verify(&a);
        match c.degree() {
            1 => pairs.push(None),
            2 => {
                let var = format!("w{}", pairs.iter().flatten().count() + 1);
                let r = super::real_quadratic::quadratic_real(&a, c, &var).ok_or_else(|| {
                    Error::Verification("a quadratic factor without a real form".into())
                })?;
                verified &= r.verified;
                pairs.push(Some(r));
            }
            d => {
                return Err(Error::Unsupported(format!(
                    "jordan --real over QQ(p): the factor {} has degree {d}; its roots are not \
                     a +- i w with a and w^2 in the parameters' field, so the real form is \
                     written for eigenvalues in QQ(p) and quadratic factors only",
                    c.factor.to_string_var("s")
                )));
            }
        }
    }
    Ok(QpRealForm {
        a,
        charpoly,
        components,
        pairs,
        verified,
    })
}

/// A monic polynomial over $\mathbb{Q}(p)$ with denominators cleared: in
/// $\mathbb{Z}\lbrack p, x\rbrack$ ($x$ the last variable), primitive, positive (lex) leading
/// coefficient. For an irreducible factor of $\chi_A$ this is the factor as
/// [`crate::mpoly::factor()`] writes it.
pub fn integral(f: &Poly<RatFuncField>) -> MPoly {
    let nv = f.field().nvars();
    let (nums, _) = crate::ratfunc::kernels::clear_common(nv, f.coeffs());
    let cs: Vec<MPoly> = nums.iter().map(|s| s.extend_vars(nv + 1)).collect();
    MPoly::from_univariate(nv + 1, nv, &cs).primitive_part()
}
