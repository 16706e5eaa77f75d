//! Multi-modular kernels on the images of the rational matrix itself ([`super::qimage`]).
//!
//! Row-wise denominator clearing turns a matrix of fractions $p/q$ ($|p|, q \le 10^6$) into
//! an integer matrix with $n \log_2 10^6$-bit entries, whose reduction modulo each prime
//! costs as much as the elimination. Here every image is $\bar A = A \bmod p$ directly
//! ($O(n^2)$ word operations), and the integer structure enters only the certificates:
//! with $d_i$ the denominator lcm of row $i$, $D = \operatorname{diag}(d_i)$ and
//! $\Delta = \prod_i d_i$,
//!
//! | kernel | computes | certificate |
//! |---|---|---|
//! | [`rank_if_full`] | $\operatorname{rank} A = \min(m, n)$, or `None` | $\operatorname{rank} \bar A \le \operatorname{rank} A \le \min(m, n)$ |
//! | [`det_direct`] | $\det A = \det(DA) / \Delta$ | Hadamard: $|\det DA| \le \prod_i d_i \|A_{i,:}\|_2$ |
//! | [`charpoly_direct`] | $\det(xI - A)$ | $\Delta c_k \in \mathbb{Z}$, $|\Delta c_k| \le \Delta \binom{n}{k} \max_{|S| = k} \prod_{i \in S} \|A_{i,:}\|_2$ |
//! | [`is_cyclic`] | whether $\mu_A = \chi_A$ (`false`: undecided) | a Krylov basis $v, \bar A v, \dots, \bar A^{n-1} v$ modulo $p$ |
//! | [`solve_direct`], [`inverse_direct`] | $A^{-1} B = N / \delta$, $\delta = \det(DA)$, or `None` | $(DA) N = \delta DB$ checked modulo $M > 2\beta$ |
//!
//! The minimal-polynomial certificate: $\mu_A$ divides $\chi_A \in \mathbb{Z}_{(p)}[x]$ and is
//! monic, so (Gauss's lemma over the valuation ring $\mathbb{Z}_{(p)}$) $\mu_A \in
//! \mathbb{Z}_{(p)}[x]$ and $\mu_A(\bar A) = 0$: the minimal polynomial of $\bar A$, of
//! degree at least that of any vector's, divides $\bar\mu_A$. A Krylov sequence of rank $n$
//! modulo $p$ gives $\deg \mu_A = n$, hence $\mu_A = \chi_A$.
//!
//! Primes dividing a denominator of $A$ have no image and are skipped.

use super::charpoly::charpoly_mod_p;
use super::crt::Crt;
use super::det::det_mod_p;
use super::qimage::{RatMat, log2_int};
use super::rank::rank_mod_p;
use super::rref::rref_mod_p;
use crate::field::Rational;
use crate::qkernels::gcd;
use crate::qkernels::intmat::primes_for_bits;
use crate::qkernels::prime::{Prime, primes};
use crate::rng::SplitMix64;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};

/// The images of `rm` with their primes, in prime order (primes dividing a denominator
/// skipped).
fn images<'a>(rm: &'a RatMat<'a>) -> impl Iterator<Item = (Prime, Vec<u64>)> + 'a {
    primes(0).filter_map(move |pr| rm.image(&pr).map(|img| (pr, img)))
}

/// $\operatorname{rank} A$ when one image has rank $\min(m, n)$ (then certified); `None`
/// when the image is deficient (the caller takes the certified RREF path).
pub fn rank_if_full(m: usize, n: usize, a: &[Rational]) -> Option<usize> {
    let rm = RatMat::new(m, n, a);
    let (pr, mut img) = images(&rm).next()?;
    let r = rank_mod_p(&pr, m, n, &mut img);
    (r == m.min(n)).then_some(r)
}

