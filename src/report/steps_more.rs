//! The texts of the derivations of `scb`, `zeros`, `tf` and `minreal --method
//! rosenbrock|ho-kalman` (`--steps`): titles, JSON names, identities, sentences (plain and
//! LaTeX) and the LaTeX symbols of their objects. The Jordan and Kalman texts are in
//! `report::steps`; both are called through the same functions there.

use super::steps_base::{counts, one_based};
use crate::field::Field;
use crate::jordan::derivation::{Derivation, Method, Step, StepKind};

/// The title of a method of this file.
pub fn title(m: Method) -> &'static str {
    match m {
        Method::Scb => "special coordinate basis (modified Silverman algorithm), step by step",
        Method::Zeros => "invariant zeros of the system pencil, step by step",
        Method::Transfer => "transfer matrix (Faddeev-LeVerrier), step by step",
        Method::Rosenbrock => "minimal realization (Rosenbrock staircase), step by step",
        Method::HoKalman => "minimal realization (Ho-Kalman), step by step",
        m => super::steps_forms::title(m),
    }
}

/// The JSON name of a step kind of this file.
pub fn kind_name(k: StepKind) -> &'static str {
    match k {
        StepKind::ScbPreTransform => "pre_transformation",
        StepKind::SilvermanS => "silverman_s",
        StepKind::SilvermanPhi => "silverman_phi",
        StepKind::ScbStates => "states_xs",
        StepKind::ScbKalmanSplit => "kalman_split",
        StepKind::ScbForm => "scb",
        StepKind::ZeroDynamics => "zero_dynamics",
        StepKind::ZerosCompress => "compress",
        StepKind::SystemPencil => "system_pencil",
        StepKind::NormalRank => "normal_rank",
        StepKind::SmithDiagonal => "smith_diagonal",
        StepKind::Markov => "markov",
        StepKind::Numerators => "numerators",
        StepKind::TransferEntries => "entries",
        StepKind::Staircase => "staircase",
        StepKind::Hankel => "hankel",
        StepKind::HankelFactor => "hankel_factorization",
        k => super::steps_forms::kind_name(k),
    }
}

/// The identity of a step kind of this file, as plain text and as LaTeX math.
pub fn identity(k: StepKind) -> (&'static str, &'static str) {
    match k {
        StepKind::ScbPreTransform => (
            "Y^-1 D U = diag(I_m0, 0)",
            r"Y^{-1} D U = \operatorname{diag}(I_{m_0}, 0)",
        ),
        StepKind::SilvermanS => (
            "S M = 0 with S a basis of the left null space of M; S_i1 = the rows of I at the non-leading-one columns of rref(S_i2)",
            r"[S_{ib},\ S_{i2}]\,M = 0,\ \text{rows} = \dim\ker M^T",
        ),
        StepKind::SilvermanPhi => (
            "Phi [rows found; Cbar_i] = 0 with Phi a basis of that left null space",
            r"\Phi\,[\text{rows found};\ \bar C_i] = 0",
        ),
        StepKind::ScbStates => (
            "T_s B Gamma_3 has zero u_d columns; T_s A - X T_s lies in the row space of C",
            r"(T_s \hat B \Gamma_3)_{u_d} = 0,\ T_s \hat A - X T_s \in \operatorname{row}\hat C",
        ),
        StepKind::ScbKalmanSplit => (
            "P invertible, (P^-1 X P)_ac = 0, (P^-1 B_sc)_a = 0",
            r"\det P \ne 0,\ (P^{-1} X P)_{ac} = 0,\ (P^{-1} B_{sc})_{a} = 0",
        ),
        StepKind::ScbForm => (
            "A_s = Gamma1^-1 (A^ - B0 C0) Gamma1, B_s = Gamma1^-1 B^ Gamma3, C_s = Gamma2^-1 C^ Gamma1, D_s = Gamma2^-1 D^ Gamma3, pattern of eq. (4)-(6)",
            r"\Gamma_1 A_s = (\hat A - B_0 C_0) \Gamma_1,\ \Gamma_1 B_s = \hat B \Gamma_3,\ \Gamma_2 C_s = \hat C \Gamma_1,\ \text{pattern of eq. (4)--(6)}",
        ),
        StepKind::ZeroDynamics => ("z(A_aa) = 0, deg z = n_a", r"z(A_{aa}) = 0,\ \deg z = n_a"),
        StepKind::ZerosCompress => (
            "the kept columns (rows) are independent and span those of [B; D] ([C, D])",
            r"\operatorname{rank}[B; D]_{\text{kept}} = \operatorname{rank}[B; D]",
        ),
        StepKind::SystemPencil => ("(the pencil written down)", ""),
        StepKind::NormalRank => (
            "z(s0) != 0 and rank P(s0) is the normal rank",
            r"z(s_0) \ne 0 \Rightarrow \operatorname{rank} P(s_0) = \operatorname{normrank} P",
        ),
        StepKind::SmithDiagonal => (
            "z = the monic product of the diagonal entries",
            r"z = \operatorname{monic}\textstyle\prod_i d_i",
        ),
        StepKind::Markov => ("(Markov parameters computed)", ""),
        StepKind::Numerators => (
            "N(s0) = chi(s0) C (s0 I - A)^-1 B at a point s0 with chi(s0) != 0",
            r"N(s_0) = \chi(s_0)\, C (s_0 I - A)^{-1} B",
        ),
        StepKind::TransferEntries => (
            "the Laurent coefficients of G at infinity are D, CB, CAB, ..., C A^(2n-1) B",
            r"G(s) = D + \textstyle\sum_{j \ge 0} C A^j B\, s^{-j-1}",
        ),
        StepKind::Staircase => (
            "A T = T At, B = T Bt, Ct = C T; At and Bt zero on the unreached rows",
            r"A T = T \tilde A,\ B = T \tilde B,\ \tilde C = C T,\ \tilde A_{12} = 0,\ \tilde B_1 = 0",
        ),
        StepKind::Hankel => ("(rank computed)", ""),
        StepKind::HankelFactor => (
            "L R = H_0, L^+ L = I, R R^+ = I, A_r = L^+ H_1 R^+",
            r"L R = H_0,\ A_r = L^{+} H_1 R^{+}",
        ),
        k => super::steps_forms::identity(k),
    }
}

