//! Connection by a routing: the parts side by side ($\mathrm{diag}$, [`super::append`]),
//! then $u = K y + E r$ (subsystem inputs from subsystem outputs and external inputs) and
//! $z = F y$ (external outputs), with 0/1 routing matrices made from signal names by the
//! caller. With $M = (I - D K)^{-1}$ (the algebraic loop; singular: ill-posed):
//! $y = M C x + M D E r$, so
//! $A_c = A + B K M C$, $B_c = B (I + K M D) E$, $C_c = F M C$, $D_c = F M D E$.
//! The check ([`routing_holds`]) evaluates both sides at points: the closed loop's
//! $G_c(s_0)$ equals $F (I - G(s_0) K)^{-1} G(s_0) E$ with $G$ the appended parts.

use super::super::StateSpace;
use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;

/// The routing of a connection: `k` ($m \times p$), `e` ($m \times r$), `f` ($q \times p$)
/// for a system with $m$ inputs and $p$ outputs.
#[derive(Clone, Debug)]
pub struct Routing<K: Field> {
    pub k: Matrix<K>,
    pub e: Matrix<K>,
    pub f: Matrix<K>,
}

/// The system closed by `r` (see the module documentation).
///
/// # Errors
/// `Shape` when the routing does not fit; `IllPosed` when $I - D K$ is singular.
pub fn close<K: Field>(s: &StateSpace<K>, r: &Routing<K>) -> Result<StateSpace<K>> {
    let (m, p) = (s.ninputs(), s.noutputs());
    r.k.check_shape("connect K", (m, p))?;
    if r.e.nrows() != m || r.f.ncols() != p {
        return Err(Error::Shape {
            op: "connect E, F",
            expected: (m, p),
            found: (r.e.nrows(), r.f.ncols()),
        });
    }
    let k = s.field().clone();
    let loop_ = &Matrix::identity(k.clone(), p) - &(&s.d * &r.k);
    let mi = match loop_.inverse() {
        Ok(x) => x,
        Err(Error::Singular) => {
            return Err(Error::IllPosed(
                "I - D K is singular: the algebraic loop has no unique solution".into(),
            ));
        }
        Err(e) => return Err(e),
    };
    let mc = &mi * &s.c;
    let md = &mi * &s.d;
    let a = &s.a + &(&(&s.b * &r.k) * &mc);
    let inner = &Matrix::identity(k, m) + &(&r.k * &md);
    let b = &(&s.b * &inner) * &r.e;
    let c = &r.f * &mc;
    let d = &(&r.f * &md) * &r.e;
    StateSpace::new(a, b, c, d)
}

/// At each of `points` where both sides are defined: $G_c(s_0) = F (I - G(s_0) K)^{-1}
/// G(s_0) E$ exactly.
pub fn routing_holds<K: Field>(
    s: &StateSpace<K>,
    r: &Routing<K>,
    closed: &StateSpace<K>,
    points: &[K::Elem],
) -> bool {
    let k = s.field().clone();
    let at = |sys: &StateSpace<K>, z: &K::Elem| {
        let n = sys.nstates();
        let shifted = &Matrix::identity(k.clone(), n).scale(z) - &sys.a;
        shifted
            .inverse()
            .ok()
            .map(|x| &sys.d + &(&(&sys.c * &x) * &sys.b))
    };
    points.iter().all(|z| {
        let (Some(g), Some(gc)) = (at(s, z), at(closed, z)) else {
            return true;
        };
        let lhs = &Matrix::identity(k.clone(), g.nrows()) - &(&g * &r.k);
        match lhs.inverse() {
            Ok(li) => gc == &(&(&r.f * &li) * &g) * &r.e,
            Err(_) => true,
        }
    })
}
