//! Structural bifurcations of a system over $\mathbb{Q}(p_1, \dots, p_k)$.
//!
//! A structural computation over $\mathbb{Q}(p)$ (SCB, minimal realization, zeros,
//! controllability, ...) holds *generically*: wherever none of the irreducible polynomials it
//! divided by (its *conditions*, [`RatFuncField::conditions`]) vanishes. [`bifurcations`]
//! runs the computation generically and then, for every condition $c$, on the branch
//! $c = 0$:
//!
//! - when $c = a\,p_i + b$ is linear in some parameter $p_i$ ($a$, $b$ free of $p_i$), the
//!   branch substitutes $p_i = -b/a$ into every entry (exactly: each entry
//!   $N/D \mapsto N(-b/a)/D(-b/a)$ brought to lowest terms) and runs the computation again,
//!   over the same field (the parameter stays, unused); the branch result holds where its own
//!   conditions and the factors of $a$ are nonzero. When some entry's denominator vanishes
//!   identically after the substitution, the system is not defined on that branch
//!   ([`BranchOutcome::Undefined`]);
//! - otherwise the branch is reported as not explored ([`BranchOutcome::NotExplored`]).
//!
//! Branches recurse up to `depth` substitutions along a path; every node counts against
//! `max_nodes` (the work bound). The computation is a closure, so any structural summary `S`
//! can be explored; [`Node::changed`] compares a branch's summary with its parent's.
//!
//! Grip & Saberi's DC motor with LuGre friction: generically (σ₁ ≠ 0) the SCB has dims
//! (1, 0, 0, 2) with the zero $-\sigma_0/\sigma_1$; the branch σ₁ = 0 has dims (0, 0, 0, 3),
//! "a single integrator chain of length three" (sec. V).

use crate::error::{Error, Result};
use crate::matrix::Matrix;
use crate::mpoly::MPoly;
use crate::mpoly::factor::cmp_poly;
use crate::ratfunc::{RatFunc, RatFuncField};
use crate::system::StateSpace;

/// The computation explored: a summary of the system (compared with `==` between a branch
/// and its parent).
pub type Analysis<'a, S> = dyn Fn(&StateSpace<RatFuncField>) -> Result<S> + 'a;

/// One node of the bifurcation tree: the result where its conditions hold.
#[derive(Clone, Debug)]
pub struct Node<S> {
    /// The computation's summary on this branch.
    pub result: S,
    /// The system on this branch (its entries with the branch's substitutions made).
    pub system: StateSpace<RatFuncField>,
    /// Irreducible polynomials assumed nonzero by this result (sorted, no duplicates):
    /// the computation's own conditions and the leading coefficients of the substitutions.
    pub conditions: Vec<MPoly>,
    /// The branches `c = 0`, one per condition of the computation (empty at the depth limit).
    pub branches: Vec<Branch<S>>,
    /// `false` at the depth limit (the branches were not looked at).
    pub expanded: bool,
}

/// A branch `condition = 0` of a node.
#[derive(Clone, Debug)]
pub struct Branch<S> {
    /// The condition set to zero.
    pub condition: MPoly,
    /// The condition solved: `sigma1 = 0` as it is, or the substitution made
    /// (`cr = m*u^2/(a + b)`).
    pub equation: Equation,
    /// What happens there.
    pub outcome: BranchOutcome<S>,
}

/// The equation of a branch, as values (the text is made in `report`).
#[derive(Clone, Debug, PartialEq)]
pub enum Equation {
    /// The condition set to zero, not solved for a parameter.
    Zero,
    /// Parameter `var` (index into the field's variables) set to `value`.
    Substitution { var: usize, value: RatFunc },
}

/// What a branch gives.
#[derive(Clone, Debug)]
pub enum BranchOutcome<S> {
    /// The substitution was made and the computation run again.
    Explored(Box<Node<S>>),
    /// An entry of the system has a pole at the substitution (the system is not defined
    /// there).
    Undefined,
    /// Not explored: the reason.
    NotExplored(NotExplored),
}

/// Why a branch was not explored.
#[derive(Clone, Debug)]
pub enum NotExplored {
    /// The condition is not linear in any parameter.
    NotLinear,
    /// The computation failed on the branch.
    Failed(Error),
}

/// The substitution that solves a condition `c = a p_i + b`: parameter `i`, value `-b/a`,
/// and `a` (assumed nonzero on the branch).
#[derive(Clone, Debug)]
pub struct Solved {
    pub var: usize,
    pub value: RatFunc,
    pub lead: MPoly,
}

