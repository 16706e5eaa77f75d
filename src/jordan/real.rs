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
use crate::error::Result;
use crate::field::{ComplexPair, Field, NfElem, NumberField, Q, Rational};
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
    /// Why the block is not exact.
    pub note: Option<String>,
    pub(crate) map: Option<ReImMap>,
}

/// The real Jordan form $A = T J T^{-1}$ with real $T$, $J$.
#[derive(Clone, Debug, PartialEq)]
pub struct RealJordanForm {
    pub n: usize,
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
            f.elem_from_poly(&Poly::new(Q, vec![Rational::zero(), s]))
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
    /// The real Jordan form (see the module docs of [`super::real`]).
    ///
    /// # Errors
    /// None at present beyond internal shape errors; non-exact cases are reported in
    /// [`RealJordanForm::notes`], never silently.
    pub fn real_form(&self) -> Result<RealJordanForm> {
        let n = self.n();
        let cols = self.root_columns();
        let mut blocks = vec![];
        let mut notes = vec![];
        let mut parts = vec![];
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
                map: None,
            };
            match real_field_for(self, rc.eigenvalue) {
                Ok((f, map)) => {
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
                    block.t_approx = t.to_approx();
                    block.j_approx = j.to_approx();
                    block.t = Some(t);
                    block.j = Some(j);
                }
                Err(note) => {
                    notes.push(note.clone());
                    block.note = Some(note);
                }
            }
            blocks.push(block);
        }
        let exact = blocks.iter().all(|b| b.t.is_some());
        Ok(RealJordanForm {
            n,
            blocks,
            exact,
            verified: verified && exact,
            notes,
            parts,
        })
    }
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
