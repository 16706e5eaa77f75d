//! Example systems from the papers, built exactly.
#![allow(dead_code)]

use exactlti::field::{Field, Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::rng::SplitMix64;
use exactlti::system::StateSpace;

/// 10-DOF sliding masses (Minaker & Gonzalez sec. 4.1): two fixed-fixed chains of five unit
/// masses and unit springs; actuator pushes sliders 4 and 7 apart; output x9 - x2.
pub fn sliding_masses() -> StateSpace<Q> {
    let n = 10;
    let mut k = Matrix::zeros(Q, n, n);
    for g in [0, 5] {
        for i in 0..5 {
            k.set(g + i, g + i, Rational::from_integer(2.into()));
            if i < 4 {
                k.set(g + i, g + i + 1, Rational::from_integer((-1).into()));
                k.set(g + i + 1, g + i, Rational::from_integer((-1).into()));
            }
        }
    }
    let mut a = Matrix::zeros(Q, 20, 20);
    a.set_block(0, 10, &Matrix::identity(Q, 10));
    a.set_block(10, 0, &-&k);
    let mut b = Matrix::zeros(Q, 20, 1);
    b.set(13, 0, Rational::from_integer((-1).into()));
    b.set(16, 0, Rational::from_integer(1.into()));
    let mut c = Matrix::zeros(Q, 1, 20);
    c.set(0, 8, Rational::from_integer(1.into()));
    c.set(0, 1, Rational::from_integer((-1).into()));
    StateSpace::new_strictly_proper(a, b, c).unwrap()
}

/// A planted non-minimal system: its McMillan degree is known by construction.
pub struct Planted {
    /// The scrambled system $(T^{-1}A_0T, T^{-1}B_0, C_0T, 0)$.
    pub sys: StateSpace<Q>,
    /// The minimal core $(A_{11}, B_1, C_1)$ (its transfer matrix is the system's).
    pub core: StateSpace<Q>,
    /// The true McMillan degree (= order of the core).
    pub order: usize,
    /// Sizes of the parts: controllable-observable (the core), controllable-unobservable,
    /// uncontrollable-observable, uncontrollable-unobservable.
    pub parts: [usize; 4],
    /// The similarity `x = T z` applied to the block form, and its inverse (integer,
    /// determinant +-1).
    pub t: Matrix<Q>,
    pub tinv: Matrix<Q>,
}

/// The planted systems' generator: the library's SplitMix64 with the drawing helpers below.
pub struct PlantRng(pub SplitMix64);

impl PlantRng {
    pub fn new(seed: u64) -> Self {
        PlantRng(SplitMix64(seed))
    }
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        self.0.int(lo, hi)
    }
    /// `k / d` with `k` in `-2..=2` and `d` in `{1, 2}`: exact in binary floating point.
    fn small(&mut self) -> Rational {
        Rational::new(self.int(-2, 2).into(), self.int(1, 2).into())
    }
    fn matrix(&mut self, r: usize, c: usize) -> Matrix<Q> {
        Matrix::from_fn(Q, r, c, |_, _| self.small())
    }
}

/// A planted non-minimal system with `n` states, 2 inputs, 2 outputs and McMillan degree
/// `n / 2`, built exactly.
///
/// In block form (Kalman's, parts co, c-not-o, not-c-o, not-c-not-o)
/// $$A_0 = \begin{bmatrix} A_{11} & 0 & A_{13} & 0 \\ A_{21} & A_{22} & A_{23} & A_{24} \\
/// 0 & 0 & A_{33} & 0 \\ 0 & 0 & A_{43} & A_{44} \end{bmatrix},\ B_0 = \begin{bmatrix} B_1 \\
/// B_2 \\ 0 \\ 0 \end{bmatrix},\ C_0 = [C_1\ 0\ C_3\ 0]$$
/// with every block random (entries `k/d`, `|k| <= 2`, `d` in {1, 2}) and $(A_{11}, B_1, C_1)$
/// controllable and observable (checked exactly, redrawn otherwise), so that
/// $G(s) = C_1(sI - A_{11})^{-1}B_1$ has McMillan degree $r = n/2$. The hidden parts are as
/// large as the core. Scrambled by $x = Tz$ with $T = \Pi E_1 \cdots E_k$, $E_i$ elementary
/// row additions with multipliers $\pm 1$ ($k = n$) and $\Pi$ a random permutation, so $T$
/// and $T^{-1}$ are integer and the entries of the result keep denominators 1 or 2 (exactly
/// representable as `f64`: the float tools see the same system).
pub fn planted(n: usize, seed: u64) -> Planted {
    planted_scaled(n, seed, 1)
}

