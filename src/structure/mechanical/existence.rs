//! Existence of the mechanical normal form, decided exactly.
//!
//! For $\dot x = A x + B u$ with $n$ states and $p$ inputs, a transformation $z = T x$ with
//! $T A T^{-1} = \begin{bmatrix} 0 & I \\ \tilde A_{21} & \tilde A_{22}\end{bmatrix}$ and
//! $T B = \begin{bmatrix} 0 \\ I_p \end{bmatrix}$ exists **iff**
//!
//! 1. $n$ is even;
//! 2. $p \le n/2$;
//! 3. $\operatorname{rank} B = p$;
//! 4. $\operatorname{rank}(U_{B,2}^T A U_{B,1}) = p$, i.e. $\operatorname{rank}[B, AB] = 2p$;
//! 5. every eigenvalue $\lambda$ of the *uncontrollable part* of $(A, B)$ (the map induced by
//!    $A$ on $\mathbb{Q}^n / \mathcal{R}$, $\mathcal{R}$ the reachable subspace) has at most
//!    $n/2 - p$ independent eigenvectors.
//!
//! Conditions 1–4 are those of Theorem 2.1 of Mayet & Kammermeier. The theorem's last
//! condition, $\operatorname{rank} G \ge n/2 - p$ with
//! $G = (U_{B,2}U_{K,2})^T A (U_{B,2}U_{K,2})$, is computed and reported as a diagnostic but
//! does **not** decide: it is not invariant under similarity, and it is neither necessary
//! (the system $A = \[\[0,0,1,0\],\[0,0,0,0\],\[0,0,0,1\],\[0,0,0,0\]\]$, $B = e_4$ has $G = 0$ and a
//! normal form) nor sufficient ($A = \mathrm{diag}(2, 2) \oplus \[\[0,1\],\[-1,0\]\]$, $B = e_4$
//! has $G = 2I$ and none: the two uncontrollable modes at $2$ cannot both live in the one
//! coordinate $q_1$). Condition 5 replaces it.
//!
//! Why 5 is the right condition (proof sketch): write
//! $N = \ker B^T$ and $V = \ker [B, AB]^T$ (functionals). Rows of $T$ are $y_i^T$ and
//! $y_i^T A$ with $y_1..y_k \in V$ ($k = n/2 - p$) and $y_{k+1}..y_{n/2}$ spanning a
//! complement $P$ of $V$ in $N$. $T$ is invertible iff $W \oplus H_P W = V$ for
//! $W = \mathrm{span}(y_1..y_k)$, where $H_P = \pi_P A^T|_V = H_0 + \Phi \Psi$ (output
//! injection, $\Phi$ free). A map on $\mathbb{Q}^{2k}$ admits such a $W$ iff it has at most $k$
//! non-trivial invariant factors (it is then a block companion matrix of a monic quadratic
//! $k\times k$ matrix polynomial; Rosenbrock's degree theorem). The unobservable part of
//! $(\Psi, H_0)$ is $A^T$ on $\mathcal{R}^\perp$, which no $\Phi$ changes; the observable part
//! can be made cyclic with a characteristic polynomial coprime to it. Hence the minimum number
//! of invariant factors over all $\Phi$ is the maximal geometric multiplicity of the
//! uncontrollable part (or 1 if that part is empty).
//!
//! Geometric multiplicities are computed without factoring: Gaussian elimination of
//! $M - \theta I$ over $\mathbb{Q}[\theta]/(s)$, $s$ the square-free part of the
//! characteristic polynomial, splitting $s$ whenever a pivot candidate is a zero divisor
//! (dynamic evaluation).
//!
//! | entry point | computes |
//! |---|---|
//! | [`decide_existence`] | all conditions, the verdict and the reason |
//! | [`max_geometric_multiplicity`] | $\max_\lambda \dim\ker(M - \lambda I)$ and a witness factor |

use crate::field::Field;
use crate::matrix::Matrix;
use crate::poly::Poly;

