//! Jordan decomposition over $\mathbb{Q}(p_1, \dots, p_k)$ (symbolic parameters), valid
//! generically, with the conditions under which it holds.
//!
//! For $A \in \mathbb{Q}(p)^{n \times n}$ the module computes
//! $$A T = T J \quad\text{as rational functions}, \qquad \det T \ne 0,$$
//! with $J = \operatorname{diag}(J_1, \dots, J_q)$:
//! * for every eigenvalue $\theta \in \mathbb{Q}(p)$ (a factor of degree 1 of $\chi_A$), the
//!   Jordan blocks of $\theta$ and, in $T$, its Jordan chains ($N v_1 = 0$, $N v_j = v_{j-1}$,
//!   $N = A - \theta I$; [`super::chains::jordan_chains`] over [`RatFuncField`]);
//! * for an irreducible factor $f$ of degree $d \ge 2$ and multiplicity $e$ (eigenvalues not
//!   in $\mathbb{Q}(p)$): the block structure of each root from the ranks of $f(A)^k$ (the
//!   number of blocks of size $\ge k$ is $(\operatorname{rank} f(A)^{k-1} - \operatorname{rank}
//!   f(A)^k)/d$), and in $T$ a basis $B_f$ of $\ker f(A)^e$ with the restriction $M_f$
//!   ($A B_f = B_f M_f$) as the diagonal block of $J$ (a primary block, not a Jordan block:
//!   [`ParamJordanForm::complete`] is `false` then).
//!
//! **Characteristic polynomial and its factors** over $\mathbb{Q}(p)$, with their conditions:
//! [`super::over_qp::charpoly_factors`] (shared with the generic components over
//! $\mathbb{Q}(p)$, [`super::over_qp::components_qp`], which `jordan --real` and the Jordan-method
//! realization use).
//!
//! **Conditions** (irreducible polynomials in $p$ assumed nonzero; [`ParamJordanForm::conditions`]):
//! every pivot the eliminations divided by (recorded by [`RatFuncField`]); the leading
//! coefficient in $x$ of every factor (the denominators of the eigenvalues); the
//! discriminant in $x$ of every factor of degree $\ge 2$ (its roots stay distinct); the
//! resultant in $x$ of every pair of factors (distinct eigenvalues stay distinct: for
//! linear factors this is the numerator of $\theta_i - \theta_j$); the numerator of
//! $\det T$. Where none of them vanishes the structure (eigenvalue multiplicities and block
//! sizes) is the generic one and $T$, $J$ are valid after substitution.

use super::chains::{jordan_block_matrix, jordan_chains};
use super::over_qp::{QpCharpoly, QpFactor, charpoly_factors, drop_last};
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::matrix::params::rref_params;
use crate::mpoly::MPoly;
use crate::poly::Poly;
use crate::ratfunc::{RatFunc, RatFuncField};

pub use super::over_qp::MAX_N;

/// One irreducible factor of $\chi_A$ over $\mathbb{Q}(p)$ and its eigenvalues.
#[derive(Clone, Debug, PartialEq)]
pub struct ParamEigenvalue {
    /// The factor in $\mathbb{Z}\lbrack p, x\rbrack$ ($x$ is the last variable): primitive,
    /// irreducible, positive leading coefficient.
    pub factor: MPoly,
    /// The factor made monic over $\mathbb{Q}(p)$ (low degree first).
    pub monic: Poly<RatFuncField>,
    /// Degree in $x$ (number of roots).
    pub degree: usize,
    /// The eigenvalue when it lies in $\mathbb{Q}(p)$ (degree 1).
    pub value: Option<RatFunc>,
    /// Multiplicity of the factor in $\chi_A$ (algebraic multiplicity of each root).
    pub algebraic_multiplicity: usize,
    /// Number of Jordan blocks of each root.
    pub geometric_multiplicity: usize,
    /// Jordan block sizes of each root, largest first.
    pub blocks: Vec<usize>,
    /// $\dim \ker f(A)^k$, $k = 1, 2, \dots$ (for degree 1: $\dim\ker (A - \theta I)^k$).
    pub kernel_dims: Vec<usize>,
    /// First column of this factor's columns in $T$, and their number ($d e$).
    pub offset: usize,
    pub width: usize,
}