/// $\Delta = \prod_i d_i$ and $\log_2 \Delta$.
pub(crate) fn delta(rm: &RatMat) -> (BigInt, f64) {
    let dens = rm.row_dens();
    let log = dens.iter().map(log2_int).sum();
    (dens.iter().product(), log)
}

/// $\det A$ (1 for `n = 0`).
///
/// # Panics
/// When `a.len() != n * n`.
pub fn det_direct(n: usize, a: &[Rational]) -> Rational {
    let rm = RatMat::new(n, n, a);
    let rows = rm.row_norm_log2();
    if rows.contains(&f64::NEG_INFINITY) {
        return Rational::zero();
    }
    let (big_delta, log_delta) = delta(&rm);
    let h = log_delta + rows.iter().sum::<f64>().max(0.0);
    let k = primes_for_bits(h + 1.0);
    let (ps, dets): (Vec<Prime>, Vec<u64>) = images(&rm)
        .take(k)
        .map(|(pr, mut img)| {
            let d = det_mod_p(&pr, n, &mut img);
            (pr, pr.mul(d, delta_mod(&pr, &big_delta)))
        })
        .unzip();
    let x = Crt::new(&ps).lift(|i| dets[i]);
    gcd::fraction(x, &big_delta)
}

/// $\log_2$ of the bound of the module docs on $|\Delta c_k|$, maximised over $k$.
fn charpoly_bound_log2(rm: &RatMat, log_delta: f64) -> f64 {
    log_delta + principal_minors_log2(rm.row_norm_log2())
}

/// $\log_2 \max_k \binom{n}{k} \max_{|S| = k} \prod_{i \in S} 2^{\ell_i}$ for upper bounds
/// $\ell_i$ of $\log_2$ of the row norms (`-inf` for a zero row): a bound of every
/// coefficient of $\det(xI - A)$ (the sum of the $\binom nk$ principal $k \times k$ minors,
/// each at most the product of its row norms by Hadamard). 0 for `n = 0`.
pub(crate) fn principal_minors_log2(mut rows: Vec<f64>) -> f64 {
    let n = rows.len();
    rows.sort_by(|x, y| y.total_cmp(x));
    let (mut best, mut s, mut lbin) = (0.0f64, 0.0f64, 0.0f64);
    for k in 1..=n {
        if rows[k - 1] == f64::NEG_INFINITY {
            break;
        }
        s += rows[k - 1];
        lbin += ((n - k + 1) as f64 / k as f64).log2() + 1e-12;
        best = best.max(lbin + s);
    }
    best
}

/// $\det(xI - A)$, coefficients low degree first, monic, length `n + 1`.
///
/// # Panics
/// When `a.len() != n * n`.
pub fn charpoly_direct(n: usize, a: &[Rational]) -> Vec<Rational> {
    let rm = RatMat::new(n, n, a);
    let (big_delta, log_delta) = delta(&rm);
    let k = primes_for_bits(charpoly_bound_log2(&rm, log_delta) + 1.0);
    let (ps, imgs): (Vec<Prime>, Vec<Vec<u64>>) = images(&rm)
        .take(k)
        .map(|(pr, mut img)| {
            let dm = delta_mod(&pr, &big_delta);
            let mut c = charpoly_mod_p(&pr, n, &mut img);
            pr.scale(&mut c, dm);
            (pr, c)
        })
        .unzip();
    let crt = Crt::new(&ps);
    (0..=n)
        .map(|j| gcd::fraction(crt.lift(|i| imgs[i][j]), &big_delta))
        .collect()
}

/// The residue of a (signed) big integer modulo `pr`.
pub(crate) fn delta_mod(pr: &Prime, x: &BigInt) -> u64 {
    let (s, l) = x.to_u64_digits();
    pr.reduce_limbs(s == num_bigint::Sign::Minus, &l)
}

