//! A derivation (`--steps --format latex`) typeset as a worked example: one numbered step per
//! paragraph (its sentence), the objects it computed in display math (matrices as `bmatrix`
//! with the field's own LaTeX entries, polynomials with their coefficients as fractions), the
//! identity it establishes with its exact verdict, and what it assumes. With `--standalone`
//! a complete A4 document (`article`, 2 cm margins); matrices wider than 10 columns are set
//! small, wider than 20 in column blocks, so every page is A4.

use super::escape::latex_text;
use super::latex::lines::{TEXT_PT, display, width_pt};
use super::steps::{generic_root, identity, kind_name, step_field, theta_step, title};
use crate::field::Field;
use crate::jordan::derivation::{Derivation, Object, Step, StepKind};
use crate::matrix::Matrix;
use crate::poly::Poly;
use std::fmt::Write;

/// Most columns of a matrix set in one block.
const BLOCK_COLS: usize = 20;
/// The A4 text width with 2 cm margins, in mm (a little less, for the brackets).
const TEXT_MM: f64 = 145.0;

/// The math symbol of an object key, in the variable `var`.
fn symbol(kind: StepKind, key: &str, var: &str) -> String {
    super::steps::in_variable(&symbol_in_s(kind, key), var)
}

fn symbol_in_s(kind: StepKind, key: &str) -> String {
    match (kind, key) {
        (StepKind::KalmanBasis, "dims") => {
            return r"\dim X_{c\bar o},\,\dim X_{co},\,\dim X_{\bar c\bar o},\,\dim X_{\bar co}"
                .into();
        }
        (StepKind::Similarity, "dims") => return r"d_i\,m_i".into(),
        (StepKind::PrimaryBlock, "dims") => return r"\dim\ker f(A)^k".into(),
        (StepKind::Restriction, "g") => return "g(s)".into(),
        (StepKind::Restriction, "deg") => return r"\deg g".into(),
        (StepKind::Restriction, "Ag") => return "A_g".into(),
        (StepKind::Restriction, "PB") => return "P B".into(),
        (StepKind::Restriction, "Cu") => return "C u".into(),
        (StepKind::Stages, "Ar") => return "A_r".into(),
        (StepKind::Stages, "Br") => return "B_r".into(),
        (StepKind::Stages, "Cr") => return "C_r".into(),
        (StepKind::Stages, "Dr") => return "D_r".into(),
        // the algebraic multiplicity: not `m`, which a system's parameter may be called
        (StepKind::KernelSequence, "m") => return r"\mu".into(),
        _ => {}
    }
    if let Some(sym) = super::steps_more::symbol(kind, key) {
        return sym.into();
    }
    match key {
        "chi" => r"\chi_A(s)".into(),
        "factors" => r"\chi_A(s)".into(),
        "theta" => r"\theta".into(),
        "ranks" => r"\operatorname{rank} N^k".into(),
        "dims" => r"\dim\ker N^k".into(),
        "weyr" => "w".into(),
        "segre" => r"\text{blocks}".into(),
        "Ctrb" => r"\mathcal C".into(),
        "Obsv" => r"\mathcal O".into(),
        "Nobs" => r"\mathcal N".into(),
        "R" => r"\mathcal R".into(),
        "At" => r"\tilde A".into(),
        "Bt" => r"\tilde B".into(),
        "Ct" => r"\tilde C".into(),
        "Am" => "A_{22}".into(),
        "Bm" => "B_2".into(),
        "Cm" => "C_2".into(),
        "WB" => "W B".into(),
        "CV" => "C V".into(),
        "Jk" => r"J_{\mathrm{kept}}".into(),
        "Bk" => r"(W B)_{\mathrm{kept}}".into(),
        "Ck" => r"(C V)_{\mathrm{kept}}".into(),
        "rank" => r"\operatorname{rank}".into(),
        "order" => "r".into(),
        "mcmillan" => r"\delta_M".into(),
        "top" => r"\text{length}".into(),
        "deg" => r"\text{conjugates}".into(),
        k if k.len() <= 2 => k.into(),
        k => format!(r"\text{{{}}}", k.replace('_', " ")),
    }
}

/// An entry's LaTeX: the field's own, or a plain display (`1/4*t`) through the display grammar.
fn entry<K: Field>(k: &K, x: &K::Elem) -> String {
    let e = k.latex_elem(x);
    if !e.contains('\\') && e.contains(['*', '/']) {
        super::latex::to_math(&e).unwrap_or(e)
    } else {
        e
    }
}