/// What one condition compares, with the values computed ($h = n/2$).
#[derive(Clone, Debug, PartialEq)]
pub enum Check<K: Field> {
    /// $n$ even.
    StatesEven { n: usize },
    /// $p \le h$.
    InputsAtMostHalf { p: usize, half: usize },
    /// $\operatorname{rank} B = p$.
    RankB { rank: usize, p: usize },
    /// $\operatorname{rank}(U_{B,2}^T A U_{B,1}) = p$.
    RankK { rank: usize, p: usize },
    /// Theorem 2.1's $\operatorname{rank} G \ge h - p$ (a diagnostic).
    PaperRankG { rank: usize, bound: usize },
    /// The largest geometric multiplicity of an uncontrollable eigenvalue $\le h - p$, with a
    /// square-free polynomial whose roots attain it.
    UncontrollableMultiplicity {
        geo: usize,
        bound: usize,
        witness: Option<Poly<K>>,
    },
    /// $\operatorname{rank} B < p$: the conditions are those of $(A, B_1)$, $B = B_1 R$.
    InputCompression { rank: usize, p: usize },
}

/// One checked condition.
#[derive(Clone, Debug, PartialEq)]
pub struct Condition<K: Field> {
    /// What was compared, with the values.
    pub check: Check<K>,
    pub holds: bool,
    /// Whether the verdict depends on it (Theorem 2.1's `G` and the input compression do not
    /// decide).
    pub decisive: bool,
}

impl<K: Field> Condition<K> {
    /// Short key: `n_even`, `p_le_half`, `rank_b`, `rank_k`, `paper_rank_g`,
    /// `uncontrollable_multiplicity`, `input_compression`.
    pub fn name(&self) -> &'static str {
        match self.check {
            Check::StatesEven { .. } => "n_even",
            Check::InputsAtMostHalf { .. } => "p_le_half",
            Check::RankB { .. } => "rank_b",
            Check::RankK { .. } => "rank_k",
            Check::PaperRankG { .. } => "paper_rank_g",
            Check::UncontrollableMultiplicity { .. } => "uncontrollable_multiplicity",
            Check::InputCompression { .. } => "input_compression",
        }
    }
}

/// The verdict on existence.
#[derive(Clone, Debug, PartialEq)]
pub struct Existence<K: Field> {
    pub n: usize,
    pub p: usize,
    pub conditions: Vec<Condition<K>>,
    pub exists: bool,
    /// Index in `conditions` of the first failing decisive condition when `exists` is false.
    pub reason: Option<usize>,
}

fn cond<K: Field>(check: Check<K>, holds: bool) -> Condition<K> {
    Condition {
        check,
        holds,
        decisive: true,
    }
}

/// The matrices the existence decision computed (for `mnf --steps`): `None` where the
/// decision stopped before them.
#[derive(Clone, Debug)]
pub struct ExistenceParts<K: Field> {
    /// The input matrix of the pair decided on ($F^{-1} B$ for a descriptor system).
    pub b: Matrix<K>,
    /// $\operatorname{rank} B$.
    pub rank_b: Option<usize>,
    /// $U_{B,2}^T$: rows spanning $\{w : w B = 0\}$ (the canonical left null space).
    pub ub2t: Option<Matrix<K>>,
    /// $K = U_{B,2}^T A B$.
    pub k: Option<Matrix<K>>,
    /// Theorem 2.1's $G = (U_{B,2} U_{K,2})^T A (U_{B,2} U_{K,2})$ (diagnostic).
    pub g: Option<Matrix<K>>,
    /// The largest geometric multiplicity of an eigenvalue of the uncontrollable part.
    pub geo: Option<usize>,
}

/// Decides whether $(A, B)$ has a mechanical normal form. Shapes must already agree
/// (`a` is `n x n`, `b` is `n x p`); the caller checks them.
pub fn decide_existence<K: Field>(a: &Matrix<K>, b: &Matrix<K>) -> Existence<K> {
    decide_existence_parts(a, b).0
}

