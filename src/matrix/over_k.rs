//! Kernels over a quadratic field $K = \mathbb{Q}(\sqrt d)$ on top of the $\mathbb{Q}$ ones
//! (the matrix-side choice of method, as [`super::over_q`] does for $\mathbb{Q}$).
//!
//! * [`mul_k`]: $C = AB$ with integer dot products: row $i$ of $A$ scaled by the lcm $d_i$
//!   of the denominators of both parts of its entries, column $j$ of $B$ by $e_j$, then
//!   $(x_0 + x_1\sqrt d)(y_0 + y_1\sqrt d) = (x_0 y_0 + d\,x_1 y_1) + (x_0 y_1 + x_1 y_0)\sqrt d$
//!   summed exactly and reduced once per entry, instead of normalising four rationals after
//!   every multiply-add.
//! * [`inverse_k`], [`rank_k`]: through the regular representation
//!   $\rho(A) = \begin{pmatrix} A_0 & d A_1 \\ A_1 & A_0 \end{pmatrix} \in
//!   \mathbb{Q}^{2m \times 2n}$ of $A = A_0 + A_1\sqrt d$ (the matrix of $A$ as a
//!   $\mathbb{Q}$-linear map, coordinates $(u_0, u_1)$ for $u_0 + u_1 \sqrt d$). $\rho$ is an
//!   injective ring homomorphism, so $\rho(A)^{-1} = \rho(A^{-1})$ (its first block column
//!   is $(X_0; X_1)$), and the image of $A$ is a $K$-space, so
//!   $\mathrm{rank}_{\mathbb{Q}}\,\rho(A) = 2\,\mathrm{rank}_K A$. Both go to the certified
//!   kernels of [`super::over_q`]; so does [`rank_at_least_mod_p`] (a rank of $\rho(A)$
//!   modulo a prime of at least $2r$ proves $\mathrm{rank}_K A \ge r$) and [`rref_k`] (the
//!   RREF of $\rho(A)$ with interleaved columns is $\rho$ of the RREF over $K$, see there).
//!
//! * [`charpoly_k`], [`det_k`]: the certified multi-modular kernels of
//!   [`crate::qkernels::modular::quadratic`] (images under $\sqrt d \mapsto \pm r$ modulo
//!   primes where $d$ is a square, CRT up to a Hadamard-type bound) from
//!   [`MODULAR_MIN_N`] rows on; smaller matrices keep the generic algorithm.
//!
//! Each function computes the same canonical result as the generic algorithm of
//! [`crate::matrix::Matrix`] over $K$. Matrices are row-major slices; a slice of the wrong
//! length is a caller bug and panics.

use super::over_q::{self, MUL_MIN_K};
use crate::field::lehmer::{fraction, gcd};
use crate::field::{Quadratic, Rational};
use crate::qkernels::modular::quadratic::{charpoly_quadratic, det_quadratic};
use num_bigint::BigInt;
use num_traits::{One, Zero};

fn check_len(op: &str, len: usize, m: usize, n: usize) {
    assert_eq!(
        len,
        m * n,
        "{op}: slice of length {len} for a {m}x{n} matrix"
    );
}

/// The lcm $s$ of the denominators of both parts of `xs`, and the integer pairs $s x$.
fn scale<'a>(xs: impl Iterator<Item = &'a Quadratic> + Clone) -> (BigInt, Vec<(BigInt, BigInt)>) {
    let mut s = BigInt::one();
    for x in xs.clone() {
        for den in [x.a.denom(), x.b.denom()] {
            if !den.is_one() {
                let g = gcd(&s, den);
                s = &s / g * den;
            }
        }
    }
    let int = |q: &Rational| {
        if q.is_zero() {
            BigInt::zero()
        } else if q.denom().is_one() {
            q.numer() * &s
        } else {
            q.numer() * (&s / q.denom())
        }
    };
    let v = xs.map(|x| (int(&x.a), int(&x.b))).collect();
    (s, v)
}