/// A polynomial in `var` with the field's LaTeX coefficients (compound ones in parentheses,
/// a coefficient of $\pm 1$ not written).
///
/// ```
/// use exactlti::field::{Field, Q};
/// use exactlti::poly::Poly;
/// use exactlti::report::steps_latex::poly_latex;
/// let c = |n: i64| Q.from_i64(n);
/// // -s^3 + s^2 - 2 s - 1
/// let p = Poly::new(Q, vec![c(-1), c(-2), c(1), c(-1)]);
/// assert_eq!(poly_latex(&p, "s"), "-s^{3} + s^{2} - 2\\,s - 1");
/// ```
pub fn poly_latex<K: Field>(p: &Poly<K>, var: &str) -> String {
    let k = p.field();
    let mut out = String::new();
    for (i, c) in p.coeffs().iter().enumerate().rev() {
        if k.is_zero(c) {
            continue;
        }
        let mut t = entry(k, c);
        let neg = t.starts_with('-') && !t[1..].contains(['+', '-']);
        if neg {
            t = t[1..].to_string();
        }
        let compound = t.contains(['+', '-']) || t.contains(' ');
        // a unit coefficient (+1 or -1, its sign taken off above) is not written
        let coef = if i > 0 && (k.is_one(c) || (neg && t == "1")) {
            String::new()
        } else if i > 0 && compound {
            format!("\\left({t}\\right)")
        } else {
            t
        };
        let mono = match i {
            0 => String::new(),
            1 => var.to_string(),
            _ => format!("{var}^{{{i}}}"),
        };
        let body = if i > 0 && coef.is_empty() {
            mono
        } else if i > 0 {
            format!("{coef}\\,{mono}")
        } else {
            coef
        };
        if out.is_empty() {
            out = if neg { format!("-{body}") } else { body };
        } else {
            let _ = write!(out, " {} {body}", if neg { "-" } else { "+" });
        }
    }
    if out.is_empty() { "0".into() } else { out }
}

/// A matrix in display math: `bmatrix`, small beyond 10 columns, column blocks beyond 20
/// (`a4`: for a printed page; else one block at full size, as a notebook scrolls).
fn matrix_latex<K: Field>(s: &mut String, name: &str, m: &Matrix<K>, a4: bool) {
    let k = m.field();
    if m.nrows() == 0 || m.ncols() == 0 {
        let _ = writeln!(
            s,
            "\\[ {name} \\ ({} \\times {},\\ \\text{{empty}}) \\]",
            m.nrows(),
            m.ncols()
        );
        return;
    }
    let cells: Vec<Vec<String>> = (0..m.nrows())
        .map(|i| (0..m.ncols()).map(|j| entry(k, m.get(i, j))).collect())
        .collect();
    // rough widths in mm: a character of the plain display, plus the column gap
    let plain: Vec<usize> = (0..m.ncols())
        .map(|j| {
            (0..m.nrows())
                .map(|i| k.fmt_elem(m.get(i, j)).chars().count())
                .max()
                .unwrap_or(1)
        })
        .collect();
    let width = |small: bool, c: &[usize]| -> f64 {
        let (ch, gap) = if small { (1.3, 3.6) } else { (2.0, 5.0) };
        c.iter().map(|&w| w as f64 * ch + gap).sum::<f64>() + 20.0
    };
    let widest = plain.iter().copied().max().unwrap_or(0);
    if a4 && width(true, &[widest]) > TEXT_MM {
        return entries_latex(s, name, &cells);
    }
    let small = a4 && (m.ncols() > 10 || width(false, &plain) > TEXT_MM);
    if small {
        s.push_str("{\\scriptsize\n");
    }
    // column blocks that fit the A4 text width
    let mut blocks = vec![];
    let mut c0 = 0;
    while c0 < m.ncols() {
        let mut c1 = c0 + 1;
        while c1 < m.ncols()
            && (!a4 || (c1 - c0 < BLOCK_COLS && width(small, &plain[c0..=c1]) <= TEXT_MM))
        {
            c1 += 1;
        }
        blocks.push((c0, c1));
        c0 = c1;
    }
    for &(c0, c1) in &blocks {
        let head = if blocks.len() > 1 {
            // braces: a name with its own subscript (A_s, A_{22}) takes the block's
            // and `{}` inside: TeX unwraps a group of one accent atom (\bar C_i), whose
            // subscript would then be a double one
            format!("{{{name}{{}}}}_{{:,\\,{}..{}}}", c0 + 1, c1)
        } else {
            name.to_string()
        };
        let _ = writeln!(
            s,
            "\\[ {head} = \\left[\\begin{{array}}{{*{{{}}}{{c}}}}",
            c1 - c0
        );
        for row in &cells {
            let _ = writeln!(s, "{} \\\\", row[c0..c1].join(" & "));
        }
        s.push_str("\\end{array}\\right] \\]\n");
    }
    if small {
        s.push_str("}\n");
    }
}

