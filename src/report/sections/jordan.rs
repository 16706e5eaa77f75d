//! Reports of Jordan forms, real Jordan forms and free responses, written once for every base
//! field ([`crate::jordan::EigenField`]: $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$);
//! over $\mathbb{Q}(p)$, whose eigenvalues are functions of the parameters, the primary form
//! with its conditions ([`crate::jordan::jordan_qp`], [`crate::jordan::over_qp::real_form_qp`]).
//!
//! Presentation only: these `report` methods read finished results of [`crate::jordan`]
//! (matrices over the fields, algebraic numbers) and make every string of the CLI contract's
//! keys here; the math modules do not depend on [`crate::report`].

pub(super) use super::cells::Cells;
use super::eigenvalue_items;
use crate::algebraic::{Ext, ExtElem};
use crate::field::ElemDisplay;
use crate::field::Field;
use crate::jordan::qp_form::integral;
use crate::jordan::{
    CompactPair, EigenField, EigenValue, Eigenvalue, FreeResponse, JordanForm, NumberEigen,
    RealEntries, RealJordanForm,
};
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;
use crate::report::{MatrixOut, Report, Value, str_list};

/// `r<k> = <value>`, with `(over K: root of g)` when the factor over the base field is not
/// the eigenvalue's minimal polynomial over $\mathbb{Q}$.
pub(super) fn root_line<F: Field>(k: &F, e: &Eigenvalue<F>, g: &Poly<F>) -> String {
    let over = match e.value() {
        EigenValue::Number(z) if g.deg() != z.minpoly.deg() => format!(" (over {k}: root of {g})"),
        _ => String::new(),
    };
    format!("{} = {}{over}", e.symbol(), eigenvalue_value_text(k, e))
}

/// Whether the eigenvalue's field displays with its symbol (`r<k>`), so the symbol needs a
/// definition.
pub(super) fn named<F: Field>(f: &Ext<F>, e: &Eigenvalue<F>) -> bool {
    f.degree() >= 2 && f.var() == e.symbol()
}

/// `var = root of m near x` for a number field of degree $\ge 3$ shown with its generator.
pub(super) fn field_line(f: &crate::algebraic::NumberField) -> Option<String> {
    (f.degree() >= 3 || (f.degree() == 2 && f.radicand().is_none())).then(|| {
        format!(
            "{} = {}",
            f.var(),
            crate::report::display::value_display(f.modulus(), f.root_approx())
        )
    })
}

/// `-x` for a display string (`-b3`, `-(1 + sqrt(2))`).
pub(super) fn neg_display(x: &str) -> String {
    if x == "0" {
        return x.to_string();
    }
    if let Some(rest) = x.strip_prefix('-')
        && !rest.contains([' ', '+', '-'])
    {
        return rest.to_string();
    }
    // `Re(...)`, `Im(...)`: one call, no parentheses needed
    let call = (x.starts_with("Re(") || x.starts_with("Im(")) && x.ends_with(')') && {
        let mut depth = 0i32;
        x[2..].char_indices().all(|(i, ch)| {
            depth += match ch {
                '(' => 1,
                ')' => -1,
                _ => 0,
            };
            depth > 0 || i + 3 == x.len()
        })
    };
    if call {
        return format!("-{x}");
    }
    if x.contains([' ', '+']) || x[1..].contains('-') {
        format!("-({x})")
    } else {
        format!("-{x}")
    }
}

/// $q\sqrt g$ for rational $q$ and square-free $g > 0$ (`q` itself when $g = 1$).
fn im_radical(q: &crate::field::Rational, g: &num_bigint::BigInt) -> String {
    if num_traits::One::is_one(g) {
        crate::report::display::fmt_rational(q)
    } else {
        crate::report::display::fmt_pair(&num_traits::Zero::zero(), q, &format!("sqrt({g})"))
    }
}

