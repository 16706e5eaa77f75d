//! Multi-modular determinant and characteristic polynomial over a quadratic field
//! $K = \mathbb{Q}(\sqrt d)$ ($d$ not a square; $d = -1$ is $\mathbb{Q}(i)$), on the images
//! of the matrix under the two embeddings $\sqrt d \mapsto \pm r$ into $\mathbb{Z}/p$.
//!
//! **Integral form.** Write $A = A_0 + A_1 \sqrt d$ with $A_0, A_1 \in \mathbb{Q}^{n \times n}$,
//! let $d_i$ be the lcm of the denominators of both parts of row $i$, $D =
//! \operatorname{diag}(d_i)$ and $\Delta = \prod_i d_i$ (the row-wise form of "scale by a
//! common denominator": a global $L$ gives $\det(xI - LA)$ with coefficients $L^{n-k} c_k$,
//! and $\Delta \le L^n$). $DA$ has entries in $\mathbb{Z}\lbrack\sqrt d\rbrack$, so
//!
//! * $\Delta \det A = \det(DA) \in \mathbb{Z}\lbrack\sqrt d\rbrack$;
//! * $\Delta c_k \in \mathbb{Z}\lbrack\sqrt d\rbrack$ for every coefficient of
//!   $\det(xI - A) = \sum_k c_k x^k$: $c_k$ is $\pm$ a sum of principal minors, the minor on
//!   the rows $S$ has denominator dividing $\prod_{i \in S} d_i \mid \Delta$.
//!
//! **Images.** For a word prime $p$ ([`crate::qkernels::prime`]) dividing no denominator
//! and not $d$, with $d \equiv r^2 \pmod p$ (Euler's criterion, then Tonelli–Shanks:
//! [`Prime::sqrt`]), both $\varphi_\pm : \mathbb{Z}_{(p)}\lbrack\sqrt d\rbrack \to
//! \mathbb{Z}/p$, $\sqrt d \mapsto \pm r$, are ring homomorphisms, so the determinant and
//! the characteristic polynomial of $\varphi_\pm(A) = \bar A_0 \pm r \bar A_1$ (computed by
//! the $\mathbb{Z}/p$ kernels [`det_mod_p`] and [`charpoly_mod_p`]) are the images of
//! those of $A$. For $c = a + b\sqrt d$ ($a, b \in \mathbb{Z}$) with images $c_\pm = a \pm
//! b r$:
//! $$a \equiv \frac{c_+ + c_-}{2}, \qquad b \equiv \frac{c_+ - c_-}{2r} \pmod p.$$
//! The residues of $a$ and $b$ are lifted by the Chinese remainder theorem ([`Crt`],
//! symmetric range) and divided by $\Delta$. About half of the primes qualify.
//!
//! **Certified bound (no early termination).** Let $\sigma$ be an embedding of $K$ into
//! $\mathbb{C}$ ($\sigma(\sqrt d) = \pm\sqrt d$, or $\pm i\sqrt{|d|}$ for $d < 0$). Since
//! $\sigma(A_{i,:}) = A_{0,i,:} + \sigma(\sqrt d) A_{1,i,:}$, the triangle inequality gives
//! $\|\sigma(A_{i,:})\|_2 \le \|A_{0,i,:}\|_2 + \sqrt{|d|}\,\|A_{1,i,:}\|_2 =: \rho_i$
//! (the rows of $\sigma(DA)$ have norms at most $d_i \rho_i$), and by Hadamard's inequality
//! (valid over $\mathbb{C}$) on $\det(DA)$ and on each principal minor of $\Delta c_k =
//! \pm\sum_{|S| = n-k} (\Delta / \prod_{i \in S} d_i) \det (DA)_{S,S}$:
//!
//! * $|\sigma(\Delta \det A)| \le \Delta \prod_i \rho_i$,
//! * $|\sigma(\Delta c_k)| \le \Delta \binom{n}{k} \max_{|S| = n-k} \prod_{i \in S} \rho_i$.
//!
//! Both integer parts of $c = a + b\sqrt d$ are bounded by $\max_\sigma |\sigma(c)|$: for
//! $d > 0$, $a = (\sigma_+(c) + \sigma_-(c))/2$ and $b = (\sigma_+(c) - \sigma_-(c)) /
//! (2\sqrt d)$; for $d < 0$, $a = \operatorname{Re} \sigma(c)$ and $b\sqrt{|d|} =
//! \operatorname{Im} \sigma(c)$. With $B$ that bound, primes are taken until $M = \prod p >
//! 2B$, so the symmetric lift is exact: the result is proved, never guessed.
//!
//! Matrices are row-major slices; a slice whose length is not `n * n` is a caller bug and
//! panics.

