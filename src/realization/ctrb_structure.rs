//! Controllability structure of $(A, B)$: controllable order, controllability (Kronecker /
//! Brunovsky) indices, staircase block dimensions, uncontrollable part; observability by
//! duality; finite and infinite controllability of regular descriptor systems.
//!
//! # Algorithm
//! Luenberger's greedy Krylov selection, exact: level $k$ holds the candidates
//! $A^kb_j$ of the inputs whose chain is still alive; a candidate dependent on all
//! earlier columns (exact RREF pivots of $[S \mid \text{candidates}]$) ends its chain (and
//! every later one of that input would be dependent too). Chain $j$ has length
//! $\kappa_j$ (the controllability index of input $j$; $0$ for an input in the span of the
//! earlier ones); the staircase block dimensions are $\rho_k = \#\{j : \kappa_j \ge k\}$,
//! $\rho_1 = \mathrm{rank}\,B$; the indices are the right Kronecker indices of
//! $[sI - A, B]$ (SLICOT AB01ND / AB01OD report the same $\rho_k$).
//!
//! # Verification
//! With $S$ the selected Krylov columns and $L$ (rows) a basis of the left null space of
//! $S$: $\mathrm{rank}\,S = \sum\kappa_j$, $LB = 0$ and $LA = A_{\bar c}L$; so
//! $\mathrm{span}\,S$ contains $B$, is $A$-invariant and lies in the controllable subspace,
//! hence equals it, and $A_{\bar c}$ is the uncontrollable part (its eigenvalues are the
//! uncontrollable eigenvalues).

use super::weierstrass::weierstrass_split;
use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::Descriptor;

/// The controllability structure of $(A, B)$.
#[derive(Clone, Debug)]
pub struct ControllabilityStructure<K: Field> {
    /// $\dim$ of the controllable subspace.
    pub order: usize,
    /// Controllability indices $\kappa_j$, largest first (one per input; zeros for inputs
    /// dependent on earlier ones).
    pub indices: Vec<usize>,
    /// Staircase block dimensions $\rho_1 \ge \rho_2 \ge \dots$ ($\rho_1 = \mathrm{rank}\,B$).
    pub block_dims: Vec<usize>,
    /// Selected Krylov columns: a basis of the controllable subspace ($n \times$ `order`).
    pub basis: Matrix<K>,
    /// $L$ with $LS = 0$ of full row rank, $LA = A_{\bar c}L$.
    pub left: Matrix<K>,
    /// The uncontrollable part $A_{\bar c}$ ($(n - \text{order})$ square).
    pub uncontrollable: Matrix<K>,
    pub verified: bool,
}

impl<K: Field> ControllabilityStructure<K> {
    /// The largest controllability index (0 without inputs).
    pub fn controllability_index(&self) -> usize {
        self.indices.first().copied().unwrap_or(0)
    }
}

