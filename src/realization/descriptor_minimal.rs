//! Minimal and irreducible descriptor realizations, improper systems included.
//!
//! From the Weierstrass split ([`weierstrass_split`]) $G(s) = C_f(sI - A_f)^{-1}B_f + D +
//! C_\infty(I + sN)^{-1}B_\infty$, $N$ nilpotent:
//!
//! 1. **irreducible**: a minimal (Kalman) realization $(A_m, B_m, C_m)$ of the finite part,
//!    and one, $(N_r, B_r, C_r)$, of the sequence $C_\infty N^kB_\infty$, $k \ge 0$ ($N_r$ is
//!    nilpotent as a restriction of $N$); $E = \mathrm{diag}(I, -N_r)$, $A = I$ on the
//!    infinite part, $B = [B_m; -B_r]$, $C = [C_m, C_r]$ (as $-(-sN_r - I)^{-1} = (I +
//!    sN_r)^{-1}$). For nilpotent $N_r$ the PBH test at its only eigenvalue reads
//!    $\mathrm{rank}[N_r, B_r] = n_r$: Kalman's controllability of $(N_r, B_r)$ is
//!    controllability at infinity, and the same for observability. This is the least order
//!    with the pole and zero structure kept (SLICOT TG01JD, DescriptorSystems.jl `gir`);
//! 2. **minimal**: the non-dynamic modes (infinite blocks of size 1) of the irreducible
//!    infinite part are eliminated ([`super::descriptor_elim::remove_nondynamic`]); an
//!    irreducible realization without non-dynamic modes has least order
//!    (Verghese-Lévy-Kailath 1981).
//!
//! When the realization of the shifted sequence $(0, P_1, \dots, P_q)$ with $D = P_0$ (the
//! constant of the polynomial part) has the same order, it is preferred (same least order,
//! $D$ is then $G$'s constant at infinity).
//!
//! Both steps only remove states, so the order never exceeds the input's. The result is
//! checked exactly: same transfer matrix, finite part controllable and observable,
//! $\mathrm{rank}[E, B] = \mathrm{rank}[E; C] = n$ and $A\ker E \subseteq \mathrm{im}\,E$.
//! The transfer matrix is compared piecewise, never by expanding the input's (over
//! $\mathbb{Q}(p)$ with many parameters its Taylor coefficients were what ran out of
//! memory): the split's identities prove $G = G_f + G_\infty$
//! (`FittingSplit` in [`super::weierstrass`]), the finite part's minimal realization has its
//! Markov parameters ([`minimal_kalman`]'s check), and the realization of the infinite part
//! (with $D$) has the transfer matrix of $(GN, -I, G\hat B_2, CV_2, D)$
//! ([`same_transfer`] on the small infinite parts); the result is block diagonal, so its
//! transfer matrix is the sum of the two.
//!
//! (Realizing only the shifted sequence, as an earlier version did, fixes $C_rB_r = 0$ and
//! can need more states than the input: $[[s^2, s], [s, 1]]$ from De Terán-Dopico-Mackey
//! has minimal order 3, that gave 4.)

use super::controllability::{is_controllable, is_observable};
use super::descriptor_elim::remove_nondynamic;
use super::descriptor_minimal_steps as steps;
use super::minimal::minimal_kalman;
use super::weierstrass::{WeierstrassSplit, same_transfer};
use crate::error::Result;
use crate::field::Field;
use crate::jordan::derivation::Recorder;
use crate::matrix::Matrix;
use crate::system::{Descriptor, StateSpace};

pub use super::descriptor_minimal_result::{DescriptorMinimal, is_minimal_at_infinity};

/// $\mathrm{diag}$ of a standard system $(A_f, B_f, C_f)$ and a descriptor system.
fn assemble<K: Field>(fin: &StateSpace<K>, inf: &Descriptor<K>) -> Result<Descriptor<K>> {
    let fld = inf.d.field().clone();
    let e = Matrix::block_diag(
        fld.clone(),
        &[Matrix::identity(fld.clone(), fin.nstates()), inf.e.clone()],
    );
    let a = Matrix::block_diag(fld, &[fin.a.clone(), inf.a.clone()]);
    Descriptor::new(
        e,
        a,
        fin.b.vstack(&inf.b)?,
        fin.c.hstack(&inf.c)?,
        inf.d.clone(),
    )
}