/// The Jordan decomposition of a matrix over $\mathbb{Q}(p)$ (see the module docs).
#[derive(Clone, Debug)]
pub struct ParamJordanForm {
    /// The field of the result (its condition log holds this computation's divisors).
    pub field: RatFuncField,
    /// The input matrix (over [`ParamJordanForm::field`]).
    pub a: Matrix<RatFuncField>,
    /// $\chi_A(x) = \det(xI - A)$, monic, low degree first.
    pub charpoly: Poly<RatFuncField>,
    /// $\chi_A$ with cleared denominators in $\mathbb{Z}\lbrack p, x\rbrack$ (`x` last).
    pub charpoly_integral: MPoly,
    /// One entry per irreducible factor of $\chi_A$ with positive degree in $x$.
    pub eigenvalues: Vec<ParamEigenvalue>,
    /// $J$: Jordan blocks of the eigenvalues in $\mathbb{Q}(p)$, primary blocks $M_f$ else.
    pub j: Matrix<RatFuncField>,
    /// $T$ with $A T = T J$.
    pub t: Matrix<RatFuncField>,
    /// Every eigenvalue lies in $\mathbb{Q}(p)$: `J` is a Jordan matrix.
    pub complete: bool,
    /// Irreducible polynomials in the parameters assumed nonzero, sorted.
    pub conditions: Vec<MPoly>,
    /// $A T = T J$ holds as rational functions, $T$ is square of full rank, and the factor
    /// dimensions add up to $n$.
    pub verified: bool,
}

impl ParamJordanForm {
    /// Size of the matrix.
    pub fn n(&self) -> usize {
        self.a.nrows()
    }
    /// Name used for the eigenvalue variable in displays: `s` unless a parameter is
    /// called so (then `x`, then `lambda_`).
    pub fn var_name(&self) -> String {
        var_name(self.field.vars())
    }
    /// Display of a factor in the parameters and [`ParamJordanForm::var_name`].
    pub fn fmt_factor(&self, f: &MPoly) -> String {
        let mut vars = self.field.vars().to_vec();
        vars.push(self.var_name());
        f.to_string_vars(&vars)
    }
    /// Conditions as display strings.
    pub fn conditions_strings(&self) -> Vec<String> {
        self.conditions
            .iter()
            .map(|p| p.display_normalized().to_string_vars(self.field.vars()))
            .collect()
    }
    /// The eigenvalue with value `v` (in $\mathbb{Q}(p)$), if any.
    pub fn eigenvalue(&self, v: &RatFunc) -> Option<&ParamEigenvalue> {
        self.eigenvalues
            .iter()
            .find(|e| e.value.as_ref() == Some(v))
    }
    /// The eigenvalue variable is `x`-last; the discriminant of $\chi_A$'s squarefree part
    /// etc. live in the parameters only: this drops the (unused) last variable.
    pub fn drop_x(&self, f: &MPoly) -> MPoly {
        drop_last(f)
    }
}

fn var_name(vars: &[String]) -> String {
    for c in ["s", "x", "lambda_"] {
        if !vars.iter().any(|v| v == c) {
            return c.to_string();
        }
    }
    "lambda__".to_string()
}