/// Solves `c = 0` for a parameter in which `c` is linear: the one with the simplest leading
/// coefficient (a constant first; then fewest terms; then the first parameter).
pub fn solve_linear(k: &RatFuncField, c: &MPoly) -> Option<Solved> {
    let mut best: Option<Solved> = None;
    for i in 0..k.nvars() {
        if c.deg(i) != 1 {
            continue;
        }
        let cs = c.to_univariate(i);
        let (b, a) = (&cs[0], &cs[1]);
        let better = match &best {
            None => true,
            Some(s) => (a.total_degree(), a.len()) < (s.lead.total_degree(), s.lead.len()),
        };
        if better {
            let value = k.frac(b.neg(), a.clone())?;
            best = Some(Solved {
                var: i,
                value,
                lead: a.clone(),
            });
        }
    }
    best
}

/// `f(p_i = n/d) * d^e` for `e = deg_i f` (a polynomial).
fn hom_subst(f: &MPoly, i: usize, n: &MPoly, d: &MPoly, e: u32) -> MPoly {
    let cs = f.to_univariate(i);
    let nv = f.nvars();
    let mut acc = MPoly::zero(nv);
    for (j, c) in cs.iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        let mut t = c.clone();
        for _ in 0..j {
            t = t.mul(n);
        }
        for _ in j..e as usize {
            t = t.mul(d);
        }
        acc = acc.add(&t);
    }
    acc
}

/// The entry `x` with `p_i` replaced by `v`; `None` when the denominator vanishes
/// identically after the substitution.
pub fn substitute(k: &RatFuncField, x: &RatFunc, i: usize, v: &RatFunc) -> Option<RatFunc> {
    let (n, d) = (v.num(), v.den());
    let (dn, dd) = (x.num().deg(i), x.den().deg(i));
    let e = dn.max(dd);
    let num = hom_subst(x.num(), i, n, d, e);
    let den = hom_subst(x.den(), i, n, d, e);
    k.frac(num, den)
}

fn subst_matrix(
    k: &RatFuncField,
    m: &Matrix<RatFuncField>,
    i: usize,
    v: &RatFunc,
) -> std::result::Result<Matrix<RatFuncField>, (usize, usize)> {
    let mut data = Vec::with_capacity(m.nrows() * m.ncols());
    for r in 0..m.nrows() {
        for c in 0..m.ncols() {
            data.push(substitute(k, m.get(r, c), i, v).ok_or((r, c))?);
        }
    }
    Ok(Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), data))
}

/// The system over a field with an empty condition log (entries unchanged).
pub fn refield(s: &StateSpace<RatFuncField>, k: &RatFuncField) -> StateSpace<RatFuncField> {
    let m = |x: &Matrix<RatFuncField>| x.map(k, |e| e.clone());
    StateSpace {
        a: m(&s.a),
        b: m(&s.b),
        c: m(&s.c),
        d: m(&s.d),
    }
}

/// Runs `f` on `s` over a fresh condition log; the result and its conditions.
///
/// # Errors
/// Those of `f`, and `Limit` from factoring the conditions.
pub fn with_conditions<S>(
    s: &StateSpace<RatFuncField>,
    f: &Analysis<S>,
) -> Result<(S, Vec<MPoly>)> {
    let k = s.a.field().fresh();
    let s = refield(s, &k);
    let r = f(&s)?;
    Ok((r, k.conditions()?))
}

/// Limits of the exploration.
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    /// Substitutions along one path (the CLI's `--depth`, default 2).
    pub depth: usize,
    /// Runs of the computation in all (generic result included).
    pub max_nodes: usize,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            depth: 2,
            max_nodes: 200,
        }
    }
}

