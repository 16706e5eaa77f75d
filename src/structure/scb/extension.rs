//! Beyond the paper (its sec. VI): transform $x_c$ so that the influence of $x_a$ is matched
//! with the input $u_c$, i.e. $A_{ca} = B_c E_{ca}$.
//!
//! With $x_c' = x_c + M x_a$ the $(c, a)$ block becomes $A_{ca} + M A_{aa} - A_{cc} M$; we solve
//! $A_{cc} M - M A_{aa} + B_c E = A_{ca}$ for $(M, E)$ (always solvable when $(A_{cc}, B_c)$ is
//! controllable: pick $F$ with $\sigma(A_{cc} + B_c F) \cap \sigma(A_{aa}) = \emptyset$), as one
//! linear system in $\mathrm{vec}(M), \mathrm{vec}(E)$, taking the canonical particular
//! solution. Then $\Gamma_1' = \Gamma_1 T^{-1}$ with $T = I + (\text{block } M \text{ at } (c, a))$.

use super::Scb;
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

impl<K: Field> Scb<K> {
    /// The same SCB with $x_c$ replaced by $x_c + M x_a$ so that $A_{ca} = B_c E_{ca}$
    /// (sec. VI's future step). Returns the new SCB and $E_{ca}$.
    ///
    /// # Errors
    /// `Verification` if the result fails the exact checks (internal error).
    pub fn match_x_c(&self) -> Result<(Scb<K>, Matrix<K>)> {
        let k = self.a.field().clone();
        let [ra, _, rc, _] = self.ranges();
        let (na, nc) = (ra.len(), rc.len());
        let md = self.chains.len();
        let mc = self.b.ncols() - self.m0 - md;
        let aaa = self.a.submatrix(ra.start, ra.end, ra.start, ra.end);
        let acc = self.a.submatrix(rc.start, rc.end, rc.start, rc.end);
        let aca = self.a.submatrix(rc.start, rc.end, ra.start, ra.end);
        let bc = self
            .b
            .submatrix(rc.start, rc.end, self.m0 + md, self.b.ncols());
        if na == 0 || nc == 0 {
            return Ok((self.clone(), Matrix::zeros(k, mc, na)));
        }
        // vec (column-major): vec(A_cc M) = (I ⊗ A_cc) vec M, vec(M A_aa) = (A_aa^T ⊗ I) vec M
        let ia = Matrix::identity(k.clone(), na);
        let ic = Matrix::identity(k.clone(), nc);
        let lhs_m = &ia.kron(&acc) - &aaa.transpose().kron(&ic);
        let lhs_e = ia.kron(&bc);
        let lhs = lhs_m.hstack(&lhs_e)?;
        let rhs = aca.vec();
        let (sol, _) = lhs
            .solve(&rhs)?
            .ok_or_else(|| Error::Verification("A_ca could not be matched with B_c".into()))?;
        let mm = sol.submatrix(0, nc * na, 0, 1).unvec(nc, na)?;
        let e = sol
            .submatrix(nc * na, nc * na + mc * na, 0, 1)
            .unvec(mc, na)?;
        let n = self.nstates();
        let mut t = Matrix::identity(k.clone(), n); // x' = T x
        t.set_block(rc.start, ra.start, &mm);
        let tinv = t.inverse()?;
        let mut s = self.clone();
        s.a = &(&t * &self.a) * &tinv;
        s.zero_poly = std::sync::OnceLock::new(); // A changed
        s.b = &t * &self.b;
        s.c = &self.c * &tinv;
        s.gamma1 = &self.gamma1 * &tinv;
        s.verified = false;
        s.check()?;
        s.verified = true;
        Ok((s, e))
    }
}
