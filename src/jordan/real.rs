//! The real Jordan form in the papers' convention.
//!
//! A real eigenvalue keeps its Jordan blocks and chains. A complex pair
//! $\theta = a + b i$, $\bar\theta$ ($b > 0$) with chain $v_1, \dots, v_k$
//! ($A v_1 = \theta v_1$, $A v_j = \theta v_j + v_{j-1}$) becomes the real columns
//! $x_j = \operatorname{Re} v_j$, $y_j = \operatorname{Im} v_j$ and the block
//! $$\begin{bmatrix} C & I_2 & \\ & C & \ddots \\ & & C \end{bmatrix},\quad
//! C = \begin{bmatrix} a & b \\ -b & a \end{bmatrix},$$
//! since $A(x + iy) = (a + bi)(x + iy)$ gives $A x = a x - b y$, $A y = b x + a y$.
//!
//! # Exactness
//! $\operatorname{Re}$ and $\operatorname{Im}$ of elements of $K = \mathbb{Q}(\theta)$
//! are exact in a real field $F$:
//! * $\deg p = 2$, $\theta = a_0 + s\sqrt{f}$, $f < 0$: $F = \mathbb{Q}$ or
//!   $\mathbb{Q}(\sqrt{|f|})$;
//! * $\theta = i\beta$ purely imaginary ($p$ even): $F = \mathbb{Q}(\beta)$ with $\beta$ a
//!   root of a factor of $p(i x)$ (e.g. $x^4 - 4x^2 + 1$ for $s^4 + 4s^2 + 1$, $\beta =
//!   \sqrt{2 \pm \sqrt 3}$); then $\operatorname{Re} \sum c_k \theta^k = \sum_{k \text{
//!   even}} c_k (-1)^{k/2} \beta^k$ and $\operatorname{Im} = \sum_{k \text{ odd}} c_k
//!   (-1)^{(k-1)/2}\beta^k$;
//! * every other complex factor ($\deg p \ge 3$, $\operatorname{Re}\theta \ne 0$):
//!   $F = \mathbb{Q}(\operatorname{Re}\theta, \operatorname{Im}\theta) = \mathbb{Q}(c)$
//!   with the primitive element $c = \operatorname{Re}\theta + k\operatorname{Im}\theta$,
//!   its minimal polynomial a factor of a composed resultant and $\operatorname{Re}\theta$,
//!   $\operatorname{Im}\theta$ as polynomials in $c$ from a gcd over $F(i)$ (see
//!   `realfield`), e.g. $F = \mathbb{Q}(\sqrt\[3\]{2}, \sqrt 3)$ of degree 6 for
//!   $x^3 - 2$; the field is listed in the report (`fields`) with `parts`
//!   $\theta = a(c) + b(c)\,i$.
//!
//! The real field of each pair is identified by certified isolation (the roots of the
//! candidate minimal polynomials against the box of $\theta$). Every block is verified:
//! $A T_c = T_c J_c$ in $F$. Should a step fail (an internal limit), the block is given
//! approximately, `exact` is false and `notes` says why: never silently.

use super::primary::{named_field, rational_field};
use super::realfield::{RealParts, identify_real_root, real_parts_field, simplify, theta_powers};
use super::roots::{factor_q, fmt_approx, quadratic_roots};
use super::{JordanForm, quadratic_field};
use crate::algebraic::AlgebraicNumber;
use crate::algebraic::{NfElem, NumberField};
use crate::error::Result;
use crate::field::{ComplexPair, Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use num_traits::{One, Zero};

/// How $\operatorname{Re}$, $\operatorname{Im}$ of $K$-elements land in the real field.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum ReImMap {
    /// Real root: the element itself (already in the real field).
    Real,
    /// Complex root $\theta = a + i b$ with $a, b$ in the real field $F$: an element
    /// $\sum c_k t^k$ maps to $\sum c_k \theta^k$ evaluated in $F(i)$; the table holds
    /// $\theta^0, \dots, \theta^{d-1}$ ($d = \deg p$), so each image costs only rational
    /// scalings.
    Complex(Vec<ComplexPair<NfElem>>),
}