/// A matrix whose widest column alone is wider than the page: one display per nonzero entry
/// (`name_{(i,j)} = ...`, broken over lines where it is long: [`display`]).
fn entries_latex(s: &mut String, name: &str, cells: &[Vec<String>]) {
    let zeros = cells.iter().flatten().filter(|c| c.as_str() == "0").count();
    let _ = writeln!(
        s,
        r"\[ {name}\ ({} \times {}),\ \text{{entries one by one (wider than the page){}}} \]",
        cells.len(),
        cells.first().map_or(0, |r| r.len()),
        if zeros > 0 {
            "; those not listed are 0"
        } else {
            ""
        }
    );
    for (i, row) in cells.iter().enumerate() {
        for (j, c) in row.iter().enumerate() {
            if c != "0" {
                display(s, &format!(r"{{{name}{{}}}}_{{({},{})}}", i + 1, j + 1), c);
            }
        }
    }
}

fn counts_latex(xs: &[usize], one_based: bool) -> String {
    let v: Vec<String> = xs
        .iter()
        .map(|x| (x + usize::from(one_based)).to_string())
        .collect();
    format!("({})", v.join(",\\ "))
}

/// An object of a step in display math (`a4`: see [`matrix_latex`]).
pub(crate) fn object_latex<K: Field>(
    s: &mut String,
    kind: StepKind,
    key: &str,
    o: &Object<K>,
    field: &K,
    a4: bool,
    var: &str,
) {
    let name = symbol(kind, key, var);
    let index_list = matches!(key, "kept" | "not_excited" | "not_observed" | "pivots")
        || super::steps_more::index_list(key);
    match o {
        Object::Matrix(m) => matrix_latex(s, &name, m, a4),
        Object::Poly(p) => display_wrapped(s, &name, &poly_latex(p, var)),
        Object::Factors(fs) => {
            let parts: Vec<String> = fs
                .iter()
                .map(|(p, e)| {
                    let b = format!("\\left({}\\right)", poly_latex(p, var));
                    if *e > 1 { format!("{b}^{{{e}}}") } else { b }
                })
                .collect();
            let all = parts.join("");
            if !a4 || width_pt(&all) <= TEXT_PT {
                let _ = writeln!(s, "\\[ {name} = {all} \\]");
                return;
            }
            // too wide for the page: the product by names, then each factor on its own
            let names: Vec<String> = fs
                .iter()
                .enumerate()
                .map(|(i, (_, e))| {
                    let b = format!("p_{{{}}}", i + 1);
                    if *e > 1 { format!("{b}^{{{e}}}") } else { b }
                })
                .collect();
            let _ = writeln!(s, "\\[ {name} = {} \\]", names.join("\\,"));
            for (i, (p, _)) in fs.iter().enumerate() {
                display_wrapped(s, &format!("p_{{{}}}", i + 1), &poly_latex(p, "s"));
            }
        }
        Object::Scalar(x) => display(s, &name, &entry(field, x)),
        Object::Count(c) => {
            let _ = writeln!(s, "\\[ {name} = {c} \\]");
        }
        Object::Counts(cs) => {
            let _ = writeln!(s, "\\[ {name} = {} \\]", counts_latex(cs, index_list));
        }
        Object::Polys(ps) => {
            let parts: Vec<String> = ps.iter().map(|p| poly_latex(p, var)).collect();
            let one_line = parts.iter().map(|p| width_pt(p) + 15.0).sum::<f64>() <= TEXT_PT;
            if !a4 || one_line {
                let _ = writeln!(s, "\\[ {name}:\\ {} \\]", parts.join(",\\; "));
            } else {
                for (i, p) in parts.iter().enumerate() {
                    display_wrapped(s, &format!("\\text{{({})}}\\ {name}", i + 1), p);
                }
            }
        }
    }
}

