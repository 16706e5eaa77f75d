//! Reproducible random test systems (for tests, benchmarks and the python comparison).
//!
//! A 64-bit linear congruential generator $x_{k+1} = a x_k + c \bmod 2^{64}$ (Knuth's MMIX
//! constants) whose top 53 bits give $u \in [0, 1)$; entries are $2u - 1$. The same recurrence
//! is a few lines in any language, so other tools can rebuild the same matrices.
//!
//! [`random_nonminimal`] builds the benchmark family: a random minimal part of order
//! $n_m = \lfloor n/2 \rfloor$, a controllable but unobservable part of order
//! $\lfloor n/4 \rfloor$ and an uncontrollable but observable part (the rest), in Kalman form
//!
//! $$A = \begin{bmatrix} A_{11} & 0 & A_{13} \\ A_{21} & A_{22} & A_{23} \\ 0 & 0 & A_{33}
//! \end{bmatrix},\ B = \begin{bmatrix} B_1 \\ B_2 \\ 0 \end{bmatrix},\
//! C = \begin{bmatrix} C_1 & 0 & C_3 \end{bmatrix},\ D = 0,$$
//!
//! where $A_{22}$ and $A_{33}$ are scaled by [`HIDDEN_SCALE`] (otherwise the hidden parts of a
//! large random system are ill-conditioned and no float tool finds them), scrambled by the
//! orthogonal factor $Q$ of a random matrix: $(Q^TAQ, Q^TB, CQ, D)$. Its
//! transfer matrix is $C_1(sI - A_{11})^{-1}B_1$, of McMillan degree $n_m$ (generically).
//!
//! | entry point           | returns                                  |
//! |-----------------------|------------------------------------------|
//! | [`Lcg`]               | the generator                            |
//! | [`random_nonminimal`] | [`RandomSystem`] with its minimal order  |

use nalgebra::DMatrix;
use nalgebra::linalg::QR;

/// Knuth's MMIX linear congruential generator.
#[derive(Clone, Debug)]
pub struct Lcg(u64);

impl Lcg {
    /// A generator started at `seed`.
    pub fn new(seed: u64) -> Self {
        Lcg(seed)
    }

    /// The next 64-bit state.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0
    }

    /// Uniform in `[-1, 1)`: `2 (x >> 11) / 2^53 - 1`.
    pub fn uniform(&mut self) -> f64 {
        let u = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        2.0 * u - 1.0
    }

    /// An `r x c` matrix filled row by row with `scale * uniform()`.
    pub fn matrix(&mut self, r: usize, c: usize, scale: f64) -> DMatrix<f64> {
        let mut m = DMatrix::zeros(r, c);
        for i in 0..r {
            for j in 0..c {
                m[(i, j)] = scale * self.uniform();
            }
        }
        m
    }

    /// A random orthogonal matrix: the Q factor of a random `n x n` matrix.
    pub fn orthogonal(&mut self, n: usize) -> DMatrix<f64> {
        let m = self.matrix(n, n, 1.0);
        QR::new(m).q()
    }
}

/// Scale of the hidden diagonal blocks $A_{22}$, $A_{33}$ of [`random_nonminimal`].
///
/// A staircase step multiplies the error in the computed controllable subspace by about
/// $\lVert A_{33}\rVert / \sigma_{\min}(A_{k+1,k})$ (the hidden part's norm over the step's
/// subdiagonal block), so with $A_{33}$ as large as the rest the error grows geometrically with
/// the number of steps $n_c/m$ and no float tool (neither this staircase nor SLICOT TB01PD)
/// finds the hidden parts of a large random system. A factor 0.1 keeps the family well posed.
pub const HIDDEN_SCALE: f64 = 0.1;

/// A random system with known minimal order.
#[derive(Clone, Debug)]
pub struct RandomSystem {
    /// State matrix.
    pub a: DMatrix<f64>,
    /// Input matrix.
    pub b: DMatrix<f64>,
    /// Output matrix.
    pub c: DMatrix<f64>,
    /// Feedthrough (zero).
    pub d: DMatrix<f64>,
    /// The order of the minimal part.
    pub minimal_order: usize,
}

/// The benchmark family described in the module docs, for `n` states, `m` inputs, `p`
/// outputs. Draw order: the full `A` (row-major, `sqrt(3/n)` scale), then `B`, then `C`
/// (each full, structural zeros overwritten afterwards), then the matrix whose Q factor
/// scrambles the states.
pub fn random_nonminimal(n: usize, m: usize, p: usize, seed: u64) -> RandomSystem {
    let mut g = Lcg::new(seed);
    let nm = n / 2;
    let nu = n / 4;
    let s = (3.0 / n.max(1) as f64).sqrt();
    let mut a = g.matrix(n, n, s);
    let mut b = g.matrix(n, m, 1.0);
    let mut c = g.matrix(p, n, 1.0);
    let (r1, r2) = (nm, nm + nu);
    for i in 0..n {
        for j in 0..n {
            let zero = (i < r1 && (r1..r2).contains(&j)) || (i >= r2 && j < r2);
            if zero {
                a[(i, j)] = 0.0;
            }
        }
        if i >= r2 {
            b.row_mut(i).fill(0.0);
        }
    }
    for j in r1..r2 {
        c.column_mut(j).fill(0.0);
    }
    // Shrink the hidden diagonal blocks (see HIDDEN_SCALE).
    for i in r1..n {
        let lo = if i < r2 { r1 } else { r2 };
        let hi = if i < r2 { r2 } else { n };
        for j in lo..hi {
            a[(i, j)] *= HIDDEN_SCALE;
        }
    }
    let q = g.orthogonal(n);
    RandomSystem {
        a: q.transpose() * &a * &q,
        b: q.transpose() * &b,
        c: &c * &q,
        d: DMatrix::zeros(p, m),
        minimal_order: nm,
    }
}
