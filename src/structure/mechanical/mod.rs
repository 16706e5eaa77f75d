//! Mechanical normal form (Mayet & Kammermeier): a first-order system back to second order.
//!
//! Given $\dot x = A x + B u$, $y = C x + D u$ ($n$ states, $p$ inputs), find $z = T x$ with
//! $$\tilde A = T A T^{-1} = \begin{bmatrix} 0 & I \\ \tilde A_{21} & \tilde A_{22}\end{bmatrix},
//! \quad \tilde B = T B = \begin{bmatrix} 0 \\ I_p \end{bmatrix},
//! \quad \tilde C = C T^{-1}, \quad \tilde D = D,$$
//! so that with $z = [q; \dot q]$, $q \in \mathbb{Q}^{n/2}$:
//! $$M \ddot q + D_q \dot q + K q = W u, \quad y = \tilde C \begin{bmatrix} q \\ \dot q\end{bmatrix} + \tilde D u,$$
//! with mass $M = I$, damping $D_q = -\tilde A_{22}$, stiffness $K = -\tilde A_{21}$ and input
//! matrix $W = [0; I_p]$ ($n/2 \times p$). `T` here is the paper's product $W T$ of sec. 2.2
//! (the unifying transformation is built into the linear system of sec. 3, eq. 15).
//!
//! Dependent inputs (rank $B = r < p$, including $B = 0$) are handled by the column
//! compression $B = B_1 R$ ([`input_compression`]): the form is computed for $(A, B_1)$, so
//! $\tilde B = T B = [0; I_r] R$ and $W = [0; R]$.
//!
//! For a descriptor system $F \dot x = A x + B u$ with invertible $F$ (sec. 3.1, eq. 16) the
//! same $\tilde A, \tilde B$ arise from a row transformation $T$ with
//! $[I\ 0] T A = [0\ I] T F$, $T B = [0; I_p]$ and the state map $z = (T F) x$:
//! $\tilde A = T A (TF)^{-1}$, $\tilde C = C (TF)^{-1}$. $F$ itself is never inverted.
//!
//! Existence is decided exactly before any search ([`existence`]); the paper's Theorem 2.1
//! conditions are reported, and its last one is replaced by a similarity-invariant condition
//! on the uncontrollable part (see [`existence`] for why).
//!
//! | entry point | input | result |
//! |---|---|---|
//! | [`mechanical_normal_form`] | $(A, B, C, D)$ over any exact field | [`MechanicalNormalForm`] ([`MnfResult`] over $\mathbb{Q}$) |
//! | [`mechanical_normal_form_descriptor`] | $(F, A, B, C, D)$, $F$ invertible | [`MnfResult`] |
//! | [`mechanical_normal_form_in`] | the same over any exact field `K` | [`MechanicalNormalForm<K>`] |
//! | [`existence::decide_existence`] | $(A, B)$ | the conditions and the verdict |
//! | [`transform::transformation_family`], [`transform::find_invertible`] | eq. 15/16 | $T$ |
//! | [`transform::transformation_from_x`] | $X$ | $T = [X^T; X^T A]$ (eq. 7) |
//! | [`unify::unifying_transformation`] | $\hat T$ | $W$ of sec. 2.2 |

pub mod companion;
pub(crate) mod descriptor;
pub(crate) mod existence;
pub(crate) mod steps;
pub mod transform;
pub mod unify;

pub use descriptor::mechanical_normal_form_descriptor;
pub use existence::{Check, Condition, Existence, decide_existence};

use crate::jordan::derivation::Recorder;

use crate::error::{Error, Result};
use crate::field::{Field, Q};
use crate::matrix::Matrix;

/// Default candidate budget of the transformation search (see [`transform::find_invertible`]).
pub const DEFAULT_MAX_CANDIDATES: u64 = 1_000_000;