/// One real eigenvalue or one complex pair of the real Jordan form.
#[derive(Clone, Debug, PartialEq)]
pub struct RealBlock {
    /// Index into [`JordanForm::eigenvalues`] (the root with $\operatorname{Im} \ge 0$).
    pub eigenvalue: usize,
    /// A complex pair ($2 \times 2$ blocks).
    pub pair: bool,
    /// The real field of the exact entries (`None` when not exact).
    pub field: Option<NumberField>,
    /// Columns ($n \times$ size) and block ($\text{size} \times \text{size}$), exact.
    pub t: Option<Matrix<NumberField>>,
    pub j: Option<Matrix<NumberField>>,
    pub t_approx: Vec<Vec<f64>>,
    pub j_approx: Vec<Vec<f64>>,
    /// Why the block is not expanded into a real field (it is then exact in the compact
    /// form, [`RealBlock::compact`]).
    pub note: Option<String>,
    /// The compact exact form of a complex pair (when not expanded into a real field).
    pub compact: Option<CompactPair>,
    pub(crate) map: Option<ReImMap>,
}

/// The compact exact form of one complex pair $\theta, \bar\theta$ (see the module
/// docs): the block $[[a, b], [-b, a]]$ with $a = \operatorname{Re}\theta$,
/// $b = \operatorname{Im}\theta$ as algebraic numbers, and the real columns
/// $[\operatorname{Re} v_j, \operatorname{Im} v_j]$ of the complex chains $v_j \in
/// \mathbb{Q}(\theta)^n$, i.e. $T_R = T_C S$ with $S = \frac12\begin{bmatrix} 1 & -i \\ 1
/// & i\end{bmatrix}$ per pair of columns $(v_j, \bar v_j)$.
#[derive(Clone, Debug, PartialEq)]
pub struct CompactPair {
    /// $K = \mathbb{Q}(\theta)$ marked at $\theta$, displayed with the eigenvalue's symbol.
    pub field: NumberField,
    /// The complex chains $V$ over $K$ ($n \times m$), verified $A V = V J_\theta$.
    pub v: Matrix<NumberField>,
    /// Display symbols of $\operatorname{Re}\theta$, $\operatorname{Im}\theta$ (`a<k>`,
    /// `b<k>`), used in `J` unless the part has a closed form.
    pub re_symbol: String,
    pub im_symbol: String,
    /// $\operatorname{Re}\theta$, $\operatorname{Im}\theta$ as certified algebraic numbers
    /// (minimal polynomial and isolating interval), computed when $\deg p \le$
    /// [`PARTS_MAX_DEGREE`]; otherwise they are defined through $\theta$ itself.
    pub re: Option<AlgebraicNumber>,
    pub im: Option<AlgebraicNumber>,
}

/// `-x` for a display string (`-b3`, `-(1 + sqrt(2))`).
#[cfg(feature = "cli")]
fn neg_display(x: &str) -> String {
    if let Some(rest) = x.strip_prefix('-')
        && !rest.contains([' ', '+', '-'])
    {
        return rest.to_string();
    }
    if x.contains([' ', '+']) || x[1..].contains('-') {
        format!("-({x})")
    } else {
        format!("-{x}")
    }
}

/// Largest eigenvalue degree for which the minimal polynomials of $\operatorname{Re}\theta$
/// (degree up to $d(d-1)/2$) and $\operatorname{Im}\theta$ (up to $d(d-1)$) are computed.
pub const PARTS_MAX_DEGREE: usize = 4;

/// Largest real-field degree that [`JordanForm::real_form`] expands into by default.
pub const EXPAND_MAX_DEGREE: usize = 4;

/// Largest eigenvalue degree whose pair is expanded into its real field even on request
/// (`--expand`): the real field of a generic factor of degree $d$ has degree $d(d-1)$, found by
/// factoring a polynomial of that degree (degree 5, field 20: 0.6 s; degree 6, field 30: 16 s
/// for the companion matrix of $x^6 - x + 1$, and more than 60 s for a dense random 6x6).
pub const EXPAND_MAX_EIGENVALUE_DEGREE: usize = 5;

