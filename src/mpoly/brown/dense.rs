//! Arithmetic mod a word prime on dense arrays: univariate polynomials (`Up`, low degree
//! first) and dense multivariate polynomials ([`Dense`], a flat array, the last variable
//! contiguous), with evaluation of the last variable, Newton interpolation in it, contents in
//! it, and exact division through a Kronecker substitution.

use num_bigint::{BigInt, Sign};

#[derive(Clone, Copy)]
pub(super) struct Zp {
    pub p: u64,
}

impl Zp {
    #[inline(always)]
    pub fn add(self, a: u64, b: u64) -> u64 {
        let s = a + b;
        if s >= self.p { s - self.p } else { s }
    }
    #[inline(always)]
    pub fn sub(self, a: u64, b: u64) -> u64 {
        if a >= b { a - b } else { a + self.p - b }
    }
    #[inline(always)]
    pub fn mul(self, a: u64, b: u64) -> u64 {
        a * b % self.p
    }
    /// Inverse of a nonzero residue (extended Euclid).
    pub fn inv(self, a: u64) -> u64 {
        let (mut t, mut nt) = (0i64, 1i64);
        let (mut r, mut nr) = (self.p as i64, a as i64);
        while nr != 0 {
            let q = r / nr;
            (t, nt) = (nt, t - q * nt);
            (r, nr) = (nr, r - q * nr);
        }
        debug_assert_eq!(r, 1, "inverse of a non-unit");
        if t < 0 {
            (t + self.p as i64) as u64
        } else {
            t as u64
        }
    }
    /// `c mod p` in `[0, p)`.
    pub fn reduce(self, c: &BigInt) -> u64 {
        let (sign, digits) = c.to_u64_digits();
        let mut r: u128 = 0;
        for &d in digits.iter().rev() {
            r = ((r << 64) | d as u128) % self.p as u128;
        }
        let r = r as u64;
        if sign == Sign::Minus && r != 0 {
            self.p - r
        } else {
            r
        }
    }
}

// ---------------------------------------------------------------- univariate

/// Dense univariate polynomial, low degree first; [`utrim`] drops leading zeros.
pub(super) type Up = Vec<u64>;

pub(super) fn utrim(a: &mut Up) {
    while a.last() == Some(&0) {
        a.pop();
    }
}

fn urem_in_place(zp: Zp, a: &mut Up, b: &[u64]) {
    let db = b.len() - 1;
    let inv = zp.inv(b[db]);
    while a.len() > db {
        let d = a.len() - 1;
        let q = zp.mul(a[d], inv);
        if q != 0 {
            for j in 0..db {
                a[d - db + j] = zp.sub(a[d - db + j], zp.mul(q, b[j]));
            }
        }
        a.pop();
        utrim(a);
    }
}

/// Monic gcd (empty for two zeros).
pub(super) fn ugcd(zp: Zp, a: &[u64], b: &[u64]) -> Up {
    let (mut a, mut b) = (a.to_vec(), b.to_vec());
    utrim(&mut a);
    utrim(&mut b);
    while !b.is_empty() {
        if b.len() == 1 {
            return vec![1];
        }
        urem_in_place(zp, &mut a, &b);
        std::mem::swap(&mut a, &mut b);
    }
    umonic(zp, &mut a);
    a
}

pub(super) fn umonic(zp: Zp, a: &mut Up) {
    if let Some(&l) = a.last()
        && l != 1
    {
        let i = zp.inv(l);
        for c in a.iter_mut() {
            *c = zp.mul(*c, i);
        }
    }
}

/// Quotient `a / b` (`b` nonzero, trimmed) and whether the remainder is zero.
pub(super) fn udivrem(zp: Zp, a: &[u64], b: &[u64]) -> (Up, bool) {
    let mut r = a.to_vec();
    utrim(&mut r);
    let db = b.len() - 1;
    if r.len() <= db {
        return (Vec::new(), r.is_empty());
    }
    let inv = zp.inv(b[db]);
    let mut q = vec![0; r.len() - db];
    for d in (db..r.len()).rev() {
        let c = zp.mul(r[d], inv);
        q[d - db] = c;
        if c != 0 {
            for j in 0..=db {
                r[d - db + j] = zp.sub(r[d - db + j], zp.mul(c, b[j]));
            }
        }
    }
    (q, r[..db].iter().all(|&c| c == 0))
}

pub(super) fn umul(zp: Zp, a: &[u64], b: &[u64]) -> Up {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut r = vec![0; a.len() + b.len() - 1];
    for (i, &x) in a.iter().enumerate() {
        if x != 0 {
            for (j, &y) in b.iter().enumerate() {
                r[i + j] = zp.add(r[i + j], zp.mul(x, y));
            }
        }
    }
    utrim(&mut r);
    r
}

