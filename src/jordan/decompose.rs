//! The Jordan decomposition written once for every base field $F$ that can factor
//! $\chi_A$ and certify the roots of its factors ([`EigenField`]: $\mathbb{Q}$,
//! $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$).
//!
//! For $A \in F^{n \times n}$ with $\chi_A = \prod_g g^{e_g}$ ($g$ monic irreducible over $F$)
//! each factor gets one [`Component`] in $E = F\[t\]/(g)$: $A V = V J_t$, $W A = J_t W$,
//! $W V = I$, checked exactly ([`Component::verify`]); the eigenvalues are the roots of the
//! factors as certified algebraic numbers (minimal polynomial over $\mathbb{Q}$ and an
//! isolating region), and the dimensions must add up to $n$.
//!
//! What differs between base fields is a method of [`EigenField`], never a copy of the
//! algorithm: the factorization with certified roots, the exact field of one eigenvalue
//! ([`EigenField::root_field`]) and, for the real forms, whether the field is real and the
//! real field of a complex pair ([`EigenField::real_pair`]); the implementations for
//! $\mathbb{Q}$ and the quadratic fields are in `fields.rs`.

use super::chains::{Chains, jordan_chains};
use super::eigenvalue::{Certified, Eigenvalue, NumberEigen};
use super::pair_field::{PairField, RealEmbed};
use super::primary::Component;
use super::{Embedding, JordanForm, simple};
use crate::algebraic::{AlgebraicNumber, Ext};
use crate::error::Result;
use crate::field::{Field, Q};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// Certified roots with their approximations.
pub type CertifiedRoots = Vec<(AlgebraicNumber, (f64, f64))>;

/// One irreducible factor $g$ over $F$, its multiplicity, the minimal polynomial over
/// $\mathbb{Q}$ of its roots and the certified roots of $g$ (real part descending).
pub type FactorRoots<F> = (Poly<F>, usize, Poly<Q>, CertifiedRoots);

/// A number field as base field of the exact Jordan decomposition: it factors polynomials
/// and certifies the roots of each factor (its eigenvalues are certified algebraic numbers,
/// [`NumberEigen`]); the component of a factor has a generic default. Every base field,
/// $\mathbb{Q}(p)$ included, is a [`super::JordanField`], whose [`JordanForm`] carries the
/// eigenvalue list as values ([`super::eigenvalue`]); over $\mathbb{Q}(p)$ there is no
/// embedding into a number field (its elements are functions of the parameters), so the
/// real-embedding questions are the typed answers of [`super::Eigenvalue::is_real`] and
/// [`super::Eigenvalue::re_sign`], not a [`RealEmbed`].
pub trait EigenField: RealEmbed + NumberEigen + 'static {
    /// The irreducible factors of the monic `chi` over the field with their roots.
    ///
    /// # Errors
    /// Those of the factorization and of root isolation.
    fn eigen_factors(chi: &Poly<Self>) -> Result<Vec<FactorRoots<Self>>>;
    /// The component of the factor `g` of multiplicity `e` of `chi` $= \chi_A$.
    ///
    /// # Errors
    /// `Verification` if an internal identity fails.
    fn component(
        a: &Matrix<Self>,
        chi: &Poly<Self>,
        (g, e, minpoly): (&Poly<Self>, usize, Poly<Q>),
        roots: Vec<(f64, f64)>,
    ) -> Result<Component<Self>> {
        generic_component(a, chi, (g, e, minpoly), roots)
    }
    /// The exact field of eigenvalue `ev` of `jf` (marked at that root, displayed with the
    /// eigenvalue's symbol or its radical) and the embedding $t \mapsto \theta_j$ of the
    /// component field into it.
    fn root_field(jf: &JordanForm<Self>, ev: usize) -> (Ext<Self>, Embedding<'_, Self>) {
        let e = &jf.eigenvalues[ev];
        let c = &jf.components[e.component];
        let radical = match c
            .minpoly
            .as_ref()
            .filter(|m| c.factor.deg() == 2 && m.deg() == 2)
        {
            Some(m) => super::roots::quadratic_roots(m).map(|(a0, s, f)| {
                let positive = if num_traits::Signed::is_negative(&f) {
                    e.approx.1 > 0.0
                } else {
                    e.approx.0 > crate::field::rational_to_f64(&a0)
                };
                (a0, if positive { s } else { -s }, f)
            }),
            None => None,
        };
        (
            c.field.marked(e.approx, &e.symbol(), radical),
            Box::new(|x| x.clone()),
        )
    }
    /// The real field of the complex pair of eigenvalue `ev` of `jf` (the upper root);
    /// `None` when it is not built (it may be large and `expand` is false, or the pair is
    /// written with its radical).
    ///
    /// # Errors
    /// Why the field was not found (the pair then stays compact, with a note).
    fn real_pair(jf: &JordanForm<Self>, ev: usize, expand: bool) -> Result<Option<PairField>>;
}

