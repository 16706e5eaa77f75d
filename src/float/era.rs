//! Markov parameters and the eigensystem realization algorithm (ERA).
//!
//! Markov parameters: $M_0 = D$, $M_k = C A^{k-1} B$ ($k \ge 1$). ERA (Juang and Pappa; the
//! minimal-realizations paper, eq. 10-15) takes the block Hankel matrices
//! $H_0 = [M_{i+j+1}]_{i<r,\,j<s}$ and $H_1 = [M_{i+j+2}]_{i<r,\,j<s}$, the SVD
//! $H_0 = U \Sigma V^T$ (one-sided Jacobi) truncated to the numerical rank (or a requested order) $n$, and
//!
//! $$A = \Sigma_n^{-1/2} U_n^T H_1 V_n \Sigma_n^{-1/2},\quad
//!   B = \Sigma_n^{1/2} V_n^T \begin{bmatrix} I_m \\ 0 \end{bmatrix},\quad
//!   C = \begin{bmatrix} I_p & 0 \end{bmatrix} U_n \Sigma_n^{1/2},\quad D = M_0.$$
//!
//! When $H_0$ has exact rank equal to the McMillan degree, this realization is minimal and
//! reproduces every Markov parameter.
//!
//! | entry point             | returns                              |
//! |-------------------------|--------------------------------------|
//! | [`markov_parameters`]   | $M_0, \dots, M_{k-1}$                |
//! | [`era`]                 | [`FloatRealization`]                 |

use super::svd::jacobi_svd;
use nalgebra::DMatrix;

use super::{FloatScalar, RankGap, Tol, Truth, check_finite, check_system, decide_rank};
use crate::error::{Error, Result};

/// A realization computed from Markov parameters, with its diagnostics.
#[derive(Clone, Debug, PartialEq)]
pub struct FloatRealization<T: FloatScalar = f64> {
    /// State matrix (`order x order`).
    pub a: DMatrix<T>,
    /// Input matrix (`order x m`).
    pub b: DMatrix<T>,
    /// Output matrix (`p x order`).
    pub c: DMatrix<T>,
    /// Feedthrough `M_0`.
    pub d: DMatrix<T>,
    /// The order used.
    pub order: usize,
    /// Block rows and block columns of the Hankel matrices.
    pub hankel_blocks: (usize, usize),
    /// Singular values of $H_0$, descending.
    pub singular_values: Vec<f64>,
    /// The rank decision on $H_0$.
    pub rank_gap: RankGap,
    /// `True` when the rank gap is clear, the order equals the numerical rank, the Hankel
    /// matrix is larger than its rank (so the McMillan degree was reached), and the dropped
    /// singular values are at the rounding floor (`sqrt(gap) * ε σ_1 k`).
    pub truth: Truth,
}

/// The first `k` Markov parameters `D, CB, CAB, ..., C A^{k-2} B`.
///
/// # Errors
/// Shape errors and non-finite entries, as [`super::minreal`].
pub fn markov_parameters<T: FloatScalar>(
    a: &DMatrix<T>,
    b: &DMatrix<T>,
    c: &DMatrix<T>,
    d: &DMatrix<T>,
    k: usize,
) -> Result<Vec<DMatrix<T>>> {
    check_system("markov_parameters", a, b, c, d)?;
    let mut out = Vec::with_capacity(k);
    if k == 0 {
        return Ok(out);
    }
    out.push(d.clone());
    let mut x = b.clone();
    for i in 1..k {
        out.push(c * &x);
        if i + 1 < k {
            x = a * &x;
        }
    }
    Ok(out)
}

/// ERA realization from Markov parameters `markov[0] = D, markov[k] = C A^{k-1} B`.
///
/// With `order = None` the order is the numerical rank of $H_0$; `Some(n)` truncates to `n`.
///
/// # Examples
/// ```
/// use exactlti::float::{era, markov_parameters, Tol, Truth};
/// use nalgebra::DMatrix;
/// let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, -2.0, -3.0]);
/// let b = DMatrix::from_row_slice(2, 1, &[0.0, 1.0]);
/// let c = DMatrix::from_row_slice(1, 2, &[1.0, 0.0]);
/// let d = DMatrix::zeros(1, 1);
/// let h = markov_parameters(&a, &b, &c, &d, 8).unwrap();
/// let r = era(&h, None, &Tol::default()).unwrap();
/// assert_eq!((r.order, r.truth), (2, Truth::True));
/// ```
///
/// # Errors
/// [`Error::Invalid`] for fewer than three parameters, parameters of different shapes,
/// non-finite entries, or a requested order larger than the Hankel matrix or beyond a zero
/// singular value.
pub fn era<T: FloatScalar>(
    markov: &[DMatrix<T>],
    order: Option<usize>,
    tol: &Tol,
) -> Result<FloatRealization<T>> {
    era_scaled(markov, order, 0.0, tol)
}

