//! Kronecker structure of a matrix pencil $A - sE$ ($m \times n$, singular or regular), exactly.
//!
//! Every pencil is strictly equivalent ($P(A - sE)Q$, $P$, $Q$ invertible) to a block
//! diagonal of right blocks $L_{\varepsilon}$ ($\varepsilon \times (\varepsilon + 1)$), left
//! blocks $L_\eta^T$, infinite Jordan blocks $N_k$ ($sN_k - I$, size $k$; $k = 1$ is a
//! non-dynamic mode) and a finite part $J - sI$. The dimension count is
//! $n = \sum(\varepsilon_i + 1) + \sum \eta_j + n_\infty + n_f$,
//! $m = \sum \varepsilon_i + \sum(\eta_j + 1) + n_\infty + n_f$, and the normal rank is
//! $r = n - \#\varepsilon = m - \#\eta$.
//!
//! # Algorithm
//! Van Dooren's staircase with exact ranks and null spaces ([`staircase`]): deflate the right
//! and infinite structure from $\ker E$; run the same on the transposed remainder for the left
//! indices; the last remainder has $E$ invertible and its finite part is $E^{-1}A$. This is
//! the exact analogue of SLICOT AG08BD/MB04VD and MatrixPencils.jl `pkstruct`/`klf`, with
//! no tolerance: a rank is a rank.
//!
//! # Verification
//! The proof is the certificate of every staircase step ([`staircase`]): exact products
//! $EN_i = 0$, $Y(AN_i) = 0$ for the exhibited null spaces, and lower bounds on ranks,
//! each from one elimination modulo a word prime (a rank modulo $p$ never exceeds the rank
//! over $\mathbb{Q}$, so the bound is exact); the last remainder has $E_r$ of full rank
//! and $E_r A_f = A_r$ exactly. With Van Dooren's theorem these determine every index.
//! Cross-checks independent of the staircase ([`verify`]): block Toeplitz ranks for the
//! right and left indices and the infinite eigenvalue's partial multiplicities (modulo a
//! prime; they refute any structure that predicts a lower rank than found),
//! $\mathrm{rank}(A - s_0E) \ge r$ at one point, and the dimension count. The finite
//! eigenvalues are those of $A_f$, with the Jordan form's own identities
//! ([`crate::jordan`]), and the Toeplitz ranks of the pencil at each of them.
//!
//! Over $\mathbb{Q}$ no certified (multi-modular) rank of a Toeplitz matrix is needed:
//! a 100 x 120 pencil's checks cost single eliminations modulo $p$ of matrices up to
//! 500 x 480 instead of tens of primes each.
//!
//! | entry point | computes |
//! |---|---|
//! | [`kronecker_structure`] | indices, infinite divisors, finite part $E_f^{-1}A_f$ over any field |
//! | [`pencil_structure`] | over $\mathbb{Q}$: also the finite eigenvalues with Jordan blocks |

mod staircase;
pub(crate) mod verify;

use crate::error::{Error, Result};
use crate::field::{Field, Q};
use crate::jordan::{JordanField, JordanForm};
use crate::matrix::Matrix;

/// The Kronecker structure of $A - sE$.
#[derive(Clone, Debug, PartialEq)]
pub struct KroneckerStructure<K: Field> {
    /// $(m, n)$.
    pub shape: (usize, usize),
    pub normal_rank: usize,
    /// Right (column) minimal indices $\varepsilon_i$, ascending.
    pub right_indices: Vec<usize>,
    /// Left (row) minimal indices $\eta_j$, ascending.
    pub left_indices: Vec<usize>,
    /// Sizes of the infinite Jordan blocks, ascending (1 = non-dynamic mode).
    pub infinite_divisors: Vec<usize>,
    /// $A_f$ with $A_f - sI$ strictly equivalent to the finite part ($n_f \times n_f$).
    pub finite_part: Matrix<K>,
    /// Staircase steps $(n_i, \rho_i)$ of the right and of the (transposed) left deflation.
    pub right_steps: Vec<(usize, usize)>,
    pub left_steps: Vec<(usize, usize)>,
    /// The staircase certificate (module docs), the dimension count, the rank at a point
    /// and the Toeplitz cross-checks of the right, left and infinite structure held.
    pub verified: bool,
}

