//! Invariant zeros of the Rosenbrock system matrix, exactly.
//!
//! $P(s) = \begin{bmatrix} A - sI & B \\ C & D \end{bmatrix}$ over $K\[s\]$: its normal rank
//! $r$ and its invariant zero polynomial, the monic $r$-th determinantal divisor (gcd of all
//! $r \times r$ minors, the product of the invariant factors of the Smith form).
//!
//! # Algorithm
//! 1. Remove dependent constant columns of $[B; D]$ and rows of $[C, D]$ (pivot columns of
//!    the canonical RREF). A constant unimodular column (row) operation makes them zero, so
//!    the Smith form, hence the zero polynomial and the normal rank, are unchanged.
//! 2. The special coordinate basis ([`crate::structure::scb`]) of the compressed system,
//!    checked exactly at construction: the zero polynomial is $\det(sI - A_{aa})$ (the
//!    invariant zeros with their structure are the eigenvalue structure of the zero dynamics
//!    $A_{aa}$, Sannuti–Saberi). Only constant-matrix eliminations over $K$, dispatched to
//!    the fraction-free / multi-modular kernels for rationals, so entry size stays bounded.
//! 3. The normal rank is $\operatorname{rank} P(s_0)$ at the first $s_0 \in \{0, 1, -1, 2,
//!    \dots\}$ that is not a root of the zero polynomial: $P(s_0)$ loses rank exactly at the
//!    roots of the $r$-th determinantal divisor.
//! 4. When the SCB is not available (an internal failure) the polynomial matrix is
//!    diagonalized by unimodular operations over $K\[s\]$ ([`diagonalize`], Euclidean
//!    elimination): the non-zero diagonal entries number $r$ and their product is the
//!    divisor. This path is also the tests' independent oracle.
//!
//! | entry point | computes |
//! |---|---|
//! | [`invariant_zeros`] | zero polynomial and normal rank of $P(s)$ (SCB, fallback 4) |
//! | [`invariant_zeros_smith`] | the same by the polynomial diagonal form only |
//! | [`diagonalize`] | diagonal form of a polynomial matrix |

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::poly::Poly;

/// The invariant zeros of a system.
#[derive(Clone, Debug)]
pub struct InvariantZeros<K: Field> {
    /// Monic gcd of the maximal non-vanishing minors of $P(s)$ (`1`: no finite zeros).
    pub polynomial: Poly<K>,
    /// Normal rank of $P(s)$.
    pub normal_rank: usize,
    /// Size $(n + p) \times (n + m)$ of $P(s)$.
    pub size: (usize, usize),
}

impl<K: Field> InvariantZeros<K> {
    /// Number of invariant zeros, with multiplicity.
    pub fn count(&self) -> usize {
        self.polynomial.deg()
    }
}

/// Invariant zeros of $(A, B, C, D)$: the zero polynomial and the normal rank of the
/// Rosenbrock system matrix (SCB path of the module docs, steps 1-3; fallback step 4).
///
/// # Errors
/// `NotSquare`/`Shape` on inconsistent shapes.
///
/// # Examples
/// ```
/// use exactlti::qmat;
/// use exactlti::structure::zeros::invariant_zeros;
/// // G(s) = (s + 2) / (s^2 + 3 s + 1)
/// let z = invariant_zeros(&qmat![[0, 1], [-1, -3]], &qmat![[0], [1]], &qmat![[2, 1]], &qmat![[0]]).unwrap();
/// assert_eq!(z.polynomial.to_string(), "x + 2");
/// assert_eq!(z.normal_rank, 3);
/// ```
pub fn invariant_zeros<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
) -> Result<InvariantZeros<K>> {
    invariant_zeros_recorded(a, b, c, d, None)
}

/// [`invariant_zeros`], recording its steps into `rec` (`zeros --steps`, see
/// [`crate::structure::steps`]): the compression, the pencil, the SCB's steps, the normal rank
/// (or the diagonal form on the fallback path).
///
/// # Errors
/// As [`invariant_zeros`].
pub fn invariant_zeros_recorded<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
    mut rec: crate::structure::scb::steps::Rec<'_, '_, K>,
) -> Result<InvariantZeros<K>> {
    let (n, m, p) = check(a, b, c, d)?;
    // 1. independent input columns of [B; D] and output rows of [C, D]
    let (_, cols) = b.vstack(d)?.rref();
    let (_, rows) = c.hstack(d)?.transpose().rref();
    let (bc, dc) = (
        b.select_cols(&cols),
        d.select_cols(&cols).select_rows(&rows),
    );
    let cc = c.select_rows(&rows);
    if let Some(r) = rec.as_deref_mut() {
        super::steps::compress(r, [a, b, c, d], &cols, &rows);
    }
    // 2. the SCB of the compressed system (verified at construction)
    let Ok(s) = crate::structure::scb::scb_recorded(a, &bc, &cc, &dc, rec.as_deref_mut()) else {
        return invariant_zeros_smith_recorded(a, b, c, d, rec);
    };
    if !s.verified {
        return invariant_zeros_smith_recorded(a, b, c, d, rec);
    }
    let polynomial = s.invariant_zero_polynomial().monic();
    // 3. normal rank at a point that is not a zero
    let k = a.field().clone();
    let mut s0 = 0i64;
    while k.is_zero(&polynomial.eval(&k.from_i64(s0))) {
        s0 = if s0 > 0 { -s0 } else { 1 - s0 };
    }
    let shift = Matrix::identity(k.clone(), n).scale(&k.from_i64(s0));
    let top = a.try_sub(&shift)?.hstack(b)?;
    let ps0 = top.vstack(&c.hstack(d)?)?;
    let normal_rank = ps0.rank();
    if let Some(r) = rec {
        super::steps::normal_rank(r, &k.from_i64(s0), &ps0, normal_rank, &polynomial);
    }
    Ok(InvariantZeros {
        polynomial,
        normal_rank,
        size: (n + p, n + m),
    })
}

