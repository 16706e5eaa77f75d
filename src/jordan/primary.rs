//! One primary component per irreducible factor $p$ of the characteristic polynomial.
//!
//! All roots $\theta_1, \dots, \theta_d$ of $p$ are handled at once in
//! $K = \mathbb{Q}\[t\]/(p)$: the chains $V(t)$, $W(t)$ computed for the generic root $t$
//! give, under each embedding $t \mapsto \theta_j$, the chains of $\theta_j$ (Galois
//! conjugation), so nothing is recomputed per root. A rational eigenvalue ($\deg p = 1$)
//! is computed directly over $\mathbb{Q}$.
//!
//! When the factor's generalized eigenspace is smaller than $A$ ($dm < n$, $n \ge 8$) the chains
//! are computed for the restriction of $A$ to it, found over $\mathbb{Q}$ (`restrict`).
//!
//! Identities checked exactly in $K$: $A V = V J_t$, $W A = J_t W$, $W V = I_m$.

use super::chains::{Chains, jordan_block_matrix, jordan_chains, mul};
use crate::algebraic::{Ext, ExtElem, NumberField};
use crate::error::Result;
use crate::field::{Field, Q};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// The data of one irreducible factor $p \in F\[x\]$ of $\chi_A$, in $E = F\[t\]/(p)$ (over
/// $\mathbb{Q}$: [`PrimaryComponent`], over $\mathbb{Q}(\sqrt d)$:
/// `Component<QuadraticField>`).
#[derive(Clone, Debug, PartialEq)]
pub struct Component<F: Field> {
    /// The monic irreducible factor $p$.
    pub factor: Poly<F>,
    /// The minimal polynomial over $\mathbb{Q}$ of its roots ($p$ itself over $\mathbb{Q}$);
    /// `None` over $\mathbb{Q}(p)$, whose roots are functions of the parameters.
    pub minpoly: Option<Poly<Q>>,
    /// Multiplicity of $p$ in $\chi_A$ = algebraic multiplicity of each root.
    pub multiplicity: usize,
    /// $E = F\[t\]/(p)$, marked at `roots[0]`.
    pub field: Ext<F>,
    /// Approximations of the roots $\theta_j$ (real part descending); the embedding
    /// $t \mapsto \theta_j$ carries the chains to the root $\theta_j$ (empty over
    /// $\mathbb{Q}(p)$).
    pub roots: Vec<(f64, f64)>,
    /// Jordan block sizes of each root, largest first.
    pub blocks: Vec<usize>,
    /// $\dim \ker (A - t I)^k$, $k = 1, \dots$ (over $E$).
    pub kernel_dims: Vec<usize>,
    /// Right chains $V$ ($n \times m$) over $E$: $A V = V J_t$ ($n \times 0$ for a factor
    /// of degree $\ge 2$ of [`super::jordan_qp`], which keeps its primary block:
    /// [`Component::has_chains`]).
    pub chains: Matrix<Ext<F>>,
    /// Left chains $W$ ($m \times n$) over $E$: $W A = J_t W$, $W V = I$.
    pub left_chains: Matrix<Ext<F>>,
    /// The generalized eigenspace over $F$ when it was computed ([`restrict`]): the
    /// primary-block presentation of the factor ([`super::JordanForm::primary_form`]).
    pub restriction: Option<Restriction<F>>,
}

/// A component over $\mathbb{Q}$: $K = \mathbb{Q}\[t\]/(p)$.
pub type PrimaryComponent = Component<Q>;

