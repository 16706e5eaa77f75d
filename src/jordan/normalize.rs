//! The papers' normalisations of Jordan chains (issue 27 item 2), exact over any field.
//!
//! A chain $v_1, \dots, v_s$ of $N = A - \theta I$ ($N v_1 = 0$, $N v_j = v_{j-1}$) is not
//! unique: for a polynomial $p(N) = c\,(I + b_1 N + \dots + b_{s-1} N^{s-1})$, $c \ne 0$, the
//! columns $v_j' = c\,(v_j + \sum_k b_k v_{j-k})$ are again a chain, and $A V' = V' J_\theta$
//! holds with the same $J_\theta$ (a polynomial in $N$ commutes with $N$). These are the free
//! constants of the vehicle paper's eq. 30, 32 restricted to the chain's own span. Choices:
//!
//! * **orthogonal** (minimal-realization paper eq. 31, $[A - \lambda I] Y = X$, $Y \perp X$):
//!   $b_k$ solve $v_j' \cdot v_1 = 0$ for $j = 2..s$, a triangular system with diagonal
//!   $v_1 \cdot v_1$ (solved when it is nonzero: always for a real eigenvector, not for an
//!   isotropic complex one such as $(1, i)$);
//! * **entry**: $c = 1 / (v_1)_r$ makes the entry $r$ of the eigenvector 1 (the first nonzero
//!   entry unless a row is chosen), exact in every field;
//! * **unit**: $c = 1/\sqrt{v_1 \cdot v_1}$ (the eigenvector of unit Euclidean length: the
//!   papers' eq. 27 and 32). Exact when $v_1 \cdot v_1$ is the square of a rational;
//!   otherwise the square root lies in a quadratic extension (over $\mathbb Q$) or outside the
//!   field, and the chain is kept with $n = v_1 \cdot v_1$ so that the columns are
//!   $V / \sqrt n$ in closed form. For a non-real eigenvalue $v \cdot v$ is not the length
//!   ($v^H v$ needs complex conjugation, which is not a map of the field): refused, the chain
//!   keeps its other normalisations.
//!
//! Bilinear dot products only: no conjugation, no floats.

use crate::error::{Error, Result};
use crate::field::{Field, Rational};
use crate::matrix::Matrix;
use num_traits::Signed;

/// How the eigenvector of a chain is scaled.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Scale {
    /// As computed.
    #[default]
    Keep,
    /// The entry `Some(r)` (0-based row) of $v_1$ equals 1; `None`: its first nonzero entry.
    Entry(Option<usize>),
    /// $v_1 \cdot v_1 = 1$ (exact or in closed form, module docs).
    Unit,
}

/// A normalisation of the chains (module docs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Normalization {
    /// $v_j \cdot v_1 = 0$ for $j \ge 2$ (eq. 31).
    pub orthogonal: bool,
    pub scale: Scale,
}

impl Normalization {
    /// Whether this changes nothing.
    pub fn is_none(&self) -> bool {
        !self.orthogonal && self.scale == Scale::Keep
    }
}

impl std::str::FromStr for Normalization {
    type Err = String;
    /// A comma list of `orth` (eq. 31), `entry`, `entry:<row>` (1-based), `unit`; `paper` is
    /// `orth,unit` (the minimal-realization paper's eq. 32).
    fn from_str(s: &str) -> std::result::Result<Self, String> {
        let mut out = Normalization::default();
        let scale = |out: &mut Normalization, sc: Scale| {
            if out.scale != Scale::Keep && out.scale != sc {
                return Err(format!("--normalize `{s}`: choose one of entry and unit"));
            }
            out.scale = sc;
            Ok(())
        };
        for part in s.split(',').map(str::trim) {
            match part {
                "orth" | "orthogonal" => out.orthogonal = true,
                "entry" => scale(&mut out, Scale::Entry(None))?,
                "unit" => scale(&mut out, Scale::Unit)?,
                "paper" => {
                    out.orthogonal = true;
                    scale(&mut out, Scale::Unit)?;
                }
                p if p.starts_with("entry:") => {
                    let r: usize =
                        p["entry:".len()..]
                            .parse()
                            .ok()
                            .filter(|&r| r >= 1)
                            .ok_or(format!(
                                "--normalize `{p}`: the row after `entry:` is a number >= 1"
                            ))?;
                    scale(&mut out, Scale::Entry(Some(r - 1)))?;
                }
                _ => {
                    return Err(format!(
                        "--normalize `{part}`: expected a comma list of orth, entry, entry:<row>, unit, paper"
                    ));
                }
            }
        }
        Ok(out)
    }
}

