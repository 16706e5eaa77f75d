//! The Jordan decomposition over $\mathbb{Q}(p_1, \dots, p_k)$ (symbolic parameters) as the
//! generic [`JordanForm`], valid generically, with the conditions under which it holds.
//!
//! For $A \in \mathbb{Q}(p)^{n \times n}$, [`jordan_qp`] computes one generic [`Component`]
//! per irreducible factor $g$ of $\chi_A$ over $\mathbb{Q}(p)$ ([`Component::compute`]: the
//! code $\mathbb{Q}$ uses, in $E = \mathbb{Q}(p)\[t\]/(g)$) and its primary form over
//! $\mathbb{Q}(p)$ ([`JordanForm::primary_form`]):
//! $$A T = T J \quad\text{as rational functions}, \qquad \det T \ne 0,$$
//! with $J = \operatorname{diag}(J_1, \dots, J_q)$:
//! * for every eigenvalue $\theta \in \mathbb{Q}(p)$ (a factor of degree 1 of $\chi_A$), its
//!   Jordan blocks and, in $T$, its Jordan chains ($N v_1 = 0$, $N v_j = v_{j-1}$,
//!   $N = A - \theta I$);
//! * for an irreducible factor $g$ of degree $d \ge 2$ and multiplicity $e$ (eigenvalues not
//!   in $\mathbb{Q}(p)$): in $T$ a basis $B_g$ of $\ker g(A)^e$ and in $J$ the restriction
//!   $M_g$ ($A B_g = B_g M_g$, a primary block, not a Jordan block); the block sizes of each
//!   root are the component's (chains over $E$; $\dim_{\mathbb{Q}(p)} \ker g(A)^k = d
//!   \dim_E \ker (A - tI)^k$).
//!
//! **Conditions** ([`JordanForm::conditions`]: irreducible polynomials in $p$ assumed
//! nonzero): every pivot the eliminations divided by (recorded by [`RatFuncField`]); the
//! leading coefficient in $x$ of every factor (the denominators of the eigenvalues); the
//! discriminant in $x$ of every factor of degree $\ge 2$ (its roots stay distinct); the
//! resultant in $x$ of every pair of factors (distinct eigenvalues stay distinct: for linear
//! factors the numerator of $\theta_i - \theta_j$); the numerator of $\det T$. Where none of
//! them vanishes the structure (multiplicities and block sizes) is the generic one and $T$,
//! $J$ are valid after substitution ([`JordanForm::at`]). The chains of a factor of degree
//! $\ge 2$ over $E$ (used by the free response and the real forms, not by $T$, $J$) record
//! the divisions they make in their component field's own log.
//!
//! The free response is the generic one ([`JordanForm::free_response`],
//! [`super::FreeResponse::from_state`]): its terms are rational functions when every factor
//! is linear.

use super::JordanForm;
use super::eigenvalue::{EigenValue, Eigenvalue};
use super::over_qp::charpoly_factors;
use super::primary::{Component, Restriction};
use crate::algebraic::Ext;
use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};
use crate::matrix::params::rref_params;
use crate::matrix::{Matrix, nullspace_from_rref};
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;

pub use super::over_qp::{MAX_N, integral};

/// The Jordan decomposition of a square matrix over $\mathbb{Q}(p)$ (module docs).
///
/// The computation runs in a fresh copy of the field (an empty condition log); the result's
/// matrices live over that copy, and its conditions are that log's.
///
/// # Errors
/// `NotSquare`; `Limit` for more than [`MAX_N`] rows, more than `MAX_VARS - 1` parameters,
/// or from the interpolation and factorization budgets; `Verification` when a chain
/// computation contradicts the multiplicities.
///
/// # Examples
/// ```
/// use exactlti::field::Field;
/// use exactlti::jordan::jordan_qp;
/// use exactlti::matrix::Matrix;
/// use exactlti::ratfunc::RatFuncField;
/// let k = RatFuncField::new(&["a"]).unwrap();
/// let rows = [["a", "1"], ["0", "a"]];
/// let m = Matrix::from_rows(
///     k.clone(),
///     rows.iter().map(|r| r.iter().map(|s| k.parse(s).unwrap()).collect()).collect(),
/// )
/// .unwrap();
/// let jf = jordan_qp(&m).unwrap();
/// assert_eq!(jf.components.len(), 1);
/// assert_eq!(jf.components[0].blocks, [2]);
/// assert!(jf.verified && jf.complete());
/// ```
pub fn jordan_qp(a_in: &Matrix<RatFuncField>) -> Result<JordanForm<RatFuncField>> {
    a_in.check_square("jordan")?;
    let n = a_in.nrows();
    let k = a_in.field().fresh();
    let a = Matrix::from_vec(k.clone(), n, n, a_in.as_slice().to_vec());
    let cp = charpoly_factors(&a)?;
    let components = cp
        .factors
        .iter()
        .map(|f| match f.monic.deg() {
            1 => Component::compute(&a, &f.monic, f.multiplicity, None, vec![], true),
            _ => primary_component(&a, &f.monic, f.multiplicity),
        })
        .collect::<Result<Vec<_>>>()?;
    let eigenvalues = eigenvalues_qp(&k, &components);
    let mut jf = JordanForm {
        a,
        charpoly: cp.charpoly,
        components,
        eigenvalues,
        conditions: vec![],
        verified: false,
    };
    let dim: usize = jf
        .components
        .iter()
        .map(|c| c.degree() * c.multiplicity)
        .sum();
    // the chains of the linear factors, then A T = T J for the whole primary form
    let mut verified = dim == n
        && jf
            .components
            .iter()
            .all(|c| !c.has_chains() || c.verify(&jf.a));
    if verified {
        let (t, j) = jf.primary_form()?;
        verified = jf.a.try_mul(&t)? == t.try_mul(&j)?;
        if verified {
            // det T != 0 as a rational function; its numerator's factors are conditions
            let det = t.det()?;
            verified = !k.is_zero(&det);
            k.record_because(
                det.num(),
                crate::ratfunc::Reason::StructureChange(crate::ratfunc::Structure::SingularBasis),
            );
        }
    }
    jf.conditions = k
        .conditions()?
        .into_iter()
        .map(|c| k.from_mpoly(c))
        .collect();
    jf.verified = verified;
    Ok(jf)
}

