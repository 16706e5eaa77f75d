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

use crate::algebraic::AlgebraicNumber;
use crate::algebraic::{NfElem, NumberField};
use crate::error::Result;
use crate::field::{ComplexField, ComplexPair, Field, Q};
use crate::matrix::Matrix;
use crate::system::StateSpace;

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
    let core = super::jordan_core::jordan_core(sys)?;
    // real blocks
    let mut blocks = vec![];
    let mut symbols: Vec<(String, String)> = vec![];
    for c in &core.comps {
        let comp = &core.jf.components[c.comp];
        let p = &comp.factor;
        let mut certified: Option<Vec<AlgebraicNumber>> = None;
        for (j, &(re, im)) in comp.roots.iter().enumerate() {
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
                        NumberField::with_var(comp.field.modulus(), comp.roots[j], &var),
                        None,
                    ),
                };
                let conv = |m: &Matrix<NumberField>| match &radical {
                    Some((a0, s)) => m.map(&f, |x| crate::jordan::quadratic_image(x, a0, s)),
                    None => m.map(&f, |x| x.clone()),
                };
                let ev = crate::jordan::value_display(p, comp.roots[j]);
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
                let f = NumberField::with_var(comp.field.modulus(), (re, im), &var);
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
            let [a, b, cc] =
                super::jordan_core::real_pair_block(&f, [&c.a, &c.b, &c.c], |x| split(&cf, &t, x));
            let s = c.a.nrows();
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
        stages: core.stages,
        blocks,
        d: sys.d.clone(),
        mcmillan_degree: core.mcmillan_degree,
        symbols,
        verified: core.verified,
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
