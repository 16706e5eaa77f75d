//! Reports of the special coordinate basis, the mechanical normal form and invariant zeros.
//!
//! Presentation only: these `report` methods read finished results of [`crate::structure`] and
//! build the CLI contract's keys; the math modules do not depend on [`crate::report`].

use crate::field::{ElemDisplay, Field};
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;
use crate::report::{Report, Value};
use crate::structure::bifurcation::{Branch, BranchOutcome, Equation, NotExplored};
use crate::structure::mechanical::{Check, Condition, MechanicalNormalForm};
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

/// The statement of an existence condition with its values, e.g. `rank B = p = 2`.
pub fn condition_statement<K: Field>(c: &Condition<K>) -> String {
    let rel = |holds: bool, yes: &'static str, no: &'static str| if holds { yes } else { no };
    match &c.check {
        Check::StatesEven { n } => format!("n = {n} is {}", rel(c.holds, "even", "odd")),
        Check::InputsAtMostHalf { p, half } => {
            format!("p = {p} {} n/2 = {half}", rel(c.holds, "<=", ">"))
        }
        Check::RankB { p, .. } if c.holds => format!("rank B = p = {p}"),
        Check::RankB { rank, p } => format!("rank B = {rank} < p = {p}"),
        Check::RankK { p, .. } if c.holds => format!("rank(U_B2^T A U_B1) = p = {p}"),
        Check::RankK { rank, p } => format!("rank(U_B2^T A U_B1) = {rank} < p = {p}"),
        Check::PaperRankG { rank, bound } => {
            format!(
                "rank G = {rank} {} n/2 - p = {bound}",
                rel(c.holds, ">=", "<")
            )
        }
        Check::UncontrollableMultiplicity {
            geo,
            bound,
            witness,
        } => {
            let wit = witness
                .as_ref()
                .map_or(String::new(), |f| format!(" (eigenvalues: roots of {f})"));
            format!(
                "max geometric multiplicity of the uncontrollable part = {geo} {} n/2 - p = \
                 {bound}{wit}",
                rel(c.holds, "<=", ">")
            )
        }
        Check::InputCompression { rank, p } => {
            format!("rank B = {rank} < p = {p}: B = B1 R with B1 its pivot columns")
        }
    }
}

/// What a failure of the condition means for the system (for the diagnostics: why it does
/// not decide).
pub fn condition_meaning<K: Field>(c: &Check<K>) -> String {
    match c {
        Check::StatesEven { .. } => {
            "a second-order model with n/2 coordinates q and their velocities q' needs an even \
             number of states"
        }
        Check::InputsAtMostHalf { .. } => {
            "each input must act as a force on its own coordinate, so there cannot be more \
             inputs than coordinates"
        }
        Check::RankB { .. } => {
            "the input matrix must have full column rank (combine or remove redundant inputs)"
        }
        Check::RankK { .. } => {
            "A B must be independent of B (rank [B, AB] = 2p): in a mechanical system an input \
             force changes accelerations, which become positions only through the velocities; \
             here some input combination acts directly on the position-like states"
        }
        Check::PaperRankG { .. } => {
            "Theorem 2.1's last condition; it depends on the orthonormal bases (it is not \
             similarity invariant), so it is reported but does not decide"
        }
        Check::UncontrollableMultiplicity { .. } => {
            "in q'' + D q' + K q = [0; I_p] u only the n/2 - p unforced coordinates can carry \
             independent uncontrollable modes of one eigenvalue, so an uncontrollable eigenvalue \
             with more independent eigenvectors cannot be represented"
        }
        Check::InputCompression { .. } => {
            "dependent inputs act through fewer independent forces; the conditions below are \
             those of (A, B1) and the input matrix of the second-order model is W = [0; R] \
             instead of [0; I_p]"
        }
    }
    .to_string()
}

impl<K: Field> MechanicalNormalForm<K> {
    /// Which condition fails and what it means (`statement: meaning`), when `exists` is
    /// false.
    pub fn reason_text(&self) -> Option<String> {
        let c = &self.conditions[self.reason?];
        Some(format!(
            "{}: {}",
            condition_statement(c),
            condition_meaning(&c.check)
        ))
    }
    /// The report with the CLI contract keys of `mnf`: `exists`, `reason`, `mass`, `damping`,
    /// `stiffness`, `input`, `output`, `feedthrough`, `T`, `verified` (`"not applicable"` when
    /// no form exists, e.g. an odd number of states), then `conditions` and the search
    /// statistics.
    pub fn report(&self) -> Report {
        let mut r = Report::titled("mechanical normal form")
            .bool("exists", self.exists)
            .with("reason", self.reason_text().map_or(Value::Null, Value::Str));
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
                        .str("name", c.name())
                        .str("statement", condition_statement(c))
                        .bool("holds", c.holds)
                        .bool("decisive", c.decisive)
                        .str("meaning", condition_meaning(&c.check)),
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

/// The equation of a bifurcation branch: `c = 0` for a condition not solved, else the
/// substitution made (`cr = m*u^2/(a + b)`).
pub fn branch_equation<S>(k: &RatFuncField, b: &Branch<S>) -> String {
    match &b.equation {
        Equation::Zero => format!("{} = 0", k.fmt_poly(&b.condition)),
        Equation::Substitution { var, value } => {
            format!("{} = {}", k.vars()[*var], k.fmt_elem(value))
        }
    }
}

/// Why a bifurcation branch has no result: an entry's pole at the substitution, or why it
/// was not explored; `None` for an explored branch.
pub fn branch_reason<S>(k: &RatFuncField, b: &Branch<S>) -> Option<String> {
    match &b.outcome {
        BranchOutcome::Explored(_) => None,
        BranchOutcome::Undefined => Some(format!(
            "an entry of the system has a pole at {}",
            branch_equation(k, b)
        )),
        BranchOutcome::NotExplored(NotExplored::NotLinear) => {
            Some("not linear in any parameter: not explored".into())
        }
        BranchOutcome::NotExplored(NotExplored::Failed(e)) => {
            Some(format!("the computation failed there: {e}"))
        }
    }
}
