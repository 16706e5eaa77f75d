//! The kernels behind the symbolic scale commands (issue 25), as identities:
//! - the resultant interpolated from the Sylvester determinant equals the subresultant
//!   algorithm's (random f, g in Z[x, a, b], degrees 2..5 in x, fixed seed), and the
//!   discriminant identity Disc(f g) = Disc(f) Disc(g) Res(f, g)^2 holds;
//! - the check of probed degrees accepts the right determinant and rejects one that differs
//!   by a single term, at any size;
//! - the side primes (profile points, probes, checks) are none of the interpolation primes;
//! - probed and certified grids (`with_certified_grid`, the switch behind
//!   `EXACTLTI_CERTIFIED_GRID`) give the same characteristic polynomial and determinant of
//!   $L M L^{-1}$ (random $M$ linear in a, b, c; $L$ unit lower triangular of degree 2: entries
//!   of degree up to 11 whose invariants are those of $M$), and the probe did lower the grid.

use exactlti::mpoly::MPoly;
use exactlti::mpoly::interp::Bounds;
use exactlti::mpoly::probe::{side_prime, verify, with_certified_grid};
use exactlti::mpoly::resultant::{discriminant, resultant, resultant_prs};
use exactlti::qkernels::modular::charpoly::charpoly_mod_p;
use exactlti::qkernels::modular::det::det_mod_p;
use exactlti::qkernels::prime::{Prime, nth_prime};
use exactlti::ratfunc::{charpoly_zp, det_zp};
use exactlti::rng::SplitMix64;

/// A random polynomial in (x, a, b) of degree `dx` in x (leading coefficient nonzero),
/// coefficients of total degree <= 2 in a, b.
fn random_poly(rng: &mut SplitMix64, dx: u32) -> MPoly {
    let mut terms: Vec<(Vec<u32>, i64)> = vec![];
    for e in 0..=dx {
        for (ea, eb) in [(0, 0), (1, 0), (0, 1), (1, 1), (2, 0)] {
            let c = rng.int(-3, 3);
            if c != 0 || (e == dx && ea == 0 && eb == 0) {
                terms.push((vec![e, ea, eb], if c == 0 { 1 } else { c }));
            }
        }
    }
    let t: Vec<(&[u32], i64)> = terms.iter().map(|(e, c)| (e.as_slice(), *c)).collect();
    MPoly::from_exps(3, &t)
}

#[test]
fn interpolated_resultant_equals_the_subresultant_one() {
    let mut rng = SplitMix64(0x5e5);
    for case in 0..12 {
        let (df, dg) = (2 + case % 4, 3 + (case / 4) % 3);
        let f = random_poly(&mut rng, df);
        let g = random_poly(&mut rng, dg);
        assert_eq!(
            resultant(&f, &g, 0),
            resultant_prs(&f, &g, 0),
            "case {case}"
        );
        assert_eq!(
            resultant(&g, &f, 0),
            resultant_prs(&g, &f, 0),
            "case {case}"
        );
    }
    // a common factor: zero
    let f = random_poly(&mut rng, 2);
    let (g, h) = (random_poly(&mut rng, 3), random_poly(&mut rng, 2));
    assert!(resultant(&f.mul(&g), &f.mul(&h), 0).is_zero());
}

#[test]
fn discriminant_of_a_product() {
    let mut rng = SplitMix64(0xd15c);
    for case in 0..4 {
        let f = random_poly(&mut rng, 2 + case % 2);
        let g = random_poly(&mut rng, 3);
        let lhs = discriminant(&f.mul(&g), 0);
        let r = resultant(&f, &g, 0);
        let rhs = discriminant(&f, 0)
            .mul(&discriminant(&g, 0))
            .mul(&r)
            .mul(&r);
        assert_eq!(lhs, rhs, "case {case}");
    }
}