#[inline]
pub(super) fn ueval(zp: Zp, a: &[u64], x: u64) -> u64 {
    a.iter().rev().fold(0, |s, &c| zp.add(zp.mul(s, x), c))
}

/// Degree of a (possibly untrimmed) fiber; `None` when zero.
#[inline]
fn fdeg(a: &[u64]) -> Option<usize> {
    a.iter().rposition(|&c| c != 0)
}

// ---------------------------------------------------------------- dense multivariate

/// Dense polynomial in `dims.len()` variables, exponent of variable `i` below `dims[i]`;
/// index $\sum_i e_i s_i$ with the last variable at stride 1, so index order is lex order
/// (variable 0 first).
#[derive(Clone, Debug, PartialEq, Eq)]
pub(super) struct Dense {
    pub dims: Vec<usize>,
    pub c: Vec<u64>,
}

impl Dense {
    pub fn zeros(dims: Vec<usize>) -> Dense {
        let n = dims.iter().product();
        Dense {
            dims,
            c: vec![0; n],
        }
    }
    /// Length of a fiber in the last variable.
    pub fn flen(&self) -> usize {
        *self.dims.last().unwrap()
    }
    pub fn fibers(&self) -> std::slice::ChunksExact<'_, u64> {
        self.c.chunks_exact(self.flen())
    }
    /// Index of the lex leading term.
    pub fn lead(&self) -> Option<usize> {
        self.c.iter().rposition(|&c| c != 0)
    }
    /// The last variable set to `b`.
    pub fn eval_last(&self, zp: Zp, b: u64) -> Dense {
        let dims = self.dims[..self.dims.len() - 1].to_vec();
        let c = self.fibers().map(|u| ueval(zp, u, b)).collect();
        Dense { dims, c }
    }
    /// Largest degree in the last variable.
    pub fn deg_last(&self) -> usize {
        self.fibers().filter_map(fdeg).max().unwrap_or(0)
    }
    /// The leading fiber (coefficient of the lex leading monomial in the other variables).
    pub fn lead_fiber(&self) -> Up {
        let l = self.flen();
        let i = self.lead().unwrap_or(0) / l;
        let mut u = self.c[i * l..(i + 1) * l].to_vec();
        utrim(&mut u);
        u
    }
    /// Monic gcd of the fibers (the content in the last variable).
    pub fn content_last(&self, zp: Zp) -> Up {
        let mut nz: Vec<&[u64]> = Vec::new();
        for u in self.fibers() {
            match fdeg(u) {
                None => {}
                Some(0) => return vec![1],
                Some(_) => nz.push(u),
            }
        }
        nz.sort_by_key(|u| fdeg(u));
        let mut g: Up = Vec::new();
        for u in nz {
            g = ugcd(zp, &g, u);
            if g.len() == 1 {
                break;
            }
        }
        g
    }
    /// Every fiber divided by `d` (assumed to divide), same shape.
    pub fn div_fibers(&self, zp: Zp, d: &[u64]) -> Dense {
        let l = self.flen();
        let mut c = vec![0; self.c.len()];
        for (out, u) in c.chunks_exact_mut(l).zip(self.fibers()) {
            if fdeg(u).is_some() {
                let (q, _) = udivrem(zp, u, d);
                out[..q.len()].copy_from_slice(&q);
            }
        }
        Dense {
            dims: self.dims.clone(),
            c,
        }
    }
    /// Every fiber multiplied by `m`, in a shape whose last dimension is `len`; `None` if a
    /// product does not fit.
    pub fn mul_fibers(&self, zp: Zp, m: &[u64], len: usize) -> Option<Dense> {
        let mut dims = self.dims.clone();
        *dims.last_mut().unwrap() = len;
        let mut out = Dense::zeros(dims);
        for (o, u) in out.c.chunks_exact_mut(len).zip(self.fibers()) {
            if fdeg(u).is_some() {
                let q = umul(zp, u, m);
                if q.len() > len {
                    return None;
                }
                o[..q.len()].copy_from_slice(&q);
            }
        }
        Some(out)
    }
    /// Primitive part in the last variable.
    pub fn pp_last(&self, zp: Zp) -> Dense {
        let c = self.content_last(zp);
        if c.len() <= 1 {
            self.clone()
        } else {
            self.div_fibers(zp, &c)
        }
    }
    pub fn scale(&mut self, zp: Zp, s: u64) {
        if s != 1 {
            for c in self.c.iter_mut() {
                *c = zp.mul(*c, s);
            }
        }
    }
    /// Calls `f(exponents, coefficient)` for every nonzero term.
    pub fn for_each_term(&self, mut f: impl FnMut(&[usize], u64)) {
        let k = self.dims.len();
        let mut e = [0usize; super::super::MAX_VARS];
        for (i, &c) in self.c.iter().enumerate() {
            if c != 0 {
                let mut r = i;
                for j in (0..k).rev() {
                    e[j] = r % self.dims[j];
                    r /= self.dims[j];
                }
                f(&e[..k], c);
            }
        }
    }
    /// The same polynomial in another shape; `None` if a term does not fit.
    pub fn reshape(&self, dims: &[usize]) -> Option<Dense> {
        if dims == self.dims.as_slice() {
            return Some(self.clone());
        }
        let mut out = Dense::zeros(dims.to_vec());
        let mut fits = true;
        self.for_each_term(|e, c| {
            if e.iter().zip(dims).any(|(a, d)| a >= d) {
                fits = false;
            } else {
                out.c[index(dims, e)] = c;
            }
        });
        fits.then_some(out)
    }
}

