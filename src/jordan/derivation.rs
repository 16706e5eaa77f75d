//! Derivations as data: the steps a method takes, each with the exact objects it computed and
//! the identity it establishes (issue 27, `--steps`).
//!
//! A [`Derivation`] over a field `K` is a list of [`Step`]s. A step holds
//! * its [`StepKind`] (which fixes the sentence and the identity the report writes),
//! * the objects it computed ([`Object`]: matrices, polynomials, ranks, index lists), keyed by
//!   the symbol they carry in the identity (`"N"`, `"ranks"`, ...),
//! * `holds`: the identity, checked exactly in `K` (`None` for a step that only computes),
//! * `assumes`: elements of `K` assumed nonzero from this step on (over $\mathbb{Q}(p)$: the
//!   irreducible factors of the pivots it divided by; empty over number fields).
//!
//! Algorithms record steps through a [`Recorder`]; the text, JSON and LaTeX renderings are made
//! in `report::steps`. No display strings live here.

use crate::field::Field;
use crate::matrix::Matrix;
use crate::poly::Poly;

/// The method a derivation belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// The Jordan decomposition $A T = T J$.
    Jordan,
    /// Minimal realization by the Kalman decomposition.
    Kalman,
    /// Minimal realization by the Jordan form (minimal-realization paper sec. 3.3).
    JordanMethod,
    /// The special coordinate basis by the modified Silverman iterations (SCB paper sec. III).
    Scb,
    /// Invariant zeros of the system pencil.
    Zeros,
    /// The transfer matrix by Faddeev--LeVerrier.
    Transfer,
    /// Minimal realization by Rosenbrock's staircase.
    Rosenbrock,
    /// Minimal realization by Ho--Kalman (Hankel factorization).
    HoKalman,
    /// The mechanical normal form (Mayet & Kammermeier, sec. 2-3).
    Mnf,
    /// A descriptor system $E \dot x = A x + B u$ to standard form.
    Standard,
    /// The real Jordan form (complex pairs as real $2 \times 2$ blocks).
    RealJordan,
    /// A minimal descriptor realization (`minreal --descriptor`): Weierstrass split, finite
    /// and infinite parts reduced, non-dynamic modes removed.
    DescriptorMinimal,
    /// Mode contributions (minimal-realization paper eq. 33) and truncation by contribution.
    Contributions,
    /// The free response $x(t) = e^{At} x_0$ in closed form.
    FreeResponse,
}

