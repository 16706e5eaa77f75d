//! Minimal realization by every exact method, the Kalman decomposition and the PBH tests over
//! Q, Q(sqrt 2), Q(i) and Q(p) from one generic function (issue 23, "Done when": each operation
//! tested over the four fields from one generic test).
//!
//! The generator plants a non-minimal system: `A = T blockdiag(A_co, A_cu, A_uo, A_uu) T^-1`
//! with `B = T [B_co; B_cu; 0; 0]` and `C = [C_co, 0, C_uo, 0] T^-1` (the parts controllable
//! and observable, controllable only, observable only, neither), `T` unimodular, so the
//! McMillan degree is at most `dim A_co` and every method must drop the other parts. Asserted,
//! recomputed here:
//!
//! * every method of `realization::minimal` (Kalman, Rosenbrock, Ho-Kalman, Jordan): Markov
//!   parameters `C A^k B` (`k < 2n + 2`) and `D` equal, order = McMillan degree (Hankel rank),
//!   the result controllable and observable;
//! * the Kalman decomposition: `A T = T A~`, `B = T B~`, `C T = C~`, the zero blocks of its
//!   four parts, dimensions = ranks of the controllability and observability matrices;
//! * PBH (`rank [A - lambda I, B] = n` per eigenvalue, in the eigenvalue's field) agrees with
//!   the rank of the controllability matrix, and dually for observability.

use crate::common::{self, Rng};
use exactlti::field::Field;
use exactlti::matrix::Matrix;
use exactlti::realization::{
    MinrealMethod, SystemField, controllability_matrix, is_controllable, is_observable,
    kalman_decomposition, mcmillan_degree, minimal, observability_matrix, pbh_controllable,
    pbh_observable,
};
use exactlti::system::StateSpace;

/// A random square block of size `n` over `k` (entries `c + s g`).
fn block<F: Field>(k: &F, g: &Option<F::Elem>, n: usize, rng: &mut Rng) -> Matrix<F> {
    common::random_matrix(k, g, n, n, rng)
}

/// The planted system of the module docs; returns it with the planted part sizes.
fn planted<F: Field>(k: &F, g: &Option<F::Elem>, rng: &mut Rng) -> (StateSpace<F>, [usize; 4]) {
    let dims = [
        rng.int(1, 3) as usize,
        rng.int(0, 1) as usize,
        rng.int(0, 1) as usize,
        rng.int(0, 1) as usize,
    ];
    let n: usize = dims.iter().sum();
    let (m, p) = (rng.int(1, 2) as usize, rng.int(1, 2) as usize);
    let blocks: Vec<Matrix<F>> = dims.iter().map(|&d| block(k, g, d, rng)).collect();
    let a0 = Matrix::block_diag(k.clone(), &blocks);
    let controllable = dims[0] + dims[1];
    let b_top = common::random_matrix(k, g, controllable, m, rng);
    let b0 = b_top
        .vstack(&Matrix::zeros(k.clone(), n - controllable, m))
        .unwrap();
    let c0 = Matrix::from_fn(k.clone(), p, n, |_, j| {
        let observable = j < dims[0] || (j >= controllable && j < controllable + dims[2]);
        if observable {
            common::elem(k, g, rng)
        } else {
            k.zero()
        }
    });
    let d = common::random_matrix(k, g, p, m, rng);
    let t = common::unimodular(k, n, rng);
    let sys = StateSpace::new(a0, b0, c0, d)
        .unwrap()
        .transform(&t)
        .unwrap();
    (sys, dims)
}

fn check_all<F: SystemField>(k: &F, g: &Option<F::Elem>, seed: u64, cases: usize) {
    let mut rng = Rng(seed);
    for _ in 0..cases {
        let (sys, dims) = planted(k, g, &mut rng);
        let n = sys.nstates();
        let mcm = mcmillan_degree(&sys);
        assert!(
            mcm <= dims[0],
            "McMillan degree at most the planted minimal part"
        );
        // every exact method
        for method in [
            MinrealMethod::Kalman,
            MinrealMethod::Rosenbrock,
            MinrealMethod::HoKalman,
            MinrealMethod::Jordan,
        ] {
            let r = minimal(&sys, method).unwrap();
            assert_eq!(r.order, mcm, "{method:?}: order = McMillan degree");
            assert_eq!(r.system.nstates(), mcm, "{method:?}");
            assert!(
                r.system.same_markov(&sys, 2 * n + 2),
                "{method:?}: Markov parameters"
            );
            assert_eq!(r.system.d, sys.d, "{method:?}: D");
            assert!(is_controllable(&r.system.a, &r.system.b), "{method:?}");
            assert!(is_observable(&r.system.a, &r.system.c), "{method:?}");
        }
        // the Kalman decomposition
        let kd = kalman_decomposition(&sys).unwrap();
        let (t, s) = (&kd.t, &kd.system);
        assert_eq!(&sys.a * t, t * &s.a, "A T = T A~");
        assert_eq!(sys.b, t * &s.b, "B = T B~");
        assert_eq!(&sys.c * t, s.c, "C T = C~");
        assert_eq!(kd.dims.iter().sum::<usize>(), n);
        let rc = controllability_matrix(&sys.a, &sys.b).rank();
        let ro = observability_matrix(&sys.a, &sys.c).rank();
        assert_eq!(kd.dims[0] + kd.dims[1], rc, "controllable dimension");
        assert_eq!(kd.dims[1] + kd.dims[3], ro, "observable dimension");
        assert_eq!(kd.dims[1], mcm, "minimal part");
        // parts in the order (co-unobs, co-obs, unco-unobs, unco-obs): B~ zero below the
        // controllable rows, C~ zero on the unobservable columns, A~ zero below-left of the
        // controllable block
        let ctrl = kd.dims[0] + kd.dims[1];
        for i in ctrl..n {
            for j in 0..sys.ninputs() {
                assert!(k.is_zero(s.b.get(i, j)), "B~ uncontrollable rows zero");
            }
            for j in 0..ctrl {
                assert!(k.is_zero(s.a.get(i, j)), "A~ block triangular");
            }
        }
        let unobs: Vec<usize> = (0..kd.dims[0]).chain(ctrl..ctrl + kd.dims[2]).collect();
        for i in 0..sys.noutputs() {
            for &j in &unobs {
                assert!(k.is_zero(s.c.get(i, j)), "C~ unobservable columns zero");
            }
        }
        // PBH against the ranks
        assert_eq!(
            pbh_controllable(&sys.a, &sys.b).unwrap(),
            rc == n,
            "PBH ctrb"
        );
        assert_eq!(pbh_observable(&sys.a, &sys.c).unwrap(), ro == n, "PBH obsv");
    }
}

crate::for_each_field!(check_all, 2711, 8, 3; realization_every_method_over_q,
    realization_every_method_over_q_sqrt2, realization_every_method_over_q_i,
    realization_every_method_over_q_p);
