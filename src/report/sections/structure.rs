//! Reports of the special coordinate basis, the mechanical normal form and invariant zeros.
//!
//! Presentation only: these `report` methods read finished results of [`crate::structure`] and
//! build the CLI contract's keys; the math modules do not depend on [`crate::report`].

use crate::field::Field;
use crate::poly::Poly;
use crate::report::{Report, Value};
use crate::structure::mechanical::MechanicalNormalForm;
use crate::structure::scb::Scb;
use crate::structure::zeros::InvariantZeros;
use crate::system::discrete::stability::{Domain, schur_stable};

impl<K: Field> Scb<K> {
    /// Report with the CLI contract's keys for `scb`.
    pub fn report(&self) -> Report {
        let [na, nb, nc, nd] = self.dims;
        let dims = Report::new()
            .int("a", na)
            .int("b", nb)
            .int("c", nc)
            .int("d", nd);
        Report::titled("special coordinate basis")
            .obj("dims", dims)
            .list(
                "chains",
                self.chains.iter().map(|&q| Value::Int(q as i64)).collect(),
            )
            .list(
                "invariant_zeros",
                zero_items(&self.invariant_zero_polynomial()),
            )
            .str(
                "zero_polynomial",
                self.invariant_zero_polynomial().to_string_var("s"),
            )
            .bool("left_invertible", self.left_invertible)
            .bool("right_invertible", self.right_invertible)
            .with(
                "minimum_phase",
                self.minimum_phase().map_or(Value::Null, Value::Bool),
            )
            .matrices(&[
                ("A", &self.a),
                ("B", &self.b),
                ("C", &self.c),
                ("D", &self.d),
                ("G1", &self.gamma1),
                ("G2", &self.gamma2),
                ("G3", &self.gamma3),
                ("U", &self.u_pre),
                ("Y", &self.y_pre),
            ])
            .bool("verified", self.verified && self.verify())
    }
}

/// The matrices of the mechanical normal form, in the report's order.
const MNF_KEYS: [&str; 7] = [
    "mass",
    "damping",
    "stiffness",
    "input",
    "output",
    "feedthrough",
    "T",
];

impl<K: Field> MechanicalNormalForm<K> {
    /// The report with the CLI contract keys of `mnf`: `exists`, `reason`, `mass`, `damping`,
    /// `stiffness`, `input`, `output`, `feedthrough`, `T`, `verified` (`"not applicable"` when
    /// no form exists, e.g. an odd number of states), then `conditions` and the search
    /// statistics.
    pub fn report(&self) -> Report {
        let mut r = Report::titled("mechanical normal form")
            .bool("exists", self.exists)
            .with(
                "reason",
                self.reason.clone().map_or(Value::Null, Value::Str),
            );
        match &self.form {
            Some(m) => {
                let ms = [
                    &m.mass,
                    &m.damping,
                    &m.stiffness,
                    &m.input,
                    &m.output,
                    &m.feedthrough,
                    &m.t,
                ];
                r = r.matrices(&MNF_KEYS.into_iter().zip(ms).collect::<Vec<_>>());
                if let Some(l) = &m.left {
                    r = r.matrix("T_rows", l);
                }
            }
            None => {
                for key in MNF_KEYS {
                    r = r.with(key, Value::Null);
                }
            }
        }
        // no form, nothing to check: "not applicable" (never `false` beside exit 0)
        r = if self.exists || self.form.is_some() {
            r.bool("verified", self.verified)
        } else {
            r.str("verified", "not applicable")
        };
        let conds = self
            .conditions
            .iter()
            .map(|c| {
                Value::Obj(
                    Report::new()
                        .str("name", c.name)
                        .str("statement", c.statement.clone())
                        .bool("holds", c.holds)
                        .bool("decisive", c.decisive)
                        .str("meaning", c.meaning.clone()),
                )
            })
            .collect();
        r = r.list("conditions", conds);
        if let Some(m) = &self.form {
            r = r.int("candidates_tested", m.candidates as usize);
        }
        r
    }
}

impl<K: Field> InvariantZeros<K> {
    /// Report with the CLI contract's key `invariant_zeros[]` (square-free factors with
    /// multiplicities; the value for linear factors), plus `zero_polynomial`, `normal_rank`.
    pub fn report(&self) -> Report {
        self.report_in(Domain::Continuous)
    }

    /// [`Self::report`] of a system in `domain`: the zero polynomial in `s` or `z`, and
    /// `minimum_phase` for every zero in $\mathrm{Re}\, s < 0$ (Hurwitz) or, in discrete
    /// time, in $|z| < 1$ (Schur-Cohn over $\mathbb{Q}$; `null` over other fields).
    pub fn report_in(&self, domain: Domain) -> Report {
        let p = &self.polynomial;
        let minimum_phase = match domain {
            Domain::Continuous => crate::structure::scb::hurwitz(p),
            Domain::Discrete => {
                let k = p.field();
                let q: Option<Vec<crate::field::Rational>> =
                    p.coeffs().iter().map(|c| k.to_rational(c)).collect();
                q.map(|c| schur_stable(&Poly::new(crate::field::Q, c)))
            }
        };
        Report::titled("invariant zeros")
            .with("variable", super::variable(domain))
            .list("invariant_zeros", zero_items_in(p, domain.var()))
            .str("zero_polynomial", p.to_string_var(domain.var()))
            .int("normal_rank", self.normal_rank)
            .with(
                "minimum_phase",
                minimum_phase.map_or(crate::report::Value::Null, crate::report::Value::Bool),
            )
    }
}

/// The zero polynomial's square-free factors as report items `{factor, multiplicity}`, with
/// `root` for linear factors.
pub(crate) fn zero_items<K: Field>(p: &Poly<K>) -> Vec<Value> {
    zero_items_in(p, "s")
}

/// [`zero_items`] with the factors written in the variable `var`.
pub(crate) fn zero_items_in<K: Field>(p: &Poly<K>, var: &str) -> Vec<Value> {
    if p.deg() == 0 {
        return vec![];
    }
    let k = p.field().clone();
    // rational zero polynomial: the zeros as exact algebraic numbers
    let rational: Option<Vec<crate::field::Rational>> =
        p.coeffs().iter().map(|c| k.to_rational(c)).collect();
    if let Some(cs) = rational
        && let Ok(rs) = crate::algebraic::roots(&Poly::new(crate::field::Q, cs))
    {
        return rs
            .into_iter()
            .map(|(z, mult)| {
                let (re, im) = z.approx();
                Value::Obj(
                    Report::new()
                        .str("minpoly", z.minpoly().to_string())
                        .str("value", z.value_string())
                        .with(
                            "approx",
                            Value::List(vec![Value::Float(re), Value::Float(im)]),
                        )
                        .int("multiplicity", mult),
                )
            })
            .collect();
    }
    p.squarefree()
        .into_iter()
        .filter(|(f, _)| f.deg() > 0)
        .map(|(f, mult)| {
            let mut r = Report::new()
                .str("factor", f.to_string_var(var))
                .int("multiplicity", mult);
            if f.deg() == 1 {
                let root = k.neg(&k.div(&f.coeff(0), &f.coeff(1)).expect("non-zero lc"));
                r = r.str("value", k.fmt_elem(&root));
                if let Some((re, im)) = k.approx(&root) {
                    r = r.with(
                        "approx",
                        Value::List(vec![Value::Float(re), Value::Float(im)]),
                    );
                }
            }
            Value::Obj(r)
        })
        .collect()
}