/// The sizes `(n, m, p)` of a consistent $(A, B, C, D)$.
fn check<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
) -> Result<(usize, usize, usize)> {
    a.check_square("invariant_zeros")?;
    let n = a.nrows();
    let (m, p) = (b.ncols(), c.nrows());
    if b.nrows() != n || c.ncols() != n || d.shape() != (p, m) {
        return Err(Error::Shape {
            op: "invariant_zeros",
            expected: (p, m),
            found: d.shape(),
        });
    }
    Ok((n, m, p))
}

/// [`invariant_zeros`] by the diagonal form of $P(s)$ over $K\[s\]$ only (step 4 of the
/// module docs): independent of the SCB, slow when entries are large (the polynomial
/// remainders grow), kept as the fallback and the tests' oracle.
///
/// # Errors
/// `NotSquare`/`Shape` on inconsistent shapes.
pub fn invariant_zeros_smith<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
) -> Result<InvariantZeros<K>> {
    invariant_zeros_smith_recorded(a, b, c, d, None)
}

/// [`invariant_zeros_smith`], recording the diagonal into `rec`.
fn invariant_zeros_smith_recorded<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
    rec: crate::structure::scb::steps::Rec<'_, '_, K>,
) -> Result<InvariantZeros<K>> {
    let k = a.field().clone();
    let (n, m, p) = check(a, b, c, d)?;
    let cst = |x: &K::Elem| Poly::constant(k.clone(), x.clone());
    let mut pm: Vec<Vec<Poly<K>>> = Vec::with_capacity(n + p);
    for i in 0..n {
        let mut row: Vec<Poly<K>> = (0..n)
            .map(|j| {
                if i == j {
                    Poly::new(k.clone(), vec![a.get(i, j).clone(), k.neg(&k.one())])
                } else {
                    cst(a.get(i, j))
                }
            })
            .collect();
        row.extend((0..m).map(|j| cst(b.get(i, j))));
        pm.push(row);
    }
    for i in 0..p {
        let mut row: Vec<Poly<K>> = (0..n).map(|j| cst(c.get(i, j))).collect();
        row.extend((0..m).map(|j| cst(d.get(i, j))));
        pm.push(row);
    }
    let diag = diagonalize(pm, n + m);
    let mut poly = Poly::one(k.clone());
    for dgl in &diag {
        poly = poly.mul(dgl);
    }
    if let Some(r) = rec {
        super::steps::smith(r, &diag, &poly.monic());
    }
    Ok(InvariantZeros {
        polynomial: poly.monic(),
        normal_rank: diag.len(),
        size: (n + p, n + m),
    })
}

/// Diagonal form of a polynomial matrix (rows of length `ncols`) by unimodular operations:
/// returns the non-zero diagonal entries $d_1, \dots, d_r$ (not normalized; no divisibility
/// order). Their product is, up to a unit, the $r$-th determinantal divisor.
///
/// # Algorithm
/// At each step the non-zero entry of least degree in the trailing block becomes the pivot;
/// its row and column are cleared by division with remainder, and a non-zero remainder
/// (of smaller degree) becomes the next pivot, so each step terminates.
pub fn diagonalize<K: Field>(mut m: Vec<Vec<Poly<K>>>, ncols: usize) -> Vec<Poly<K>> {
    let nrows = m.len();
    let mut out = Vec::new();
    for t in 0..nrows.min(ncols) {
        loop {
            // pivot: least degree non-zero entry in m[t.., t..]
            let mut best: Option<(usize, usize, usize)> = None;
            for (i, row) in m.iter().enumerate().skip(t) {
                for (j, e) in row.iter().enumerate().skip(t) {
                    if let Some(dg) = e.degree()
                        && best.is_none_or(|(_, _, bd)| dg < bd)
                    {
                        best = Some((i, j, dg));
                    }
                }
            }
            let Some((pi, pj, _)) = best else {
                return out;
            };
            m.swap(t, pi);
            for row in m.iter_mut() {
                row.swap(t, pj);
            }
            let piv = m[t][t].clone();
            let mut clean = true;
            for i in t + 1..nrows {
                if m[i][t].is_zero() {
                    continue;
                }
                let (q, r) = m[i][t].divrem(&piv).expect("non-zero pivot");
                clean &= r.is_zero();
                for j in t..ncols {
                    let v = m[i][j].sub(&q.mul(&m[t][j]));
                    m[i][j] = v;
                }
            }
            for j in t + 1..ncols {
                if m[t][j].is_zero() {
                    continue;
                }
                let (q, r) = m[t][j].divrem(&piv).expect("non-zero pivot");
                clean &= r.is_zero();
                for row in m.iter_mut().skip(t) {
                    let v = row[j].sub(&q.mul(&row[t]));
                    row[j] = v;
                }
            }
            if clean {
                out.push(piv);
                break;
            }
        }
    }
    out
}
