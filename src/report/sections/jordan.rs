//! Reports of Jordan forms, real Jordan forms and free responses.
//!
//! Presentation only: these `report` methods read finished results of [`crate::jordan`] and
//! build the CLI contract's keys; the math modules do not depend on [`crate::report`].

use crate::algebraic::Ext;
use crate::field::Field;
use crate::jordan::{FreeResponse, JordanForm, RealJordanForm};
use crate::matrix::Matrix;
use crate::report::{MatrixOut, Report, Value};

/// $J$ and $T$ for output from the columns of each eigenvalue, $(E, \sigma_j(V),
/// \sigma_j(J))$ exact in its field $E = F(\theta_j)$: one writer for every base field.
pub(super) fn j_t_cells<F: Field>(
    n: usize,
    cols: impl IntoIterator<Item = (Ext<F>, Matrix<Ext<F>>, Matrix<Ext<F>>)>,
) -> (MatrixOut, MatrixOut) {
    let zero_s = || vec![vec!["0".to_string(); n]; n];
    let zero_a = || vec![vec![(0.0, 0.0); n]; n];
    let (mut je, mut ja, mut te, mut ta) = (zero_s(), zero_a(), zero_s(), zero_a());
    let mut off = 0;
    for (k, v, j) in cols {
        let m = v.ncols();
        for r in 0..n {
            for q in 0..m {
                te[r][off + q] = k.fmt_elem(v.get(r, q));
                ta[r][off + q] = k.approx(v.get(r, q));
            }
        }
        for r in 0..m {
            for q in 0..m {
                je[off + r][off + q] = k.fmt_elem(j.get(r, q));
                ja[off + r][off + q] = k.approx(j.get(r, q));
            }
        }
        off += m;
    }
    (MatrixOut::from_parts(je, ja), MatrixOut::from_parts(te, ta))
}

/// `J` and `T` as report values: one exact matrix each when every eigenvalue lies in one
/// field (`single`), else the per-eigenvalue writer `per_root`.
pub(super) fn j_t_values<K: Field>(
    single: Option<(Matrix<K>, Matrix<K>)>,
    per_root: impl FnOnce() -> (MatrixOut, MatrixOut),
) -> (Value, Value) {
    let (jo, to) = match single {
        Some((j, t)) => (MatrixOut::from_matrix(&j), MatrixOut::from_matrix(&t)),
        None => per_root(),
    };
    (Value::Matrix(Box::new(jo)), Value::Matrix(Box::new(to)))
}

/// The tail shared by the real Jordan reports over every field: `presentation` and `symbols`
/// for the compact form (`presentation` the field's wording), then `fields`, `parts` and
/// `notes` (each when not empty).
pub(super) fn real_form_tail(
    mut r: Report,
    compact: Option<&str>,
    symbols: &[String],
    fields: Vec<Value>,
    [parts, notes]: [&[String]; 2],
) -> Report {
    let strs = |xs: &[String]| xs.iter().cloned().map(Value::Str).collect::<Vec<_>>();
    if let Some(presentation) = compact {
        r = r
            .str("presentation", presentation)
            .list("symbols", strs(symbols));
    }
    if !fields.is_empty() {
        r = r.list("fields", fields);
    }
    if !parts.is_empty() {
        r = r.list("parts", strs(parts));
    }
    if !notes.is_empty() {
        r = r.list("notes", strs(notes));
    }
    r
}

impl JordanForm {
    /// $J$ and $T$ for output: exact strings (per-root fields) and approximations.
    pub fn j_t_out(&self) -> (MatrixOut, MatrixOut) {
        let cols = self.root_columns().into_iter().map(|c| (c.field, c.v, c.j));
        j_t_cells(self.n(), cols)
    }
    /// The report with the CLI contract's keys: `eigenvalues[]` (`minpoly`, `value`,
    /// `approx`, `algebraic_multiplicity`, `geometric_multiplicity`, `blocks`), `J`, `T`
    /// (exact, with `_approx`), `verified`, plus `charpoly`, `presentation`, `symbols`.
    pub fn report(&self) -> Report {
        let evs = super::pencil::eigen_items(self);
        let single = self.single_field();
        let presentation = match &single {
            Some((j, _)) if j.field().degree() == 1 => "single matrix over QQ".to_string(),
            Some((j, _)) => format!("single matrix over QQ({})", j.field().0.var),
            None => "per eigenvalue: the columns of eigenvalue r<k> are exact in QQ(r<k>) \
                     (closed form for degree <= 2)"
                .to_string(),
        };
        let symbols: Vec<Value> = self
            .eigenvalues
            .iter()
            .filter(|e| e.minpoly.deg() >= 3)
            .map(|e| {
                Value::Str(format!(
                    "{} = {}",
                    e.symbol,
                    crate::jordan::value_display(&e.minpoly, e.approx)
                ))
            })
            .collect();
        let (jo, to) = j_t_values(single, || self.j_t_out());
        let mut r = Report::titled("Jordan form")
            .int("n", self.n())
            .str("charpoly", self.charpoly.to_string())
            .list("eigenvalues", evs)
            .with("J", jo)
            .with("T", to)
            .str("presentation", presentation);
        if !symbols.is_empty() {
            r = r.list("symbols", symbols);
        }
        r.bool("verified", self.verified)
    }
}