/// `Re x` (`imag` false) or `Im x` of $x \in E$ at a root $\theta = a_0 + s\sqrt f$
/// ($f < 0$) of a rational quadratic factor, exact: $x = c_0 + c_1\theta$ has
/// $\operatorname{Re} x = c_0 + a_0 c_1 \in F$ and $\operatorname{Im} x = (s c_1)
/// \sqrt{-f}$, written `u` and `w*sqrt(-f)` (`None` without the radical form).
fn radical_part<F: Field>(f: &Ext<F>, x: &ExtElem<F::Elem>, imag: bool) -> Option<String> {
    let (a0, s, fd) = f.0.radical.as_ref()?;
    let kf = f.base();
    let c0 = x.0.first().cloned().unwrap_or_else(|| kf.zero());
    let c1 = x.0.get(1).cloned().unwrap_or_else(|| kf.zero());
    if !imag {
        return Some(kf.fmt_elem(&kf.add(&c0, &kf.mul(&kf.from_rational(a0), &c1))));
    }
    let w = kf.mul(&kf.from_rational(s), &c1);
    let g = -fd;
    let rad = format!("sqrt({g})");
    Some(match kf.to_rational(&w) {
        Some(q) => im_radical(&q, &g),
        None if num_traits::One::is_one(&g) => kf.fmt_elem(&w),
        None => {
            let wt = kf.fmt_elem(&w);
            if wt[1..].contains([' ', '+', '-']) {
                format!("({wt})*{rad}")
            } else {
                format!("{wt}*{rad}")
            }
        }
    })
}

/// `Re(x)` / `Im(x)` display of an element of $E$ at $\theta$: exact parts for the radical
/// form, plain when it lies in the base field, `theta` (the displays of
/// $\operatorname{Re}\theta$, $\operatorname{Im}\theta$) for $\pm\theta$ itself.
pub(super) fn part_text<F: Field>(
    f: &Ext<F>,
    x: &ExtElem<F::Elem>,
    imag: bool,
    theta: (&str, &str),
) -> String {
    if let Some(t) = radical_part(f, x, imag) {
        return t;
    }
    if f.is_zero(x) {
        return "0".into();
    }
    if let Some(c) = f.to_base(x) {
        return if imag {
            "0".into()
        } else {
            f.base().fmt_elem(&c)
        };
    }
    if *x == f.generator() {
        return (if imag { theta.1 } else { theta.0 }).to_string();
    }
    if f.neg(x) == f.generator() {
        return neg_display(if imag { theta.1 } else { theta.0 });
    }
    format!("{}({})", if imag { "Im" } else { "Re" }, f.fmt_elem(x))
}

/// The displays of $\operatorname{Re}\theta$, $\operatorname{Im}\theta$ of a pair: closed
/// forms up to degree 2, else the symbols `a<k>`, `b<k>`.
pub(super) fn theta_parts<F: Field>(cp: &CompactPair<F>, e: &Eigenvalue<F>) -> (String, String) {
    let k = e.index;
    let show = |x: &Option<crate::algebraic::AlgebraicNumber>, sym: String| match x {
        Some(x) if x.degree() <= 2 => x.value_string(),
        _ => sym,
    };
    (show(&cp.re, format!("a{k}")), show(&cp.im, format!("b{k}")))
}

/// The legend lines of a compact pair: `r<k> = a<k> + b<k>*i` and each part's definition
/// (a closed form where there is one, else `root of P near X`; a part not computed exactly
/// is `near X`).
fn part_lines<F: NumberEigen>(e: &Eigenvalue<F>, cp: &CompactPair<F>) -> Vec<String> {
    let (re, im) = theta_parts(cp, e);
    let k = e.index;
    let define = |sym: String, what: &str, x: &Option<crate::algebraic::AlgebraicNumber>, v| match x
    {
        Some(x) if x.degree() <= 2 => None,
        Some(x) => Some(format!(
            "{sym} = {what} {} = {}",
            e.symbol(),
            x.value_string()
        )),
        None => Some(format!(
            "{sym} = {what} {}, near {}",
            e.symbol(),
            crate::report::display::approx_text((v, 0.0))
        )),
    };
    let mut out = vec![format!("{} = {re} + {im}*i", e.symbol())];
    out.extend(define(format!("a{k}"), "Re", &cp.re, e.approx.0));
    out.extend(define(format!("b{k}"), "Im", &cp.im, e.approx.1));
    out
}

/// The exact display of an eigenvalue (one number display: rational, closed form up to
/// degree 2 and for biquadratics, else `root of <minpoly> near <approx>`), from its minimal
/// polynomial and the approximation that marks the root.
pub fn eigenvalue_text<F: NumberEigen>(e: &Eigenvalue<F>) -> String {
    crate::report::display::value_display(&e.minpoly, e.approx)
}

