//! Reduction of $\mathbb{Q}(v_0) = \mathbb{Q}[t]/(f)$ to $\mathbb{F}_p$ through a root
//! $t_0$ of $f$ modulo $p$: a ring homomorphism on the elements whose denominators stay
//! invertible, so a nonzero minor modulo $p$ proves a nonzero minor over $\mathbb{Q}(v_0)$
//! (rank over $\mathbb{Q}(v_0)$ $\ge$ rank modulo $p$), without any arithmetic on the large
//! coefficients of $\mathbb{Q}(v_0)$.

use super::family::{FamilyForm, ParamFamily, RatMatrix};
use crate::field::{Q, Rational};
use crate::poly::Poly;
use crate::qkernels::modular::rank::{rank_mod_p, reduce_rational};
use crate::qkernels::modular::rref::rref_mod_p;
use crate::qkernels::prime::Prime;
use crate::ratfunc::kernels::modp::eval_mod_p;

/// Primes tried, and the residues searched for a root of $f$ (all of $\mathbb{F}_p$).
const PRIMES: [u64; 8] = [10007, 10009, 10037, 10039, 10061, 10067, 10069, 10079];

/// $q \bmod p$, `None` when $p$ divides the denominator (the shared kernel's reduction).
pub fn rational_mod(q: &Rational, p: u64) -> Option<u64> {
    reduce_rational(&Prime::new(p), q)
}

/// $g(t_0) \bmod p$.
pub fn poly_at(g: &Poly<Q>, t0: u64, p: u64) -> Option<u64> {
    let pr = Prime::new(p);
    let mut acc = 0u64;
    for c in g.coeffs().iter().rev() {
        acc = pr.add(pr.mul(acc, t0), reduce_rational(&pr, c)?);
    }
    Some(acc)
}

/// A prime $p$ and a root $t_0$ of $f$ modulo $p$ ($f$'s coefficients $p$-integral).
pub fn root_mod_p(f: &Poly<Q>, skip: usize) -> Option<(u64, u64)> {
    let mut found = 0;
    for &p in &PRIMES {
        let pr = Prime::new(p);
        let cs: Option<Vec<u64>> = f.coeffs().iter().map(|c| reduce_rational(&pr, c)).collect();
        let Some(cs) = cs else { continue };
        if cs.last() == Some(&0) {
            continue;
        }
        for t in 0..p {
            let v = cs
                .iter()
                .rev()
                .fold(0u64, |acc, &c| pr.add(pr.mul(acc, t), c));
            if v == 0 {
                if found == skip {
                    return Some((p, t));
                }
                found += 1;
                break;
            }
        }
    }
    None
}

/// Rank of a matrix over $\mathbb{F}_p$ (the shared kernel [`rank_mod_p`]).
pub fn rank_mod(m: Vec<Vec<u64>>, p: u64) -> usize {
    let (rows, cols) = (m.len(), m.first().map_or(0, Vec::len));
    let mut flat: Vec<u64> = m.into_iter().flatten().collect();
    rank_mod_p(&Prime::new(p), rows, cols, &mut flat)
}

/// $m(t_0) \bmod p$ (the shared kernel [`eval_mod_p`] on numerators and denominators),
/// `None` at a pole modulo $p$.
fn mat_at(m: &RatMatrix, t0: u64, p: u64) -> Option<Vec<Vec<u64>>> {
    let pr = Prime::new(p);
    m.rows()
        .iter()
        .map(|r| {
            r.iter()
                .map(|f| {
                    let d = eval_mod_p(&pr, f.den(), &[t0]);
                    Some(pr.mul(eval_mod_p(&pr, f.num(), &[t0]), pr.inv(d)?))
                })
                .collect()
        })
        .collect()
}

/// $X^{-1} Y$ over $\mathbb{F}_p$ (the RREF of $[X \mid Y]$ by the shared kernel
/// [`rref_mod_p`]), `None` when $X$ is singular.
fn solve_mod(x: Vec<Vec<u64>>, y: Vec<Vec<u64>>, p: u64) -> Option<Vec<Vec<u64>>> {
    let n = x.len();
    let k = y.first().map_or(0, Vec::len);
    let w = n + k;
    let mut a: Vec<u64> = x
        .into_iter()
        .zip(y)
        .flat_map(|(r, s)| r.into_iter().chain(s))
        .collect();
    let pivots = rref_mod_p(&Prime::new(p), n, w, &mut a);
    if pivots.len() < n || (n > 0 && pivots[n - 1] != n - 1) {
        return None;
    }
    Some((0..n).map(|i| a[i * w + n..(i + 1) * w].to_vec()).collect())
}

/// $A(t_0) \bmod p$, `None` when a denominator or $\det M$ / $\det E$ vanishes mod $p$.
pub fn state_matrix_mod(fam: &ParamFamily, t0: u64, p: u64) -> Option<Vec<Vec<u64>>> {
    match &fam.form {
        FamilyForm::First { a, e } => {
            let a = mat_at(a, t0, p)?;
            match e {
                None => Some(a),
                Some(e) => solve_mod(mat_at(e, t0, p)?, a, p),
            }
        }
        FamilyForm::Second { m, l, k } => {
            let n = m.nrows();
            let mm = mat_at(m, t0, p)?;
            let mk = solve_mod(mm.clone(), mat_at(k, t0, p)?, p)?;
            let ml = solve_mod(mm, mat_at(l, t0, p)?, p)?;
            let mut a = vec![vec![0u64; 2 * n]; 2 * n];
            for i in 0..n {
                a[i][n + i] = 1;
                for j in 0..n {
                    a[n + i][j] = (p - mk[i][j]) % p;
                    a[n + i][n + j] = (p - ml[i][j]) % p;
                }
            }
            Some(a)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_and_ranks() {
        // f = t^2 - 2 has a root mod 10007? 2 is a QR mod p iff p = +-1 mod 8
        let f = Poly::<Q>::from_i64s(&[-2, 0, 1]);
        if let Some((p, t)) = root_mod_p(&f, 0) {
            assert_eq!(t * t % p, 2);
        }
        assert_eq!(rank_mod(vec![vec![1, 2], vec![2, 4]], 7), 1);
        assert_eq!(rank_mod(vec![vec![1, 2], vec![2, 5]], 7), 2);
        assert_eq!(rational_mod(&Rational::new(1.into(), 2.into()), 7), Some(4));
    }
}
