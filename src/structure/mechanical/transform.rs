//! The transformation $T$: sec. 2.1 ($T^T = [X, A^T X]$) and sec. 3 (the linear system of
//! eq. 15 / eq. 16 and a search of its solution space for an invertible member).
//!
//! Sec. 3 writes the requirements $[I\ 0]\,T A = [0\ I]\,T F$ and $T B = [0; I_p]$ as
//! $L\,\mathrm{vec}(T) = R$ with
//! $L = \begin{bmatrix} A^T \otimes [I\ 0] - F^T \otimes [0\ I] \\ B^T \otimes I_n \end{bmatrix}$,
//! $R = \begin{bmatrix} 0 \\ \mathrm{vec}([0; I_p]) \end{bmatrix}$ ($F = I$ for a standard
//! system; column-stacking $\mathrm{vec}$, so $\mathrm{vec}(P X Q) = (Q^T \otimes P)\mathrm{vec}X$).
//! Its solutions are $T(\alpha) = T_0 + \sum_k \alpha_k T_k$. The paper picks $\alpha$ by a
//! numerical optimisation; here [`find_invertible`] searches integer $\alpha$ with an exact
//! determinant test.
//!
//! # Why the search terminates
//! $\det T(\alpha)$ is a polynomial in $\alpha$ of degree at most $n$ in each variable (each
//! entry of $T$ is affine in $\alpha$). When a normal form exists (see
//! [`super::existence`]) some $T(\alpha)$ is invertible, so the polynomial is not zero, and a
//! non-zero polynomial of degree $\le n$ in each variable cannot vanish on the whole grid
//! $S^s$ with $|S| = n + 1$ (the Schwartz–Zippel / Alon lemma, by induction on $s$). The
//! search first tries $\alpha = 0$ and a fixed pseudo-random sequence of small integer vectors
//! (each succeeds with probability at least $1 - n/(2r+1)$ when its entries are drawn from
//! $[-r, r]$), then enumerates the grid $\{0, \dots, n\}^s$ exhaustively: a finite search that
//! must succeed. An explicit candidate budget turns an (astronomically unlikely) long
//! enumeration into [`Error::Limit`].
//!
//! | entry point | computes |
//! |---|---|
//! | [`transformation_from_x`] | $T = [X^T; X^T A]$ (sec. 2.1, eq. 7) |
//! | [`transformation_family`] | $T_0$ and null-space directions $T_k$ of eq. 15 / 16 |
//! | [`find_invertible`] | an invertible $T(\alpha)$, exact determinant |

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// $T = [X^T; X^T A]$, i.e. $T^T = [X, A^T X]$ (eq. 7): `z = T x` puts the first half of the
/// new state equal to $X^T x$ and the second half to its derivative when $B^T X = 0$.
///
/// # Errors
/// `Shape` when `x` does not have as many rows as `a`.
pub fn transformation_from_x<K: Field>(a: &Matrix<K>, x: &Matrix<K>) -> Result<Matrix<K>> {
    let xt = x.transpose();
    xt.vstack(&xt.try_mul(a)?)
}

/// The affine solution set $\{T_0 + \sum_k \alpha_k T_k\}$ of eq. 15 (or eq. 16 with `f`).
#[derive(Clone, Debug, PartialEq)]
pub struct TransformationFamily<K: Field> {
    /// $T_0$: the solution with all free coordinates of $\mathrm{vec}(T)$ zero.
    pub particular: Matrix<K>,
    /// $T_1, \dots, T_s$: a basis of the null space of $L$, devectorised.
    pub directions: Vec<Matrix<K>>,
}

impl<K: Field> TransformationFamily<K> {
    /// $T(\alpha) = T_0 + \sum_k \alpha_k T_k$ for integer coefficients.
    pub fn member(&self, alpha: &[i64]) -> Matrix<K> {
        let k = self.particular.field();
        let mut t = self.particular.clone();
        for (d, &c) in self.directions.iter().zip(alpha) {
            if c != 0 {
                t = &t + &d.scale(&k.from_i64(c));
            }
        }
        t
    }
}

/// Builds $L$ and $R$ of eq. 15 (`f = None`) or eq. 16 and solves $L\,\mathrm{vec}(T) = R$.
/// Returns `None` when the system has no solution (then no normal form exists).
/// `a` is `n x n` with `n` even, `b` is `n x p`, `f` (if any) is `n x n`.
pub fn transformation_family<K: Field>(
    f: Option<&Matrix<K>>,
    a: &Matrix<K>,
    b: &Matrix<K>,
) -> Option<TransformationFamily<K>> {
    transformation_family_with_l(f, a, b).0
}

