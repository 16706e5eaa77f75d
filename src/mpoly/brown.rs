//! Brown's dense modular gcd in $\mathbb{Z}\lbrack x_0, \dots, x_{k-1}\rbrack$.
//!
//! For primitive $f, g$ with lex leading coefficients $\operatorname{lc} f$, $\operatorname{lc} g$
//! (integers), $G = \gcd(f, g)$ and $\gamma = \gcd(\operatorname{lc} f, \operatorname{lc} g)$,
//! the polynomial $H = (\gamma / \operatorname{lc} G)\, G$ has integer coefficients. For word
//! primes $p \nmid \operatorname{lc} f \operatorname{lc} g$ the image
//! $\gamma \cdot \gcd(f \bmod p, g \bmod p)$ (monic gcd over $\mathbb{Z}_p$) equals
//! $H \bmod p$ unless $p$ is unlucky, in which case its lex leading monomial is larger
//! (the modular gcd is a multiple of $G \bmod p$). Images are combined by the Chinese
//! remainder theorem (symmetric residues) until one more prime leaves the lift unchanged; then
//! $\operatorname{pp}(H)$ is accepted only if it **divides $f$ and $g$ exactly** over
//! $\mathbb{Z}$ (so the result is never wrong; a failed test restarts with fresh primes).
//!
//! The gcd over $\mathbb{Z}_p$ (`pgcd`) is Brown's recursion (Geddes–Czapor–Labahn, Alg.
//! 7.2): with $v$ the last active variable, contents and leading coefficients are
//! univariate in $x_v$; evaluate $x_v = \beta$ where $\gamma_v(\beta) \ne 0$, recurse, scale
//! the image to leading coefficient $\gamma_v(\beta)$, discard images whose leading monomial
//! is larger (unlucky), restart on a smaller one, and Newton-interpolate in $x_v$ until the
//! interpolant is stable or reaches the degree bound
//! $\deg_v \gamma_v + \min(\deg_v f, \deg_v g)$. One variable left: the dense Euclidean
//! algorithm.
//!
//! FLINT's `fmpz_mpoly_gcd` stages the same way (trivial cases, then Brown / Zippel / Hensel
//! by shape); SymPy's `euclidtools` default over ZZ is `heugcd`, then the PRS.

use super::{MPoly, shift, width};
use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_traits::{One, Signed};

/// A sparse polynomial over $\mathbb{Z}_p$: `(monomial, residue)` with nonzero residues,
/// monomials strictly decreasing (same packing as [`MPoly`]).
type Sp = Vec<(u128, u64)>;

/// Word primes below $2^{31}$ (products fit a `u64`).
const PRIME_START: u64 = (1 << 31) - 1;
/// Primes tried before giving up (the caller falls back to the subresultant PRS).
const MAX_PRIMES: usize = 400;
/// Extra (unlucky or skipped) evaluation points tolerated per interpolation.
const MAX_BAD_POINTS: usize = 64;

#[derive(Clone, Copy)]
struct Zp {
    p: u64,
}

