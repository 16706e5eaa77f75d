//! Minimal realization by the Jordan form (minimal-realizations paper sec. 3.3), exactly.
//!
//! In modal coordinates $z = W x$ of each eigenvalue $\theta$ (root of an irreducible factor
//! $p$, worked once in $K = \mathbb{Q}[t]/(p)$, conjugates by embedding) the system splits into
//! Jordan blocks $(J_\theta, W B, C V)$. The method then:
//!
//! 1. **drops non-contributing modes**: in a block $z_i' = \theta z_i + z_{i+1} + b_i u$,
//!    $y \mathrel{+}= \sum c_i z_i$, the states below the last excited one ($i > \max\{j :
//!    b_j \ne 0\}$) stay zero and the states above the first observed one ($i < \min\{j : c_j
//!    \ne 0\}$) never reach $y$; what remains is again a Jordan chain (for the sliding masses the
//!    four modes at $\pm i\sqrt 2$ vanish: 20 → 16 states);
//! 2. **compacts repeated modes** (eq. 34-36, generalised to MIMO and to non-trivial blocks):
//!    the blocks of one eigenvalue are replaced by a minimal realization of $(N, WB, CV)$,
//!    $N = J_\theta - \theta I$ nilpotent, over $K$ (Kalman), put back in Jordan form by the
//!    chains of the reduced nilpotent matrix; for diagonalizable modes this is the exact rank
//!    factorization $b_5 c_5 = b_1 c_1 + b_3 c_3$ of eq. 36 (16 → 8 for the sliding masses);
//! 3. returns the **real** Jordan realization: real eigenvalues as they are, each complex pair
//!    $a \pm b i$ as blocks $[[a, b], [-b, a]]$ with $2 \times 2$ identity coupling, with
//!    $x = [\mathrm{Re}\, z; -\mathrm{Im}\, z]$ interleaved, $B_r = [\mathrm{Re}\, B;
//!    -\mathrm{Im}\, B]$, $C_r = [2\,\mathrm{Re}\, C, 2\,\mathrm{Im}\, C]$. Entries are exact in
//!    a real field per eigenvalue: $\mathbb{Q}$, the real field of a real root, or
//!    $\mathbb{Q}(\mathrm{Re}\,\theta, \mathrm{Im}\,\theta)$ (a primitive element, see
//!    `jordan::realfield`) for a complex pair.
//!
//! # Verification
//! Exact: $\sum_p \mathrm{Tr}_{K_p/\mathbb{Q}}(C_p J_p^k B_p) = C A^k B$ for $k < n + r$ (the
//! trace over the conjugates of each factor is rational), and the order equals the McMillan
//! degree (Hankel rank), so the result is minimal.

use super::controllability::mcmillan_degree;
use super::minimal::minimal_kalman;
use crate::algebraic::AlgebraicNumber;
use crate::algebraic::{NfElem, NumberField, NumberFieldCtx};
use crate::error::Result;
use crate::field::{ComplexField, ComplexPair, Field, Q, Rational};
use crate::jordan::{chains::jordan_chains, jordan};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::system::StateSpace;
use num_traits::Zero;
use std::sync::Arc;

/// One real block of the result: its field, and its (A, B, C) over that field.
#[derive(Clone, Debug)]
pub struct RealModalBlock {
    /// Display of the eigenvalue(s) (`-1 + i`, `sqrt(3)*i`, `-2`, ...).
    pub eigenvalue: String,
    /// The real field of the entries; for a compact pair $K = \mathbb{Q}(\theta)$ marked
    /// at $\theta$ (see [`RealModalBlock::compact`]).
    pub field: NumberField,
    /// The block's $(A, B, C)$ over `field`; for a compact pair the complex modal data
    /// $(J_\theta, W B, C V)$ over $K$, from which the real block is read off as
    /// $A_r = [[\mathrm{Re}, \mathrm{Im}], [-\mathrm{Im}, \mathrm{Re}]]$ of $J_\theta$,
    /// $B_r = [\mathrm{Re}\, WB; -\mathrm{Im}\, WB]$, $C_r = [2\,\mathrm{Re}\, CV,
    /// 2\,\mathrm{Im}\, CV]$ (interleaved per state).
    pub a: Matrix<NumberField>,
    pub b: Matrix<NumberField>,
    pub c: Matrix<NumberField>,
    /// A complex pair given in the compact form: the real block's entries are the real
    /// and imaginary parts of the $K$-entries above (displayed `Re(...)`, `Im(...)`, with
    /// `a<k>`, `b<k>` for $\mathrm{Re}\,\theta$, $\mathrm{Im}\,\theta$), never expanded
    /// into $\mathbb{Q}(\mathrm{Re}\,\theta, \mathrm{Im}\,\theta)$ of degree up to $d(d-1)$.
    pub compact: bool,
    /// Order of the real block (twice the complex order for a pair).
    pub order: usize,
}

