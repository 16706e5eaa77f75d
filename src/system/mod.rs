//! LTI systems: standard state space, descriptor and second-order forms.
//!
//! | type / entry point | meaning |
//! |---|---|
//! | [`StateSpace`] | $\dot x = A x + B u$, $y = C x + D u$ |
//! | [`Descriptor`] | $E \dot x = A x + B u$, $y = C x + D u$ |
//! | [`StateSpace::from_second_order`] | $M \ddot q + L \dot q + K q = F u$ as $x = [q; \dot q]$ (paper eq. 1-4) |
//! | [`StateSpace::transform`] | coordinates $x = T z$: $(T^{-1}AT, T^{-1}B, CT, D)$ |
//! | [`StateSpace::markov`] | Markov parameters $C A^k B$ |
//! | [`transfer::TransferMatrix`] | $G(s) = C (sI - A)^{-1} B + D$ as exact rational functions |
//! | [`transfer_algebra`] | sums, products, block diagonals of transfer matrices (exact) |
//! | [`dcgain::dc_gain`] | $G(0) = D - C A^{-1} B$ per channel (infinite at a pole at 0) |
//! | [`interconnect`] | series, parallel, feedback, append (python-control's conventions) |
//! | [`discrete`] | sample time: Tustin c2d/d2c, step and impulse sequences, stability in $|z| < 1$ |
//! | [`margins::margins`] | gain and phase margins of a SISO system, exact crossover frequencies |

pub mod dcgain;
pub mod discrete;
pub mod interconnect;
pub mod margins;
pub(crate) mod steps;
pub mod time_response;
pub mod transfer;
pub(crate) mod transfer_algebra;

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// A standard state-space system over the field `K`.
#[derive(Clone, Debug, PartialEq)]
pub struct StateSpace<K: Field> {
    pub a: Matrix<K>,
    pub b: Matrix<K>,
    pub c: Matrix<K>,
    pub d: Matrix<K>,
}

/// A descriptor system $E \dot x = A x + B u$, $y = C x + D u$.
#[derive(Clone, Debug, PartialEq)]
pub struct Descriptor<K: Field> {
    pub e: Matrix<K>,
    pub a: Matrix<K>,
    pub b: Matrix<K>,
    pub c: Matrix<K>,
    pub d: Matrix<K>,
}

fn check_abcd<K: Field>(a: &Matrix<K>, b: &Matrix<K>, c: &Matrix<K>, d: &Matrix<K>) -> Result<()> {
    if !a.is_square() {
        return Err(Error::NotSquare {
            op: "state space A",
            nrows: a.nrows(),
            ncols: a.ncols(),
        });
    }
    let n = a.nrows();
    if b.nrows() != n {
        return Err(Error::Shape {
            op: "state space B",
            expected: (n, b.ncols()),
            found: b.shape(),
        });
    }
    if c.ncols() != n {
        return Err(Error::Shape {
            op: "state space C",
            expected: (c.nrows(), n),
            found: c.shape(),
        });
    }
    if d.shape() != (c.nrows(), b.ncols()) {
        return Err(Error::Shape {
            op: "state space D",
            expected: (c.nrows(), b.ncols()),
            found: d.shape(),
        });
    }
    if a.field() != b.field() || a.field() != c.field() || a.field() != d.field() {
        return Err(Error::FieldMismatch);
    }
    Ok(())
}

