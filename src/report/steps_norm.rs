//! The texts of the normalisation steps (`jordan --normalize`, the compaction's $|B| =
//! |\tilde B|$) and of `minreal --descriptor --steps`: titles, JSON names, identities,
//! sentences (plain and LaTeX) and the LaTeX symbols of their objects. Called through
//! `report::steps_forms`.

use crate::algebraic::ExtElem;
use crate::field::ElemDisplay;
use crate::field::Field;
use crate::jordan::derivation::{Derivation, Method, Step, StepKind};
use crate::jordan::normalize::{ClosedUnit, Normalization, Scale};
use crate::jordan::{EigenField, JordanForm};
use crate::report::{Report, Value};

/// The title of a method of this file.
pub fn title(m: Method) -> &'static str {
    match m {
        Method::DescriptorMinimal => "minimal descriptor realization, step by step",
        m => super::steps_modes::title(m),
    }
}

/// The JSON name of a step kind of this file.
pub fn kind_name(k: StepKind) -> &'static str {
    match k {
        StepKind::Normalization => "normalization",
        StepKind::NormMatch => "norm_match",
        StepKind::DescriptorFinite => "finite_part",
        StepKind::DescriptorInfinite => "infinite_part",
        StepKind::DescriptorNondynamic => "nondynamic_modes",
        StepKind::DescriptorMinimalForm => "minimal_descriptor",
        k => super::steps_modes::kind_name(k),
    }
}

/// The identity of a step kind of this file, as plain text and as LaTeX math.
pub fn identity(k: StepKind) -> (&'static str, &'static str) {
    match k {
        StepKind::Normalization => (
            "N v'_1 = 0, N v'_j = v'_(j-1), span V' = span V (so A V' = V' J_theta); v'_j . v'_1 = 0 (eq. 31); entry 1, or v'_1 . v'_1 = 1 (= n in closed form)",
            r"N v_1' = 0,\ N v_j' = v_{j-1}',\ \operatorname{span} V' = \operatorname{span} V,\ v_j' \cdot v_1' = 0,\ v_1' \cdot v_1' \in \{1, n\}",
        ),
        StepKind::NormMatch => (
            "|Bt|^2 = |B|^2 (exact or in closed form), Ct Bt = C B",
            r"|\tilde B|^2 = |B|^2,\ \tilde C \tilde B = C B",
        ),
        StepKind::DescriptorFinite => (
            "Cf Af^k Bf = Cm Am^k Bm (k < nf + nm), (Am, Bm) controllable, (Am, Cm) observable",
            r"C_f A_f^k B_f = C_m A_m^k B_m,\ (A_m, B_m)\ \text{controllable},\ (A_m, C_m)\ \text{observable}",
        ),
        StepKind::DescriptorInfinite => (
            "Cinf N^k Binf = Cr Nr^k Br (k < ninf + nr), Nr nilpotent",
            r"C_\infty N^k B_\infty = C_r N_r^k B_r,\ N_r^{n_r} = 0",
        ),
        StepKind::DescriptorNondynamic => (
            "same transfer matrix, rank[E, B] = rank[E; C] = n, A ker E in im E",
            r"G\ \text{unchanged},\ \operatorname{rank}[E,\ B] = \operatorname{rank}[E;\ C] = n,\ A\ker E \subseteq \operatorname{im} E",
        ),
        StepKind::DescriptorMinimalForm => (
            "C(sE - A)^-1 B + D unchanged, finite part controllable and observable, minimal at infinity",
            r"C(sE - A)^{-1}B + D\ \text{unchanged},\ \text{minimal}",
        ),
        k => super::steps_modes::identity(k),
    }
}

fn cnt<K: Field>(s: &Step<K>, key: &str) -> usize {
    s.count(key).unwrap_or(0)
}

/// What the scaling of a normalised chain did, in words.
fn scaled_text<K: Field>(d: &Derivation<K>, s: &Step<K>, latex: bool) -> String {
    let k = super::steps_base::step_field(d, s);
    let el = |x: &K::Elem| {
        if latex {
            format!("${}$", k.latex_elem(x))
        } else {
            k.fmt_elem(x)
        }
    };
    if let Some(r) = s.count("row") {
        return format!(
            " The whole chain is divided by entry {r} of the eigenvector, which becomes 1 (exact)."
        );
    }
    if cnt(s, "refused") == 1 {
        return " Unit length refused: the eigenvalue is not real, and v . v is not a length (v^H v needs complex conjugation, which is not a map of this field); the chain keeps its other normalisations.".into();
    }
    match (s.scalar("n2"), s.scalar("root")) {
        (Some(n), Some(r)) => format!(
            " Unit length, exact: n = v_1 . v_1 = {} = ({})^2, the chain divided by {}.",
            el(n),
            el(r),
            el(r)
        ),
        (Some(n), None) => format!(
            " Unit length in closed form: n = v_1 . v_1 = {} is not a square in the field, so the unit-length chain is V' / sqrt({}) (shown: V'; sqrt n lies in a quadratic extension over Q, not in this field).",
            el(n),
            el(n)
        ),
        _ => String::new(),
    }
}