/// [`transformation_family`] and the matrix $L$ of eq. 15/16 it solved with.
pub fn transformation_family_with_l<K: Field>(
    f: Option<&Matrix<K>>,
    a: &Matrix<K>,
    b: &Matrix<K>,
) -> (Option<TransformationFamily<K>>, Matrix<K>) {
    let k = a.field().clone();
    let n = a.nrows();
    let p = b.ncols();
    let h = n / 2;
    let id_h = Matrix::identity(k.clone(), h);
    let zero_h = Matrix::zeros(k.clone(), h, h);
    let upper = id_h.hstack(&zero_h).expect("same rows"); // [I 0]
    let lower = zero_h.hstack(&id_h).expect("same rows"); // [0 I]
    let ft = f.map_or_else(|| Matrix::identity(k.clone(), n), |f| f.transpose());
    let l_top = &a.transpose().kron(&upper) - &ft.kron(&lower);
    let l_bot = b.transpose().kron(&Matrix::identity(k.clone(), n));
    let l = l_top.vstack(&l_bot).expect("same columns");
    let mut target = Matrix::zeros(k.clone(), n, p);
    for j in 0..p {
        target.set(n - p + j, j, k.one());
    }
    let r = Matrix::zeros(k.clone(), h * n, 1)
        .vstack(&target.vec())
        .expect("one column");
    let Some((x0, null)) = l.solve(&r).expect("shapes agree") else {
        return (None, l);
    };
    let particular = x0.unvec(n, n).expect("n^2 entries");
    let directions = (0..null.ncols())
        .map(|j| {
            Matrix::column(k.clone(), null.col(j))
                .unvec(n, n)
                .expect("n^2 entries")
        })
        .collect();
    let family = TransformationFamily {
        particular,
        directions,
    };
    (Some(family), l)
}

/// Whether $T = I$ solves eq. 15/16 for `(f, a, b)`: the system is already in mechanical
/// normal form ($[I\ 0] A = [0\ I] F$, $B = [0; I_p]$), so no search is needed.
pub fn identity_solves<K: Field>(f: Option<&Matrix<K>>, a: &Matrix<K>, b: &Matrix<K>) -> bool {
    let k = a.field().clone();
    let (n, p) = (a.nrows(), b.ncols());
    let h = n / 2;
    if n % 2 == 1 || p > h {
        return false;
    }
    let lower = match f {
        None => Matrix::identity(k.clone(), n).submatrix(h, n, 0, n),
        Some(f) => f.submatrix(h, n, 0, n),
    };
    let mut target = Matrix::zeros(k.clone(), n, p);
    for j in 0..p {
        target.set(n - p + j, j, k.one());
    }
    a.submatrix(0, h, 0, n) == lower && *b == target
}

/// An invertible member of a family and how it was found.
#[derive(Clone, Debug, PartialEq)]
pub struct SearchOutcome<K: Field> {
    pub t: Matrix<K>,
    /// The exact (non-zero) determinant of `t`.
    pub det: K::Elem,
    /// The integer coefficients $\alpha$.
    pub alpha: Vec<i64>,
    /// How many candidates were tested (1 = the first one).
    pub candidates: u64,
}

/// Number of pseudo-random candidates before the exhaustive grid enumeration.
const PSEUDO_RANDOM_TRIALS: u64 = 512;

/// SplitMix64, fixed seed: the candidate sequence is deterministic.
use crate::rng::SplitMix64 as SplitMix;

/// The `t`-th pseudo-random candidate (`t >= 1`): sparse 0/1 vectors first, then entries
/// uniform in `[-r, r]` with `r` growing to `degree`.
fn pseudo_random_alpha(rng: &mut SplitMix, t: u64, s: usize, degree: usize) -> Vec<i64> {
    (0..s)
        .map(|_| {
            let z = rng.next_u64();
            if t <= 8 {
                i64::from(z.is_multiple_of(4))
            } else if t <= 16 {
                i64::from(z.is_multiple_of(2))
            } else {
                let r = (1 + (t - 17) / 16).min(degree.max(1) as u64);
                (z % (2 * r + 1)) as i64 - r as i64
            }
        })
        .collect()
}

