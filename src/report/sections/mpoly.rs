//! Reports of `poly factor` and `poly gcd` on multivariate input (every identifier is a
//! variable; CLI contract, second wave).

use crate::mpoly::{QPoly, factor::factor_q, gcd};
use crate::report::{Report, Value};

fn vars_value(vars: &[String]) -> Value {
    Value::List(vars.iter().map(|v| Value::Str(v.clone())).collect())
}

/// `poly factor` of a multivariate polynomial: `content` (a rational carrying the sign) and
/// `factors[]` of `{poly, multiplicity}` (primitive integer polynomials, irreducible over Q,
/// positive leading coefficient); `input == content * prod(poly^multiplicity)` is checked
/// (`verified`).
///
/// # Errors
/// As [`crate::mpoly::factor()`].
pub fn mfactor_report(vars: &[String], p: &QPoly) -> crate::Result<Report> {
    let (mut c, facs) = factor_q(p)?;
    // show every factor with a positive first term; the sign goes into the content
    let facs: Vec<(crate::mpoly::MPoly, usize)> = facs
        .into_iter()
        .map(|(f, e)| {
            if f.display_lead_negative() {
                if e % 2 == 1 {
                    c = -c.clone();
                }
                (f.neg(), e)
            } else {
                (f, e)
            }
        })
        .collect();
    let mut prod = crate::mpoly::MPoly::one(p.prim.nvars());
    for (f, e) in &facs {
        prod = prod.mul(&f.pow(*e as u32));
    }
    let verified = QPoly::new(c.clone(), prod) == *p;
    let items = facs
        .iter()
        .map(|(f, e)| {
            Value::Obj(
                Report::new()
                    .str("poly", f.to_string_vars(vars))
                    .int("multiplicity", *e),
            )
        })
        .collect();
    Ok(Report::titled("factorization over QQ")
        .str("input", p.to_string_vars(vars))
        .with("variables", vars_value(vars))
        .rational("content", &c)
        .list("factors", items)
        .bool("verified", verified))
}

/// `poly gcd F G`: the primitive gcd over Q (positive leading coefficient; `1` when coprime,
/// `0` when both are zero) and the cofactors `F / gcd`, `G / gcd`; `verified` checks
/// `F = gcd * cofactor_F` and `G = gcd * cofactor_G`.
pub fn mgcd_report(vars: &[String], f: &QPoly, g: &QPoly) -> Report {
    let h = gcd(&f.prim, &g.prim).display_normalized();
    let (cf, cg) = if h.is_zero() {
        (None, None)
    } else {
        (f.prim.div_exact(&h), g.prim.div_exact(&h))
    };
    let verified = h.is_zero() || (cf.is_some() && cg.is_some());
    let cof = |q: &QPoly, c: &Option<crate::mpoly::MPoly>| match c {
        Some(c) => QPoly::new(q.content.clone(), c.clone()).to_string_vars(vars),
        None => "0".into(),
    };
    Report::titled("gcd over QQ")
        .with("variables", vars_value(vars))
        .str("gcd", h.to_string_vars(vars))
        .str("cofactor_f", cof(f, &cf))
        .str("cofactor_g", cof(g, &cg))
        .bool("verified", verified)
}
