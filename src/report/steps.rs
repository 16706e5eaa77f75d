//! Derivations (`--steps`) as reports: one sentence per step, the exact objects it computed,
//! the identity it establishes, whether that identity held, and (over $\mathbb{Q}(p)$) what it
//! assumes. JSON gives the steps as data (`steps: [{step, sentence, <objects>, identity,
//! holds, assumes}]`); text prints them as a numbered derivation; LaTeX
//! (`report::steps_latex`) typesets a worked example.

use crate::field::Field;
use crate::jordan::derivation::{Derivation, Method, Object, Step, StepKind};
use crate::poly::Poly;
use crate::report::{MatrixOut, Report, Value, str_list};

pub(crate) use super::steps_base::{counts, one_based, poly_var, step_field, theta_step};

/// `text` with the Laplace variable `s` written as `var` (`z` in discrete time): every `s`
/// standing as a symbol of its own (`(s)`, `sI`, `s_0`, `s0`, `s^{k}`), not a letter of a
/// word, a subscript (`A_s`, `x_s`) or a LaTeX command. The identity for `var = "s"`.
pub(crate) fn in_variable(text: &str, var: &str) -> String {
    if var == "s" {
        return text.to_string();
    }
    let cs: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    for (i, &c) in cs.iter().enumerate() {
        let prev = i.checked_sub(1).map(|j| cs[j]);
        let next = cs.get(i + 1).copied();
        let alone = c == 's'
            && !prev.is_some_and(|p| p.is_alphanumeric() || matches!(p, '_' | '\\' | '\'' | '{'))
            && !next.is_some_and(|n| n.is_ascii_lowercase() || n == '\'' || n == '}');
        if alone {
            out.push_str(var);
        } else {
            out.push(c);
        }
    }
    out
}

/// [`in_variable`] inside the math of a LaTeX sentence only (between `$` signs): the words
/// around it (`chain(s)`) stay.
pub(crate) fn in_variable_math(text: &str, var: &str) -> String {
    if var == "s" {
        return text.to_string();
    }
    text.split('$')
        .enumerate()
        .map(|(i, part)| {
            if i % 2 == 1 {
                in_variable(part, var)
            } else {
                part.to_string()
            }
        })
        .collect::<Vec<_>>()
        .join("$")
}

/// The name of a derivation's field (a field $F$ as its extension of degree 1,
/// $F\[t\]/(t)$: $F$, so the rationals as a number field of degree 1 are `QQ`).
pub fn field_name<K: Field>(k: &K) -> String {
    let s = k.to_string();
    match s.strip_suffix("[t]/(t)") {
        Some(base) => base.to_string(),
        None => s,
    }
}

/// The method's title.
pub fn title(m: Method) -> &'static str {
    match m {
        Method::Jordan => "Jordan decomposition, step by step",
        Method::Kalman => "minimal realization (Kalman decomposition), step by step",
        Method::JordanMethod => "minimal realization (Jordan-form method), step by step",
        m => super::steps_more::title(m),
    }
}

/// The JSON name of a step kind.
pub fn kind_name(k: StepKind) -> &'static str {
    match k {
        StepKind::CharPoly => "charpoly",
        StepKind::Factorization => "factorization",
        StepKind::KernelSequence => "kernel_sequence",
        StepKind::WeyrSegre => "weyr_segre",
        StepKind::Chain => "chain",
        StepKind::EigenCheck => "eigen_check",
        StepKind::PrimaryBlock => "primary_block",
        StepKind::Similarity => "similarity",
        StepKind::Controllability => "controllability",
        StepKind::ControllableSubspace => "controllable_subspace",
        StepKind::Observability => "observability",
        StepKind::UnobservableSubspace => "unobservable_subspace",
        StepKind::KalmanBasis => "kalman_basis",
        StepKind::KalmanForm => "kalman_form",
        StepKind::MinimalPart => "minimal_part",
        StepKind::ModalData => "modal_data",
        StepKind::DropModes => "drop_modes",
        StepKind::Compaction => "compaction",
        StepKind::Stages => "stages",
        StepKind::Restriction => "restriction",
        k => super::steps_more::kind_name(k),
    }
}