/// The Jordan-method minimal realization.
#[derive(Clone, Debug)]
pub struct JordanMinimal {
    /// Orders: original, after dropping non-contributing modes, after compaction.
    pub stages: [usize; 3],
    pub blocks: Vec<RealModalBlock>,
    pub d: Matrix<Q>,
    pub mcmillan_degree: usize,
    /// Symbols used in entries, with their definitions.
    pub symbols: Vec<(String, String)>,
    pub verified: bool,
}

/// Per-component complex-form data after compaction.
struct Compact {
    field: NumberField,
    factor: Poly<Q>,
    roots: Vec<(f64, f64)>,
    a: Matrix<NumberField>,
    b: Matrix<NumberField>,
    c: Matrix<NumberField>,
}

/// Keeps, per Jordan block, the states from the first observed to the last excited one.
pub(super) fn drop_modes<K: Field>(
    blocks: &[usize],
    b: &Matrix<K>,
    c: &Matrix<K>,
) -> (Vec<usize>, Vec<usize>) {
    let k = b.field().clone();
    let (mut keep, mut sizes, mut start) = (vec![], vec![], 0);
    for &s in blocks {
        let idx: Vec<usize> = (start..start + s).collect();
        let excited = idx
            .iter()
            .rposition(|&i| b.row(i).iter().any(|x| !k.is_zero(x)));
        let observed = idx
            .iter()
            .position(|&i| (0..c.nrows()).any(|r| !k.is_zero(c.get(r, i))));
        if let (Some(hi), Some(lo)) = (excited, observed)
            && lo <= hi
        {
            keep.extend(start + lo..=start + hi);
            sizes.push(hi - lo + 1);
        }
        start += s;
    }
    (keep, sizes)
}

/// Newton power sums $p_j = \sum_i \theta_i^j$, $j < m$, of the roots of `p`
/// ([`crate::poly::newton_power_sums`]).
fn power_sums(p: &Poly<Q>, m: usize) -> Vec<Rational> {
    let mut s = crate::poly::newton_power_sums(&p.monic(), m.saturating_sub(1));
    s.truncate(m);
    s
}

/// Adds $\mathrm{Tr}_{K/\mathbb{Q}}(C_p J_\theta^k B_p)$ to `sum[k]` for every $k$, without
/// products in $K$ per $k$: $(J_\theta^k)_{l, l+r} = \binom kr \theta^{k-r}$ inside a Jordan
/// block, so each entry is a sum of $\binom kr \mathrm{Tr}(\theta^{k-r} x)$ over the
/// products $x = C_{il} B_{l+r,j}$ (computed once), and $\mathrm{Tr}(\theta^e x) = \sum_c
/// x_c\, s_{e+c}$ with the power sums $s$ of the factor.
fn add_traces(c: &Compact, sum: &mut [Matrix<Q>]) {
    let kmax = sum.len();
    let f = &c.field;
    let s = c.a.nrows();
    let sums = power_sums(&c.factor, kmax + c.factor.deg() + 1);
    let mut start = vec![0; s];
    for l in 1..s {
        start[l] = if f.is_zero(c.a.get(l - 1, l)) {
            l
        } else {
            start[l - 1]
        };
    }
    for i in 0..c.c.nrows() {
        for j in 0..c.b.ncols() {
            for l in 0..s {
                for l2 in l..s {
                    if start[l2] != start[l] {
                        continue;
                    }
                    let x = f.mul(c.c.get(i, l), c.b.get(l2, j));
                    if f.is_zero(&x) {
                        continue;
                    }
                    let r = l2 - l;
                    // binom(k, r) for k = r, r + 1, ...
                    let mut binom = Rational::from_integer(1.into());
                    for (k, mk) in sum.iter_mut().enumerate().skip(r) {
                        if k > r {
                            binom = binom * Rational::from_integer(k.into())
                                / Rational::from_integer((k - r).into());
                        }
                        let tr: Rational = x.0.iter().zip(&sums[k - r..]).map(|(a, b)| a * b).sum();
                        let cur = mk.get(i, j) + &(&binom * &tr);
                        mk.set(i, j, cur);
                    }
                }
            }
        }
    }
}