fn rows_of<K: Field>(s: &Step<K>, key: &str) -> usize {
    s.matrix(key).map_or(0, |m| m.nrows())
}

/// The plain sentence of a step of this file.
pub fn sentence<K: Field>(d: &Derivation<K>, s: &Step<K>, var: &str) -> String {
    let c = |key: &str| s.count(key).unwrap_or(0);
    let ob = |key: &str| s.counts(key).map(one_based).unwrap_or_default();
    let cs = |key: &str| s.counts(key).map(counts).unwrap_or_default();
    let poly = |key: &str| {
        s.poly(key)
            .map(|p| p.to_string_var(var))
            .unwrap_or_default()
    };
    match s.kind {
        StepKind::ScbPreTransform => format!(
            "Pre-transformation (sec. II-D, III-C): Y^-1 = [Y_1; Y_2] with Y_2 the canonical left null space of D and Y_1 unit rows completing it, U^-1 = [Y_1 D; U_2]; so Y^-1 D U = diag(I_m0, 0) with m0 = rank D = {}. The strictly proper part is (A_1, B_1, C_1) = (A - B_0 C_0, the last inputs, the last outputs).",
            c("m0")
        ),
        StepKind::SilvermanS => format!(
            "Level i = {i}: y_{i}0 = C_{i} x (the rows C_{i}); the input coefficients M = [Dbar_{p}; C_{i} B] have the canonical (RREF) left null space S = [S_{i}b, S_{i}2] ({r} rows: chains that continue without input); S_{i}1 = the rows ({e}) of I not at a leading one of rref(S_{i}2): those chains end in x_d with length {i}.",
            i = c("level"),
            p = c("level").saturating_sub(1),
            r = rows_of(s, "S"),
            e = ob("ending"),
        ),
        StepKind::SilvermanPhi => format!(
            "Level i = {i}: the derivatives Cbar_{i} = C_{i} A of the {nc} continuing chains against the {nr} rows found so far; the canonical left null space Phi ({np} rows) gives {np} x_b chain(s) of length {i}; the chains ({g}) continue as y_{n}0.",
            i = c("level"),
            n = c("level") + 1,
            nc = rows_of(s, "Cbar"),
            nr = rows_of(s, "Rows"),
            np = rows_of(s, "Phi"),
            g = ob("going_on"),
        ),
        StepKind::ScbStates => "The states x_s (sec. III-B): T_s^0 = unit rows completing [T_b; T_d] (leading-one deletion rule); T_s = T_s^0 + K T_bd removes u_d (x_s^1 = x_s^0 - B_d^0 x_d0) and then the chain levels one by one, so x_s' = X x_s + (outputs) + B_sc u_c.".into(),
        StepKind::ScbKalmanSplit => format!(
            "Kalman split of x_s by RREF: C_ctr = [B_sc, X B_sc, ...] has rank {}; T_1 = the RREF basis of its column space, T_2 = its left null space transposed; (x_a, x_c) = P^-1 x_s with P = [T_2, T_1]: n_a = {} states are not reached by u_c.",
            c("rank"),
            c("na")
        ),
        StepKind::ScbForm => format!(
            "The special coordinate basis: dims (n_a, n_b, n_c, n_d) = ({}), x_d made of integrator chains of lengths ({}) (the infinite zero structure), m0 = {}; left invertible iff n_c = 0, right invertible iff n_b = 0.",
            cs("dims"),
            cs("chains"),
            c("m0")
        ),
        StepKind::ZeroDynamics => format!(
            "Zero dynamics x_a' = A_aa x_a + (outputs): the invariant zero polynomial z({var}) = det({var} I - A_aa) = {}.",
            poly("z")
        ),
        StepKind::ZerosCompress => format!(
            "Independent inputs and outputs: the pivot columns ({}) of [B; D] (rank {}) and the pivot rows ({}) of [C, D] (rank {}); a constant unimodular operation zeroes the others, so the Smith form of P({var}) is unchanged.",
            ob("cols"),
            c("rank_in"),
            ob("rows"),
            c("rank_out")
        ),
        StepKind::SystemPencil => format!(
            "The system pencil P({var}) = P_0 - {var} E = [A - {var} I, B; C, D] ({} x {}).",
            rows_of(s, "P0"),
            s.matrix("P0").map_or(0, |m| m.ncols())
        ),
        StepKind::NormalRank => format!(
            "Normal rank: at {var}_0 = {}, z({var}_0) = {} != 0, so rank P({var}_0) = {} is the normal rank (P({var}) loses rank exactly at the roots of z).",
            s.scalar("s0").map(|x| d.field.fmt_elem(x)).unwrap_or_default(),
            s.scalar("z_s0").map(|x| d.field.fmt_elem(x)).unwrap_or_default(),
            c("rank")
        ),
        StepKind::SmithDiagonal => format!(
            "Diagonal form of P({var}) by unimodular operations over K[{var}] (Euclidean elimination): {} nonzero diagonal entries (the normal rank); their monic product is z({var}) = {}.",
            s.polys("diag").map_or(0, |p| p.len()),
            poly("z")
        ),
        StepKind::Markov => format!(
            "Markov parameters h_j = C A^j B, j = 0..{} (products of A with n x m matrices), side by side: H = [h_0, h_1, ...].",
            c("n").saturating_sub(1)
        ),
        StepKind::Numerators => format!(
            "Faddeev-LeVerrier: adj({var} I - A) = sum_k {var}^(n-1-k) R_k, R_0 = I, R_k = A R_(k-1) + c_(n-k) I, so N({var}) = C adj({var} I - A) B with C R_k B = sum_(j<=k) c_(n-k+j) h_j (chi = {}); the entries of N row by row.",
            poly("chi")
        ),
        StepKind::TransferEntries => "Each entry G_ij = (N_ij + D_ij chi) / chi in lowest terms (the gcd cancelled), monic denominator.".into(),
        StepKind::Staircase => format!(
            "Rosenbrock staircase{}: the Krylov pivot columns of [B, AB, ...] (block 0 last) completed by unit vectors give T; k = {} states are reached, and (T^-1 A T, T^-1 B, C T) has the zero pattern of eq. 17.",
            if c("dual") == 1 { " on the dual (A^T, C^T) of the controllable part (eq. 19)" } else { "" },
            c("k")
        ),
        StepKind::Hankel => format!(
            "Block Hankel matrix H_0 = [C A^(i+j) B] (n block rows and columns), rank {} (the McMillan degree).",
            c("rank")
        ),
        StepKind::HankelFactor => "Rank factorization H_0 = L R (L the pivot columns of H_0, R the nonzero rows of its RREF); A_r = L^+ H_1 R^+ with the shifted Hankel matrix H_1, B_r = the first columns of R (one per input), C_r = the first rows of L (one per output).".into(),
        _ => super::steps_forms::sentence(d, s),
    }
}

