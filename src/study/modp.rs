//! Reduction of $\mathbb{Q}(v_0) = \mathbb{Q}[t]/(f)$ to $\mathbb{F}_p$ through a root
//! $t_0$ of $f$ modulo $p$: a ring homomorphism on the elements whose denominators stay
//! invertible, so a nonzero minor modulo $p$ proves a nonzero minor over $\mathbb{Q}(v_0)$
//! (rank over $\mathbb{Q}(v_0)$ $\ge$ rank modulo $p$), without any arithmetic on the large
//! coefficients of $\mathbb{Q}(v_0)$.

use super::family::{FamilyForm, ParamFamily, RatMatrix};
use crate::field::{Q, Rational};
use crate::poly::Poly;
use num_bigint::BigInt;
use num_traits::ToPrimitive;

/// Primes tried, and the residues searched for a root of $f$ (all of $\mathbb{F}_p$).
const PRIMES: [u64; 8] = [10007, 10009, 10037, 10039, 10061, 10067, 10069, 10079];

fn pow_mod(mut b: u64, mut e: u64, p: u64) -> u64 {
    let mut r = 1;
    b %= p;
    while e > 0 {
        if e & 1 == 1 {
            r = r * b % p;
        }
        b = b * b % p;
        e >>= 1;
    }
    r
}

fn inv_mod(a: u64, p: u64) -> Option<u64> {
    (!a.is_multiple_of(p)).then(|| pow_mod(a, p - 2, p))
}

fn int_mod(n: &BigInt, p: u64) -> u64 {
    let r = n % BigInt::from(p);
    let r = r.to_i64().unwrap_or(0);
    r.rem_euclid(p as i64) as u64
}

/// $q \bmod p$, `None` when $p$ divides the denominator.
pub fn rational_mod(q: &Rational, p: u64) -> Option<u64> {
    Some(int_mod(q.numer(), p) * inv_mod(int_mod(q.denom(), p), p)? % p)
}

/// $g(t_0) \bmod p$.
pub fn poly_at(g: &Poly<Q>, t0: u64, p: u64) -> Option<u64> {
    let mut acc = 0u64;
    for c in g.coeffs().iter().rev() {
        acc = (acc * t0 + rational_mod(c, p)?) % p;
    }
    Some(acc)
}

/// A prime $p$ and a root $t_0$ of $f$ modulo $p$ ($f$'s coefficients $p$-integral).
pub fn root_mod_p(f: &Poly<Q>, skip: usize) -> Option<(u64, u64)> {
    let mut found = 0;
    for &p in &PRIMES {
        let cs: Option<Vec<u64>> = f.coeffs().iter().map(|c| rational_mod(c, p)).collect();
        let Some(cs) = cs else { continue };
        if cs.last() == Some(&0) {
            continue;
        }
        for t in 0..p {
            let v = cs.iter().rev().fold(0u64, |acc, c| (acc * t + c) % p);
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

/// Rank of a matrix over $\mathbb{F}_p$.
pub fn rank_mod(mut m: Vec<Vec<u64>>, p: u64) -> usize {
    let (rows, cols) = (m.len(), m.first().map_or(0, Vec::len));
    let mut r = 0;
    for c in 0..cols {
        let Some(piv) = (r..rows).find(|&i| m[i][c] != 0) else {
            continue;
        };
        m.swap(r, piv);
        let inv = inv_mod(m[r][c], p).expect("nonzero pivot");
        for i in 0..rows {
            if i != r && m[i][c] != 0 {
                let f = m[i][c] * inv % p;
                for j in c..cols {
                    m[i][j] = (m[i][j] + p - f * m[r][j] % p) % p;
                }
            }
        }
        r += 1;
        if r == rows {
            break;
        }
    }
    r
}

fn mat_at(m: &RatMatrix, t0: u64, p: u64) -> Option<Vec<Vec<u64>>> {
    m.iter()
        .map(|r| {
            r.iter()
                .map(|f| Some(poly_at(&f.num, t0, p)? * inv_mod(poly_at(&f.den, t0, p)?, p)? % p))
                .collect()
        })
        .collect()
}

/// $X^{-1} Y$ over $\mathbb{F}_p$ (Gauss–Jordan), `None` when $X$ is singular.
fn solve_mod(x: Vec<Vec<u64>>, y: Vec<Vec<u64>>, p: u64) -> Option<Vec<Vec<u64>>> {
    let n = x.len();
    let mut a: Vec<Vec<u64>> = x
        .into_iter()
        .zip(y)
        .map(|(mut r, s)| {
            r.extend(s);
            r
        })
        .collect();
    let w = a.first().map_or(0, Vec::len);
    for c in 0..n {
        let piv = (c..n).find(|&i| a[i][c] != 0)?;
        a.swap(c, piv);
        let inv = inv_mod(a[c][c], p)?;
        for j in 0..w {
            a[c][j] = a[c][j] * inv % p;
        }
        for i in 0..n {
            if i != c && a[i][c] != 0 {
                let f = a[i][c];
                for j in 0..w {
                    a[i][j] = (a[i][j] + p - f * a[c][j] % p) % p;
                }
            }
        }
    }
    Some(a.into_iter().map(|r| r[n..].to_vec()).collect())
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
            let n = m.len();
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