/// The certified root among `roots` (those of one irreducible polynomial, isolated once per
/// factor) closest to the approximation `theta`.
fn closest_root(roots: &[AlgebraicNumber], theta: (f64, f64)) -> Option<AlgebraicNumber> {
    let d = |z: &AlgebraicNumber| (z.approx().0 - theta.0).hypot(z.approx().1 - theta.1);
    roots.iter().min_by(|x, y| d(x).total_cmp(&d(y))).cloned()
}

/// Whether the real field of the complex root `z` may be small (both parts of degree at
/// most [`crate::jordan::real::EXPAND_MAX_DEGREE`], computed only for eigenvalues of
/// degree at most [`crate::jordan::real::PARTS_MAX_DEGREE`] with moderate coefficients,
/// [`crate::jordan::real::parts_affordable`]), as for the real Jordan form.
fn small_real_field(z: &AlgebraicNumber) -> bool {
    use crate::jordan::real::{EXPAND_MAX_DEGREE, parts_affordable};
    if !parts_affordable(z.minpoly()) {
        return false;
    }
    match (z.try_re(), z.try_im()) {
        (Ok(a), Ok(b)) => a.degree() <= EXPAND_MAX_DEGREE && b.degree() <= EXPAND_MAX_DEGREE,
        _ => false,
    }
}

/// Splits an element $e = \sum c_j t^j$ of $K$ at $t = a + i\beta$ into real and imaginary
/// parts in $F = \mathbb{Q}(\beta)$.
fn split(cf: &ComplexField<NumberField>, t: &ComplexPair<NfElem>, e: &NfElem) -> (NfElem, NfElem) {
    let mut acc = cf.zero();
    for c in e.0.iter().rev() {
        acc = cf.add(&cf.mul(&acc, t), &cf.from_rational(c));
    }
    (acc.re, acc.im)
}

/// An element of $K$ from a coefficient column (trailing zeros dropped: canonical form).
fn elem_of(m: &Matrix<Q>, j: usize) -> NfElem {
    let mut c: Vec<Rational> = (0..m.nrows()).map(|i| m.get(i, j).clone()).collect();
    while c.last().is_some_and(|x| x.is_zero()) {
        c.pop();
    }
    NfElem(c)
}

/// $W B$ for $W$ over $K$ and rational $B$, as rational products of coefficient matrices
/// (row $r$ of $W$ as the $d \times n$ matrix of its coefficients times $B$): no product in
/// $K$, and the integer product kernel does the work.
pub(super) fn times_rational(w: &Matrix<NumberField>, b: &Matrix<Q>) -> Matrix<NumberField> {
    let k = w.field().clone();
    let d = k.degree();
    let mut out = Matrix::zeros(k, w.nrows(), b.ncols());
    for r in 0..w.nrows() {
        let wc = crate::jordan::coeffs::coeff_cols(w.row(r), d);
        let prod = &wc * b;
        for j in 0..b.ncols() {
            out.set(r, j, elem_of(&prod, j));
        }
    }
    out
}

/// $C V$ for rational $C$ and $V$ over $K$, as [`times_rational`] does $W B$.
pub(super) fn rational_times(c: &Matrix<Q>, v: &Matrix<NumberField>) -> Matrix<NumberField> {
    let k = v.field().clone();
    let d = k.degree();
    let ct = c.transpose();
    let mut out = Matrix::zeros(k, c.nrows(), v.ncols());
    for r in 0..v.ncols() {
        let vc = crate::jordan::coeffs::coeff_cols(&v.col(r), d);
        let prod = &vc * &ct;
        for i in 0..c.nrows() {
            out.set(i, r, elem_of(&prod, i));
        }
    }
    out
}