/// The LaTeX sentence of a step of this file.
pub fn sentence_latex<K: Field>(st: &Step<K>) -> String {
    let c = |k: &str| st.count(k).unwrap_or(0);
    let i = c("level");
    match st.kind {
        StepKind::ScbPreTransform => "Pre-transformation (sec.~II-D, III-C): $Y^{-1} = [Y_1; Y_2]$ with $Y_2$ the canonical left null space of $D$ and $Y_1$ unit rows completing it; $U^{-1} = [Y_1 D; U_2]$. Then $\\hat D = Y^{-1} D U = \\operatorname{diag}(I_{m_0}, 0)$ and the strictly proper part is $(A_1, B_1, C_1)$, $A_1 = A - B_0 C_0$.".into(),
        StepKind::SilvermanS => format!(
            "Level $i = {i}$: $y_{{{i}0}} = C_{i} \\hat x$. The input coefficients $M = [\\bar D_{{{p}}}; C_{i} \\hat B]$ have the canonical (RREF) left null space $[S_{{{i}b}}, S_{{{i}2}}]$: chains that continue without input. $S_{{{i}1}}$ keeps the rows of $I$ that are not at a leading one of $\\operatorname{{rref}}(S_{{{i}2}})$; those chains end in $x_d$ with length {i}.",
            p = i.saturating_sub(1)
        ),
        StepKind::SilvermanPhi => format!(
            "Level $i = {i}$: the derivatives $\\bar C_{i} = C_{i} \\hat A$ of the continuing chains against the rows found so far; the canonical left null space $\\Phi$ gives the $x_b$ chains of length {i}; the others continue as $y_{{{n}0}}$.",
            n = i + 1
        ),
        StepKind::ScbStates => "The states $x_s$ (sec.~III-B): $T_s^0$ unit rows completing $[T_b; T_d]$; $T_s = T_s^0 + K T_{bd}$ removes $u_d$ ($x_s^1 = x_s^0 - B_d^0 x_{d0}$) and then the chain levels, so that $\\dot x_s = X x_s + (\\text{outputs}) + B_{sc} u_c$.".into(),
        StepKind::ScbKalmanSplit => "Kalman split of $x_s$ by RREF: $T_1$ the RREF basis of the column space of $C_{ctr} = [B_{sc}, X B_{sc}, \\dots]$, $T_2$ its left null space transposed, $(x_a, x_c) = P^{-1} x_s$ with $P = [T_2, T_1]$.".into(),
        StepKind::ScbForm => "The special coordinate basis $\\hat x = \\Gamma_1 x$, $\\hat y = \\Gamma_2 y$, $\\hat u = \\Gamma_3 u$ and the system in the compact form of eq.~(6); $x_d$ consists of integrator chains of lengths $q_i$ (the infinite zero structure).".into(),
        StepKind::ZeroDynamics => "The zero dynamics $\\dot x_a = A_{aa} x_a + (\\text{outputs})$: the invariant zero polynomial $z(s) = \\det(sI - A_{aa})$.".into(),
        StepKind::ZerosCompress => "Independent inputs and outputs: the pivot columns of $[B; D]$ and the pivot rows of $[C, D]$ (numbers below); a constant unimodular operation zeroes the others, so the Smith form of $P(s)$ is unchanged.".into(),
        StepKind::SystemPencil => "The system pencil $P(s) = P_0 - sE = \\begin{bmatrix} A - sI & B \\\\ C & D\\end{bmatrix}$.".into(),
        StepKind::NormalRank => "The normal rank: at a point $s_0$ with $z(s_0) \\ne 0$ the pencil has its normal rank ($P(s)$ loses rank exactly at the roots of $z$).".into(),
        StepKind::SmithDiagonal => "A diagonal form of $P(s)$ by unimodular operations over $K[s]$ (Euclidean elimination); the monic product of the diagonal is $z(s)$.".into(),
        StepKind::Markov => "The Markov parameters $h_j = C A^j B$ ($j < n$), side by side: $H = [h_0, h_1, \\dots]$.".into(),
        StepKind::Numerators => "Faddeev--LeVerrier: $\\operatorname{adj}(sI - A) = \\sum_k s^{n-1-k} R_k$, $R_0 = I$, $R_k = A R_{k-1} + c_{n-k} I$, so $N(s) = C \\operatorname{adj}(sI - A) B$ with $C R_k B = \\sum_{j \\le k} c_{n-k+j} h_j$.".into(),
        StepKind::TransferEntries => "Each entry $G_{ij} = (N_{ij} + D_{ij}\\chi)/\\chi$ in lowest terms, monic denominator.".into(),
        StepKind::Staircase if c("dual") == 1 => "The staircase on the dual $(A^T, C^T)$ of the controllable part (eq.~19): its reached states are the observable ones.".into(),
        StepKind::Staircase => "Rosenbrock's staircase: the Krylov pivot columns of $[B, AB, \\dots]$ (block 0 last) completed by unit vectors give $T$; $(T^{-1}AT, T^{-1}B, CT)$ has the zero pattern of eq.~17 and $k$ reached states.".into(),
        StepKind::Hankel => "The block Hankel matrix $H_0 = [C A^{i+j} B]$ ($n$ block rows and columns) and its rank, the McMillan degree.".into(),
        StepKind::HankelFactor => "Rank factorization $H_0 = L R$ ($L$ the pivot columns, $R$ the nonzero rows of the RREF); $A_r = L^{+} H_1 R^{+}$ with the shifted Hankel matrix $H_1$, $B_r$ the first columns of $R$ (one per input), $C_r$ the first rows of $L$ (one per output).".into(),
        _ => super::steps_forms::sentence_latex(st),
    }
}

