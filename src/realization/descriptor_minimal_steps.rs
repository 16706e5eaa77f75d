//! The steps of a minimal descriptor realization (`minreal --descriptor --steps`), recorded
//! by [`super::descriptor_minimal::minimal_descriptor_recorded`] with the objects the
//! algorithm computes, each with its identity checked exactly:
//!
//! * the finite part: $C_f A_f^k B_f = C_m A_m^k B_m$ for $k < n_f + n_m$ (equal strictly
//!   proper transfer matrices), $(A_m, B_m)$ controllable, $(A_m, C_m)$ observable;
//! * the infinite part: $C_\infty N^k B_\infty = C_r N_r^k B_r$ for $k < n_\infty + n_r$ (the
//!   same polynomial part $\sum_k (-s)^k C_\infty N^k B_\infty$) and $N_r^{n_r} = 0$;
//! * the non-dynamic modes removed: the same transfer matrix, $\operatorname{rank}[E, B] =
//!   \operatorname{rank}[E; C] = n$, $A \ker E \subseteq \operatorname{im} E$;
//! * the assembled realization: the input's transfer matrix, finite part minimal, minimal at
//!   infinity.

use super::descriptor_minimal_result::{DescriptorMinimal, is_minimal_at_infinity};
use super::weierstrass::same_transfer;
use crate::field::Field;
use crate::jordan::derivation::{Object, Recorder, StepKind};
use crate::matrix::Matrix;
use crate::system::{Descriptor, StateSpace};

fn mat<K: Field>(m: &Matrix<K>) -> Object<K> {
    Object::Matrix(m.clone())
}

/// The finite part `full` and its minimal part `min`; `ok` is the Kalman realization's own
/// check of exactly these identities ([`super::minimal::verify_minimal`]: Markov parameters
/// for $k < n_f + n_m$, controllable, observable), not computed a second time (over
/// $\mathbb{Q}(p)$ with many parameters the Markov parameters are the costly part).
pub(crate) fn finite<K: Field>(
    rec: &mut Recorder<'_, K>,
    full: &StateSpace<K>,
    min: &StateSpace<K>,
    ok: bool,
) {
    rec.push(
        StepKind::DescriptorFinite,
        None,
        vec![
            ("Af", mat(&full.a)),
            ("Bf", mat(&full.b)),
            ("Cf", mat(&full.c)),
            ("Am", mat(&min.a)),
            ("Bm", mat(&min.b)),
            ("Cm", mat(&min.c)),
            ("order", Object::Count(min.nstates())),
        ],
        Some(ok),
    );
}

/// The infinite part $(N, B_\infty, C_\infty)$ as `tri` and its minimal realization `red`;
/// `q` the degree of the polynomial part.
pub(crate) fn infinite<K: Field>(
    rec: &mut Recorder<'_, K>,
    tri: &StateSpace<K>,
    red: &StateSpace<K>,
    q: usize,
) {
    let k = tri.nstates() + red.nstates();
    let nr = red.nstates();
    let nilpotent = nr == 0 || red.a.pow(nr as u32).is_ok_and(|p| p.is_zero());
    let ok = tri.markov(k) == red.markov(k) && nilpotent;
    rec.push(
        StepKind::DescriptorInfinite,
        None,
        vec![
            ("N", mat(&tri.a)),
            ("Binf", mat(&tri.b)),
            ("Cinf", mat(&tri.c)),
            ("Nr", mat(&red.a)),
            ("Br", mat(&red.b)),
            ("Cr", mat(&red.c)),
            ("order", Object::Count(nr)),
            ("q", Object::Count(q)),
        ],
        Some(ok),
    );
}

/// The irreducible infinite part and `inf`, the part kept (`shifted`: the realization of
/// the shifted sequence with $D = P_0$).
pub(crate) fn nondynamic<K: Field>(
    rec: &mut Recorder<'_, K>,
    irreducible: &Descriptor<K>,
    inf: &Descriptor<K>,
    shifted: bool,
) {
    let ok = same_transfer(irreducible, inf) && is_minimal_at_infinity(inf);
    rec.push(
        StepKind::DescriptorNondynamic,
        None,
        vec![
            (
                "removed",
                Object::Count(irreducible.nstates().saturating_sub(inf.nstates())),
            ),
            ("order", Object::Count(inf.nstates())),
            ("shifted", Object::Count(usize::from(shifted))),
            ("E", mat(&inf.e)),
            ("A", mat(&inf.a)),
            ("B", mat(&inf.b)),
            ("C", mat(&inf.c)),
            ("D", mat(&inf.d)),
        ],
        Some(ok),
    );
}

/// The assembled minimal realization (its checks: [`DescriptorMinimal::verified`]).
pub(crate) fn assembled<K: Field>(rec: &mut Recorder<'_, K>, m: &DescriptorMinimal<K>) {
    let s = &m.system;
    rec.push(
        StepKind::DescriptorMinimalForm,
        None,
        vec![
            ("E", mat(&s.e)),
            ("A", mat(&s.a)),
            ("B", mat(&s.b)),
            ("C", mat(&s.c)),
            ("D", mat(&s.d)),
            (
                "orders",
                Object::Counts(vec![
                    m.original_order,
                    m.irreducible_order,
                    m.order,
                    m.finite_order,
                    m.infinite_order,
                ]),
            ),
        ],
        Some(m.verified),
    );
}