/// What a step computes; each kind has one sentence and one identity (see `report::steps`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StepKind {
    /// $\chi_A(x) = \det(xI - A)$. Objects: `A`, `chi`.
    CharPoly,
    /// $\chi_A = \prod_i p_i^{e_i}$, $p_i$ irreducible. Objects: `factors`.
    Factorization,
    /// $N = A - \theta I$ and $\operatorname{rank} N^k$, $\dim\ker N^k = n - \operatorname{rank}
    /// N^k$ until the dimension reaches the multiplicity $m$. Objects: `theta`, `N`, `ranks`,
    /// `dims`, `m`.
    KernelSequence,
    /// Weyr characteristic $w_k = \dim\ker N^k - \dim\ker N^{k-1}$ (blocks of size $\ge k$) and
    /// its conjugate, the Segre characteristic (block sizes). Objects: `weyr`, `segre`.
    WeyrSegre,
    /// One Jordan chain, built top-down: $v_s \in \ker N^s \setminus \ker N^{s-1}$, $v_{j-1} =
    /// N v_j$, so $N v_1 = 0$. Objects: `V` (columns $v_1, \dots, v_s$), `top` (level $s$).
    Chain,
    /// The chains of one eigenvalue: $A V = V J_\theta$. Objects: `V`, `J`.
    EigenCheck,
    /// An irreducible factor $f$ of degree $d \ge 2$ over $\mathbb{Q}(p)$: $\dim\ker f(A)^k$,
    /// block sizes, a basis $B$ of $\ker f(A)^e$ and the restriction $M$ with $A B = B M$.
    /// Objects: `f`, `dims`, `segre`, `B`, `M`.
    PrimaryBlock,
    /// One chain normalised (`jordan --normalize`, [`super::normalize`]): `V` before, `Vn`
    /// after, `top`, `orth` (1: eq. 31, $v_j \cdot v_1 = 0$), `b` (eq. 31's constants),
    /// `row` (1-based, the entry made 1), `n2` ($n = v_1 \cdot v_1$; the columns are $V_n /
    /// \sqrt n$ unless `root` $= \sqrt n$ was exact and applied), `refused` (unit length of a
    /// non-real eigenvector).
    Normalization,
    /// The Jordan method's compacted block scaled so that $|\tilde B| = |B|$ (eq. 36): $a^2 =
    /// |B|^2 / |\tilde B|^2$, with `a` when $a$ lies in the field. Objects: `nB`, `nBt`,
    /// `a2`, `a`, `Bt`, `Ct`.
    NormMatch,
    /// Descriptor minimal: the finite part $(A_f, B_f, C_f)$ and its minimal part $(A_m, B_m,
    /// C_m)$. Objects: `Af`, `Bf`, `Cf`, `Am`, `Bm`, `Cm`, `order`.
    DescriptorFinite,
    /// Descriptor minimal: the infinite part $(N, B_\infty, C_\infty)$ and a minimal
    /// realization $(N_r, B_r, C_r)$ of $C_\infty N^k B_\infty$. Objects: `N`, `Binf`, `Cinf`,
    /// `Nr`, `Br`, `Cr`, `order`, `q`.
    DescriptorInfinite,
    /// Descriptor minimal: non-dynamic modes removed. Objects: `removed`, `order`, `shifted`,
    /// `E`, `A`, `B`, `C`, `D` (the infinite part).
    DescriptorNondynamic,
    /// Descriptor minimal: the assembled realization. Objects: `E`, `A`, `B`, `C`, `D`,
    /// `orders` (original, irreducible, minimal, finite, infinite).
    DescriptorMinimalForm,
    /// $A T = T J$ with $T$ invertible. Objects: `T`, `J` (over $\mathbb{Q}(p)$) or `n`, `dims`.
    Similarity,
    /// $\mathcal C = [B, AB, \dots, A^{n-1}B]$, its rank. Objects: `Ctrb`, `rank`.
    Controllability,
    /// Controllable subspace $\mathcal R = \operatorname{im}\mathcal C$: the pivot columns of the
    /// RREF of $\mathcal C$ (Krylov vectors). Objects: `R`, `pivots`.
    ControllableSubspace,
    /// $\mathcal O = [C; CA; \dots; CA^{n-1}]$, its rank. Objects: `Obsv`, `rank`.
    Observability,
    /// Unobservable subspace $\mathcal N = \ker\mathcal O$. Objects: `Nobs`.
    UnobservableSubspace,
    /// $T = [X_{c\bar o}, X_{co}, X_{\bar c\bar o}, X_{\bar c o}]$. Objects: `T`, `dims`.
    KalmanBasis,
    /// $(T^{-1}AT, T^{-1}B, CT)$ with the Kalman zero pattern. Objects: `At`, `Bt`, `Ct`.
    KalmanForm,
    /// The controllable and observable part $(A_{22}, B_2, C_2, D)$ and the check of the
    /// Markov parameters $C A^k B = C_2 A_{22}^k B_2$, $k < n + r$. Objects: `Am`, `Bm`, `Cm`,
    /// `order`, `mcmillan`.
    MinimalPart,
    /// Modal data of one eigenvalue: $(J_\theta, W B, C V)$. Objects: `theta`, `J`, `WB`, `CV`.
    ModalData,
    /// Non-contributing modes dropped: per Jordan block the states before the first observed
    /// one and after the last excited one. Objects: `kept`, `not_excited`, `not_observed`,
    /// `Jk`, `Bk`, `Ck`; identity: the Markov parameters of the block are unchanged.
    DropModes,
    /// Repeated modes compacted: a minimal realization of $(N, W B, C V)$ over $K$ in Jordan
    /// form. Objects: `J`, `B`, `C`, `order`; identity: Markov parameters unchanged.
    Compaction,
    /// The orders of the stages (original, after dropping, after compaction), each stage's
    /// realization over the base field reproducing $C A^k B$ ($k < 2n$), and the method's
    /// realization $(A_r, B_r, C_r, D)$ (the command's result): $C_r A_r^k B_r = C A^k B$,
    /// order = McMillan degree. Objects: `stages`, `mcmillan`, `Ar`, `Br`, `Cr`, `Dr`.
    Stages,
    /// The Jordan method on a simple irreducible factor $g$ of degree $d \ge 2$, without chains:
    /// $u$ a basis of $\ker g(A)$, $A_g$ with $A u = u A_g$, $P$ the projector along
    /// $\operatorname{im} g(A)$ ($P u = I$, $P A = A_g P$); the part $(A_g, P B, C u)$ is kept
    /// iff $P B \ne 0$ and $C u \ne 0$ (then minimal: $g$ irreducible). Objects: `g`, `deg`,
    /// `u`, `Ag`, `P` (not for $d = n$: $u = P = I$), `PB`, `Cu`, `excited`, `observed`.
    Restriction,
    /// SCB pre-transformation (sec. II-D, III-C): $Y^{-1} D U = \operatorname{diag}(I_{m_0}, 0)$
    /// and the strictly proper system $(A_1, B_1, C_1)$, $A_1 = A - B_0 C_0$. Objects: `U`,
    /// `Yinv`, `Dh`, `m0`, `A1`, `B1`, `C1`.
    ScbPreTransform,
    /// Silverman step $\bar S_i$ at level $i$: the level rows $C_i$ ($y_{i0} = C_i \hat x$), the
    /// input coefficients $[\bar D_{i-1}; C_i \hat B]$ and its canonical left null space
    /// $[S_{ib}, S_{i2}]$; the rows of $I$ kept by $S_{i1}$ end $x_d$ chains of length $i$.
    /// Objects: `level`, `Ci`, `M` ($= [\bar D_{i-1}; C_i \hat B]$), `S`, `ending`.
    SilvermanS,
    /// Silverman step $\bar\phi_i$: the candidates $\bar C_i = C_i \hat A$ of the continuing
    /// chains against all rows found so far; the canonical left null space $\Phi$ gives $x_b$
    /// chains, the rest continue as $y_{i+1,0}$. Objects: `level`, `Rows`, `Cbar`, `Phi`,
    /// `going_on`.
    SilvermanPhi,
    /// The states $x_s$ (sec. III-B): $T_s = T_s^0 + K T_{bd}$ with $\dot x_s = X x_s +
    /// (\text{outputs}) + B_{sc} u_c$. Objects: `Ts0`, `Ts`, `X`, `Bsc`, `md`.
    ScbStates,
    /// Kalman split of $x_s$ by RREF: $P = [T_2, T_1]$, $T_1$ the RREF basis of
    /// $\operatorname{im}[B_{sc}, X B_{sc}, \dots]$, $T_2$ its left null space. Objects: `Ctr`,
    /// `rank`, `P`, `na`.
    ScbKalmanSplit,
    /// The SCB $(\Gamma_1, \Gamma_2, \Gamma_3)$ and the system in the compact form of eq. (6).
    /// Objects: `A`, `B`, `C`, `D`, `Gamma1`, `Gamma2`, `Gamma3`, `dims`, `chains`, `m0`.
    ScbForm,
    /// Zero dynamics: $z(s) = \det(sI - A_{aa})$. Objects: `Aaa`, `z`.
    ZeroDynamics,
    /// Redundant inputs/outputs removed: pivot columns of $[B; D]$, pivot rows of $[C, D]$.
    /// Objects: `cols`, `rows`, `rank_in`, `rank_out`.
    ZerosCompress,
    /// The system pencil $P(s) = P_0 - s E$, $P_0 = [A, B; C, D]$, $E = \operatorname{diag}(I_n, 0)$.
    /// Objects: `P0`, `E`.
    SystemPencil,
    /// The normal rank: $\operatorname{rank} P(s_0)$ at $s_0$ with $z(s_0) \ne 0$. Objects: `s0`,
    /// `Ps0`, `z_s0`, `rank`, `z`.
    NormalRank,
    /// The Smith path: a diagonal form of $P(s)$ by unimodular operations over $K[s]$; the zero
    /// polynomial is the monic product of the diagonal. Objects: `diag`, `z`.
    SmithDiagonal,
    /// Markov parameters $h_j = C A^j B$, $j < n$. Objects: `H` ($[h_0, h_1, \dots]$).
    Markov,
    /// Faddeev--LeVerrier numerators: $N(s) = \sum_k s^{n-1-k} C R_k B$, $C R_k B = \sum_{j \le
    /// k} c_{n-k+j} h_j$; objects `N` (entries row by row), `chi`.
    Numerators,
    /// The entries $G_{ij} = (N_{ij} + D_{ij}\chi)/\chi$ in lowest terms. Objects: `num`, `den`,
    /// `shape`.
    TransferEntries,
    /// Rosenbrock staircase: $T = [\text{units}, \text{Krylov pivots}]$, $k$ reached states, the
    /// transformed $(T^{-1} A T, T^{-1} B, C T)$ with the eq. 17 zero pattern. Objects: `T`,
    /// `k`, `At`, `Bt`, `Ct`, `dual` (0: controllability, 1: on the dual).
    Staircase,
    /// Hankel matrix of Markov parameters and its rank. Objects: `H`, `rank`.
    Hankel,
    /// Ho--Kalman factorization: $H = \mathcal O_r \mathcal C_r$ and $(A_r, B_r, C_r)$ from the
    /// shifted Hankel matrix. Objects: `Am`, `Bm`, `Cm`, `order`.
    HankelFactor,
    /// MNF input compression $B = B_1 R$ ($B_1$ the pivot columns of $B$, $R$ the nonzero rows
    /// of its RREF). Objects: `B1`, `R`.
    MnfCompression,
    /// MNF existence (Theorem 2.1 and the similarity-invariant last condition): $U_{B,2}^T$
    /// with $U_{B,2}^T B = 0$, $K = U_{B,2}^T A B$ and its rank, Theorem 2.1's $G$ and its rank
    /// (diagnostic), the largest geometric multiplicity of the uncontrollable part. Objects:
    /// `n`, `p`, `rank_b`, `UB2t`, `K`, `rank_k`, `G`, `rank_g`, `geo`, `exists`.
    MnfExistence,
    /// MNF eq. 15/16: $L\,\mathrm{vec}(T) = R$; its particular solution $T_0$ and the number
    /// $s$ of null-space directions $T_k$. Objects: `L` (small systems), `rank_L`, `T0`, `s`.
    MnfEquation,
    /// MNF: an invertible member $T = T_0 + \sum_k \alpha_k T_k$ (exact determinant). Objects:
    /// `alpha`, `candidates`, `T`, `det`.
    MnfSearch,
    /// MNF: $\tilde A = T A T^{-1}$, $\tilde B = T B$, $\tilde C = C T^{-1}$ and the
    /// second-order model $M \ddot q + D_q \dot q + K q = W u$. Objects: `At`, `Bt`, `Ct`,
    /// `Mq`, `Dq`, `Kq`, `W`.
    MnfForm,
    /// Descriptor: compression $U E V = \operatorname{diag}(E_{11}, 0)$, $r = \operatorname{rank}
    /// E$, $x = V z$. Objects: `E`, `U`, `V`, `UEV`, `UAV`, `r`.
    DescriptorCompress,
    /// Descriptor: elimination of the algebraic states $z_J$ with the equations $I$ ($X =
    /// \hat A_{IJ}$ invertible), $z_J = -X^{-1}(\hat A_{IS} z_S + \hat B_I u)$. Objects: `X`,
    /// `rows`, `cols`, `Er`, `Ar`, `Br`, `Cr`, `Dr`.
    DescriptorEliminate,
    /// Descriptor (index $> 1$): $\lambda_0$ with $\det(\lambda_0 E - A) \ne 0$, $\hat E =
    /// (\lambda_0 E - A)^{-1} E$ and its Fitting split $x = V_1 z_1 + V_2 z_2$. Objects:
    /// `lambda0`, `Eh`, `V1`, `V2`, `GN`, `GB`.
    DescriptorFitting,
    /// The standard form $(A_s, B_s, C_s, D_s)$ and its certificate: $x = V_1 z + W u$ maps
    /// solutions ($E W = 0$, $E V_1 A_s = A V_1$, ...) or equal transfer matrices. Objects:
    /// `As`, `Bs`, `Cs`, `Ds`, `V1`, `removed`.
    StandardForm,
    /// A complex pair $\theta, \bar\theta$ written in real coordinates: $T_c = [\operatorname{Re}
    /// v_1, \operatorname{Im} v_1, \dots]$ and the blocks $[[a, b], [-b, a]]$. Objects:
    /// `Tc`, `Jc` (or `compact`).
    RealPair,
    /// The real Jordan basis $T$ (real chains and the pairs' real columns) and the real $J$:
    /// $A T = T J$, $T$ invertible, over one real field. Objects: `T`, `J`.
    RealForm,
    /// The spectral projector of one irreducible factor $p$ of $\chi_A$: $P_p = V_p R_p$ and the
    /// part $(A_p, B_p, C_p) = (R_p A V_p, R_p B, C V_p)$; identity $R_p V_p = I$, $A V_p = V_p
    /// A_p$, $P_p^2 = P_p$. Objects: `f`, `P`, `V`, `R`, `Ap`, `Bp`, `Cp`.
    SpectralProjector,
    /// The residues $H_k = C G_{\theta,k} B$ of the mode at the generic root (side by side);
    /// identity $\sum_{\text{conj}} H_0 = C_p B_p$. Objects: `theta`, `H`, `deg`.
    ModeResidues,
    /// The mode's weight: $\|G_p\|_2^2 = \operatorname{tr}(C_p W C_p^T)$ with the Lyapunov
    /// identity $A_p W + W A_p^T + B_p B_p^T = 0$ (`W`, `h2`), or `zero` (all Markov
    /// parameters 0) or `infinite` (not stable).
    ModeWeight,
    /// The projectors add up to $I$ and the parts to $G$: $\sum_p P_p = I$, $\sum_p C_p A_p^k
    /// B_p = C A^k B$ ($k < 2n$); the modes ranked heaviest first. Objects: `n`, `order`.
    ModeRanking,
    /// The truncated realization $(A_K, B_K, C_K, D)$ and its error $E = G - G_K$: $E(0)$,
    /// its first Markov parameter, its $H_2^2$. Objects: `kept`, `Ak`, `Bk`, `Ck`, `dc`, `M0`,
    /// `h2`.
    TruncationError,
    /// The free response's vectors of one factor at its generic root: $g_k = G_{\theta,k} x_0$,
    /// identity $A g_k = \theta g_k + (k+1) g_{k+1}$. Objects: `theta`, `g`, `deg`.
    FreeTerms,
    /// $x(0) = \sum_p \operatorname{Tr} g_{p,0} = x_0$. Objects: `x0`.
    InitialState,
}