/// The LaTeX symbol of an object key of this file's steps (`None`: the common table).
pub fn symbol(kind: StepKind, key: &str) -> Option<&'static str> {
    if let Some(sym) = super::steps_forms::symbol(kind, key) {
        return Some(sym);
    }
    Some(match (kind, key) {
        (StepKind::ScbForm, "A") => r"A_s",
        (StepKind::ScbForm, "B") => r"B_s",
        (StepKind::ScbForm, "C") => r"C_s",
        (StepKind::ScbForm, "D") => r"D_s",
        (StepKind::ScbForm, "dims") => r"(n_a, n_b, n_c, n_d)",
        (StepKind::SilvermanS, "M") => r"M",
        (StepKind::SilvermanS, "S") => r"[S_{ib},\ S_{i2}]",
        (StepKind::HankelFactor, "R") => "R",
        (StepKind::Markov, "H") | (StepKind::Hankel, "H") => "H",
        (StepKind::Numerators, "N") => r"N_{ij}(s)",
        (StepKind::Staircase, "k") => "k",
        (_, "U") => "U",
        (_, "Yinv") => r"Y^{-1}",
        (_, "Dh") => r"\hat D",
        (_, "m0") => "m_0",
        (_, "A1") => "A_1",
        (_, "B1") => "B_1",
        (_, "C1") => "C_1",
        (_, "Ci") => "C_i",
        (_, "Bottoms") => r"\text{ended bottoms}",
        (_, "level") => "i",
        (_, "ending") => r"\text{rows of } S_{i1}",
        (_, "Rows") => r"\text{rows found}",
        (_, "Cbar") => r"\bar C_i",
        (_, "Phi") => r"\Phi",
        (_, "going_on") => r"\text{continuing}",
        (_, "Ts0") => "T_s^0",
        (_, "Ts") => "T_s",
        (_, "G3") => r"\Gamma_3",
        (_, "md") => "m_d",
        (_, "Bsc") => "B_{sc}",
        (_, "Ctr") => "C_{ctr}",
        (_, "na") => "n_a",
        (_, "Gamma1") => r"\Gamma_1",
        (_, "Gamma2") => r"\Gamma_2",
        (_, "Gamma3") => r"\Gamma_3",
        (_, "chains") => "(q_i)",
        (_, "Aaa") => "A_{aa}",
        (_, "z") => "z(s)",
        (_, "cols") => r"\text{input columns}",
        (_, "rows") => r"\text{output rows}",
        (_, "rank_in") => r"\operatorname{rank}[B; D]",
        (_, "rank_out") => r"\operatorname{rank}[C, D]",
        (_, "P0") => "P_0",
        (_, "s0") => "s_0",
        (_, "Ps0") => "P(s_0)",
        (_, "z_s0") => "z(s_0)",
        (_, "diag") => "d_i(s)",
        (_, "H1") => "H_1",
        (_, "L") => "L",
        (_, "dual") => r"\text{dual}",
        (_, "n") => "n",
        _ => return None,
    })
}

/// Whether an object key lists indices (shown one-based).
pub fn index_list(key: &str) -> bool {
    matches!(key, "ending" | "going_on" | "cols" | "rows") || super::steps_forms::index_list(key)
}