fn compact_component(
    sys: &StateSpace<Q>,
    comp: &crate::jordan::primary::PrimaryComponent,
    stage1: &mut usize,
) -> Result<Option<Compact>> {
    let k = comp.field.clone();
    let d = comp.degree();
    let bk = times_rational(&comp.left_chains, &sys.b);
    let ck = rational_times(&sys.c, &comp.chains);
    let (keep, sizes) = drop_modes(&comp.blocks, &bk, &ck);
    *stage1 += keep.len() * d;
    if keep.is_empty() {
        return Ok(None);
    }
    let theta = comp.root_elem();
    if keep.len() == 1 {
        // one excited and observed mode (a simple eigenvalue): already minimal
        return Ok(Some(Compact {
            a: Matrix::from_vec(k.clone(), 1, 1, vec![theta]),
            b: bk.select_rows(&keep),
            c: ck.select_cols(&keep),
            field: k,
            factor: comp.factor.clone(),
            roots: comp.roots.clone(),
        }));
    }
    let nilp = crate::jordan::chains::jordan_block_matrix(&k, &k.zero(), &sizes);
    let trimmed =
        StateSpace::new_strictly_proper(nilp, bk.select_rows(&keep), ck.select_cols(&keep))?;
    let min = minimal_kalman(&trimmed)?.system;
    let r = min.nstates();
    if r == 0 {
        return Ok(None);
    }
    let ch = jordan_chains(&min.a, r)?;
    let jn = crate::jordan::chains::jordan_block_matrix(&k, &theta, &ch.blocks);
    Ok(Some(Compact {
        field: k,
        factor: comp.factor.clone(),
        roots: comp.roots.clone(),
        a: jn,
        b: &ch.w * &min.b,
        c: &min.c * &ch.v,
    }))
}

/// Minimal realization by the Jordan-form method, complex pairs expanded into their real
/// field only when it is small (degree at most [`crate::jordan::real::EXPAND_MAX_DEGREE`]),
/// otherwise in the compact form ([`RealModalBlock::compact`]).
///
/// # Errors
/// Errors of the Jordan decomposition.
pub fn minimal_jordan(sys: &StateSpace<Q>) -> Result<JordanMinimal> {
    minimal_jordan_with(sys, false)
}