/// Finds an invertible $T(\alpha)$, testing candidates by exact determinant: $\alpha = 0$,
/// then `PSEUDO_RANDOM_TRIALS` fixed pseudo-random integer vectors, then the grid
/// $\{0..n\}^s$ in odometer order (see the module docs for why this terminates).
///
/// # Errors
/// `Limit` after `max_candidates` singular candidates (the family may contain no invertible
/// member, or the budget is too small).
pub fn find_invertible<K: Field>(
    family: &TransformationFamily<K>,
    max_candidates: u64,
) -> Result<SearchOutcome<K>> {
    let n = family.particular.nrows();
    let s = family.directions.len();
    let k = family.particular.field().clone();
    let mut rng = SplitMix(0x6d6e_665f_7365_6564);
    let mut tried = 0u64;
    let mut test = |alpha: Vec<i64>| -> Option<SearchOutcome<K>> {
        tried += 1;
        let t = family.member(&alpha);
        let det = t.det().expect("square");
        (!k.is_zero(&det)).then_some(SearchOutcome {
            t,
            det,
            alpha,
            candidates: tried,
        })
    };
    let limit = |tried: u64| {
        Error::Limit(format!(
            "no invertible transformation among {tried} candidates of the {s}-parameter family"
        ))
    };
    if let Some(o) = test(vec![0; s]) {
        return Ok(o);
    }
    if s == 0 {
        return Err(limit(1));
    }
    for t in 1..=PSEUDO_RANDOM_TRIALS {
        if t + 1 > max_candidates {
            return Err(limit(t));
        }
        if let Some(o) = test(pseudo_random_alpha(&mut rng, t, s, n)) {
            return Ok(o);
        }
    }
    // Exhaustive grid {0..n}^s: must contain a non-root of the non-zero determinant.
    let mut alpha = vec![0i64; s];
    let mut count = PSEUDO_RANDOM_TRIALS + 1;
    loop {
        // odometer increment; the all-zero start was already tested
        let mut i = 0;
        while i < s && alpha[i] == n as i64 {
            alpha[i] = 0;
            i += 1;
        }
        if i == s {
            return Err(limit(count));
        }
        alpha[i] += 1;
        count += 1;
        if count > max_candidates {
            return Err(limit(count - 1));
        }
        if let Some(o) = test(alpha.clone()) {
            return Ok(o);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::Q;
    use crate::qmat;

    #[test]
    fn search_skips_singular_candidates() {
        // T(alpha) = [[a1, 1], [a1, a2]]: alpha = 0 is singular, det = a1 (a2 - 1).
        let fam = TransformationFamily {
            particular: qmat![[0, 1], [0, 0]],
            directions: vec![qmat![[1, 0], [1, 0]], qmat![[0, 0], [0, 1]]],
        };
        let o = find_invertible(&fam, 10_000).unwrap();
        assert!(o.candidates > 1);
        assert_eq!(o.t, fam.member(&o.alpha));
        assert_ne!(
            o.t.det().unwrap(),
            crate::field::Rational::from_integer(0.into())
        );
    }

    #[test]
    fn search_reports_limit_on_empty_family() {
        let fam = TransformationFamily::<Q> {
            particular: qmat![[1, 1], [1, 1]],
            directions: vec![qmat![[1, 1], [1, 1]]],
        };
        assert!(matches!(find_invertible(&fam, 100), Err(Error::Limit(_))));
        // the exhaustive grid {0..2}^1 is finite: the search stops by itself
        assert!(matches!(
            find_invertible(&fam, u64::MAX),
            Err(Error::Limit(_))
        ));
    }

    #[test]
    fn family_satisfies_equation_15() {
        let a = qmat![[0, 0, 1, 0], [0, 0, 0, 1], [-4, 0, 0, 0], [0, -9, 0, 0]];
        let b = qmat![[0], [0], [0], [1]];
        let fam = transformation_family(None, &a, &b).unwrap();
        assert_eq!(fam.directions.len(), 4); // (n/2)(n - 2p)
        for alpha in [[0, 0, 0, 0], [1, 0, 0, 0], [2, -3, 1, 5]] {
            let t = fam.member(&alpha);
            let ta = &t * &a;
            assert_eq!(ta.submatrix(0, 2, 0, 4), t.submatrix(2, 4, 0, 4));
            assert_eq!(&t * &b, qmat![[0], [0], [0], [1]]);
        }
    }
}
