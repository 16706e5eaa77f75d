//! A tolerance-based guess of the Jordan structure.
//!
//! A Jordan block of size $k$ for $\lambda$ turns, under a perturbation of size
//! $\varepsilon\lVert A\rVert$, into $k$ eigenvalues on a circle of radius about
//! $(\varepsilon\lVert A\rVert^{k-1}\cdots)^{1/k}$ around $\lambda$; a repeated rigid-body zero
//! shows up as a tiny complex pair (minimal-realizations paper, sec. 5). So eigenvalues are
//! first **clustered**: the $s$ computed eigenvalues nearest to one of them form a cluster when
//! they all lie within $r(s) = \lVert A\rVert_F\,\min(\text{rel}^{1/s}, 10^{-2})$ of it (the
//! largest such $s$ wins). The cluster centre $c$ is the mean (accurate to $O(\varepsilon)$ even
//! for a defective eigenvalue: it is a trace). Then the nullities
//! $\nu_k = n - \operatorname{rank}(A - cI)^k$ are decided by SVD with thresholds relative to
//! $\lVert A - cI\rVert_2^k$, and the number of blocks of size $\ge k$ is $\nu_k - \nu_{k-1}$.
//! Every rank decision is reported; a cluster is [`Truth::True`] only when all gaps are clear,
//! $\nu$ reaches the cluster size consistently and, for a multiple eigenvalue, the dropped
//! singular values are at the rounding floor $8k\,\varepsilon\lVert A - cI\rVert_2^k$
//! (otherwise the members are distinct eigenvalues closer than the threshold).
//!
//! | entry point      | returns                                      |
//! |------------------|----------------------------------------------|
//! | [`jordan_guess`] | [`FloatJordan`]: clusters with block sizes   |

use nalgebra::DMatrix;
use num_complex::Complex;

use super::svd::complex_singular_values;
use super::{RankGap, Tol, Truth, all_clear, decide_rank, eigenvalues};
use crate::error::Result;

/// One cluster of computed eigenvalues, taken as one eigenvalue of the exact matrix.
#[derive(Clone, Debug, PartialEq)]
pub struct Cluster {
    /// The mean of the members (real when the members are closed under conjugation).
    pub center: Complex<f64>,
    /// The computed eigenvalues in the cluster.
    pub members: Vec<Complex<f64>>,
    /// Largest distance from a member to the centre.
    pub spread: f64,
    /// Number of members.
    pub algebraic_multiplicity: usize,
    /// $\nu_1 = n - \operatorname{rank}(A - cI)$.
    pub geometric_multiplicity: usize,
    /// Jordan block sizes, non-increasing (sum = algebraic multiplicity when consistent).
    pub block_sizes: Vec<usize>,
    /// `True` when every rank decision is clear and the nullities are consistent.
    pub truth: Truth,
    /// The rank decisions for $(A - cI)^k$, $k = 1, 2, \dots$
    pub rank_gaps: Vec<RankGap>,
}

/// The guessed Jordan structure of a real matrix.
#[derive(Clone, Debug, PartialEq)]
pub struct FloatJordan {
    /// Clusters sorted by centre (real part, then imaginary part).
    pub clusters: Vec<Cluster>,
    /// Frobenius norm of the matrix (the scale of all tolerances).
    pub norm: f64,
    /// Conjunction of the clusters' truths.
    pub truth: Truth,
    /// Human-readable warnings (scattered multiple eigenvalues, inconsistent ranks).
    pub warnings: Vec<String>,
}

