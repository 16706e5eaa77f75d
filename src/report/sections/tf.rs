//! `tf`: one report for every ground field ($\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$,
//! $\mathbb{Q}(i)$, $\mathbb{Q}(p)$), written once over [`GroundField`]: the transfer matrix in lowest terms,
//! its zero-pole-gain display, the McMillan degree, and the poles and transmission zeros as
//! the irreducible factors over the field of the pole and zero polynomials
//! ([`crate::jordan::EigenField::eigen_factors`]: each factor with the minimal polynomial over $\mathbb{Q}$
//! of its roots and their certified values); over $\mathbb{Q}(p)$ the factors over
//! $\mathbb{Q}(p)$, the roots of linear factors as formulas ([`root_items`]).
//!
//! # Verification
//! `verified` is the conjunction of: the minimal realization's checks
//! ([`TransferRealization::verified`]), the zero pencil's checks, the product of the pole
//! (zero) factors equals the pole (zero) polynomial (the pole polynomial is the
//! characteristic polynomial of the minimal realization's finite block), and, for a
//! state-space input, `markov` (the Markov parameters of the transfer matrix equal
//! $D, CB, CAB, \dots$ of the input system).

use crate::error::{Error, Result};
use crate::field::Field;
use crate::io::{GroundField, NumericField};
use crate::poly::Poly;
use crate::realization::TransferRealization;
use crate::report::{Report, Value};
use crate::system::discrete::stability::Domain;
use crate::system::transfer::TransferMatrix;

fn approx(a: (f64, f64)) -> Value {
    Value::List(vec![Value::Float(a.0), Value::Float(a.1)])
}

/// The root of an irreducible factor as a report `value`: exact for a linear factor, else
/// `a root of f` (in `var`).
fn root_value<K: Field>(f: &Poly<K>, var: &str) -> Result<String> {
    if f.deg() != 1 {
        return Ok(format!("a root of {}", f.to_string_var(var)));
    }
    let k = f.field();
    let root = k
        .div(&f.coeff(0), &f.coeff(1))
        .ok_or(Error::DivisionByZero)?;
    Ok(k.fmt_elem(&k.neg(&root)))
}

