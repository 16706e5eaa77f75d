//! Several system files over one field: the systems of an interconnection (`series`,
//! `feedback`, ...) must live in one field $K$. Files over $\mathbb{Q}$ are lifted into the
//! field of the others ($\mathbb{Q} \subset \mathbb{Q}(\sqrt d)$, $\mathbb{Q} \subset
//! \mathbb{Q}(p_1, \dots, p_k)$); two different quadratic fields, or parameter fields with
//! different symbols, are refused naming the file.
//!
//! [`load_system_or_gain`] also reads a static gain: a file with only `D` (a system without
//! states, $y = D u$).

use super::load::{LoadedSystem, TypedAny, TypedSystem};
use super::raw::{Raw, from_text};
use super::{Ground, InputError, SystemFormat};
use crate::field::{Field, Q, QuadraticField};
use crate::ratfunc::RatFuncField;

/// Systems over one common field.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)]
pub enum CommonSystems {
    Rational(Vec<TypedSystem<Q>>),
    Quadratic(Vec<TypedSystem<QuadraticField>>),
    RatFunc(Vec<TypedSystem<RatFuncField>>),
}

/// Work on several systems, written once for every field `K`.
pub trait SystemsVisitor {
    type Output;
    fn visit<K: super::GroundField>(self, systems: &[TypedSystem<K>]) -> Self::Output;
}

impl CommonSystems {
    /// Runs `v` over the common field.
    pub fn run<V: SystemsVisitor>(&self, v: V) -> V::Output {
        match self {
            CommonSystems::Rational(s) => v.visit(s),
            CommonSystems::Quadratic(s) => v.visit(s),
            CommonSystems::RatFunc(s) => v.visit(s),
        }
    }
}

/// The systems over one field (see the module docs).
///
/// # Errors
/// Files over two different non-rational fields (named by the second file).
pub fn common_field(systems: &[&LoadedSystem]) -> Result<CommonSystems, InputError> {
    let target = systems.iter().find(|s| s.file.ground != Ground::Rational);
    let Some(target) = target else {
        let all = systems
            .iter()
            .filter_map(|s| s.rational().cloned())
            .collect();
        return Ok(CommonSystems::Rational(all));
    };
    for s in systems {
        if s.file.ground != Ground::Rational && s.file.ground != target.file.ground {
            return Err(InputError::file(
                &s.file.path,
                format!(
                    "its entries lie in {} but those of {} in {}: the systems need one field",
                    s.file.ground, target.file.path, target.file.ground
                ),
            ));
        }
    }
    Ok(match &target.system {
        TypedAny::Quadratic(t) => {
            let k = t.ss.field().clone();
            CommonSystems::Quadratic(
                systems
                    .iter()
                    .map(|s| match &s.system {
                        TypedAny::Quadratic(t) => t.clone(),
                        TypedAny::Rational(t) => t.map(&k, &|x| k.from_rational(x)),
                        TypedAny::RatFunc(_) => unreachable!("checked: one field"),
                    })
                    .collect(),
            )
        }
        TypedAny::RatFunc(t) => {
            let k = t.ss.field().fresh();
            CommonSystems::RatFunc(
                systems
                    .iter()
                    .map(|s| match &s.system {
                        TypedAny::RatFunc(t) => t.in_field(&k),
                        TypedAny::Rational(t) => t.map(&k, &|x| k.from_rational(x)),
                        TypedAny::Quadratic(_) => unreachable!("checked: one field"),
                    })
                    .collect(),
            )
        }
        TypedAny::Rational(_) => unreachable!("not rational"),
    })
}

/// A static gain: for a file whose only matrix key is `D`, its text with `A = []` first
/// (the system without states $y = D u$); `None` for any other file (read as it is). The
/// one reader ([`crate::api::System::open_or_gain`]) reads the text this returns.
pub fn gain_text(text: &str, format: SystemFormat, name: &str) -> Option<String> {
    let raw = from_text(text, format, name);
    let gain_only = match &raw {
        Ok(Raw::Table(entries)) => {
            let keys: Vec<&str> = entries.iter().map(|(k, _)| k.as_str()).collect();
            keys.contains(&"D") && !keys.iter().any(|k| SYSTEM_MATRIX_KEYS.contains(k))
        }
        _ => false,
    };
    // `A = []` first: a top-level TOML key before any table, a JSON object's first member
    gain_only.then(|| match format {
        SystemFormat::Toml => format!("A = []\n{text}"),
        SystemFormat::Json => text.replacen('{', "{\"A\": [], ", 1),
    })
}

/// Keys that make a file more than a gain.
const SYSTEM_MATRIX_KEYS: [&str; 9] = ["A", "B", "C", "E", "M", "L", "K", "F", "G"];
