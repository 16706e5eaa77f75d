//! The texts of the derivations of `mnf`, `standard` (descriptor files) and `jordan --real`
//! (`--steps`): titles, JSON names, identities, sentences (plain and LaTeX) and the LaTeX
//! symbols of their objects. Called through `report::steps` and `report::steps_more`.

use crate::field::Field;
use crate::jordan::derivation::{Derivation, Method, Step, StepKind};

/// The title of a method of this file.
pub fn title(m: Method) -> &'static str {
    match m {
        Method::Mnf => "mechanical normal form (Mayet & Kammermeier), step by step",
        Method::Standard => "descriptor system to standard form, step by step",
        Method::RealJordan => "real Jordan form, step by step",
        m => super::steps_norm::title(m),
    }
}

/// The JSON name of a step kind of this file.
pub fn kind_name(k: StepKind) -> &'static str {
    match k {
        StepKind::MnfCompression => "input_compression",
        StepKind::MnfExistence => "existence",
        StepKind::MnfEquation => "equation_15",
        StepKind::MnfSearch => "invertible_member",
        StepKind::MnfForm => "normal_form",
        StepKind::DescriptorCompress => "compress_e",
        StepKind::DescriptorEliminate => "eliminate_algebraic",
        StepKind::DescriptorFitting => "fitting_split",
        StepKind::StandardForm => "standard_form",
        StepKind::RealPair => "real_pair",
        StepKind::RealForm => "real_form",
        k => super::steps_norm::kind_name(k),
    }
}

/// The identity of a step kind of this file, as plain text and as LaTeX math.
pub fn identity(k: StepKind) -> (&'static str, &'static str) {
    match k {
        StepKind::MnfCompression => ("B1 R = B", r"B_1 R = B"),
        StepKind::MnfExistence => (
            "U_B2^T B = 0 with n - rank B independent rows",
            r"U_{B,2}^T B = 0,\ \operatorname{rank} U_{B,2}^T = n - \operatorname{rank} B",
        ),
        StepKind::MnfEquation => (
            "[I 0] T0 A = [0 I] T0 F, T0 B = [0; I_p]; [I 0] Tk A = [0 I] Tk F, Tk B = 0",
            r"[I\ 0]\,T_0 A = [0\ I]\,T_0 F,\ T_0 B = [0;\ I_p],\ [I\ 0]\,T_k A = [0\ I]\,T_k F,\ T_k B = 0",
        ),
        StepKind::MnfSearch => (
            "T = T0 + sum_k alpha_k Tk (or T = I solving eq. 15), det T != 0",
            r"T = T_0 + \textstyle\sum_k \alpha_k T_k,\ \det T \ne 0",
        ),
        StepKind::MnfForm => (
            "At (T F) = T A, Bt = T B, Ct (T F) = C, At = [0, I; -K, -D], C At^j Bt = C (F^-1 A)^j F^-1 B (j < 2n)",
            r"\tilde A\,(TF) = T A,\ \tilde B = T B,\ \tilde C\,(TF) = C,\ \tilde C \tilde A^j \tilde B = C (F^{-1}A)^j F^{-1} B",
        ),
        StepKind::DescriptorCompress => (
            "U E V = diag(E11, 0), E11 invertible (r x r), U and V invertible",
            r"U E V = \operatorname{diag}(E_{11}, 0),\ \det E_{11} \ne 0,\ \det U \ne 0,\ \det V \ne 0",
        ),
        StepKind::DescriptorEliminate => (
            "X invertible, the reduced E' invertible (index <= 1)",
            r"\det X \ne 0,\ \det E' \ne 0",
        ),
        StepKind::DescriptorFitting => (
            "V^-1 Eh V = diag(Eh_1, N) block diagonal, G N nilpotent (E invertible: E Af = A, E Bf = B)",
            r"V^{-1}\hat E V = \operatorname{diag}(\hat E_1, N),\ (GN)^{n_\infty} = 0\ (\det E \ne 0:\ E A_f = A,\ E B_f = B)",
        ),
        StepKind::StandardForm => (
            "x = V1 z + W u maps solutions (E W = 0, E V1 As = A V1, E V1 Bs = A W + B, C V1 = Cs, C W + D = Ds), or C (sE - A)^-1 B + D = Cs (sI - As)^-1 Bs + Ds",
            r"C(sE - A)^{-1}B + D = C_s(sI - A_s)^{-1}B_s + D_s",
        ),
        StepKind::RealPair => ("A Tc = Tc Jc in the real field", r"A T_c = T_c J_c"),
        StepKind::RealForm => (
            "A T = T J, T invertible, T and J real",
            r"A T = T J,\ \det T \ne 0,\ T, J\ \text{real}",
        ),
        k => super::steps_norm::identity(k),
    }
}