impl CompactPair {
    /// Entry `(r, q)` of the pair block: `a`, `b`, `-b` on the $2 \times 2$ diagonal
    /// blocks, `1` where the chain couples (`coupling`), else `0`.
    #[cfg(feature = "cli")]
    pub(crate) fn j_entry(&self, r: usize, q: usize, coupling: bool) -> String {
        if r / 2 == q / 2 {
            match (r % 2, q % 2) {
                (0, 0) | (1, 1) => self.re_display(),
                (0, 1) => self.im_display(),
                _ => neg_display(&self.im_display()),
            }
        } else if coupling {
            "1".to_string()
        } else {
            "0".to_string()
        }
    }
    /// The display of $\operatorname{Re}\theta$ (closed form up to degree 2, else the symbol).
    pub fn re_display(&self) -> String {
        match &self.re {
            Some(x) if x.degree() <= 2 => x.value_string(),
            _ => self.re_symbol.clone(),
        }
    }
    /// The display of $\operatorname{Im}\theta$ (closed form up to degree 2, else the symbol).
    pub fn im_display(&self) -> String {
        match &self.im {
            Some(x) if x.degree() <= 2 => x.value_string(),
            _ => self.im_symbol.clone(),
        }
    }
    /// `Re(x)` / `Im(x)` displays of an element of $K$ (plain when $x$ is rational).
    #[cfg(feature = "cli")]
    pub(crate) fn part_strings(&self, x: &NfElem) -> (String, String) {
        let f = &self.field;
        if let Some(q) = f.to_rational(x) {
            return (crate::field::fmt_rational(&q), "0".to_string());
        }
        let s = f.fmt_elem(x);
        (format!("Re({s})"), format!("Im({s})"))
    }
}

/// The real Jordan form $A = T J T^{-1}$ with real $T$, $J$.
#[derive(Clone, Debug, PartialEq)]
pub struct RealJordanForm {
    pub n: usize,
    /// Symbols of the eigenvalues (`r<k>`) used in compact blocks, with their definitions.
    pub symbols: Vec<String>,
    pub blocks: Vec<RealBlock>,
    /// Every block is exact.
    pub exact: bool,
    /// The complex form was verified and every exact block satisfies $A T_c = T_c J_c$.
    pub verified: bool,
    /// Non-exact cases, one line each.
    pub notes: Vec<String>,
    /// For each pair in a real field of degree $\ge 3$: `r<k> = a + (b)*i` with $a$, $b$
    /// exact in that field.
    pub parts: Vec<String>,
}

impl RealBlock {
    /// $(\operatorname{Re} x, \operatorname{Im} x)$ in the block's real field, for $x$ in
    /// the component field $K$ (`None` for a non-exact block).
    pub(crate) fn re_im(&self, x: &NfElem) -> Option<(NfElem, NfElem)> {
        let f = self.field.as_ref()?;
        Some(match self.map.as_ref()? {
            ReImMap::Real => (x.clone(), f.zero()),
            ReImMap::Complex(powers) => {
                let mut re = f.zero();
                let mut im = f.zero();
                for (coef, pw) in x.0.iter().zip(powers) {
                    if coef.is_zero() {
                        continue;
                    }
                    let c = f.from_rational(coef);
                    re = f.add(&re, &f.mul(&c, &pw.re));
                    im = f.add(&im, &f.mul(&c, &pw.im));
                }
                (re, im)
            }
        })
    }
}

/// The pair block structure: `[[a, b], [-b, a]]` diagonal, `I2` coupling.
fn pair_block<K: Field>(k: &K, a: &K::Elem, b: &K::Elem, blocks: &[usize]) -> Matrix<K> {
    let m: usize = blocks.iter().sum();
    let mut j = Matrix::zeros(k.clone(), 2 * m, 2 * m);
    let mut off = 0;
    for &bs in blocks {
        for i in 0..bs {
            let d = 2 * (off + i);
            j.set(d, d, a.clone());
            j.set(d, d + 1, b.clone());
            j.set(d + 1, d, k.neg(b));
            j.set(d + 1, d + 1, a.clone());
            if i + 1 < bs {
                j.set(d, d + 2, k.one());
                j.set(d + 1, d + 3, k.one());
            }
        }
        off += bs;
    }
    j
}