/// The identity a step establishes, as plain text and as LaTeX math.
pub fn identity(k: StepKind) -> (&'static str, &'static str) {
    match k {
        StepKind::CharPoly => (
            "chi_A(A) = 0 (Cayley-Hamilton)",
            r"\chi_A(A) = 0 \quad\text{(Cayley--Hamilton)}",
        ),
        StepKind::Factorization => (
            "prod p_i^e_i = chi_A, p_i irreducible",
            r"\textstyle\prod_i p_i^{e_i} = \chi_A",
        ),
        StepKind::KernelSequence => (
            "dim ker N^k = n - rank N^k, increasing to the algebraic multiplicity mu",
            r"\dim\ker N^k = n - \operatorname{rank} N^k \nearrow \mu",
        ),
        StepKind::WeyrSegre => (
            "segre = conjugate partition of weyr, sum = mu",
            r"s_j = \#\{k : w_k \ge j\},\ \textstyle\sum_j s_j = \mu",
        ),
        StepKind::Chain => (
            "N v_1 = 0, v_1 != 0, N v_j = v_(j-1)",
            r"N v_1 = 0,\ v_1 \ne 0,\ N v_j = v_{j-1}",
        ),
        StepKind::EigenCheck => ("A V = V J_theta, W V = I", r"A V = V J_\theta,\ W V = I"),
        StepKind::PrimaryBlock => ("A B = B M, dim ker f(A)^e = d e", r"A B = B M"),
        StepKind::Similarity => ("A T = T J, T invertible", r"A T = T J,\ \det T \ne 0"),
        StepKind::Controllability | StepKind::Observability => ("(rank computed)", ""),
        StepKind::ControllableSubspace => (
            "im B in R, A R in R, dim R = rank Ctrb",
            r"\operatorname{im} B \subseteq \mathcal R,\ A\mathcal R \subseteq \mathcal R",
        ),
        StepKind::UnobservableSubspace => (
            "Obsv N = 0, A N in N, dim N = n - rank Obsv",
            r"\mathcal O \mathcal N = 0,\ A\mathcal N \subseteq \mathcal N",
        ),
        StepKind::KalmanBasis => ("T invertible, dims agree with the ranks", r"\det T \ne 0"),
        StepKind::KalmanForm => (
            "A T = T At, B = T Bt, Ct = C T, Kalman zero pattern",
            r"A T = T \tilde A,\ B = T \tilde B,\ \tilde C = C T",
        ),
        StepKind::MinimalPart => (
            "C A^k B = Cm Am^k Bm (k < n + r), r = McMillan degree",
            r"C A^k B = C_2 A_{22}^k B_2,\ r = \delta_M",
        ),
        StepKind::ModalData => ("(modal coordinates z = W x)", ""),
        StepKind::DropModes | StepKind::Compaction => (
            "the block's Markov parameters are unchanged",
            r"C V J_\theta^k W B\ \text{unchanged for all } k",
        ),
        StepKind::Stages => (
            "every stage's C_s A_s^k B_s = C A^k B and Cr Ar^k Br = C A^k B (k < 2n), Dr = D, order = McMillan degree",
            r"C_s A_s^k B_s = C_r A_r^k B_r = C A^k B\ (k < 2n),\ r = \delta_M",
        ),
        StepKind::Restriction => (
            "A u = u Ag, P u = I, P A = Ag P",
            r"A u = u A_g,\ P u = I,\ P A = A_g P",
        ),
        k => super::steps_more::identity(k),
    }
}

/// A polynomial in `var`.
pub fn poly_text<K: Field>(p: &Poly<K>, var: &str) -> String {
    p.to_string_var(var)
}

