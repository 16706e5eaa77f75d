//! Eigenvalues of a real upper Hessenberg matrix by the Francis double-shift QR iteration
//! with exceptional shifts (the algorithm of LAPACK's `dlahqr`, eigenvalues only).
//!
//! The iteration works on the active block $H_{l..i,\,l..i}$: it deflates when a subdiagonal
//! entry is negligible (the Ahues-Tisseur criterion of LAWN 122), reads a real eigenvalue off
//! a $1\times 1$ block and a real or complex pair off a $2\times 2$ block, and otherwise applies
//! one implicit double-shift step $H \leftarrow Q^T H Q$ (a similarity: the eigenvalues are
//! unchanged) with the eigenvalues of the trailing $2\times 2$ block as shifts. Every 10 steps
//! without a deflation the shifts are replaced by exceptional ones built from the size of the
//! last (every 20 steps: the first) subdiagonal entries, as `dlahqr` does; without them the
//! plain Francis iteration cycles forever on matrices whose shifts are symmetric about the
//! spectrum, such as the companion matrices of $x^4 + 1$ and $x^6 + 1$ (nalgebra's Schur
//! form, used before, did).
//!
//! | entry point | computes | cost |
//! |---|---|---|
//! | [`hessenberg_eigenvalues`] | the eigenvalues of an upper Hessenberg $H$ | $O(n^2)$ per step, $O(n^3)$ in all |

use nalgebra::DMatrix;
use num_complex::Complex;

/// Steps without a deflation after which an exceptional shift is used (`dlahqr`'s `KEXSH`).
const KEXSH: usize = 10;
/// The exceptional shift's constants (`dlahqr`'s `DAT1`, `DAT2`).
const DAT1: f64 = 0.75;
const DAT2: f64 = -0.4375;

/// The eigenvalues of the upper Hessenberg matrix `h` (entries below the subdiagonal are
/// ignored), in the order they deflate; a complex pair comes as exact conjugates. `None` when
/// some block needs more than $30\max(10, n)$ steps (LAPACK's bound; not seen in practice
/// with the exceptional shifts).
///
/// # Algorithm
/// LAPACK `dlahqr` (Francis double shift, Ahues-Tisseur deflation, exceptional shifts every
/// 10 and 20 steps without deflation), eigenvalues only.
pub(crate) fn hessenberg_eigenvalues(h: &DMatrix<f64>) -> Option<Vec<Complex<f64>>> {
    let n = h.nrows();
    let mut h = h.clone();
    for c in 0..n {
        for r in c + 2..n {
            h[(r, c)] = 0.0;
        }
    }
    let mut out = vec![Complex::new(0.0, 0.0); n];
    let itmax = 30 * n.max(10);
    let mut kdefl = 0;
    // eigenvalues i + 1 .. n are found; the active block is l ..= i
    let mut i = n as isize - 1;
    while i >= 0 {
        let iu = i as usize;
        let mut l = 0;
        let mut converged = false;
        for _ in 0..=itmax {
            l = deflation_point(&h, iu);
            if l > 0 {
                h[(l, l - 1)] = 0.0;
            }
            if l + 1 >= iu {
                converged = true;
                break;
            }
            kdefl += 1;
            let shifts = shifts(&h, l, iu, kdefl);
            double_shift_step(&mut h, l, iu, shifts);
        }
        if !converged {
            return None;
        }
        if l == iu {
            out[iu] = Complex::new(h[(iu, iu)], 0.0);
        } else {
            let (a, b) = eig2(h[(l, l)], h[(l, iu)], h[(iu, l)], h[(iu, iu)]);
            out[l] = a;
            out[iu] = b;
        }
        kdefl = 0;
        i = l as isize - 1;
    }
    Some(out)
}

/// The largest `k <= i` with `h[k][k-1]` negligible (0 when none): LAPACK's small
/// subdiagonal test with the Ahues-Tisseur refinement.
fn deflation_point(h: &DMatrix<f64>, i: usize) -> usize {
    let ulp = f64::EPSILON;
    let smlnum = f64::MIN_POSITIVE * (h.nrows() as f64 / ulp);
    for k in (1..=i).rev() {
        let sub = h[(k, k - 1)].abs();
        if sub <= smlnum {
            return k;
        }
        let mut tst = h[(k - 1, k - 1)].abs() + h[(k, k)].abs();
        if tst == 0.0 {
            if k >= 2 {
                tst += h[(k - 1, k - 2)].abs();
            }
            if k + 1 < h.nrows() {
                tst += h[(k + 1, k)].abs();
            }
        }
        if sub <= ulp * tst {
            let ab = sub.max(h[(k - 1, k)].abs());
            let ba = sub.min(h[(k - 1, k)].abs());
            let d = (h[(k - 1, k - 1)] - h[(k, k)]).abs();
            let aa = h[(k, k)].abs().max(d);
            let bb = h[(k, k)].abs().min(d);
            let s = aa + ab;
            if ba * (ab / s) <= smlnum.max(ulp * (bb * (aa / s))) {
                return k;
            }
        }
    }
    0
}

