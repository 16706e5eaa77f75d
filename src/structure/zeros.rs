//! Invariant zeros from the Rosenbrock system matrix, exactly and independently of the SCB.
//!
//! $P(s) = \begin{bmatrix} A - sI & B \\ C & D \end{bmatrix}$ over $K\[s\]$ is brought to a
//! diagonal form $\mathrm{diag}(d_1, \dots, d_r, 0, \dots)$ by unimodular row and column
//! operations (Euclidean elimination over the principal ideal domain $K\[s\]$). The number of
//! non-zero $d_i$ is the normal rank $r$ of $P$, and the monic $\prod d_i$ is the $r$-th
//! determinantal divisor (gcd of all $r \times r$ minors): the invariant zero polynomial,
//! whose roots (with multiplicity) are the invariant zeros.
//!
//! | entry point | computes |
//! |---|---|
//! | [`invariant_zeros`] | zero polynomial and normal rank of $P(s)$ |
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

/// Invariant zeros of $(A, B, C, D)$ through the Rosenbrock system matrix.
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
    let k = a.field().clone();
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