impl RealJordanForm {
    /// $J$, $T$ for output (exact strings in each block's field; `~x` marks an
    /// approximate entry of a non-exact block).
    pub fn j_t_out(&self) -> (MatrixOut, MatrixOut) {
        let n = self.n;
        let mut je = vec![vec!["0".to_string(); n]; n];
        let mut te = je.clone();
        let mut ja = vec![vec![(0.0, 0.0); n]; n];
        let mut ta = ja.clone();
        let mut off = 0;
        for b in &self.blocks {
            let w = b.t_approx.first().map_or(b.j_approx.len(), |r| r.len());
            for r in 0..n {
                for q in 0..w {
                    ta[r][off + q] = (b.t_approx[r][q], 0.0);
                    te[r][off + q] = match (&b.field, &b.t, &b.compact) {
                        (Some(f), Some(t), _) => f.fmt_elem(t.get(r, q)),
                        (_, _, Some(cp)) => {
                            let (re, im) = cp.part_strings(cp.v.get(r, q / 2));
                            if q % 2 == 0 { re } else { im }
                        }
                        _ => format!("~{}", b.t_approx[r][q]),
                    };
                }
            }
            for r in 0..w {
                for q in 0..w {
                    ja[off + r][off + q] = (b.j_approx[r][q], 0.0);
                    je[off + r][off + q] = match (&b.field, &b.j, &b.compact) {
                        (Some(f), Some(j), _) => f.fmt_elem(j.get(r, q)),
                        (_, _, Some(cp)) => cp.j_entry(r, q, b.j_approx[r][q] == 1.0),
                        _ => format!("~{}", b.j_approx[r][q]),
                    };
                }
            }
            off += w;
        }
        (MatrixOut::from_parts(je, ja), MatrixOut::from_parts(te, ta))
    }
    /// Report: `J`, `T` (exact strings and `_approx`), `exact`, `verified`, `fields`,
    /// `parts`, `notes`.
    pub fn report(&self) -> Report {
        let (jo, to) = j_t_values(self.single_field(), || self.j_t_out());
        let fields: Vec<Value> = self
            .blocks
            .iter()
            .filter_map(|b| b.field.as_ref())
            .filter(|f| f.degree() >= 3)
            .map(|f| {
                Value::Str(format!(
                    "{} = {}",
                    f.0.var,
                    crate::jordan::value_display(f.modulus(), f.root_approx())
                ))
            })
            .collect();
        let compact = self.blocks.iter().any(|b| b.compact.is_some());
        let r = Report::titled("Real Jordan form")
            .with("J", jo)
            .with("T", to)
            .bool("exact", self.exact)
            .bool("verified", self.verified);
        let presentation = "compact: each complex pair r<k> = a<k> + b<k>*i has the block \
             [[a, b], [-b, a]] and the columns Re v, Im v of its complex chains v in QQ(r<k>) \
             (T_R = T_C S); verified on the complex side (A T_C = T_C J_C in QQ(r<k>), which \
             implies A T_R = T_R J_R); `--expand` writes the entries in a real field";
        real_form_tail(
            r,
            compact.then_some(presentation),
            &self.symbols,
            fields,
            [&self.parts, &self.notes],
        )
    }
}

impl FreeResponse {
    /// Report: one entry per eigenvalue and power, `x(t) = sum t^k e^(s t) G x0`, and
    /// `verified` ([`FreeResponse::verify`]: the derivative and the value at `t = 0`).
    pub fn report(&self, jf: &JordanForm) -> Report {
        let mut items = vec![];
        for (ev, e) in jf.eigenvalues.iter().enumerate() {
            let (field, f) = jf.root_map(ev);
            for t in self.terms.iter().filter(|t| t.component == e.component) {
                items.push(Value::Obj(
                    Report::new()
                        .str("eigenvalue", e.value.clone())
                        .int("power", t.power)
                        .matrix("G", &t.coeff.map(&field, &f)),
                ));
            }
        }
        Report::titled("Free response x(t) = sum_k t^k e^(s t) G x0")
            .list("terms", items)
            .bool("verified", self.verify(jf))
    }
}

impl std::fmt::Display for JordanForm {
    /// The text report: eigenvalues with their blocks, `J`, `T`, `verified`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.report().to_text())
    }
}

impl std::fmt::Display for RealJordanForm {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.report().to_text())
    }
}
