//! Descriptor to standard state space (paper sec. 3.5), exactly and for any index.
//!
//! The basis is the one a person would write down by hand whenever possible:
//!
//! * **$E$ invertible**: $\dot x = E^{-1}Ax + E^{-1}Bu$, $y = Cx + Du$ (the file's states).
//! * **index 1** (paper eq. 40-47): compress $UEV = \mathrm{diag}(E_{11}, 0)$ (a permutation
//!   when $E$ is block diagonal up to one; [`super::descriptor_elim`]); with $\hat A_{22}$
//!   invertible the algebraic states are eliminated,
//!   $\dot z_1 = E_{11}^{-1}(\hat A_{11} - \hat A_{12}\hat A_{22}^{-1}\hat A_{21})z_1 +
//!   E_{11}^{-1}(\hat B_1 - \hat A_{12}\hat A_{22}^{-1}\hat B_2)u$,
//!   $y = (\hat C_1 - \hat C_2\hat A_{22}^{-1}\hat A_{21})z_1 + (D - \hat C_2\hat A_{22}^{-1}\hat B_2)u$.
//! * **higher index**: a Weierstrass-type split, without inverting $E$:
//!
//! 1. pick $\lambda_0$ with $\det(\lambda_0 E - A) \ne 0$ (trying $0, 1, -1, 2, \dots$: if
//!    $n + 1$ values fail, $\det(sE - A) \equiv 0$ and the pencil is singular);
//! 2. $M = (\lambda_0 E - A)^{-1}$, $\hat E = M E$, $\hat B = M B$; then $M A = \lambda_0
//!    \hat E - I$, so $E\dot x = Ax + Bu \iff \hat E \dot x = (\lambda_0 \hat E - I)x + \hat B u$;
//! 3. the Fitting decomposition $K^n = \mathrm{range}\,\hat E^n \oplus \ker \hat E^n$, $x = V_1
//!    z_1 + V_2 z_2$, splits $\hat E$ into an invertible $\hat E_1$ (the finite eigenvalues
//!    $\lambda = \lambda_0 - 1/\mu$) and a nilpotent $N$ (the infinite ones); the bases come
//!    from $\hat E^k$, $k$ the index of $N$, without forming a power of $\hat E$
//!    ([`super::weierstrass`]'s `fitting_bases`);
//! 4. $\dot z_1 = (\lambda_0 I - \hat E_1^{-1}) z_1 + \hat E_1^{-1}\hat B_1 u$ and, with
//!    $G = (I - \lambda_0 N)^{-1}$, $z_2 = \sum_{k \ge 0} (-s\,GN)^k G \hat B_2 u$.
//!
//! The system is proper iff $C V_2 (GN)^k G \hat B_2 = 0$ for $k \ge 1$; then
//! $y = C V_1 z_1 + (D + C V_2 G \hat B_2) u$. Otherwise the polynomial part is reported in the
//! error. Impulsive (infinite) modes are removed in every case; the result has exactly
//! $\deg \det(sE - A)$ states.
//!
//! Every route is checked the same way: the transfer matrix of the standard form equals
//! $C(sE - A)^{-1}B + D$ exactly ([`super::weierstrass::same_transfer`]: Markov parameters
//! when both $E$ are invertible, else Taylor coefficients at a regular rational point, as
//! many as the degree of the difference allows).

use super::weierstrass::same_transfer;
use crate::error::{Error, Result};
use crate::field::Field;
use crate::jordan::derivation::Recorder;
use crate::matrix::Matrix;
use crate::system::{Descriptor, StateSpace};

/// The standard form of a descriptor system.
#[derive(Clone, Debug)]
pub struct StandardForm<K: Field> {
    pub system: StateSpace<K>,
    /// Number of infinite eigenvalues (states) removed.
    pub removed_infinite: usize,
    /// How the basis was chosen.
    pub method: StandardMethod,
    /// The shift $\lambda_0$ of the Weierstrass split (`None` for the other methods).
    pub lambda0: Option<i64>,
    /// `x = V1 z + (terms in u)`: the standard form's states in the descriptor's.
    pub v1: Matrix<K>,
    /// `z_j = x_{states[j]}` exactly, when every state of the standard form is one of the
    /// descriptor's own ($x = V_1 z + W u$ with row `states[j]` of $V_1$ the unit row $e_j^T$
    /// and of $W$ zero; the index-0 and index-1 routes when $E$ is block diagonal up to a
    /// permutation); `None` otherwise.
    pub states: Option<Vec<usize>>,
    /// The transfer matrix of the standard form equals the descriptor's (exactly,
    /// [`super::weierstrass::same_transfer`]) and, for the Weierstrass split, the transformed pencil is block
    /// diagonal.
    pub verified: bool,
}

