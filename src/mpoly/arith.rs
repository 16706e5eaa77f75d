//! Ring operations, exact division, evaluation, substitution and derivatives of [`MPoly`].

use super::{MPoly, exp, max_exponent, shift, width};
use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::collections::BTreeMap;

impl MPoly {
    /// `f + g`.
    pub fn add(&self, g: &MPoly) -> MPoly {
        self.merge(g, false)
    }
    /// `f - g`.
    pub fn sub(&self, g: &MPoly) -> MPoly {
        self.merge(g, true)
    }
    fn merge(&self, g: &MPoly, negate: bool) -> MPoly {
        assert_eq!(self.nvars, g.nvars, "variable counts differ");
        let (a, b) = (&self.terms, &g.terms);
        let mut out = Vec::with_capacity(a.len() + b.len());
        let (mut i, mut j) = (0, 0);
        while i < a.len() || j < b.len() {
            if j == b.len() || (i < a.len() && a[i].0 > b[j].0) {
                out.push(a[i].clone());
                i += 1;
            } else if i == a.len() || b[j].0 > a[i].0 {
                let c = if negate { -&b[j].1 } else { b[j].1.clone() };
                out.push((b[j].0, c));
                j += 1;
            } else {
                let c = if negate {
                    &a[i].1 - &b[j].1
                } else {
                    &a[i].1 + &b[j].1
                };
                if !c.is_zero() {
                    out.push((a[i].0, c));
                }
                i += 1;
                j += 1;
            }
        }
        MPoly::from_sorted(self.nvars, out)
    }

    /// Checks that the exponents of `f * g` fit the packing.
    fn check_product_degrees(&self, g: &MPoly) {
        let (df, dg) = (self.degrees(), g.degrees());
        let mx = max_exponent(self.nvars) as u64;
        for (a, b) in df.iter().zip(&dg) {
            assert!(
                *a as u64 + *b as u64 <= mx,
                "multivariate product: exponent beyond {mx}"
            );
        }
    }

    /// `f * g`.
    ///
    /// # Panics
    /// If an exponent of the product exceeds [`super::max_exponent`] (at least 255; callers
    /// bound degrees long before).
    pub fn mul(&self, g: &MPoly) -> MPoly {
        assert_eq!(self.nvars, g.nvars, "variable counts differ");
        if self.is_zero() || g.is_zero() {
            return MPoly::zero(self.nvars);
        }
        self.check_product_degrees(g);
        let (a, b) = if self.len() <= g.len() {
            (self, g)
        } else {
            (g, self)
        };
        if a.len() == 1 {
            let (m, c) = &a.terms[0];
            return MPoly::from_sorted(
                self.nvars,
                b.terms.iter().map(|(n, d)| (m + n, c * d)).collect(),
            );
        }
        // small coefficients: exact i128 accumulation
        let bits = a.max_norm().bits() + b.max_norm().bits() + (a.len() as u64).ilog2() as u64 + 2;
        if bits < 126 {
            let ai: Vec<(u128, i128)> = a
                .terms
                .iter()
                .map(|(m, c)| (*m, c.to_i128().unwrap()))
                .collect();
            let bi: Vec<(u128, i128)> = b
                .terms
                .iter()
                .map(|(m, c)| (*m, c.to_i128().unwrap()))
                .collect();
            let mut acc: super::monomap::MonoMap<i128> =
                super::monomap::with_capacity(product_capacity(a, b));
            for (m, c) in &ai {
                for (n, d) in &bi {
                    *acc.entry(m + n).or_insert(0) += c * d;
                }
            }
            let mut t: Vec<(u128, BigInt)> = acc
                .into_iter()
                .filter(|(_, c)| *c != 0)
                .map(|(m, c)| (m, BigInt::from(c)))
                .collect();
            t.sort_unstable_by_key(|x| std::cmp::Reverse(x.0));
            return MPoly::from_sorted(self.nvars, t);
        }
        let mut acc: super::monomap::MonoMap<BigInt> =
            super::monomap::with_capacity(product_capacity(a, b));
        for (m, c) in &a.terms {
            for (n, d) in &b.terms {
                let e = acc.entry(m + n).or_default();
                *e += c * d;
            }
        }
        let mut t: Vec<(u128, BigInt)> = acc.into_iter().filter(|(_, c)| !c.is_zero()).collect();
        t.sort_unstable_by_key(|x| std::cmp::Reverse(x.0));
        MPoly::from_sorted(self.nvars, t)
    }