/// The two shifts `(re1, im1, re2, im2)` of the step on the block `l ..= i`: the eigenvalues
/// of the trailing 2x2 block (a real pair is replaced by the one closer to `h[i][i]`, used
/// twice), or of the exceptional 2x2 block after 10 and 20 steps without deflation.
fn shifts(h: &DMatrix<f64>, l: usize, i: usize, kdefl: usize) -> [f64; 4] {
    let (h11, h12, h21, h22) = if kdefl.is_multiple_of(2 * KEXSH) {
        let s = h[(i, i - 1)].abs() + h[(i - 1, i - 2)].abs();
        let h11 = DAT1 * s + h[(i, i)];
        (h11, DAT2 * s, s, h11)
    } else if kdefl.is_multiple_of(KEXSH) {
        let s = h[(l + 1, l)].abs() + h[(l + 2, l + 1)].abs();
        let h11 = DAT1 * s + h[(l, l)];
        (h11, DAT2 * s, s, h11)
    } else {
        (h[(i - 1, i - 1)], h[(i - 1, i)], h[(i, i - 1)], h[(i, i)])
    };
    let s = h11.abs() + h12.abs() + h21.abs() + h22.abs();
    if s == 0.0 {
        return [0.0; 4];
    }
    let (h11, h12, h21, h22) = (h11 / s, h12 / s, h21 / s, h22 / s);
    let tr = (h11 + h22) / 2.0;
    let det = (h11 - tr) * (h22 - tr) - h12 * h21;
    let rtdisc = det.abs().sqrt();
    if det >= 0.0 {
        [tr * s, rtdisc * s, tr * s, -rtdisc * s]
    } else {
        let (r1, r2) = (tr + rtdisc, tr - rtdisc);
        let r = if (r1 - h22).abs() <= (r2 - h22).abs() {
            r1
        } else {
            r2
        } * s;
        [r, 0.0, r, 0.0]
    }
}

/// One implicit double-shift QR step on the block `l ..= i` (Householder reflections of
/// order 3 chasing the bulge, order 2 at the end), starting at the lowest row `m` where two
/// consecutive small subdiagonal entries let it start.
fn double_shift_step(h: &mut DMatrix<f64>, l: usize, i: usize, [r1r, r1i, r2r, r2i]: [f64; 4]) {
    let ulp = f64::EPSILON;
    let mut v = [0.0; 3];
    let mut m = i - 2;
    loop {
        let s = (h[(m, m)] - r2r).abs() + r2i.abs() + h[(m + 1, m)].abs();
        let h21s = h[(m + 1, m)] / s;
        v[0] = h21s * h[(m, m + 1)] + (h[(m, m)] - r1r) * ((h[(m, m)] - r2r) / s) - r1i * (r2i / s);
        v[1] = h21s * (h[(m, m)] + h[(m + 1, m + 1)] - r1r - r2r);
        v[2] = h21s * h[(m + 2, m + 1)];
        let s = v[0].abs() + v[1].abs() + v[2].abs();
        v.iter_mut().for_each(|x| *x /= s);
        if m == l {
            break;
        }
        let lhs = h[(m, m - 1)].abs() * (v[1].abs() + v[2].abs());
        let rhs = ulp
            * v[0].abs()
            * (h[(m - 1, m - 1)].abs() + h[(m, m)].abs() + h[(m + 1, m + 1)].abs());
        if lhs <= rhs {
            break;
        }
        m -= 1;
    }
    for k in m..i {
        let nr = 3.min(i - k + 1);
        if k > m {
            for (j, x) in v.iter_mut().enumerate().take(nr) {
                *x = h[(k + j, k - 1)];
            }
        }
        let (beta, tau) = householder(&mut v[..nr]);
        if k > m {
            h[(k, k - 1)] = beta;
            h[(k + 1, k - 1)] = 0.0;
            if k + 2 <= i {
                h[(k + 2, k - 1)] = 0.0;
            }
        } else if m > l {
            h[(k, k - 1)] *= 1.0 - tau;
        }
        apply_reflector(h, k, nr, &v, tau, (l, i));
    }
}

/// Householder reflector (LAPACK `dlarfg`): on input `x = v`, on output `v = [1, u...]` and
/// `tau` with $(I - \tau v v^T) x = (\beta, 0, \dots)$; returns `(beta, tau)`.
fn householder(v: &mut [f64]) -> (f64, f64) {
    let alpha = v[0];
    let xnorm = v[1..].iter().map(|x| x * x).sum::<f64>().sqrt();
    if xnorm == 0.0 {
        v[0] = 1.0;
        return (alpha, 0.0);
    }
    let beta = -alpha.signum() * alpha.hypot(xnorm);
    let tau = (beta - alpha) / beta;
    let scale = 1.0 / (alpha - beta);
    v[1..].iter_mut().for_each(|x| *x *= scale);
    v[0] = 1.0;
    (beta, tau)
}