/// Guesses eigenvalue clusters, multiplicities and Jordan block sizes of `a`.
///
/// # Examples
/// ```
/// use exactlti::float::{jordan_guess, Tol, Truth};
/// use nalgebra::DMatrix;
/// let a = DMatrix::from_row_slice(2, 2, &[0.0, 1.0, 0.0, 0.0]);
/// let j = jordan_guess(&a, &Tol::default()).unwrap();
/// assert_eq!(j.clusters.len(), 1);
/// assert_eq!(j.clusters[0].block_sizes, vec![2]);
/// assert_eq!(j.clusters[0].truth, Truth::True);
/// ```
///
/// # Errors
/// As [`eigenvalues`].
pub fn jordan_guess(a: &DMatrix<f64>, tol: &Tol) -> Result<FloatJordan> {
    let ev = eigenvalues(a)?;
    let n = a.nrows();
    let norm = a.norm();
    let groups = cluster_indices(&ev, norm, tol);
    let mut clusters: Vec<Cluster> = Vec::with_capacity(groups.len());
    let mut warnings = Vec::new();
    for g in &groups {
        let members: Vec<Complex<f64>> = g.iter().map(|&i| ev[i]).collect();
        let center = centre(&members);
        // Reuse the structure of the conjugate cluster when it was already analysed.
        if center.im < 0.0
            && let Some(twin) = clusters.iter().find(|c| {
                c.members.len() == members.len()
                    && (c.center - center.conj()).norm() <= f64::EPSILON * 16.0 * norm.max(1.0)
            })
        {
            let mut c = twin.clone();
            c.center = center;
            c.members = members;
            clusters.push(c);
            continue;
        }
        let c = analyse_cluster(a, center, members, n, tol);
        clusters.push(c);
    }
    clusters.sort_by(|x, y| {
        x.center
            .re
            .total_cmp(&y.center.re)
            .then(x.center.im.total_cmp(&y.center.im))
    });
    for c in &clusters {
        if c.members.len() > 1 && c.center.im == 0.0 && c.members.iter().any(|z| z.im != 0.0) {
            warnings.push(format!(
                "a real eigenvalue {:.6e} of multiplicity {} shows up as complex values spread by {:.1e} in float",
                c.center.re, c.algebraic_multiplicity, c.spread
            ));
        }
        if c.truth != Truth::True {
            warnings.push(format!(
                "structure at {:.6e}{:+.6e}i is uncertain (rank gaps not clear or nullities inconsistent)",
                c.center.re, c.center.im
            ));
        }
    }
    let truth = clusters.iter().fold(Truth::True, |acc, c| acc.and(c.truth));
    Ok(FloatJordan {
        clusters,
        norm,
        truth,
        warnings,
    })
}

/// Cluster radius for a cluster of `s` eigenvalues.
fn radius(s: usize, norm: f64, tol: &Tol) -> f64 {
    let rel = tol.rel.clamp(f64::MIN_POSITIVE, 1.0);
    let r = rel.powf(1.0 / s as f64).min(1e-2);
    (norm * r).max(tol.abs)
}

/// Greedy clustering: repeatedly take the eigenvalue whose `s` nearest neighbours (itself
/// included) fit in the ball of radius `r(s)` for the largest `s`.
fn cluster_indices(ev: &[Complex<f64>], norm: f64, tol: &Tol) -> Vec<Vec<usize>> {
    let mut remaining: Vec<usize> = (0..ev.len()).collect();
    let mut out = Vec::new();
    while !remaining.is_empty() {
        let mut best: (usize, Vec<usize>) = (0, Vec::new());
        for &i in &remaining {
            let mut near: Vec<(f64, usize)> = remaining
                .iter()
                .map(|&j| ((ev[j] - ev[i]).norm(), j))
                .collect();
            near.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
            let mut s_best = 1;
            for s in 2..=near.len() {
                if near[s - 1].0 <= radius(s, norm, tol) {
                    s_best = s;
                }
            }
            if s_best > best.0 {
                best = (s_best, near[..s_best].iter().map(|x| x.1).collect());
            }
        }
        let mut g = best.1;
        g.sort_unstable();
        remaining.retain(|i| !g.contains(i));
        out.push(g);
    }
    out
}

/// Mean of the members; exactly real when they are closed under conjugation.
fn centre(members: &[Complex<f64>]) -> Complex<f64> {
    let k = members.len() as f64;
    let re = members.iter().map(|z| z.re).sum::<f64>() / k;
    let mut im: Vec<f64> = members.iter().map(|z| z.im).collect();
    let mut neg: Vec<f64> = im.iter().filter(|x| **x < 0.0).map(|x| -x).collect();
    let mut pos: Vec<f64> = im.iter().filter(|x| **x > 0.0).copied().collect();
    neg.sort_by(f64::total_cmp);
    pos.sort_by(f64::total_cmp);
    if neg == pos {
        return Complex::new(re, 0.0);
    }
    im.sort_by(f64::total_cmp);
    Complex::new(re, im.iter().sum::<f64>() / k)
}

/// A multiple eigenvalue is clear only when the dropped singular values of $(A - cI)^k$ are at
/// most `FLOOR_FACTOR * k * ε * ‖A - cI‖_2^k`: the centre error plus the SVD's own rounding.
/// (MATLAB's `wilkinson(20)` has pairs 7.7e-13 apart: 87 ε‖A - cI‖, not a double eigenvalue.)
const FLOOR_FACTOR: f64 = 8.0;