/// The display of an eigenvalue over any base field `k`: a certified number as
/// [`eigenvalue_text`], an element of the field (over $\mathbb{Q}(p)$) as the field writes
/// it, the roots of a factor $g$ of degree $\ge 2$ as `root of g`.
pub fn eigenvalue_value_text<F: Field>(k: &F, e: &Eigenvalue<F>) -> String {
    match e.value() {
        EigenValue::Number(z) => crate::report::display::value_display(&z.minpoly, z.approx),
        EigenValue::InField(x) => k.fmt_elem(x),
        EigenValue::RootOf(g) => format!("root of {g}"),
    }
}

impl<F: EigenField> JordanForm<F> {
    /// $J$ and $T$ for output: per eigenvalue, entries exact in its field (texts, LaTeX and
    /// approximations).
    pub fn j_t_out(&self) -> (MatrixOut, MatrixOut) {
        let n = self.n();
        let (mut j, mut t) = (Cells::zeros(n, n), Cells::zeros(n, n));
        let mut off = 0;
        for c in self.root_columns() {
            t.block((0, off), &c.v);
            j.block((off, off), &c.j);
            off += c.v.ncols();
        }
        (j.0, t.0)
    }
    /// The report with the CLI contract's keys: `eigenvalues[]` (`minpoly`, `value`,
    /// `approx`, `algebraic_multiplicity`, `geometric_multiplicity`, `blocks`), `J`, `T`
    /// (exact, with `_approx`), `verified`, plus `n`, `field`, `charpoly`, `presentation`,
    /// `symbols`.
    pub fn report(&self) -> Report {
        let k = self.base();
        let single = self.single_field();
        let presentation = match &single {
            Some((j, _)) if j.field().degree() == 1 => format!("single matrix over {k}"),
            Some((j, _)) => format!("single matrix over QQ({})", j.field().var()),
            None => format!(
                "per eigenvalue: the columns of eigenvalue r<k> are exact in {k}(r<k>), written \
                 as polynomials in r<k> over {k} (closed form or radical for degree <= 2)"
            ),
        };
        let symbols: Vec<Value> = (0..self.eigenvalues.len())
            .filter(|&ev| named(&self.root_map(ev).0, &self.eigenvalues[ev]))
            .map(|ev| {
                let e = &self.eigenvalues[ev];
                Value::Str(root_line(k, e, &self.components[e.component].factor))
            })
            .collect();
        let (jo, to) = match single {
            Some((j, t)) => (
                Value::Matrix(Box::new(MatrixOut::from_matrix(&j))),
                Value::Matrix(Box::new(MatrixOut::from_matrix(&t))),
            ),
            None => {
                let (j, t) = self.j_t_out();
                (Value::Matrix(Box::new(j)), Value::Matrix(Box::new(t)))
            }
        };
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

/// The legend of a real Jordan form: `symbols` (eigenvalues of compact pairs), `fields`
/// (generators of the fields shown with a symbol), `parts` (the parts of $\theta$).
#[derive(Default)]
struct Legend {
    symbols: Vec<String>,
    fields: Vec<String>,
    parts: Vec<String>,
}

impl<F: EigenField> RealJordanForm<F> {
    /// `J`, `T` (exact texts, LaTeX and approximations) and the legend.
    fn cells(&self) -> (Cells, Cells, Legend) {
        let n = self.n;
        let (mut jc, mut tc) = (Cells::zeros(n, n), Cells::zeros(n, n));
        let mut legend = Legend::default();
        let mut off = 0;
        for b in &self.blocks {
            let e = &self.eigenvalues[b.eigenvalue];
            let g = &self.factors[e.component];
            let w = b.j_approx.len();
            match &b.entries {
                RealEntries::Root { field, t, j } => {
                    if named(field, e) {
                        legend.fields.push(root_line(&self.base, e, g));
                    }
                    tc.block((0, off), t);
                    jc.block((off, off), j);
                }
                RealEntries::Expanded { pair, t, j } => {
                    let f = &pair.field;
                    if f.degree() >= 3 {
                        legend.fields.extend(field_line(f));
                        let th = pair.theta();
                        legend.parts.push(format!(
                            "{} = {} + ({})*i",
                            e.symbol(),
                            f.fmt_elem(&th.re),
                            f.fmt_elem(&th.im)
                        ));
                    }
                    tc.block((0, off), t);
                    jc.block((off, off), j);
                }
                RealEntries::Compact(cp) | RealEntries::Radical(cp) => {
                    if b.is_compact() {
                        legend.symbols.push(root_line(&self.base, e, g));
                        legend.parts.extend(part_lines(e, cp));
                    }
                    let (a, bb) = theta_parts(cp, e);
                    for r in 0..n {
                        for q in 0..w {
                            let x = cp.v.get(r, q / 2);
                            let txt = part_text(&cp.field, x, q % 2 == 1, (&a, &bb));
                            tc.text((r, off + q), txt, b.t_approx[r][q]);
                        }
                    }
                    for r in 0..w {
                        for q in 0..w {
                            let txt = if r / 2 == q / 2 {
                                match (r % 2, q % 2) {
                                    (0, 0) | (1, 1) => a.clone(),
                                    (0, 1) => bb.clone(),
                                    _ => neg_display(&bb),
                                }
                            } else if b.j_approx[r][q] == 1.0 {
                                "1".to_string()
                            } else {
                                "0".to_string()
                            };
                            jc.text((off + r, off + q), txt, b.j_approx[r][q]);
                        }
                    }
                }
            }
            off += w;
        }
        (jc, tc, legend)
    }
    /// $J$, $T$ for output (exact texts in each block's field).
    pub fn j_t_out(&self) -> (MatrixOut, MatrixOut) {
        let (j, t, _) = self.cells();
        (j.0, t.0)
    }
    /// The notes, one line per pair left compact although its real field was asked for.
    pub fn note_lines(&self) -> Vec<String> {
        self.notes
            .iter()
            .map(|note| {
                let e = &self.eigenvalues[note.eigenvalue];
                format!(
                    "eigenvalue {} (root of {}): exact real field not found ({}); compact exact \
                     form given instead",
                    e.symbol(),
                    e.minpoly,
                    note.error
                )
            })
            .collect()
    }
    /// Report: `J`, `T` (exact texts and `_approx`), `exact`, `verified`, and for the compact
    /// form `presentation` and `symbols`, then `fields`, `parts`, `notes` (each when not
    /// empty).
    pub fn report(&self) -> Report {
        let (j, t, legend) = self.cells();
        let mut r = Report::titled("Real Jordan form")
            .with("J", j.value())
            .with("T", t.value())
            .bool("exact", self.exact)
            .bool("verified", self.verified);
        let strs = |xs: Vec<String>| xs.into_iter().map(Value::Str).collect::<Vec<_>>();
        if self.blocks.iter().any(|b| b.is_compact()) {
            let k = &self.base;
            let presentation = format!(
                "compact: each complex pair r<k> = a<k> + b<k>*i has the block [[a, b], [-b, a]] \
                 and the columns Re v, Im v of its complex chains v in {k}(r<k>) (T_R = T_C S); \
                 verified on the complex side (A T_C = T_C J_C in {k}(r<k>), which implies \
                 A T_R = T_R J_R); `--expand` writes the entries in a real field"
            );
            r = r
                .str("presentation", presentation)
                .list("symbols", strs(legend.symbols));
        }
        let notes = self.note_lines();
        for (key, xs) in [
            ("fields", legend.fields),
            ("parts", legend.parts),
            ("notes", notes),
        ] {
            if !xs.is_empty() {
                r = r.list(key, strs(xs));
            }
        }
        r
    }
}

impl<F: EigenField> FreeResponse<Ext<F>> {
    /// Report: one entry per eigenvalue and power, `x(t) = sum t^k e^(s t) G x0` (`G` exact
    /// in the eigenvalue's field), and `verified` ([`FreeResponse::verify`]: the derivative
    /// and the value at `t = 0`).
    pub fn report(&self, jf: &JordanForm<F>) -> Report {
        let items = response_terms(jf, "G", |ev| self.terms_of(jf, ev));
        Report::titled("Free response x(t) = sum_k t^k e^(s t) G x0")
            .list("terms", items)
            .bool("verified", self.verify(jf))
    }
}

/// The terms of a free response, one per eigenvalue and power (`terms_of(ev)`: the powers
/// and matrices of eigenvalue `ev`), the matrix under `key`.
pub(super) fn response_terms<F: EigenField>(
    jf: &JordanForm<F>,
    key: &str,
    terms_of: impl Fn(usize) -> Vec<(usize, crate::matrix::Matrix<Ext<F>>)>,
) -> Vec<Value> {
    let mut items = vec![];
    for (ev, e) in jf.eigenvalues.iter().enumerate() {
        for (power, g) in terms_of(ev) {
            items.push(Value::Obj(
                Report::new()
                    .str("eigenvalue", eigenvalue_text(e))
                    .int("power", power)
                    .matrix(key, &g),
            ));
        }
    }
    items
}

/// A matrix over any field as rows of exact strings.
fn rows<K: Field>(m: &crate::matrix::Matrix<K>) -> Value {
    let k = m.field();
    Value::List(
        (0..m.nrows())
            .map(|i| str_list(m.row(i).iter().map(|x| k.fmt_elem(x))))
            .collect(),
    )
}

/// The name of the eigenvalue variable in displays over $\mathbb{Q}(p)$: `s` unless a
/// parameter is called so (then `x`, then `lambda_`).
pub fn qp_var_name(vars: &[String]) -> String {
    for c in ["s", "x", "lambda_"] {
        if !vars.iter().any(|v| v == c) {
            return c.to_string();
        }
    }
    "lambda__".to_string()
}

/// $\chi_A$ over $\mathbb{Q}(p)$ as `s^4 + (cr/(m*u))*s^3` (coefficients in parentheses).
fn charpoly_qp(k: &RatFuncField, p: &Poly<RatFuncField>, s: &str) -> String {
    let mut parts = vec![];
    for (i, c) in p.coeffs().iter().enumerate().rev() {
        if k.is_zero(c) {
            continue;
        }
        let mono = match i {
            0 => String::new(),
            1 => s.to_string(),
            _ => format!("{s}^{i}"),
        };
        let cf = k.fmt_elem(c);
        parts.push(match (mono.is_empty(), k.is_one(c)) {
            (true, _) => format!("({cf})"),
            (false, true) => mono,
            (false, false) => format!("({cf})*{mono}"),
        });
    }
    if parts.is_empty() {
        "0".to_string()
    } else {
        parts.join(" + ")
    }
}

/// The conditions of a result over $\mathbb{Q}(p)$ as display strings.
pub fn conditions_qp(jf: &JordanForm<RatFuncField>) -> Vec<String> {
    let vars = jf.base().vars();
    jf.conditions
        .iter()
        .map(|c| c.num().display_normalized().to_string_vars(vars))
        .collect()
}

impl JordanForm<RatFuncField> {
    /// The report over $\mathbb{Q}(p)$ ([`crate::jordan::jordan_qp`]): `field`, `n`,
    /// `charpoly`, `charpoly_factored` (in $\mathbb{Z}\lbrack p, s\rbrack$), `eigenvalues[]`
    /// (`value` in $\mathbb{Q}(p)$ or `roots_of` the factor, `factor`, `degree`, the
    /// multiplicities, `blocks`, `kernel_dims` of $g(A)^k$ over $\mathbb{Q}(p)$), `J`, `T` (the
    /// primary form), `presentation`, `conditions`, `verified`.
    pub fn report(&self) -> Report {
        let k = self.base();
        let s = qp_var_name(k.vars());
        let mut vars = k.vars().to_vec();
        vars.push(s.clone());
        let ints = |xs: &[usize]| Value::List(xs.iter().map(|&b| Value::Int(b as i64)).collect());
        let (mut evs, mut factors) = (vec![], vec![]);
        for e in &self.eigenvalues {
            let c = &self.components[e.component];
            let big = integral(&c.factor);
            let f = big.to_string_vars(&vars);
            let r = match e.value() {
                EigenValue::InField(v) => Report::new().str("value", k.fmt_elem(v)),
                _ => Report::new().str("roots_of", format!("{f} = 0")),
            };
            let dims: Vec<usize> = c.kernel_dims.iter().map(|x| x * c.degree()).collect();
            evs.push(Value::Obj(
                r.str("factor", f.clone())
                    .int("degree", c.degree())
                    .int("algebraic_multiplicity", e.algebraic_multiplicity)
                    .int("geometric_multiplicity", e.geometric_multiplicity)
                    .with("blocks", ints(&e.blocks))
                    .with("kernel_dims", ints(&dims)),
            ));
            let f = if big.len() > 1 { format!("({f})") } else { f };
            factors.push(match c.multiplicity {
                1 => f,
                e => format!("{f}^{e}"),
            });
        }
        let presentation = if self.complete() {
            "every eigenvalue in the field: J is the Jordan matrix, T its chains"
        } else {
            "eigenvalues of irreducible factors of degree >= 2 are roots of that factor: their \
             diagonal block of J is the restriction of A to ker f(A)^e (T: a basis of it); \
             their Jordan blocks are listed under eigenvalues[].blocks"
        };
        let mut r = Report::titled("Jordan form over QQ(p)")
            .str("field", k.to_string())
            .int("n", self.n())
            .str("charpoly", charpoly_qp(k, &self.charpoly, &s))
            .str("charpoly_factored", factors.join("*"))
            .list("eigenvalues", evs);
        r = match self.primary_form() {
            Ok((t, j)) => r.with("J", rows(&j)).with("T", rows(&t)),
            Err(err) => r.str("error", err.to_string()),
        };
        r.str("presentation", presentation)
            .with("conditions", str_list(conditions_qp(self)))
            .bool("verified", self.verified)
    }
}

impl crate::jordan::over_qp::QpRealForm {
    /// The CLI report of `jordan --real` over $\mathbb{Q}(p)$: `field`, `n`, `charpoly`,
    /// `components[]` (an eigenvalue in $\mathbb{Q}(p)$ with `blocks` and its chains `T`, or
    /// a pair with `factor`, `real_part`, `imaginary_part`, `complex_where`, `blocks`,
    /// `J_real`, `T_real` over $\mathbb{Q}(p)(w)$), `conditions`, `verified`.
    pub fn report(&self) -> Report {
        let k = self.a.field();
        let comps = self
            .components
            .iter()
            .zip(&self.pairs)
            .map(|(c, pair)| {
                let blocks = Value::List(c.blocks.iter().map(|&b| Value::Int(b as i64)).collect());
                let r = match pair {
                    None => {
                        let theta = k.neg(&c.factor.monic().coeff(0));
                        let e = &c.field;
                        let t = c
                            .chains
                            .map(k, |x| e.to_base(x).unwrap_or_else(|| k.zero()));
                        Report::new()
                            .str("eigenvalue", k.fmt_elem(&theta))
                            .with("blocks", blocks)
                            .with("T", rows(&t))
                    }
                    Some(p) => {
                        let w = p.field.var();
                        Report::new()
                            .str("factor", c.factor.to_string_var("s"))
                            .str("real_part", k.fmt_elem(&p.re))
                            .str(
                                "imaginary_part",
                                format!("{w} = sqrt({})", k.fmt_elem(&p.im_squared)),
                            )
                            .str(
                                "complex_where",
                                format!("{} < 0", k.fmt_elem(&p.discriminant)),
                            )
                            .with("blocks", blocks)
                            .with("J_real", rows(&p.j))
                            .with("T_real", rows(&p.t))
                            .bool("verified", p.verified)
                    }
                };
                Value::Obj(r)
            })
            .collect();
        Report::titled("real Jordan form over QQ(p)")
            .str("field", k.to_string())
            .int("n", self.a.nrows())
            .str("charpoly", self.charpoly.charpoly.to_string_var("s"))
            .list("components", comps)
            .str(
                "presentation",
                "eigenvalues in QQ(p) with their Jordan chains; each quadratic factor s^2 + b s + c \
                 as blocks [[a, w], [-w, a]] (I2 coupling), a = -b/2, w = sqrt(c - b^2/4), a \
                 complex pair exactly where b^2 - 4c < 0; A T = T J checked exactly with w a \
                 symbol (w^2 = c - b^2/4)",
            )
            .bool("verified", self.verified)
    }
}

impl<F: EigenField> std::fmt::Display for JordanForm<F> {
    /// The text report: eigenvalues with their blocks, `J`, `T`, `verified`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.report().to_text())
    }
}

impl<F: EigenField> std::fmt::Display for RealJordanForm<F> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.report().to_text())
    }
}