fn cnt<K: Field>(s: &Step<K>, key: &str) -> usize {
    s.count(key).unwrap_or(0)
}

fn existence_sentence<K: Field>(s: &Step<K>) -> String {
    let (n, p) = (cnt(s, "n"), cnt(s, "p"));
    let h = n / 2;
    let mut parts = vec![format!(
        "Existence (Theorem 2.1, last condition replaced){}: n = {n} {}",
        if cnt(s, "descriptor") == 1 {
            ", on the pair (F^-1 A, F^-1 B) by one solve with F"
        } else {
            ""
        },
        if n % 2 == 0 { "is even" } else { "is odd" }
    )];
    if n % 2 == 0 {
        parts.push(format!(
            "p = {p} {} n/2 = {h}",
            if p <= h { "<=" } else { ">" }
        ));
    }
    if let Some(rb) = s.count("rank_b") {
        parts.push(format!("rank B = {rb}"));
    }
    if let Some(rk) = s.count("rank_k") {
        parts.push(format!(
            "U_B2^T (the canonical left null space of B) gives K = U_B2^T A B of rank {rk} (rank [B, AB] = 2p iff rank K = p)"
        ));
    }
    if let Some(rg) = s.count("rank_g") {
        parts.push(format!(
            "Theorem 2.1's G has rank {rg} (n/2 - p = {}; reported only: not similarity invariant)",
            h.saturating_sub(p)
        ));
    }
    if let Some(g) = s.count("geo") {
        parts.push(format!(
            "the uncontrollable part's largest geometric multiplicity is {g} ({} n/2 - p = {})",
            if g <= h.saturating_sub(p) { "<=" } else { ">" },
            h.saturating_sub(p)
        ));
    }
    format!(
        "{}: the normal form {}.",
        parts.join("; "),
        if cnt(s, "exists") == 1 {
            "exists"
        } else {
            "does not exist"
        }
    )
}