/// The Jordan decomposition of a square matrix over $\mathbb{Q}(p)$ (module docs).
///
/// The computation runs in a fresh copy of the field (an empty condition log); the result's
/// [`ParamJordanForm::field`] is that copy and its matrices live over it.
///
/// # Errors
/// `NotSquare`; `Limit` for more than [`MAX_N`] rows, more than `MAX_VARS - 1` parameters,
/// or from the interpolation and factorization budgets; `Verification` when a chain
/// computation contradicts the multiplicities.
///
/// # Examples
/// ```
/// use exactlti::field::Field;
/// use exactlti::jordan::params::jordan_params;
/// use exactlti::matrix::Matrix;
/// use exactlti::ratfunc::RatFuncField;
/// let k = RatFuncField::new(&["a"]).unwrap();
/// let rows = [["a", "1"], ["0", "a"]];
/// let m = Matrix::from_rows(
///     k.clone(),
///     rows.iter().map(|r| r.iter().map(|s| k.parse(s).unwrap()).collect()).collect(),
/// )
/// .unwrap();
/// let jf = jordan_params(&m).unwrap();
/// assert_eq!(jf.eigenvalues.len(), 1);
/// assert_eq!(jf.eigenvalues[0].blocks, [2]);
/// assert!(jf.verified && jf.complete);
/// ```
pub fn jordan_params(a_in: &Matrix<RatFuncField>) -> Result<ParamJordanForm> {
    a_in.check_square("jordan")?;
    let n = a_in.nrows();
    let k = a_in.field().fresh();
    let a = Matrix::from_vec(k.clone(), n, n, a_in.as_slice().to_vec());
    let QpCharpoly {
        charpoly: chi,
        integral: big_f,
        factors: facs,
    } = charpoly_factors(&a)?;
    let mut eigenvalues = Vec::with_capacity(facs.len());
    let mut t_cols: Vec<Matrix<RatFuncField>> = vec![];
    let mut j_blocks: Vec<Matrix<RatFuncField>> = vec![];
    let mut complete = true;
    let mut offset = 0;
    for QpFactor {
        factor: f,
        monic,
        multiplicity: e,
    } in facs
    {
        let e = &e;
        let d = monic.deg();
        if d == 1 {
            let theta = k.neg(monic.coeffs().first().expect("degree 1"));
            let mut nm = a.clone();
            for i in 0..n {
                let v = k.sub(nm.get(i, i), &theta);
                nm.set(i, i, v);
            }
            let ch = jordan_chains(&nm, *e)?;
            if ch.v.ncols() != *e {
                return Err(Error::Verification(
                    "jordan over QQ(p): chain count differs from the multiplicity".into(),
                ));
            }
            j_blocks.push(jordan_block_matrix(&k, &theta, &ch.blocks));
            t_cols.push(ch.v);
            eigenvalues.push(ParamEigenvalue {
                factor: f.clone(),
                monic,
                degree: 1,
                value: Some(theta),
                algebraic_multiplicity: *e,
                geometric_multiplicity: ch.blocks.len(),
                blocks: ch.blocks,
                kernel_dims: ch.kernel_dims,
                offset,
                width: *e,
            });
            offset += *e;
        } else {
            complete = false;
            let fa = a.eval_poly(&monic)?;
            let mut pw = fa.clone();
            let mut dims = vec![];
            loop {
                let (_, piv) = rref_params(&pw);
                let dim = n - piv.len();
                dims.push(dim);
                if dim >= d * e || dims.len() > *e {
                    break;
                }
                pw = pw.try_mul(&fa)?;
            }
            let top = *dims.last().expect("one level");
            if top != d * e {
                return Err(Error::Verification(format!(
                    "jordan over QQ(p): dim ker f(A)^{e} = {top}, expected {}",
                    d * e
                )));
            }
            let blocks = blocks_from_dims(&dims, d);
            let basis = pw.nullspace();
            // restriction: A B = B M through independent rows of B
            let (_, rows) = basis.transpose().rref();
            let b_sub = basis.select_rows(&rows);
            let ab = a.try_mul(&basis)?;
            let m = b_sub.inverse()?.try_mul(&ab.select_rows(&rows))?;
            j_blocks.push(m);
            t_cols.push(basis);
            eigenvalues.push(ParamEigenvalue {
                factor: f.clone(),
                monic,
                degree: d,
                value: None,
                algebraic_multiplicity: *e,
                geometric_multiplicity: blocks.len(),
                blocks,
                kernel_dims: dims,
                offset,
                width: d * e,
            });
            offset += d * e;
        }
    }
    let mut t = Matrix::zeros(k.clone(), n, offset);
    let mut c0 = 0;
    for c in &t_cols {
        t.set_block(0, c0, c);
        c0 += c.ncols();
    }
    let j = Matrix::block_diag(k.clone(), &j_blocks);
    let mut verified = offset == n && a.try_mul(&t)? == t.try_mul(&j)?;
    if verified {
        // det T != 0 as a rational function; its numerator's factors are conditions
        let det = t.det()?;
        verified = !k.is_zero(&det);
        k.record_condition(det.num());
    }
    let conditions = k.conditions()?;
    Ok(ParamJordanForm {
        field: k,
        a,
        charpoly: chi,
        charpoly_integral: big_f,
        eigenvalues,
        j,
        t,
        complete,
        conditions,
        verified,
    })
}

/// Block sizes (largest first) from $\dim\ker f(A)^k$, $k = 1..$, for a factor of degree `d`:
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

/// The Jordan decomposition evaluated at a parameter point: `A(p0)`, `T(p0)`, `J(p0)`
/// over $\mathbb{Q}$, `None` when a denominator vanishes there. A caller checks
/// $A(p_0) T(p_0) = T(p_0) J(p_0)$ and compares with the rational Jordan form.
pub type PointMatrices = (
    Matrix<crate::field::Q>,
    Matrix<crate::field::Q>,
    Matrix<crate::field::Q>,
);

