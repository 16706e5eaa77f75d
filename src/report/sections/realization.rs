//! Reports of minimal realizations, the modal table and descriptor conversion.
//!
//! Presentation only: these `report` methods read finished results of [`crate::realization`] and
//! build the CLI contract's keys; the math modules do not depend on [`crate::report`].

use crate::algebraic::NfElem;
use crate::field::Field;
use crate::realization::{
    JordanMinimal, MinimalRealization, ModalTable, RealModalBlock, StandardForm,
};
use crate::report::{MatrixOut, Report, Value, str_list};

/// Writes a compact pair block at offset `off`: state `2i` is $\mathrm{Re}\, z_i$, state
/// `2i + 1` is $-\mathrm{Im}\, z_i$ (the module docs' convention), entries displayed as
/// `Re(...)`, `Im(...)` of the $K$-entries and `a<k>`, `b<k>` for the parts of $\theta$.
fn compact_outputs(
    blk: &RealModalBlock,
    off: usize,
    (a, b, c): (&mut MatrixOut, &mut MatrixOut, &mut MatrixOut),
) {
    let f = &blk.field;
    let k = f.0.var.trim_start_matches('r').to_string();
    let theta = f.generator();
    // display of Re x / Im x (scaled by `scale`, negated by `neg`) and its approximation
    let part = |x: &NfElem, im: bool, scale: i64, neg: bool| -> (String, f64) {
        let (ar, ai) = f.approx(x);
        let v = scale as f64 * if im { ai } else { ar } * if neg { -1.0 } else { 1.0 };
        let sign = if neg { "-" } else { "" };
        let pre = if scale == 1 {
            String::new()
        } else {
            format!("{scale}*")
        };
        let text = if let Some(q) = f.to_rational(x) {
            if im {
                "0".to_string()
            } else {
                let q = q * crate::field::Rational::from_integer(scale.into());
                crate::field::fmt_rational(&if neg { -q } else { q })
            }
        } else if *x == theta {
            format!("{sign}{pre}{}{k}", if im { "b" } else { "a" })
        } else {
            let s = f.fmt_elem(x);
            format!("{sign}{pre}{}({s})", if im { "Im" } else { "Re" })
        };
        (text, v)
    };
    let put = |o: &mut MatrixOut, i: usize, j: usize, (text, v): (String, f64)| {
        o.latex[i][j] = text.clone();
        o.exact[i][j] = text;
        o.approx[i][j] = (v, 0.0);
    };
    let s = blk.a.nrows();
    for i in 0..s {
        for j in 0..s {
            let x = blk.a.get(i, j);
            // [[Re, Im], [-Im, Re]] per complex entry
            put(a, off + 2 * i, off + 2 * j, part(x, false, 1, false));
            put(a, off + 2 * i, off + 2 * j + 1, part(x, true, 1, false));
            put(a, off + 2 * i + 1, off + 2 * j, part(x, true, 1, true));
            put(
                a,
                off + 2 * i + 1,
                off + 2 * j + 1,
                part(x, false, 1, false),
            );
        }
        for col in 0..blk.b.ncols() {
            let x = blk.b.get(i, col);
            put(b, off + 2 * i, col, part(x, false, 1, false));
            put(b, off + 2 * i + 1, col, part(x, true, 1, true));
        }
        for row in 0..blk.c.nrows() {
            let x = blk.c.get(row, i);
            put(c, row, off + 2 * i, part(x, false, 2, false));
            put(c, row, off + 2 * i + 1, part(x, true, 2, false));
        }
    }
}

impl JordanMinimal {
    /// Assembles block-diagonal `A` and stacked `B`, `C` for output (entries exact in each
    /// block's field, symbols defined in `symbols`).
    fn outputs(&self) -> (MatrixOut, MatrixOut, MatrixOut) {
        let r = self.order();
        let (m, p) = (self.d.ncols(), self.d.nrows());
        let empty = |rows: usize, cols: usize| MatrixOut {
            exact: vec![vec!["0".to_string(); cols]; rows],
            latex: vec![vec!["0".to_string(); cols]; rows],
            approx: vec![vec![(0.0, 0.0); cols]; rows],
            nrows: rows,
            ncols: cols,
        };
        let (mut a, mut b, mut c) = (empty(r, r), empty(r, m), empty(p, r));
        let mut off = 0;
        for blk in &self.blocks {
            if blk.compact {
                compact_outputs(blk, off, (&mut a, &mut b, &mut c));
                off += blk.order;
                continue;
            }
            let f = &blk.field;
            let put = |o: &mut MatrixOut, i: usize, j: usize, x: &NfElem| {
                o.exact[i][j] = f.fmt_elem(x);
                o.latex[i][j] = f.latex_elem(x);
                o.approx[i][j] = f.approx(x);
            };
            let s = blk.a.nrows();
            for i in 0..s {
                for j in 0..s {
                    put(&mut a, off + i, off + j, blk.a.get(i, j));
                }
                for j in 0..m {
                    put(&mut b, off + i, j, blk.b.get(i, j));
                }
                for row in 0..p {
                    put(&mut c, row, off + i, blk.c.get(row, i));
                }
            }
            off += s;
        }
        (a, b, c)
    }
    /// The CLI report (`order`, `mcmillan_degree`, `A`..`D`, `verified`, the stage orders and
    /// the symbols used in the entries).
    pub fn report(&self) -> Report {
        let (a, b, c) = self.outputs();
        Report::titled("minimal realization (jordan)")
            .str("method", "jordan")
            .int("original_order", self.stages[0])
            .int("order", self.order())
            .int("mcmillan_degree", self.mcmillan_degree)
            .with(
                "stages",
                Value::List(self.stages.iter().map(|&s| Value::Int(s as i64)).collect()),
            )
            .with("A", Value::Matrix(Box::new(a)))
            .with("B", Value::Matrix(Box::new(b)))
            .with("C", Value::Matrix(Box::new(c)))
            .matrix("D", &self.d)
            .with(
                "modes",
                str_list(self.blocks.iter().map(|b| b.eigenvalue.clone())),
            )
            .with(
                "symbols",
                Value::List(
                    self.symbols
                        .iter()
                        .map(|(k, v)| Value::Str(format!("{k} = {v}")))
                        .collect(),
                ),
            )
            .bool("verified", self.verified)
    }
}