/// An exact object a step computed.
#[derive(Clone, Debug, PartialEq)]
pub enum Object<K: Field> {
    Matrix(Matrix<K>),
    Poly(Poly<K>),
    /// Irreducible factors with multiplicities.
    Factors(Vec<(Poly<K>, usize)>),
    Scalar(K::Elem),
    Count(usize),
    /// A sequence of counts (ranks, dimensions, block sizes).
    Counts(Vec<usize>),
    /// A list of polynomials (a diagonal, the entries of a polynomial matrix row by row).
    Polys(Vec<Poly<K>>),
}

/// One step (see the module docs).
#[derive(Clone, Debug, PartialEq)]
pub struct Step<K: Field> {
    pub kind: StepKind,
    /// The eigenvalue / factor this step belongs to (index in the order of the factors).
    pub part: Option<usize>,
    pub objects: Vec<(&'static str, Object<K>)>,
    /// The identity of the step, checked exactly (`None`: the step only computes).
    pub holds: Option<bool>,
    /// Elements assumed nonzero from this step on (over $\mathbb{Q}(p)$).
    pub assumes: Vec<K::Elem>,
}

impl<K: Field> Step<K> {
    /// The object named `key`.
    pub fn get(&self, key: &str) -> Option<&Object<K>> {
        self.objects.iter().find(|(k, _)| *k == key).map(|(_, o)| o)
    }
    /// The matrix named `key`.
    pub fn matrix(&self, key: &str) -> Option<&Matrix<K>> {
        match self.get(key) {
            Some(Object::Matrix(m)) => Some(m),
            _ => None,
        }
    }
    /// The counts named `key` (a single count as a one-element slice is not returned).
    pub fn counts(&self, key: &str) -> Option<&[usize]> {
        match self.get(key) {
            Some(Object::Counts(c)) => Some(c),
            _ => None,
        }
    }
    /// The count named `key`.
    pub fn count(&self, key: &str) -> Option<usize> {
        match self.get(key) {
            Some(Object::Count(c)) => Some(*c),
            _ => None,
        }
    }
    /// The polynomial named `key`.
    pub fn poly(&self, key: &str) -> Option<&Poly<K>> {
        match self.get(key) {
            Some(Object::Poly(p)) => Some(p),
            _ => None,
        }
    }
    /// The polynomials named `key`.
    pub fn polys(&self, key: &str) -> Option<&[Poly<K>]> {
        match self.get(key) {
            Some(Object::Polys(p)) => Some(p),
            _ => None,
        }
    }
    /// The scalar named `key`.
    pub fn scalar(&self, key: &str) -> Option<&K::Elem> {
        match self.get(key) {
            Some(Object::Scalar(x)) => Some(x),
            _ => None,
        }
    }
}

/// A method's derivation: its steps, in order.
#[derive(Clone, Debug, PartialEq)]
pub struct Derivation<K: Field> {
    pub method: Method,
    /// The field of the input (the assumptions' field).
    pub field: K,
    pub steps: Vec<Step<K>>,
    /// The variable of the transfer function and of characteristic polynomials in displays:
    /// `s`, or `z` for a discrete-time system.
    pub variable: &'static str,
}

impl<K: Field> Derivation<K> {
    /// Every identity recorded holds.
    pub fn verified(&self) -> bool {
        self.steps.iter().all(|s| s.holds != Some(false))
    }
    /// The steps of one kind.
    pub fn of_kind(&self, kind: StepKind) -> impl Iterator<Item = &Step<K>> {
        self.steps.iter().filter(move |s| s.kind == kind)
    }
    /// Every element assumed nonzero.
    pub fn assumptions(&self) -> Vec<&K::Elem> {
        self.steps.iter().flat_map(|s| &s.assumes).collect()
    }
}

/// Source of the elements assumed nonzero so far (over $\mathbb{Q}(p)$: the field's log).
pub type AssumptionLog<'a, K> = Box<dyn Fn() -> Vec<<K as Field>::Elem> + 'a>;

/// Collects steps; with a log, each step gets the assumptions that appeared since the last.
pub struct Recorder<'a, K: Field> {
    derivation: Derivation<K>,
    log: Option<AssumptionLog<'a, K>>,
    seen: Vec<K::Elem>,
}

