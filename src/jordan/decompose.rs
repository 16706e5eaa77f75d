//! The Jordan decomposition written once for every base field $F$ that can factor
//! $\chi_A$ and certify the roots of its factors ([`EigenField`]: $\mathbb{Q}$,
//! $\mathbb{Q}(\sqrt d)$, $\mathbb{Q}(i)$).
//!
//! For $A \in F^{n \times n}$ with $\chi_A = \prod_g g^{e_g}$ ($g$ monic irreducible over $F$)
//! each factor gets one [`Component`] in $E = F\[t\]/(g)$: $A V = V J_t$, $W A = J_t W$,
//! $W V = I$, checked exactly ([`Component::verify`]); the eigenvalues are the roots of the
//! factors as certified algebraic numbers (minimal polynomial over $\mathbb{Q}$ and an
//! isolating region), and the dimensions must add up to $n$.

use super::chains::{Chains, jordan_chains};
use super::over_k::eigen::{self, CertifiedRoots};
use super::primary::Component;
use super::{Eigenvalue, JordanForm, roots, simple};
use crate::algebraic::Ext;
use crate::error::Result;
use crate::field::{Field, Q, QuadraticField};
use crate::matrix::Matrix;
use crate::poly::Poly;

/// One irreducible factor $g$ over $F$, its multiplicity, the minimal polynomial over
/// $\mathbb{Q}$ of its roots and the certified roots of $g$ (real part descending).
pub type FactorRoots<F> = (Poly<F>, usize, Poly<Q>, CertifiedRoots);

/// A base field of the exact Jordan decomposition: it factors polynomials and certifies
/// the roots of each factor; the component of a factor has a generic default.
pub trait EigenField: Field + 'static {
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
        minpoly,
        multiplicity: e,
        field,
        roots,
        blocks,
        kernel_dims,
        chains: v,
        left_chains: w,
    })
}

impl EigenField for Q {
    fn eigen_factors(chi: &Poly<Q>) -> Result<Vec<FactorRoots<Q>>> {
        let mut out = vec![];
        for (p, e) in roots::factor_q(chi)? {
            let rts = roots::certified_roots(&p)?;
            out.push((p.clone(), e, p, rts));
        }
        Ok(out)
    }
    /// Over $\mathbb{Q}$ a repeated factor goes through the rational restriction to its
    /// generalized eigenspace ([`super::PrimaryComponent::compute`]).
    fn component(
        a: &Matrix<Q>,
        chi: &Poly<Q>,
        (g, e, minpoly): (&Poly<Q>, usize, Poly<Q>),
        roots: Vec<(f64, f64)>,
    ) -> Result<Component<Q>> {
        if e == 1 && g.deg() >= 2 {
            generic_component(a, chi, (g, e, minpoly), roots)
        } else {
            Component::compute(a, g, e, roots)
        }
    }
}

impl EigenField for QuadraticField {
    fn eigen_factors(chi: &Poly<QuadraticField>) -> Result<Vec<FactorRoots<QuadraticField>>> {
        let mut out = vec![];
        if chi.deg() == 0 {
            return Ok(out);
        }
        for (g, e) in eigen::factor_over_k(chi)? {
            let (m, roots) = eigen::roots_of_factor(&g)?;
            out.push((g, e, m, roots));
        }
        Ok(out)
    }
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
        for (j, (number, z)) in certified.into_iter().enumerate() {
            let k = eigenvalues.len() + 1;
            eigenvalues.push(Eigenvalue {
                minpoly: m.clone(),
                value: roots::value_string(&m, z),
                approx: z,
                number,
                component: ci,
                root: j,
                symbol: format!("r{k}"),
                algebraic_multiplicity: e,
                geometric_multiplicity: c.geometric_multiplicity(),
                blocks: c.blocks.clone(),
            });
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
        verified,
    })
}
