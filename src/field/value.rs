//! Field elements as plain structured values ([`ElemValue`]): what an element IS (a rational,
//! $a + b\sqrt d$, $x + y i$, a polynomial in a marked generator $t$ of $F\[t\]/(g)$, a
//! quotient of integer polynomials in named parameters), never its display text. Bindings
//! (the Python package) rebuild every exact value from these, so no display is parsed back
//! (issue 23 item 4: values in math, strings in `report/`).
//!
//! Identity: for every field `k` and element `x`, the value of [`Field::elem_value`]`(x)`
//! evaluates, in the field it names, to `x` (tests: `tests/elem_values.rs`).

use super::{Field, Rational};
use num_bigint::BigInt;

/// Terms of an integer polynomial in named parameters: (exponent of each parameter, in the
/// order of the parameter names; integer coefficient).
pub type Terms = Vec<(Vec<u32>, BigInt)>;

/// One field element as a structured value (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub enum ElemValue {
    /// A rational number.
    Rational(Rational),
    /// $a + b\sqrt d$ in $\mathbb{Q}(\sqrt d)$ ($d = -1$: $\mathbb{Q}(i)$).
    Quadratic { a: Rational, b: Rational, d: BigInt },
    /// $x + y\,i$ over a real field.
    Complex {
        re: Box<ElemValue>,
        im: Box<ElemValue>,
    },
    /// $\sum_k c_k t^k$ with $t$ the marked root of [`Generator::modulus`].
    Ext {
        coeffs: Vec<ElemValue>,
        generator: Box<Generator>,
    },
    /// `num / den` in $\mathbb{Q}(p_1, \dots, p_k)$, integer polynomials in `vars`.
    RatFunc {
        vars: Vec<String>,
        num: Terms,
        den: Terms,
    },
}

/// The generator $t$ of an extension $F\[t\]/(g)$, marked at one root of $g$.
#[derive(Clone, Debug, PartialEq)]
pub struct Generator {
    /// Coefficients of the monic modulus $g$, low degree first (values of the base field).
    pub modulus: Vec<ElemValue>,
    /// Approximation `(re, im)` of the marked root (certified to about $2^{-60}$ relative;
    /// it tells the root among those of $g$).
    pub root: (f64, f64),
    /// Its display name (`r3`, `sqrt(2)`, `i`, `t`).
    pub name: String,
    /// $t = a_0 + s\sqrt f$ when the field knows its radical form.
    pub radical: Option<(Rational, Rational, BigInt)>,
}

/// The value of an element of any field whose elements are rational (a field without its
/// own [`Field::elem_value`]).
pub(crate) fn rational_or_none<K: Field>(k: &K, x: &K::Elem) -> Option<ElemValue> {
    k.to_rational(x).map(ElemValue::Rational)
}
