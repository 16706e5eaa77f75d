//! The api's side of [`GroundField`]: the one refusal of a command that needs numbers over
//! a field of symbols ([`needs_numbers`]), used by every command (over $\mathbb{Q}(p)$ by
//! `api::symbolic`, generically by [`numeric`]).

use super::Failure;
use crate::io::{GroundField, TypedSystem};
use std::path::Path;

/// The one refusal of a command that needs numbers over a field of symbols (`what`: the
/// command's name), for every such command over every field without numbers:
/// "`margin` needs numbers (a float computation), this system's entries lie in QQ(m, u);
/// give every symbol a value with --at" (exit 2).
pub(super) fn needs_numbers<K: GroundField>(k: &K, what: &str, path: &Path) -> Failure {
    Failure::unsupported(format!(
        "{}: `{what}` needs numbers (a float computation), this system's entries lie in {k}; give every symbol a value with --at",
        path.display()
    ))
}

/// The system over its numeric field, or the one refusal line ([`needs_numbers`]).
pub(super) fn numeric<'a, K: GroundField>(
    t: &'a TypedSystem<K>,
    what: &str,
    path: &Path,
) -> Result<&'a TypedSystem<K::Numeric>, Failure> {
    K::numeric(t).ok_or_else(|| needs_numbers(t.ss.field(), what, path))
}

/// The exact stability of `a` over its own field for `domain`, written once
/// ([`crate::system::discrete::stability::stability_with`] with the field's factorization,
/// [`GroundField::factors`]).
///
/// # Errors
/// `Unsupported` over a field the crate does not factor in ($\mathbb{Q}(p)$: the signs of
/// rational functions of the parameters are undecided), those of the test.
pub(super) fn stability_over<K: GroundField>(
    a: &crate::matrix::Matrix<K>,
    domain: crate::system::discrete::stability::Domain,
) -> crate::Result<crate::system::discrete::stability::Stability<K>> {
    let undecided = || {
        crate::Error::Unsupported(format!(
            "stability is decided exactly over Q, Q(sqrt d), Q(i); this system is over {} (give every symbol a value with --at)",
            a.field()
        ))
    };
    if a.field().symbolic().is_some() {
        return Err(undecided());
    }
    crate::system::discrete::stability::stability_with(a, domain, |chi| {
        K::factors(chi).unwrap_or_else(|| Err(undecided()))
    })
}