/// How a chain's unit length came out.
#[derive(Clone, Debug, PartialEq)]
pub enum UnitLength<E> {
    /// Not asked.
    NotAsked,
    /// $\sqrt n$ lies in the field: the chain was divided by it ($v_1 \cdot v_1 = 1$).
    Exact { n: E, root: E },
    /// $\sqrt n$ is not in the field: the columns are $V / \sqrt n$ (closed form).
    ClosedForm { n: E },
    /// The eigenvalue is not real: $v \cdot v$ is not a length.
    Refused,
}

/// One chain after [`normalize_chain`].
#[derive(Clone, Debug, PartialEq)]
pub struct NormalizedChain<K: Field> {
    /// The new chain $V'$ (divided by $\sqrt n$ only when that is exact).
    pub v: Matrix<K>,
    /// $b_1, \dots, b_{s-1}$ of eq. 31 (empty when not orthogonalised).
    pub constants: Vec<K::Elem>,
    /// The row made 1 (entry scaling).
    pub entry_row: Option<usize>,
    pub unit: UnitLength<K::Elem>,
}

/// $x \cdot y = \sum_i x_i y_i$ (bilinear).
pub fn dot<K: Field>(k: &K, x: &[K::Elem], y: &[K::Elem]) -> K::Elem {
    let mut acc = k.zero();
    for (a, b) in x.iter().zip(y) {
        k.mul_add_assign(&mut acc, a, b);
    }
    acc
}

/// The chain made orthogonal (eq. 31): $v_j' = v_j + \sum_{k<j} b_k v_{j-k}$ with $v_j'
/// \cdot v_1 = 0$ for $j \ge 2$; returns $V'$ and $b_1..b_{s-1}$.
///
/// # Errors
/// `Unsupported` when $v_1 \cdot v_1 = 0$ (an isotropic eigenvector) for a chain of length
/// $\ge 2$.
pub fn orthogonalize_chain<K: Field>(v: &Matrix<K>) -> Result<(Matrix<K>, Vec<K::Elem>)> {
    let k = v.field().clone();
    let s = v.ncols();
    if s < 2 {
        return Ok((v.clone(), vec![]));
    }
    let cols: Vec<Vec<K::Elem>> = (0..s).map(|j| v.col(j)).collect();
    let g: Vec<K::Elem> = cols.iter().map(|c| dot(&k, c, &cols[0])).collect();
    let inv = k.inv(&g[0]).ok_or_else(|| {
        Error::Unsupported(
            "an eigenvector with v . v = 0 (isotropic, complex): no chain orthogonal to it".into(),
        )
    })?;
    // column j (0-based) of V': v_j + sum_{k=1}^{j} b_k v_{j-k}; (v_j' . v_1) = g_j + sum b_k g_{j-k}
    let mut b: Vec<K::Elem> = vec![];
    for j in 1..s {
        let mut r = g[j].clone();
        for (kk, bk) in b.iter().enumerate() {
            k.mul_add_assign(&mut r, bk, &g[j - kk - 1]);
        }
        b.push(k.neg(&k.mul(&r, &inv)));
    }
    let mut out = v.clone();
    for j in 1..s {
        for i in 0..v.nrows() {
            let mut x = v.get(i, j).clone();
            for kk in 1..=j {
                k.mul_add_assign(&mut x, &b[kk - 1], v.get(i, j - kk));
            }
            out.set(i, j, x);
        }
    }
    Ok((out, b))
}

/// The exact square root of a nonnegative rational square, if it is one.
pub fn rational_sqrt(q: &Rational) -> Option<Rational> {
    if q.is_negative() {
        return None;
    }
    let (n, d) = (q.numer(), q.denom());
    let (rn, rd) = (n.sqrt(), d.sqrt());
    (&rn * &rn == *n && &rd * &rd == *d).then(|| Rational::new(rn, rd))
}