/// The plain sentence of a step of this file.
pub fn sentence<K: Field>(d: &Derivation<K>, s: &Step<K>) -> String {
    match s.kind {
        StepKind::SpectralProjector
        | StepKind::ModeResidues
        | StepKind::ModeWeight
        | StepKind::ModeRanking
        | StepKind::TruncationError
        | StepKind::FreeTerms
        | StepKind::InitialState => super::steps_modes::sentence(d, s),
        StepKind::Normalization => format!(
            "Normalise the chain of length {}{}: V' = p(N) V with p(N) = c (I + b_1 N + ...), again a chain of the same block.{}{}",
            cnt(s, "top"),
            theta_text(d, s),
            if cnt(s, "orth") == 1 && cnt(s, "top") > 1 {
                " Eq. 31 (Y orthogonal to X): b_k solve v'_j . v'_1 = 0, j = 2..s (triangular, diagonal v_1 . v_1)."
            } else {
                ""
            },
            scaled_text(d, s, false)
        ),
        StepKind::NormMatch => format!(
            "The paper's |B| = |Bt| (eq. 36) for the compacted block{}: Bt -> a Bt, Ct -> Ct / a with a^2 = |B|^2 / |Bt|^2 = {}{}.",
            theta_text(d, s),
            s.scalar("a2")
                .map(|x| super::steps_base::step_field(d, s).fmt_elem(x))
                .unwrap_or_default(),
            match s.scalar("a") {
                Some(a) => format!(
                    ", a = {} exact (shown: the scaled Bt, Ct)",
                    super::steps_base::step_field(d, s).fmt_elem(a)
                ),
                None =>
                    ", a = sqrt(a^2) not in the field: closed form (shown: Bt, Ct before scaling)"
                        .into(),
            }
        ),
        StepKind::DescriptorFinite => format!(
            "The finite part (Af, Bf, Cf) of the Weierstrass split ({} state(s)) reduced by the Kalman decomposition to its controllable and observable part (Am, Bm, Cm): order {}.",
            s.matrix("Af").map_or(0, |m| m.nrows()),
            cnt(s, "order")
        ),
        StepKind::DescriptorInfinite => format!(
            "The infinite part C_inf (I + s N)^-1 B_inf = sum_k (-s)^k C_inf N^k B_inf ({} state(s), polynomial part of degree {}): a minimal realization (Nr, Br, Cr) of the sequence C_inf N^k B_inf (Kalman on (N, B_inf, C_inf)), order {}; as a descriptor part E = -Nr, A = I, B = -Br, C = Cr.",
            s.matrix("N").map_or(0, |m| m.nrows()),
            cnt(s, "q"),
            cnt(s, "order")
        ),
        StepKind::DescriptorNondynamic => format!(
            "Non-dynamic modes (infinite blocks of size 1) of the irreducible infinite part eliminated: {} removed, {} infinite states left{}.",
            cnt(s, "removed"),
            cnt(s, "order"),
            if cnt(s, "shifted") == 1 {
                "; the realization of the shifted sequence (0, P_1, ..., P_q) with D = P_0 has the same order and is taken (D is then G's constant at infinity)"
            } else {
                ""
            }
        ),
        StepKind::DescriptorMinimalForm => {
            let o = s.counts("orders").unwrap_or(&[]);
            let at = |i: usize| o.get(i).copied().unwrap_or(0);
            format!(
                "The minimal descriptor realization E = diag(I, E_inf), A = diag(Am, A_inf), B = [Bm; B_inf], C = [Cm, C_inf]: {} states -> {} (irreducible) -> {} (finite {} + infinite {}).",
                at(0),
                at(1),
                at(2),
                at(3),
                at(4)
            )
        }
        _ => String::new(),
    }
}

/// `" of theta = ..."` for a step of an eigenvalue part.
fn theta_text<K: Field>(d: &Derivation<K>, s: &Step<K>) -> String {
    match super::steps_base::theta_step(d, s.part).and_then(|t| t.scalar("theta").map(|x| (t, x))) {
        Some((t, x)) => format!(
            " of theta = {}",
            super::steps_base::step_field(d, t).fmt_elem(x)
        ),
        None => String::new(),
    }
}