use super::charpoly::charpoly_mod_p;
use super::crt::Crt;
use super::det::det_mod_p;
use super::direct::{delta, delta_mod, principal_minors_log2};
use super::qimage::{RatMat, log2_int};
use crate::field::{Quadratic, Rational};
use crate::qkernels::gcd;
use crate::qkernels::intmat::primes_for_bits;
use crate::qkernels::prime::{Prime, primes};
use num_bigint::BigInt;
use num_traits::Zero;

/// One prime's data: the prime, $r$ with $r^2 \equiv d$, and the images
/// $\bar A_0 + r \bar A_1$, $\bar A_0 - r \bar A_1$ (row-major).
struct Image {
    pr: Prime,
    r: u64,
    plus: Vec<u64>,
    minus: Vec<u64>,
}

/// `A` prepared for its images: the rationals $(A_{0,i,:}, A_{1,i,:})$ row by row (an
/// `n x 2n` matrix, whose row denominators are the $d_i$ of the module docs).
struct Parts {
    n: usize,
    joint: Vec<Rational>,
}

impl Parts {
    fn new(n: usize, a: &[Quadratic]) -> Self {
        assert_eq!(
            a.len(),
            n * n,
            "quadratic kernel: slice of length {} for {n}x{n}",
            a.len()
        );
        let mut joint = Vec::with_capacity(2 * n * n);
        for row in a.chunks(n.max(1)) {
            joint.extend(row.iter().map(|x| x.a.clone()));
            joint.extend(row.iter().map(|x| x.b.clone()));
        }
        Parts { n, joint }
    }

    fn rat(&self) -> RatMat<'_> {
        RatMat::new(self.n, 2 * self.n, &self.joint)
    }

    /// Upper bounds of $\log_2 \rho_i$ (module docs), `-inf` for a zero row.
    fn row_bounds_log2(&self, d: &BigInt) -> Vec<f64> {
        let n = self.n;
        let half = |h: usize| -> Vec<Rational> {
            (0..n)
                .flat_map(|i| {
                    self.joint[(2 * i + h) * n..(2 * i + h + 1) * n]
                        .iter()
                        .cloned()
                })
                .collect()
        };
        let (a0, a1) = (half(0), half(1));
        let l0 = RatMat::new(n, n, &a0).row_norm_log2();
        let l1 = RatMat::new(n, n, &a1).row_norm_log2();
        let log_sqrt_d = log2_int(d) / 2.0;
        l0.iter()
            .zip(&l1)
            .map(|(&x, &y)| log2_sum(x, y + log_sqrt_d))
            .collect()
    }
}

/// An upper bound of $\log_2(2^x + 2^y)$ (`-inf` when both are).
fn log2_sum(x: f64, y: f64) -> f64 {
    let (hi, lo) = if x >= y { (x, y) } else { (y, x) };
    if hi == f64::NEG_INFINITY {
        return hi;
    }
    hi + (lo - hi).exp2().ln_1p() / std::f64::consts::LN_2 + 1e-6
}

/// The images of `rm` (the [`Parts`] of an `n x n` matrix) for the primes that qualify (module
/// docs), in prime order.
fn images<'a>(rm: &'a RatMat<'a>, n: usize, d: &'a BigInt) -> impl Iterator<Item = Image> + 'a {
    primes(0).filter_map(move |pr| {
        let dm = delta_mod(&pr, d);
        if dm == 0 {
            return None;
        }
        let r = pr.sqrt(dm)?;
        let img = rm.image(&pr)?;
        let rs = pr.shoup(r);
        let (mut plus, mut minus) = (Vec::with_capacity(n * n), Vec::with_capacity(n * n));
        for row in img.chunks((2 * n).max(1)) {
            for (&x, &y) in row[..n].iter().zip(&row[n..]) {
                let ry = pr.mul_shoup(r, rs, y);
                plus.push(pr.add(x, ry));
                minus.push(pr.sub(x, ry));
            }
        }
        Some(Image { pr, r, plus, minus })
    })
}