/// A chain normalised as `how` asks (module docs); `real`: the eigenvalue is real.
///
/// # Errors
/// As [`orthogonalize_chain`]; `Invalid` for an `entry:<row>` beyond the rows.
pub fn normalize_chain<K: Field>(
    v: &Matrix<K>,
    how: &Normalization,
    real: bool,
) -> Result<NormalizedChain<K>> {
    let k = v.field().clone();
    let (mut out, constants) = if how.orthogonal {
        orthogonalize_chain(v)?
    } else {
        (v.clone(), vec![])
    };
    let v1 = out.col(0);
    let mut entry_row = None;
    let mut unit = UnitLength::NotAsked;
    match how.scale {
        Scale::Keep => {}
        Scale::Entry(row) => {
            let r = match row {
                Some(r) if r >= v1.len() => {
                    return Err(Error::Invalid(format!(
                        "--normalize entry:{}: A has only {} rows",
                        r + 1,
                        v1.len()
                    )));
                }
                // the chosen row, or the first nonzero entry when the chosen one is zero
                Some(r) if !k.is_zero(&v1[r]) => r,
                _ => v1.iter().position(|x| !k.is_zero(x)).unwrap_or(0),
            };
            if let Some(c) = k.inv(&v1[r]) {
                out = out.scale(&c);
                entry_row = Some(r);
            }
        }
        Scale::Unit if !real => unit = UnitLength::Refused,
        Scale::Unit => {
            let n = dot(&k, &v1, &v1);
            let root = k.to_rational(&n).and_then(|q| rational_sqrt(&q));
            unit = match root.map(|q| k.from_rational(&q)) {
                Some(root) if !k.is_zero(&root) => {
                    out = out.scale(&k.inv(&root).expect("nonzero"));
                    UnitLength::Exact { n, root }
                }
                _ => UnitLength::ClosedForm { n },
            };
        }
    }
    Ok(NormalizedChain {
        v: out,
        constants,
        entry_row,
        unit,
    })
}

/// The identities of a normalised chain `w` (from `v`, both chains of `nm` of one block):
/// `w` is a chain of `nm` spanning the same space as `v` ($A W = W J_\theta$ then holds with
/// the same block), orthogonal when asked, entry 1 or $w_1 \cdot w_1 \in \{1, n\}$.
pub fn normalized_holds<K: Field>(
    nm: &Matrix<K>,
    v: &Matrix<K>,
    c: &NormalizedChain<K>,
    how: &Normalization,
) -> bool {
    let k = nm.field().clone();
    let w = &c.v;
    let s = w.ncols();
    let same_span = v.hstack(w).is_ok_and(|m| m.rank() == s) && w.rank() == s;
    let w1 = w.col(0);
    let orth = !how.orthogonal || (1..s).all(|j| k.is_zero(&dot(&k, &w.col(j), &w1)));
    let n1 = dot(&k, &w1, &w1);
    let scaled = match (&how.scale, &c.unit) {
        (Scale::Entry(_), _) => c.entry_row.is_some_and(|r| k.is_one(&w1[r])),
        (Scale::Unit, UnitLength::Exact { .. }) => k.is_one(&n1),
        (Scale::Unit, UnitLength::ClosedForm { n }) => n1 == *n && !k.is_zero(n),
        _ => true,
    };
    super::chains::is_chain(nm, w) && same_span && orth && scaled
}

/// A chain whose unit length is in closed form after [`normalize_form`]: the columns
/// `first..first + len` of its component's chains are shown as $V'$, the normalised chain
/// being $V' / \sqrt n$.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosedUnit<E> {
    /// Index of the component (irreducible factor) in the Jordan form.
    pub component: usize,
    /// First column of the chain among the component's chains, and its length.
    pub first: usize,
    pub len: usize,
    /// $n = v_1 \cdot v_1$ (in the component's field $E$).
    pub n: E,
}