/// [`decide_existence`] with the matrices it computed on the way.
pub fn decide_existence_parts<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
) -> (Existence<K>, ExistenceParts<K>) {
    let n = a.nrows();
    let p = b.ncols();
    let mut conds = vec![];
    let mut parts = ExistenceParts {
        b: b.clone(),
        rank_b: None,
        ub2t: None,
        k: None,
        g: None,
        geo: None,
    };
    let done = |conds: Vec<Condition<K>>, parts: ExistenceParts<K>| {
        let reason = conds.iter().position(|c| c.decisive && !c.holds);
        let e = Existence {
            n,
            p,
            exists: reason.is_none(),
            reason,
            conditions: conds,
        };
        (e, parts)
    };
    conds.push(cond(Check::StatesEven { n }, n.is_multiple_of(2)));
    if !n.is_multiple_of(2) {
        return done(conds, parts);
    }
    let h = n / 2;
    conds.push(cond(Check::InputsAtMostHalf { p, half: h }, p <= h));
    if p > h {
        return done(conds, parts);
    }
    let rb = b.rank();
    parts.rank_b = Some(rb);
    conds.push(cond(Check::RankB { rank: rb, p }, rb == p));
    if rb != p {
        return done(conds, parts);
    }
    // U_B2^T: rows spanning {w : w B = 0}; U_B1 = B spans the column space of B.
    let ub2t = b.left_nullspace();
    let kmat = &(&ub2t * a) * b;
    let rk = kmat.rank();
    conds.push(cond(Check::RankK { rank: rk, p }, rk == p));
    if rk != p {
        parts.ub2t = Some(ub2t);
        parts.k = Some(kmat);
        return done(conds, parts);
    }
    // Theorem 2.1's rank(G) condition (diagnostic).
    let uk2t = kmat.left_nullspace();
    let vt = &uk2t * &ub2t;
    let g = &(&vt * a) * &vt.transpose();
    // a diagnostic: its generic rank is enough (a full rank proved at a point modulo a
    // prime is exact and records no condition; over Q(p) a factored minor of G can cost
    // seconds, diag(p0..p9): 60% of `mnf`)
    let full = g.nrows().min(g.ncols());
    let rg = if g.generic_rank_at_least(full) {
        full
    } else {
        g.rank()
    };
    let holds_g = rg >= h - p;
    conds.push(Condition {
        check: Check::PaperRankG {
            rank: rg,
            bound: h - p,
        },
        holds: holds_g,
        decisive: false,
    });
    parts.ub2t = Some(ub2t);
    parts.k = Some(kmat);
    parts.g = Some(g);
    let (geo, witness) = uncontrollable_multiplicity(a, b);
    parts.geo = Some(geo);
    let holds_u = geo <= h - p;
    conds.push(cond(
        Check::UncontrollableMultiplicity {
            geo,
            bound: h - p,
            witness,
        },
        holds_u,
    ));
    done(conds, parts)
}

/// Maximal geometric multiplicity of the uncontrollable part of `(a, b)` and a square-free
/// factor whose roots attain it (`(0, None)` when `(a, b)` is controllable).
pub fn uncontrollable_multiplicity<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
) -> (usize, Option<Poly<K>>) {
    let n = a.nrows();
    // Krylov basis of the reachable subspace R: the pivot columns of [B, AB, ..., A^(n-1) B]
    // (one pivot computation; no reduced form of the growing Krylov matrices, whose entries
    // are large for a diagonal A in symbols)
    let krylov = crate::realization::controllability_matrix(a, b);
    let piv = krylov.pivots();
    if piv.len() == n {
        return (0, None);
    }
    let basis = krylov.select_cols(&piv);
    // R^perp as rows Wl (u x n) is A^T-invariant: Wl A = M Wl.
    let wl = basis.left_nullspace();
    let rhs = (&wl * a).transpose();
    let (mt, _) = wl
        .transpose()
        .solve(&rhs)
        .expect("shapes agree")
        .expect("R^perp is invariant under A^T");
    let (g, f) = max_geometric_multiplicity(&mt.transpose());
    (g, f)
}

/// $\max_\lambda \dim\ker(M - \lambda I)$ over the algebraic closure, and a monic square-free
/// polynomial whose roots are eigenvalues attaining it (`(0, None)` for a `0 x 0` matrix).
///
/// # Panics
/// When `m` is not square.
pub fn max_geometric_multiplicity<K: Field>(m: &Matrix<K>) -> (usize, Option<Poly<K>>) {
    let u = m.nrows();
    if u == 0 {
        return (0, None);
    }
    let chi = m.charpoly().expect("square matrix");
    let s = chi.quo(&chi.gcd(&chi.derivative())).monic();
    let k = m.field().clone();
    let theta = Poly::x(k.clone());
    let rows: Vec<Vec<Poly<K>>> = (0..u)
        .map(|i| {
            (0..u)
                .map(|j| {
                    let c = Poly::constant(k.clone(), m.get(i, j).clone());
                    if i == j {
                        c.sub(&theta).rem(&s)
                    } else {
                        c.rem(&s)
                    }
                })
                .collect()
        })
        .collect();
    let mut parts = vec![];
    rank_mod(rows, s, 0, 0, &mut parts);
    parts
        .into_iter()
        .map(|(f, r)| (u - r, f))
        .max_by_key(|(g, _)| *g)
        .map(|(g, f)| (g, Some(f)))
        .unwrap_or((0, None))
}