/// [`era`] with the rank threshold relative to `scale` (at least $\sigma_1(H_0)$): the size
/// the Markov parameters have before cancellation, so that Markov parameters that are all
/// rounding noise give order 0, not a full rank of noise.
fn era_scaled<T: FloatScalar>(
    markov: &[DMatrix<T>],
    order: Option<usize>,
    scale: f64,
    tol: &Tol,
) -> Result<FloatRealization<T>> {
    if markov.len() < 3 {
        return Err(Error::Invalid(format!(
            "era: need at least 3 Markov parameters (D, CB, CAB), got {}",
            markov.len()
        )));
    }
    let (p, m) = markov[0].shape();
    if p == 0 || m == 0 {
        return Err(Error::Invalid(format!(
            "era: Markov parameters are {p}x{m}; need at least one input and one output"
        )));
    }
    for h in markov {
        if h.shape() != (p, m) {
            return Err(Error::Shape {
                op: "era",
                expected: (p, m),
                found: h.shape(),
            });
        }
        check_finite("era", h)?;
    }
    let moments = markov.len() - 1;
    let r = moments / 2;
    let s = moments - r;
    check_hankel_size(r * p, s * m)?;
    let hankel = |shift: usize| {
        let mut h = DMatrix::<T>::zeros(r * p, s * m);
        for i in 0..r {
            for j in 0..s {
                h.view_mut((i * p, j * m), (p, m))
                    .copy_from(&markov[i + j + 1 + shift]);
            }
        }
        h
    };
    let h0 = hankel(0);
    let h1 = hankel(1);
    let k = (r * p).min(s * m);
    // One-sided Jacobi rotates columns: run it on the narrower side (a wide H0 through its
    // transpose) so that the orthogonal factor is k x k, not (s m) x (s m).
    // un = U (left singular vectors, r p x k), vk = V (right, s m x k), sv descending.
    let (sv, un_all, vk_all) = if r * p >= s * m {
        let svd = jacobi_svd(h0);
        let sv: Vec<f64> = svd.sv[..k].to_vec();
        let u = DMatrix::from_fn(r * p, k, |i, j| {
            if sv[j] > 0.0 {
                svd.w[(i, j)].unscale(sv[j])
            } else {
                T::zero()
            }
        });
        (sv, u, svd.v.columns(0, k).into_owned())
    } else {
        let svd = jacobi_svd(h0.adjoint());
        let sv: Vec<f64> = svd.sv[..k].to_vec();
        let v = DMatrix::from_fn(s * m, k, |i, j| {
            if sv[j] > 0.0 {
                svd.w[(i, j)].unscale(sv[j])
            } else {
                T::zero()
            }
        });
        (sv, svd.v.columns(0, k).into_owned(), v)
    };
    let gap = decide_rank("rank H0", &sv, scale, tol);
    let maxrank = sv.len();
    let n = order.unwrap_or(gap.rank);
    if n > maxrank {
        return Err(Error::Invalid(format!(
            "era: order {n} exceeds the Hankel matrix size {maxrank}; supply more Markov parameters"
        )));
    }
    if n > 0 && sv[n - 1] <= 0.0 {
        return Err(Error::Invalid(format!(
            "era: order {n} reaches a zero singular value of the Hankel matrix"
        )));
    }
    let sq: Vec<f64> = sv[..n].iter().map(|x| x.sqrt()).collect();
    let un = un_all.columns(0, n).into_owned();
    let vtn = vk_all.columns(0, n).adjoint();
    let mut a = un.adjoint() * &h1 * vtn.adjoint();
    for i in 0..n {
        for j in 0..n {
            a[(i, j)] = a[(i, j)].unscale(sq[i] * sq[j]);
        }
    }
    let b = DMatrix::from_fn(n, m, |i, j| vtn[(i, j)].scale(sq[i]));
    let c = DMatrix::from_fn(p, n, |i, j| un[(i, j)].scale(sq[j]));
    let saturated = gap.rank >= maxrank;
    // Markov parameters of a finite system give a Hankel matrix whose discarded singular
    // values are rounding noise; dropped values far above that floor mean the fast modes
    // swamped the slow ones (the paper's sec. 4 ERA failure), so the order is not trusted.
    let floor = f64::EPSILON * scale.max(sv.first().copied().unwrap_or(0.0)) * sv.len() as f64;
    let noise_only = gap.dropped <= tol.gap.max(1.0).sqrt() * floor;
    let truth = if gap.truth == Truth::True && n == gap.rank && !saturated && noise_only {
        Truth::True
    } else {
        Truth::Unknown
    };
    Ok(FloatRealization {
        a,
        b,
        c,
        d: markov[0].clone(),
        order: n,
        hankel_blocks: (r, s),
        singular_values: sv,
        rank_gap: gap,
        truth,
    })
}

