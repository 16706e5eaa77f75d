//! Reports of `poly factor` and `poly roots`.

use crate::field::Q;
use crate::poly::Poly;
use crate::report::{Report, Value};

/// The `poly factor` report: `content` (leading coefficient, exact) and `factors[]` of
/// `{poly, multiplicity}` (monic irreducible over Q).
///
/// # Errors
/// As [`crate::algebraic::factor_q`].
pub fn factor_report(p: &Poly<Q>) -> crate::Result<Report> {
    let (lc, facs) = crate::algebraic::factor_q(p)?;
    let items = facs
        .iter()
        .map(|(f, e)| {
            Value::Obj(
                Report::new()
                    .str("poly", f.to_string())
                    .int("multiplicity", *e),
            )
        })
        .collect();
    Ok(Report::titled("factorization over QQ")
        .str("input", p.to_string())
        .rational("content", &lc)
        .list("factors", items))
}

/// The `poly roots` report: `roots[]` of `{minpoly, value, approx: [re, im], multiplicity,
/// digits: [re, im]}` with `digits` correct significant digits (default use: 10).
///
/// # Errors
/// As [`crate::algebraic::roots`].
pub fn roots_report(p: &Poly<Q>, digits: usize) -> crate::Result<Report> {
    let rs = crate::algebraic::roots(p)?;
    let items = rs
        .iter()
        .map(|(r, e)| {
            let (re, im) = r.approx();
            let (dre, dim) = r.digits(digits);
            Value::Obj(
                Report::new()
                    .str("minpoly", r.minpoly().to_string())
                    .str("value", r.value_string())
                    .list("approx", vec![Value::Float(re), Value::Float(im)])
                    .int("multiplicity", *e)
                    .list("digits", vec![Value::Str(dre), Value::Str(dim)]),
            )
        })
        .collect();
    Ok(Report::titled("roots")
        .str("input", p.to_string())
        .int("degree", p.deg())
        .list("roots", items))
}