/// The multi-modular driver: `per_prime` maps the two images (destroyed) to the residues of
/// the `len` values wanted; enough primes for `bits` ($\log_2 B$, module docs) are used, and
/// the values, times $\Delta$, are lifted and divided by $\Delta$.
fn lift_values(
    parts: &Parts,
    d: &BigInt,
    bits: f64,
    per_prime: impl Fn(&Prime, &mut [u64]) -> Vec<u64>,
) -> Vec<Quadratic> {
    let rm = parts.rat();
    let (big_delta, log_delta) = delta(&rm);
    let k = primes_for_bits(log_delta + bits + 1.0);
    let (mut ps, mut xs, mut ys) = (Vec::with_capacity(k), vec![], vec![]);
    for mut im in images(&rm, parts.n, d).take(k) {
        let pr = im.pr;
        let cp = per_prime(&pr, &mut im.plus);
        let cm = per_prime(&pr, &mut im.minus);
        // a = (c+ + c-) / 2 and b = (c+ - c-) / (2r), both times Delta
        let dm = delta_mod(&pr, &big_delta);
        let half = pr.mul(dm, pr.inv(2).expect("odd prime"));
        let over = pr.mul(dm, pr.inv(pr.add(im.r, im.r)).expect("r != 0"));
        xs.push(
            cp.iter()
                .zip(&cm)
                .map(|(&u, &v)| pr.mul(pr.add(u, v), half))
                .collect::<Vec<_>>(),
        );
        ys.push(
            cp.iter()
                .zip(&cm)
                .map(|(&u, &v)| pr.mul(pr.sub(u, v), over))
                .collect::<Vec<_>>(),
        );
        ps.push(pr);
    }
    let crt = Crt::new(&ps);
    let len = xs.first().map_or(0, Vec::len);
    let part = |v: &[Vec<u64>], j: usize| gcd::fraction(crt.lift(|i| v[i][j]), &big_delta);
    (0..len)
        .map(|j| Quadratic::new(part(&xs, j), part(&ys, j)))
        .collect()
}

/// $\det A$ for the `n x n` row-major `a` over $\mathbb{Q}(\sqrt d)$ (1 for `n = 0`).
///
/// # Panics
/// When `a.len() != n * n`.
pub fn det_quadratic(d: &BigInt, n: usize, a: &[Quadratic]) -> Quadratic {
    let parts = Parts::new(n, a);
    let rows = parts.row_bounds_log2(d);
    if rows.contains(&f64::NEG_INFINITY) {
        return Quadratic::new(Rational::zero(), Rational::zero());
    }
    let bits = rows.iter().sum::<f64>().max(0.0);
    let mut v = lift_values(&parts, d, bits, |pr, img| vec![det_mod_p(pr, n, img)]);
    v.pop().expect("one value per prime")
}

/// $\det(xI - A)$ for the `n x n` row-major `a` over $\mathbb{Q}(\sqrt d)$, coefficients
/// low degree first, monic, length `n + 1`.
///
/// # Panics
/// When `a.len() != n * n`.
pub fn charpoly_quadratic(d: &BigInt, n: usize, a: &[Quadratic]) -> Vec<Quadratic> {
    let parts = Parts::new(n, a);
    let bits = principal_minors_log2(parts.row_bounds_log2(d));
    lift_values(&parts, d, bits, |pr, img| charpoly_mod_p(pr, n, img))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(a: i64, b: i64) -> Quadratic {
        Quadratic::new(
            Rational::from_integer(a.into()),
            Rational::from_integer(b.into()),
        )
    }

    #[test]
    fn two_by_two_over_sqrt2_and_gaussian() {
        // [[1 + sqrt2, 2], [sqrt2, 3]]: det = 3 + 3 sqrt2 - 2 sqrt2 = 3 + sqrt2,
        // trace 4 + sqrt2: x^2 - (4 + sqrt2) x + (3 + sqrt2)
        let two = BigInt::from(2);
        let a = [q(1, 1), q(2, 0), q(0, 1), q(3, 0)];
        assert_eq!(det_quadratic(&two, 2, &a), q(3, 1));
        assert_eq!(
            charpoly_quadratic(&two, 2, &a),
            vec![q(3, 1), q(-4, -1), q(1, 0)]
        );
        // over Q(i): [[i, 1], [1, i]]: det = -1 - 1 = -2, x^2 - 2i x - 2
        let m1 = BigInt::from(-1);
        let b = [q(0, 1), q(1, 0), q(1, 0), q(0, 1)];
        assert_eq!(det_quadratic(&m1, 2, &b), q(-2, 0));
        assert_eq!(
            charpoly_quadratic(&m1, 2, &b),
            vec![q(-2, 0), q(0, -2), q(1, 0)]
        );
        assert_eq!(charpoly_quadratic(&two, 0, &[]), vec![q(1, 0)]);
        assert_eq!(det_quadratic(&two, 0, &[]), q(1, 0));
        assert_eq!(det_quadratic(&two, 1, &[q(0, 0)]), q(0, 0));
    }

    #[test]
    fn bound_sums_are_upper_bounds() {
        for (x, y) in [
            (3.0, 3.0),
            (10.0, -5.0),
            (0.0, f64::NEG_INFINITY),
            (-2.0, 7.5),
        ] {
            let exact = (f64::exp2(x) + f64::exp2(y)).log2();
            assert!(log2_sum(x, y) >= exact && log2_sum(x, y) < exact + 1e-5);
        }
        assert_eq!(
            log2_sum(f64::NEG_INFINITY, f64::NEG_INFINITY),
            f64::NEG_INFINITY
        );
    }
}