impl<F: Field> Component<F> {
    /// The chains over $E$ were computed (always but for a factor of degree $\ge 2$ of the
    /// primary form over $\mathbb{Q}(p)$, [`super::jordan_qp`]).
    pub fn has_chains(&self) -> bool {
        self.chains.ncols() == self.multiplicity
    }
    /// Degree of the factor (number of conjugate eigenvalues over $F$).
    pub fn degree(&self) -> usize {
        self.factor.deg()
    }
    /// The generic root $t \in E$ (for $\deg p = 1$ the root itself).
    pub fn root_elem(&self) -> ExtElem<F::Elem> {
        self.field.generator()
    }
    /// Geometric multiplicity of each root (number of blocks).
    pub fn geometric_multiplicity(&self) -> usize {
        self.blocks.len()
    }
    /// $J_t$ over $E$ ($m \times m$).
    pub fn jordan_matrix(&self) -> Matrix<Ext<F>> {
        jordan_block_matrix(&self.field, &self.root_elem(), &self.blocks)
    }
    /// The same field marked at root `j` (the embedding $t \mapsto \theta_j$) with display
    /// variable `var`.
    pub fn embedding(&self, j: usize, var: &str) -> Ext<F> {
        self.field.marked(self.roots[j], var, None)
    }
    /// `a` with entries in $E \supset F$.
    pub fn lift(&self, a: &Matrix<F>) -> Matrix<Ext<F>> {
        a.map(&self.field, |x| self.field.from_base(x))
    }
    /// Exact check of $A V = V J_t$, $W A = J_t W$ and $W V = I$: for a simple factor of
    /// degree $\ge 2$ on coefficient matrices over $F$ ([`super::coeffs::verify_simple`]),
    /// for a linear factor over $F$ itself (the field's product kernel), else in $E$.
    pub fn verify(&self, a: &Matrix<F>) -> bool {
        let v = &self.chains;
        let w = &self.left_chains;
        if self.multiplicity == 1 && self.degree() >= 2 {
            return super::coeffs::verify_simple(&self.field, v, w, a);
        }
        if v.nrows() != a.nrows() || v.ncols() != self.multiplicity {
            return false;
        }
        if self.degree() == 1 {
            let k = a.field();
            let to_base = |m: &Matrix<Ext<F>>| -> Option<Matrix<F>> {
                let mut out = Matrix::zeros(k.clone(), m.nrows(), m.ncols());
                for i in 0..m.nrows() {
                    for j in 0..m.ncols() {
                        out.set(i, j, self.field.to_base(m.get(i, j))?);
                    }
                }
                Some(out)
            };
            let (Some(vf), Some(wf), Some(jf)) =
                (to_base(v), to_base(w), to_base(&self.jordan_matrix()))
            else {
                return false;
            };
            return mul(a, &vf) == mul(&vf, &jf)
                && mul(&wf, a) == mul(&jf, &wf)
                && mul(&wf, &vf).is_identity();
        }
        let ak = self.lift(a);
        let j = self.jordan_matrix();
        &ak * v == v * &j && w * &ak == &j * w && (w * v).is_identity()
    }
}

/// A number field $\mathbb{Q}[x]/(m)$ marked at `root`, displayed with variable `var`.
pub(crate) fn named_field(m: &Poly<Q>, root: (f64, f64), var: &str) -> NumberField {
    NumberField::with_var(m, root, var)
}

/// $\mathbb{Q}$ as a number field of degree 1 (modulus $x$).
pub(crate) fn rational_field() -> NumberField {
    named_field(&Poly::x(Q), (0.0, 0.0), "t")
}

/// The generalized eigenspace of a factor over $F$: `u` ($n \times dm$) spans
/// $\ker p(A)^m$, $A u = u\,A_p$, and `proj` $= (L^T u)^{-1} L^T$ with $L$ spanning the
/// left space $\ker (p(A)^m)^T$ (so `proj u = I` and `proj A = A_p proj`). Over
/// $\mathbb{Q}(p)$, $A_p$ is the primary block of the factor (the presentation of a factor
/// of degree $\ge 2$).
#[derive(Clone, Debug, PartialEq)]
pub struct Restriction<F: Field> {
    pub u: Matrix<F>,
    pub ap: Matrix<F>,
    /// `None` when only $u$ and $A_p$ were asked for (the primary form needs no projector:
    /// the left null space is a second elimination of $p(A)^m$, half the cost over
    /// $\mathbb{Q}(p)$).
    pub proj: Option<Matrix<F>>,
}

impl<F: Field> Restriction<F> {
    /// The projector (`proj u = I`).
    ///
    /// # Errors
    /// `Verification` when the restriction was computed without it.
    pub fn projector(&self) -> Result<&Matrix<F>> {
        self.proj.as_ref().ok_or_else(|| {
            crate::error::Error::Verification("restriction computed without its projector".into())
        })
    }
}

/// $p(A)^m$ for a monic `p`: $p(A)$ by Horner, then its $m$-th power.
fn power_of_poly_at<F: Field>(a: &Matrix<F>, p: &Poly<F>, m: usize) -> Matrix<F> {
    let (n, k) = (a.nrows(), a.field());
    let mut pa = Matrix::identity(k.clone(), n);
    for i in (0..p.deg()).rev() {
        let c = Matrix::identity(k.clone(), n).scale(&p.coeff(i));
        pa = mul(a, &pa).try_add(&c).expect("same shape");
    }
    let mut pm = pa.clone();
    for _ in 1..m {
        pm = mul(&pm, &pa);
    }
    pm
}