impl<K: Field> MinimalRealization<K> {
    /// The CLI report (`order`, `mcmillan_degree`, `A`..`D`, `verified`).
    pub fn report(&self) -> Report {
        let mut r = Report::titled(format!("minimal realization ({})", self.method.name()))
            .str("method", self.method.name())
            .int("original_order", self.original_order)
            .int("order", self.order)
            .int("mcmillan_degree", self.order)
            .matrix("A", &self.system.a)
            .matrix("B", &self.system.b)
            .matrix("C", &self.system.c)
            .matrix("D", &self.system.d);
        if let Some(t) = &self.t {
            r = r.matrix("T", t);
        }
        r.bool("verified", self.verified)
    }
}

impl ModalTable {
    /// The CLI report: `modes[]` with `eigenvalue`, `frequency_hz`, `damping_ratio`,
    /// `time_constant_s`, `period_s` (plus `minpoly`, `approx`, `multiplicity`, `exact`).
    pub fn report(&self) -> Report {
        let opt = |x: Option<f64>| x.map_or(Value::Null, Value::Float);
        let modes = self
            .modes
            .iter()
            .map(|m| {
                let mut ex = Report::new();
                for (k, v) in &m.exact {
                    ex.push(k.clone(), Value::Str(v.clone()));
                }
                Value::Obj(
                    Report::new()
                        .str("eigenvalue", m.eigenvalue.clone())
                        .str("minpoly", m.minpoly.clone())
                        .with(
                            "approx",
                            Value::List(vec![Value::Float(m.approx.0), Value::Float(m.approx.1)]),
                        )
                        .int("multiplicity", m.multiplicity)
                        .float("frequency_hz", m.frequency_hz)
                        .with("damping_ratio", opt(m.damping_ratio))
                        .with("time_constant_s", opt(m.time_constant_s))
                        .with("period_s", opt(m.period_s))
                        .obj("exact", ex),
                )
            })
            .collect();
        let header = [
            "mode",
            "multiplicity",
            "frequency (Hz)",
            "damping ratio",
            "time constant (s)",
        ]
        .map(String::from)
        .to_vec();
        let rows = self.modes.iter().map(mode_row).collect();
        Report::titled("modal table").with("modes", Value::table(Value::List(modes), header, rows))
    }
}

/// One row of the modal table's text: the mode (exact when short, the pair as `a ± b i`,
/// an unpaired eigenvalue of a non-real matrix as `a + b i`, otherwise), its multiplicity, frequency in Hz, damping ratio and time constant.
fn mode_row(m: &crate::realization::Mode) -> Vec<String> {
    use crate::report::text::{MAX_EXACT_ENTRY, short};
    let (re, im) = m.approx;
    let mode = if m.eigenvalue.chars().count() <= MAX_EXACT_ENTRY {
        m.eigenvalue.clone()
    } else if m.paired {
        format!("{} ± {}i (approx.)", short(re), short(im))
    } else if im != 0.0 {
        let sign = if im > 0.0 { "+" } else { "-" };
        format!("{} {sign} {}i (approx.)", short(re), short(im.abs()))
    } else {
        format!("{} (approx.)", short(re))
    };
    let opt = |x: Option<f64>| x.map_or("-".to_string(), short);
    vec![
        mode,
        m.multiplicity.to_string(),
        short(m.frequency_hz),
        opt(m.damping_ratio),
        opt(m.time_constant_s),
    ]
}

impl<K: Field> StandardForm<K> {
    pub fn report(&self) -> Report {
        Report::titled("descriptor to standard form")
            .int("order", self.system.nstates())
            .int("removed_infinite", self.removed_infinite)
            .str("method", self.method.name())
            .matrix("A", &self.system.a)
            .matrix("B", &self.system.b)
            .matrix("C", &self.system.c)
            .matrix("D", &self.system.d)
            .matrix("V1", &self.v1)
            .str(
                "V1_note",
                "the descriptor's states x = V1 z + (terms in u), z the states of A",
            )
            .bool("verified", self.verified)
    }
}

impl<K: Field> std::fmt::Display for MinimalRealization<K> {
    /// The text report: orders, `A`..`D` of the minimal system, `verified`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.report().to_text())
    }
}

impl std::fmt::Display for JordanMinimal {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.report().to_text())
    }
}