/// The route of [`descriptor_to_standard`] (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StandardMethod {
    /// $E$ invertible: $E^{-1}A$, $E^{-1}B$, $C$, $D$.
    Invertible,
    /// Index 1: elimination of the algebraic states.
    IndexOne,
    /// Higher index: the Weierstrass-type split.
    Weierstrass,
}

impl StandardMethod {
    pub fn name(self) -> &'static str {
        match self {
            StandardMethod::Invertible => "E invertible: A = E^-1 A, B = E^-1 B",
            StandardMethod::IndexOne => "index 1: algebraic states eliminated",
            StandardMethod::Weierstrass => "Weierstrass split (index > 1)",
        }
    }
}

/// The standard form of an index-0 or index-1 system by compression and elimination
/// (module docs); `None` for a higher index.
fn index_one_form<K: Field>(
    sys: &Descriptor<K>,
    mut rec: Option<&mut Recorder<'_, K>>,
) -> Result<Option<StandardForm<K>>> {
    let n = sys.nstates();
    let c = super::descriptor_elim::compress_e(sys)?;
    let r = c.rank;
    let (rows, cols) = super::descriptor_elim::algebraic_block(&c);
    if let Some(rec) = rec.as_deref_mut() {
        super::standard_steps::compress(rec, sys, &c, rows.len());
    }
    if rows.len() != n - r {
        return Ok(None);
    }
    let (red, xa, xb) = super::descriptor_elim::eliminate(&c.system, &rows, &cols)?;
    if let Some(rec) = rec.as_deref_mut()
        && !rows.is_empty()
    {
        super::standard_steps::eliminate(rec, &c, (&rows, &cols), &red);
    }
    let e11i = red.e.inverse()?;
    let system = StateSpace::new(&e11i * &red.a, &e11i * &red.b, red.c, red.d)?;
    // x = V [z1; z2], z2 = -A22^-1 (A21 z1 + B2 u): x = V1 z1 + W u
    let v2 = c.v.submatrix(0, n, r, n);
    let v1 = &c.v.submatrix(0, n, 0, r) + &(&v2 * &xa);
    let w = &v2 * &xb;
    let method = if r == n {
        StandardMethod::Invertible
    } else {
        StandardMethod::IndexOne
    };
    let verified = maps_solutions(sys, &system, &v1, &w);
    if let Some(rec) = rec {
        let route = usize::from(method == StandardMethod::IndexOne);
        super::standard_steps::form(rec, &system, (&v1, Some(&w)), (n - r, route), verified);
    }
    let states = own_states(&v1, &w);
    Ok(Some(StandardForm {
        system,
        removed_infinite: n - r,
        method,
        lambda0: None,
        v1,
        states,
        verified,
    }))
}

/// For each state $z_j$ the descriptor state $x_i$ it equals ($x = V_1 z + W u$, row $i$ of
/// $V_1$ is $e_j^T$ and row $i$ of $W$ is zero), the first such $i$; `None` when some $z_j$
/// has none.
fn own_states<K: Field>(v1: &Matrix<K>, w: &Matrix<K>) -> Option<Vec<usize>> {
    let k = v1.field();
    let unit_row = |i: usize| -> Option<usize> {
        let nz: Vec<usize> = (0..v1.ncols())
            .filter(|&j| !k.is_zero(v1.get(i, j)))
            .collect();
        let clean = (0..w.ncols()).all(|j| k.is_zero(w.get(i, j)));
        (clean && nz.len() == 1 && k.is_one(v1.get(i, nz[0]))).then(|| nz[0])
    };
    let mut states = vec![None; v1.ncols()];
    for i in 0..v1.nrows() {
        if let Some(j) = unit_row(i) {
            states[j].get_or_insert(i);
        }
    }
    states.into_iter().collect()
}

/// The certificate of the index-1 route: with $x = V_1z + Wu$ every solution of the
/// standard system solves the descriptor system with the same output, i.e. $EW = 0$,
/// $EV_1A_s = AV_1$, $EV_1B_s = AW + B$, $CV_1 = C_s$, $CW + D = D_s$. In the Laplace domain
/// $(sE - A)(V_1Z + WU) = BU$, and since $sE - A$ is regular ($E_{11}$ and $X$ invertible)
/// the transfer matrices are equal. Four products, cheap over every field.
fn maps_solutions<K: Field>(
    sys: &Descriptor<K>,
    s: &StateSpace<K>,
    v1: &Matrix<K>,
    w: &Matrix<K>,
) -> bool {
    let ev1 = &sys.e * v1;
    (&sys.e * w).is_zero()
        && &ev1 * &s.a == &sys.a * v1
        && &ev1 * &s.b == &(&sys.a * w) + &sys.b
        && &sys.c * v1 == s.c
        && &(&sys.c * w) + &sys.d == s.d
}