    /// `f^e` by repeated squaring.
    pub fn pow(&self, e: u32) -> MPoly {
        crate::field::pow_by_squaring(self, e, MPoly::one(self.nvars), MPoly::mul)
    }

    /// Multiplication by the monomial `c * m`.
    pub fn mul_term(&self, m: u128, c: &BigInt) -> MPoly {
        if c.is_zero() {
            return MPoly::zero(self.nvars);
        }
        MPoly::from_sorted(
            self.nvars,
            self.terms.iter().map(|(n, d)| (m + n, c * d)).collect(),
        )
    }

    /// The exact quotient $q = f / g$ in $\mathbb{Z}\lbrack x\rbrack$, or `None` when $g$ does not
    /// divide $f$ (or `g` is zero). Lex division: the remainder's leading term must always be
    /// divisible by that of $g$.
    pub fn div_exact(&self, g: &MPoly) -> Option<MPoly> {
        if g.is_zero() {
            return None;
        }
        if self.is_zero() {
            return Some(MPoly::zero(self.nvars));
        }
        if let Some(c) = g.to_constant() {
            if self.terms.iter().all(|(_, a)| a.is_multiple_of(&c)) {
                return Some(self.div_integer(&c));
            }
            return None;
        }
        let n = self.nvars;
        let (gm, gc) = (g.terms[0].0, g.terms[0].1.clone());
        // degree screen
        let (df, dg) = (self.degrees(), g.degrees());
        if df.iter().zip(&dg).any(|(a, b)| a < b) {
            return None;
        }
        let divides = |m: u128| (0..n).all(|i| exp(n, m, i) >= exp(n, gm, i));
        let mut rem: BTreeMap<u128, BigInt> = self.terms.iter().cloned().collect();
        let mut q: Vec<(u128, BigInt)> = Vec::new();
        while let Some((&m, _)) = rem.last_key_value() {
            let c = rem.remove(&m).unwrap();
            if !divides(m) {
                return None;
            }
            let (t, r) = c.div_rem(&gc);
            if !r.is_zero() {
                return None;
            }
            let qm = m - gm;
            // a quotient term can have at most deg f - deg g in every variable
            if (0..n).any(|i| exp(n, qm, i) > df[i] - dg[i]) {
                return None;
            }
            for (gm2, gc2) in &g.terms[1..] {
                let key = qm + gm2;
                let v = &t * gc2;
                match rem.entry(key) {
                    std::collections::btree_map::Entry::Occupied(mut o) => {
                        *o.get_mut() -= v;
                        if o.get().is_zero() {
                            o.remove();
                        }
                    }
                    std::collections::btree_map::Entry::Vacant(vac) => {
                        vac.insert(-v);
                    }
                }
            }
            q.push((qm, t));
        }
        Some(MPoly::from_sorted(n, q))
    }

    /// $\partial f / \partial x_i$.
    pub fn derivative(&self, i: usize) -> MPoly {
        let one = 1u128 << shift(self.nvars, i);
        let t = self
            .terms
            .iter()
            .filter_map(|(m, c)| {
                let e = self.exp(*m, i);
                (e > 0).then(|| (m - one, c * BigInt::from(e)))
            })
            .collect();
        MPoly::from_sorted(self.nvars, t)
    }

    /// $f\vert_{x_i = a}$ (the variable stays in the ring, unused).
    pub fn eval_var(&self, i: usize, a: &BigInt) -> MPoly {
        let sh = shift(self.nvars, i);
        let mask = !(((1u128 << width(self.nvars)) - 1) << sh);
        let d = self.deg(i) as usize;
        let mut pw = Vec::with_capacity(d + 1);
        pw.push(BigInt::one());
        for k in 1..=d {
            let p = &pw[k - 1] * a;
            pw.push(p);
        }
        let t = self
            .terms
            .iter()
            .map(|(m, c)| (m & mask, c * &pw[self.exp(*m, i) as usize]))
            .collect();
        MPoly::from_terms(self.nvars, t)
    }

    /// $f(a_0, \dots, a_{k-1})$.
    pub fn eval_all(&self, a: &[BigInt]) -> BigInt {
        let mut s = BigInt::zero();
        for (m, c) in &self.terms {
            let mut t = c.clone();
            for (i, ai) in a.iter().enumerate().take(self.nvars) {
                let e = self.exp(*m, i);
                if e > 0 {
                    t *= num_traits::pow(ai.clone(), e as usize);
                }
            }
            s += t;
        }
        s
    }