/// Flat index of an exponent vector.
pub(super) fn index(dims: &[usize], e: &[usize]) -> usize {
    e.iter().zip(dims).fold(0, |s, (&ei, &d)| s * d + ei)
}

/// The exact quotient $a / d$ in the shape of `a`, or `None` when $d$ does not divide $a$.
/// Kronecker substitution in `a`'s shape: long division of the flat arrays from the top; the
/// quotient is a true multivariate quotient when its degrees plus those of $d$ stay inside
/// the shape (checked), since then no exponent wraps.
pub(super) fn div_dense(zp: Zp, a: &Dense, d: &Dense) -> Option<Dense> {
    let dims = &a.dims;
    let mut dt: Vec<(usize, u64)> = Vec::new();
    let mut ddeg = vec![0usize; dims.len()];
    let mut fits = true;
    d.for_each_term(|e, c| {
        if e.iter().zip(dims).any(|(x, n)| x >= n) {
            fits = false;
            return;
        }
        for (m, x) in ddeg.iter_mut().zip(e) {
            *m = (*m).max(*x);
        }
        dt.push((index(dims, e), c));
    });
    if !fits {
        return None;
    }
    let &(pd, cd) = dt.last()?;
    dt.pop();
    let inv = zp.inv(cd);
    let mut r = a.c.clone();
    let mut q = vec![0u64; r.len()];
    let mut qdeg = vec![0usize; dims.len()];
    let mut pos = r.len();
    while pos > pd {
        pos -= 1;
        let c = r[pos];
        if c == 0 {
            continue;
        }
        let t = zp.mul(c, inv);
        let qp = pos - pd;
        q[qp] = t;
        r[pos] = 0;
        let mut rem = qp;
        for j in (0..dims.len()).rev() {
            let e = rem % dims[j];
            rem /= dims[j];
            if e + ddeg[j] >= dims[j] {
                return None;
            }
            qdeg[j] = qdeg[j].max(e);
        }
        for &(pj, cj) in &dt {
            let x = &mut r[qp + pj];
            *x = zp.sub(*x, zp.mul(t, cj));
        }
    }
    if r[..pd].iter().any(|&c| c != 0) {
        return None;
    }
    Some(Dense {
        dims: dims.clone(),
        c: q,
    })
}

/// Newton interpolation in a new last variable: `pre` values per point, at most `len`
/// points.
pub(super) struct Interp {
    pub len: usize,
    pub c: Vec<u64>,
}