/// As [`minimal_jordan`]; `expand` writes every complex pair in its real field
/// $\mathbb{Q}(\mathrm{Re}\,\theta, \mathrm{Im}\,\theta)$ (degree up to $d(d-1)$; a pair
/// whose field cannot be built stays compact).
///
/// # Errors
/// Errors of the Jordan decomposition.
pub fn minimal_jordan_with(sys: &StateSpace<Q>, expand: bool) -> Result<JordanMinimal> {
    let n = sys.nstates();
    let jf = jordan(&sys.a)?;
    let mut stage1 = 0;
    let mut comps = vec![];
    for comp in &jf.components {
        if let Some(c) = compact_component(sys, comp, &mut stage1)? {
            comps.push(c);
        }
    }
    // exact verification through traces
    let r: usize = comps.iter().map(|c| c.a.nrows() * c.factor.deg()).sum();
    let kmax = n + r;
    let markov = sys.markov(kmax);
    let mut sum: Vec<Matrix<Q>> = (0..kmax)
        .map(|_| Matrix::zeros(Q, sys.noutputs(), sys.ninputs()))
        .collect();
    for c in &comps {
        add_traces(c, &mut sum);
    }
    let mcm = mcmillan_degree(sys);
    let verified = sum == markov && r == mcm;
    // real blocks
    let mut blocks = vec![];
    let mut symbols: Vec<(String, String)> = vec![];
    for c in &comps {
        let p = &c.factor;
        let mut certified: Option<Vec<AlgebraicNumber>> = None;
        for (j, &(re, im)) in c.roots.iter().enumerate() {
            if im < 0.0 {
                continue;
            }
            let var = format!(
                "r{}",
                symbols.iter().filter(|(k, _)| k.starts_with('r')).count() + 1
            );
            if im == 0.0 || p.deg() == 1 {
                // a real root: the same data in K marked at this root; a quadratic K as
                // Q(sqrt f), shown as every quadratic number is (`1 - sqrt(2)/2`)
                let (f, radical) = match crate::algebraic::display::quadratic_roots(p) {
                    Some((a0, s, fd)) if p.deg() == 2 => {
                        let s = if re > crate::field::rational_to_f64(&a0) {
                            s
                        } else {
                            -s
                        };
                        (crate::jordan::quadratic_field(&fd), Some((a0, s)))
                    }
                    _ => (
                        NumberField(Arc::new(NumberFieldCtx {
                            modulus: c.field.modulus().clone(),
                            root: c.roots[j],
                            var: var.clone(),
                        })),
                        None,
                    ),
                };
                let conv = |m: &Matrix<NumberField>| match &radical {
                    Some((a0, s)) => m.map(&f, |x| crate::jordan::quadratic_image(x, a0, s)),
                    None => m.map(&f, |x| x.clone()),
                };
                let ev = crate::jordan::value_display(p, c.roots[j]);
                if p.deg() > 2 {
                    symbols.push((var, ev.clone()));
                }
                blocks.push(RealModalBlock {
                    eigenvalue: ev,
                    field: f.clone(),
                    a: conv(&c.a),
                    b: conv(&c.b),
                    c: conv(&c.c),
                    compact: false,
                    order: c.a.nrows(),
                });
                continue;
            }
            let roots = certified.get_or_insert_with(|| {
                AlgebraicNumber::roots_of_irreducible(p).unwrap_or_default()
            });
            let number = closest_root(roots, (re, im));
            let ev = number
                .as_ref()
                .map(|z| z.value_string())
                .unwrap_or_default();
            let expanded = match &number {
                Some(z) if expand || small_real_field(z) => {
                    crate::jordan::realfield::real_parts_field(z, &var)
                        .ok()
                        .map(|parts| (parts.field, parts.re, parts.im))
                }
                _ => None,
            };
            let Some((f, a_re, beta)) = expanded else {
                // compact: the complex modal data over K marked at theta
                let f = NumberField(Arc::new(NumberFieldCtx {
                    modulus: c.field.modulus().clone(),
                    root: (re, im),
                    var: var.clone(),
                }));
                let k = var.trim_start_matches('r').to_string();
                symbols.push((var.clone(), crate::jordan::value_display(p, (re, im))));
                symbols.push((format!("a{k}"), format!("Re {var}")));
                symbols.push((format!("b{k}"), format!("Im {var}")));
                let conv = |m: &Matrix<NumberField>| m.map(&f, |x| x.clone());
                blocks.push(RealModalBlock {
                    eigenvalue: format!("{ev} (and its conjugate)"),
                    field: f.clone(),
                    a: conv(&c.a),
                    b: conv(&c.b),
                    c: conv(&c.c),
                    compact: true,
                    order: 2 * c.a.nrows(),
                });
                continue;
            };
            // a quadratic real field shows its radical (`sqrt(3)`), not the symbol
            if f.degree() > 1 && f.0.var == var {
                symbols.push((
                    var,
                    crate::jordan::value_display(f.modulus(), f.root_approx()),
                ));
            }
            let cf = ComplexField::new(f.clone());
            let t = ComplexPair { re: a_re, im: beta };
            let s = c.a.nrows();
            let two = f.from_i64(2);
            let mut a = Matrix::zeros(f.clone(), 2 * s, 2 * s);
            let mut b = Matrix::zeros(f.clone(), 2 * s, c.b.ncols());
            let mut cc = Matrix::zeros(f.clone(), c.c.nrows(), 2 * s);
            for i in 0..s {
                for jj in 0..s {
                    let (x, y) = split(&cf, &t, c.a.get(i, jj));
                    // z = x1 - i x2: [[Re, -Im], [Im, Re]] acting on (x1, -x2) -> [[Re, Im], [-Im, Re]]
                    a.set(2 * i, 2 * jj, x.clone());
                    a.set(2 * i, 2 * jj + 1, y.clone());
                    a.set(2 * i + 1, 2 * jj, f.neg(&y));
                    a.set(2 * i + 1, 2 * jj + 1, x);
                }
                for col in 0..c.b.ncols() {
                    let (x, y) = split(&cf, &t, c.b.get(i, col));
                    b.set(2 * i, col, x);
                    b.set(2 * i + 1, col, f.neg(&y));
                }
            }
            for row in 0..c.c.nrows() {
                for i in 0..s {
                    let (x, y) = split(&cf, &t, c.c.get(row, i));
                    cc.set(row, 2 * i, f.mul(&two, &x));
                    cc.set(row, 2 * i + 1, f.mul(&two, &y));
                }
            }
            blocks.push(RealModalBlock {
                eigenvalue: format!("{ev} (and its conjugate)"),
                field: f,
                order: 2 * s,
                a,
                b,
                c: cc,
                compact: false,
            });
        }
    }
    Ok(JordanMinimal {
        stages: [n, stage1, r],
        blocks,
        d: sys.d.clone(),
        mcmillan_degree: mcm,
        symbols,
        verified,
    })
}