/// The plain sentence of a step of this file.
pub fn sentence<K: Field>(d: &Derivation<K>, s: &Step<K>) -> String {
    let c = |key: &str| cnt(s, key);
    match s.kind {
        StepKind::MnfCompression => format!(
            "Input compression: rank B = {} < p = {}, so B = B1 R with B1 the pivot columns of B and R the nonzero rows of rref(B); the form is sought for (A, B1) and W = [0; R].",
            s.matrix("B1").map_or(0, |m| m.ncols()),
            s.matrix("B").map_or(0, |m| m.ncols())
        ),
        StepKind::MnfExistence => existence_sentence(s),
        StepKind::MnfEquation => format!(
            "Eq. 15/16: the requirements [I 0] T A = [0 I] T F and T B = [0; I_p] as L vec(T) = R (column-stacking vec, L = [A^T (x) [I 0] - F^T (x) [0 I]; B^T (x) I_n]); rank L = {}, so T = T0 + sum_k alpha_k T_k with s = {} free directions T_k (shown side by side when s <= 4).",
            c("rank_L"),
            c("s")
        ),
        StepKind::MnfSearch if c("t_equals_i") == 1 => "The system is already in mechanical normal form: T = I solves eq. 15 ([I 0] A = [0 I] F and B = [0; I_p]), so it is taken without a search.".into(),
        StepKind::MnfSearch => format!(
            "An invertible member: integer alpha (first alpha = 0, then a fixed pseudo-random sequence, then the grid {{0..n}}^s, which must contain a non-root of det T(alpha)); candidate {} has det T = {} != 0.",
            c("candidates"),
            s.scalar("det").map(|x| d.field.fmt_elem(x)).unwrap_or_default()
        ),
        StepKind::MnfForm => "The normal form z = (T F) x: At = T A (T F)^-1 = [0, I; -K, -D], Bt = T B = [0; W], Ct = C (T F)^-1; the second-order model M q'' + D q' + K q = W u with M = I, D = -At_22, K = -At_21.".into(),
        StepKind::DescriptorCompress => format!(
            "Compress E: r = rank E = {}; U = [unit rows at the pivot rows of E; its left null space], V = [unit columns at its pivot columns, its null space], so U E V = diag(E11, 0) and x = V z. The algebraic block A^22 of U A V has rank {} ({}).",
            c("r"),
            c("k"),
            if c("k") + c("r") == s.matrix("E").map_or(0, |m| m.nrows()) {
                "= n - r: index at most 1, every algebraic state is eliminated"
            } else {
                "< n - r: index > 1, the Weierstrass split follows"
            }
        ),
        StepKind::DescriptorEliminate => format!(
            "Eliminate the algebraic states {} with the equations {} (X = A^_IJ invertible): z_J = -X^-1 (A^_IS z_S + B^_I u); E' = E11, A' = A^_RS - A^_RJ X^-1 A^_IS, B' = B^_R - A^_RJ X^-1 B^_I, C' = C^_S - C^_J X^-1 A^_IS, D' = D - C^_J X^-1 B^_I.",
            s.counts("states").map(super::steps_base::one_based).unwrap_or_default(),
            s.counts("eqs").map(super::steps_base::one_based).unwrap_or_default()
        ),
        StepKind::DescriptorFitting if s.get("lambda0").is_none() => "E is invertible: no infinite eigenvalues, the split is trivial, V1 = I, Af = E^-1 A, Bf = E^-1 B (E Af = A, E Bf = B).".into(),
        StepKind::DescriptorFitting => format!(
            "Weierstrass split: lambda_0 = {} has det(lambda_0 E - A) != 0; Eh = (lambda_0 E - A)^-1 E and its Fitting decomposition x = V1 z1 + V2 z2 (range and kernel of Eh^n) give z1' = Af z1 + Bf u (finite modes) and (I + s G N) z2 = G B2 u (infinite modes, G = (I - lambda_0 N)^-1).",
            s.scalar("lambda0").map(|x| d.field.fmt_elem(x)).unwrap_or_default()
        ),
        StepKind::StandardForm => format!(
            "The standard form (As, Bs, Cs, Ds): {} states, {} infinite eigenvalue(s) removed; {}.",
            s.matrix("As").map_or(0, |m| m.nrows()),
            c("removed"),
            match c("route") {
                0 => "E invertible: As = E^-1 A, Bs = E^-1 B",
                1 => "x = V1 z + W u with the eliminated states",
                _ => "the system is proper: Ds = D + C V2 G B2",
            }
        ),
        StepKind::RealPair if c("compact") == 1 => "A complex pair whose real field K(Re theta, Im theta) is large: kept in the compact form (its complex chains above; T_R = [Re V, Im V]).".into(),
        StepKind::RealForm => "The real Jordan form: T = [the real eigenvalues' chains, the pairs' real columns] and J = diag(their Jordan blocks, the real pair blocks), over one real field.".into(),
        StepKind::RealPair if s.get("w2").is_some() => "The quadratic factor x^2 + c1 x + c0: its roots theta = alpha +- i w with alpha = -c1/2 (re) and w^2 = c0 - c1^2/4 (w2), w a symbol, are a complex pair where the discriminant c1^2 - 4 c0 (disc) is < 0 (assumed for this real form; where it is > 0 the roots are real). The chain v_j = p_j + q_j t shown above (t the generic root) gives the real columns x_j = p_j + alpha q_j, y_j = w q_j and the blocks [[alpha, w], [-w, alpha]] with I_2 above the diagonal; A Tc = Tc Jc is checked in QQ(p)[w]/(w^2 - w2) by ring operations only, so it holds for either square root.".into(),
        StepKind::RealPair => "A complex pair theta = a + b i, conj(theta): the chain v_1..v_k of theta gives the real columns x_j = Re v_j, y_j = Im v_j, and A(x + i y) = (a + b i)(x + i y) gives A x = a x - b y, A y = b x + a y: the blocks [[a, b], [-b, a]] with I_2 above the diagonal.".into(),
        _ => super::steps_norm::sentence(d, s),
    }
}