/// `name = body` in display math, broken over lines that fit A4 when long
/// ([`super::latex::lines::display`]: a polynomial of the 747 model is several lines wide, a
/// symbolic numerator dozens).
fn display_wrapped(s: &mut String, name: &str, body: &str) {
    display(s, name, body);
}

/// The sentence of a step in LaTeX (the objects follow it in display math).
pub(crate) fn sentence_latex<K: Field>(d: &Derivation<K>, st: &Step<K>) -> String {
    super::steps::in_variable_math(&sentence_latex_in_s(d, st), super::steps::poly_var(d))
}

fn sentence_latex_in_s<K: Field>(d: &Derivation<K>, st: &Step<K>) -> String {
    let th = theta_step(d, st.part)
        .and_then(|s| s.scalar("theta").map(|t| entry(&step_field(d, s), t)))
        .unwrap_or_default();
    let c = |k: &str| st.count(k).unwrap_or(0);
    let conj = if c("deg") > 1 {
        format!(" (the same for each of the {} conjugate roots)", c("deg"))
    } else {
        String::new()
    };
    let generic = if generic_root(d, st) {
        // a long field name (its modulus with big coefficients) does not break in
        // \texttt: named by its factor instead, which the factorization step shows
        let f = step_field(d, st).to_string();
        let field = if f.chars().count() <= 40 {
            format!("\\texttt{{{}}}", latex_text(&f))
        } else {
            "$F[t]/(f)$, $f$ its irreducible factor,".into()
        };
        format!(
            ", worked once in {field} at the generic root $t$ (its conjugates by the embeddings $t \\mapsto \\theta_j$)"
        )
    } else {
        String::new()
    };
    match st.kind {
        StepKind::CharPoly => "The characteristic polynomial $\\chi_A(s) = \\det(sI - A)$.".into(),
        StepKind::Factorization => "Its irreducible factors.".into(),
        StepKind::KernelSequence => format!(
            "Eigenvalue $\\theta = {th}$ of algebraic multiplicity $\\mu${generic}: with $N = A - \\theta I$ the ranks of $N, N^2, \\dots$ give the kernel dimensions $\\dim\\ker N^k = n - \\operatorname{{rank}} N^k$, up to $\\mu$."
        ),
        StepKind::WeyrSegre => "The Weyr characteristic $w_k = \\dim\\ker N^k - \\dim\\ker N^{k-1}$ counts the Jordan blocks of size $\\ge k$; its conjugate partition (the Segre characteristic) lists the block sizes.".into(),
        StepKind::Chain if c("top") == 1 => format!("An eigenvector of $\\theta = {th}$: $v_1 \\in \\ker N$."),
        StepKind::Chain => format!(
            "A chain of length {top} for $\\theta = {th}$, built top-down: $v_{top} \\in \\ker N^{top} \\setminus \\ker N^{below}$, then $v_{{j-1}} = N v_j$; the columns of $V$ are $v_1, \\dots, v_{top}$. The family (the free constants of the vehicle paper's eq.~30, 32): with the columns of $K$ a basis of $\\ker N$ ($N K = 0$, checked), $v_j + K c$ solves $N x = v_{{j-1}}$ for every $c$; the chain takes $c = 0$.",
            top = c("top"),
            below = c("top") - 1
        ),
        StepKind::EigenCheck => format!("The chains of $\\theta = {th}$ side by side, and its Jordan matrix."),
        StepKind::PrimaryBlock => "An irreducible factor $f$ of degree $\\ge 2$ (its roots are not in the field of the entries): the kernel dimensions of $f(A)^k$, the block sizes of each root, a basis $B$ of $\\ker f(A)^e$ and $M$ with $AB = BM$.".into(),
        StepKind::Similarity => "The Jordan basis $T$ and the Jordan matrix $J$ from the steps above (conjugate roots by Galois conjugation).".into(),
        StepKind::Controllability => "The controllability matrix $\\mathcal C = [B, AB, \\dots, A^{n-1}B]$ and its rank.".into(),
        StepKind::ControllableSubspace => "The controllable subspace $\\mathcal R$: the pivot columns of the RREF of $\\mathcal C$ (Krylov vectors).".into(),
        StepKind::Observability => "The observability matrix $\\mathcal O = [C; CA; \\dots; CA^{n-1}]$ and its rank.".into(),
        StepKind::UnobservableSubspace => "The unobservable subspace $\\mathcal N = \\ker \\mathcal O$.".into(),
        StepKind::KalmanBasis => "The Kalman basis $T = [X_{c\\bar o}, X_{co}, X_{\\bar c\\bar o}, X_{\\bar co}]$: $\\mathcal R \\cap \\mathcal N$, completed to $\\mathcal R$, to $\\mathcal N$, to the whole space (dimensions of the parts).".into(),
        StepKind::KalmanForm => "The Kalman form $(T^{-1}AT, T^{-1}B, CT)$.".into(),
        StepKind::MinimalPart => "The controllable and observable part $(A_{22}, B_2, C_2, D)$: a minimal realization.".into(),
        StepKind::ModalData => format!("Eigenvalue $\\theta = {th}${generic}: the modal data $(J_\\theta, WB, CV)$ in $z = Wx${conj}."),
        StepKind::DropModes => format!(
            "Non-contributing modes of $\\theta = {th}$ dropped{conj}: in each Jordan block the states after the last excited one are never excited and those before the first observed one never reach $y$ (state numbers below, within the block)."
        ),
        StepKind::Compaction => format!(
            "Repeated modes of $\\theta = {th}$ compacted{conj}: a minimal realization of $(N, WB, CV)$ over the field, back in Jordan form by its chains."
        ),
        StepKind::Stages => "The orders of the stages: original, after dropping, after compacting; the last is the McMillan degree $\\delta_M$. Each stage $(A_s, B_s, C_s)$, written over the base field, reproduces the Markov parameters $C A^k B$; $(A_r, B_r, C_r, D_r)$ is the command's realization (\\texttt{minreal --method jordan}).".into(),
        StepKind::Restriction => restriction_latex(st),
        _ => super::steps_more::sentence_latex(st),
    }
}

