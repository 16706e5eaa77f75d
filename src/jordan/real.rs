//! The real Jordan form in the papers' convention, written once for every real base field
//! ($\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$ with $d > 0$; [`super::EigenField::is_real`]).
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
//! Over $K = \mathbb{Q}(\sqrt d)$ the real field of a pair is built from a primitive element
//! of $K(\theta)$ ([`super::pair_field`]); a pair of a rational quadratic factor,
//! $a_0 \pm s\sqrt f$, keeps its radical form (entries $u$ and $w\sqrt{-f}$, $u, w \in K$).
//!
//! The real field of each pair is identified by certified isolation (the roots of the
//! candidate minimal polynomials against the box of $\theta$). Every expanded block is
//! verified: $A T_c = T_c J_c$ in $F$; a block kept in the compact (or radical) form is
//! verified on the complex side ($A V = V J_t$ in $E$ implies $A T_R = T_R J_R$). Should a
//! field not be found, the pair stays compact and `notes` says why: never silently.
//!
//! The result holds values (matrices over the fields, algebraic numbers); its displays are
//! made in `report/`.

pub use super::pair_field::{
    EXPAND_MAX_DEGREE, EXPAND_MAX_EIGENVALUE_DEGREE, PARTS_MAX_BITS, PARTS_MAX_DEGREE,
    parts_affordable,
};
use super::pair_field::{PairField, exact_parts};
use super::{EigenField, JordanForm};
use crate::algebraic::{AlgebraicNumber, Ext, NumberField};
use crate::error::{Error, Result};
use crate::field::{Field, Q};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// The exact entries of one block of the real Jordan form.
#[derive(Clone, Debug, PartialEq)]
pub enum RealEntries<F: Field> {
    /// A real eigenvalue: its columns and Jordan block, exact in the eigenvalue's field
    /// ([`super::EigenField::root_field`]).
    Root {
        field: Ext<F>,
        t: Matrix<Ext<F>>,
        j: Matrix<Ext<F>>,
    },
    /// A complex pair written in its real field $F$: `t` $= [\operatorname{Re} v_1,
    /// \operatorname{Im} v_1, \dots]$, `j` the blocks $[[a, b], [-b, a]]$, checked
    /// $A T = T J$ in $F$.
    Expanded {
        pair: PairField,
        t: Matrix<NumberField>,
        j: Matrix<NumberField>,
    },
    /// A pair of a rational quadratic factor $a_0 \pm s\sqrt f$ over a quadratic field: the
    /// complex chains over $E$ at $\theta$ (displayed with the radical), whose entries
    /// $u + w\sqrt f$ have the exact parts $u$ and $w\sqrt{-f}$.
    Radical(CompactPair<F>),
    /// A complex pair whose real field is large (or not found): the compact form.
    Compact(CompactPair<F>),
}

/// One real eigenvalue or one complex pair of the real Jordan form.
#[derive(Clone, Debug, PartialEq)]
pub struct RealBlock<F: Field = Q> {
    /// Index into [`JordanForm::eigenvalues`] (the root with $\operatorname{Im} \ge 0$).
    pub eigenvalue: usize,
    /// A complex pair ($2 \times 2$ blocks).
    pub pair: bool,
    /// The exact entries.
    pub entries: RealEntries<F>,
    /// Approximations of the columns ($n \times$ size) and of the block.
    pub t_approx: Vec<Vec<f64>>,
    pub j_approx: Vec<Vec<f64>>,
}

/// The compact exact form of one complex pair $\theta, \bar\theta$ (see the module
/// docs): the block $[[a, b], [-b, a]]$ with $a = \operatorname{Re}\theta$,
/// $b = \operatorname{Im}\theta$ as algebraic numbers, and the real columns
/// $[\operatorname{Re} v_j, \operatorname{Im} v_j]$ of the complex chains $v_j \in
/// E^n$, i.e. $T_R = T_C S$ with $S = \frac12\begin{bmatrix} 1 & -i \\ 1
/// & i\end{bmatrix}$ per pair of columns $(v_j, \bar v_j)$.
#[derive(Clone, Debug, PartialEq)]
pub struct CompactPair<F: Field = Q> {
    /// $E = F\[t\]/(g)$ marked at $\theta$, displayed with the eigenvalue's symbol (or its
    /// radical).
    pub field: Ext<F>,
    /// The complex chains $V$ over $E$ ($n \times m$), verified $A V = V J_\theta$.
    pub v: Matrix<Ext<F>>,
    /// Jordan block sizes of $\theta$.
    pub blocks: Vec<usize>,
    /// $\operatorname{Re}\theta$, $\operatorname{Im}\theta$ as certified algebraic numbers
    /// (minimal polynomial and isolating interval), computed when the eigenvalue's degree is
    /// at most [`PARTS_MAX_DEGREE`]; otherwise they are defined through $\theta$ itself.
    pub re: Option<AlgebraicNumber>,
    pub im: Option<AlgebraicNumber>,
}

