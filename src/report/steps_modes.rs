//! The texts of `contributions --steps` and `response --steps` (issue 27): titles, JSON
//! names, identities, sentences (plain and LaTeX) and the LaTeX symbols of their objects.
//! Called through `report::steps_norm`.

use crate::field::Field;
use crate::jordan::derivation::{Derivation, Method, Step, StepKind};

/// The title of a method of this file.
pub fn title(m: Method) -> &'static str {
    match m {
        Method::Contributions => "mode contributions (eq. 33) and truncation, step by step",
        Method::FreeResponse => "free response x(t) = e^(At) x0, step by step",
        _ => "derivation, step by step",
    }
}

/// The JSON name of a step kind of this file.
pub fn kind_name(k: StepKind) -> &'static str {
    match k {
        StepKind::SpectralProjector => "spectral_projector",
        StepKind::ModeResidues => "residues",
        StepKind::ModeWeight => "weight",
        StepKind::ModeRanking => "ranking",
        StepKind::TruncationError => "truncation",
        StepKind::FreeTerms => "free_terms",
        StepKind::InitialState => "initial_state",
        _ => "step",
    }
}

/// The identity of a step kind of this file, as plain text and as LaTeX math.
pub fn identity(k: StepKind) -> (&'static str, &'static str) {
    match k {
        StepKind::SpectralProjector => (
            "R V = I, A V = V Ap, P^2 = P, Bp = R B, Cp = C V",
            r"R_p V_p = I,\ A V_p = V_p A_p,\ P_p^2 = P_p",
        ),
        StepKind::ModeResidues => (
            "sum over the conjugate roots of H_0 = Cp Bp",
            r"\textstyle\sum_{\text{conj}} H_0 = C_p B_p",
        ),
        StepKind::ModeWeight => (
            "Ap W + W Ap^H + Bp Bp^H = 0, h2 = tr(Cp W Cp^H) (^H: conjugate transpose; or every Cp Ap^k Bp = 0)",
            r"A_p W + W A_p^H + B_p B_p^H = 0,\ \|G_p\|_2^2 = \operatorname{tr}(C_p W C_p^H)",
        ),
        StepKind::ModeRanking => (
            "sum_p P_p = I, sum_p Cp Ap^k Bp = C A^k B (k < 2n)",
            r"\textstyle\sum_p P_p = I,\ \sum_p C_p A_p^k B_p = C A^k B",
        ),
        StepKind::TruncationError => (
            "C B = Ck Bk + E_0 (the error's first Markov parameter), G(0) = G_K(0) + E(0), the error's Lyapunov identity",
            r"CB = C_K B_K + E_0,\ G(0) = G_K(0) + E(0)",
        ),
        StepKind::FreeTerms => (
            "A g_k = theta g_k + (k+1) g_(k+1), so x' = A x term by term",
            r"A g_k = \theta g_k + (k+1) g_{k+1}",
        ),
        StepKind::InitialState => (
            "x(0) = sum_p Tr g_(p,0) = x0",
            r"x(0) = \textstyle\sum_p \operatorname{Tr} g_{p,0} = x_0",
        ),
        _ => ("", ""),
    }
}

fn theta<K: Field>(d: &Derivation<K>, s: &Step<K>) -> String {
    let f = super::steps_base::step_field(d, s);
    s.scalar("theta").map(|t| f.fmt_elem(t)).unwrap_or_default()
}

fn roots(s: usize) -> String {
    if s > 1 {
        format!(" (at the generic root t of a factor of degree {s}; its conjugates by embedding)")
    } else {
        String::new()
    }
}