/// The second-order model and the transformation that produced it.
#[derive(Clone, Debug, PartialEq)]
pub struct MechanicalForm<K: Field> {
    /// $M = I_{n/2}$.
    pub mass: Matrix<K>,
    /// $D_q = -\tilde A_{22}$.
    pub damping: Matrix<K>,
    /// $K = -\tilde A_{21}$.
    pub stiffness: Matrix<K>,
    /// $W = [0; I_p]$, `n/2 x p` ($W = [0; R]$ when $B = B_1 R$ has rank $r < p$).
    pub input: Matrix<K>,
    /// $\tilde C$, `q x n`, acting on $[q; \dot q]$.
    pub output: Matrix<K>,
    /// $\tilde D = D$.
    pub feedthrough: Matrix<K>,
    /// The state map: `z = t x` (for a descriptor system `t` $= T F$).
    pub t: Matrix<K>,
    /// $t^{-1}$ (the exact checks are products with it: $t^{-1} t = I$, $t^{-1} \tilde A =
    /// A t^{-1}$, ...).
    pub t_inv: Matrix<K>,
    /// Descriptor systems only: the row transformation $T$ of eq. 16 ($\tilde A\,t = T A$).
    pub left: Option<Matrix<K>>,
    /// $\tilde A = \begin{bmatrix} 0 & I \\ -K & -D_q \end{bmatrix}$.
    pub a_tilde: Matrix<K>,
    /// $\tilde B = [0; W]$.
    pub b_tilde: Matrix<K>,
    /// The integer coefficients $\alpha$ of $T$ in the eq. 15/16 family and the number of
    /// candidates tested (both empty/0 when the system is already in normal form: $T = I$).
    pub alpha: Vec<i64>,
    pub candidates: u64,
}

/// The original system (kept for [`MechanicalNormalForm::verify`]).
#[derive(Clone, Debug, PartialEq)]
struct Original<K: Field> {
    f: Option<Matrix<K>>,
    a: Matrix<K>,
    b: Matrix<K>,
    c: Matrix<K>,
    d: Matrix<K>,
}

/// Result of [`mechanical_normal_form`]: existence with the reason, and the form.
#[derive(Clone, Debug, PartialEq)]
pub struct MechanicalNormalForm<K: Field> {
    pub exists: bool,
    /// Index in `conditions` of the decisive condition that fails, when `exists` is false.
    pub reason: Option<usize>,
    /// Every condition that was checked (Theorem 2.1's and the decisive replacement).
    pub conditions: Vec<Condition<K>>,
    /// The second-order model, when `exists`.
    pub form: Option<MechanicalForm<K>>,
    /// [`MechanicalNormalForm::verify`] evaluated at construction.
    pub verified: bool,
    original: Original<K>,
}

/// The rational mechanical normal form.
pub type MnfResult = MechanicalNormalForm<Q>;

/// Mechanical normal form of $\dot x = A x + B u$, $y = C x + D u$ over any exact field.
///
/// A system that has no normal form gives `Ok` with `exists = false` and the reason.
///
/// # Errors
/// `NotSquare`/`Shape` when the matrices do not form a system; `Limit` when the search budget
/// [`DEFAULT_MAX_CANDIDATES`] is exhausted (not expected: see [`transform`]);
/// `Verification` when the exact check of the result fails (an internal error).
///
/// # Examples
/// ```
/// use exactlti::qmat;
/// use exactlti::structure::mechanical::mechanical_normal_form;
/// // one mass, spring 4, damper 1: x = [q; q'] scrambled by x = S x'
/// let a = qmat![[-2, -6], [1, 1]]; // S^-1 [[0, 1], [-4, -1]] S with S = [[0, 1], [1, 1]]
/// let r = mechanical_normal_form(&a, &qmat![[1], [0]], &qmat![[1, 0]], &qmat![[0]]).unwrap();
/// assert!(r.exists && r.verified);
/// let f = r.form.unwrap();
/// assert_eq!(f.stiffness.to_string(), "[[4]]");
/// assert_eq!(f.damping.to_string(), "[[1]]");
/// ```
pub fn mechanical_normal_form<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
) -> Result<MechanicalNormalForm<K>> {
    mechanical_normal_form_in(None, a, b, c, d, DEFAULT_MAX_CANDIDATES)
}

/// Shape checks shared by both entry points.
pub(crate) fn check_system<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
) -> Result<()> {
    if !a.is_square() {
        return Err(Error::NotSquare {
            op: "mechanical_normal_form",
            nrows: a.nrows(),
            ncols: a.ncols(),
        });
    }
    let n = a.nrows();
    let shape = |m: &Matrix<K>, expected: (usize, usize)| {
        if m.shape() != expected {
            return Err(Error::Shape {
                op: "mechanical_normal_form",
                expected,
                found: m.shape(),
            });
        }
        Ok(())
    };
    shape(b, (n, b.ncols()))?;
    shape(c, (c.nrows(), n))?;
    shape(d, (c.nrows(), b.ncols()))
}