/// The LaTeX sentence of a step of this file.
pub fn sentence_latex<K: Field>(st: &Step<K>) -> String {
    let c = |k: &str| cnt(st, k);
    match st.kind {
        StepKind::MnfCompression => "Input compression: $B = B_1 R$ with $B_1$ the pivot columns of $B$ and $R$ the nonzero rows of $\\operatorname{rref}(B)$; the form is sought for $(A, B_1)$ and $W = [0; R]$.".into(),
        StepKind::MnfExistence => format!(
            "Existence (Theorem~2.1 with its last condition replaced by a similarity-invariant one){}: $n$ even, $p \\le n/2$, $\\operatorname{{rank}} B = p$, $K = U_{{B,2}}^T A B$ of rank $p$ ($U_{{B,2}}^T$ the canonical left null space of $B$), and every uncontrollable eigenvalue with at most $n/2 - p$ independent eigenvectors. Theorem~2.1's $G$ is shown for comparison. The normal form {}.",
            if c("descriptor") == 1 { ", on the pair $(F^{-1}A, F^{-1}B)$" } else { "" },
            if c("exists") == 1 { "exists" } else { "does not exist" }
        ),
        StepKind::MnfEquation => "Eq.~15/16: $[I\\ 0]\\,T A = [0\\ I]\\,T F$ and $T B = [0; I_p]$ as $L\\,\\mathrm{vec}(T) = R$ with $L = [A^T \\otimes [I\\ 0] - F^T \\otimes [0\\ I];\\ B^T \\otimes I_n]$; its solutions $T = T_0 + \\sum_k \\alpha_k T_k$ ($s$ directions, side by side below when $s \\le 4$).".into(),
        StepKind::MnfSearch if c("t_equals_i") == 1 => "The system is already in mechanical normal form: $T = I$ solves eq.~15, so it is taken without a search.".into(),
        StepKind::MnfSearch => "An invertible member $T(\\alpha)$ with integer $\\alpha$ (first $\\alpha = 0$, then a fixed pseudo-random sequence, then the grid $\\{0..n\\}^s$, which must contain a non-root of $\\det T(\\alpha)$), tested by its exact determinant.".into(),
        StepKind::MnfForm => "The normal form $z = (TF)x$: $\\tilde A = TA(TF)^{-1} = [0,\\ I;\\ -K,\\ -D_q]$, $\\tilde B = TB = [0; W]$, $\\tilde C = C(TF)^{-1}$: the second-order model $M\\ddot q + D_q\\dot q + K q = W u$.".into(),
        StepKind::DescriptorCompress => "Compress $E$: $U$ = unit rows at the pivot rows of $E$ over its left null space, $V$ = unit columns at its pivot columns beside its null space, so $UEV = \\operatorname{diag}(E_{11}, 0)$, $x = Vz$; $k$ is the rank of the algebraic block $\\hat A_{22}$ (index $\\le 1$ iff $k = n - r$).".into(),
        StepKind::DescriptorEliminate => "Eliminate the algebraic states $z_J$ with the equations $I$ ($X = \\hat A_{IJ}$ invertible, one-based indices below): $z_J = -X^{-1}(\\hat A_{IS} z_S + \\hat B_I u)$, leaving $E' \\dot z_S = A' z_S + B' u$, $y = C' z_S + D' u$.".into(),
        StepKind::DescriptorFitting if st.get("lambda0").is_none() => "$E$ is invertible: no infinite eigenvalues, the split is trivial, $V_1 = I$, $A_f = E^{-1}A$, $B_f = E^{-1}B$.".into(),
        StepKind::DescriptorFitting => "Weierstrass split: $\\det(\\lambda_0 E - A) \\ne 0$, $\\hat E = (\\lambda_0 E - A)^{-1}E$ and its Fitting decomposition $x = V_1 z_1 + V_2 z_2$ give the finite part $\\dot z_1 = A_f z_1 + B_f u$ and the infinite part $(I + sGN) z_2 = G\\hat B_2 u$, $G = (I - \\lambda_0 N)^{-1}$.".into(),
        StepKind::StandardForm => "The standard form $\\dot z = A_s z + B_s u$, $y = C_s z + D_s u$.".into(),
        StepKind::RealPair if c("compact") == 1 => "A complex pair whose real field is large: kept in the compact form.".into(),
        StepKind::RealForm => "The real Jordan form: $T$ = the real eigenvalues' chains beside the pairs' real columns, $J$ = their Jordan blocks beside the real pair blocks, over one real field.".into(),
        StepKind::RealPair if st.get("w2").is_some() => "The quadratic factor $x^2 + c_1 x + c_0$: its roots $\\theta = \\alpha \\pm i w$ with $\\alpha = -c_1/2$ and $w^2 = c_0 - c_1^2/4$ ($w$ a symbol) are a complex pair where $c_1^2 - 4c_0 < 0$ (assumed for this real form). The chains $v_j = p_j + q_j t$ above ($t$ the generic root) give the real columns $x_j = p_j + \\alpha q_j$, $y_j = w q_j$ and the blocks $[\\alpha,\\ w;\\ -w,\\ \\alpha]$ (with $I_2$ above the diagonal); $A T_c = T_c J_c$ holds in $\\mathbb{Q}(p)[w]$ modulo $w^2 - (c_0 - c_1^2/4)$ by ring operations only, so for either square root.".into(),
        StepKind::RealPair => "A complex pair $\\theta = a + bi$, $\\bar\\theta$: the real columns $x_j = \\operatorname{Re} v_j$, $y_j = \\operatorname{Im} v_j$ of its chains; $A(x + iy) = (a + bi)(x + iy)$ gives $Ax = ax - by$, $Ay = bx + ay$, so the blocks are $[a,\\ b;\\ -b,\\ a]$ (with $I_2$ above the diagonal).".into(),
        _ => super::steps_norm::sentence_latex(st),
    }
}