impl<K: Field> StateSpace<K> {
    /// # Errors
    /// `NotSquare`/`Shape` when the matrices do not fit together.
    pub fn new(a: Matrix<K>, b: Matrix<K>, c: Matrix<K>, d: Matrix<K>) -> Result<Self> {
        check_abcd(&a, &b, &c, &d)?;
        Ok(StateSpace { a, b, c, d })
    }
    /// System with zero feedthrough.
    ///
    /// # Errors
    /// As [`StateSpace::new`].
    pub fn new_strictly_proper(a: Matrix<K>, b: Matrix<K>, c: Matrix<K>) -> Result<Self> {
        let d = Matrix::zeros(a.field().clone(), c.nrows(), b.ncols());
        Self::new(a, b, c, d)
    }
    pub fn field(&self) -> &K {
        self.a.field()
    }
    pub fn nstates(&self) -> usize {
        self.a.nrows()
    }
    pub fn ninputs(&self) -> usize {
        self.b.ncols()
    }
    pub fn noutputs(&self) -> usize {
        self.c.nrows()
    }
    /// The system in coordinates $x = T z$: $(T^{-1} A T, T^{-1} B, C T, D)$.
    ///
    /// # Errors
    /// `Singular` when `T` is not invertible; `Shape` on mismatch.
    pub fn transform(&self, t: &Matrix<K>) -> Result<Self> {
        let ti = t.inverse()?;
        self.transform_with_inverse(t, &ti)
    }
    /// As [`StateSpace::transform`] with a known $T^{-1}$.
    ///
    /// # Errors
    /// `Shape` on mismatch.
    pub fn transform_with_inverse(&self, t: &Matrix<K>, ti: &Matrix<K>) -> Result<Self> {
        Ok(StateSpace {
            a: ti.try_mul(&self.a.try_mul(t)?)?,
            b: ti.try_mul(&self.b)?,
            c: self.c.try_mul(t)?,
            d: self.d.clone(),
        })
    }
    /// The first `k` Markov parameters $C A^i B$, $i = 0..k-1$, as $(C A^{i-h})(A^h B)$ with
    /// $h = \lfloor i/2 \rfloor$: both halves at most $\lceil k/2 \rceil$ powers deep. In a
    /// controllable companion form the columns $A^i e_1$ swell past $i = n$ while the rows
    /// $C A^i$ stay Markov parameters, in an observer form the other way round (over
    /// $\mathbb{Q}(p_0..p_9)$: $10^5$ terms per entry at depth $2n$); at depth $\le n$ both
    /// are still unit vectors or one coefficient row.
    pub fn markov(&self, k: usize) -> Vec<Matrix<K>> {
        let mut left = vec![self.c.clone()]; // C A^j
        let mut right = vec![self.b.clone()]; // A^j B
        let mut out = Vec::with_capacity(k);
        for i in 0..k {
            let h = i / 2;
            if right.len() <= h {
                let next = &self.a * right.last().expect("one");
                right.push(next);
            }
            if left.len() <= i - h {
                let next = left.last().expect("one") * &self.a;
                left.push(next);
            }
            out.push(&left[i - h] * &right[h]);
        }
        out
    }
    /// Do the Markov parameters $C A^i B$ of `self` and `other` agree for $i < k$, and the
    /// feedthroughs too? (Equal transfer matrices when `k >= n1 + n2`.)
    pub fn same_markov(&self, other: &Self, k: usize) -> bool {
        self.d == other.d
            && self.ninputs() == other.ninputs()
            && self.noutputs() == other.noutputs()
            && self.markov(k) == other.markov(k)
    }
    /// Keeps the states `idx` (in that order).
    pub fn select_states(&self, idx: &[usize]) -> Self {
        StateSpace {
            a: self.a.select_rows(idx).select_cols(idx),
            b: self.b.select_rows(idx),
            c: self.c.select_cols(idx),
            d: self.d.clone(),
        }
    }
    /// The dual system $(A^T, C^T, B^T, D^T)$.
    pub fn dual(&self) -> Self {
        StateSpace {
            a: self.a.transpose(),
            b: self.c.transpose(),
            c: self.b.transpose(),
            d: self.d.transpose(),
        }
    }
    /// First-order form of $M \ddot q + L \dot q + K q = F u$ with $x = [q; \dot q]$:
    /// $A = [[0, I], [-M^{-1}K, -M^{-1}L]]$, $B = [0; M^{-1}F]$ (paper eq. 3). `c`, `d`
    /// act on $[q; \dot q]$; when absent the outputs are the positions $q$ (eq. 4).
    ///
    /// # Errors
    /// `Singular` when `M` is singular; shape errors.
    pub fn from_second_order(
        m: &Matrix<K>,
        l: &Matrix<K>,
        k: &Matrix<K>,
        f: &Matrix<K>,
        c: Option<&Matrix<K>>,
        d: Option<&Matrix<K>>,
    ) -> Result<Self> {
        m.check_square("second-order M")?;
        let n2 = m.nrows();
        l.check_shape("second-order L", (n2, n2))?;
        k.check_shape("second-order K", (n2, n2))?;
        if f.nrows() != n2 {
            return Err(Error::Shape {
                op: "second-order F",
                expected: (n2, f.ncols()),
                found: f.shape(),
            });
        }
        let fld = m.field().clone();
        let mi = m.inverse()?;
        let z = Matrix::zeros(fld.clone(), n2, n2);
        let i = Matrix::identity(fld.clone(), n2);
        let a = Matrix::block(
            fld.clone(),
            &[vec![&z, &i], vec![&(-&(&mi * k)), &(-&(&mi * l))]],
        )?;
        let b = Matrix::zeros(fld.clone(), n2, f.ncols()).vstack(&(&mi * f))?;
        let c = match c {
            Some(c) => c.clone(),
            None => i.hstack(&z)?,
        };
        let d = match d {
            Some(d) => d.clone(),
            None => Matrix::zeros(fld, c.nrows(), f.ncols()),
        };
        Self::new(a, b, c, d)
    }
}

impl<K: Field> Descriptor<K> {
    /// # Errors
    /// Shape errors, `NotSquare` for `E` or `A`.
    pub fn new(
        e: Matrix<K>,
        a: Matrix<K>,
        b: Matrix<K>,
        c: Matrix<K>,
        d: Matrix<K>,
    ) -> Result<Self> {
        check_abcd(&a, &b, &c, &d)?;
        e.check_shape("descriptor E", a.shape())?;
        Ok(Descriptor { e, a, b, c, d })
    }
    pub fn nstates(&self) -> usize {
        self.a.nrows()
    }
}