/// The plain sentence of a step of this file.
pub fn sentence<K: Field>(d: &Derivation<K>, s: &Step<K>) -> String {
    let c = |k: &str| s.count(k).unwrap_or(0);
    let var = super::steps_base::poly_var(d);
    match s.kind {
        StepKind::SpectralProjector => format!(
            "The mode of the factor {}: its spectral projector P = V R (V its pivot columns, R the rows of its RREF) and the part (Ap, Bp, Cp) = (R A V, R B, C V) on the generalized eigenspace.",
            s.poly("f").map(|p| p.to_string_var(var)).unwrap_or_default()
        ),
        StepKind::ModeResidues => format!(
            "Residues of theta = {}{}: H_k = C G_k B side by side (k = 0, 1, ...), G(s) = D + sum k! H_k / (s - theta)^(k+1); eq. 33's products b_i c_i.",
            theta(d, s),
            roots(c("deg"))
        ),
        StepKind::ModeWeight if c("zero") == 1 => "Weight 0: every Markov parameter of the part is zero (eq. 33: b c = 0, the mode does not reach y from u).".into(),
        StepKind::ModeWeight if c("infinite") == 1 => "Weight infinite: the part contributes and is not asymptotically stable (H2 = infinity); never dropped before the finite ones.".into(),
        StepKind::ModeWeight if c("where_stable") == 1 => "Weight: tr(Cp W Cp^T), a rational function of the parameters, with W the exact solution of the Lyapunov equation Ap W + W Ap^T + Bp Bp^T = 0: the squared H2 norm of the part for the parameter values where Ap is Hurwitz (a sign condition on the parameters, not decided in symbols; elsewhere the norm is infinite).".into(),
        StepKind::ModeWeight => "Weight: the squared H2 norm of the part, tr(Cp W Cp^H) with W the exact solution of the Lyapunov equation Ap W + W Ap^H + Bp Bp^H = 0 (^H: the conjugate transpose, the transpose over a real field).".into(),
        StepKind::ModeRanking if c("unranked") == 1 => format!(
            "The projectors add up to I (n = {}) and the parts' Markov parameters to C A^k B; the modes in the order of the factors {} (not ranked: their weights are rational functions of the parameters, whose order changes with the values).",
            c("n"),
            s.counts("ranked").map(super::steps_base::one_based).unwrap_or_default()
        ),
        StepKind::ModeRanking => format!(
            "The projectors add up to I (n = {}) and the parts' Markov parameters to C A^k B; the modes ranked heaviest first: factors {}.",
            c("n"),
            s.counts("ranked").map(super::steps_base::one_based).unwrap_or_default()
        ),
        StepKind::TruncationError => format!(
            "Truncation: keep the factors {}; (Ak, Bk, Ck, D) is the sum of their parts, the error E = G - G_K the sum of the dropped ones: its first Markov parameter M0 = C_D B_D, its DC gain E(0) = -C_D A_D^-1 B_D and its H2 norm squared h2 (when the dropped parts are stable).",
            s.counts("kept_modes").map(super::steps_base::one_based).unwrap_or_default()
        ),
        StepKind::FreeTerms => format!(
            "Eigenvalue theta = {}{}: the vectors g_k = G_k x0 (side by side) of the terms t^k e^(theta t) g_k of x(t).",
            theta(d, s),
            roots(c("deg"))
        ),
        StepKind::InitialState => "At t = 0 only the terms k = 0 remain: their sum over every root (the trace over each factor's conjugates) is x0.".into(),
        _ => String::new(),
    }
}

