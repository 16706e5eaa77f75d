//! Report of the Jordan form over a quadratic field ([`crate::jordan::over_k`]): the same
//! contract keys as the rational report (`eigenvalues`, `J`, `T`, `verified`, plus `n`,
//! `field`, `charpoly`, `presentation`, `symbols`).

use super::eigenvalue_items;
use crate::algebraic::{Ext, ExtElem};
use crate::field::Field;
use crate::jordan::fmt_approx;
use crate::jordan::over_k::{JordanFormK, RelElem, RelField};
use crate::matrix::Matrix;
use crate::realization::{ModalBlockK, RealModalBlockK};
use crate::report::{MatrixOut, Report, Value};

impl JordanFormK {
    /// $J$ and $T$ for output: per eigenvalue, entries exact in its field $E$ at that root.
    pub fn j_t_out(&self) -> (MatrixOut, MatrixOut) {
        super::jordan::j_t_cells(self.n(), self.root_columns())
    }
    /// The report with the CLI contract's keys (those of the rational Jordan report).
    pub fn report(&self) -> Report {
        let k = self.base();
        let single = self.single_field();
        let presentation = if single.is_some() {
            format!("single matrix over {k}")
        } else {
            format!(
                "per eigenvalue: the columns of eigenvalue r<k> are exact in {k}(r<k>), written \
                 as polynomials in r<k> over {k} (with the radical for a rational quadratic \
                 factor)"
            )
        };
        let symbols: Vec<Value> = self
            .eigenvalues
            .iter()
            .enumerate()
            .filter(|(_, e)| {
                let c = &self.components[e.component];
                c.factor.deg() >= 2 && !(c.factor.deg() == 2 && c.minpoly.deg() == 2)
            })
            .map(|(_, e)| {
                let c = &self.components[e.component];
                Value::Str(format!(
                    "{} = root of {} near {} (over {k}: root of {})",
                    e.symbol,
                    e.minpoly,
                    fmt_approx(e.approx),
                    c.factor
                ))
            })
            .collect();
        let (jo, to) = super::jordan::j_t_values(single, || self.j_t_out());
        let mut r = Report::titled("Jordan form")
            .int("n", self.n())
            .str("field", k.to_string())
            .str("charpoly", self.charpoly.to_string())
            .list("eigenvalues", eigenvalue_items(&self.eigenvalues))
            .with("J", jo)
            .with("T", to)
            .str("presentation", presentation);
        if !symbols.is_empty() {
            r = r.list("symbols", symbols);
        }
        r.bool("verified", self.verified)
    }
}

impl std::fmt::Display for JordanFormK {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.report().to_text())
    }
}

impl crate::jordan::over_k::response::FreeResponseK {
    /// Report: the keys of the rational free response (`terms`: `eigenvalue`, `power`, `G`
    /// per eigenvalue and power, `G` exact in the eigenvalue's field) and `verified`
    /// ([`Self::verify`]).
    pub fn report(&self, jf: &JordanFormK) -> Report {
        let mut items = vec![];
        for (ev, e) in jf.eigenvalues.iter().enumerate() {
            for (power, g) in self.terms_of(jf, ev) {
                items.push(Value::Obj(
                    Report::new()
                        .str("eigenvalue", e.value.clone())
                        .int("power", power)
                        .matrix("G", &g),
                ));
            }
        }
        Report::titled("Free response x(t) = sum_k t^k e^(s t) G x0")
            .list("terms", items)
            .bool("verified", self.verify(jf))
    }
}

impl crate::jordan::over_k::RealFormK {
    /// Report: `J`, `T` (exact texts and `_approx`), `exact`, `verified`, and for the compact
    /// form `presentation` and `symbols` (the keys of the rational real Jordan report).
    pub fn report(&self) -> Report {
        let cx = |m: &[Vec<f64>]| -> Vec<Vec<(f64, f64)>> {
            m.iter()
                .map(|r| r.iter().map(|&x| (x, 0.0)).collect())
                .collect()
        };
        let jo = MatrixOut::from_parts(self.j.clone(), cx(&self.j_approx));
        let to = MatrixOut::from_parts(self.t.clone(), cx(&self.t_approx));
        let r = Report::titled("Real Jordan form")
            .with("J", Value::Matrix(Box::new(jo)))
            .with("T", Value::Matrix(Box::new(to)))
            .bool("exact", true)
            .bool("verified", self.verified);
        let presentation = "compact: each complex pair r<k> = a<k> + b<k>*i has the block \
             [[a, b], [-b, a]] and the columns Re v, Im v of its complex chains v (exact in \
             K(r<k>)); verified on the complex side (A V = V J in K(r<k>), which implies \
             A T = T J); `--expand` writes the entries in a real field";
        let fields = self.fields.iter().cloned().map(Value::Str).collect();
        super::jordan::real_form_tail(
            r,
            self.compact.then_some(presentation),
            &self.symbols,
            fields,
            [&[], &self.notes],
        )
    }
}