/// Controllability structure of $(A, B)$.
///
/// # Errors
/// `NotSquare`/`Shape` when the matrices do not fit.
///
/// # Examples
/// ```
/// use exactlti::{qmat, realization::controllability_structure};
/// let c = controllability_structure(&qmat![[0, 1, 0], [0, 0, 0], [0, 0, 5]], &qmat![[0], [1], [0]]).unwrap();
/// assert_eq!((c.order, c.indices.clone(), c.block_dims.clone()), (2, vec![2], vec![1, 1]));
/// assert_eq!(c.uncontrollable.to_string(), "[[5]]");
/// assert!(c.verified);
/// ```
pub fn controllability_structure<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
) -> Result<ControllabilityStructure<K>> {
    a.check_square("controllability A")?;
    let n = a.nrows();
    b.check_shape("controllability B", (n, b.ncols()))?;
    let fld = a.field().clone();
    let m = b.ncols();
    let mut kappa = vec![0usize; m];
    let mut basis = Matrix::zeros(fld.clone(), n, 0);
    let mut alive: Vec<usize> = (0..m).collect();
    let mut cand = b.clone();
    let mut block_dims = Vec::new();
    while !alive.is_empty() && basis.ncols() < n {
        let both = basis.hstack(&cand)?;
        let (_, piv) = both.rref();
        let s = basis.ncols();
        let new: Vec<usize> = piv.into_iter().filter(|&c| c >= s).map(|c| c - s).collect();
        if new.is_empty() {
            break;
        }
        let survivors: Vec<usize> = new.iter().map(|&c| alive[c]).collect();
        for &j in &survivors {
            kappa[j] += 1;
        }
        block_dims.push(new.len());
        let picked = cand.select_cols(&new);
        basis = basis.hstack(&picked)?;
        cand = a * &picked;
        alive = survivors;
    }
    let order = basis.ncols();
    let left = basis.left_nullspace();
    // L in RREF: A_c̄ = (L A) restricted to the pivot columns of L
    let (_, lpiv) = left.rref();
    let la = &left * a;
    let uncontrollable = la.select_cols(&lpiv);
    let verified = basis.rank() == order
        && left.nrows() == n - order
        && left.rank() == n - order
        && (&left * b).is_zero()
        && la == &uncontrollable * &left
        && kappa.iter().sum::<usize>() == order;
    let mut indices = kappa;
    indices.sort_unstable_by(|x, y| y.cmp(x));
    Ok(ControllabilityStructure {
        order,
        indices,
        block_dims,
        basis,
        left,
        uncontrollable,
        verified,
    })
}

/// Observability structure of $(C, A)$: the controllability structure of $(A^T, C^T)$
/// (indices = observability indices, `uncontrollable` = the unobservable part transposed).
///
/// # Errors
/// As [`controllability_structure`].
pub fn observability_structure<K: Field>(
    a: &Matrix<K>,
    c: &Matrix<K>,
) -> Result<ControllabilityStructure<K>> {
    controllability_structure(&a.transpose(), &c.transpose())
}

/// Finite and infinite controllability of a regular descriptor system (the counts of
/// SLICOT TG01HD): the finite part $(A_f, B_f)$ and the infinite part $(N, B_\infty)$ of the
/// Weierstrass split, each with its controllability structure.
#[derive(Clone, Debug)]
pub struct DescriptorControllability<K: Field> {
    pub finite: ControllabilityStructure<K>,
    pub infinite: ControllabilityStructure<K>,
    /// $n_f$ and $n_\infty$.
    pub finite_order: usize,
    pub infinite_order: usize,
}

impl<K: Field> DescriptorControllability<K> {
    /// Controllable finite plus controllable infinite order.
    pub fn controllable_order(&self) -> usize {
        self.finite.order + self.infinite.order
    }
    /// Number of uncontrollable infinite eigenvalues.
    pub fn uncontrollable_infinite(&self) -> usize {
        self.infinite_order - self.infinite.order
    }
    pub fn verified(&self) -> bool {
        self.finite.verified && self.infinite.verified
    }
}

/// Finite and infinite controllability structure of $E\dot x = Ax + Bu$; with `dual` the
/// observability structure of $(C, A, E)$.
///
/// # Errors
/// `Invalid` for a singular pencil.
pub fn descriptor_controllability<K: Field>(
    sys: &Descriptor<K>,
    dual: bool,
) -> Result<DescriptorControllability<K>> {
    let split = weierstrass_split(sys)?;
    let f = &split.finite;
    let (finite, infinite) = if dual {
        (
            observability_structure(&f.a, &f.c)?,
            observability_structure(&split.n, &split.c_inf)?,
        )
    } else {
        (
            controllability_structure(&f.a, &f.b)?,
            controllability_structure(&split.n, &split.b_inf)?,
        )
    };
    Ok(DescriptorControllability {
        finite,
        infinite,
        finite_order: f.nstates(),
        infinite_order: split.n.nrows(),
    })
}
