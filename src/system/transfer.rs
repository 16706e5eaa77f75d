//! Exact transfer matrices $G(s) = C (sI - A)^{-1} B + D$.
//!
//! # Algorithm
//! Faddeev–LeVerrier form of the adjugate: with $\det(sI - A) = \sum_k c_k s^k$ (monic),
//! $\mathrm{adj}(sI - A) = \sum_{k=0}^{n-1} s^{n-1-k} R_k$, $R_0 = I$,
//! $R_k = A R_{k-1} + c_{n-k} I = \sum_{j \le k} c_{n-k+j} A^j$, so
//! $C R_k B = \sum_{j \le k} c_{n-k+j} h_j$ with the Markov parameters $h_j = C A^j B$
//! ($n$ products of $A$ with an $n \times m$ matrix). Then
//! $G_{ij} = (C\,\mathrm{adj}\,B)_{ij}/\det + D_{ij}$, each entry reduced to lowest terms with
//! a monic denominator.

use super::StateSpace;
use crate::error::Result;
use crate::field::Field;
use crate::poly::Poly;

/// A rational function `num / den` in lowest terms, `den` monic.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalFunction<K: Field> {
    pub num: Poly<K>,
    pub den: Poly<K>,
}

impl<K: Field> RationalFunction<K> {
    /// Reduces `num / den` (`den` non-zero) to lowest terms with a monic denominator.
    pub fn new(num: Poly<K>, den: Poly<K>) -> Self {
        let g = num.gcd(&den);
        let (mut n, mut d) = if g.is_zero() || g.is_one() {
            (num, den)
        } else {
            (num.quo(&g), den.quo(&g))
        };
        if n.is_zero() {
            d = Poly::one(d.field().clone());
        }
        let l = d.lc();
        let li = d.field().inv(&l).expect("non-zero denominator");
        n = n.scale(&li);
        d = d.scale(&li);
        RationalFunction { num: n, den: d }
    }
    pub fn is_proper(&self) -> bool {
        self.num.is_zero() || self.num.deg() <= self.den.deg()
    }
}

/// A matrix of rational functions.
#[derive(Clone, Debug, PartialEq)]
pub struct TransferMatrix<K: Field> {
    pub entries: Vec<Vec<RationalFunction<K>>>,
}

impl<K: Field> TransferMatrix<K> {
    /// Whether `self` is the transfer matrix of `s`: the Laurent coefficients at infinity of
    /// every entry equal `D`, `C B`, `C A B`, ... up to `C A^{2n-1} B` (`n` = states), which
    /// determines a proper rational matrix of McMillan degree at most `n`. False for an
    /// improper entry.
    pub fn matches_markov(&self, s: &StateSpace<K>) -> bool {
        let g = self;
        let k = s.a.field().clone();
        let terms = 2 * s.nstates() + 1;
        let mut h = vec![s.d.clone()];
        let mut ak_b = s.b.clone();
        for _ in 1..terms {
            h.push(&s.c * &ak_b);
            ak_b = &s.a * &ak_b;
        }
        for (i, row) in g.entries.iter().enumerate() {
            for (j, f) in row.iter().enumerate() {
                let dd = f.den.deg();
                if !f.num.is_zero() && f.num.deg() > dd {
                    return false;
                }
                // num(1/t) t^dd / (den(1/t) t^dd) as a power series in t
                let rn: Vec<_> = (0..=dd).map(|q| f.num.coeff(dd - q)).collect();
                let rd: Vec<_> = (0..=dd).map(|q| f.den.coeff(dd - q)).collect();
                let Some(lead) = k.inv(&rd[0]) else {
                    return false;
                };
                let mut series: Vec<K::Elem> = Vec::with_capacity(terms);
                for q in 0..terms {
                    let mut c = rn.get(q).cloned().unwrap_or_else(|| k.zero());
                    for (r, dr) in rd.iter().enumerate().skip(1) {
                        if r > q {
                            break;
                        }
                        c = k.sub(&c, &k.mul(dr, &series[q - r]));
                    }
                    series.push(k.mul(&c, &lead));
                }
                if (0..terms).any(|q| series[q] != *h[q].get(i, j)) {
                    return false;
                }
            }
        }
        true
    }
}

impl<K: Field> StateSpace<K> {
    /// The exact transfer matrix.
    ///
    /// # Errors
    /// Never for a valid system (shapes are checked at construction).
    pub fn transfer_matrix(&self) -> Result<TransferMatrix<K>> {
        self.transfer_matrix_recorded(None)
    }

    /// [`StateSpace::transfer_matrix`], recording its steps into `rec` (`tf --steps`, see
    /// [`super::steps`]).
    ///
    /// # Errors
    /// As [`StateSpace::transfer_matrix`].
    pub fn transfer_matrix_recorded(
        &self,
        mut rec: Option<&mut crate::jordan::derivation::Recorder<'_, K>>,
    ) -> Result<TransferMatrix<K>> {
        let k = self.field().clone();
        let n = self.nstates();
        let cp = self.a.charpoly()?;
        if let Some(r) = rec.as_deref_mut() {
            super::steps::charpoly(r, &self.a, &cp);
        }
        // numerator polynomial matrix N(s) = sum_k s^{n-1-k} C R_k B, with
        // C R_k B = sum_{j <= k} c_{n-k+j} h_j from the Markov parameters h_j = C A^j B
        // (products of A with the n x m matrix A^j B, not with n x n matrices)
        let (p, m) = (self.noutputs(), self.ninputs());
        let mut num: Vec<Vec<Vec<K::Elem>>> = vec![vec![vec![k.zero(); n.max(1)]; m]; p];
        let mut markov = Vec::with_capacity(n);
        let mut w = self.b.clone();
        for j in 0..n {
            if j > 0 {
                w = &self.a * &w;
            }
            markov.push(&self.c * &w);
        }
        if let Some(r) = rec.as_deref_mut() {
            super::steps::markov(r, self, &markov);
        }
        for kk in 0..n {
            for (j, h) in markov.iter().enumerate().take(kk + 1) {
                let c = cp.coeff(n - kk + j);
                if k.is_zero(&c) {
                    continue;
                }
                for (i, row) in num.iter_mut().enumerate() {
                    for (jj, slot) in row.iter_mut().enumerate() {
                        k.mul_add_assign(&mut slot[n - 1 - kk], &c, h.get(i, jj));
                    }
                }
            }
        }
        if let Some(r) = rec.as_deref_mut() {
            super::steps::numerators(r, self, &num, &cp);
        }
        let entries: Vec<Vec<RationalFunction<K>>> = (0..p)
            .map(|i| {
                (0..m)
                    .map(|j| {
                        let nij = if n == 0 {
                            Poly::zero(k.clone())
                        } else {
                            Poly::new(k.clone(), num[i][j].clone())
                        };
                        let total = nij.add(&cp.scale(self.d.get(i, j)));
                        RationalFunction::new(total, cp.clone())
                    })
                    .collect()
            })
            .collect();
        let g = TransferMatrix { entries };
        if let Some(r) = rec {
            let all = || g.entries.iter().flat_map(|r| r.iter());
            let nd = (
                all().map(|f| f.num.clone()).collect(),
                all().map(|f| f.den.clone()).collect(),
            );
            super::steps::entries(r, self, nd, g.matches_markov(self));
        }
        Ok(g)
    }
}