/// Exact texts and approximations of a matrix under construction.
type Cells = (Vec<Vec<String>>, Vec<Vec<(f64, f64)>>);

/// Writes a block $(A, B, C)$ over an extension $E = F\[t\]/(g)$ (any base field) at
/// `off` into the cells of `A`, `B`, `C`: block-diagonal `A`, stacked `B`, `C`.
fn put_block<F: Field>(
    f: &Ext<F>,
    [ba, bb, bc]: [&Matrix<Ext<F>>; 3],
    off: usize,
    [a, b, c]: [&mut Cells; 3],
) {
    let put = |o: &mut Cells, i: usize, j: usize, x: &ExtElem<F::Elem>| {
        o.0[i][j] = f.fmt_elem(x);
        o.1[i][j] = f.approx(x);
    };
    let s = ba.nrows();
    for i in 0..s {
        for j in 0..s {
            put(a, off + i, off + j, ba.get(i, j));
        }
        for j in 0..bb.ncols() {
            put(b, off + i, j, bb.get(i, j));
        }
        for row in 0..bc.nrows() {
            put(c, row, off + i, bc.get(row, i));
        }
    }
}

/// [`put_block`] of a complex modal block.
fn put_modal(blk: &ModalBlockK, off: usize, cells: [&mut Cells; 3]) {
    put_block(&blk.field, [&blk.a, &blk.b, &blk.c], off, cells);
}

/// `Re(x)` / `Im(x)` display and value of an element of $E$ at $\theta$ (plain when it
/// lies in $K$; `a<k>`, `b<k>` for $\theta$ itself).
fn part(f: &RelField, x: &RelElem, imag: bool, sym: &str) -> (String, (f64, f64)) {
    let (re, im) = f.approx(x);
    let val = (if imag { im } else { re }, 0.0);
    if let Some(t) = crate::jordan::over_k::real::radical_part(f, x, imag) {
        return (t, val);
    }
    let txt = if f.is_zero(x) {
        "0".to_string()
    } else if let Some(c) = f.to_base(x) {
        if imag {
            "0".into()
        } else {
            f.base().fmt_elem(&c)
        }
    } else if *x == f.generator() {
        format!("{}{sym}", if imag { "b" } else { "a" })
    } else if f.neg(x) == f.generator() && imag {
        format!("-b{sym}")
    } else {
        format!("{}({})", if imag { "Im" } else { "Re" }, f.fmt_elem(x))
    };
    (txt, val)
}

/// [`part`] of $-x$, written `-Re(x)` / `-Im(x)` when not plain.
fn part_neg(f: &RelField, x: &RelElem, imag: bool, sym: &str) -> (String, (f64, f64)) {
    let (t, v) = part(f, &f.neg(x), imag, sym);
    if f.0.radical.is_none() && (t.starts_with("Re(") || t.starts_with("Im(")) {
        (format!("-{}", part(f, x, imag, sym).0), v)
    } else {
        (t, v)
    }
}