/// The rows $r_j$ with $u_{r_j} = e_j^T$, one per column (a canonical null-space basis has
/// them at the non-pivot columns of the RREF); `None` when some column has none.
fn unit_rows<F: Field>(u: &Matrix<F>) -> Option<Vec<usize>> {
    let k = u.field();
    let mut rows = vec![None; u.ncols()];
    for i in 0..u.nrows() {
        let nz: Vec<usize> = (0..u.ncols())
            .filter(|&j| !k.is_zero(u.get(i, j)))
            .collect();
        if let [j] = nz[..]
            && k.is_one(u.get(i, j))
            && rows[j].is_none()
        {
            rows[j] = Some(i);
        }
    }
    rows.into_iter().collect()
}

/// $A_p$ with $A u = u A_p$ for `u` of full column rank spanning an $A$-invariant space: the
/// unit rows of $A u$ when `u` has them ([`unit_rows`]; no elimination), else by solving;
/// $u A_p = A u$ checked exactly.
///
/// # Errors
/// `Verification` when the span of `u` is not invariant.
pub(crate) fn restriction_of<F: Field>(a: &Matrix<F>, u: &Matrix<F>) -> Result<Matrix<F>> {
    let au = mul(a, u);
    let ap = match unit_rows(u) {
        Some(rows) => Some(au.select_rows(&rows)).filter(|ap| mul(u, ap) == au),
        None => u.solve(&au)?.map(|(ap, _)| ap),
    };
    ap.ok_or_else(|| {
        crate::error::Error::Verification("the generalized eigenspace is not invariant".into())
    })
}

/// [`Restriction`] of `a` to the factor `p` of multiplicity `m` (always computed when `always`,
/// else only when it is smaller than `a` and $n \ge 8$); the projector only when `with_proj`.
///
/// Chains of $A_p$ over $E$ give those of $A$: $A (u V_p) = (u V_p) J$ and
/// $(W_p\,\mathrm{proj}) A = J\,(W_p\,\mathrm{proj})$, $(W_p \mathrm{proj})(u V_p) = W_p V_p = I$.
/// Every elimination here is over $F$ (over $\mathbb{Q}$ the multi-modular kernels), so the
/// extension field work is on a $dm \times dm$ matrix whose entries are those of a canonical
/// basis, not on $A$'s (possibly huge) entries.
///
/// # Errors
/// `Verification` when the kernel dimension is not $dm$.
pub(crate) fn restrict<F: Field>(
    a: &Matrix<F>,
    p: &Poly<F>,
    m: usize,
    always: bool,
    with_proj: bool,
) -> Result<Option<Restriction<F>>> {
    let n = a.nrows();
    let dm = p.deg() * m;
    if dm >= n || (!always && n < 8) {
        return Ok(None);
    }
    let p = p.monic();
    let pm = power_of_poly_at(a, &p, m);
    let u = pm.nullspace();
    let dim_error = |d: usize| {
        crate::error::Error::Verification(format!(
            "ker p(A)^{m} has dimension {d} for p = {p} of multiplicity {m}"
        ))
    };
    if u.ncols() != dm {
        return Err(dim_error(u.ncols()));
    }
    let ap = restriction_of(a, &u)?;
    let proj = if with_proj {
        let l = pm.transpose().nullspace();
        if l.ncols() != dm {
            return Err(dim_error(l.ncols()));
        }
        let lt = l.transpose();
        Some(mul(&mul(&lt, &u).inverse()?, &lt))
    } else {
        None
    };
    Ok(Some(Restriction { u, ap, proj }))
}

