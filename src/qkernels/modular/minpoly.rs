//! Multi-modular minimal polynomial of a rational matrix by Krylov sequences modulo primes.
//!
//! For a fixed integer vector $v$, the minimal polynomial $\mu_v$ of the sequence
//! $v, Av, A^2v, \dots$ is computed modulo each prime on the image $\bar A$
//! ([`super::qimage`]) by incremental elimination of the Krylov vectors ($O(n^3)$ word
//! operations). Images of lower degree come from unlucky primes and are dropped; the
//! coefficients of the highest degree seen are combined by CRT and rational reconstruction
//! over one common denominator, tried when a probe is stable between two checkpoints.
//!
//! **Certificate.** The candidate $\mu$ is accepted only when $\mu(A) = 0$ exactly (Horner
//! with the integer product kernel [`crate::qkernels::intmul`]). Then $\mu_A \mid \mu$, and
//! $\deg \mu = \deg \mu_{\bar v} \le \deg \mu_{\bar A} \le \deg \mu_A$ (the monic divisor
//! $\mu_A$ of $\chi_A \in \mathbb{Z}_{(p)}[x]$ reduces modulo $p$ and annihilates $\bar A$),
//! so $\mu = \mu_A$. A vector whose $\mu_v$ is a proper divisor of $\mu_A$ fails the check;
//! the next random vector is then tried.

use super::crt::{CommonDenominator, Crt};
use super::qimage::RatMat;
use crate::field::Rational;
use crate::qkernels::intmul;
use crate::qkernels::prime::{Prime, primes};
use crate::rng::SplitMix64;
use num_traits::Zero;

/// Minimal polynomial of the Krylov sequence of `v` under the `n x n` image `a` modulo
/// `pr`: monic, low degree first.
pub fn krylov_minpoly_mod_p(pr: &Prime, n: usize, a: &[u64], v: &[u64]) -> Vec<u64> {
    // echelon basis: (pivot, vector with 1 at the pivot, its combination of A^k v)
    let mut basis: Vec<(usize, Vec<u64>, Vec<u64>)> = vec![];
    let mut cur = v.to_vec();
    for d in 0..=n {
        let mut w = cur.clone();
        let mut comb = vec![0u64; d + 1];
        comb[d] = 1;
        for (p, b, pc) in &basis {
            let f = w[*p];
            if f != 0 {
                pr.axpy_neg(&mut w, b, f);
                pr.axpy_neg(&mut comb[..pc.len()], pc, f);
            }
        }
        let Some(p) = w.iter().position(|&x| x != 0) else {
            return comb;
        };
        let inv = pr.inv(w[p]).expect("nonzero");
        pr.scale(&mut w, inv);
        pr.scale(&mut comb, inv);
        basis.push((p, w, comb));
        cur = (0..n)
            .map(|i| {
                let s = a[i * n..(i + 1) * n]
                    .iter()
                    .zip(&cur)
                    .fold(0u128, |s, (&x, &y)| {
                        (s + x as u128 * y as u128) % pr.p as u128
                    });
                s as u64
            })
            .collect();
    }
    unreachable!("n + 1 Krylov vectors are dependent")
}

/// $p(A)$ for `p` low degree first, by Horner with the integer product kernel.
fn poly_at(n: usize, p: &[Rational], a: &[Rational]) -> Vec<Rational> {
    let mut acc = vec![Rational::zero(); n * n];
    for c in p.iter().rev() {
        if acc.iter().any(|x| !x.is_zero()) {
            acc = intmul::mul_q(n, n, n, &acc, a);
        }
        (0..n).for_each(|i| acc[i * n + i] += c);
    }
    acc
}

/// The minimal polynomial of the `n x n` rational `a` (monic, low degree first), certified
/// by $\mu(A) = 0$ (see the module docs); `None` when four random vectors gave no
/// certified candidate (the caller takes the generic path).
///
/// # Panics
/// When `a.len() != n * n`.
pub fn minpoly_modular(n: usize, a: &[Rational]) -> Option<Vec<Rational>> {
    let rm = RatMat::new(n, n, a);
    let mut rng = SplitMix64(0x6b72_796c_6f76);
    let annihilates = |mu: &[Rational]| poly_at(n, mu, a).iter().all(Zero::is_zero);
    (0..4).find_map(|_| {
        let v: Vec<u64> = (0..n).map(|_| rng.next_u64() >> 34).collect();
        minpoly_of_vector(&rm, &v, &annihilates)
    })
}

/// The rational $\mu_v$ from its images (CRT and rational reconstruction, tried when stable
/// between two checkpoints) once `accept` holds; `None` after three rejected candidates.
fn minpoly_of_vector(
    rm: &RatMat,
    v: &[u64],
    accept: &dyn Fn(&[Rational]) -> bool,
) -> Option<Vec<Rational>> {
    let n = rm.n;
    let (mut used, mut imgs): (Vec<Prime>, Vec<Vec<u64>>) = (vec![], vec![]);
    let (mut next_check, mut last, mut rejected) = (1usize, None, 0);
    for pr in primes(0) {
        let Some(img) = rm.image(&pr) else { continue };
        let vp: Vec<u64> = v.iter().map(|&x| x % pr.p).collect();
        let mu = krylov_minpoly_mod_p(&pr, n, &img, &vp);
        match imgs.first().map(Vec::len) {
            Some(d) if mu.len() < d => continue, // unlucky
            Some(d) if mu.len() > d => {
                imgs.clear();
                used.clear();
                last = None;
                next_check = 1;
            }
            _ => {}
        }
        imgs.push(mu);
        used.push(pr);
        if used.len() < next_check {
            continue;
        }
        next_check = used.len() + (used.len() / 8).max(1);
        let crt = Crt::new(&used);
        let d = imgs[0].len();
        let us = (0..d).map(|j| crt.lift_nonneg(|t| imgs[t][j]));
        let cand = CommonDenominator::reconstruct(&crt, us).map(|cd| {
            cd.nums
                .into_iter()
                .map(|x| Rational::new(x, cd.den.clone()))
                .collect::<Vec<_>>()
        });
        if cand.is_some() && cand == last {
            let mu = cand.clone().expect("stable");
            if accept(&mu) {
                return Some(mu);
            }
            rejected += 1;
            if rejected == 3 {
                return None;
            }
        }
        last = cand;
    }
    unreachable!("the prime sequence is endless")
}