/// The LaTeX sentence of a step of this file.
pub fn sentence_latex<K: Field>(st: &Step<K>) -> String {
    let c = |k: &str| cnt(st, k);
    match st.kind {
        StepKind::Normalization => format!(
            "The chain normalised: $V' = p(N)V$ with $p(N) = c\\,(I + b_1 N + \\dots)$ is again a chain of the same block, so $AV' = V'J_\\theta$.{}{}",
            if c("orth") == 1 && c("top") > 1 {
                " Eq.~31 ($Y \\perp X$): $b_k$ solve $v_j' \\cdot v_1' = 0$, $j \\ge 2$."
            } else {
                ""
            },
            if st.count("row").is_some() {
                " The chain is divided by the chosen entry of its eigenvector (exact)."
            } else if c("refused") == 1 {
                " Unit length refused: the eigenvalue is not real ($v^H v$ needs complex conjugation)."
            } else if st.scalar("root").is_some() {
                " Unit length, exact: divided by $\\sqrt n$, $n = v_1 \\cdot v_1$."
            } else if st.scalar("n2").is_some() {
                " Unit length in closed form: the columns are $V'/\\sqrt n$, $n = v_1 \\cdot v_1$ not a square in the field."
            } else {
                ""
            }
        ),
        StepKind::NormMatch => "The compacted block scaled so that $|\\tilde B| = |B|$ (the paper's eq.~36 choice): $\\tilde B \\to a\\tilde B$, $\\tilde C \\to \\tilde C/a$, $a^2 = |B|^2/|\\tilde B|^2$ (exact when $a$ lies in the field, else in closed form).".into(),
        StepKind::DescriptorFinite => "The finite part $(A_f, B_f, C_f)$ of the Weierstrass split reduced to its controllable and observable part $(A_m, B_m, C_m)$ (Kalman).".into(),
        StepKind::DescriptorInfinite => "The infinite part $C_\\infty(I + sN)^{-1}B_\\infty = \\sum_k (-s)^k C_\\infty N^k B_\\infty$: a minimal realization $(N_r, B_r, C_r)$ of the sequence $C_\\infty N^k B_\\infty$; as a descriptor part $E = -N_r$, $A = I$, $B = -B_r$, $C = C_r$.".into(),
        StepKind::DescriptorNondynamic => "The non-dynamic modes (infinite blocks of size 1) of the irreducible infinite part eliminated.".into(),
        StepKind::DescriptorMinimalForm => "The minimal descriptor realization $E = \\operatorname{diag}(I, E_\\infty)$, $A = \\operatorname{diag}(A_m, A_\\infty)$, $B = [B_m; B_\\infty]$, $C = [C_m, C_\\infty]$ (orders: original, irreducible, minimal, finite, infinite).".into(),
        _ => super::steps_modes::sentence_latex(st),
    }
}

/// The LaTeX symbol of an object key of this file's steps (`None`: the common tables).
pub fn symbol(kind: StepKind, key: &str) -> Option<&'static str> {
    use StepKind as S;
    if let Some(sym) = super::steps_modes::symbol(kind, key) {
        return Some(sym);
    }
    let desc = matches!(
        kind,
        S::DescriptorFinite
            | S::DescriptorInfinite
            | S::DescriptorNondynamic
            | S::DescriptorMinimalForm
    );
    Some(match key {
        "Vn" => "V'",
        "b" if kind == S::Normalization => r"[b_1, \dots, b_{s-1}]",
        "row" => r"r\ (v_{1,r}' = 1)",
        "n2" => r"n = v_1 \cdot v_1",
        "root" => r"\sqrt n",
        "a2" => r"a^2 = |B|^2 / |\tilde B|^2",
        "a" => "a",
        "nB" => r"|B|^2",
        "nBt" => r"|\tilde B|^2",
        "Bt" if kind == S::NormMatch => r"\tilde B",
        "Ct" if kind == S::NormMatch => r"\tilde C",
        "Af" if desc => "A_f",
        "Bf" if desc => "B_f",
        "Cf" if desc => "C_f",
        "Am" if desc => "A_m",
        "Bm" if desc => "B_m",
        "Cm" if desc => "C_m",
        "N" if desc => "N",
        "Binf" => r"B_\infty",
        "Cinf" => r"C_\infty",
        "Nr" => "N_r",
        "Br" if desc => "B_r",
        "Cr" if desc => "C_r",
        "q" if desc => r"q\ (\text{degree of the polynomial part})",
        "order" if desc => r"\text{order}",
        "removed" if desc => r"\text{removed}",
        "orders" => r"n,\ n_{\text{irr}},\ n_{\min},\ n_f,\ n_\infty",
        "E" if desc => "E",
        "A" if desc => "A",
        "B" if desc => "B",
        "C" if desc => "C",
        "D" if desc => "D",
        _ => return None,
    })
}