/// The LaTeX sentence of a restriction step (the plain one in `report::steps`).
fn restriction_latex<K: Field>(st: &Step<K>) -> String {
    let deg = st.count("deg").unwrap_or(0);
    let flag = |k: &str| st.count(k) == Some(1);
    let basis = if st.matrix("u").is_some() {
        "the columns of $u$ a basis of $\\ker g(A)$, $A_g$ with $A u = u A_g$ and $P$ the projector along $\\operatorname{im} g(A)$ ($P u = I$, $P A = A_g P$)"
    } else {
        "$g$ has degree $n$: $u = P = I$ and the part is $(A, B, C)$ itself"
    };
    let why = match (flag("excited"), flag("observed")) {
        (true, true) => format!(
            "kept, as $P B \\ne 0$ (excited) and $C u \\ne 0$ (observed); $g$ is irreducible, so the only $A_g$-invariant subspaces are $0$ and the whole space: the part is controllable and observable, a minimal block of {deg} states"
        ),
        (false, true) => "dropped: $P B = 0$, its modes are not excited".into(),
        (true, false) => "dropped: $C u = 0$, its modes are not observed".into(),
        (false, false) => "dropped: $P B = 0$ and $C u = 0$".into(),
    };
    format!(
        "A simple irreducible factor $g$ of degree {deg}: its {deg} roots form one block, realized without chains over $F[t]/(g)$ by the restriction ({basis}). The part $(A_g, P B, C u)$ is the factor's share of $C(sI - A)^{{-1}}B$; it is {why}."
    )
}

fn step_latex<K: Field>(s: &mut String, d: &Derivation<K>, i: usize, st: &Step<K>) {
    let _ = writeln!(
        s,
        "\\subsection*{{Step {} \\quad {{\\normalfont\\small\\texttt{{{}}}}}}}",
        i + 1,
        latex_text(kind_name(st.kind))
    );
    let _ = writeln!(s, "{}\n", sentence_latex(d, st));
    let field = step_field(d, st);
    let var = super::steps::poly_var(d);
    for (k, o) in &st.objects {
        if transfer_latex(s, st, k, true, var) || super::steps_forms::flag(k) {
            continue;
        }
        object_latex(s, st.kind, k, o, &field, true, var);
    }
    let (_, id) = identity(st.kind);
    let id = super::steps::in_variable(id, var);
    if let Some(h) = st.holds {
        let verdict = if h { "holds exactly" } else { "FAILS" };
        let _ = writeln!(s, "\\noindent Identity: $ {id} $ --- {verdict}.\n");
    }
    if let Some(conds) = assumes_latex(d, st) {
        let _ = writeln!(s, "{{\\sloppy\\noindent Assumes: ${conds}$.\\par}}\n");
    }
}