/// The generic result of `f` on `s` and its branches (see the module docs).
///
/// # Errors
/// Those of `f` on the generic system; `Limit` when more than `limits.max_nodes` runs would
/// be needed (lower `--depth`). Failures on a branch are reported in the branch.
///
/// # Examples
/// ```
/// use exactlti::field::Field;
/// use exactlti::matrix::Matrix;
/// use exactlti::ratfunc::RatFuncField;
/// use exactlti::structure::bifurcation::{BranchOutcome, Equation, Limits, bifurcations};
/// use exactlti::system::StateSpace;
/// // x' = a x + u, y = x: the controllability matrix [1] never degenerates, but its
/// // eigenvalue a is kept; dividing by a makes `a` a condition.
/// let k = RatFuncField::new(&["a"]).unwrap();
/// let m = |t: &str| Matrix::from_vec(k.clone(), 1, 1, vec![k.parse(t).unwrap()]);
/// let s = StateSpace::new(m("a"), m("1"), m("1"), m("0")).unwrap();
/// let f = |s: &StateSpace<RatFuncField>| {
///     let k = s.a.field();
///     Ok(k.inv(s.a.get(0, 0)).map_or(0, |_| 1usize))
/// };
/// let t = bifurcations(&s, &f, Limits::default()).unwrap();
/// assert_eq!(t.result, 1);
/// // the condition a is solved for a: the substitution a = 0
/// let zero = Equation::Substitution { var: 0, value: k.zero() };
/// assert_eq!(t.branches[0].equation, zero);
/// let BranchOutcome::Explored(b) = &t.branches[0].outcome else { panic!() };
/// assert_eq!(b.result, 0);
/// ```
pub fn bifurcations<S: Clone>(
    s: &StateSpace<RatFuncField>,
    f: &Analysis<S>,
    limits: Limits,
) -> Result<Node<S>> {
    let mut budget = limits.max_nodes;
    let (result, conditions) = run_budgeted(s, f, &mut budget)?;
    let mut root = Node {
        result,
        system: s.clone(),
        conditions,
        branches: vec![],
        expanded: false,
    };
    expand(&mut root, f, limits.depth, &mut budget, &[])?;
    Ok(root)
}

fn run_budgeted<S>(
    s: &StateSpace<RatFuncField>,
    f: &Analysis<S>,
    budget: &mut usize,
) -> Result<(S, Vec<MPoly>)> {
    if *budget == 0 {
        return Err(Error::Limit(
            "bifurcations: more branches than the work bound allows; lower --depth".into(),
        ));
    }
    *budget -= 1;
    with_conditions(s, f)
}

fn expand<S: Clone>(
    node: &mut Node<S>,
    f: &Analysis<S>,
    depth: usize,
    budget: &mut usize,
    assumed: &[MPoly],
) -> Result<()> {
    if depth == 0 {
        return Ok(());
    }
    node.expanded = true;
    let k = node.system.a.field().clone();
    let conditions = node.conditions.clone();
    for (j, c) in conditions.iter().cloned().enumerate() {
        // a condition whose branch an ancestor's earlier sibling covers already
        if assumed.contains(&c) {
            continue;
        }
        let Some(sol) = solve_linear(&k, &c) else {
            node.branches.push(Branch {
                condition: c.clone(),
                equation: Equation::Zero,
                outcome: BranchOutcome::NotExplored(NotExplored::NotLinear),
            });
            continue;
        };
        let equation = Equation::Substitution {
            var: sol.var,
            value: sol.value.clone(),
        };
        let sub = |m: &Matrix<RatFuncField>| subst_matrix(&k, m, sol.var, &sol.value);
        let sys = match (
            sub(&node.system.a),
            sub(&node.system.b),
            sub(&node.system.c),
            sub(&node.system.d),
        ) {
            (Ok(a), Ok(b), Ok(c), Ok(d)) => StateSpace { a, b, c, d },
            _ => {
                node.branches.push(Branch {
                    condition: c.clone(),
                    equation,
                    outcome: BranchOutcome::Undefined,
                });
                continue;
            }
        };
        let outcome = match run_budgeted(&sys, f, budget) {
            Ok((result, mut conds)) => {
                // the substitution needs its leading coefficient nonzero: assumed, not a branch
                let mut lead = vec![];
                if !sol.lead.is_constant() {
                    for (g, _) in crate::mpoly::factor(&sol.lead)?.factors {
                        if !conds.contains(&g) {
                            conds.push(g.clone());
                        }
                        lead.push(g);
                    }
                    conds.sort_by(cmp_poly);
                }
                let mut child = Node {
                    result,
                    system: sys,
                    conditions: conds,
                    branches: vec![],
                    expanded: false,
                };
                // each set {c1 = 0, c2 = 0} once: the siblings explored before are skipped
                let mut path = assumed.to_vec();
                path.extend(conditions[..j].iter().cloned());
                path.extend(lead);
                expand(&mut child, f, depth - 1, budget, &path)?;
                BranchOutcome::Explored(Box::new(child))
            }
            Err(e @ Error::Limit(_)) if *budget == 0 => return Err(e),
            Err(e) => BranchOutcome::NotExplored(NotExplored::Failed(e)),
        };
        node.branches.push(Branch {
            condition: c,
            equation,
            outcome,
        });
    }
    Ok(())
}

impl<S: PartialEq> Node<S> {
    /// Does branch `b`'s result differ from this node's?
    pub fn changed(&self, b: &Branch<S>) -> Option<bool> {
        match &b.outcome {
            BranchOutcome::Explored(n) => Some(n.result != self.result),
            _ => None,
        }
    }
}