/// Whether an object key is a flag its sentence already states (not typeset in LaTeX).
pub fn flag(key: &str) -> bool {
    matches!(key, "orth" | "refused" | "shifted" | "excited" | "observed")
        || super::steps_modes::flag(key)
}

/// The words of a normalisation (`jordan --normalize`).
fn normalization_words(how: &Normalization) -> String {
    let mut parts = vec![];
    if how.orthogonal {
        parts.push(
            "every generalized eigenvector orthogonal to its eigenvector, v_j . v_1 = 0 (eq. 31)"
                .to_string(),
        );
    }
    match how.scale {
        Scale::Keep => {}
        Scale::Entry(Some(r)) => parts.push(format!("entry {} of each eigenvector 1 (its first nonzero entry where that one is 0)", r + 1)),
        Scale::Entry(None) => parts.push("the first nonzero entry of each eigenvector 1".into()),
        Scale::Unit => parts.push("each real eigenvector of unit length, v_1 . v_1 = 1 (exact when the length is rational, else in closed form: unit_lengths)".into()),
    }
    format!(
        "chains normalised: {}; each chain c (I + b_1 N + ...) V is again a chain of the same block, so J is unchanged and A T = T J is checked again",
        parts.join("; ")
    )
}

/// `jordan --normalize` without `--steps`: the Jordan form's report (its `T` with the
/// normalised chains) with `normalize` (what was asked) and `unit_lengths` (the chains whose
/// unit length is in closed form: the columns of `T` shown as $V'$, to be divided by
/// $\sqrt n$).
pub fn normalized_form_report<F: EigenField>(
    jf: &JordanForm<F>,
    how: &Normalization,
    closed: &[ClosedUnit<ExtElem<F::Elem>>],
) -> Report {
    // the columns of T: eigenvalue by eigenvalue (each conjugate root its own columns)
    let mut notes = vec![];
    let mut off = 0;
    for ev in 0..jf.eigenvalues.len() {
        let ci = jf.eigenvalues[ev].component;
        let (field, f) = jf.root_map(ev);
        for c in closed.iter().filter(|c| c.component == ci) {
            notes.push(unit_note(off + c.first, c.len, &field.fmt_elem(&f(&c.n))));
        }
        off += jf.components[ci].chains.ncols();
    }
    with_notes(jf.report(), how, notes)
}

/// [`normalized_form_report`] over $\mathbb{Q}(p)$ (after
/// [`crate::jordan::normalize::normalize_form_qp`]): the columns of $T$ component by
/// component (a factor of degree $d \ge 2$ and multiplicity $e$ takes $d e$ columns, its
/// primary block, which is not normalised), `conditions` the refreshed ones.
pub fn normalized_form_report_qp(
    jf: &JordanForm<crate::ratfunc::RatFuncField>,
    how: &Normalization,
    closed: &[ClosedUnit<ExtElem<crate::ratfunc::RatFunc>>],
) -> Report {
    let mut notes = vec![];
    let mut off = 0;
    for (ci, comp) in jf.components.iter().enumerate() {
        for c in closed.iter().filter(|c| c.component == ci) {
            notes.push(unit_note(off + c.first, c.len, &comp.field.fmt_elem(&c.n)));
        }
        off += comp.degree() * comp.multiplicity;
    }
    let mut r = with_notes(jf.report(), how, notes);
    if jf.components.iter().any(|c| !c.has_chains()) {
        r.push(
            "normalize_note",
            Value::Str("the columns of a factor of degree >= 2 are a basis of ker g(A)^e (its primary block), not Jordan chains: kept as they are".into()),
        );
    }
    r
}

/// The note of one chain whose unit length is in closed form (0-based first column).
fn unit_note(first: usize, len: usize, n: &str) -> Value {
    let (a, b) = (first + 1, first + len);
    let cols = if a == b {
        format!("column {a}")
    } else {
        format!("columns {a}-{b}")
    };
    Value::Str(format!(
        "{cols} of T: the chain shown is V' with v_1 . v_1 = n = {n}; the unit-length chain is V' / sqrt(n)"
    ))
}

fn with_notes(mut r: Report, how: &Normalization, notes: Vec<Value>) -> Report {
    r.push("normalize", Value::Str(normalization_words(how)));
    if !notes.is_empty() {
        r.push("unit_lengths", Value::List(notes));
    }
    r
}