/// The real field and map for a complex root, or a note why there is none.
fn real_field_for(
    jf: &JordanForm,
    ev: usize,
) -> std::result::Result<(NumberField, ReImMap), String> {
    let e = &jf.eigenvalues[ev];
    let p = &e.minpoly;
    if p.deg() == 2 {
        // theta = a0 + s sqrt(d), d < 0: Im = s sqrt(-d) (s > 0 for the upper root)
        let (a0, s, d) = quadratic_roots(p).expect("irreducible");
        let g = -d;
        let f = if g.is_one() {
            rational_field()
        } else {
            quadratic_field(&g)
        };
        let re = f.from_rational(&a0);
        let im = if g.is_one() {
            f.from_rational(&s)
        } else {
            f.from_poly(&Poly::new(Q, vec![Rational::zero(), s]))
        };
        let powers = theta_powers(p, &f, &re, &im).map_err(|e| e.to_string())?;
        return Ok((f, ReImMap::Complex(powers)));
    }
    let note = |err: crate::error::Error| {
        format!(
            "eigenvalue {} (root of {p}): exact real field not found ({err}); block given \
             approximately",
            fmt_approx(e.approx)
        )
    };
    if e.number.is_pure_imaginary() {
        // theta = i beta: beta is a real root of r(x) = p(i x) = sum c_k (-1)^(k/2) x^k
        let r = Poly::new(
            Q,
            p.coeffs()
                .iter()
                .enumerate()
                .map(|(k, c)| if (k / 2) % 2 == 0 { c.clone() } else { -c })
                .collect(),
        );
        let factors: Vec<Poly<Q>> = factor_q(&r)
            .map_err(note)?
            .into_iter()
            .map(|(g, _)| g)
            .collect();
        let (g, beta) =
            identify_real_root(&factors, &e.number, &Rational::zero(), &Rational::one())
                .map_err(note)?;
        let f = named_field(&g, (beta.approx().0, 0.0), &format!("b{}", ev + 1));
        let b = if g.deg() == 1 {
            f.from_rational(&-g.coeff(0))
        } else {
            f.generator()
        };
        let parts = simplify(RealParts {
            re: f.zero(),
            im: b,
            field: f,
            primitive: None,
            powers: vec![],
        });
        let powers = theta_powers(p, &parts.field, &parts.re, &parts.im).map_err(note)?;
        return Ok((parts.field, ReImMap::Complex(powers)));
    }
    let parts = real_parts_field(&e.number, &format!("c{}", ev + 1)).map_err(note)?;
    Ok((parts.field, ReImMap::Complex(parts.powers)))
}