/// A realization of the infinite part with $D = P_0$: a minimal realization $(N_m, B_z, C_z)$
/// of the Markov sequence $(0, P_1, \dots, P_q)$ (as the system $w' = u$, $x' = -Nx - NBw$,
/// $y = C_\infty x$), $E = N_m$, $A = I$, $C = -C_z$. It fixes $C_zB_z = 0$, so its order can
/// exceed the minimal one; [`minimal_descriptor`] takes it only at the minimal order, where it
/// shows the constant of the polynomial part as $D$.
fn shifted_sequence<K: Field>(
    n: &Matrix<K>,
    b: &Matrix<K>,
    c: &Matrix<K>,
    p0: &Matrix<K>,
) -> Result<Descriptor<K>> {
    let fld = n.field().clone();
    let (p, m) = p0.shape();
    let ni = n.nrows();
    let a_aug = Matrix::block(
        fld.clone(),
        &[
            vec![&-n, &-&(n * b)],
            vec![
                &Matrix::zeros(fld.clone(), m, ni),
                &Matrix::zeros(fld.clone(), m, m),
            ],
        ],
    )?;
    let b_aug = Matrix::zeros(fld.clone(), ni, m).vstack(&Matrix::identity(fld.clone(), m))?;
    let c_aug = c.hstack(&Matrix::zeros(fld.clone(), p, m))?;
    let z = minimal_kalman(&StateSpace::new_strictly_proper(a_aug, b_aug, c_aug)?)?.system;
    let k = z.nstates();
    Descriptor::new(z.a, Matrix::identity(fld, k), z.b, -&z.c, p0.clone())
}

/// The infinite part of a split with the feedthrough, as the descriptor system
/// $(GN, -I, G\hat B_2, CV_2, D)$: $(sGN + I)^{-1}$ (`FittingSplit` in [`super::weierstrass`]).
fn infinite_descriptor<K: Field>(split: &WeierstrassSplit<K>) -> Result<Descriptor<K>> {
    let fld = split.d.field().clone();
    Descriptor::new(
        split.n.clone(),
        -&Matrix::identity(fld, split.n.nrows()),
        split.b_inf.clone(),
        split.c_inf.clone(),
        split.d.clone(),
    )
}

/// Minimal descriptor realization of a regular descriptor system (proper or not).
///
/// # Errors
/// `Invalid` for a singular pencil.
pub fn minimal_descriptor<K: Field>(sys: &Descriptor<K>) -> Result<DescriptorMinimal<K>> {
    minimal_descriptor_recorded(sys, None)
}

/// [`minimal_descriptor`], recording its steps (`minreal --descriptor --steps`,
/// [`super::descriptor_minimal_steps`]) when `rec` is given: the Weierstrass split, the
/// finite part's minimal part, the infinite part's minimal realization, the non-dynamic
/// modes removed, the assembled realization, each with its identity.
///
/// # Errors
/// As [`minimal_descriptor`].
pub fn minimal_descriptor_recorded<K: Field>(
    sys: &Descriptor<K>,
    mut rec: Option<&mut Recorder<'_, K>>,
) -> Result<DescriptorMinimal<K>> {
    let fitting = super::weierstrass::fitting_split(sys)?;
    if let Some(r) = rec.as_deref_mut() {
        super::standard_steps::fitting(r, &fitting);
    }
    let split_exact = fitting.decoupled;
    let split = super::weierstrass::from_fitting(sys, fitting)?;
    let fld = sys.a.field().clone();
    let fin_min = minimal_kalman(&split.finite)?;
    let fin_verified = fin_min.verified;
    let fin = fin_min.system;
    let poly = split.polynomial_part();
    let q = poly.len() - 1;
    let tri =
        StateSpace::new_strictly_proper(split.n.clone(), split.b_inf.clone(), split.c_inf.clone())?;
    let red = minimal_kalman(&tri)?.system;
    if let Some(r) = rec.as_deref_mut() {
        steps::finite(r, &split.finite, &fin, fin_verified);
        steps::infinite(r, &tri, &red, q);
    }
    let nr = red.nstates();
    let irreducible = Descriptor::new(
        -&red.a,
        Matrix::identity(fld, nr),
        -&red.b,
        red.c.clone(),
        split.d.clone(),
    )?;
    let (mut inf, _) = remove_nondynamic(&irreducible)?;
    // the same order with D = P_0 (the constant of the polynomial part) when it exists
    let shifted = shifted_sequence(&split.n, &split.b_inf, &split.c_inf, &poly[0])?;
    let took_shifted = shifted.nstates() == inf.nstates();
    if took_shifted {
        inf = shifted;
    }
    if let Some(r) = rec.as_deref_mut() {
        steps::nondynamic(r, &irreducible, &inf, took_shifted);
    }
    let system = assemble(&fin, &inf)?;
    // G = G_split (the split's identities) = G_fin + G_inf (Markov parameters of the finite
    // parts, Taylor coefficients of the small infinite parts): the module docs
    let verified = split_exact
        && fin_verified
        && same_transfer(&infinite_descriptor(&split)?, &inf)
        && is_controllable(&fin.a, &fin.b)
        && is_observable(&fin.a, &fin.c)
        && is_minimal_at_infinity(&system);
    let out = DescriptorMinimal {
        order: system.nstates(),
        finite_order: fin.nstates(),
        infinite_order: inf.nstates(),
        irreducible_order: fin.nstates() + nr,
        original_order: sys.nstates(),
        polynomial_degree: q,
        system,
        verified,
    };
    if let Some(r) = rec {
        steps::assembled(r, &out);
    }
    Ok(out)
}