/// Largest Hankel matrix (entries) the float ERA builds: 2^22 (32 MB of `f64`).
pub const HANKEL_ENTRY_LIMIT: usize = 1 << 22;

/// Largest `min(rows, cols)^2 * max(rows, cols)` (the work of one Jacobi sweep) ERA accepts:
/// 2^28, a fraction of a second per sweep.
pub const HANKEL_WORK_LIMIT: usize = 1 << 28;

fn check_hankel_size(rows: usize, cols: usize) -> Result<()> {
    let (lo, hi) = (rows.min(cols), rows.max(cols));
    let entries = rows.checked_mul(cols);
    let work = lo.checked_mul(lo).and_then(|x| x.checked_mul(hi));
    match (entries, work) {
        (Some(e), Some(w)) if e <= HANKEL_ENTRY_LIMIT && w <= HANKEL_WORK_LIMIT => Ok(()),
        _ => Err(Error::Limit(format!(
            "era: a {rows} x {cols} Hankel matrix exceeds the size limits ({HANKEL_ENTRY_LIMIT} entries, \
             {HANKEL_WORK_LIMIT} for min^2*max)"
        ))),
    }
}

/// ERA run on a state-space system, with the Hankel size chosen by rank stabilisation.
#[derive(Clone, Debug, PartialEq)]
pub struct SystemEra<T: FloatScalar = f64> {
    /// The realization (of the original time scale: `A` multiplied back by `time_scale`).
    pub realization: FloatRealization<T>,
    /// `ρ`, a power of two at least the spectral radius: ERA runs on the Markov parameters of
    /// $(A/\rho, B, C, D)$ so that no mode grows along the Hankel matrix.
    pub time_scale: f64,
    /// `(K, rank)` for each square block size `K` tried (`K x K` blocks); with a requested
    /// `K`, also `K + 1` and `K + 2` (to tell whether the rank is stable).
    pub ranks: Vec<(usize, usize)>,
    /// Whether the numerical rank stopped growing (equal for three consecutive `K`, or
    /// `K = n + 2`).
    pub stabilised: bool,
}