/// The step's assumptions as LaTeX math, `x \ne 0, ...` (`None` when it assumes nothing):
/// one text for the LaTeX and the HTML derivation.
pub(crate) fn assumes_latex<K: Field>(d: &Derivation<K>, st: &Step<K>) -> Option<String> {
    if st.assumes.is_empty() {
        return None;
    }
    let conds: Vec<String> = st
        .assumes
        .iter()
        .map(|x| format!("{} \\ne 0", entry(&d.field, x)))
        .collect();
    Some(conds.join(",\\ "))
}

/// The derivation as LaTeX: a fragment, or with `standalone` a complete A4 document.
pub fn derivation_latex<K: Field>(d: &Derivation<K>, standalone: bool) -> String {
    let mut body = String::new();
    let _ = writeln!(body, "\\section*{{{}}}", latex_text(title(d.method)));
    let _ = writeln!(
        body,
        "Over {}.\n",
        latex_text(&super::steps::field_name(&d.field))
    );
    for (i, st) in d.steps.iter().enumerate() {
        step_latex(&mut body, d, i, st);
    }
    let _ = writeln!(
        body,
        "\\medskip\\noindent Every identity above was checked in exact arithmetic: {}.",
        if d.verified() {
            "all hold"
        } else {
            "one FAILS"
        }
    );
    if !standalone {
        return body;
    }
    format!(
        "\\documentclass[11pt,a4paper]{{article}}\n\\usepackage[a4paper,margin=2cm]{{geometry}}\n\
         \\usepackage{{amsmath,amssymb}}\n\\setlength{{\\parindent}}{{0pt}}\n\\allowdisplaybreaks\n\
         \\begin{{document}}\n{body}\\end{{document}}\n"
    )
}

/// The transfer entries as one matrix of fractions; `true` when `key` was written here.
pub(crate) fn transfer_latex<K: Field>(
    out: &mut String,
    st: &Step<K>,
    key: &str,
    a4: bool,
    var: &str,
) -> bool {
    if st.kind != StepKind::TransferEntries {
        return false;
    }
    if key != "num" {
        return true; // `den`, `p` are part of the fractions
    }
    let (Some(num), Some(den)) = (st.polys("num"), st.polys("den")) else {
        return true;
    };
    let p = st.count("p").unwrap_or(1).max(1);
    let m = num.len() / p;
    let row_len = |i: usize| -> f64 {
        (0..m)
            .map(|j| {
                let (n, d) = (&num[i * m + j], &den[i * m + j]);
                width_pt(&poly_latex(n, var)).max(width_pt(&poly_latex(d, var))) + 15.0
            })
            .sum()
    };
    if a4 && (0..p).any(|i| row_len(i) > TEXT_PT) {
        // one entry at a time, numerator and denominator each wrapped over lines
        for i in 0..p {
            for j in 0..m {
                let (n, d) = (&num[i * m + j], &den[i * m + j]);
                let ij = format!("{{{},{}}}", i + 1, j + 1);
                if d.deg() == 0 {
                    display_wrapped(out, &format!("G_{ij}({var})"), &poly_latex(n, var));
                    continue;
                }
                let _ = writeln!(
                    out,
                    "\\[ G_{ij}({var}) = \\frac{{n_{ij}({var})}}{{d_{ij}({var})}} \\]"
                );
                display_wrapped(out, &format!("n_{ij}({var})"), &poly_latex(n, var));
                display_wrapped(out, &format!("d_{ij}({var})"), &poly_latex(d, var));
            }
        }
        return true;
    }
    let _ = writeln!(out, "\\[ G({var}) = \\begin{{bmatrix}}");
    for i in 0..p {
        let row: Vec<String> = (0..m)
            .map(|j| {
                let (n, d) = (&num[i * m + j], &den[i * m + j]);
                let nl = poly_latex(n, var);
                if d.deg() == 0 {
                    nl
                } else {
                    format!("\\dfrac{{{nl}}}{{{}}}", poly_latex(d, var))
                }
            })
            .collect();
        let _ = writeln!(out, "{} \\\\", row.join(" & "));
    }
    out.push_str("\\end{bmatrix} \\]\n");
    true
}