/// The chains of one factor in $E = F\[t\]/(g)$: Krylov vectors for a simple factor of
/// degree $\ge 2$ ([`simple::simple_chains`]), else the kernels of $(A - tI)^k$.
///
/// # Errors
/// Those of the chain computations.
pub fn generic_component<F: Field + 'static>(
    a: &Matrix<F>,
    chi: &Poly<F>,
    (g, e, minpoly): (&Poly<F>, usize, Poly<Q>),
    roots: Vec<(f64, f64)>,
) -> Result<Component<F>> {
    let n = a.nrows();
    let field = Ext::with_var(g, roots[0], "t");
    let Chains {
        blocks,
        kernel_dims,
        v,
        w,
    } = if e == 1 && g.deg() >= 2 {
        let (v, w) = simple::simple_chains(a, chi, &field)?;
        Chains {
            blocks: vec![1],
            kernel_dims: vec![1],
            v,
            w,
        }
    } else {
        let t = field.generator();
        let lifted = a.map(&field, |x| field.from_base(x));
        jordan_chains(
            &lifted.try_sub(&Matrix::identity(field.clone(), n).scale(&t))?,
            e,
        )?
    };
    Ok(Component {
        factor: g.clone(),
        minpoly: Some(minpoly),
        multiplicity: e,
        field,
        roots,
        blocks,
        kernel_dims,
        chains: v,
        left_chains: w,
        restriction: None,
    })
}

/// The eigenvalues of $A$ without chains: $\chi_A$ and, per irreducible factor $g$ over
/// the field (multiplicity $e$), $g$, $e$, the minimal polynomial over $\mathbb{Q}$ and the
/// certified roots of $g$.
///
/// # Errors
/// `NotSquare`; those of the factorization and root isolation.
pub fn eigenvalues_over<F: EigenField>(a: &Matrix<F>) -> Result<(Poly<F>, Vec<FactorRoots<F>>)> {
    a.check_square("jordan")?;
    let chi = a.charpoly()?;
    let out = F::eigen_factors(&chi)?;
    Ok((chi, out))
}

/// The exact Jordan decomposition of a square matrix over an [`EigenField`] (module docs).
///
/// # Errors
/// `NotSquare`; those of the factorization and root isolation; `Verification` if an
/// internal identity fails.
pub fn jordan_over<F: EigenField>(a: &Matrix<F>) -> Result<JordanForm<F>> {
    a.check_square("jordan")?;
    let n = a.nrows();
    let chi = a.charpoly()?;
    let mut components = vec![];
    let mut eigenvalues = vec![];
    for (g, e, m, certified) in F::eigen_factors(&chi)? {
        let approx: Vec<(f64, f64)> = certified.iter().map(|z| z.1).collect();
        let c = F::component(a, &chi, (&g, e, m.clone()), approx)?;
        let ci = components.len();
        for (j, (number, approx)) in certified.into_iter().enumerate() {
            let k = eigenvalues.len() + 1;
            let root = Certified {
                minpoly: m.clone(),
                approx,
                number,
            };
            eigenvalues.push(Eigenvalue::number(root, (ci, j, k, e, c.blocks.clone())));
        }
        components.push(c);
    }
    let dim: usize = components.iter().map(|c| c.degree() * c.multiplicity).sum();
    let verified = dim == n && components.iter().all(|c| c.verify(a));
    Ok(JordanForm {
        a: a.clone(),
        charpoly: chi,
        components,
        eigenvalues,
        conditions: vec![],
        verified,
    })
}