/// $(I, A, B, C, D)$.
fn system_as_descriptor<K: Field>(s: &StateSpace<K>) -> Result<Descriptor<K>> {
    Descriptor::new(
        Matrix::identity(s.a.field().clone(), s.nstates()),
        s.a.clone(),
        s.b.clone(),
        s.c.clone(),
        s.d.clone(),
    )
}

/// Converts $E\dot x = Ax + Bu$, $y = Cx + Du$ to standard form.
///
/// # Errors
/// `Invalid` for a singular pencil; `ImproperTransfer` (naming the highest power of $s$)
/// when the transfer matrix has a polynomial part.
pub fn descriptor_to_standard<K: Field>(sys: &Descriptor<K>) -> Result<StandardForm<K>> {
    descriptor_to_standard_recorded(sys, None)
}

/// [`descriptor_to_standard`], recording its steps (`standard --steps`,
/// [`super::standard_steps`]) when `rec` is given.
///
/// # Errors
/// As [`descriptor_to_standard`].
pub fn descriptor_to_standard_recorded<K: Field>(
    sys: &Descriptor<K>,
    mut rec: Option<&mut Recorder<'_, K>>,
) -> Result<StandardForm<K>> {
    if let Some(f) = index_one_form(sys, rec.as_deref_mut())? {
        return Ok(f);
    }
    let split = super::weierstrass::fitting_split(sys)?;
    if let Some(rec) = rec.as_deref_mut() {
        super::standard_steps::fitting(rec, &split);
    }
    let (gn, gb) = (&split.gn, &split.gb);
    let k2 = gn.nrows();
    let cv2 = &sys.c * &split.v2;
    let d_std = &sys.d + &(&cv2 * gb);
    // properness: C V2 (G N)^k G B2 = 0 for k >= 1
    let mut term = gb.clone();
    for k in 1..=k2 {
        term = gn * &term;
        if !(&cv2 * &term).is_zero() {
            let mut hi = k;
            let mut t2 = term.clone();
            for kk in k + 1..=k2 {
                t2 = gn * &t2;
                if !(&cv2 * &t2).is_zero() {
                    hi = kk;
                }
            }
            return Err(Error::ImproperTransfer(format!(
                "the transfer matrix has a polynomial part of degree {hi} in s{} (derivatives of the input reach the output); no standard state-space form exists",
                polynomial_part_display(sys)
            )));
        }
    }
    let system = StateSpace::new(split.a_f, split.b_f, &sys.c * &split.v1, d_std)?;
    let verified = split.decoupled && same_transfer(sys, &system_as_descriptor(&system)?);
    if let Some(rec) = rec {
        super::standard_steps::form(rec, &system, (&split.v1, None), (k2, 2), verified);
    }
    Ok(StandardForm {
        system,
        removed_infinite: k2,
        method: StandardMethod::Weierstrass,
        lambda0: split.lambda0,
        v1: split.v1,
        states: None,
        verified,
    })
}

/// `", P(s) = [[...]]"`: the polynomial part of the transfer matrix (constant term
/// included) for at most 16 entries; empty otherwise or when the split fails.
fn polynomial_part_display<K: Field>(sys: &Descriptor<K>) -> String {
    let (p, m) = (sys.c.nrows(), sys.b.ncols());
    if p * m > 16 {
        return String::new();
    }
    let Ok(split) = super::weierstrass::weierstrass_split(sys) else {
        return String::new();
    };
    let coeffs = split.polynomial_part();
    let fld = sys.d.field().clone();
    let rows: Vec<String> = (0..p)
        .map(|i| {
            let entries: Vec<String> = (0..m)
                .map(|j| {
                    let c = coeffs.iter().map(|pk| pk.get(i, j).clone()).collect();
                    crate::poly::Poly::new(fld.clone(), c).to_string_var("s")
                })
                .collect();
            format!("[{}]", entries.join(", "))
        })
        .collect();
    format!(", P(s) = [{}]", rows.join(", "))
}

/// The finite dynamics of a regular descriptor system, proper or not: the standard form's
/// $A$ when the system is proper, else the finite part of the Weierstrass split
/// ([`super::weierstrass_split`]). Its eigenvalues and Jordan blocks are the finite
/// eigenvalues and finite elementary divisors of $sE - A$.
///
/// # Errors
/// `Invalid` for a singular pencil.
pub fn finite_dynamics<K: Field>(sys: &Descriptor<K>) -> Result<(Matrix<K>, StandardMethod)> {
    match descriptor_to_standard(sys) {
        Ok(f) => Ok((f.system.a, f.method)),
        Err(Error::ImproperTransfer(_)) => Ok((
            super::weierstrass::weierstrass_split(sys)?.finite.a,
            StandardMethod::Weierstrass,
        )),
        Err(e) => Err(e),
    }
}