/// Nullities of powers of `A - cI` and the block sizes they imply.
fn analyse_cluster(
    a: &DMatrix<f64>,
    center: Complex<f64>,
    members: Vec<Complex<f64>>,
    n: usize,
    tol: &Tol,
) -> Cluster {
    let alg = members.len();
    let spread = members
        .iter()
        .map(|z| (z - center).norm())
        .fold(0.0, f64::max);
    let m: DMatrix<Complex<f64>> = DMatrix::from_fn(n, n, |i, j| {
        let x = Complex::new(a[(i, j)], 0.0);
        if i == j { x - center } else { x }
    });
    let mut gaps: Vec<RankGap> = Vec::new();
    let mut nullity = vec![0usize];
    let mut power = m.clone();
    let mut mnorm = 0.0;
    for k in 1..=alg {
        if k > 1 {
            power = &power * &m;
        }
        let sv = complex_singular_values(&power);
        if k == 1 {
            mnorm = sv.iter().copied().fold(0.0, f64::max);
        }
        let scale = mnorm.powi(k as i32);
        let g = decide_rank(&format!("rank (A - cI)^{k}"), &sv, scale, tol);
        let nu = n - g.rank;
        gaps.push(g);
        let prev = *nullity.last().unwrap_or(&0);
        nullity.push(nu);
        if nu >= alg || nu == prev {
            break;
        }
    }
    let (block_sizes, consistent) = blocks_from_nullities(&nullity, alg);
    // A multiple eigenvalue of the data makes the dropped singular values of (A - cI)^k pure
    // rounding (the centre is a trace, accurate to O(ε‖A‖)); dropped values far above that
    // floor mean distinct eigenvalues closer than the threshold (Wilkinson pairs, clusters
    // merged by the radius), so the multiplicity is not clear.
    let at_floor = alg == 1
        || gaps.iter().enumerate().all(|(i, g)| {
            let k = (i + 1) as f64;
            g.dropped <= FLOOR_FACTOR * k * f64::EPSILON * mnorm.powi(i as i32 + 1)
        });
    let truth = if consistent && at_floor {
        all_clear(&gaps)
    } else {
        Truth::Unknown
    };
    Cluster {
        center,
        members,
        spread,
        algebraic_multiplicity: alg,
        geometric_multiplicity: nullity.get(1).copied().unwrap_or(0),
        block_sizes,
        truth,
        rank_gaps: gaps,
    }
}

/// Block sizes from $\nu_0 = 0, \nu_1, \dots$; `false` when the sequence does not describe
/// `alg` eigenvalues (then all blocks are reported as size 1, the distinct-eigenvalue reading).
fn blocks_from_nullities(nu: &[usize], alg: usize) -> (Vec<usize>, bool) {
    let last = *nu.last().unwrap_or(&0);
    // d[k-1] = number of blocks of size >= k.
    let d: Vec<usize> = nu.windows(2).map(|w| w[1].saturating_sub(w[0])).collect();
    let monotone = nu.windows(2).all(|w| w[1] >= w[0]) && d.windows(2).all(|w| w[1] <= w[0]);
    if last != alg || !monotone || d.first().copied().unwrap_or(0) == 0 {
        return (vec![1; alg], false);
    }
    let mut sizes = Vec::new();
    for k in 1..=d.len() {
        let ge_k = d[k - 1];
        let ge_k1 = d.get(k).copied().unwrap_or(0);
        for _ in 0..(ge_k - ge_k1) {
            sizes.push(k);
        }
    }
    sizes.sort_unstable_by(|x, y| y.cmp(x));
    (sizes, true)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blocks_from_nullities_cases() {
        assert_eq!(blocks_from_nullities(&[0, 1, 2, 3], 3), (vec![3], true));
        assert_eq!(blocks_from_nullities(&[0, 2, 3], 3), (vec![2, 1], true));
        assert_eq!(blocks_from_nullities(&[0, 3], 3), (vec![1, 1, 1], true));
        assert_eq!(blocks_from_nullities(&[0, 0], 2), (vec![1, 1], false));
        assert_eq!(blocks_from_nullities(&[0, 1, 1], 2), (vec![1, 1], false));
    }

    #[test]
    fn centre_of_conjugate_pair_is_real() {
        let c = centre(&[Complex::new(0.1, 1e-8), Complex::new(0.1, -1e-8)]);
        assert_eq!(c.im, 0.0);
    }
}