/// Row-major product of an `m x k` and a `k x n` matrix over $\mathbb{Q}(\sqrt d)$; `None`
/// when the generic loop is the better choice (inner dimension below
/// [`MUL_MIN_K`] or fewer than 4 entries).
///
/// # Panics
/// When a slice length does not match its shape.
pub fn mul_k(
    d: &BigInt,
    m: usize,
    k: usize,
    n: usize,
    a: &[Quadratic],
    b: &[Quadratic],
) -> Option<Vec<Quadratic>> {
    check_len("mul_k", a.len(), m, k);
    check_len("mul_k", b.len(), k, n);
    (k >= MUL_MIN_K && m * n >= 4).then(|| mul_k_integer(d, (m, k, n), a, b))
}

/// [`mul_k`] without the size dispatch (the integer kernel itself) for the shape
/// `(m, k, n)`.
///
/// # Panics
/// When a slice length does not match its shape.
pub fn mul_k_integer(
    d: &BigInt,
    (m, k, n): (usize, usize, usize),
    a: &[Quadratic],
    b: &[Quadratic],
) -> Vec<Quadratic> {
    check_len("mul_k", a.len(), m, k);
    check_len("mul_k", b.len(), k, n);
    let rows: Vec<_> = (0..m)
        .map(|i| scale(a[i * k..(i + 1) * k].iter()))
        .collect();
    let cols: Vec<_> = (0..n)
        .map(|j| scale((0..k).map(|l| &b[l * n + j])))
        .collect();
    let part = |acc: BigInt, den: &BigInt| {
        if acc.is_zero() {
            Rational::zero()
        } else if den.is_one() {
            Rational::from_integer(acc)
        } else {
            fraction(acc, den)
        }
    };
    let mut out = Vec::with_capacity(m * n);
    for (di, ri) in &rows {
        for (ej, cj) in &cols {
            let (mut re, mut rd, mut im) = (BigInt::zero(), BigInt::zero(), BigInt::zero());
            for ((x0, x1), (y0, y1)) in ri.iter().zip(cj) {
                if !x0.is_zero() {
                    if !y0.is_zero() {
                        re += x0 * y0;
                    }
                    if !y1.is_zero() {
                        im += x0 * y1;
                    }
                }
                if !x1.is_zero() {
                    if !y1.is_zero() {
                        rd += x1 * y1;
                    }
                    if !y0.is_zero() {
                        im += x1 * y0;
                    }
                }
            }
            if !rd.is_zero() {
                re += rd * d;
            }
            let den = di * ej;
            out.push(Quadratic {
                a: part(re, &den),
                b: part(im, &den),
            });
        }
    }
    out
}

/// $\rho(A)$ (`2m x 2n`, row-major) of the module docs.
fn regular(d: &BigInt, m: usize, n: usize, a: &[Quadratic]) -> Vec<Rational> {
    let dq = Rational::from_integer(d.clone());
    let mut out = Vec::with_capacity(4 * m * n);
    for half in 0..2 {
        for r in 0..m {
            let row = &a[r * n..(r + 1) * n];
            if half == 0 {
                out.extend(row.iter().map(|x| x.a.clone()));
                out.extend(row.iter().map(|x| &dq * &x.b));
            } else {
                out.extend(row.iter().map(|x| x.b.clone()));
                out.extend(row.iter().map(|x| x.a.clone()));
            }
        }
    }
    out
}

/// Inverse of the `n x n` matrix `a` over $\mathbb{Q}(\sqrt d)$; `None` when singular.
///
/// # Panics
/// When `a.len() != n * n`.
pub fn inverse_k(d: &BigInt, n: usize, a: &[Quadratic]) -> Option<Vec<Quadratic>> {
    check_len("inverse_k", a.len(), n, n);
    let inv = over_q::inverse_q(2 * n, &regular(d, n, n, a))?;
    let w = 2 * n;
    Some(
        (0..n * n)
            .map(|e| {
                let (r, c) = (e / n, e % n);
                Quadratic {
                    a: inv[r * w + c].clone(),
                    b: inv[(n + r) * w + c].clone(),
                }
            })
            .collect(),
    )
}

/// Rank of the `m x n` matrix `a` over $\mathbb{Q}(\sqrt d)$.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rank_k(d: &BigInt, m: usize, n: usize, a: &[Quadratic]) -> usize {
    check_len("rank_k", a.len(), m, n);
    over_q::rank_q(2 * m, 2 * n, &regular(d, m, n, a)) / 2
}