/// Is $\mu_A = \chi_A$ certified by a Krylov sequence of rank $n$ modulo one prime (see
/// the module docs)? `false` for a derogatory $A$ (or an unlucky prime or vector).
///
/// # Panics
/// When `a.len() != n * n`.
pub fn is_cyclic(n: usize, a: &[Rational]) -> bool {
    let rm = RatMat::new(n, n, a);
    let Some((pr, img)) = images(&rm).next() else {
        return false;
    };
    let mut rng = SplitMix64(0x006d_696e_706f_6c79);
    let mut v: Vec<u64> = (0..n).map(|_| rng.next_u64() % pr.p).collect();
    let mut krylov = Vec::with_capacity(n * n);
    for _ in 0..n {
        krylov.extend_from_slice(&v);
        v = (0..n)
            .map(|i| {
                let row = &img[i * n..(i + 1) * n];
                let s: u128 = row.iter().zip(&v).fold(0u128, |s, (&x, &y)| {
                    (s + x as u128 * y as u128) % pr.p as u128
                });
                s as u64
            })
            .collect();
    }
    rank_mod_p(&pr, n, n, &mut krylov) == n
}

/// $A^{-1}$ (`None` when $A$ is singular): [`solve_direct`] with $B = I$.
///
/// # Panics
/// When `a.len() != n * n`.
pub fn inverse_direct(n: usize, a: &[Rational]) -> Option<Vec<Rational>> {
    let mut id = vec![Rational::zero(); n * n];
    (0..n).for_each(|i| id[i * n + i] = Rational::one());
    solve_direct(n, n, a, &id)
}

/// $X = A^{-1} B$ for the `n x n` `a` and the `n x k` `b` (`None` when $A$ is singular).
///
/// With $D$ the row denominators of $[A \mid B]$ and $\delta = \det(DA)$, the matrix
/// $N = \delta X = \operatorname{adj}(DA)\,DB$ is integral: each prime gives $\bar\delta$
/// (the determinant of $\bar A$ times $\bar\Delta$) and $\bar N = \bar\delta \bar X$
/// (Gauss–Jordan on $[\bar A \mid \bar B]$), and $N$ is lifted by CRT alone, with no
/// rational reconstruction (which would need a modulus of twice the bits). Output-sensitive:
/// the lift is tried when $\delta$ is stable between two checkpoints, and accepted only with
/// the certificate of the module docs.
///
/// # Panics
/// When `a.len() != n * n` or `b.len() != n * k`.
pub fn solve_direct(n: usize, k: usize, a: &[Rational], b: &[Rational]) -> Option<Vec<Rational>> {
    let (d, nums) = solve_direct_int(n, k, a, b)?;
    Some(nums.into_iter().map(|x| gcd::fraction(x, &d)).collect())
}