impl<F: Field + 'static> Component<F> {
    /// Computes the component of the irreducible monic `factor` (multiplicity `mult`) over
    /// $F$: for a linear factor the chains of $A - \theta I$ over $F$, else those of the
    /// restriction $A_p$ ([`restrict`]; of $A$ itself when it is not smaller) over
    /// $E = F\[t\]/(p)$. `minpoly` and `roots` as in the fields of [`Component`] (`None` and
    /// none over $\mathbb{Q}(p)$, where the roots are not numbers; $E$ is then marked at
    /// `(0, 0)`, a mark no display reads). `always_restrict`: restrict whenever the
    /// generalized eigenspace is smaller than $A$ (over $\mathbb{Q}(p)$, where the
    /// arithmetic of $E$ is the cost), else from $n \ge 8$ on.
    ///
    /// # Errors
    /// `Verification` when the multiplicity does not match the generalized eigenspace.
    pub(crate) fn compute(
        a: &Matrix<F>,
        factor: &Poly<F>,
        mult: usize,
        minpoly: Option<Poly<Q>>,
        roots: Vec<(f64, f64)>,
        always_restrict: bool,
    ) -> Result<Self> {
        let n = a.nrows();
        let k = a.field();
        let mark = roots.first().copied().unwrap_or((0.0, 0.0));
        let field = Ext::with_var(factor, mark, "t");
        let lift = |m: &Matrix<F>| m.map(&field, |x| field.from_base(x));
        if factor.deg() == 1 {
            let theta = k.neg(&factor.monic().coeff(0));
            let nm = a.try_sub(&Matrix::identity(k.clone(), n).scale(&theta))?;
            let ch = jordan_chains(&nm, mult)?;
            return Ok(Component {
                factor: factor.clone(),
                minpoly,
                multiplicity: mult,
                roots,
                blocks: ch.blocks,
                kernel_dims: ch.kernel_dims,
                chains: lift(&ch.v),
                left_chains: lift(&ch.w),
                field,
                restriction: None,
            });
        }
        let t = field.generator();
        let restriction = restrict(a, factor, mult, always_restrict, true)?;
        if mult == 1 {
            // a simple factor: Krylov chains of A_p (or of A = A_p), no elimination over E
            let (ap, chi) = match &restriction {
                Some(r) => (&r.ap, factor.monic()),
                None => (a, a.charpoly()?),
            };
            let (v, w) = super::simple::simple_chains(ap, &chi, &field)?;
            let (v, w) = match &restriction {
                Some(r) => (mul(&lift(&r.u), &v), mul(&w, &lift(r.projector()?))),
                None => (v, w),
            };
            return Ok(Component {
                factor: factor.clone(),
                minpoly,
                multiplicity: 1,
                roots,
                blocks: vec![1],
                kernel_dims: vec![1],
                chains: v,
                left_chains: w,
                field,
                restriction,
            });
        }
        let (blocks, kernel_dims, v, w) = match &restriction {
            // chains of the restriction A_p (dm x dm) instead of the n x n matrix over E
            Some(r) => {
                let nm = lift(&r.ap)
                    .try_sub(&Matrix::identity(field.clone(), r.ap.nrows()).scale(&t))?;
                let ch = jordan_chains(&nm, mult)?;
                (
                    ch.blocks,
                    ch.kernel_dims,
                    mul(&lift(&r.u), &ch.v),
                    mul(&ch.w, &lift(r.projector()?)),
                )
            }
            None => {
                let nm = lift(a).try_sub(&Matrix::identity(field.clone(), n).scale(&t))?;
                let Chains {
                    blocks,
                    kernel_dims,
                    v,
                    w,
                } = jordan_chains(&nm, mult)?;
                (blocks, kernel_dims, v, w)
            }
        };
        Ok(Component {
            factor: factor.clone(),
            minpoly,
            multiplicity: mult,
            roots,
            blocks,
            kernel_dims,
            chains: v,
            left_chains: w,
            field,
            restriction,
        })
    }
}

impl<F: Field + 'static> super::JordanForm<F> {
    /// $T$ and $J$ over $F$ itself, $A T = T J$: for a linear factor its chains and Jordan
    /// blocks; for a factor $g$ of degree $\ge 2$ and multiplicity $e$ a basis of
    /// $\ker g(A)^e$ and the restriction of $A$ to it (the primary block, [`restrict`]; kept
    /// from the component's computation when it was made). Over $\mathbb{Q}(p)$ this is the
    /// presentation of [`super::jordan_qp`].
    ///
    /// # Errors
    /// `Verification` when a kernel contradicts a multiplicity.
    pub fn primary_form(&self) -> Result<(Matrix<F>, Matrix<F>)> {
        let k = self.base();
        let (a, n) = (&self.a, self.n());
        let mut cols: Vec<Matrix<F>> = vec![];
        let mut blocks: Vec<Matrix<F>> = vec![];
        for c in &self.components {
            if c.degree() == 1 {
                let theta = k.neg(&c.factor.monic().coeff(0));
                let e = &c.field;
                cols.push(c.chains.map(k, |x| e.to_base(x).expect("degree 1")));
                blocks.push(jordan_block_matrix(k, &theta, &c.blocks));
                continue;
            }
            let r = match &c.restriction {
                Some(r) => Some(r.clone()),
                None => restrict(a, &c.factor, c.multiplicity, true, false)?,
            };
            match r {
                Some(r) => {
                    cols.push(r.u);
                    blocks.push(r.ap);
                }
                // the generalized eigenspace is the whole space
                None => {
                    cols.push(Matrix::identity(k.clone(), n));
                    blocks.push(a.clone());
                }
            }
        }
        let width: usize = cols.iter().map(|c| c.ncols()).sum();
        let mut t = Matrix::zeros(k.clone(), n, width);
        let mut c0 = 0;
        for c in &cols {
            t.set_block(0, c0, c);
            c0 += c.ncols();
        }
        Ok((t, Matrix::block_diag(k.clone(), &blocks)))
    }
}