/// The eigenvalues of the components over $\mathbb{Q}(p)$, one entry per component: the
/// root $-g_0 \in \mathbb{Q}(p)$ of a linear factor $x + g_0$, else the roots of the factor
/// $g$ (its minimal polynomial over $\mathbb{Q}(p)$), with the multiplicity and the block
/// sizes of each root.
fn eigenvalues_qp(
    k: &RatFuncField,
    components: &[Component<RatFuncField>],
) -> Vec<Eigenvalue<RatFuncField>> {
    components
        .iter()
        .enumerate()
        .map(|(ci, c)| {
            let s = (ci, 0, ci + 1, c.multiplicity, c.blocks.clone());
            match c.degree() {
                1 => Eigenvalue::in_field(k.neg(&c.factor.monic().coeff(0)), s),
                _ => Eigenvalue::root_of(c.factor.monic(), s),
            }
        })
        .collect()
}

/// The component of an irreducible factor `g` of degree $d \ge 2$ and multiplicity `e` in its
/// primary-block presentation: the restriction of $A$ to $\ker g(A)^e$ over $\mathbb{Q}(p)$
/// (the canonical basis of $\ker g(A)^e$ from the RREF that gave its dimension, $A_g$ from its
/// unit rows; $A$ itself when that is the whole space) and the block sizes
/// of each root from $\dim \ker g(A)^k$ (blocks of size $\ge k$: $(\dim_k - \dim_{k-1})/d$),
/// without chains over $E$ ([`Component::has_chains`]: their normalisation $W V = I$ inverts
/// elements of $E$ whose coefficients are large; [`Component::compute`] makes them).
///
/// # Errors
/// `Verification` when $\dim \ker g(A)^e \ne d e$.
fn primary_component(
    a: &Matrix<RatFuncField>,
    g: &Poly<RatFuncField>,
    e: usize,
) -> Result<Component<RatFuncField>> {
    let (n, d) = (a.nrows(), g.deg());
    let ga = a.eval_poly(g)?;
    let mut pw = ga.clone();
    let mut dims = vec![];
    let top = loop {
        let (r, piv) = rref_params(&pw);
        dims.push(n - piv.len());
        if n - piv.len() >= d * e || dims.len() > e {
            break (r, piv);
        }
        pw = pw.try_mul(&ga)?;
    };
    if dims.last() != Some(&(d * e)) {
        return Err(Error::Verification(format!(
            "jordan over QQ(p): dim ker f(A)^{e} = {:?}, expected {}",
            dims.last(),
            d * e
        )));
    }
    // the canonical basis of ker g(A)^e from the RREF just made (no second elimination)
    let restriction = (d * e < n)
        .then(|| -> Result<Restriction<RatFuncField>> {
            let u = nullspace_from_rref(&top.0, &top.1);
            let ap = super::primary::restriction_of(a, &u)?;
            Ok(Restriction { u, ap, proj: None })
        })
        .transpose()?;
    let field = Ext::with_var(g, (0.0, 0.0), "t");
    Ok(Component {
        factor: g.clone(),
        minpoly: None,
        multiplicity: e,
        roots: vec![],
        blocks: blocks_from_dims(&dims, d),
        kernel_dims: dims.iter().map(|x| x / d).collect(),
        chains: Matrix::zeros(field.clone(), n, 0),
        left_chains: Matrix::zeros(field.clone(), 0, n),
        field,
        restriction,
    })
}

/// Block sizes (largest first) from $\dim\ker g(A)^k$, $k = 1..$, for a factor of degree `d`:
/// blocks of size $\ge k$ per root: $(\dim_k - \dim_{k-1}) / d$.
fn blocks_from_dims(dims: &[usize], d: usize) -> Vec<usize> {
    let mut ge = vec![];
    let mut prev = 0;
    for &x in dims {
        ge.push((x - prev) / d);
        prev = x;
    }
    let mut blocks = vec![];
    for (i, &g) in ge.iter().enumerate() {
        let next = ge.get(i + 1).copied().unwrap_or(0);
        for _ in 0..g.saturating_sub(next) {
            blocks.push(i + 1);
        }
    }
    blocks.sort_unstable_by(|a, b| b.cmp(a));
    blocks
}