/// The chains of a Jordan form normalised as `how` asks (`jordan --normalize` without
/// `--steps`): in every component each chain $V$ is replaced by [`normalize_chain`]'s $V'$
/// (in $E = F\[t\]/(g)$ at the generic root, so every conjugate root's columns follow by
/// embedding) and the left chains by $W' = (W V')^{-1} W$ (so $W' V' = I$). $T$ changes,
/// $J$ does not; $A V' = V' J_t$, $W' A = J_t W'$, $W' V' = I$ are checked again
/// ([`super::primary::Component::verify`]) and `verified` keeps only what held. Returns the
/// chains whose unit length is in closed form. A component without chains (over
/// $\mathbb{Q}(p)$ a factor of degree $\ge 2$, presented by its primary block) is left as it
/// is; over $\mathbb{Q}(p)$ use [`normalize_form_qp`], which also re-checks the primary form.
///
/// # Errors
/// As [`normalize_chain`]; `Verification` when $W V'$ is singular (it cannot be: $V'$ spans
/// the chains' space).
pub fn normalize_form<F: Field>(
    jf: &mut super::JordanForm<F>,
    how: &Normalization,
) -> Result<Vec<ClosedUnit<crate::algebraic::ExtElem<F::Elem>>>> {
    let mut closed = vec![];
    if how.is_none() {
        return Ok(closed);
    }
    let a = jf.a.clone();
    let mut ok = jf.verified;
    for (ci, comp) in jf.components.iter_mut().enumerate() {
        if !comp.has_chains() {
            // a primary block over Q(p) (a factor of degree >= 2): a basis of ker g(A)^e,
            // not Jordan chains; nothing to normalise
            continue;
        }
        let real = comp
            .roots
            .first()
            .map_or(comp.degree() == 1, |z| z.1 == 0.0);
        let n = comp.chains.nrows();
        let mut v = comp.chains.clone();
        let mut off = 0;
        for &s in &comp.blocks {
            let chain = comp.chains.submatrix(0, n, off, off + s);
            let c = normalize_chain(&chain, how, real)?;
            v.set_block(0, off, &c.v);
            if let UnitLength::ClosedForm { n } = c.unit {
                closed.push(ClosedUnit {
                    component: ci,
                    first: off,
                    len: s,
                    n,
                });
            }
            off += s;
        }
        let wv = comp.left_chains.try_mul(&v)?;
        let inv = wv
            .inverse()
            .map_err(|_| Error::Verification("normalised chains: W V' is singular".into()))?;
        comp.left_chains = inv.try_mul(&comp.left_chains)?;
        comp.chains = v;
        ok &= comp.verify(&a);
    }
    jf.verified = ok;
    Ok(closed)
}

/// [`normalize_form`] over $\mathbb{Q}(p)$ (`jordan --normalize X` on a file with symbols):
/// the chains of every eigenvalue $\theta \in \mathbb{Q}(p)$ normalised as rational functions
/// (the primary blocks of the factors of degree $\ge 2$ are kept: they are not chains), then
/// the primary form re-checked, $A T = T J$ as rational functions with $\det T \ne 0$, and the
/// conditions refreshed from the field's log: a division the normalisation made (by the entry
/// $(v_1)_r$ made 1, by $v_1 \cdot v_1$ of eq. 31) is a condition of the result like the
/// pivots of [`super::jordan_qp`]. A unit length is exact only when $v_1 \cdot v_1$ is the
/// square of a rational number; otherwise it is given in closed form ($V' / \sqrt n$, $n$ a
/// rational function).
///
/// # Errors
/// As [`normalize_form`] and [`super::JordanForm::primary_form`].
pub fn normalize_form_qp(
    jf: &mut super::JordanForm<crate::ratfunc::RatFuncField>,
    how: &Normalization,
) -> Result<Vec<ClosedUnit<crate::algebraic::ExtElem<crate::ratfunc::RatFunc>>>> {
    let closed = normalize_form(jf, how)?;
    let k = jf.base().clone();
    let (t, j) = jf.primary_form()?;
    let holds = jf.a.try_mul(&t)? == t.try_mul(&j)?;
    let det = t.det()?;
    let invertible = !k.is_zero(&det);
    k.record_condition(det.num());
    jf.conditions = k
        .conditions()?
        .into_iter()
        .map(|c| k.from_mpoly(c))
        .collect();
    jf.verified &= holds && invertible;
    Ok(closed)
}