/// The factors `(p)^e` joined by `*`.
fn factors_text<K: Field>(fs: &[(Poly<K>, usize)], var: &str) -> String {
    let v: Vec<String> = fs
        .iter()
        .map(|(p, e)| {
            let s = format!("({})", poly_text(p, var));
            if *e > 1 { format!("{s}^{e}") } else { s }
        })
        .collect();
    v.join(" * ")
}

/// The eigenvalue of a part, as text.
fn theta_of<K: Field>(d: &Derivation<K>, part: Option<usize>) -> String {
    match theta_step(d, part).and_then(|s| s.scalar("theta").map(|t| (s, t))) {
        Some((s, t)) => step_field(d, s).fmt_elem(t),
        None => "?".into(),
    }
}

/// Whether a part is worked in a number field at its generic root `t` (degree >= 3).
pub(crate) fn generic_root<K: Field>(d: &Derivation<K>, s: &Step<K>) -> bool {
    s.scalar("theta")
        .is_some_and(|t| step_field(d, s).fmt_elem(t) == "t")
}

fn field_note<K: Field>(d: &Derivation<K>, s: &Step<K>) -> String {
    if generic_root(d, s) {
        format!(
            " (worked once in {} at the generic root t; its conjugates by the embeddings t -> theta_j)",
            step_field(d, s)
        )
    } else {
        String::new()
    }
}

fn conjugates(d: usize) -> String {
    if d > 1 {
        format!(" (the same for each of the {d} conjugate roots)")
    } else {
        String::new()
    }
}