/// Why a pair is not written in its real field.
#[derive(Clone, Debug, PartialEq)]
pub struct RealNote {
    /// Index into [`JordanForm::eigenvalues`].
    pub eigenvalue: usize,
    /// The reason (the error of [`super::EigenField::real_pair`]).
    pub error: Error,
}

/// The real Jordan form $A = T J T^{-1}$ with real $T$, $J$.
#[derive(Clone, Debug, PartialEq)]
pub struct RealJordanForm<F: Field = Q> {
    pub n: usize,
    /// The base field.
    pub base: F,
    /// The eigenvalues of the complex form (the blocks refer to them) and the irreducible
    /// factor over the base field of each component.
    pub eigenvalues: Vec<super::Eigenvalue<F>>,
    pub factors: Vec<Poly<F>>,
    pub blocks: Vec<RealBlock<F>>,
    /// Every block is exact (always: a pair whose real field is not found is compact).
    pub exact: bool,
    /// The complex form was verified and every expanded block satisfies $A T_c = T_c J_c$.
    pub verified: bool,
    /// Pairs left compact although `expand` asked for their real field, one each.
    pub notes: Vec<RealNote>,
}

impl<F: Field> RealBlock<F> {
    /// The compact (or radical) form of a pair.
    pub fn compact(&self) -> Option<&CompactPair<F>> {
        match &self.entries {
            RealEntries::Compact(cp) | RealEntries::Radical(cp) => Some(cp),
            _ => None,
        }
    }
    /// Whether the block is written in the compact form (not the radical one).
    pub fn is_compact(&self) -> bool {
        matches!(self.entries, RealEntries::Compact(_))
    }
}

