//! Reports of minimal realizations, the modal table and descriptor conversion.
//!
//! Presentation only: these `report` methods read finished results of [`crate::realization`] and
//! build the CLI contract's keys; the math modules do not depend on [`crate::report`].

use super::jordan::{
    Cells, eigenvalue_value_text, field_line, named, neg_display, part_text, root_line,
};
use crate::algebraic::ExtElem;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::realization::{
    JordanMethod, JordanMinimal, MinimalRealization, ModalBlock, ModalTable, PrimaryJordanMinimal,
    RealModalBlock, StandardForm,
};
use crate::report::{Report, Value, str_list};

/// Writes a block $(A, B, C)$ at offset `off`: block-diagonal `A`, stacked `B`, `C`.
fn put_block<K: Field>([ba, bb, bc]: [&Matrix<K>; 3], off: usize, [a, b, c]: [&mut Cells; 3]) {
    a.block((off, off), ba);
    b.block((off, 0), bb);
    c.block((0, off), bc);
}

/// Writes the compact real block of a pair (complex data `blk` of the upper root) at `off`:
/// state `2i` is $\mathrm{Re}\, z_i$, state `2i + 1` is $-\mathrm{Im}\, z_i$, so
/// $A_r = [[\mathrm{Re}, \mathrm{Im}], [-\mathrm{Im}, \mathrm{Re}]]$ of $J$,
/// $B_r = [\mathrm{Re}; -\mathrm{Im}]$ of $WB$, $C_r = [\mathrm{Re}, \mathrm{Im}]$ of $2CV$;
/// `a<k>`, `b<k>` stand for the parts of $\theta$ (exact parts in the radical form).
fn put_compact<F: Field>(blk: &ModalBlock<F>, sym: &str, off: usize, [a, b, c]: [&mut Cells; 3]) {
    let f = &blk.field;
    let k = &sym[1..];
    let (ta, tb) = (format!("a{k}"), format!("b{k}"));
    let two = f.from_i64(2);
    let put = |o: &mut Cells, at: (usize, usize), x: &ExtElem<F::Elem>, imag: bool, neg: bool| {
        let (re, im) = f.approx(x);
        let v = if imag { im } else { re };
        let t = part_text(f, x, imag, (&ta, &tb));
        let (t, v) = if neg { (neg_display(&t), -v) } else { (t, v) };
        o.text(at, t, v);
    };
    let s = blk.a.nrows();
    for i in 0..s {
        for j in 0..s {
            let x = blk.a.get(i, j);
            let (o, q) = (off + 2 * i, off + 2 * j);
            put(a, (o, q), x, false, false);
            put(a, (o, q + 1), x, true, false);
            put(a, (o + 1, q), x, true, true);
            put(a, (o + 1, q + 1), x, false, false);
        }
        for j in 0..blk.b.ncols() {
            let x = blk.b.get(i, j);
            put(b, (off + 2 * i, j), x, false, false);
            put(b, (off + 2 * i + 1, j), x, true, true);
        }
        for row in 0..blk.c.nrows() {
            let x = f.mul(&two, blk.c.get(row, i));
            put(c, (row, off + 2 * i), &x, false, false);
            put(c, (row, off + 2 * i + 1), &x, true, false);
        }
    }
}