/// The sentence of a step (plain text).
pub fn sentence<K: Field>(d: &Derivation<K>, s: &Step<K>) -> String {
    let var = poly_var(d);
    let c = |key: &str| s.count(key).unwrap_or(0);
    let cs = |key: &str| s.counts(key).map(counts).unwrap_or_default();
    let ob = |key: &str| s.counts(key).map(one_based).unwrap_or_default();
    let theta = || theta_of(d, s.part);
    match s.kind {
        StepKind::CharPoly => match s.get("chi") {
            Some(Object::Poly(p)) => format!(
                "Characteristic polynomial chi_A({var}) = det({var} I - A) = {}.",
                poly_text(p, var)
            ),
            _ => "Characteristic polynomial.".into(),
        },
        StepKind::Factorization => match s.get("factors") {
            Some(Object::Factors(f)) => {
                format!("Irreducible factors: chi_A = {}.", factors_text(f, var))
            }
            _ => "Irreducible factors.".into(),
        },
        StepKind::KernelSequence => format!(
            "Eigenvalue theta = {} of algebraic multiplicity mu = {}{}: N = A - theta I; rank N^k = {} so dim ker N^k = {} (k = 1..{}).",
            theta(),
            c("m"),
            field_note(d, s),
            cs("ranks"),
            cs("dims"),
            s.counts("dims").map_or(0, |x| x.len())
        ),
        StepKind::WeyrSegre => format!(
            "Weyr characteristic w_k = dim ker N^k - dim ker N^(k-1) = ({}): the number of Jordan blocks of size >= k; its conjugate partition, the Segre characteristic ({}), gives the block sizes.",
            cs("weyr"),
            cs("segre")
        ),
        StepKind::Chain if c("top") == 1 => format!(
            "Eigenvector of theta = {} (a chain of length 1): v_1 in ker N.",
            theta()
        ),
        StepKind::Chain => format!(
            "Chain of length {top} for theta = {}, built top-down: v_{top} in ker N^{top} but not in ker N^{below}, then v_(j-1) = N v_j (the columns v_1..v_{top}). The family (the free constants of the vehicle paper's eq. 30, 32): with K a basis of ker N (N K = 0, checked), v_j + K c solves N x = v_(j-1) for every c; the chain takes c = 0.",
            theta(),
            top = c("top"),
            below = c("top") - 1
        ),
        StepKind::EigenCheck => format!(
            "The chains of theta = {} as the columns V, with its Jordan matrix J_theta.",
            theta()
        ),
        StepKind::PrimaryBlock => format!(
            "Irreducible factor f of degree {} (its roots are not in the field of the entries): dim ker f(A)^k = {}; each root has Jordan blocks ({}); a basis B of ker f(A)^e and M with A B = B M form the primary block.",
            match s.get("f") {
                Some(Object::Poly(p)) => p.deg(),
                _ => 0,
            },
            cs("dims"),
            cs("segre")
        ),
        StepKind::Similarity => match s.counts("dims") {
            Some(dims) => format!(
                "The generalized eigenspaces (dimension degree x multiplicity: {}) add up to n = {}; with the conjugate roots' columns by Galois conjugation, T = [V_1, V_2, ...] is the Jordan basis.",
                counts(dims),
                c("n")
            ),
            None => "T = [V_1, V_2, ...] and J = diag(J_1, J_2, ...) from the steps above.".into(),
        },
        StepKind::Controllability => format!(
            "Controllability matrix Ctrb = [B, AB, ..., A^(n-1) B], rank {}.",
            c("rank")
        ),
        StepKind::ControllableSubspace => format!(
            "Controllable subspace R: the pivot columns ({}) of the RREF of Ctrb (Krylov vectors).",
            ob("pivots")
        ),
        StepKind::Observability => format!(
            "Observability matrix Obsv = [C; CA; ...; CA^(n-1)], rank {}.",
            c("rank")
        ),
        StepKind::UnobservableSubspace => format!(
            "Unobservable subspace N = ker Obsv, dimension {}.",
            s.matrix("Nobs").map_or(0, |m| m.ncols())
        ),
        StepKind::KalmanBasis => format!(
            "Kalman basis T = [X_co', X_co, X_c'o', X_c'o] with parts of dimensions ({}): R meet N, R completed, N completed, the whole space completed.",
            cs("dims")
        ),
        StepKind::KalmanForm => "The Kalman form (T^-1 A T, T^-1 B, C T).".into(),
        StepKind::MinimalPart => format!(
            "The controllable and observable part (A_22, B_2, C_2, D) is minimal: order {} = McMillan degree {}.",
            c("order"),
            c("mcmillan")
        ),
        StepKind::ModalData => format!(
            "Eigenvalue theta = {}{}: modal data in z = W x: (J_theta, W B, C V){}.",
            theta(),
            field_note(d, s),
            conjugates(c("deg"))
        ),
        StepKind::DropModes => format!(
            "Drop non-contributing modes of theta = {}: kept states ({}); not excited (after the last excited state of their block): {}; not observed (before the first observed state): {}{}.",
            theta(),
            ob("kept"),
            ob("not_excited"),
            ob("not_observed"),
            conjugates(c("deg"))
        ),
        StepKind::Compaction => format!(
            "Compact the repeated modes of theta = {}: a minimal realization of (N, W B, C V) over the field (Kalman), back in Jordan form by its chains: order {}{}.",
            theta(),
            c("order"),
            conjugates(c("deg"))
        ),
        StepKind::Stages => {
            let st = s.counts("stages").unwrap_or(&[]);
            let at = |i: usize| st.get(i).copied().unwrap_or(0);
            format!(
                "Stages: {} states -> {} after dropping non-contributing modes -> {} after compacting repeated modes (McMillan degree {}); each stage, written over the base field, reproduces the Markov parameters C A^k B. The realization (Ar, Br, Cr, Dr) is the command's result (`minreal --method jordan`).",
                at(0),
                at(1),
                at(2),
                c("mcmillan")
            )
        }
        StepKind::Restriction => restriction_sentence(s, var),
        _ => super::steps_more::sentence(d, s, var),
    }
}