impl<K: Field> KroneckerStructure<K> {
    /// Square with $\det(A - sE) \not\equiv 0$.
    pub fn is_regular(&self) -> bool {
        self.shape.0 == self.shape.1 && self.normal_rank == self.shape.0
    }
    /// Number of finite eigenvalues with multiplicity.
    pub fn finite_order(&self) -> usize {
        self.finite_part.nrows()
    }
    /// Total size of the infinite Jordan blocks.
    pub fn infinite_order(&self) -> usize {
        self.infinite_divisors.iter().sum()
    }
    /// Number of infinite elementary divisors of size 1 (non-dynamic modes).
    pub fn nondynamic_modes(&self) -> usize {
        self.infinite_divisors.iter().filter(|&&k| k == 1).count()
    }
    fn dimension_count_holds(&self) -> bool {
        let (m, n) = self.shape;
        let se: usize = self.right_indices.iter().sum();
        let sh: usize = self.left_indices.iter().sum();
        let core = self.infinite_order() + self.finite_order();
        n == se + self.right_indices.len() + sh + core
            && m == se + sh + self.left_indices.len() + core
            && self.normal_rank + self.right_indices.len() == n
            && self.normal_rank + self.left_indices.len() == m
    }
}

/// Kronecker structure of $A - sE$ over any field.
///
/// # Errors
/// `Shape` when `A` and `E` differ in shape; `Verification` if the deflation leaves a
/// remainder that is not a square pencil with invertible $E$ (an internal error).
///
/// # Examples
/// ```
/// use exactlti::{pencil::kronecker_structure, qmat};
/// // [s, 1] (an L_1 block) beside the non-dynamic mode 1 (E = 0, A = 1)
/// let a = qmat![[0, 1, 0], [0, 0, 1]];
/// let e = qmat![[1, 0, 0], [0, 0, 0]];
/// let k = kronecker_structure(&a, &e).unwrap();
/// assert_eq!((k.right_indices, k.infinite_divisors, k.normal_rank), (vec![1], vec![1], 2));
/// assert!(k.verified);
/// ```
pub fn kronecker_structure<K: Field>(
    a: &Matrix<K>,
    e: &Matrix<K>,
) -> Result<KroneckerStructure<K>> {
    e.check_shape("pencil E", a.shape())?;
    if a.field() != e.field() {
        return Err(Error::FieldMismatch);
    }
    let right = staircase::deflate_right(a, e);
    let (right_indices, infinite_divisors) = staircase::indices_from_steps(&right.steps);
    let left = staircase::deflate_right(&right.a.transpose(), &right.e.transpose());
    let (left_indices, inf_left) = staircase::indices_from_steps(&left.steps);
    let (ar, er) = (left.a.transpose(), left.e.transpose());
    if !inf_left.is_empty() || !er.is_square() {
        return Err(Error::Verification(
            "pencil staircase: remainder is not a regular pencil without infinite eigenvalues"
                .into(),
        ));
    }
    let n_r = er.nrows();
    let remainder_ok = right.certified && left.certified && er.rank_at_least(n_r);
    let finite_part = &er.inverse()? * &ar;
    let remainder_ok = remainder_ok && &er * &finite_part == ar;
    let (m, n) = a.shape();
    let mut ks = KroneckerStructure {
        shape: (m, n),
        normal_rank: n - right_indices.len(),
        right_indices,
        left_indices,
        infinite_divisors,
        finite_part,
        right_steps: right.steps,
        left_steps: left.steps,
        verified: false,
    };
    ks.verified = remainder_ok && verify_structure(a, e, &ks);
    Ok(ks)
}