/// Writes the compact real block of a pair (complex data `blk` of the upper root) at `off`:
/// $A_r = [[\mathrm{Re}, \mathrm{Im}], [-\mathrm{Im}, \mathrm{Re}]]$ of $J$,
/// $B_r = [\mathrm{Re}; -\mathrm{Im}]$ of $WB$, $C_r = [\mathrm{Re}, \mathrm{Im}]$ of $2CV$.
fn put_compact(blk: &ModalBlockK, off: usize, [a, b, c]: [&mut Cells; 3]) {
    let f = &blk.field;
    let sym = &f.0.var[1..];
    let two = f.from_i64(2);
    let put = |o: &mut Cells, i: usize, j: usize, x: &RelElem, imag: bool, neg: bool| {
        let (t, v) = if neg {
            part_neg(f, x, imag, sym)
        } else {
            part(f, x, imag, sym)
        };
        o.0[i][j] = t;
        o.1[i][j] = v;
    };
    let s = blk.a.nrows();
    for i in 0..s {
        for j in 0..s {
            let x = blk.a.get(i, j);
            let (o, q) = (off + 2 * i, off + 2 * j);
            put(a, o, q, x, false, false);
            put(a, o, q + 1, x, true, false);
            put(a, o + 1, q, x, true, true);
            put(a, o + 1, q + 1, x, false, false);
        }
        for j in 0..blk.b.ncols() {
            let x = blk.b.get(i, j);
            put(b, off + 2 * i, j, x, false, false);
            put(b, off + 2 * i + 1, j, x, true, true);
        }
        for row in 0..blk.c.nrows() {
            let x = f.mul(&two, blk.c.get(row, i));
            put(c, row, off + 2 * i, &x, false, false);
            put(c, row, off + 2 * i + 1, &x, true, false);
        }
    }
}

impl crate::realization::JordanMinimalK {
    /// The CLI report: the keys of the rational Jordan-method report (`order`,
    /// `mcmillan_degree`, `stages`, `A`..`D`, `modes`, `symbols`, `verified`).
    pub fn report(&self) -> Report {
        let r = self.order();
        let (m, p) = (self.d.ncols(), self.d.nrows());
        let empty = |rows: usize, cols: usize| {
            (
                vec![vec!["0".to_string(); cols]; rows],
                vec![vec![(0.0, 0.0); cols]; rows],
            )
        };
        let (mut a, mut b, mut c) = (empty(r, r), empty(r, m), empty(p, r));
        let mut off = 0;
        if let Some(real) = &self.real {
            for blk in real {
                let s = blk.order();
                let cells = [&mut a, &mut b, &mut c];
                match blk {
                    RealModalBlockK::Root(bk) => put_modal(bk, off, cells),
                    RealModalBlockK::Pair { field, a, b, c, .. } => {
                        put_block(field, [a, b, c], off, cells)
                    }
                    RealModalBlockK::Compact(bk) | RealModalBlockK::Radical(bk) => {
                        put_compact(bk, off, cells)
                    }
                }
                off += s;
            }
        }
        for blk in self.blocks.iter().filter(|_| self.real.is_none()) {
            put_modal(blk, off, [&mut a, &mut b, &mut c]);
            off += blk.a.nrows();
        }
        let out = |x: Cells| Value::Matrix(Box::new(MatrixOut::from_parts(x.0, x.1)));
        let compact = self
            .real
            .iter()
            .flatten()
            .any(|b| matches!(b, RealModalBlockK::Compact(_)));
        let presentation = match (&self.real, compact) {
            (None, _) => "complex modal form: one Jordan block group per eigenvalue r<k>, entries \
                          exact in K(r<k>)"
                .to_string(),
            (Some(_), false) => "real modal form: real eigenvalues as they are, each complex pair \
                                 a +- b*i as blocks [[a, b], [-b, a]] with I2 coupling, entries \
                                 exact in a real field; verified on the complex side (Markov \
                                 parameters through traces over K)"
                .to_string(),
            (Some(_), true) => "real modal form: real eigenvalues as they are, each complex pair \
                                a +- b*i as blocks [[a, b], [-b, a]]; a pair r<k> = a<k> + b<k>*i \
                                with a large real field is compact: entries Re(x), Im(x) of \
                                elements of K(r<k>); verified on the complex side (Markov \
                                parameters through traces over K)"
                .to_string(),
        };
        Report::titled("minimal realization (jordan)")
            .str("method", "jordan")
            .str("field", self.d.field().to_string())
            .int("original_order", self.stages[0])
            .int("order", r)
            .int("mcmillan_degree", self.mcmillan_degree)
            .with(
                "stages",
                Value::List(self.stages.iter().map(|&s| Value::Int(s as i64)).collect()),
            )
            .with("A", out(a))
            .with("B", out(b))
            .with("C", out(c))
            .matrix("D", &self.d)
            .with(
                "modes",
                crate::report::str_list(match &self.real {
                    Some(real) => real.iter().map(|b| b.eigenvalue()).collect::<Vec<_>>(),
                    None => self.blocks.iter().map(|b| b.eigenvalue.clone()).collect(),
                }),
            )
            .str("presentation", presentation)
            .with("symbols", super::realization::symbol_list(&self.symbols))
            .bool("verified", self.verified)
    }
}