/// Rank of a polynomial matrix over $K[\theta]/(s)$ for square-free `s`, by Gaussian
/// elimination that splits `s` at zero divisors. Pushes `(factor, rank)` pairs whose factors
/// multiply to `s`. `r`, `c0`: rows and columns already eliminated.
fn rank_mod<K: Field>(
    mut a: Vec<Vec<Poly<K>>>,
    s: Poly<K>,
    mut r: usize,
    c0: usize,
    out: &mut Vec<(Poly<K>, usize)>,
) {
    let nr = a.len();
    let nc = a.first().map_or(0, |row| row.len());
    for c in c0..nc {
        let mut pivot = None;
        for i in r..nr {
            if a[i][c].is_zero() {
                continue;
            }
            let (g, inv, _) = a[i][c].xgcd(&s);
            if g.is_one() {
                pivot = Some((i, inv.rem(&s)));
                break;
            }
            // Zero divisor: s = g (s / g) with coprime parts; continue on each.
            let s2 = s.quo(&g);
            for part in [g, s2] {
                let red = a
                    .iter()
                    .map(|row| row.iter().map(|e| e.rem(&part)).collect())
                    .collect();
                rank_mod(red, part, r, c, out);
            }
            return;
        }
        let Some((i, inv)) = pivot else { continue };
        a.swap(r, i);
        let prow: Vec<Poly<K>> = a[r].iter().map(|e| e.mul(&inv).rem(&s)).collect();
        for i in r + 1..nr {
            if a[i][c].is_zero() {
                continue;
            }
            let f = a[i][c].clone();
            for j in c..nc {
                a[i][j] = a[i][j].sub(&f.mul(&prow[j])).rem(&s);
            }
        }
        a[r] = prow;
        r += 1;
    }
    out.push((s, r));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::qmat;

    #[test]
    fn geometric_multiplicity_examples() {
        // diag(2, 2, 3): 2 eigenvectors for 2
        let (g, f) = max_geometric_multiplicity(&qmat![[2, 0, 0], [0, 2, 0], [0, 0, 3]]);
        assert_eq!(g, 2);
        assert_eq!(f.unwrap().to_string(), "x - 2");
        // a 2x2 Jordan block and a 1x1 block at the same eigenvalue
        let (g, _) = max_geometric_multiplicity(&qmat![[1, 1, 0], [0, 1, 0], [0, 0, 1]]);
        assert_eq!(g, 2);
        // rotation blocks twice: x^2 + 1 with geometric multiplicity 2, next to x - 5
        let m = qmat![
            [0, -1, 0, 0, 0],
            [1, 0, 0, 0, 0],
            [0, 0, 0, -1, 0],
            [0, 0, 1, 0, 0],
            [0, 0, 0, 0, 5]
        ];
        let (g, f) = max_geometric_multiplicity(&m);
        assert_eq!(g, 2);
        assert_eq!(f.unwrap().to_string(), "x^2 + 1");
        // a companion matrix is cyclic
        let (g, _) = max_geometric_multiplicity(&qmat![[0, 1], [-6, 5]]);
        assert_eq!(g, 1);
    }

    #[test]
    fn uncontrollable_part_examples() {
        let a = qmat![[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 0, 1], [0, 0, -1, 0]];
        let b = qmat![[0], [0], [0], [1]];
        assert_eq!(uncontrollable_multiplicity(&a, &b).0, 2);
        let e = decide_existence(&a, &b);
        assert!(!e.exists);
        // Theorem 2.1's conditions all hold here.
        assert!(
            e.conditions
                .iter()
                .all(|c| c.holds || c.name() == "uncontrollable_multiplicity")
        );
    }
}