/// Mechanical normal form over any exact field; `f = Some(F)` for a descriptor system.
///
/// # Errors
/// As [`mechanical_normal_form`]; `Shape` when `f` is not `n x n`, `Invalid` when `f` is
/// singular.
pub fn mechanical_normal_form_in<K: Field>(
    f: Option<&Matrix<K>>,
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
    max_candidates: u64,
) -> Result<MechanicalNormalForm<K>> {
    mechanical_normal_form_recorded(f, [a, b, c, d], max_candidates, None)
}

/// [`mechanical_normal_form_in`], recording its steps (`mnf --steps`, [`steps`]) when `rec`
/// is given: the input compression, the existence conditions with their matrices, eq. 15/16
/// and its solution family, the invertible member and the form. A system already in normal
/// form gets $T = I$ (no search).
///
/// # Errors
/// As [`mechanical_normal_form_in`].
pub fn mechanical_normal_form_recorded<K: Field>(
    f: Option<&Matrix<K>>,
    abcd: [&Matrix<K>; 4],
    max_candidates: u64,
    mut rec: Option<&mut Recorder<'_, K>>,
) -> Result<MechanicalNormalForm<K>> {
    let [a, b, c, d] = abcd;
    check_system(a, b, c, d)?;
    // B = B1 R with B1 = the pivot columns of B (full column rank r) and R the non-zero rows
    // of rref(B): the form is sought for (A, B1) and then T B = [0; I_r] R = [0; R].
    let (b1, r_mat) = input_compression(b);
    if let Some(r) = rec.as_deref_mut()
        && b1.ncols() < b.ncols()
    {
        steps::compression(r, b, &b1, &r_mat);
    }
    let (mut existence, parts) = match f {
        None => existence::decide_existence_parts(a, &b1),
        Some(f) => descriptor::decide_existence_descriptor(f, a, &b1)?,
    };
    // (A, B1) controllable: no uncontrollable part (geometric multiplicity 0)
    let controllable = parts.geo == Some(0);
    if let Some(r) = rec.as_deref_mut() {
        steps::existence(r, &existence, parts, f.is_some());
    }
    let n_decided = existence.conditions.len();
    if b1.ncols() < b.ncols() {
        existence.conditions.insert(
            0,
            Condition {
                check: Check::InputCompression {
                    rank: b1.ncols(),
                    p: b.ncols(),
                },
                holds: true,
                decisive: false,
            },
        );
    }
    let original = Original {
        f: f.cloned(),
        a: a.clone(),
        b: b.clone(),
        c: c.clone(),
        d: d.clone(),
    };
    let shift = existence.conditions.len() - n_decided;
    let mut out = MechanicalNormalForm {
        exists: existence.exists,
        reason: existence.reason.map(|i| i + shift),
        conditions: existence.conditions,
        form: None,
        verified: false,
        original,
    };
    if !out.exists {
        return Ok(out);
    }
    // one controllable input, no steps asked: the interleaved controller form (no search)
    if f.is_none()
        && rec.is_none()
        && controllable
        && !transform::identity_solves(f, a, &b1)
        && let Some((t, t_inv, a_tilde)) = companion::interleaved_controller_form(a, &b1)?
    {
        out.form = Some(form_from_parts([a, b, c, d], &r_mat, (t, t_inv, a_tilde))?);
        return finish(out);
    }
    let (family, l) = transform::transformation_family_with_l(f, a, &b1);
    let family = family.ok_or_else(|| {
        Error::Verification("the conditions hold but eq. 15 has no solution".into())
    })?;
    if let Some(r) = rec.as_deref_mut() {
        steps::equation(r, (f, a, &b1), l, &family);
    }
    let found = if transform::identity_solves(f, a, &b1) {
        let k = a.field().clone();
        transform::SearchOutcome {
            t: Matrix::identity(k.clone(), a.nrows()),
            det: k.one(),
            alpha: vec![],
            candidates: 0,
        }
    } else {
        transform::find_invertible(&family, max_candidates)?
    };
    if let Some(r) = rec.as_deref_mut() {
        steps::search(r, (f, a, &b1), &family, &found);
    }
    out.form = Some(build_form(f, a, b, c, d, found)?);
    out.verified = out.verify();
    if let (Some(r), Some(form)) = (rec, &out.form) {
        steps::form(r, form, out.verified);
    }
    if !out.verified {
        return Err(Error::Verification(
            "the mechanical normal form does not reproduce the system".into(),
        ));
    }
    Ok(out)
}

