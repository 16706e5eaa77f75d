//! A derivation (`--steps --format latex`) typeset as a worked example: one numbered step per
//! paragraph (its sentence), the objects it computed in display math (matrices as `bmatrix`
//! with the field's own LaTeX entries, polynomials with their coefficients as fractions), the
//! identity it establishes with its exact verdict, and what it assumes. With `--standalone`
//! a complete A4 document (`article`, 2 cm margins); matrices wider than 10 columns are set
//! small, wider than 20 in column blocks, so every page is A4.

use super::escape::latex_text;
use super::steps::{identity, kind_name, sentence, step_field, title};
use crate::field::Field;
use crate::jordan::derivation::{Derivation, Object, Step};
use crate::matrix::Matrix;
use crate::poly::Poly;
use std::fmt::Write;

/// Columns of a matrix set in one block.
const BLOCK_COLS: usize = 20;

/// The math symbol of an object key.
fn symbol(key: &str) -> String {
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

/// A polynomial in `var` with the field's LaTeX coefficients (compound ones in parentheses).
pub fn poly_latex<K: Field>(p: &Poly<K>, var: &str) -> String {
    let k = p.field();
    let mut out = String::new();
    for (i, c) in p.coeffs().iter().enumerate().rev() {
        if k.is_zero(c) {
            continue;
        }
        let mut t = k.latex_elem(c);
        let neg = t.starts_with('-') && !t[1..].contains(['+', '-']);
        if neg {
            t = t[1..].to_string();
        }
        let compound = t.contains(['+', '-']) || t.contains(' ');
        let coef = if i > 0 && k.is_one(c) {
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

/// A matrix in display math: `bmatrix`, small beyond 10 columns, column blocks beyond 20.
fn matrix_latex<K: Field>(s: &mut String, name: &str, m: &Matrix<K>) {
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
    let small = m.ncols() > 10;
    if small {
        s.push_str("{\\scriptsize\n");
    }
    for c0 in (0..m.ncols()).step_by(BLOCK_COLS) {
        let c1 = (c0 + BLOCK_COLS).min(m.ncols());
        let head = if m.ncols() > BLOCK_COLS {
            format!("{name}_{{:, {}..{}}}", c0 + 1, c1)
        } else {
            name.to_string()
        };
        let _ = write!(
            s,
            "\\[ {head} = \\left[\\begin{{array}}{{*{{{}}}{{c}}}}\n",
            c1 - c0
        );
        for i in 0..m.nrows() {
            let cells: Vec<String> = (c0..c1).map(|j| k.latex_elem(m.get(i, j))).collect();
            let _ = writeln!(s, "{} \\\\", cells.join(" & "));
        }
        s.push_str("\\end{array}\\right] \\]\n");
    }
    if small {
        s.push_str("}\n");
    }
}

fn counts_latex(xs: &[usize], one_based: bool) -> String {
    let v: Vec<String> = xs
        .iter()
        .map(|x| (x + usize::from(one_based)).to_string())
        .collect();
    format!("({})", v.join(",\\ "))
}

fn object_latex<K: Field>(s: &mut String, key: &str, o: &Object<K>, field: &K) {
    let name = symbol(key);
    let index_list = matches!(key, "kept" | "not_excited" | "not_observed" | "pivots");
    match o {
        Object::Matrix(m) => matrix_latex(s, &name, m),
        Object::Poly(p) => {
            let _ = writeln!(s, "\\[ {name} = {} \\]", poly_latex(p, "s"));
        }
        Object::Factors(fs) => {
            let parts: Vec<String> = fs
                .iter()
                .map(|(p, e)| {
                    let b = format!("\\left({}\\right)", poly_latex(p, "s"));
                    if *e > 1 { format!("{b}^{{{e}}}") } else { b }
                })
                .collect();
            let _ = writeln!(s, "\\[ {name} = {} \\]", parts.join(""));
        }
        Object::Scalar(x) => {
            let _ = writeln!(s, "\\[ {name} = {} \\]", field.latex_elem(x));
        }
        Object::Count(c) => {
            let _ = writeln!(s, "\\[ {name} = {c} \\]");
        }
        Object::Counts(cs) => {
            let _ = writeln!(s, "\\[ {name} = {} \\]", counts_latex(cs, index_list));
        }
    }
}

fn step_latex<K: Field>(s: &mut String, d: &Derivation<K>, i: usize, st: &Step<K>) {
    let _ = writeln!(
        s,
        "\\subsection*{{Step {} \\quad {{\\normalfont\\small\\texttt{{{}}}}}}}",
        i + 1,
        latex_text(kind_name(st.kind))
    );
    let _ = writeln!(s, "{}\n", latex_text(&sentence(d, st)));
    let field = step_field(d, st);
    for (k, o) in &st.objects {
        object_latex(s, k, o, &field);
    }
    let (_, id) = identity(st.kind);
    if let Some(h) = st.holds {
        let verdict = if h { "holds exactly" } else { "FAILS" };
        let _ = writeln!(s, "\\noindent Identity: $ {id} $ --- {verdict}.\n");
    }
    if !st.assumes.is_empty() {
        let conds: Vec<String> = st
            .assumes
            .iter()
            .map(|x| format!("{} \\ne 0", d.field.latex_elem(x)))
            .collect();
        let _ = writeln!(s, "\\noindent Assumes: ${}$.\n", conds.join(",\\ "));
    }
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