/// The LaTeX sentence of a step of this file.
pub fn sentence_latex<K: Field>(st: &Step<K>) -> String {
    let c = |k: &str| st.count(k).unwrap_or(0);
    match st.kind {
        StepKind::SpectralProjector => "The mode of the factor $f$: its spectral projector $P_p = V_p R_p$ ($V_p$ its pivot columns, $R_p$ the rows of its RREF) and the part $(A_p, B_p, C_p) = (R_p A V_p, R_p B, C V_p)$.".into(),
        StepKind::ModeResidues => "The residues $H_k = C G_{\\theta,k} B$ (side by side, $k = 0, 1, \\dots$) of $G(s) = D + \\sum_k k!\\,H_k/(s - \\theta)^{k+1}$: eq.~33's products $b_i c_i$.".into(),
        StepKind::ModeWeight if c("zero") == 1 => "Weight $0$: every Markov parameter of the part vanishes (eq.~33: $bc = 0$).".into(),
        StepKind::ModeWeight if c("infinite") == 1 => "Weight $\\infty$: the part contributes and is not asymptotically stable.".into(),
        StepKind::ModeWeight if c("where_stable") == 1 => "Weight: $\\operatorname{tr}(C_p W C_p^T)$, a rational function of the parameters, with $W$ the exact solution of $A_p W + W A_p^T + B_p B_p^T = 0$: it is $\\|G_p\\|_2^2$ where $A_p$ is Hurwitz (a sign condition on the parameters, not decided in symbols; elsewhere $\\|G_p\\|_2 = \\infty$).".into(),
        StepKind::ModeWeight => "Weight: $\\|G_p\\|_2^2 = \\operatorname{tr}(C_p W C_p^H)$ with $W$ the exact solution of $A_p W + W A_p^H + B_p B_p^H = 0$ ($^H$: the conjugate transpose, the transpose over a real field).".into(),
        StepKind::ModeRanking if c("unranked") == 1 => "The projectors add up to $I$ and the parts to $G$; the modes in the order of the factors (not ranked: their weights are rational functions of the parameters, whose order changes with their values).".into(),
        StepKind::ModeRanking => "The projectors add up to $I$ and the parts to $G$; the modes ranked heaviest first (factor numbers below).".into(),
        StepKind::TruncationError => "Truncation: $(A_K, B_K, C_K, D)$ keeps the heaviest modes; the error $E = G - G_K$ is the sum of the dropped parts: $E_0 = C_D B_D$, $E(0) = -C_D A_D^{-1} B_D$, $\\|E\\|_2^2$.".into(),
        StepKind::FreeTerms => "The vectors $g_k = G_{\\theta,k} x_0$ (side by side) of the terms $t^k e^{\\theta t} g_k$ of $x(t)$.".into(),
        StepKind::InitialState => "At $t = 0$ only the terms $k = 0$ remain; their sum over every root is $x_0$.".into(),
        _ => String::new(),
    }
}

/// The LaTeX symbol of an object key of this file's steps.
pub fn symbol(kind: StepKind, key: &str) -> Option<&'static str> {
    use StepKind as S;
    let modes = matches!(
        kind,
        S::SpectralProjector
            | S::ModeResidues
            | S::ModeWeight
            | S::ModeRanking
            | S::TruncationError
            | S::FreeTerms
            | S::InitialState
    );
    if !modes {
        return None;
    }
    Some(match key {
        "f" => "f",
        "P" => "P_p",
        "V" => "V_p",
        "R" => "R_p",
        "Ap" => "A_p",
        "Bp" => "B_p",
        "Cp" => "C_p",
        "theta" => r"\theta",
        "H" => r"[H_0, H_1, \dots]",
        "W" => "W",
        "h2" if kind == S::TruncationError => r"\|E\|_2^2",
        "h2" => r"\|G_p\|_2^2",
        "ranked" => r"\text{ranking}",
        "kept_modes" => r"\text{kept}",
        "Ak" => "A_K",
        "Bk" => "B_K",
        "Ck" => "C_K",
        "M0" => "E_0",
        "dc" => "E(0)",
        "g" => r"[g_0, g_1, \dots]",
        "x0" => "x_0",
        "n" => "n",
        _ => return None,
    })
}

/// Whether an object key lists indices (shown one-based).
pub fn index_list(key: &str) -> bool {
    matches!(key, "ranked" | "kept_modes")
}

/// Flags the sentence states.
pub fn flag(key: &str) -> bool {
    matches!(key, "zero" | "infinite" | "where_stable" | "unranked")
}