/// $H \leftarrow G H G$ with $G = I - \tau v v^T$ acting on rows and columns `k .. k + nr`,
/// restricted to the active block `lo ..= hi` (eigenvalues only: the rest is never read).
fn apply_reflector(
    h: &mut DMatrix<f64>,
    k: usize,
    nr: usize,
    v: &[f64; 3],
    tau: f64,
    (lo, hi): (usize, usize),
) {
    if tau == 0.0 {
        return;
    }
    for c in k..=hi {
        let s: f64 = (0..nr).map(|j| v[j] * h[(k + j, c)]).sum::<f64>() * tau;
        for j in 0..nr {
            h[(k + j, c)] -= s * v[j];
        }
    }
    for r in lo..=(k + 3).min(hi) {
        let s: f64 = (0..nr).map(|j| v[j] * h[(r, k + j)]).sum::<f64>() * tau;
        for j in 0..nr {
            h[(r, k + j)] -= s * v[j];
        }
    }
}

/// The eigenvalues of `[[a, b], [c, d]]`: a real pair (the larger-magnitude root by a sum,
/// the other from the determinant, no cancellation, unless both are at the rounding level)
/// or exact conjugates `p +- q i`, `q > 0`.
fn eig2(a: f64, b: f64, c: f64, d: f64) -> (Complex<f64>, Complex<f64>) {
    let s = a.abs() + b.abs() + c.abs() + d.abs();
    if s == 0.0 {
        return (Complex::new(0.0, 0.0), Complex::new(0.0, 0.0));
    }
    let (a, b, c, d) = (a / s, b / s, c / s, d / s);
    let p = 0.5 * (a - d);
    let mean = 0.5 * (a + d);
    let disc = p * p + b * c;
    if disc >= 0.0 {
        let r = disc.sqrt();
        let big = mean + if mean >= 0.0 { r } else { -r };
        // det / big has the absolute error eps / |big|; when |big| <= sqrt(eps) both roots are
        // at the rounding level and the direct formula (error about sqrt(eps)) is the better
        let small = if big.abs() <= f64::EPSILON.sqrt() {
            mean - if mean >= 0.0 { r } else { -r }
        } else {
            (a * d - b * c) / big
        };
        (Complex::new(big * s, 0.0), Complex::new(small * s, 0.0))
    } else {
        let q = (-disc).sqrt() * s;
        (Complex::new(mean * s, q), Complex::new(mean * s, -q))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sorted(mut v: Vec<Complex<f64>>) -> Vec<Complex<f64>> {
        v.sort_by(|x, y| x.re.total_cmp(&y.re).then(x.im.total_cmp(&y.im)));
        v
    }

    #[test]
    fn small_blocks() {
        let h = DMatrix::from_row_slice(1, 1, &[3.0]);
        assert_eq!(
            hessenberg_eigenvalues(&h).unwrap(),
            [Complex::new(3.0, 0.0)]
        );
        let h = DMatrix::<f64>::zeros(0, 0);
        assert!(hessenberg_eigenvalues(&h).unwrap().is_empty());
        // [[0, -1], [1, 0]]: +- i, exact conjugates
        let h = DMatrix::from_row_slice(2, 2, &[0.0, -1.0, 1.0, 0.0]);
        let ev = sorted(hessenberg_eigenvalues(&h).unwrap());
        assert_eq!(ev, [Complex::new(0.0, -1.0), Complex::new(0.0, 1.0)]);
        // a real pair with cancellation: x^2 - 1e8 x + 1 (roots 1e8 and 1e-8)
        let (x, y) = eig2(1e8, -1.0, 1.0, 0.0);
        assert!(
            (x.re - 1e8).abs() < 1e-6 && (y.re - 1e-8).abs() < 1e-22,
            "{x} {y}"
        );
    }

    #[test]
    fn companion_of_x4_plus_1_converges() {
        // the cycle of the plain Francis iteration: shifts symmetric about the spectrum
        let mut h = DMatrix::<f64>::zeros(4, 4);
        for k in 1..4 {
            h[(k, k - 1)] = 1.0;
        }
        h[(0, 3)] = -1.0;
        let ev = hessenberg_eigenvalues(&h).unwrap();
        let r = std::f64::consts::FRAC_1_SQRT_2;
        for z in &ev {
            assert!(
                (z.re.abs() - r).abs() < 1e-14 && (z.im.abs() - r).abs() < 1e-14,
                "{ev:?}"
            );
        }
    }
}
