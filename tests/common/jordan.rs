//! Test and example systems for the Jordan module (the papers' matrices).
#![allow(dead_code)]

use crate::common::Rng;
use exactlti::field::{Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;

pub fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

/// The 10-DOF sliding masses (minimal-realizations paper sec. 4.1): two fixed-fixed chains
/// of five unit masses and unit springs; `A = [[0, I], [-K, 0]]`, 20x20.
pub fn sliding_masses() -> Matrix<Q> {
    let n = 10;
    let mut k = Matrix::zeros(Q, n, n);
    for g in [0, 5] {
        for i in 0..5 {
            k.set(g + i, g + i, r(2, 1));
            if i < 4 {
                k.set(g + i, g + i + 1, r(-1, 1));
                k.set(g + i + 1, g + i, r(-1, 1));
            }
        }
    }
    let mut a = Matrix::zeros(Q, 20, 20);
    a.set_block(0, 10, &Matrix::identity(Q, 10));
    a.set_block(10, 0, &(-&k));
    a
}

/// Yaw-plane model, vehicle paper eq. 25.
pub fn yaw_plane(
    m: Rational,
    izz: Rational,
    a: Rational,
    b: Rational,
    cf: Rational,
    cr: Rational,
    u: Rational,
) -> Matrix<Q> {
    let z = Rational::from_integer(0.into());
    let one = Rational::from_integer(1.into());
    let mu = &m * &u;
    let iu = &izz * &u;
    let k1 = &a * &cf - &b * &cr;
    Matrix::from_rows(
        Q,
        vec![
            vec![z.clone(), u.clone(), -&one, z.clone()],
            vec![z.clone(), z.clone(), z.clone(), -&one],
            vec![z.clone(), z.clone(), -(&cf + &cr) / &mu, -(&k1 / &mu) - &u],
            vec![
                z.clone(),
                z.clone(),
                -(&k1 / &iu),
                -((&a * &a * &cf + &b * &b * &cr) / &iu),
            ],
        ],
    )
    .unwrap()
}

/// `A = P J P^-1` with a random block structure over the eigenvalues `0, -1, 2, -3, 1/2`
/// (as the anchors' `planted_jordan`) and a random invertible integer `P` (entries in
/// -2..=2); returns `A` and the `(eigenvalue, size)` blocks.
pub fn planted(n: usize, seed: u64) -> (Matrix<Q>, Vec<(Rational, usize)>) {
    let mut rng = Rng(seed);
    let evs = [r(0, 1), r(-1, 1), r(2, 1), r(-3, 1), r(1, 2)];
    let mut blocks = vec![];
    let mut size = 0;
    while size < n {
        let k = [1, 1, 2, 3][rng.int(0, 3) as usize].min(n - size);
        blocks.push((evs[rng.int(0, 4) as usize].clone(), k));
        size += k;
    }
    let mut j = Matrix::zeros(Q, n, n);
    let mut off = 0;
    for (lam, k) in &blocks {
        for i in 0..*k {
            j.set(off + i, off + i, lam.clone());
            if i + 1 < *k {
                j.set(off + i, off + i + 1, r(1, 1));
            }
        }
        off += k;
    }
    loop {
        let p = Matrix::from_fn(Q, n, n, |_, _| {
            Rational::from_integer(rng.int(-2, 2).into())
        });
        if let Ok(pi) = p.inverse() {
            return (&(&p * &j) * &pi, blocks);
        }
    }
}

/// The companion matrix of the monic `p` (last row `-p_0, ..., -p_{n-1}`): charpoly `p`.
pub fn companion(p: &[i64]) -> Matrix<Q> {
    let n = p.len() - 1;
    let mut a = Matrix::zeros(Q, n, n);
    for i in 0..n - 1 {
        a.set(i, i + 1, r(1, 1));
    }
    for (j, c) in p[..n].iter().enumerate() {
        a.set(n - 1, j, r(-c, 1));
    }
    a
}

/// `[[C, I], [0, C]]` for the companion `C` of `p`: every root of `p` has one Jordan block
/// of size 2 (minimal polynomial `p^2`), similar by a random unimodular `P`.
pub fn companion_pair_chain(p: &[i64], seed: u64) -> Matrix<Q> {
    let c = companion(p);
    let n = c.nrows();
    let mut j = Matrix::zeros(Q, 2 * n, 2 * n);
    j.set_block(0, 0, &c);
    j.set_block(n, n, &c);
    j.set_block(0, n, &Matrix::identity(Q, n));
    let mut rng = Rng(seed);
    let p = crate::common::unimodular(&Q, 2 * n, &mut rng);
    &(&p * &j) * &p.inverse().unwrap()
}

/// `A = P J P^-1` over `k` with `P` unimodular: Jordan blocks (sizes 1..3) of eigenvalues
/// `c + s g` (`c` in -2..=2, `s` in {0, 1} when a generator `g` is given) filling
/// `lo..=hi` rows, and on some seeds a coupled pair of companion blocks of `x^2 + c0`
/// (`[[C, I], [0, C]]`, one chain of length 2; `c0 = 3`, or `3 + g` when `shift_pair`).
/// Returns `A`, the planted linear blocks `(eigenvalue, size)` and whether the pair was planted.
pub type PlantedJordan<F> = (
    Matrix<F>,
    Vec<(<F as exactlti::field::Field>::Elem, usize)>,
    bool,
);

pub fn planted_jordan<F: exactlti::field::Field>(
    k: &F,
    g: &Option<F::Elem>,
    rng: &mut Rng,
    (lo, hi): (i64, i64),
    shift_pair: bool,
) -> PlantedJordan<F> {
    let mut blocks = vec![];
    let mut size = 0;
    let n_lin = rng.int(lo, hi) as usize;
    while size < n_lin {
        let m = [1, 1, 2, 3][rng.int(0, 3) as usize].min(n_lin - size);
        let mut lam = k.from_i64(rng.int(-2, 2));
        if let Some(g) = g
            && rng.int(0, 1) == 1
        {
            lam = k.add(&lam, g);
        }
        blocks.push((lam, m));
        size += m;
    }
    let pair = rng.int(0, 1) == 1;
    let n = size + if pair { 4 } else { 0 };
    let mut j = jordan_blocks(k, &blocks, n);
    let off = size;
    if pair {
        let c = match g {
            Some(g) if shift_pair => k.add(&k.from_i64(3), g),
            _ => k.from_i64(3),
        };
        for b in [0, 2] {
            j.set(off + b, off + b + 1, k.one());
            j.set(off + b + 1, off + b, k.neg(&c));
        }
        j.set(off, off + 2, k.one());
        j.set(off + 1, off + 3, k.one());
    }
    let p = crate::common::unimodular(k, n, rng);
    let pi = p.inverse().expect("unimodular");
    (&(&p * &j) * &pi, blocks, pair)
}

/// One part `(J, B, C)` of a realization written over an extension `E = F[t]/(g)`.
pub type ExtPart<'a, F> = (
    &'a Matrix<exactlti::algebraic::Ext<F>>,
    &'a Matrix<exactlti::algebraic::Ext<F>>,
    &'a Matrix<exactlti::algebraic::Ext<F>>,
);

