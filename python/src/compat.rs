//! Typed loading through the library's own loader (`exactlti::io::load`), so a system
//! built from Python is read and typed exactly as the same data in a file given to the
//! command line (same one-line messages).

use exactlti::field::{Q, QuadraticField};
use exactlti::io::{LoadedSystem, TypedAny, TypedSystem};
use exactlti::ratfunc::RatFuncField;

/// A system over its ground field, as given and in standard form.
pub type Typed<K> = TypedSystem<K>;

/// A typed system over one of the supported ground fields.
#[allow(clippy::large_enum_variant)]
pub enum Loaded {
    Q(String, Typed<Q>),
    Quadratic(String, Typed<QuadraticField>),
    Sym(String, Typed<RatFuncField>),
}

/// The loaded system over its field; `Err` for a ground field this layer does not know.
pub fn from_loaded(l: LoadedSystem) -> Result<Loaded, String> {
    let g = l.file.ground.to_string();
    match l.system {
        TypedAny::Rational(t) => Ok(Loaded::Q(g, t)),
        TypedAny::Quadratic(t) => Ok(Loaded::Quadratic(g, t)),
        TypedAny::RatFunc(t) => Ok(Loaded::Sym(g, t)),
        #[allow(unreachable_patterns)]
        _ => Err(format!("{}: unsupported: entries in {g}", l.file.path)),
    }
}