/// [`solve_direct`] before the division: $(\delta, N)$ with $\delta \ne 0$ and $X = N /
/// \delta$ (`N` row-major `n x k`, integral), certified as there.
///
/// # Panics
/// When `a.len() != n * n` or `b.len() != n * k`.
pub fn solve_direct_int(
    n: usize,
    k: usize,
    a: &[Rational],
    b: &[Rational],
) -> Option<(BigInt, Vec<BigInt>)> {
    assert_eq!(a.len(), n * n, "solve_direct: A is not n x n");
    assert_eq!(b.len(), n * k, "solve_direct: B is not n x k");
    let w = n + k;
    let mut aug = Vec::with_capacity(n * w);
    for i in 0..n {
        aug.extend_from_slice(&a[i * n..(i + 1) * n]);
        aug.extend_from_slice(&b[i * k..(i + 1) * k]);
    }
    let rm = RatMat::new(n, w, &aug);
    let total = n * k;
    if total == 0 {
        let singular = n > 0 && det_direct(n, a).is_zero();
        return (!singular).then(|| (BigInt::one(), Vec::new()));
    }
    let cert = SolveCertificate::new(&rm, n);
    let (big_delta, _) = delta(&rm);
    // images[t] = (delta mod p_t, N mod p_t)
    let (mut used, mut imgs): (Vec<Prime>, Vec<(u64, Vec<u64>)>) = (vec![], vec![]);
    let (mut next_check, mut last_det, mut checked_det) = (1usize, None, false);
    for (pr, mut img) in images(&rm) {
        let mut sq: Vec<u64> = (0..n)
            .flat_map(|i| img[i * w..i * w + n].to_vec())
            .collect();
        let det = pr.mul(det_mod_p(&pr, n, &mut sq), delta_mod(&pr, &big_delta));
        let piv = rref_mod_p(&pr, n, w, &mut img);
        // pivots strictly increase: they are 0..n exactly when the n-th one is n - 1
        if det == 0 || piv.len() < n || piv[n - 1] != n - 1 {
            if !checked_det {
                if det_direct(n, a).is_zero() {
                    return None;
                }
                checked_det = true;
            }
            continue; // unlucky prime
        }
        let mut x: Vec<u64> = (0..n)
            .flat_map(|i| img[i * w + n..(i + 1) * w].to_vec())
            .collect();
        pr.scale(&mut x, det);
        imgs.push((det, x));
        used.push(pr);
        if used.len() < next_check {
            continue;
        }
        next_check = used.len() + (used.len() / 8).max(1);
        let crt = Crt::new(&used);
        let d = crt.lift(|t| imgs[t].0);
        let stable = last_det.as_ref() == Some(&d);
        last_det = Some(d.clone());
        if !stable {
            continue;
        }
        let nums: Vec<BigInt> = (0..total).map(|i| crt.lift(|t| imgs[t].1[i])).collect();
        match cert.needed_bits(&crt, &d, &nums) {
            None => return Some((d, nums)),
            // the candidate is (very likely) right: wait until the modulus can certify it
            Some(bits) => next_check = next_check.max(primes_for_bits(bits)),
        }
    }
    unreachable!("the prime sequence is endless")
}

/// The bound data of $(DA) N = \delta (DB)$: $\max_i \sum_j |d_i a_{ij}|$ and
/// $\max_{ij} |d_i b_{ij}|$.
struct SolveCertificate {
    max_row: BigInt,
    max_b: BigInt,
}

impl SolveCertificate {
    fn new(rm: &RatMat, n: usize) -> Self {
        let dens = rm.row_dens();
        let w = rm.n;
        let scaled = |i: usize, x: &Rational| x.numer().abs() * (&dens[i] / x.denom());
        let max_row = (0..rm.m)
            .map(|i| (0..n).map(|j| scaled(i, &rm.a[i * w + j])).sum::<BigInt>())
            .max()
            .unwrap_or_default();
        let max_b = (0..rm.m)
            .flat_map(|i| (n..w).map(move |j| (i, j)))
            .map(|(i, j)| scaled(i, &rm.a[i * w + j]))
            .max()
            .unwrap_or_default();
        SolveCertificate { max_row, max_b }
    }

    /// $(DA) N \equiv \delta (DB)$ modulo every prime used (by construction), $\delta \ne 0$
    /// and $M > 2\beta$ with $\beta = \max_i \sum_j |d_i a_{ij}| \max|N| + |\delta| \max
    /// |d_i b_{ij}|$ bounding both sides: the identity holds over $\mathbb{Z}$, so $X = N /
    /// \delta$ solves $AX = B$. `None` when certified, else $\log_2 2\beta$ (the modulus it
    /// needs).
    fn needed_bits(&self, crt: &Crt, den: &BigInt, nums: &[BigInt]) -> Option<f64> {
        let max_n = nums.iter().map(|x| x.abs()).max().unwrap_or_default();
        let beta2 = (&self.max_row * max_n + den.abs() * &self.max_b) * 2u32;
        if !den.is_zero() && *crt.modulus() > beta2 {
            return None;
        }
        Some(log2_int(&beta2))
    }
}