/// Checks the form just built ([`MechanicalNormalForm::verify`]).
fn finish<K: Field>(mut out: MechanicalNormalForm<K>) -> Result<MechanicalNormalForm<K>> {
    out.verified = out.verify();
    if !out.verified {
        return Err(Error::Verification(
            "the mechanical normal form does not reproduce the system".into(),
        ));
    }
    Ok(out)
}

/// The form from a known $T$, $T^{-1}$ and $\tilde A = T A T^{-1}$ with $T B_1 = e_n$
/// ([`companion`]): $\tilde B = [0; R]$ for $B = B_1 R$, $\tilde C = C T^{-1}$ (no inverse,
/// no product with $T$ on the left).
fn form_from_parts<K: Field>(
    [a, b, c, d]: [&Matrix<K>; 4],
    r_mat: &Matrix<K>,
    (t, t_inv, a_tilde): (Matrix<K>, Matrix<K>, Matrix<K>),
) -> Result<MechanicalForm<K>> {
    let n = a.nrows();
    let h = n / 2;
    let p = b.ncols();
    let k = a.field().clone();
    let mut b_tilde = Matrix::zeros(k.clone(), n, p);
    b_tilde.set_block(n - r_mat.nrows(), 0, r_mat);
    Ok(MechanicalForm {
        mass: Matrix::identity(k, h),
        damping: -&a_tilde.submatrix(h, n, h, n),
        stiffness: -&a_tilde.submatrix(h, n, 0, h),
        input: b_tilde.submatrix(h, n, 0, p),
        output: c.try_mul(&t_inv)?,
        feedthrough: d.clone(),
        t,
        t_inv,
        left: None,
        a_tilde,
        b_tilde,
        alpha: vec![],
        candidates: 0,
    })
}

/// `(B1, R)` with `B = B1 R`: `B1` the pivot columns of `B` (full column rank `r`), `R` the
/// `r` non-zero rows of the reduced row echelon form of `B` (`R = I` when `B` has full
/// column rank).
pub fn input_compression<K: Field>(b: &Matrix<K>) -> (Matrix<K>, Matrix<K>) {
    let (e, piv) = b.rref();
    (b.select_cols(&piv), e.submatrix(0, piv.len(), 0, b.ncols()))
}

/// $\tilde A, \tilde B, \tilde C$ and the second-order matrices from an invertible $T$.
fn build_form<K: Field>(
    f: Option<&Matrix<K>>,
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    d: &Matrix<K>,
    found: transform::SearchOutcome<K>,
) -> Result<MechanicalForm<K>> {
    let n = a.nrows();
    let h = n / 2;
    let p = b.ncols();
    let row_t = found.t;
    let (state_map, left) = match f {
        None => (row_t.clone(), None),
        Some(f) => (row_t.try_mul(f)?, Some(row_t.clone())),
    };
    let s_inv = state_map.inverse()?;
    let a_tilde = row_t.try_mul(a)?.try_mul(&s_inv)?;
    let b_tilde = row_t.try_mul(b)?;
    let output = c.try_mul(&s_inv)?;
    let k = a.field().clone();
    Ok(MechanicalForm {
        mass: Matrix::identity(k, h),
        damping: -&a_tilde.submatrix(h, n, h, n),
        stiffness: -&a_tilde.submatrix(h, n, 0, h),
        input: b_tilde.submatrix(h, n, 0, p),
        output,
        feedthrough: d.clone(),
        t: state_map,
        t_inv: s_inv,
        left,
        a_tilde,
        b_tilde,
        alpha: found.alpha,
        candidates: found.candidates,
    })
}