/// Whether $\operatorname{lc}(p) \prod f^e = p$ for the factors `fs`.
fn is_product<'a, K: Field + 'a>(
    p: &Poly<K>,
    fs: impl IntoIterator<Item = (&'a Poly<K>, usize)>,
) -> bool {
    let mut prod = Poly::new(p.field().clone(), vec![p.lc()]);
    for (f, e) in fs {
        for _ in 0..e {
            prod = prod.mul(f);
        }
    }
    prod == *p
}

/// One report item per irreducible factor $f$ over the field of `p`: `factor` (monic, in
/// `var`), `degree`, `minpoly` (over $\mathbb{Q}$, of the factor's roots), `value` and
/// `approx` (the exact root of a linear factor; `a root of f` otherwise, with `roots`: each
/// certified root as `{value, approx}`), `algebraic_multiplicity`. Returns the items and
/// whether the product of the factors is `p` up to its leading coefficient.
///
/// # Errors
/// From the factorization and root isolation.
pub fn factor_items<F: NumericField>(p: &Poly<F>, var: &str) -> Result<(Vec<Value>, bool)> {
    if p.is_zero() || p.deg() == 0 {
        return Ok((vec![], true));
    }
    let factors = F::eigen_factors(&p.monic())?;
    let mut items = vec![];
    for (f, e, minpoly, roots) in &factors {
        let mut r = Report::new()
            .str("factor", f.to_string_var(var))
            .int("degree", f.deg())
            .str("minpoly", minpoly.to_string())
            .str("value", root_value(f, var)?);
        if f.deg() == 1 {
            let a = roots.first().map_or((f64::NAN, f64::NAN), |z| z.1);
            r = r.with("approx", approx(a));
        } else {
            r = r.list(
                "roots",
                roots
                    .iter()
                    .map(|(z, a)| {
                        Value::Obj(
                            Report::new()
                                .str("value", z.value_string())
                                .with("approx", approx(*a)),
                        )
                    })
                    .collect(),
            );
        }
        items.push(Value::Obj(r.int("algebraic_multiplicity", *e)));
    }
    let ok = is_product(p, factors.iter().map(|(f, e, _, _)| (f, *e)));
    Ok((items, ok))
}

/// The roots of `p` as report items: over a numeric field [`factor_items`]; over
/// $\mathbb{Q}(p)$ one item per irreducible factor over the field ([`GroundField::factors`]):
/// `factor`, `degree`, `value` (the root as a formula for a linear factor, else `a root of
/// f`) and `algebraic_multiplicity`. Returns the items and whether the product of the
/// factors is `p` up to its leading coefficient.
///
/// # Errors
/// From the factorization and root isolation.
pub fn root_items<K: GroundField>(p: &Poly<K>, var: &str) -> Result<(Vec<Value>, bool)> {
    if let Some(pn) = K::numeric_poly(p) {
        return factor_items(pn, var);
    }
    if p.is_zero() || p.deg() == 0 {
        return Ok((vec![], true));
    }
    let fs = match K::factors(p) {
        Some(fs) => fs?,
        None => vec![(p.monic(), 1)],
    };
    let mut items = vec![];
    for (f, e) in &fs {
        items.push(Value::Obj(
            Report::new()
                .str("factor", f.to_string_var(var))
                .int("degree", f.deg())
                .str("value", root_value(f, var)?)
                .int("algebraic_multiplicity", *e),
        ));
    }
    Ok((items, is_product(p, fs.iter().map(|(f, e)| (f, *e)))))
}

/// Zero-pole-gain display of one rational function over the field in the variable `var`:
/// `k (factors) / (factors)` with the monic irreducible factors over the field
/// ([`GroundField::factors`]), assembled by [`zpk_text`]; a field that does
/// not factor keeps the polynomials whole.
///
/// # Errors
/// From the factorization.
pub fn zpk_string<K: GroundField>(num: &Poly<K>, den: &Poly<K>, var: &str) -> Result<String> {
    if num.is_zero() {
        return Ok("0".into());
    }
    let k = num.field().clone();
    let gain = k.fmt_elem(&k.div(&num.lc(), &den.lc()).ok_or(Error::DivisionByZero)?);
    let factors = |p: &Poly<K>| -> Result<Vec<(String, usize)>> {
        if p.deg() == 0 {
            return Ok(Vec::new());
        }
        Ok(match K::factors(p) {
            Some(fs) => fs?
                .iter()
                .map(|(f, e)| (f.monic().to_string_var(var), *e))
                .collect(),
            None => vec![(p.monic().to_string_var(var), 1)],
        })
    };
    Ok(zpk_text(&gain, &factors(num)?, &factors(den)?))
}

/// `tf` over a numeric ground field, in the variable of `domain`: `field`, `variable`,
/// `transfer_matrix`, `zpk`, `mcmillan_degree`, `infinite_pole_degree`, `pole_polynomial`,
/// `poles` and `transmission_zeros` ([`factor_items`]), `infinite_zero_orders`,
/// `normal_rank`, `order`, `markov_verified` (when `markov` is given: the input was a
/// state-space system whose Markov parameters were compared with `g`'s) and `verified`
/// (module docs).
///
/// # Errors
/// From the factorizations and the zero pencil.
pub fn tf_report<K: GroundField>(
    g: &TransferMatrix<K>,
    r: &TransferRealization<K>,
    markov: Option<bool>,
    domain: Domain,
) -> Result<Report> {
    let sys = &r.minimal.system;
    let var = domain.var();
    let k = r.minimal.system.a.field().clone();
    let nf = r.minimal.finite_order;
    let pole_poly = sys.a.submatrix(0, nf, 0, nf).charpoly()?;
    let (poles, poles_ok) = root_items(&pole_poly, var)?;
    let zeros = crate::structure::descriptor_zeros::descriptor_zeros(sys)?;
    let (tzeros, zeros_ok) = root_items(&zeros.polynomial, var)?;
    let (tm, zpk) = transfer_lists(g, var, zpk_string::<K>)?;
    let ints = |v: &[usize]| Value::List(v.iter().map(|&x| Value::Int(x as i64)).collect());
    let mut rep = Report::titled("transfer matrix")
        .str("field", k.to_string())
        .with("variable", super::variable(domain))
        .list("transfer_matrix", tm)
        .list("zpk", zpk)
        .int("mcmillan_degree", r.mcmillan_degree)
        .int("infinite_pole_degree", r.mcmillan_degree - nf)
        .str("pole_polynomial", pole_poly.to_string_var(var))
        .list("poles", poles)
        .list("transmission_zeros", tzeros)
        .with("infinite_zero_orders", ints(&zeros.infinite_zero_orders))
        .int("normal_rank", zeros.pencil.normal_rank - sys.nstates())
        .int("order", r.minimal.order);
    if let Some(m) = markov {
        rep = rep.bool("markov_verified", m);
    }
    Ok(rep.bool(
        "verified",
        r.verified && zeros.pencil.verified && poles_ok && zeros_ok && markov.unwrap_or(true),
    ))
}

/// The `transfer_matrix` and `zpk` lists of a `tf` report (rows of entries) in the
/// variable `var`, the latter with the field's zero-pole-gain display `zpk`.
///
/// # Errors
/// From `zpk` (a factorization).
fn transfer_lists<K: Field>(
    g: &TransferMatrix<K>,
    var: &str,
    zpk: impl Fn(&Poly<K>, &Poly<K>, &str) -> Result<String>,
) -> Result<(Vec<Value>, Vec<Value>)> {
    let zpk = g
        .entries
        .iter()
        .map(|row| {
            Ok(Value::List(
                row.iter()
                    .map(|f| zpk(&f.num, &f.den, var).map(Value::Str))
                    .collect::<Result<Vec<_>>>()?,
            ))
        })
        .collect::<Result<Vec<_>>>()?;
    let tm = g
        .to_strings_var(var)
        .into_iter()
        .map(|row| Value::List(row.into_iter().map(Value::Str).collect()))
        .collect();
    Ok((tm, zpk))
}

/// One line of zero-pole-gain text that reads one way only: the gain (in parentheses when it
/// is a fraction or a sum and factors follow), the numerator factors, and `/` followed by the
/// denominator in parentheses when it has more than one factor: `(-1/1500) / (s (s + 8/3))`,
/// `10 (s + 1) / (s (s^2 + 2*s + 10))`, `2 / (s + 1)^2`. A factor that is a single symbol
/// (`s`) is written bare.
fn zpk_text(gain: &str, num: &[(String, usize)], den: &[(String, usize)]) -> String {
    let factor = |(f, e): &(String, usize)| {
        let f = if f.chars().all(|c| c.is_alphanumeric()) {
            f.clone()
        } else {
            format!("({f})")
        };
        if *e > 1 { format!("{f}^{e}") } else { f }
    };
    let product = |fs: &[(String, usize)]| fs.iter().map(factor).collect::<Vec<_>>().join(" ");
    let compound = gain.contains(['/', ' ', '+']) || gain.get(1..).unwrap_or("").contains('-');
    let mut s = if compound && !(num.is_empty() && den.is_empty()) {
        format!("({gain})")
    } else {
        gain.to_string()
    };
    if !num.is_empty() {
        s = format!("{s} {}", product(num));
    }
    if !den.is_empty() {
        let d = product(den);
        s = if den.len() > 1 {
            format!("{s} / ({d})")
        } else {
            format!("{s} / {d}")
        };
    }
    s
}

#[cfg(test)]
mod zpk_tests {
    use super::zpk_text;
    fn f(s: &str, e: usize) -> (String, usize) {
        (s.to_string(), e)
    }
    #[test]
    fn zpk_text_reads_one_way() {
        assert_eq!(
            zpk_text("-1/1500", &[], &[f("s", 1), f("s + 8/3", 1)]),
            "(-1/1500) / (s (s + 8/3))"
        );
        assert_eq!(
            zpk_text("10", &[f("s + 1", 1)], &[f("s", 1), f("s^2 + 2*s + 10", 1)]),
            "10 (s + 1) / (s (s^2 + 2*s + 10))"
        );
        assert_eq!(zpk_text("2", &[], &[f("s + 1", 2)]), "2 / (s + 1)^2");
        assert_eq!(zpk_text("-3", &[f("s", 2)], &[]), "-3 s^2");
        assert_eq!(zpk_text("1/2", &[], &[]), "1/2");
        assert_eq!(
            zpk_text("1 + sqrt(2)", &[f("s - 1", 1)], &[]),
            "(1 + sqrt(2)) (s - 1)"
        );
    }
}