impl<F: Field> JordanMinimal<F> {
    /// The display of mode `blk` (a pair: `... (and its conjugate)`).
    fn mode_text(&self, ev: usize, pair: bool) -> String {
        let v = eigenvalue_value_text(self.jordan.base(), &self.jordan.eigenvalues[ev]);
        if pair {
            format!("{v} (and its conjugate)")
        } else {
            v.clone()
        }
    }
    /// `name = definition` of every symbol in the entries.
    fn symbols(&self) -> Vec<String> {
        let jf = &self.jordan;
        let k = jf.base();
        let line = |ev: usize| {
            let e = &jf.eigenvalues[ev];
            root_line(k, e, &jf.components[e.component].factor)
        };
        let named_root = |b: &ModalBlock<F>| named(&b.field, &jf.eigenvalues[b.eigenvalue]);
        let mut out = vec![];
        match &self.real {
            None => out.extend(
                self.blocks
                    .iter()
                    .filter(|b| named_root(b))
                    .map(|b| line(b.eigenvalue)),
            ),
            Some(real) => {
                for blk in real {
                    match blk {
                        RealModalBlock::Root(b) if named_root(b) => out.push(line(b.eigenvalue)),
                        RealModalBlock::Pair { pair, .. } => out.extend(field_line(&pair.field)),
                        RealModalBlock::Compact(b) => {
                            let e = &jf.eigenvalues[b.eigenvalue];
                            let (kk, sym) = (e.index, e.symbol());
                            out.push(line(b.eigenvalue));
                            out.push(format!("a{kk} = Re {sym}"));
                            out.push(format!("b{kk} = Im {sym}"));
                        }
                        _ => {}
                    }
                }
            }
        }
        out
    }
    /// The CLI report: `method`, `field`, `original_order`, `order`, `mcmillan_degree`,
    /// `stages`, `A`..`D`, `modes`, `presentation`, `symbols`, `verified`.
    pub fn report(&self) -> Report {
        let r = self.order();
        let (m, p) = (self.d.ncols(), self.d.nrows());
        let (mut a, mut b, mut c) = (Cells::zeros(r, r), Cells::zeros(r, m), Cells::zeros(p, r));
        let mut off = 0;
        let mut modes = vec![];
        match &self.real {
            Some(real) => {
                for blk in real {
                    let cells = [&mut a, &mut b, &mut c];
                    match blk {
                        RealModalBlock::Root(bk) => put_block([&bk.a, &bk.b, &bk.c], off, cells),
                        RealModalBlock::Pair { a, b, c, .. } => put_block([a, b, c], off, cells),
                        RealModalBlock::Compact(bk) | RealModalBlock::Radical(bk) => {
                            let sym = self.jordan.eigenvalues[bk.eigenvalue].symbol();
                            put_compact(bk, &sym, off, cells)
                        }
                    }
                    modes.push(self.mode_text(blk.eigenvalue(), blk.is_pair()));
                    off += blk.order();
                }
            }
            None => {
                for bk in &self.blocks {
                    put_block([&bk.a, &bk.b, &bk.c], off, [&mut a, &mut b, &mut c]);
                    modes.push(self.mode_text(bk.eigenvalue, false));
                    off += bk.a.nrows();
                }
            }
        }
        let compact = self
            .real
            .iter()
            .flatten()
            .any(|b| matches!(b, RealModalBlock::Compact(_)));
        let k = self.d.field();
        let presentation = match (&self.real, compact) {
            (None, _) => format!(
                "complex modal form: one Jordan block group per eigenvalue r<k>, entries exact in \
                 {k}(r<k>)"
            ),
            (Some(_), false) => "real modal form: real eigenvalues as they are, each complex pair \
                                 a +- b*i as blocks [[a, b], [-b, a]] with I2 coupling, entries \
                                 exact in a real field; verified on the complex side (Markov \
                                 parameters through traces)"
                .to_string(),
            (Some(_), true) => format!(
                "real modal form: real eigenvalues as they are, each complex pair a +- b*i as \
                 blocks [[a, b], [-b, a]]; a pair r<k> = a<k> + b<k>*i with a large real field \
                 is compact: entries Re(x), Im(x) of elements of {k}(r<k>); verified on the \
                 complex side (Markov parameters through traces)"
            ),
        };
        Report::titled("minimal realization (jordan)")
            .str("method", "jordan")
            .str("field", k.to_string())
            .int("original_order", self.stages[0])
            .int("order", r)
            .int("mcmillan_degree", self.mcmillan_degree)
            .with(
                "stages",
                Value::List(self.stages.iter().map(|&s| Value::Int(s as i64)).collect()),
            )
            .with("A", a.value())
            .with("B", b.value())
            .with("C", c.value())
            .matrix("D", &self.d)
            .with("modes", str_list(modes))
            .str("presentation", presentation)
            .with(
                "symbols",
                Value::List(self.symbols().into_iter().map(Value::Str).collect()),
            )
            .bool("verified", self.verified)
    }
}