impl<K: Field> MechanicalNormalForm<K> {
    /// Exact check of the result: $t^{-1} t = I$ (so `t` is invertible and `t_inv` its
    /// inverse); $\tilde A = [[0, I], [-K, -D_q]]$ with $M = I$; $\tilde B = [0; W]$,
    /// $W = [0; R]$ with $B = B_1 R$ ([`input_compression`]; $R = I_p$ for full column rank);
    /// $t^{-1} \tilde A = A t^{-1}$, $t^{-1} \tilde B = B$, $\tilde C = C t^{-1}$ (a
    /// descriptor system: $\tilde A\,t = T A$, $\tilde B = T B$, $\tilde C\,t = C$ with the row
    /// transformation $T$, $T F = t$, and then equal Markov parameters
    /// $\tilde C \tilde A^j \tilde B = C (F^{-1}A)^j F^{-1} B$ for $j < 2n$, computed with
    /// solves, not $F^{-1}$; for a standard system they follow from the similarity) and
    /// $\tilde D = D$. Products with $t^{-1}$ rather than with $t$
    /// on the left: the columns of $t$ may carry different denominators whose common multiple
    /// is large (a diagonal $A$ in symbols), its columns one each. `false` when no form exists.
    pub fn verify(&self) -> bool {
        let Some(m) = &self.form else { return false };
        let o = &self.original;
        let k = o.a.field().clone();
        let n = o.a.nrows();
        let h = n / 2;
        let p = o.b.ncols();
        // t^-1 t = I: t is invertible and t_inv its inverse (square matrices)
        if !(&m.t_inv * &m.t).is_identity() || !m.mass.is_identity() {
            return false;
        }
        let id = Matrix::identity(k.clone(), h);
        let zero = Matrix::zeros(k.clone(), h, h);
        let expected_a = Matrix::block(
            k.clone(),
            &[vec![&zero, &id], vec![&(-&m.stiffness), &(-&m.damping)]],
        )
        .expect("blocks agree");
        // W = [0; R] with B = B1 R (R = I_p when B has full column rank)
        let (_, r_mat) = input_compression(&o.b);
        let r = r_mat.nrows();
        if r > h {
            return false;
        }
        let mut w = Matrix::zeros(k.clone(), h, p);
        w.set_block(h - r, 0, &r_mat);
        let expected_b = Matrix::zeros(k.clone(), h, p)
            .vstack(&w)
            .expect("p columns");
        if m.a_tilde != expected_a || m.b_tilde != expected_b || m.input != w {
            return false;
        }
        if m.feedthrough != o.d {
            return false;
        }
        let Some(f) = &o.f else {
            // t^-1 t = I, t^-1 A~ = A t^-1, t^-1 B~ = B, C~ = C t^-1: a similarity, so
            // C~ A~^j B~ = C A^j B for every j (the Markov parameters agree by the identity;
            // forming the powers would only grow the entries)
            return &m.t_inv * &m.a_tilde == &o.a * &m.t_inv
                && &m.t_inv * &m.b_tilde == o.b
                && m.output == &o.c * &m.t_inv;
        };
        let row_t = m.left.as_ref().unwrap_or(&m.t);
        if row_t * f != m.t
            || &m.a_tilde * &m.t != row_t * &o.a
            || m.b_tilde != row_t * &o.b
            || &m.output * &m.t != o.c
        {
            return false;
        }
        markov_parameters(o.f.as_ref(), &o.a, &o.b, &o.c, 2 * n)
            == markov_parameters(None, &m.a_tilde, &m.b_tilde, &m.output, 2 * n)
    }
}

/// Markov parameters $C (F^{-1}A)^j F^{-1} B$, $j < count$, by solves with $F$ (never
/// $F^{-1}$). Split as $[C (F^{-1}A)^i]\,[(F^{-1}A)^{j-i} F^{-1}B]$ with $i \le count/2$ so no
/// power beyond about $count/2$ is formed (entry sizes grow with the power).
pub(crate) fn markov_parameters<K: Field>(
    f: Option<&Matrix<K>>,
    a: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    count: usize,
) -> Vec<Matrix<K>> {
    let solve = |x: &Matrix<K>| match f {
        None => x.clone(),
        Some(f) => f.solve(x).expect("shapes").expect("F invertible").0,
    };
    let solve_t = |x: &Matrix<K>| match f {
        None => x.clone(),
        Some(f) => {
            let y = f.transpose().solve(&x.transpose()).expect("shapes");
            y.expect("F invertible").0.transpose()
        }
    };
    let half = count.div_ceil(2);
    // left[i] = C (F^-1 A)^i, right[i] = (F^-1 A)^i F^-1 B
    let mut left = vec![c.clone()];
    for i in 1..half {
        left.push(&solve_t(&left[i - 1]) * a);
    }
    let mut right = vec![solve(b)];
    for i in 1..=count.saturating_sub(half) {
        right.push(solve(&(a * &right[i - 1])));
    }
    (0..count)
        .map(|j| {
            let i = j.min(half.saturating_sub(1));
            &left[i] * &right[j - i]
        })
        .collect()
}