/// The sentence of a restriction step: the factor, the part and why it is kept or dropped.
fn restriction_sentence<K: Field>(s: &Step<K>, var: &str) -> String {
    let g = s.poly("g").map(|p| poly_text(p, var)).unwrap_or_default();
    let deg = s.count("deg").unwrap_or(0);
    let flag = |k: &str| s.count(k) == Some(1);
    let basis = if s.matrix("u").is_some() {
        "u a basis of ker g(A), Ag with A u = u Ag, P the projector along im g(A) (P u = I, P A = Ag P)"
    } else {
        "g has degree n: u = P = I, the part is (A, B, C) itself"
    };
    let why = match (flag("excited"), flag("observed")) {
        (true, true) => format!(
            "kept: P B != 0 (excited) and C u != 0 (observed); g is irreducible, so Ag has no invariant subspace but 0 and the whole space, and the part is controllable and observable: minimal, {deg} states"
        ),
        (false, true) => "dropped: P B = 0, its modes are not excited".into(),
        (true, false) => "dropped: C u = 0, its modes are not observed".into(),
        (false, false) => "dropped: P B = 0 and C u = 0 (neither excited nor observed)".into(),
    };
    format!(
        "Simple irreducible factor g = {g} of degree {deg}: its {deg} roots as one block, no chains over F[t]/(g). The restriction ({basis}) gives the part (Ag, P B, C u) of C (sI - A)^-1 B; {why}."
    )
}

fn object_value<K: Field>(o: &Object<K>, var: &str, field: &K) -> Value {
    match o {
        Object::Matrix(m) => Value::Matrix(Box::new(MatrixOut::from_matrix(m))),
        Object::Poly(p) => Value::Str(poly_text(p, var)),
        Object::Factors(fs) => Value::List(
            fs.iter()
                .map(|(p, e)| {
                    Value::Obj(
                        Report::new()
                            .str("factor", poly_text(p, var))
                            .int("multiplicity", *e),
                    )
                })
                .collect(),
        ),
        Object::Scalar(x) => Value::Str(field.fmt_elem(x)),
        Object::Count(c) => Value::Int(*c as i64),
        Object::Counts(cs) => Value::List(cs.iter().map(|&c| Value::Int(c as i64)).collect()),
        Object::Polys(ps) => str_list(ps.iter().map(|p| poly_text(p, var))),
    }
}

/// One step as a report.
fn step_report<K: Field>(d: &Derivation<K>, i: usize, s: &Step<K>) -> Report {
    let var = poly_var(d);
    let text = sentence(d, s);
    let mut r = Report::titled(format!("step {}. {}", i + 1, text))
        .str("step", kind_name(s.kind))
        .with("sentence", Value::hidden_in_text(Value::Str(text)));
    if let Some(p) = s.part {
        r = r.int("part", p + 1);
    }
    let field = step_field(d, s);
    for (k, o) in &s.objects {
        r = r.with(*k, object_value(o, var, &field));
    }
    let (id, _) = identity(s.kind);
    if let Some(h) = s.holds {
        r = r.str("identity", in_variable(id, var)).bool("holds", h);
    }
    if !s.assumes.is_empty() {
        r = r.with(
            "assumes",
            str_list(
                s.assumes
                    .iter()
                    .map(|x| format!("{} != 0", d.field.fmt_elem(x))),
            ),
        );
    }
    r
}

/// The derivation as a report (text and JSON).
pub fn derivation_report<K: Field>(d: &Derivation<K>) -> Report {
    let steps: Vec<Value> = d
        .steps
        .iter()
        .enumerate()
        .map(|(i, s)| Value::Obj(step_report(d, i, s)))
        .collect();
    let mut conds: Vec<String> = vec![];
    for x in d.assumptions() {
        // parts derived in fields of their own may assume the same polynomial
        let c = format!("{} != 0", d.field.fmt_elem(x));
        if !conds.contains(&c) {
            conds.push(c);
        }
    }
    let mut r = Report::titled(title(d.method))
        .str("field", field_name(&d.field))
        .list("steps", steps);
    if !conds.is_empty() {
        r = r.with("conditions", str_list(conds));
    }
    r.bool("verified", d.verified())
}