/// As [`planted`], with the hidden diagonal blocks $A_{22}, A_{33}, A_{44}$ multiplied by
/// the integer `hidden_scale` (a power of two keeps the f64 image exact). Large hidden
/// modes are what a float staircase cannot separate from the core: its rounding errors grow
/// by about $\lVert A_{33}\rVert / \sigma_{\min}$ of a coupling block at every step, while
/// the exact order is unaffected (the McMillan degree is still `n / 2`).
pub fn planted_scaled(n: usize, seed: u64, hidden_scale: i64) -> Planted {
    let mut rng = PlantRng::new(seed ^ 0x5EED_0000_0000_0000);
    let (m, p) = (2, 2);
    let r = n / 2;
    let rest = n - r;
    let parts = [r, rest.div_ceil(3), (rest + 1) / 3, rest / 3];
    let core = loop {
        let a = rng.matrix(r, r);
        let b = rng.matrix(r, m);
        let c = rng.matrix(p, r);
        let ok = exactlti::realization::is_controllable(&a, &b)
            && exactlti::realization::is_observable(&a, &c);
        if ok {
            break StateSpace::new_strictly_proper(a, b, c).unwrap();
        }
    };
    let off: Vec<usize> = parts
        .iter()
        .scan(0, |s, &d| {
            let o = *s;
            *s += d;
            Some(o)
        })
        .collect();
    let mut a = Matrix::zeros(Q, n, n);
    let mut b = Matrix::zeros(Q, n, m);
    let mut c = Matrix::zeros(Q, p, n);
    // nonzero blocks (i, j) of A_0 by part index
    for (i, j) in [
        (0, 0),
        (0, 2),
        (1, 0),
        (1, 1),
        (1, 2),
        (1, 3),
        (2, 2),
        (3, 2),
        (3, 3),
    ] {
        let blk = if (i, j) == (0, 0) {
            core.a.clone()
        } else if i == j {
            let s = Rational::from_integer(hidden_scale.into());
            let m = rng.matrix(parts[i], parts[j]);
            Matrix::from_fn(Q, parts[i], parts[j], |r, c| m.get(r, c) * &s)
        } else {
            rng.matrix(parts[i], parts[j])
        };
        a.set_block(off[i], off[j], &blk);
    }
    b.set_block(0, 0, &core.b);
    b.set_block(off[1], 0, &rng.matrix(parts[1], m));
    c.set_block(0, 0, &core.c);
    c.set_block(0, off[2], &rng.matrix(p, parts[2]));
    // T = Pi E_1 ... E_k, built with its inverse: T <- T E (column op), T^-1 <- E^-1 T^-1.
    let one = Rational::from_integer(1.into());
    let mut t = Matrix::identity(Q, n);
    let mut tinv = Matrix::identity(Q, n);
    if n >= 2 {
        for _ in 0..n {
            let i = rng.int(0, n as i64 - 1) as usize;
            let mut j = rng.int(0, n as i64 - 2) as usize;
            if j >= i {
                j += 1;
            }
            let f = if rng.int(0, 1) == 0 {
                -one.clone()
            } else {
                one.clone()
            };
            // E = I + f e_i e_j^T: T E adds f * (column i) to column j;
            // E^-1 T^-1 subtracts f * (row j) from row i.
            for row in 0..n {
                let v = t.get(row, j) + &f * t.get(row, i);
                t.set(row, j, v);
            }
            for col in 0..n {
                let v = tinv.get(i, col) - &f * tinv.get(j, col);
                tinv.set(i, col, v);
            }
        }
    }
    // permutation: x = Pi y, applied on the left of T (rows of T, columns of T^-1)
    let mut perm: Vec<usize> = (0..n).collect();
    for k in (1..n).rev() {
        let l = rng.int(0, k as i64) as usize;
        perm.swap(k, l);
    }
    let t = t.select_rows(&perm);
    let tinv = tinv.select_cols(&perm);
    let block = StateSpace::new_strictly_proper(a, b, c).unwrap();
    let sys = block.transform_with_inverse(&t, &tinv).unwrap();
    Planted {
        sys,
        core,
        order: r,
        parts,
        t,
        tinv,
    }
}

/// diag(p0..p{n-1}) over Q(p0, ..., p{n-1}), B = C^T = ones.
pub fn diag_qp(n: usize) -> StateSpace<exactlti::ratfunc::RatFuncField> {
    let names: Vec<String> = (0..n).map(|i| format!("p{i}")).collect();
    let k = exactlti::ratfunc::RatFuncField::new(&names).unwrap();
    let a = Matrix::diagonal(k.clone(), &(0..n).map(|i| k.var(i)).collect::<Vec<_>>());
    let b = Matrix::from_fn(k.clone(), n, 1, |_, _| k.one());
    let c = Matrix::from_fn(k.clone(), 1, n, |_, _| k.one());
    StateSpace::new(a, b, c, Matrix::zeros(k, 1, 1)).unwrap()
}

/// The n-mass chain between two walls over Q(m, k, c) (masses m, springs k, dampers c), force on mass 1, position of mass n.
pub fn chain_qp(n: usize) -> StateSpace<exactlti::ratfunc::RatFuncField> {
    let k = exactlti::ratfunc::RatFuncField::new(&["m", "k", "c"]).unwrap();
    let e = |s: &str| k.parse(s).unwrap();
    let a = Matrix::from_fn(k.clone(), 2 * n, 2 * n, |i, j| {
        if i < n {
            return if j == i + n { k.one() } else { k.zero() };
        }
        let (r, col) = (i - n, j % n);
        let what = if j < n { "k" } else { "c" };
        if r == col {
            e(&format!("-2*{what}/m"))
        } else if r.abs_diff(col) == 1 {
            e(&format!("{what}/m"))
        } else {
            k.zero()
        }
    });
    let b = Matrix::from_fn(k.clone(), 2 * n, 1, |i, _| {
        if i == n { e("1/m") } else { k.zero() }
    });
    let c = Matrix::from_fn(k.clone(), 1, 2 * n, |_, j| {
        if j == n - 1 { k.one() } else { k.zero() }
    });
    StateSpace::new(a, b, c, Matrix::zeros(k, 1, 1)).unwrap()
}