impl JordanMinimal {
    pub fn order(&self) -> usize {
        self.stages[2]
    }
    /// The realization as one rational system when every block is rational.
    pub fn to_rational(&self) -> Option<StateSpace<Q>> {
        let conv = |m: &Matrix<NumberField>| crate::matrix::to_rational_matrix(m);
        let mut a = vec![];
        let mut b: Option<Matrix<Q>> = None;
        let mut c: Option<Matrix<Q>> = None;
        for blk in &self.blocks {
            if blk.compact {
                return None;
            }
            a.push(conv(&blk.a)?);
            let bb = conv(&blk.b)?;
            let cb = conv(&blk.c)?;
            b = Some(match b {
                None => bb,
                Some(x) => x.vstack(&bb).ok()?,
            });
            c = Some(match c {
                None => cb,
                Some(x) => x.hstack(&cb).ok()?,
            });
        }
        let m = self.d.ncols();
        let p = self.d.nrows();
        StateSpace::new(
            Matrix::block_diag(Q, &a),
            b.unwrap_or_else(|| Matrix::zeros(Q, 0, m)),
            c.unwrap_or_else(|| Matrix::zeros(Q, p, 0)),
            self.d.clone(),
        )
        .ok()
    }
}

/// The Jordan-method minimal realization as a rational state-space system, verified like
/// every [`super::MinimalRealization`] (Markov parameters up to $2n$, controllable,
/// observable); available when every mode's block is rational (all retained eigenvalues
/// rational, or complex blocks whose real form is rational).
///
/// # Errors
/// `Unsupported` when some block has entries in a number field of degree > 1 (then use
/// [`minimal_jordan`], whose blocks keep their fields); errors of [`minimal_jordan`].
pub fn minimal_jordan_rational(sys: &StateSpace<Q>) -> Result<super::MinimalRealization<Q>> {
    let jm = minimal_jordan(sys)?;
    let n: usize = jm.blocks.iter().map(|b| b.a.nrows()).sum();
    let (m, p) = (sys.ninputs(), sys.noutputs());
    let mut a = Matrix::zeros(Q, n, n);
    let mut b = Matrix::zeros(Q, n, m);
    let mut c = Matrix::zeros(Q, p, n);
    let mut off = 0;
    for blk in &jm.blocks {
        if blk.compact {
            return Err(crate::error::Error::Unsupported(format!(
                "the Jordan-method realization keeps the complex pair {} in compact form \
                 (entries Re/Im of elements of {}): use realization::minimal_jordan",
                blk.eigenvalue, blk.field
            )));
        }
        let q = |x: &NfElem| {
            blk.field.to_rational(x).ok_or_else(|| {
                crate::error::Error::Unsupported(format!(
                    "the Jordan-method realization has entries in {} (mode {}): use realization::minimal_jordan",
                    blk.field, blk.eigenvalue
                ))
            })
        };
        let s = blk.a.nrows();
        for i in 0..s {
            for j in 0..s {
                a.set(off + i, off + j, q(blk.a.get(i, j))?);
            }
            for j in 0..m {
                b.set(off + i, j, q(blk.b.get(i, j))?);
            }
            for r in 0..p {
                c.set(r, off + i, q(blk.c.get(r, i))?);
            }
        }
        off += s;
    }
    let min = StateSpace::new(a, b, c, jm.d.clone())?;
    Ok(super::MinimalRealization::new(
        sys,
        min,
        super::MinrealMethod::Jordan,
        None,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn power_sums_of_quadratic() {
        // x^2 - 3x + 2: roots 1, 2 -> p0 = 2, p1 = 3, p2 = 5, p3 = 9
        let s = power_sums(&Poly::from_i64s(&[2, -3, 1]), 4);
        let want: Vec<Rational> = [2, 3, 5, 9]
            .iter()
            .map(|&v: &i64| Rational::from_integer(v.into()))
            .collect();
        assert_eq!(s, want);
    }
}