impl RealBlock<Q> {
    /// The block's field, `T` and `J` when it is written in one real number field (a real
    /// root, or an expanded pair).
    pub fn exact_entries(
        &self,
    ) -> Option<(&NumberField, &Matrix<NumberField>, &Matrix<NumberField>)> {
        match &self.entries {
            RealEntries::Root { field, t, j } => Some((field, t, j)),
            RealEntries::Expanded { pair, t, j } => Some((&pair.field, t, j)),
            _ => None,
        }
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

impl<F: EigenField> JordanForm<F> {
    /// The real Jordan form (see the module docs of [`super::real`]): complex pairs are
    /// expanded into an explicit real field when it has degree at most
    /// [`EXPAND_MAX_DEGREE`], otherwise given in the compact exact form ([`CompactPair`]).
    ///
    /// # Errors
    /// `Invalid` when the field is not real (a matrix over $\mathbb{Q}(i)$ with a non-real
    /// entry has no real Jordan form).
    pub fn real_form(&self) -> Result<RealJordanForm<F>> {
        self.real_form_with(false)
    }
    /// The real Jordan form with every complex pair expanded into its real field
    /// (`--expand`), whatever its degree up to the bounds of the field
    /// ([`EXPAND_MAX_EIGENVALUE_DEGREE`] over $\mathbb{Q}$); a pair whose field cannot be
    /// built stays compact, with a note.
    ///
    /// # Errors
    /// As [`JordanForm::real_form`].
    pub fn real_form_expanded(&self) -> Result<RealJordanForm<F>> {
        self.real_form_with(true)
    }
    /// The real Jordan form; `expand` as in [`JordanForm::real_form_expanded`].
    ///
    /// # Errors
    /// As [`JordanForm::real_form`].
    pub fn real_form_with(&self, expand: bool) -> Result<RealJordanForm<F>> {
        let k = self.base();
        if !k.is_real() {
            return Err(Error::Invalid(format!(
                "A over {k} is not real, so it has no real Jordan form"
            )));
        }
        let n = self.n();
        let mut blocks = vec![];
        let mut notes = vec![];
        let mut verified = self.verified;
        for rc in self.root_columns() {
            let ev = rc.eigenvalue;
            let e = &self.eigenvalues[ev];
            if e.approx.1 < 0.0 && !e.number.is_real() {
                continue; // written with its upper partner
            }
            if e.approx.1 == 0.0 || e.number.is_real() {
                let lift = |x: &F::Elem| rc.field.from_base(x);
                verified &= &self.a.map(&rc.field, lift) * &rc.v == &rc.v * &rc.j;
                blocks.push(RealBlock {
                    eigenvalue: ev,
                    pair: false,
                    t_approx: rc.v.to_approx(),
                    j_approx: rc.j.to_approx(),
                    entries: RealEntries::Root {
                        field: rc.field,
                        t: rc.v,
                        j: rc.j,
                    },
                });
                continue;
            }
            let comp = &self.components[e.component];
            let pair = match F::real_pair(self, ev, expand) {
                Ok(p) => p,
                Err(error) => {
                    if expand {
                        notes.push(RealNote {
                            eigenvalue: ev,
                            error,
                        });
                    }
                    None
                }
            };
            let block = match pair {
                Some(pf) => {
                    let (t, j) = expanded_pair(&pf, k, comp);
                    verified &= &pf.matrix(&self.a) * &t == &t * &j;
                    // approximations from the complex embedding (degree d) are kept for large
                    // fields: a float evaluation in a field of degree d(d-1) is not reliable
                    let (t_approx, j_approx) = if pf.field.degree() <= EXPAND_MAX_DEGREE {
                        (t.to_approx(), j.to_approx())
                    } else {
                        pair_approx(&rc.field, &rc.v, e.approx, &comp.blocks)
                    };
                    RealBlock {
                        eigenvalue: ev,
                        pair: true,
                        t_approx,
                        j_approx,
                        entries: RealEntries::Expanded { pair: pf, t, j },
                    }
                }
                None => {
                    let (re, im) = exact_parts(e);
                    let (t_approx, j_approx) =
                        pair_approx(&rc.field, &rc.v, e.approx, &comp.blocks);
                    let cp = CompactPair {
                        field: rc.field,
                        v: rc.v,
                        blocks: comp.blocks.clone(),
                        re,
                        im,
                    };
                    let radical = cp.field.0.radical.is_some() && comp.factor.deg() == 2;
                    RealBlock {
                        eigenvalue: ev,
                        pair: true,
                        t_approx,
                        j_approx,
                        entries: if radical {
                            RealEntries::Radical(cp)
                        } else {
                            RealEntries::Compact(cp)
                        },
                    }
                }
            };
            blocks.push(block);
        }
        let width: usize = blocks.iter().map(|b| b.j_approx.len()).sum();
        Ok(RealJordanForm {
            n,
            base: k.clone(),
            eigenvalues: self.eigenvalues.clone(),
            factors: self.components.iter().map(|c| c.factor.clone()).collect(),
            blocks,
            exact: true,
            verified: verified && width == n,
            notes,
        })
    }
}

/// $T = [\operatorname{Re} V, \operatorname{Im} V]$ (interleaved) and the pair blocks of a
/// component in the real field of `pf`.
fn expanded_pair<F: EigenField>(
    pf: &PairField,
    k: &F,
    comp: &super::Component<F>,
) -> (Matrix<NumberField>, Matrix<NumberField>) {
    let f = &pf.field;
    let v = &comp.chains;
    let (n, m) = (v.nrows(), v.ncols());
    let mut t = Matrix::zeros(f.clone(), n, 2 * m);
    for r in 0..n {
        for q in 0..m {
            let (re, im) = pf.re_im(k, v.get(r, q));
            t.set(r, 2 * q, re);
            t.set(r, 2 * q + 1, im);
        }
    }
    let (a, b) = pf.re_im(k, &comp.root_elem());
    (t, pair_block(f, &a, &b, &comp.blocks))
}

/// Approximations of the real columns $[\operatorname{Re} v, \operatorname{Im} v]$ (from the
/// complex embedding) and of the pair blocks.
fn pair_approx<F: Field>(
    field: &Ext<F>,
    v: &Matrix<Ext<F>>,
    (a, b): (f64, f64),
    blocks: &[usize],
) -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let (n, m) = (v.nrows(), v.ncols());
    let mut t = vec![vec![0.0; 2 * m]; n];
    for (r, row) in t.iter_mut().enumerate() {
        for q in 0..m {
            let (re, im) = field.approx(v.get(r, q));
            row[2 * q] = re;
            row[2 * q + 1] = im;
        }
    }
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
    (t, j)
}

impl RealJordanForm<Q> {
    /// $J$ and $T$ over one real field when all blocks are exact in the same field.
    pub fn single_field(&self) -> Option<(Matrix<NumberField>, Matrix<NumberField>)> {
        let mut field = super::primary::rational_field();
        for b in &self.blocks {
            let (f, _, _) = b.exact_entries()?;
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
            let (_, bt, bj) = b.exact_entries()?;
            let w = bt.ncols();
            t.set_block(0, off, &bt.map(&field, |x| x.clone()));
            j.set_block(off, off, &bj.map(&field, |x| x.clone()));
            off += w;
        }
        Some((j, t))
    }
}