/// The checks of the module docs except the finite eigenvalues.
fn verify_structure<K: Field>(a: &Matrix<K>, e: &Matrix<K>, ks: &KroneckerStructure<K>) -> bool {
    let (m, n) = ks.shape;
    let r = ks.normal_rank;
    ks.dimension_count_holds()
        && verify::rank_attained(a, e, r, m.min(n) + 1)
        && verify::check_right(a, e, &ks.right_indices)
        && verify::check_right(&a.transpose(), &e.transpose(), &ks.left_indices)
        && verify::check_local(&-e, a, n - r, &ks.infinite_divisors)
}

/// The Kronecker structure of a pencil with the Jordan form of its finite part.
#[derive(Clone, Debug)]
pub struct PencilStructure<K: Field = Q> {
    pub structure: KroneckerStructure<K>,
    /// Jordan form of the finite part: eigenvalues and block sizes.
    pub finite: JordanForm<K>,
    /// The structure's certificate and checks, the Jordan identities of the finite part
    /// (the proof), and the Toeplitz cross-checks $\dim\ker T_k(\theta)$ of the pencil
    /// itself at every finite eigenvalue $\theta$ (for a root $\theta$ of an irreducible
    /// factor $f$ of degree $d \ge 2$ through $A \otimes I - E \otimes C_f$ over the field,
    /// $C_f$ the companion matrix of $f$; modulo a prime as in [`verify`] over
    /// $\mathbb{Q}$) held.
    pub verified: bool,
}

/// Companion matrix of a monic-izable polynomial (last row $-f_0, \dots, -f_{d-1}$).
fn companion<K: Field>(f: &crate::poly::Poly<K>) -> Matrix<K> {
    let k = f.field().clone();
    let d = f.deg();
    let lc = f.lc();
    Matrix::from_fn(k.clone(), d, d, |i, j| {
        if i + 1 == d {
            k.neg(
                &k.div(&f.coeff(j), &lc)
                    .expect("nonzero leading coefficient"),
            )
        } else if j == i + 1 {
            k.one()
        } else {
            k.zero()
        }
    })
}

/// Kronecker structure of a pencil over any [`JordanField`], finite eigenvalues included.
///
/// # Errors
/// As [`kronecker_structure`] and [`JordanField::jordan_form`].
pub fn pencil_structure<K: JordanField>(
    a: &Matrix<K>,
    e: &Matrix<K>,
) -> Result<PencilStructure<K>> {
    let k = a.field().clone();
    let structure = kronecker_structure(a, e)?;
    let finite = K::jordan_form(&structure.finite_part)?;
    let defect = structure.shape.1 - structure.normal_rank;
    let mut ok = structure.verified && finite.verified;
    for comp in &finite.components {
        if !ok {
            break;
        }
        ok = if comp.factor.deg() == 1 {
            let theta = k.neg(
                &k.div(&comp.factor.coeff(0), &comp.factor.coeff(1))
                    .expect("nonzero leading coefficient"),
            );
            let p0 = a - &e.scale(&theta);
            verify::check_local(&p0, &-e, defect, &comp.blocks)
        } else {
            // the pencil at the companion matrix C_f of the factor f (degree d):
            // A (x) I_d - E (x) C_f is similar over the splitting field to the direct sum of
            // A - theta_j E over the d conjugate roots, which share one local structure, so
            // every kernel dimension is d times that at theta (exact, over the field).
            let d = comp.factor.deg();
            let cf = companion(&comp.factor);
            let id = Matrix::identity(k.clone(), d);
            let p0 = &a.kron(&id) - &e.kron(&cf);
            let p1 = -&e.kron(&id);
            let blocks: Vec<usize> = comp
                .blocks
                .iter()
                .flat_map(|&b| std::iter::repeat_n(b, d))
                .collect();
            verify::check_local(&p0, &p1, d * defect, &blocks)
        };
    }
    Ok(PencilStructure {
        structure,
        finite,
        verified: ok,
    })
}