#[test]
fn the_probe_check_rejects_a_wrong_determinant() {
    let mut rng = SplitMix64(0xc4ec);
    for n in [2usize, 3, 5] {
        let b: Vec<MPoly> = (0..n * n).map(|_| random_poly(&mut rng, 1)).collect();
        let map = |pr: &Prime, x: &mut [u64]| Some(vec![det_mod_p(pr, n, x)]);
        // the determinant on the certified grid (small: no probe)
        let det = det_zp(3, n, &b).unwrap();
        assert!(verify(&b, std::slice::from_ref(&det), &map), "n = {n}");
        let wrong = det.add(&MPoly::from_exps(3, &[(&[1, 1, 1], 1)]));
        assert!(!verify(&b, &[wrong], &map), "n = {n}");
    }
}

#[test]
fn side_primes_are_not_interpolation_primes() {
    let interp: Vec<u64> = (0..64).map(|i| nth_prime(i).p).collect();
    for i in 0..4 {
        let q = side_prime(i).p;
        assert!(q > 1 << 61 && !interp.contains(&q));
        assert!(exactlti::qkernels::prime::is_prime_u64(q));
    }
}

/// `x y` for row-major `n x n` matrices over Z[a, b, c].
fn matmul(n: usize, x: &[MPoly], y: &[MPoly]) -> Vec<MPoly> {
    (0..n * n)
        .map(|ij| {
            let (i, j) = (ij / n, ij % n);
            (0..n).fold(MPoly::zero(3), |acc, k| {
                acc.add(&x[i * n + k].mul(&y[k * n + j]))
            })
        })
        .collect()
}

/// A random polynomial in (a, b, c) of total degree <= `d` (coefficients in -3..3).
fn random_abc(rng: &mut SplitMix64, d: u32) -> MPoly {
    let mut terms: Vec<(Vec<u32>, i64)> = vec![];
    for ea in 0..=d {
        for eb in 0..=d - ea {
            for ec in 0..=d - ea - eb {
                terms.push((vec![ea, eb, ec], rng.int(-3, 3)));
            }
        }
    }
    let t: Vec<(&[u32], i64)> = terms.iter().map(|(e, c)| (e.as_slice(), *c)).collect();
    MPoly::from_exps(3, &t)
}

#[test]
fn probed_and_certified_grids_agree() {
    let mut rng = SplitMix64(0x9b0b_5eed);
    // n = 5: certified bounds (assignment) of total degree 35, a grid of 8436 points
    let n = 5;
    for case in 0..3 {
        let m: Vec<MPoly> = (0..n * n).map(|_| random_abc(&mut rng, 1)).collect();
        // L unit lower triangular; its inverse (also over Z[a, b, c]) by substitution
        let mut l = vec![MPoly::zero(3); n * n];
        for i in 0..n {
            l[i * n + i] = MPoly::one(3);
            for j in 0..i {
                l[i * n + j] = random_abc(&mut rng, 2);
            }
        }
        let mut linv = vec![MPoly::zero(3); n * n];
        for j in 0..n {
            linv[j * n + j] = MPoly::one(3);
            for i in j + 1..n {
                let s = (j..i).fold(MPoly::zero(3), |acc, k| {
                    acc.add(&l[i * n + k].mul(&linv[k * n + j]))
                });
                linv[i * n + j] = s.neg();
            }
        }
        assert_eq!(matmul(n, &l, &linv), matmul(n, &linv, &l), "case {case}");
        let b = matmul(n, &matmul(n, &l, &m), &linv);
        let map = |pr: &Prime, x: &mut [u64]| Some(charpoly_mod_p(pr, n, x));
        let probed = Bounds::of_square(3, n, &b).probe(&b, &map);
        assert!(
            probed.certified.is_some(),
            "case {case}: the probe lowered the grid"
        );
        let forced = with_certified_grid(|| Bounds::of_square(3, n, &b).probe(&b, &map));
        assert!(forced.certified.is_none(), "case {case}");
        let via_probe = charpoly_zp(3, n, &b).unwrap();
        let certified = with_certified_grid(|| charpoly_zp(3, n, &b)).unwrap();
        assert_eq!(via_probe, certified, "case {case}");
        assert_eq!(certified, charpoly_zp(3, n, &m).unwrap(), "case {case}");
        let det = det_zp(3, n, &b).unwrap();
        assert_eq!(det, with_certified_grid(|| det_zp(3, n, &b)).unwrap());
        assert_eq!(det, det_zp(3, n, &m).unwrap(), "case {case}");
    }
}