impl Interp {
    pub fn new(pre: usize, len: usize) -> Interp {
        Interp {
            len,
            c: vec![0; pre * len],
        }
    }
    /// Adds the values `img` at `x = b`, given $M = \prod (x - b_j)$ over the `npts` earlier
    /// points (`m.len() == npts + 1`) and `s` = $1 / M(b)$. Returns whether the interpolant
    /// changed (it did not iff it already took these values at `b`).
    pub fn add(&mut self, zp: Zp, img: &[u64], b: u64, m: &[u64], s: u64) -> bool {
        let npts = m.len() - 1;
        let mut changed = false;
        for (f, &v) in self.c.chunks_exact_mut(self.len).zip(img) {
            let hb = ueval(zp, &f[..npts], b);
            let diff = zp.sub(v, hb);
            if diff != 0 {
                changed = true;
                let t = zp.mul(diff, s);
                for (x, &me) in f.iter_mut().zip(m) {
                    *x = zp.add(*x, zp.mul(t, me));
                }
            }
        }
        changed
    }
    /// As a dense polynomial with the interpolation variable last.
    pub fn to_dense(&self, pre_dims: &[usize]) -> Dense {
        let mut dims = pre_dims.to_vec();
        dims.push(self.len);
        Dense {
            dims,
            c: self.c.clone(),
        }
    }
    pub fn clear(&mut self) {
        self.c.iter_mut().for_each(|x| *x = 0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    const ZP: Zp = Zp { p: 2_147_483_647 };

    /// Dense from (exponents, coefficient) pairs.
    fn dense(dims: &[usize], t: &[(&[usize], u64)]) -> Dense {
        let mut d = Dense::zeros(dims.to_vec());
        for (e, c) in t {
            d.c[index(dims, e)] = *c;
        }
        d
    }

    /// Naive dense product (the oracle).
    fn mul(a: &Dense, b: &Dense, dims: &[usize]) -> Dense {
        let mut out = Dense::zeros(dims.to_vec());
        a.for_each_term(|ea, ca| {
            b.for_each_term(|eb, cb| {
                let e: Vec<usize> = ea.iter().zip(eb).map(|(x, y)| x + y).collect();
                let i = index(dims, &e);
                out.c[i] = ZP.add(out.c[i], ZP.mul(ca, cb));
            })
        });
        out
    }

    #[test]
    fn inverse_and_univariate_gcd() {
        for a in [1u64, 2, 3, 12345, 2_147_483_646] {
            assert_eq!(ZP.mul(a, ZP.inv(a)), 1);
        }
        // (x + 1)(x + 2) and (x + 1)(x + 3): gcd x + 1, exact cofactors
        let f = umul(ZP, &[1, 1], &[2, 1]);
        let g = umul(ZP, &[1, 1], &[3, 1]);
        assert_eq!(ugcd(ZP, &f, &g), vec![1, 1]);
        let (q, exact) = udivrem(ZP, &f, &[1, 1]);
        assert!(exact);
        assert_eq!(umul(ZP, &q, &[1, 1]), f);
        assert!(!udivrem(ZP, &f, &[5, 1]).1);
    }

    #[test]
    fn kronecker_division_is_exact_or_refused() {
        // a = (x y + 3 y^2 + 1)(2 x + y + 5) in shape (3, 4)
        let dims = [3, 4];
        let u = dense(&[2, 3], &[(&[1, 1], 1), (&[0, 2], 3), (&[0, 0], 1)]);
        let w = dense(&[2, 2], &[(&[1, 0], 2), (&[0, 1], 1), (&[0, 0], 5)]);
        let a = mul(&u, &w, &dims);
        let q = div_dense(ZP, &a, &w).expect("w divides a");
        assert_eq!(mul(&q, &w, &dims), a);
        assert_eq!(q.reshape(&[2, 3]).unwrap(), u);
        let q = div_dense(ZP, &a, &u).expect("u divides a");
        assert_eq!(mul(&q, &u, &dims), a);
        // a non-divisor: the remainder is not zero
        let z = dense(&[2, 2], &[(&[1, 0], 1), (&[0, 1], 1), (&[0, 0], 1)]);
        assert!(div_dense(ZP, &a, &z).is_none());
        // a quotient that would wrap around the shape is refused: y^3 / x in shape (2, 4)
        let y3 = dense(&[2, 4], &[(&[0, 3], 1), (&[1, 0], 1)]);
        assert!(div_dense(ZP, &y3, &dense(&[2, 1], &[(&[1, 0], 1)])).is_none());
    }

    #[test]
    fn newton_interpolation_and_contents() {
        // interpolate f(y) = 3 y^2 + 2 y + 1 (one fiber) from three points, then check
        // stability at a fourth
        let f = |y: u64| ueval(ZP, &[1, 2, 3], y);
        let mut it = Interp::new(1, 4);
        let mut m: Up = vec![1];
        let mut changed = Vec::new();
        for b in [5u64, 7, 11, 13] {
            let s = ZP.inv(ueval(ZP, &m, b));
            changed.push(it.add(ZP, &[f(b)], b, &m, s));
            m = umul(ZP, &m, &[ZP.sub(0, b), 1]);
        }
        assert_eq!(changed, vec![true, true, true, false]);
        assert_eq!(&it.c[..3], &[1, 2, 3]);
        // content in the last variable of (y + 1) * (x + y^2) is y + 1
        let d = dense(
            &[2, 4],
            &[(&[1, 0], 1), (&[1, 1], 1), (&[0, 2], 1), (&[0, 3], 1)],
        );
        assert_eq!(d.content_last(ZP), vec![1, 1]);
        let pp = d.pp_last(ZP);
        assert_eq!(pp, dense(&[2, 4], &[(&[1, 0], 1), (&[0, 2], 1)]));
        assert_eq!(pp.eval_last(ZP, 2).c, vec![4, 1]);
    }
}