/// The decomposition evaluated at a parameter point: `A(p0)`, `T(p0)`, `J(p0)` over
/// $\mathbb{Q}$ (see [`JordanForm::at`]).
pub type PointMatrices = (Matrix<Q>, Matrix<Q>, Matrix<Q>);

impl JordanForm<RatFuncField> {
    /// Every factor is linear: the primary form is a Jordan matrix and the free response has
    /// terms in $\mathbb{Q}(p)$.
    pub fn complete(&self) -> bool {
        self.components.iter().all(|c| c.degree() == 1)
    }
    /// The eigenvalue $\theta \in \mathbb{Q}(p)$ of each linear component (`None` for a factor
    /// of degree $\ge 2$), in component order (read off [`JordanForm::eigenvalues`], one
    /// entry per component over $\mathbb{Q}(p)$).
    pub fn values(&self) -> Vec<Option<crate::ratfunc::RatFunc>> {
        self.eigenvalues
            .iter()
            .map(|e| match e.value() {
                EigenValue::InField(x) => Some(x.clone()),
                _ => None,
            })
            .collect()
    }
    /// `(A, T, J)` at the rational point `p0` ([`JordanForm::primary_form`]); `None` when a
    /// denominator vanishes there. A caller checks $A(p_0) T(p_0) = T(p_0) J(p_0)$ and
    /// compares with the rational Jordan form.
    pub fn at(&self, p0: &[Rational]) -> Option<PointMatrices> {
        let k = self.base();
        let (t, j) = self.primary_form().ok()?;
        let ev = |m: &Matrix<RatFuncField>| -> Option<Matrix<Q>> {
            let data: Option<Vec<_>> = m.as_slice().iter().map(|x| k.eval(x, p0)).collect();
            Some(Matrix::from_vec(Q, m.nrows(), m.ncols(), data?))
        };
        Some((ev(&self.a)?, ev(&t)?, ev(&j)?))
    }
    /// Does any condition vanish at `p0`?
    pub fn conditions_vanish_at(&self, p0: &[Rational]) -> bool {
        let k = self.base();
        self.conditions
            .iter()
            .any(|c| k.eval(c, p0).is_none_or(|v| num_traits::Zero::is_zero(&v)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    fn mat(k: &RatFuncField, rows: &[&[&str]]) -> Matrix<RatFuncField> {
        let rows = rows
            .iter()
            .map(|r| r.iter().map(|s| k.parse(s).unwrap()).collect())
            .collect();
        Matrix::from_rows(k.clone(), rows).unwrap()
    }
    /// Block sizes per root from the kernel dimensions over $\mathbb{Q}(p)$ (the ranks of
    /// $g(A)^k$): $\dim \ker g(A)^k = d \dim_E \ker (A - tI)^k$.
    #[test]
    fn blocks_from_dims_counts() {
        assert_eq!(blocks_from_dims(&[1, 2, 3], 1), [3]);
        assert_eq!(blocks_from_dims(&[2, 3], 1), [2, 1]);
        assert_eq!(blocks_from_dims(&[4, 6], 2), [2, 1]);
        assert_eq!(blocks_from_dims(&[2], 2), [1]);
    }
    #[test]
    fn blocks_from_kernel_dims() {
        let k = RatFuncField::new(&["p"]).unwrap();
        // companion of x^2 - p: twice coupled (blocks [2]) and once alone (blocks [2, 1])
        let a = mat(
            &k,
            &[
                &["0", "p", "1", "0", "0", "0"],
                &["1", "0", "0", "1", "0", "0"],
                &["0", "0", "0", "p", "0", "0"],
                &["0", "0", "1", "0", "0", "0"],
                &["0", "0", "0", "0", "0", "p"],
                &["0", "0", "0", "0", "1", "0"],
            ],
        );
        let jf = jordan_qp(&a).unwrap();
        assert!(jf.verified && !jf.complete());
        let c = &jf.components[0];
        assert_eq!((c.degree(), c.multiplicity), (2, 3));
        assert_eq!(c.blocks, [2, 1]);
        let dims: Vec<usize> = c.kernel_dims.iter().map(|x| 2 * x).collect();
        assert_eq!(dims, [4, 6]);
        assert_eq!(jf.values(), [None]);
        // the integral factor: x^2 - p in Z[p, x], primitive with a positive leading
        // coefficient in lex order (p before x): p - x^2
        assert_eq!(
            integral(&c.factor).to_string_vars(&["p".into(), "s".into()]),
            "-s^2 + p"
        );
        let (t, j) = jf.primary_form().unwrap();
        assert_eq!(&jf.a * &t, &t * &j);
        // no chains over E in the form; the free response makes them and checks e^{At}
        assert!(!c.has_chains());
        let fr = jf.free_response();
        assert_eq!(fr.terms.len(), 2, "powers 0 and 1 of the one component");
        assert!(fr.verify(&jf));
    }
}