    /// Evaluates all variables but `keep` at `a` (entries at `keep` ignored): a univariate
    /// polynomial in $x_{keep}$.
    pub fn eval_except(&self, keep: usize, a: &[BigInt]) -> crate::poly::zpoly::ZPoly {
        let d = self.deg(keep) as usize;
        let mut cs = vec![BigInt::zero(); d + 1];
        for (m, c) in &self.terms {
            let mut t = c.clone();
            for (i, ai) in a.iter().enumerate().take(self.nvars) {
                if i == keep {
                    continue;
                }
                let e = self.exp(*m, i);
                if e > 0 {
                    t *= num_traits::pow(ai.clone(), e as usize);
                }
            }
            cs[self.exp(*m, keep) as usize] += t;
        }
        crate::poly::zpoly::ZPoly::new(cs)
    }

    /// $f\vert_{x_i = x_i + a}$ (Taylor shift in one variable; Horner in $x_i$).
    pub fn shift_var(&self, i: usize, a: &BigInt) -> MPoly {
        if a.is_zero() || self.deg(i) == 0 {
            return self.clone();
        }
        let cs = self.to_univariate(i);
        let lin = MPoly::var(self.nvars, i).add(&MPoly::constant(self.nvars, a.clone()));
        let mut acc = MPoly::zero(self.nvars);
        for c in cs.iter().rev() {
            acc = acc.mul(&lin).add(c);
        }
        acc
    }

    /// $f(x_0, \dots, x_{i-1}, g, x_{i+1}, \dots)$.
    pub fn substitute(&self, i: usize, g: &MPoly) -> MPoly {
        let cs = self.to_univariate(i);
        let mut acc = MPoly::zero(self.nvars);
        for c in cs.iter().rev() {
            acc = acc.mul(g).add(c);
        }
        acc
    }

    /// True when $f$ is free of $x_i$.
    pub fn is_free_of(&self, i: usize) -> bool {
        self.deg(i) == 0
    }

    /// Coefficient signs: is the leading coefficient negative?
    pub fn lc_is_negative(&self) -> bool {
        self.lc().is_negative()
    }
}

/// Most terms reserved up front for a product (the table grows past it when needed): half
/// the term pairs, at most the dense box of the product's degrees, and at most
/// [`MAX_RESERVE`] (two large factors asked for gigabytes that their product never fills).
fn product_capacity(a: &MPoly, b: &MPoly) -> usize {
    let (da, db) = (a.degrees_array(), b.degrees_array());
    let dense = da
        .iter()
        .zip(db.iter())
        .take(a.nvars())
        .fold(1usize, |acc, (x, y)| {
            acc.saturating_mul(*x as usize + *y as usize + 1)
        });
    (a.len().saturating_mul(b.len()) / 2 + 1)
        .min(dense)
        .min(MAX_RESERVE)
}

/// The cap of [`product_capacity`] (about 1M entries).
const MAX_RESERVE: usize = 1 << 20;

#[cfg(test)]
mod tests {
    use crate::mpoly::parse::abc as p;
    #[test]
    fn ring_ops() {
        let f = p("a*b + c^2 + 1");
        let g = p("a - b + 2*c");
        let h = f.mul(&g);
        assert_eq!(h.div_exact(&g).unwrap(), f);
        assert_eq!(h.div_exact(&f).unwrap(), g);
        assert!(h.div_exact(&p("a + 1")).is_none());
        assert_eq!(f.pow(3).div_exact(&f).unwrap(), f.pow(2));
        assert_eq!(f.derivative(0), p("b"));
        assert_eq!(f.eval_var(2, &2.into()), p("a*b + 5"));
        assert_eq!(f.eval_all(&[1.into(), 2.into(), 3.into()]), 12.into());
        assert_eq!(g.shift_var(0, &1.into()), p("a + 1 - b + 2*c"));
        assert_eq!(f.substitute(0, &p("c")), p("b*c + c^2 + 1"));
        let big = p("123456789012345678901234567890*a + b").pow(3);
        assert_eq!(
            big.div_exact(&p("123456789012345678901234567890*a + b"))
                .unwrap()
                .len(),
            3
        );
    }
}