/// Does an elimination modulo a word prime prove $\mathrm{rank}_K A \ge r$? The regular
/// representation has $\mathrm{rank}_{\mathbb{Q}}\,\rho(A) = 2\,\mathrm{rank}_K A$ (module
/// docs), and its rank modulo $p$ is a lower bound of that
/// ([`over_q::rank_at_least_mod_p`]). `false` decides nothing.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rank_at_least_mod_p(d: &BigInt, m: usize, n: usize, a: &[Quadratic], r: usize) -> bool {
    check_len("rank_at_least_mod_p", a.len(), m, n);
    over_q::rank_at_least_mod_p(2 * m, 2 * n, &regular(d, m, n, a), 2 * r)
}

/// Canonical RREF (`m x n`) and pivot columns over $\mathbb{Q}(\sqrt d)$, from the
/// $\mathbb{Q}$-RREF of $\rho(A)$ with the columns interleaved ($u_{0j}, u_{1j}$ for each
/// $j$). With $R = EA$ the RREF over $K$, $\rho(R) = \rho(E)\rho(A)$ is row equivalent to
/// $\rho(A)$, and its rows, half 0 then half 1 of each row of $R$, are already in RREF:
/// the row $i$ of half 0 has its leading 1 at $(p_i, 0)$, that of half 1 at $(p_i, 1)$, and
/// both pivot columns vanish elsewhere (the entries there are $R_{kp_i} \in \{0, 1\}$ and
/// $d\,\mathrm{Im}\,R_{kp_i} = 0$). The $\mathbb{Q}$-RREF is unique, so it is that matrix:
/// pivots come in pairs $(2p_i, 2p_i + 1)$ and $R_{ij} = \mathrm{row}_{2i}[2j] +
/// \mathrm{row}_{2i+1}[2j]\sqrt d$.
///
/// # Panics
/// When `a.len() != m * n`.
pub fn rref_k(d: &BigInt, m: usize, n: usize, a: &[Quadratic]) -> (Vec<Quadratic>, Vec<usize>) {
    check_len("rref_k", a.len(), m, n);
    let rho = regular(d, m, n, a);
    // interleave the columns: (u0_j, u1_j)
    let w = 2 * n;
    let mut inter = Vec::with_capacity(rho.len());
    for r in 0..2 * m {
        let row = &rho[r * w..(r + 1) * w];
        for j in 0..n {
            inter.push(row[j].clone());
            inter.push(row[n + j].clone());
        }
    }
    let (q, qpiv) = over_q::rref_q(2 * m, w, &inter);
    debug_assert!(
        qpiv.chunks(2)
            .all(|p| p.len() == 2 && p[1] == p[0] + 1 && p[0] % 2 == 0)
    );
    let piv: Vec<usize> = qpiv.iter().step_by(2).map(|c| c / 2).collect();
    let zero = Quadratic::new(Rational::zero(), Rational::zero());
    let mut out = vec![zero; m * n];
    for i in 0..piv.len() {
        for j in 0..n {
            out[i * n + j] = Quadratic::new(
                q[2 * i * w + 2 * j].clone(),
                q[(2 * i + 1) * w + 2 * j].clone(),
            );
        }
    }
    (out, piv)
}

/// Square matrices from this size on take the multi-modular determinant and characteristic
/// polynomial (below it the generic elimination over $K$ is as fast: `benches/quadratic.rs`).
pub const MODULAR_MIN_N: usize = 3;

/// $\det(xI - A)$ (low degree first, monic) of the `n x n` `a` over $\mathbb{Q}(\sqrt d)$;
/// `None` below [`MODULAR_MIN_N`] (the generic algorithm).
///
/// # Panics
/// When `a.len() != n * n`.
pub fn charpoly_k(d: &BigInt, n: usize, a: &[Quadratic]) -> Option<Vec<Quadratic>> {
    check_len("charpoly_k", a.len(), n, n);
    (n >= MODULAR_MIN_N).then(|| charpoly_quadratic(d, n, a))
}

/// $\det A$ of the `n x n` `a` over $\mathbb{Q}(\sqrt d)$; `None` below [`MODULAR_MIN_N`].
///
/// # Panics
/// When `a.len() != n * n`.
pub fn det_k(d: &BigInt, n: usize, a: &[Quadratic]) -> Option<Quadratic> {
    check_len("det_k", a.len(), n, n);
    (n >= MODULAR_MIN_N).then(|| det_quadratic(d, n, a))
}
