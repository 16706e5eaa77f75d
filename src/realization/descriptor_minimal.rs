//! Minimal and irreducible descriptor realizations, improper systems included.
//!
//! From the Weierstrass split ([`weierstrass_split`]) $G(s) = G_f(s) + P(s)$ with $G_f$
//! strictly proper (finite part) and $P(s) = \sum_{k=0}^q P_ks^k$:
//!
//! * finite part: a minimal realization $(A_m, B_m, C_m)$ of $G_f$ (Kalman);
//! * infinite part: $P(s) - P_0 = \sum_{k \ge 1} P_ks^k = C_\infty(sN - I)^{-1}B_\infty +
//!   \mathrm{const}$ needs $-C_\infty N^kB_\infty = P_k$ ($k \ge 1$); a minimal
//!   realization $(N_m, B_z, C_z)$ of the Markov sequence $(0, P_1, \dots, P_q)$ (nilpotent,
//!   order = rank of its block Hankel matrix, i.e. $\sum_i(\mu_i + 1)$ over the poles at
//!   infinity of orders $\mu_i$) gives $E_\infty = N_m$, $A_\infty = I$, $B_\infty = B_z$,
//!   $C_\infty = -C_z$, and $D = P_0$.
//!
//! The result $E = \mathrm{diag}(I, N_m)$, $A = \mathrm{diag}(A_m, I)$ is minimal: it is
//! controllable and observable at every finite $\lambda$ and at infinity
//! ($\mathrm{rank}[E, B] = \mathrm{rank}[E; C] = n$) and has no non-dynamic modes
//! ($A\ker E \subseteq \mathrm{im}\,E$), the characterization of least order
//! (Verghese–Lévy–Kailath 1981); all five conditions and the equality of the transfer
//! matrices are checked exactly. The *irreducible* order keeps the non-dynamic modes: the
//! minimal order of the finite part plus the McMillan degree of the sequence
//! $C_\infty N^kB_\infty$, $k \ge 0$ (SLICOT TG01JD, DescriptorSystems.jl `gir`).

use super::controllability::{is_controllable, is_observable, mcmillan_degree};
use super::minimal::minimal_kalman;
use super::weierstrass::{WeierstrassSplit, same_transfer, weierstrass_split};
use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::{Descriptor, StateSpace};

/// A minimal descriptor realization with its exact checks.
#[derive(Clone, Debug)]
pub struct DescriptorMinimal<K: Field> {
    pub system: Descriptor<K>,
    /// Order of the minimal realization ($n_f + n_\infty$).
    pub order: usize,
    /// Finite (McMillan degree of the strictly proper part) and infinite parts of `order`.
    pub finite_order: usize,
    pub infinite_order: usize,
    /// Order of an irreducible realization of the original (non-dynamic modes kept).
    pub irreducible_order: usize,
    pub original_order: usize,
    /// Degree $q$ of the polynomial part (0: proper).
    pub polynomial_degree: usize,
    /// Same transfer matrix, finite and infinite controllability and observability, no
    /// non-dynamic modes: checked exactly.
    pub verified: bool,
}

/// A descriptor system as a whole: $E = \mathrm{diag}$ of the parts.
fn assemble<K: Field>(
    fin: &StateSpace<K>,
    e_inf: &Matrix<K>,
    b_inf: &Matrix<K>,
    c_inf: &Matrix<K>,
    d: &Matrix<K>,
) -> Result<Descriptor<K>> {
    let fld = d.field().clone();
    let (nf, ni) = (fin.nstates(), e_inf.nrows());
    let e = Matrix::block_diag(
        fld.clone(),
        &[Matrix::identity(fld.clone(), nf), e_inf.clone()],
    );
    let a = Matrix::block_diag(
        fld.clone(),
        &[fin.a.clone(), Matrix::identity(fld.clone(), ni)],
    );
    Descriptor::new(e, a, fin.b.vstack(b_inf)?, fin.c.hstack(c_inf)?, d.clone())
}

/// Minimal descriptor realization of a regular descriptor system (proper or not).
///
/// # Errors
/// `Invalid` for a singular pencil.
pub fn minimal_descriptor<K: Field>(sys: &Descriptor<K>) -> Result<DescriptorMinimal<K>> {
    let split = weierstrass_split(sys)?;
    let fld = sys.a.field().clone();
    let (p, m) = sys.d.shape();
    let fin = minimal_kalman(&split.finite)?.system;
    let poly = split.polynomial_part();
    let q = poly.len() - 1;
    // Markov sequence (0, P_1, .., P_q) as the system w' = u, x' = -N x - N B w, y = [C 0]
    let ni = split.n.nrows();
    let z = Matrix::zeros(fld.clone(), m, ni);
    let nb = -&(&split.n * &split.b_inf);
    let a_aug = Matrix::block(
        fld.clone(),
        &[
            vec![&-&split.n, &nb],
            vec![&z, &Matrix::zeros(fld.clone(), m, m)],
        ],
    )?;
    let b_aug = Matrix::zeros(fld.clone(), ni, m).vstack(&Matrix::identity(fld.clone(), m))?;
    let c_aug = split.c_inf.hstack(&Matrix::zeros(fld.clone(), p, m))?;
    let inf = minimal_kalman(&StateSpace::new_strictly_proper(a_aug, b_aug, c_aug)?)?.system;
    let system = assemble(&fin, &inf.a, &inf.b, &-&inf.c, &poly[0])?;
    let irreducible_order = fin.nstates() + infinite_irreducible_order(&split)?;
    let verified = same_transfer(sys, &system)
        && is_controllable(&fin.a, &fin.b)
        && is_observable(&fin.a, &fin.c)
        && is_minimal_at_infinity(&system);
    Ok(DescriptorMinimal {
        order: system.nstates(),
        finite_order: fin.nstates(),
        infinite_order: inf.nstates(),
        irreducible_order,
        original_order: sys.nstates(),
        polynomial_degree: q,
        system,
        verified,
    })
}

/// McMillan degree of $C_\infty N^kB_\infty$, $k \ge 0$ (the controllable and observable
/// part of the infinite triple).
fn infinite_irreducible_order<K: Field>(split: &WeierstrassSplit<K>) -> Result<usize> {
    let tri =
        StateSpace::new_strictly_proper(split.n.clone(), split.b_inf.clone(), split.c_inf.clone())?;
    Ok(mcmillan_degree(&tri))
}

/// $\mathrm{rank}[E, B] = n$, $\mathrm{rank}[E; C] = n$, $A\ker E \subseteq \mathrm{im}\,E$.
pub fn is_minimal_at_infinity<K: Field>(sys: &Descriptor<K>) -> bool {
    let n = sys.nstates();
    let re = sys.e.rank();
    let akere = &sys.a * &sys.e.nullspace();
    sys.e.hstack(&sys.b).is_ok_and(|x| x.rank() == n)
        && sys.e.vstack(&sys.c).is_ok_and(|x| x.rank() == n)
        && sys.e.hstack(&akere).is_ok_and(|x| x.rank() == re)
}
