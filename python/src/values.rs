//! Exact values for Python: the encoding the Python layer (`python/exactlti/_values.py`)
//! builds SymPy objects from. No display text is ever parsed back: every exact number
//! crosses as its structure ([`exactlti::field::ElemValue`], made by the library's
//! `Field::elem_value`), displays travel beside it only to be shown.
//!
//! | value | Python encoding |
//! |---|---|
//! | rational $p/q$ | `(p, q)` (two ints, lowest terms, $q > 0$) |
//! | $a + b\sqrt d$ | `("sqrt", a, b, d)` (`a`, `b` rationals, `d` an int; $d = -1$: $\mathbb{Q}(i)$) |
//! | $x + y i$ over a real field | `("i", x, y)` |
//! | $\sum_k c_k t^k$, $t$ a marked root of $g$ | `("ext", [c_0, c_1, ...], gen)` |
//! | generator $t$ | `("gen", [g_0, ..., g_d], (re, im), name, radical)`: monic $g$ low degree first, an approximation of the marked root (about $2^{-60}$ relative: it tells the root among those of $g$), the display name, and `(a0, s, f)` when $t = a_0 + s\sqrt f$, else `None` |
//! | `num/den` in $\mathbb{Q}(p_1..p_k)$ | `("rf", (p_1, ..., p_k), num, den)` |
//! | integer polynomial in named variables | list of terms `((e_1, ..., e_k), c)` |
//! | polynomial in one variable | list of coefficient values, low degree first |
//! | algebraic number | `minpoly` (rationals, low degree first) and `box`: `((re_lo, re_hi), (im_lo, im_hi))`, a rational rectangle isolating the root |
//! | Re / Im of an element (compact real forms) | `("re", v)`, `("im", v)`; $-v$: `("neg", v)` |
//!
//! The identity the Python tests check: the SymPy value built from the encoding equals the
//! element (`python/tests/test_values.py`: $\sqrt 2$ eigenvalues, symbolic transfer
//! functions, conditions built independently in SymPy).

use crate::out::{Out, int, q};
use exactlti::field::{ElemValue, Field};
use exactlti::matrix::Matrix;
use exactlti::mpoly::MPoly;
use exactlti::poly::Poly;

/// One element's value (`None` for a field that does not describe its elements).
pub(crate) fn elem<K: Field>(k: &K, x: &K::Elem) -> Out {
    k.elem_value(x).as_ref().map(value).unwrap_or(Out::None)
}

/// The encoding of an [`ElemValue`] (module table).
pub(crate) fn value(v: &ElemValue) -> Out {
    match v {
        ElemValue::Rational(r) => q(r),
        ElemValue::Quadratic { a, b, d } => {
            Out::Tuple(vec![Out::Str("sqrt".into()), q(a), q(b), int(d)])
        }
        ElemValue::Complex { re, im } => {
            Out::Tuple(vec![Out::Str("i".into()), value(re), value(im)])
        }
        ElemValue::Ext {
            coeffs,
            generator: g,
        } => Out::Tuple(vec![
            Out::Str("ext".into()),
            Out::List(coeffs.iter().map(value).collect()),
            Out::Tuple(vec![
                Out::Str("gen".into()),
                Out::List(g.modulus.iter().map(value).collect()),
                Out::Tuple(vec![Out::Float(g.root.0), Out::Float(g.root.1)]),
                Out::Str(g.name.clone()),
                g.radical
                    .as_ref()
                    .map(|(a0, s, f)| Out::Tuple(vec![q(a0), q(s), int(f)]))
                    .unwrap_or(Out::None),
            ]),
        ]),
        ElemValue::RatFunc { vars, num, den } => Out::Tuple(vec![
            Out::Str("rf".into()),
            Out::Tuple(vars.iter().map(|v| Out::Str(v.clone())).collect()),
            term_list(num),
            term_list(den),
        ]),
    }
}

fn term_list(t: &[(Vec<u32>, num_bigint::BigInt)]) -> Out {
    Out::List(
        t.iter()
            .map(|(e, c)| {
                Out::Tuple(vec![
                    Out::Tuple(e.iter().map(|&x| Out::Int(x as i64)).collect()),
                    int(c),
                ])
            })
            .collect(),
    )
}

/// An integer polynomial in named variables as its terms.
pub(crate) fn terms(p: &MPoly) -> Out {
    term_list(&exactlti::ratfunc::exp_terms(p))
}

/// The rows of a matrix as element values.
pub(crate) fn rows<K: Field>(m: &Matrix<K>) -> Out {
    let k = m.field();
    Out::List(
        (0..m.nrows())
            .map(|i| Out::List(m.row(i).iter().map(|x| elem(k, x)).collect()))
            .collect(),
    )
}

/// The coefficients of a polynomial as element values, low degree first.
pub(crate) fn coeffs<K: Field>(p: &Poly<K>) -> Out {
    let k = p.field();
    Out::List(p.coeffs().iter().map(|c| elem(k, c)).collect())
}

/// A grid of values (a matrix assembled block by block), zeros first.
pub(crate) struct Grid(pub Vec<Vec<Out>>);

impl Grid {
    pub(crate) fn zeros(n: usize, m: usize) -> Self {
        Grid((0..n).map(|_| (0..m).map(|_| zero()).collect()).collect())
    }
    /// Writes the values of `b` with its top-left corner at `at`.
    pub(crate) fn block<K: Field>(&mut self, at: (usize, usize), b: &Matrix<K>) {
        let k = b.field();
        for i in 0..b.nrows() {
            for j in 0..b.ncols() {
                self.0[at.0 + i][at.1 + j] = elem(k, b.get(i, j));
            }
        }
    }
    pub(crate) fn set(&mut self, at: (usize, usize), v: Out) {
        self.0[at.0][at.1] = v;
    }
    pub(crate) fn out(self) -> Out {
        Out::List(self.0.into_iter().map(Out::List).collect())
    }
}

/// The rational zero.
pub(crate) fn zero() -> Out {
    Out::Tuple(vec![Out::Int(0), Out::Int(1)])
}

/// `("re", v)` or `("im", v)`, negated when `neg` (compact real forms).
pub(crate) fn part(v: Out, imag: bool, neg: bool) -> Out {
    let p = Out::Tuple(vec![Out::Str(if imag { "im" } else { "re" }.into()), v]);
    if neg {
        Out::Tuple(vec![Out::Str("neg".into()), p])
    } else {
        p
    }
}

/// The values a report's matrix carries ([`exactlti::report::MatrixOut::values`]); `None`
/// where an entry is shown by text only, and when the report made none.
pub(crate) fn values_of(mo: &exactlti::report::MatrixOut) -> Out {
    if mo.values.is_empty() {
        return Out::None;
    }
    Out::List(
        mo.values
            .iter()
            .map(|r| {
                Out::List(
                    r.iter()
                        .map(|v| v.as_ref().map(value).unwrap_or(Out::None))
                        .collect(),
                )
            })
            .collect(),
    )
}

/// The values of every matrix at the top level of a report, by key (`Report.to_sympy`).
pub(crate) fn report_values(r: &exactlti::report::Report) -> Out {
    Out::Map(
        r.items
            .iter()
            .filter_map(|(k, v)| match v {
                exactlti::report::Value::Matrix(mo) if !mo.values.is_empty() => {
                    Some((k.clone(), values_of(mo)))
                }
                _ => None,
            })
            .collect(),
    )
}