/// ERA on the Markov parameters of `(a, b, c, d)` with `K x K` block Hankel matrices.
///
/// With `hankel = None`, `K = 1, 2, ...` until the numerical rank of $H_0$ is the same for
/// three consecutive `K` (at most `K = n + 2`: the exact rank is at most `n`); `Some(K)` uses
/// that size. The state matrix is
/// first scaled by `ρ = 2^⌈log2 max|λ|⌉` (exact), the realization of $A/\rho$ is computed and
/// its `A` multiplied by `ρ`: without it, fast modes grow like $|\lambda|^{2K}$ along the
/// Hankel matrix and swamp the slow ones (order 4 instead of 8 on the sliding masses).
/// The result's `truth` is `True` only when the rank stabilised and [`era`]'s tests hold.
///
/// # Errors
/// Shapes and non-finite entries as [`markov_parameters`]; [`Error::Invalid`] without inputs
/// or outputs; [`Error::Limit`] when the Hankel matrix would exceed [`HANKEL_ENTRY_LIMIT`].
pub fn era_system<T: FloatScalar>(
    a: &DMatrix<T>,
    b: &DMatrix<T>,
    c: &DMatrix<T>,
    d: &DMatrix<T>,
    hankel: Option<usize>,
    tol: &Tol,
) -> Result<SystemEra<T>> {
    let (n, m, p) = check_system("era", a, b, c, d)?;
    if p == 0 || m == 0 {
        return Err(Error::Invalid(format!(
            "era: the system has {m} inputs and {p} outputs; need at least one of each"
        )));
    }
    if hankel == Some(0) {
        return Err(Error::Invalid("era: --hankel must be at least 1".into()));
    }
    // the real form's eigenvalues are those of A and of its conjugate: same moduli
    let radius = super::eigenvalues(&T::realify(a))?
        .iter()
        .map(|z| z.norm())
        .fold(0.0, f64::max);
    let rho = if radius > 0.0 && radius.is_finite() {
        2f64.powi(radius.log2().ceil().clamp(-1000.0, 1000.0) as i32)
    } else {
        1.0
    };
    let a_s = a.unscale(rho);
    let run = |k: usize| -> Result<FloatRealization<T>> {
        check_hankel_size(k.saturating_mul(p), k.saturating_mul(m))?;
        let mk = markov_parameters(&a_s, b, c, d, 2 * k + 1)?;
        era_scaled(&mk, None, markov_scale(&a_s, b, c, 2 * k), tol)
    };
    let mut ranks = Vec::new();
    let (mut best, stabilised) = if let Some(k) = hankel {
        // the requested size; K + 1 and K + 2 only to tell whether its rank is stable
        let r = run(k)?;
        ranks.push((k, r.order));
        let mut stable = true;
        for k2 in [k + 1, k + 2] {
            match run(k2) {
                Ok(x) => {
                    ranks.push((k2, x.order));
                    stable &= x.order == r.order;
                }
                Err(_) => stable = false,
            }
        }
        (r, stable)
    } else {
        // The exact rank is at most n, so K = n + 2 blocks always show it stable. Before that
        // the rank must stay put for two steps: it can stall for one step where Markov
        // parameters alternate with zeros (the sliding masses: ranks 6, 6, 8, 8, 8 for
        // K = 6..10), and a rank 0 is never stable early (leading Markov parameters vanish
        // when the relative degree is high).
        let mut prev = run(1)?;
        ranks.push((1, prev.order));
        let mut out = None;
        for k in 2..=n + 2 {
            let next = match run(k) {
                Ok(x) => x,
                Err(Error::Limit(_)) => break,
                Err(e) => return Err(e),
            };
            ranks.push((k, next.order));
            let r = next.order;
            let held = ranks.len() >= 3 && ranks[ranks.len() - 3..].iter().all(|x| x.1 == r);
            if (held && r > 0) || k == n + 2 {
                out = Some(next);
                break;
            }
            prev = next;
        }
        match out {
            Some(r) => (r, true),
            None => (prev, false),
        }
    };
    best.a.scale_mut(rho);
    // Powers of A/ρ underflow when the entries of A span more than ~1e100: Markov parameters
    // that vanish in float need not vanish (an order found is then not clear).
    let nonzero = a.iter().map(|x| x.modulus()).filter(|x| *x != 0.0);
    let (lo, hi) = nonzero.fold((f64::INFINITY, 0.0f64), |(l, h), x| (l.min(x), h.max(x)));
    let range_ok = hi == 0.0 || hi / lo <= 1e100;
    if !stabilised || !range_ok {
        best.truth = Truth::Unknown;
    }
    Ok(SystemEra {
        realization: best,
        time_scale: rho,
        ranks,
        stabilised,
    })
}

/// The size of the Markov parameters $C A^{j-1} B$ before cancellation:
/// $\|C\|_F \max_{j < k} \|A^j B\|_F$. Their rounding errors are $\varepsilon$ times this
/// size, so a Hankel matrix whose singular values are all at that level has rank 0 (a zero
/// transfer function: the uncontrollable or unobservable states cancel in $C A^j B$).
fn markov_scale<T: FloatScalar>(a: &DMatrix<T>, b: &DMatrix<T>, c: &DMatrix<T>, k: usize) -> f64 {
    let fro = |m: &DMatrix<T>| m.iter().map(|x| x.modulus().powi(2)).sum::<f64>().sqrt();
    let mut x = b.clone();
    let mut most = fro(&x);
    for _ in 1..k {
        x = a * &x;
        most = most.max(fro(&x));
    }
    fro(c) * most
}