impl Zp {
    #[inline(always)]
    fn add(self, a: u64, b: u64) -> u64 {
        let s = a + b;
        if s >= self.p { s - self.p } else { s }
    }
    #[inline(always)]
    fn sub(self, a: u64, b: u64) -> u64 {
        if a >= b { a - b } else { a + self.p - b }
    }
    #[inline(always)]
    fn mul(self, a: u64, b: u64) -> u64 {
        a * b % self.p
    }
    fn pow(self, mut a: u64, mut e: u64) -> u64 {
        let mut r = 1;
        while e > 0 {
            if e & 1 == 1 {
                r = self.mul(r, a);
            }
            a = self.mul(a, a);
            e >>= 1;
        }
        r
    }
    fn inv(self, a: u64) -> u64 {
        self.pow(a, self.p - 2)
    }
    fn reduce(self, c: &BigInt) -> u64 {
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

/// The `i`-th prime below [`PRIME_START`] in decreasing order (cached process-wide; primality
/// by the deterministic Miller–Rabin test of [`crate::qkernels::prime::is_prime_u64`]).
fn nth_prime(i: usize) -> u64 {
    static PRIMES: std::sync::OnceLock<Vec<u64>> = std::sync::OnceLock::new();
    let table = PRIMES.get_or_init(|| {
        let mut v = Vec::with_capacity(MAX_PRIMES);
        let mut c = PRIME_START + 1;
        while v.len() < MAX_PRIMES {
            c -= 1;
            if crate::qkernels::prime::is_prime_u64(c) {
                v.push(c);
            }
        }
        v
    });
    table[i]
}

// ---------------------------------------------------------------- dense univariate mod p

/// Dense univariate polynomial, low degree first, no trailing zeros.
type Up = Vec<u64>;

fn utrim(a: &mut Up) {
    while a.last() == Some(&0) {
        a.pop();
    }
}

/// Remainder of `a` by `b` (`b` nonzero).
fn urem(zp: Zp, mut a: Up, b: &[u64]) -> Up {
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
        utrim(&mut a);
    }
    a
}

/// Monic gcd (zero for two zeros).
fn ugcd(zp: Zp, a: &[u64], b: &[u64]) -> Up {
    let (mut a, mut b) = (a.to_vec(), b.to_vec());
    utrim(&mut a);
    utrim(&mut b);
    while !b.is_empty() {
        let r = urem(zp, a, &b);
        a = b;
        b = r;
    }
    umonic(zp, &mut a);
    a
}

fn umonic(zp: Zp, a: &mut Up) {
    if let Some(&l) = a.last()
        && l != 1
    {
        let i = zp.inv(l);
        for c in a.iter_mut() {
            *c = zp.mul(*c, i);
        }
    }
}

/// Exact quotient `a / b` (assumes `b | a`, `b` nonzero).
fn udiv(zp: Zp, a: &[u64], b: &[u64]) -> Up {
    let mut r = a.to_vec();
    utrim(&mut r);
    let db = b.len() - 1;
    if r.len() <= db {
        return Vec::new();
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
    q
}

fn ueval(zp: Zp, a: &[u64], x: u64) -> u64 {
    a.iter().rev().fold(0, |s, &c| zp.add(zp.mul(s, x), c))
}

// ---------------------------------------------------------------- sparse mod p

/// Layout of the packed monomials: bit offset and mask of a variable.
#[derive(Clone, Copy)]
struct Layout {
    nvars: usize,
    w: u32,
}

impl Layout {
    fn sh(self, v: usize) -> u32 {
        shift(self.nvars, v)
    }
    fn mask(self, v: usize) -> u128 {
        ((1u128 << self.w) - 1) << self.sh(v)
    }
    fn exp(self, m: u128, v: usize) -> usize {
        ((m & self.mask(v)) >> self.sh(v)) as usize
    }
}

/// Splits `a` into runs of equal monomial outside $x_v$ ($v$ is the last variable in use,
/// so runs are contiguous): `(monomial without x_v, dense coefficient in x_v)`.
fn groups(l: Layout, a: &Sp, v: usize) -> Vec<(u128, Up)> {
    let mask = l.mask(v);
    let mut out: Vec<(u128, Up)> = Vec::new();
    for &(m, c) in a {
        let key = m & !mask;
        let e = l.exp(m, v);
        match out.last_mut() {
            Some((k, u)) if *k == key => u[e] = c,
            _ => {
                let mut u = vec![0; e + 1];
                u[e] = c;
                out.push((key, u));
            }
        }
    }
    out
}

/// Rebuilds a sparse polynomial from [`groups`] (keys decreasing).
fn ungroup(l: Layout, gs: &[(u128, Up)], v: usize) -> Sp {
    let sh = l.sh(v);
    let mut out = Vec::new();
    for (k, u) in gs {
        for (e, &c) in u.iter().enumerate().rev() {
            if c != 0 {
                out.push((k | ((e as u128) << sh), c));
            }
        }
    }
    out
}

fn eval_groups(zp: Zp, gs: &[(u128, Up)], b: u64) -> Sp {
    gs.iter()
        .filter_map(|(k, u)| {
            let c = ueval(zp, u, b);
            (c != 0).then_some((*k, c))
        })
        .collect()
}

fn deg_in(l: Layout, a: &Sp, v: usize) -> usize {
    a.iter().map(|&(m, _)| l.exp(m, v)).max().unwrap_or(0)
}

fn scale_sp(zp: Zp, a: &mut Sp, c: u64) {
    if c != 1 {
        for t in a.iter_mut() {
            t.1 = zp.mul(t.1, c);
        }
    }
}

/// `a + b` of sorted sparse polynomials.
fn add_sp(zp: Zp, a: &Sp, b: &Sp) -> Sp {
    let mut out = Vec::with_capacity(a.len() + b.len());
    let (mut i, mut j) = (0, 0);
    while i < a.len() && j < b.len() {
        match a[i].0.cmp(&b[j].0) {
            std::cmp::Ordering::Greater => {
                out.push(a[i]);
                i += 1;
            }
            std::cmp::Ordering::Less => {
                out.push(b[j]);
                j += 1;
            }
            std::cmp::Ordering::Equal => {
                let s = zp.add(a[i].1, b[j].1);
                if s != 0 {
                    out.push((a[i].0, s));
                }
                i += 1;
                j += 1;
            }
        }
    }
    out.extend_from_slice(&a[i..]);
    out.extend_from_slice(&b[j..]);
    out
}

/// gcd over $\mathbb{Z}_p$ of `a`, `b` (nonzero) in the variables `0..k` (the others have
/// exponent 0), monic in lex order; `None` when too many evaluation points were unlucky.
fn pgcd(zp: Zp, l: Layout, a: &Sp, b: &Sp, k: usize) -> Option<Sp> {
    debug_assert!(!a.is_empty() && !b.is_empty());
    let v = k - 1;
    if k == 1 || v == 0 {
        let (ua, ub) = (ungroup_univariate(l, a, 0), ungroup_univariate(l, b, 0));
        let g = ugcd(zp, &ua, &ub);
        return Some(ungroup(l, &[(0, g)], 0));
    }
    // a variable absent from both: skip it
    let (dav, dbv) = (deg_in(l, a, v), deg_in(l, b, v));
    if dav == 0 && dbv == 0 {
        return pgcd(zp, l, a, b, k - 1);
    }
    let (mut ga, mut gb) = (groups(l, a, v), groups(l, b, v));
    // contents in Z_p[x_v] and primitive parts
    let content = |gs: &[(u128, Up)]| {
        let mut c: Up = Vec::new();
        for (_, u) in gs {
            c = ugcd(zp, &c, u);
            if c.len() == 1 {
                break;
            }
        }
        c
    };
    let (ca, cb) = (content(&ga), content(&gb));
    for (gs, c) in [(&mut ga, &ca), (&mut gb, &cb)] {
        if c.len() > 1 {
            for (_, u) in gs.iter_mut() {
                *u = udiv(zp, u, c);
            }
        }
    }
    let cont = ugcd(zp, &ca, &cb);
    // leading coefficients (in x_0..x_{v-1}) and their gcd, univariate in x_v
    let gamma = ugcd(zp, &ga[0].1, &gb[0].1);
    let (lca, lcb) = (&ga[0].1, &gb[0].1);
    let da = ga.iter().map(|(_, u)| u.len() - 1).max().unwrap_or(0);
    let db = gb.iter().map(|(_, u)| u.len() - 1).max().unwrap_or(0);
    let bound = gamma.len() - 1 + da.min(db);
    let sh = l.sh(v);

    let mut h: Sp = Vec::new(); // interpolant
    let mut lm: Option<u128> = None; // its leading monomial outside x_v
    let mut q: Up = vec![1]; // prod (x_v - beta_i)
    let mut npts = 0usize;
    let mut bad = 0usize;
    let mut beta: u64 = 1;
    let result = loop {
        beta += 1;
        if beta >= zp.p || bad > MAX_BAD_POINTS + bound {
            return None;
        }
        let gb_ = ueval(zp, &gamma, beta);
        if gb_ == 0 || ueval(zp, lca, beta) == 0 || ueval(zp, lcb, beta) == 0 {
            bad += 1;
            continue;
        }
        let (ae, be) = (eval_groups(zp, &ga, beta), eval_groups(zp, &gb, beta));
        let mut g = pgcd(zp, l, &ae, &be, k - 1)?;
        if g.len() == 1 && g[0].0 == 0 {
            // the primitive parts are coprime
            break vec![(0u128, 1u64)];
        }
        scale_sp(zp, &mut g, gb_);
        let glm = g[0].0;
        match lm {
            Some(m) if glm > m => {
                bad += 1;
                continue;
            }
            Some(m) if glm == m => {}
            _ => {
                // first image, or a smaller leading monomial: (re)start
                h = g;
                lm = Some(glm);
                q = vec![zp.sub(0, beta), 1];
                npts = 1;
                if bound == 0 {
                    break h;
                }
                continue;
            }
        }
        // Newton step: h += q(x_v) * (g - h(beta)) / q(beta)
        let hb = eval_groups(zp, &groups(l, &h, v), beta);
        let mut diff = g;
        let neg: Sp = hb.iter().map(|&(m, c)| (m, zp.sub(0, c))).collect();
        diff = add_sp(zp, &diff, &neg);
        npts += 1;
        if diff.is_empty() {
            break h;
        }
        let s = zp.inv(ueval(zp, &q, beta));
        let mut upd: Sp = Vec::with_capacity(diff.len() * q.len());
        for &(m, c) in &diff {
            let c = zp.mul(c, s);
            for (e, &qe) in q.iter().enumerate().rev() {
                if qe != 0 {
                    upd.push((m | ((e as u128) << sh), zp.mul(c, qe)));
                }
            }
        }
        h = add_sp(zp, &h, &upd);
        // q *= (x_v - beta)
        let mut nq = vec![0; q.len() + 1];
        for (e, &qe) in q.iter().enumerate() {
            nq[e + 1] = zp.add(nq[e + 1], qe);
            nq[e] = zp.sub(nq[e], zp.mul(qe, beta));
        }
        q = nq;
        if npts > bound {
            break h;
        }
    };
    // primitive part of the interpolant in x_0..x_{v-1}, times the content gcd, monic
    let mut gh = groups(l, &result, v);
    let c = content(&gh);
    for (_, u) in gh.iter_mut() {
        if c.len() > 1 {
            *u = udiv(zp, u, &c);
        }
        if cont.len() > 1 {
            *u = umul(zp, u, &cont);
        }
    }
    let mut out = ungroup(l, &gh, v);
    let lc = out[0].1;
    scale_sp(zp, &mut out, zp.inv(lc));
    Some(out)
}

fn umul(zp: Zp, a: &[u64], b: &[u64]) -> Up {
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

/// A polynomial in $x_0$ only, as a dense vector.
fn ungroup_univariate(l: Layout, a: &Sp, v: usize) -> Up {
    let d = deg_in(l, a, v);
    let mut u = vec![0; d + 1];
    for &(m, c) in a {
        u[l.exp(m, v)] = c;
    }
    u
}

fn reduce_poly(zp: Zp, f: &MPoly) -> Sp {
    f.terms()
        .iter()
        .filter_map(|(m, c)| {
            let r = zp.reduce(c);
            (r != 0).then_some((*m, r))
        })
        .collect()
}

/// $\gcd(f, g)$ of primitive, non-constant $f, g$ by Brown's modular algorithm, positive
/// leading coefficient, verified by exact division; `None` if no verified result came within
/// `MAX_PRIMES` (400) primes (then the caller uses another method).
///
/// # Examples
/// ```
/// use exactlti::mpoly::{brown::gcd_brown, parse_mpoly_in};
/// let v = ["a", "b", "c"];
/// let p = |s: &str| parse_mpoly_in(s, &v).unwrap().prim;
/// let h = p("a*b + c^2 + 1");
/// let g = gcd_brown(&h.pow(3).mul(&p("a - b + 2*c")), &h.pow(2).mul(&p("a + b + c"))).unwrap();
/// assert_eq!(g, h.pow(2));
/// ```
pub fn gcd_brown(f: &MPoly, g: &MPoly) -> Option<MPoly> {
    if f.is_zero() || g.is_zero() || f.nvars() != g.nvars() {
        return None;
    }
    let n = f.nvars();
    let l = Layout {
        nvars: n,
        w: width(n),
    };
    // highest variable in use: the recursion evaluates from there down
    let (df, dg) = (f.degrees(), g.degrees());
    let k = (0..n).rev().find(|&i| df[i] > 0 || dg[i] > 0)? + 1;
    let (lf, lg) = (f.lc(), g.lc());
    let gamma = lf.abs().gcd(&lg.abs());
    // CRT state: lifted coefficients in [0, m) on the monomials of `mons`
    let mut lift: Vec<(u128, BigInt)> = Vec::new();
    let mut modulus = BigInt::one();
    let mut lm: Option<u128> = None;
    for i in 0..MAX_PRIMES {
        let p = nth_prime(i);
        let zp = Zp { p };
        if zp.reduce(&lf) == 0 || zp.reduce(&lg) == 0 {
            continue;
        }
        let (fp, gp) = (reduce_poly(zp, f), reduce_poly(zp, g));
        let Some(mut img) = pgcd(zp, l, &fp, &gp, k) else {
            continue;
        };
        if img.len() == 1 && img[0].0 == 0 {
            return Some(MPoly::one(n));
        }
        scale_sp(zp, &mut img, zp.reduce(&gamma));
        let ilm = img[0].0;
        match lm {
            Some(m) if ilm > m => continue,
            Some(m) if ilm == m && same_support(&lift, &img) => {
                // stable: the symmetric lift agrees with the new image?
                let half: BigInt = &modulus >> 1;
                let sym: Vec<(u128, BigInt)> = lift
                    .iter()
                    .map(|(m, c)| (*m, if c > &half { c - &modulus } else { c.clone() }))
                    .collect();
                let agrees = sym
                    .iter()
                    .zip(&img)
                    .all(|((_, c), (_, r))| zp.reduce(c) == *r);
                if agrees {
                    let h = MPoly::from_sorted(n, sym).primitive_part();
                    if f.div_exact(&h).is_some() && g.div_exact(&h).is_some() {
                        return Some(h.abs_lc());
                    }
                    // an undetected bad image: start again
                    lm = None;
                    continue;
                }
                crt_combine(zp, &mut lift, &modulus, &img);
                modulus *= p;
            }
            Some(m) if ilm == m => {
                // same leading monomial, different support: a wrong image somewhere
                lm = None;
                continue;
            }
            _ => {
                lift = img.iter().map(|&(m, c)| (m, BigInt::from(c))).collect();
                modulus = BigInt::from(p);
                lm = Some(ilm);
            }
        }
    }
    None
}

fn same_support(lift: &[(u128, BigInt)], img: &Sp) -> bool {
    lift.len() == img.len() && lift.iter().zip(img).all(|(a, b)| a.0 == b.0)
}

/// `lift` (residues mod `m`, in `[0, m)`) combined with `img` mod `p` into residues mod `m p`.
fn crt_combine(zp: Zp, lift: &mut [(u128, BigInt)], m: &BigInt, img: &Sp) {
    let minv = zp.inv(zp.reduce(m));
    for ((_, c), &(_, r)) in lift.iter_mut().zip(img) {
        let t = zp.mul(zp.sub(r, zp.reduce(c)), minv);
        if t != 0 {
            *c += m * BigInt::from(t);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    fn p(s: &str) -> MPoly {
        crate::mpoly::parse_mpoly_in(s, &["x", "a", "b", "c"])
            .unwrap()
            .prim
    }
    #[test]
    fn textbook() {
        let f = p("a*b + c^2 + 1");
        let g = p("a - b + 2*c");
        let h = p("x^2 + a*x - 3");
        assert_eq!(
            gcd_brown(&f.pow(3).mul(&g.pow(2)), &f.pow(2).mul(&h)),
            Some(f.pow(2))
        );
        assert_eq!(gcd_brown(&f, &g), Some(MPoly::one(4)));
        // non-monic leading coefficients that vanish at small points
        let u = p("3*a*x^2 - b*c + 7");
        let w = p("2*b*x + a - 1");
        assert_eq!(
            gcd_brown(&u.mul(&w), &u.mul(&p("x*c + 5"))),
            Some(u.clone())
        );
        assert_eq!(gcd_brown(&u.mul(&w).mul(&w), &w.pow(3)), Some(w.pow(2)));
    }
}