impl ParamJordanForm {
    /// `(A, T, J)` at the rational point `p0` (see [`PointMatrices`]).
    pub fn at(&self, p0: &[crate::field::Rational]) -> Option<PointMatrices> {
        let k = &self.field;
        let ev = |m: &Matrix<RatFuncField>| -> Option<Matrix<crate::field::Q>> {
            let data: Option<Vec<_>> = m.as_slice().iter().map(|x| k.eval(x, p0)).collect();
            Some(Matrix::from_vec(
                crate::field::Q,
                m.nrows(),
                m.ncols(),
                data?,
            ))
        };
        Some((ev(&self.a)?, ev(&self.t)?, ev(&self.j)?))
    }
    /// Does any condition vanish at `p0`?
    pub fn conditions_vanish_at(&self, p0: &[crate::field::Rational]) -> bool {
        let k = &self.field;
        self.conditions.iter().any(|c| {
            k.eval(&k.from_mpoly(c.clone()), p0)
                .is_none_or(|v| num_traits::Zero::is_zero(&v))
        })
    }
}

/// The free response $x(t) = e^{At} x_0$ in closed form over $\mathbb{Q}(p)$:
/// $x(t) = \sum_\theta e^{\theta t} \sum_k t^k g_{\theta,k}$ with
/// $g_{\theta,k} = T_\theta N_\theta^k c_\theta / k!$, $c = T^{-1} x_0$ ($N_\theta$ the
/// nilpotent part of $J_\theta$).
#[derive(Clone, Debug)]
pub struct ParamResponse {
    /// Per eigenvalue in $\mathbb{Q}(p)$: its value and $g_{\theta,0}, g_{\theta,1}, \dots$.
    pub terms: Vec<(RatFunc, Vec<Vec<RatFunc>>)>,
    /// $\sum_\theta g_{\theta,0} = x_0$ and $A g_{\theta,k} = \theta g_{\theta,k} +
    /// (k+1) g_{\theta,k+1}$ (i.e. $\dot x = A x$) hold as rational functions.
    pub verified: bool,
}

impl ParamJordanForm {
    /// The closed-form free response from `x0` (entries in [`ParamJordanForm::field`]);
    /// `None` when not every eigenvalue lies in $\mathbb{Q}(p)$ or the sizes differ.
    ///
    /// # Errors
    /// `Singular` if $T$ is singular (not for a verified form).
    pub fn free_response(&self, x0: &[RatFunc]) -> Result<Option<ParamResponse>> {
        let n = self.n();
        if !self.complete || x0.len() != n {
            return Ok(None);
        }
        let k = &self.field;
        let c = self
            .t
            .inverse()?
            .try_mul(&Matrix::column(k.clone(), x0.to_vec()))?;
        let mut terms = vec![];
        let mut sum0 = vec![k.zero(); n];
        let mut verified = true;
        for e in &self.eigenvalues {
            let theta = e.value.clone().expect("complete");
            let mut gs: Vec<Vec<RatFunc>> = vec![];
            let mut off = e.offset;
            for &b in &e.blocks {
                // block columns off..off+b: chain v_1..v_b, coordinates c_off..c_{off+b-1};
                // e^{Jt} c on the block: coordinate i gets sum_k t^k/k! c_{i+k}
                for kk in 0..b {
                    if gs.len() <= kk {
                        gs.push(vec![k.zero(); n]);
                    }
                    let fact = k.from_rational(&crate::field::Rational::from_integer(
                        (1..=kk as u64).product::<u64>().into(),
                    ));
                    for i in 0..b - kk {
                        let coef = k
                            .div_unrecorded(c.get(off + i + kk, 0), &fact)
                            .expect("k! > 0");
                        for r in 0..n {
                            let v = k.add(&gs[kk][r], &k.mul(self.t.get(r, off + i), &coef));
                            gs[kk][r] = v;
                        }
                    }
                }
                off += b;
            }
            for (r, s) in sum0.iter_mut().enumerate() {
                if let Some(g0) = gs.first() {
                    *s = k.add(s, &g0[r]);
                }
            }
            for kk in 0..gs.len() {
                let ag = self.a.try_mul(&Matrix::column(k.clone(), gs[kk].clone()))?;
                for r in 0..n {
                    let mut want = k.mul(&theta, &gs[kk][r]);
                    if let Some(next) = gs.get(kk + 1) {
                        want = k.add(&want, &k.mul(&k.from_i64(kk as i64 + 1), &next[r]));
                    }
                    verified &= ag.get(r, 0) == &want;
                }
            }
            terms.push((theta, gs));
        }
        verified &= sum0.as_slice() == x0;
        Ok(Some(ParamResponse { terms, verified }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn blocks_from_kernel_dims() {
        assert_eq!(blocks_from_dims(&[1, 2, 3], 1), [3]);
        assert_eq!(blocks_from_dims(&[2, 3], 1), [2, 1]);
        assert_eq!(blocks_from_dims(&[4, 6], 2), [2, 1]);
        assert_eq!(blocks_from_dims(&[2], 2), [1]);
    }
}