impl JordanForm {
    /// The real Jordan form (see the module docs of [`super::real`]): complex pairs are
    /// expanded into an explicit real field when it has degree at most
    /// [`EXPAND_MAX_DEGREE`], otherwise given in the compact exact form ([`CompactPair`]).
    ///
    /// # Errors
    /// None at present beyond internal shape errors.
    pub fn real_form(&self) -> Result<RealJordanForm> {
        self.real_form_with(false)
    }
    /// The real Jordan form with every complex pair expanded into its real field
    /// $\mathbb{Q}(\operatorname{Re}\theta, \operatorname{Im}\theta)$ (`--expand`), whatever
    /// its degree ($d(d-1)$ for a generic factor of degree $d$) up to eigenvalues of degree
    /// [`EXPAND_MAX_EIGENVALUE_DEGREE`]; a pair of higher degree, or whose field cannot be
    /// built, stays compact, with a note.
    ///
    /// # Errors
    /// As [`JordanForm::real_form`].
    pub fn real_form_expanded(&self) -> Result<RealJordanForm> {
        self.real_form_with(true)
    }
    /// The real Jordan form; `expand` as in [`JordanForm::real_form_expanded`].
    ///
    /// # Errors
    /// As [`JordanForm::real_form`].
    pub fn real_form_with(&self, expand: bool) -> Result<RealJordanForm> {
        let n = self.n();
        let cols = self.root_columns();
        let mut blocks = vec![];
        let mut notes = vec![];
        let mut parts = vec![];
        let mut symbols = vec![];
        let mut verified = self.verified;
        for rc in cols {
            let e = &self.eigenvalues[rc.eigenvalue];
            if e.approx.1 < 0.0 {
                continue;
            }
            if e.approx.1 == 0.0 {
                let ak = self.a.convert_to(&rc.field);
                verified &= &ak * &rc.v == &rc.v * &rc.j;
                blocks.push(RealBlock {
                    eigenvalue: rc.eigenvalue,
                    pair: false,
                    t_approx: rc.v.to_approx(),
                    j_approx: rc.j.to_approx(),
                    field: Some(rc.field),
                    t: Some(rc.v),
                    j: Some(rc.j),
                    note: None,
                    compact: None,
                    map: Some(ReImMap::Real),
                });
                continue;
            }
            let comp = &self.components[e.component];
            let emb = comp.embedding(e.root, &e.symbol);
            // approximate parts from the complex embedding
            let m = comp.multiplicity;
            let mut t_approx = vec![vec![0.0; 2 * m]; n];
            for r in 0..n {
                for q in 0..m {
                    let (re, im) = emb.approx(comp.chains.get(r, q));
                    t_approx[r][2 * q] = re;
                    t_approx[r][2 * q + 1] = im;
                }
            }
            let j_approx = approx_pair_block(e.approx, &comp.blocks);
            let mut block = RealBlock {
                eigenvalue: rc.eigenvalue,
                pair: true,
                field: None,
                t: None,
                j: None,
                t_approx,
                j_approx,
                note: None,
                compact: None,
                map: None,
            };
            let (re_part, im_part) = exact_parts(e);
            let degree = e.minpoly.deg();
            let attempt = expand || expansion_may_be_small(&re_part, &im_part);
            let expanded = if attempt && degree > EXPAND_MAX_EIGENVALUE_DEGREE {
                notes.push(format!(
                    "eigenvalue {} has degree {degree}: its real field may have degree up to {} \
                     (`--expand` writes out pairs of degree at most \
                     {EXPAND_MAX_EIGENVALUE_DEGREE}); compact exact form given instead",
                    e.symbol,
                    degree * (degree - 1)
                ));
                None
            } else if attempt {
                match real_field_for(self, rc.eigenvalue) {
                    Ok((f, map)) if expand || f.degree() <= EXPAND_MAX_DEGREE => Some((f, map)),
                    Ok(_) => None,
                    Err(note) => {
                        if expand {
                            notes.push(format!("{note}; compact exact form given instead"));
                        }
                        None
                    }
                }
            } else {
                None
            };
            match expanded {
                Some((f, map)) => {
                    block.field = Some(f.clone());
                    block.map = Some(map);
                    let mut t = Matrix::zeros(f.clone(), n, 2 * m);
                    for r in 0..n {
                        for q in 0..m {
                            let (re, im) = block.re_im(comp.chains.get(r, q)).expect("exact");
                            t.set(r, 2 * q, re);
                            t.set(r, 2 * q + 1, im);
                        }
                    }
                    let (a, b) = block.re_im(&comp.root_elem()).expect("exact");
                    if f.degree() >= 3 {
                        parts.push(format!(
                            "{} = {} + ({})*i",
                            e.symbol,
                            f.fmt_elem(&a),
                            f.fmt_elem(&b)
                        ));
                    }
                    let j = pair_block(&f, &a, &b, &comp.blocks);
                    let ak = self.a.convert_to(&f);
                    verified &= &ak * &t == &t * &j;
                    // approximations from the complex embedding (degree d) are kept for
                    // large fields: a float evaluation in a field of degree d(d-1) is not
                    // reliable
                    if f.degree() <= EXPAND_MAX_DEGREE {
                        block.t_approx = t.to_approx();
                        block.j_approx = j.to_approx();
                    }
                    block.t = Some(t);
                    block.j = Some(j);
                }
                None => {
                    let cp = compact_pair(e, emb, comp.chains.clone(), re_part, im_part);
                    symbols.push(format!(
                        "{} = root of {} near {}",
                        e.symbol,
                        e.minpoly,
                        fmt_approx(e.approx)
                    ));
                    parts.extend(part_lines(e, &cp));
                    block.compact = Some(cp);
                }
            }
            blocks.push(block);
        }
        let exact = blocks.iter().all(|b| b.t.is_some() || b.compact.is_some());
        Ok(RealJordanForm {
            n,
            symbols,
            blocks,
            exact,
            verified: verified && exact,
            notes,
            parts,
        })
    }
}

/// Bit size (numerator plus denominator) above which the parts of a root of degree 3 or 4
/// are not computed: the composed polynomials of degree up to 12 and their factorization
/// then cost seconds (a mutant with an entry `-1e-300` has 300-digit coefficients), and the
/// compact form is exact anyway.
pub const PARTS_MAX_BITS: u64 = 256;

/// Whether [`exact_parts`] computes $\operatorname{Re}\theta$ and $\operatorname{Im}\theta$
/// for a root of `p`: degree at most [`PARTS_MAX_DEGREE`], and for degree 3 or 4
/// coefficients of at most [`PARTS_MAX_BITS`] bits.
pub fn parts_affordable(p: &Poly<Q>) -> bool {
    p.deg() <= 2
        || (p.deg() <= PARTS_MAX_DEGREE
            && p.coeffs()
                .iter()
                .all(|c| c.numer().bits() + c.denom().bits() <= PARTS_MAX_BITS))
}

/// $\operatorname{Re}\theta$ and $\operatorname{Im}\theta$ as certified algebraic numbers
/// when [`parts_affordable`] (composed polynomials of degree $d(d-1)/2$ and
/// $d(d-1)$, factored), else `None`.
fn exact_parts(e: &super::Eigenvalue) -> (Option<AlgebraicNumber>, Option<AlgebraicNumber>) {
    if parts_affordable(&e.minpoly) {
        (e.number.try_re().ok(), e.number.try_im().ok())
    } else {
        (None, None)
    }
}