/// The LaTeX symbol of an object key of this file's steps (`None`: the common tables).
pub fn symbol(kind: StepKind, key: &str) -> Option<&'static str> {
    use StepKind as S;
    let mnf = matches!(
        kind,
        S::MnfCompression | S::MnfExistence | S::MnfEquation | S::MnfSearch | S::MnfForm
    );
    let desc = matches!(
        kind,
        S::DescriptorCompress | S::DescriptorEliminate | S::DescriptorFitting | S::StandardForm
    );
    Some(match key {
        "B1" if mnf => "B_1",
        "R" if mnf => "R",
        "UB2t" => r"U_{B,2}^T",
        "rank_b" => r"\operatorname{rank} B",
        "rank_k" => r"\operatorname{rank} K",
        "rank_g" => r"\operatorname{rank} G",
        "geo" => r"\max_\lambda \dim\ker(A_{\bar c} - \lambda I)",
        "exists" => r"\text{exists}",
        "descriptor" => r"\text{descriptor}",
        "rank_L" => r"\operatorname{rank} L",
        "T0" => "T_0",
        "Tk" => r"[T_1, \dots, T_s]",
        "t_equals_i" => r"T = I",
        "alpha" => r"\alpha",
        "candidates" => r"\text{candidate}",
        "det" => r"\det T",
        "At" if mnf => r"\tilde A",
        "Bt" if mnf => r"\tilde B",
        "Ct" if mnf => r"\tilde C",
        "Mq" => "M",
        "Dq" => "D_q",
        "Kq" => "K",
        "W" if mnf || desc => "W",
        "U" if desc => "U",
        "V" if desc => "V",
        "UEV" => "UEV",
        "UAV" => r"\hat A = UAV",
        "r" if desc => r"r = \operatorname{rank} E",
        "k" if desc => r"k = \operatorname{rank} \hat A_{22}",
        "X" if desc => r"X = \hat A_{IJ}",
        "eqs" => r"I\ \text{(equations)}",
        "states" => r"J\ \text{(states)}",
        "Er" => "E'",
        "Ar" => "A'",
        "Br" if desc => "B'",
        "Cr" if desc => "C'",
        "Dr" => "D'",
        "lambda0" => r"\lambda_0",
        "V1" => "V_1",
        "V2" => "V_2",
        "Af" => "A_f",
        "Bf" => "B_f",
        "GN" => "GN",
        "GB" => r"G\hat B_2",
        "As" => "A_s",
        "Bs" => "B_s",
        "Cs" => "C_s",
        "Ds" => "D_s",
        "removed" if desc => r"n_\infty",
        "route" => r"\text{route}",
        "Tc" => "T_c",
        "Jc" => "J_c",
        "compact" => r"\text{compact}",
        "re" if kind == S::RealPair => r"\alpha = -c_1/2",
        "w2" => r"w^2 = c_0 - c_1^2/4",
        "disc" => r"c_1^2 - 4c_0",
        _ => return super::steps_norm::symbol(kind, key),
    })
}

/// Whether an object key of this file lists indices (shown one-based).
pub fn index_list(key: &str) -> bool {
    matches!(key, "eqs" | "states") || super::steps_modes::index_list(key)
}

/// Whether an object key is a flag its sentence already states (not typeset in LaTeX).
pub fn flag(key: &str) -> bool {
    matches!(
        key,
        "descriptor" | "exists" | "route" | "t_equals_i" | "compact"
    ) || super::steps_norm::flag(key)
}