impl<'a, K: Field> Recorder<'a, K> {
    /// A recorder for `method` over `field`, without assumptions.
    pub fn new(method: Method, field: K) -> Self {
        Recorder {
            derivation: Derivation {
                method,
                field,
                steps: vec![],
                variable: "s",
            },
            log: None,
            seen: vec![],
        }
    }
    /// A recorder reading the assumptions made so far from `log` after every step.
    pub fn with_log(method: Method, field: K, log: AssumptionLog<'a, K>) -> Self {
        let mut r = Self::new(method, field);
        r.seen = log();
        r.log = Some(log);
        r
    }
    /// Records a step.
    pub fn push(
        &mut self,
        kind: StepKind,
        part: Option<usize>,
        objects: Vec<(&'static str, Object<K>)>,
        holds: Option<bool>,
    ) {
        let mut assumes = vec![];
        if let Some(log) = &self.log {
            for c in log() {
                if !self.seen.contains(&c) {
                    self.seen.push(c.clone());
                    assumes.push(c);
                }
            }
        }
        self.derivation.steps.push(Step {
            kind,
            part,
            objects,
            holds,
            assumes,
        });
    }
    /// The steps recorded so far.
    pub fn peek(&self) -> &Derivation<K> {
        &self.derivation
    }
    /// The derivation recorded.
    pub fn finish(self) -> Derivation<K> {
        self.derivation
    }
}

/// The assumption log of a field of rational functions: its conditions (irreducible
/// polynomials in the parameters assumed nonzero) as elements.
pub fn ratfunc_log(
    k: &crate::ratfunc::RatFuncField,
) -> AssumptionLog<'static, crate::ratfunc::RatFuncField> {
    let k = k.clone();
    Box::new(move || {
        k.conditions()
            .unwrap_or_default()
            .into_iter()
            .map(|c| k.from_mpoly(c))
            .collect()
    })
}