/// Whether the real field $F = \mathbb{Q}(\operatorname{Re}\theta, \operatorname{Im}\theta)$
/// may have degree at most [`EXPAND_MAX_DEGREE`]: both parts are known and of degree at
/// most that ($[F : \mathbb{Q}]$ is at least the degree of each part). The field itself is
/// only built then (it costs a factorization of degree $d^2$ and arithmetic in $F$).
fn expansion_may_be_small(re: &Option<AlgebraicNumber>, im: &Option<AlgebraicNumber>) -> bool {
    matches!((re, im), (Some(a), Some(b))
        if a.degree() <= EXPAND_MAX_DEGREE && b.degree() <= EXPAND_MAX_DEGREE)
}

/// The compact form of the pair of eigenvalue `e` (the upper root) with the chains of its
/// component and its exact parts (when computed).
fn compact_pair(
    e: &super::Eigenvalue,
    field: NumberField,
    v: Matrix<NumberField>,
    re: Option<AlgebraicNumber>,
    im: Option<AlgebraicNumber>,
) -> CompactPair {
    let k = e.symbol.trim_start_matches('r');
    CompactPair {
        v: v.map(&field, |x| x.clone()),
        field,
        re_symbol: format!("a{k}"),
        im_symbol: format!("b{k}"),
        re,
        im,
    }
}

/// The legend lines of a compact pair: `r<k> = a<k> + b<k>*i` and each part's definition,
/// in the one display of every other section ([`AlgebraicNumber::value_string`]: a closed
/// form where there is one, else `root of P near X`; a part not computed exactly is
/// `near X` with the digits of [`crate::algebraic::display::approx_text`]).
fn part_lines(e: &super::Eigenvalue, cp: &CompactPair) -> Vec<String> {
    let define = |sym: &str, what: &str, x: &Option<AlgebraicNumber>, approx: f64| match x {
        Some(x) if x.degree() <= 2 => None,
        Some(x) => Some(format!(
            "{sym} = {what} {} = {}",
            e.symbol,
            x.value_string()
        )),
        None => Some(format!(
            "{sym} = {what} {}, near {}",
            e.symbol,
            crate::algebraic::display::approx_text((approx, 0.0))
        )),
    };
    let mut out = vec![format!(
        "{} = {} + {}*i",
        e.symbol,
        cp.re_display(),
        cp.im_display()
    )];
    out.extend(define(&cp.re_symbol, "Re", &cp.re, e.approx.0));
    out.extend(define(&cp.im_symbol, "Im", &cp.im, e.approx.1));
    out
}

fn approx_pair_block((a, b): (f64, f64), blocks: &[usize]) -> Vec<Vec<f64>> {
    let m: usize = blocks.iter().sum();
    let mut j = vec![vec![0.0; 2 * m]; 2 * m];
    let mut off = 0;
    for &bs in blocks {
        for i in 0..bs {
            let d = 2 * (off + i);
            j[d][d] = a;
            j[d][d + 1] = b;
            j[d + 1][d] = -b;
            j[d + 1][d + 1] = a;
            if i + 1 < bs {
                j[d][d + 2] = 1.0;
                j[d + 1][d + 3] = 1.0;
            }
        }
        off += bs;
    }
    j
}

impl RealJordanForm {
    /// $J$ and $T$ over one real field when all blocks are exact in the same field.
    pub fn single_field(&self) -> Option<(Matrix<NumberField>, Matrix<NumberField>)> {
        let mut field = rational_field();
        for b in &self.blocks {
            let f = b.field.as_ref()?;
            b.t.as_ref()?;
            if f.degree() > 1 {
                if field.degree() > 1 && &field != f {
                    return None;
                }
                field = f.clone();
            }
        }
        let n = self.n;
        let mut t = Matrix::zeros(field.clone(), n, n);
        let mut j = Matrix::zeros(field.clone(), n, n);
        let mut off = 0;
        for b in &self.blocks {
            let (bt, bj) = (b.t.as_ref()?, b.j.as_ref()?);
            let w = bt.ncols();
            t.set_block(0, off, &bt.map(&field, |x| x.clone()));
            j.set_block(off, off, &bj.map(&field, |x| x.clone()));
            off += w;
        }
        Some((j, t))
    }
}