/// $\sum_{\text{parts}} \operatorname{Tr}_{E/F}(C J^k B)$ for `k < kmax` (`p x m`, each part in
/// its own field `E`): the Markov parameters of the parts written over the base field `f`.
pub fn traced_markov<F: exactlti::field::Field>(
    parts: &[ExtPart<'_, F>],
    p: usize,
    m: usize,
    f: &F,
    kmax: usize,
) -> Vec<Matrix<F>> {
    (0..kmax)
        .map(|kk| {
            let mut sum = Matrix::zeros(f.clone(), p, m);
            for (j, b, c) in parts {
                let e = j.field().clone();
                let s = exactlti::poly::newton_power_sums(e.modulus(), e.degree() + 1);
                let tr = |x: &exactlti::algebraic::ExtElem<F::Elem>| {
                    x.0.iter()
                        .enumerate()
                        .fold(f.zero(), |acc, (i, xi)| f.add(&acc, &f.mul(xi, &s[i])))
                };
                let mut h = (*c).clone();
                for _ in 0..kk {
                    h = &h * *j;
                }
                let h = &h * *b;
                sum = &sum + &Matrix::from_fn(f.clone(), p, m, |r, q| tr(h.get(r, q)));
            }
            sum
        })
        .collect()
}

/// The `n x n` matrix with the Jordan blocks `(eigenvalue, size)` on the diagonal from the
/// top left (rows past the blocks are zero).
pub fn jordan_blocks<F: exactlti::field::Field>(
    k: &F,
    blocks: &[(F::Elem, usize)],
    n: usize,
) -> Matrix<F> {
    let mut j = Matrix::zeros(k.clone(), n, n);
    let mut off = 0;
    for (lam, m) in blocks {
        for i in 0..*m {
            j.set(off + i, off + i, lam.clone());
            if i + 1 < *m {
                j.set(off + i, off + i + 1, k.one());
            }
        }
        off += m;
    }
    j
}

/// The planted block sizes per distinct eigenvalue (first-seen order), largest first.
pub fn sizes_by_eigenvalue<E: Clone + PartialEq>(planted: &[(E, usize)]) -> Vec<(E, Vec<usize>)> {
    let mut out: Vec<(E, Vec<usize>)> = vec![];
    for (lam, m) in planted {
        match out.iter_mut().find(|(l, _)| l == lam) {
            Some((_, v)) => v.push(*m),
            None => out.push((lam.clone(), vec![*m])),
        }
    }
    for (_, v) in &mut out {
        v.sort_unstable_by(|x, y| y.cmp(x));
    }
    out
}

/// The vehicle paper's yaw plane over $\mathbb{Q}(cr, m, u)$ (eq. 27: a chain of length 3 at
/// 0 and the eigenvalue $-cr/(m u)$).
pub fn yaw27() -> (RatFuncField, Matrix<RatFuncField>) {
    let k = RatFuncField::new(&["cr", "m", "u"]).unwrap();
    let a = crate::common::qp_matrix(
        &k,
        &[
            &["0", "u", "-1", "0"],
            &["0", "0", "0", "-1"],
            &["0", "0", "-cr/(m*u)", "-u"],
            &["0", "0", "0", "0"],
        ],
    );
    (k, a)
}

/// $A - \theta I$ over the field of `a`.
pub fn shifted<K: exactlti::field::Field>(a: &Matrix<K>, theta: &K::Elem) -> Matrix<K> {
    let k = a.field().clone();
    let mut n = a.clone();
    for i in 0..a.nrows() {
        let v = k.sub(n.get(i, i), theta);
        n.set(i, i, v);
    }
    n
}