impl<K: Field> MinimalRealization<K> {
    /// The CLI report (`order`, `mcmillan_degree`, `A`..`D`, `verified`); by the
    /// Jordan-form method, the method's own report (its modal or primary blocks).
    pub fn report(&self) -> Report {
        match &self.jordan {
            Some(JordanMethod::Modal(m)) => {
                return m.report().set("verified", Value::Bool(self.verified));
            }
            Some(JordanMethod::Primary(p)) => {
                return p.report().set("verified", Value::Bool(self.verified));
            }
            None => {}
        }
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
                for (k, v) in m.exact_texts() {
                    ex.push(k, Value::Str(v));
                }
                Value::Obj(
                    Report::new()
                        .str("eigenvalue", m.eigenvalue.value_string())
                        .str("minpoly", m.eigenvalue.minpoly().to_string())
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

impl crate::realization::Mode {
    /// The exact figures as `(name, display)`: rationals, `sqrt(r)` in the one display of
    /// quadratic numbers, a negative root with a leading `-`.
    pub fn exact_texts(&self) -> Vec<(String, String)> {
        use crate::realization::ExactFigure;
        self.exact
            .iter()
            .map(|(k, v)| {
                let text = match v {
                    ExactFigure::Rational(q) => crate::report::display::fmt_rational(q),
                    ExactFigure::Sqrt { radicand, negative } => {
                        let s = sqrt_display(radicand);
                        if *negative { format!("-{s}") } else { s }
                    }
                };
                (k.to_string(), text)
            })
            .collect()
    }
}

/// `sqrt(r)` as an exact display.
fn sqrt_display(r: &crate::field::Rational) -> String {
    let (field, a, b) = crate::field::QuadraticField::sqrt_of_rational(r);
    match field {
        None => crate::report::display::fmt_rational(&a),
        Some(k) => crate::report::display::quadratic_display(&num_traits::Zero::zero(), &b, k.d()),
    }
}

/// One row of the modal table's text: the mode (exact when short, the pair as `a ± b i`,
/// an unpaired eigenvalue of a non-real matrix as `a + b i`, otherwise), its multiplicity, frequency in Hz, damping ratio and time constant.
fn mode_row(m: &crate::realization::Mode) -> Vec<String> {
    use crate::report::text::{MAX_EXACT_ENTRY, short};
    let (re, im) = m.approx;
    let value = m.eigenvalue.value_string();
    let mode = if value.chars().count() <= MAX_EXACT_ENTRY {
        value
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

impl<F: Field> std::fmt::Display for JordanMinimal<F> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.report().to_text())
    }
}

impl<F: Field> PrimaryJordanMinimal<F> {
    /// One line per retained component: its eigenvalue (a factor of degree 1) or the factor
    /// whose roots its primary block carries, with the Jordan block sizes and its states.
    pub fn mode_lines(&self) -> Vec<String> {
        let k = self.system.a.field();
        self.blocks
            .iter()
            .map(|b| {
                let comp = &self.components[b.component];
                let g = &comp.factor;
                let sizes: Vec<String> = b.blocks.iter().map(|s| s.to_string()).collect();
                let states = format!("states {}..{}", b.offset + 1, b.offset + b.order);
                if g.deg() == 1 {
                    let theta = k.neg(&g.monic().coeff(0));
                    format!(
                        "eigenvalue {} (Jordan blocks {}): {states}",
                        k.fmt_elem(&theta),
                        sizes.join(", ")
                    )
                } else if b.is_restriction() {
                    format!(
                        "roots of {} (Jordan blocks {} per root; primary block, the \
                         restriction of A to ker g(A)): {states}",
                        g.to_string_var("s"),
                        sizes.join(", ")
                    )
                } else {
                    format!(
                        "roots of {} (Jordan blocks {} per root; primary block, regular \
                         representation of the factor's field in the basis 1, t, .., t^{}): \
                         {states}",
                        g.to_string_var("s"),
                        sizes.join(", "),
                        g.deg() - 1
                    )
                }
            })
            .collect()
    }
    /// The CLI report: `method`, `field`, `original_order`, `order`, `mcmillan_degree`,
    /// `stages`, `A`..`D`, `modes`, `presentation`, `verified`.
    pub fn report(&self) -> Report {
        let s = &self.system;
        Report::titled("minimal realization (jordan)")
            .str("method", "jordan")
            .str("field", s.a.field().to_string())
            .int("original_order", self.stages[0])
            .int("order", s.nstates())
            .int("mcmillan_degree", self.mcmillan_degree)
            .with(
                "stages",
                Value::List(self.stages.iter().map(|&x| Value::Int(x as i64)).collect()),
            )
            .matrix("A", &s.a)
            .matrix("B", &s.b)
            .matrix("C", &s.c)
            .matrix("D", &s.d)
            .with("modes", str_list(self.mode_lines()))
            .str(
                "presentation",
                "modal form over the base field: an eigenvalue in the field as its Jordan \
                 blocks, the roots of an irreducible factor of degree d >= 2 as one primary \
                 block (d states per Jordan state); verified by C A^k B equal for k < n + r and \
                 the order equal to the McMillan degree",
            )
            .bool("verified", self.verified)
    }
}
