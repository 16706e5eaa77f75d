//! Polynomials over $\mathbb{Z}\lbrack p\rbrack$ evaluated modulo a word prime: one point
//! ([`eval_mod_p`]) or many points with the coefficients reduced once ([`ReducedPoly`],
//! with the power table of [`powers`]). The identity computed is $f(x) \bmod q$.

use super::MPoly;
use crate::qkernels::prime::Prime;
use num_bigint::Sign;

/// $f(x)$ modulo the prime.
pub fn eval_mod_p(pr: &Prime, f: &MPoly, point: &[u64]) -> u64 {
    let mut s = 0u64;
    for (m, c) in f.terms() {
        let (sg, digits) = c.to_u64_digits();
        let mut t = pr.reduce_limbs(sg == Sign::Minus, &digits);
        for (v, &x) in point.iter().enumerate() {
            let e = f.exp(*m, v);
            if e > 0 {
                t = pr.mul(t, pr.pow(x, u64::from(e)));
            }
        }
        s = pr.add(s, t);
    }
    s
}

/// A polynomial reduced modulo a prime once (coefficients as residues, exponent vectors
/// unpacked), for evaluation at many points ([`ReducedPoly::eval`]).
pub struct ReducedPoly {
    terms: Vec<(u64, Vec<u32>)>,
}

impl ReducedPoly {
    pub fn new(pr: &Prime, f: &MPoly) -> Self {
        let terms = f
            .terms()
            .iter()
            .map(|(m, c)| {
                let (sg, digits) = c.to_u64_digits();
                (pr.reduce_limbs(sg == Sign::Minus, &digits), f.exps(*m))
            })
            .collect();
        ReducedPoly { terms }
    }
    /// Largest exponent of any variable.
    pub fn max_exp(&self) -> u32 {
        self.terms
            .iter()
            .flat_map(|(_, e)| e.iter().copied())
            .max()
            .unwrap_or(0)
    }
    /// $f(x)$ with `pw[v][e]` $= x_v^e$ (see [`powers`]).
    pub fn eval(&self, pr: &Prime, pw: &[Vec<u64>]) -> u64 {
        let mut s = 0u64;
        for (c, e) in &self.terms {
            let mut t = *c;
            for (v, &ev) in e.iter().enumerate() {
                if ev > 0 {
                    t = pr.mul(t, pw[v][ev as usize]);
                }
            }
            s = pr.add(s, t);
        }
        s
    }
}

/// `pw[v][e]` $= x_v^e$ for $e \le$ `maxe`.
pub fn powers(pr: &Prime, point: &[u64], maxe: u32) -> Vec<Vec<u64>> {
    point
        .iter()
        .map(|&x| {
            let mut v = vec![1u64; maxe as usize + 1];
            for e in 1..v.len() {
                v[e] = pr.mul(v[e - 1], x);
            }
            v
        })
        .collect()
}
