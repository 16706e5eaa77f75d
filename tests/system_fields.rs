//! Every SYSTEM operation over Q, Q(sqrt 2), Q(i) and Q(p), each from one generic function
//! instantiated for the four fields (issue 23, "Done when"; the linear algebra is
//! `linalg_fields.rs`, the Jordan form `over_fields.rs`). The generator plants the answer in
//! a Kalman canonical structure and hides it behind a random change of coordinates
//! $x = T z$ ($T = L U$, unit triangular factors with entries in the field):
//!
//! * $x_{co}$: the controller form of $n(s)/d(s)$ (chosen poles and zeros, $\gcd(n, d) = 1$),
//!   $x_{c\bar o}$ (mode $\lambda_o$), $x_{\bar c o}$ ($\lambda_u$), $x_{\bar c\bar o}$
//!   ($\lambda_{uo}$), each 0 or 1 states, random couplings where the Kalman form allows them;
//! * tf: $G(s) = C(sI - A)^{-1}B + D = (n + D d)/d$ exactly, and its Markov parameters;
//!   the `tf` report (`report::sections::tf_report`, one for every field): verified, McMillan
//!   degree $\deg d$, pole polynomial $d$, the poles exactly the chosen roots of $d$ with
//!   their multiplicities, the transmission zeros' degrees summing to $\deg(n + Dd)$;
//! * minreal (Kalman, Rosenbrock, Ho-Kalman, Jordan method): order $= \deg d$ = McMillan
//!   degree, Markov parameters and $D$ equal, transfer matrix unchanged, all through the one
//!   entry point `minimal` (the Jordan method's own result kept and verified);
//! * PBH: controllable (observable) iff no uncontrollable (unobservable) mode was planted,
//!   agreeing with the rank of the controllability (observability) matrix;
//! * zeros: $\det P(s) = \pm\,\chi_{hidden}(s)\,(n + D d)(s)$, so the invariant zero
//!   polynomial is the monic $(n + Dd)\,\chi_{hidden}$ (transmission and decoupling zeros),
//!   normal rank $n + 1$; the Smith-form oracle agrees;
//! * scb: its identities (`Scb::check`), $\det(sI - A_{aa})$ = the zero polynomial, one
//!   integrator chain of the relative degree ($D = 0$) or none ($D \ne 0$);
//! * ctrb / obsv: controllable order $\deg d + n_{c\bar o}$, one index, the uncontrollable
//!   part's characteristic polynomial $(x - \lambda_u)^{n_{\bar co}}(x - \lambda_{uo})^{n_{\bar c\bar o}}$,
//!   $LB = 0$, $LA = A_{\bar c}L$; the same for $(C, A)$ by duality; the pencil $[A - sI, B]$
//!   has the controllability index as its right index and the uncontrollable modes as its
//!   finite part;
//! * pencil / standard on a descriptor system $E = P\,\mathrm{diag}(I, N)\,Q$,
//!   $A = P\,\mathrm{diag}(A_f, I)\,Q$, $B = P[B_f; B_\infty]$, $C = [C_f, C_\infty]Q$
//!   ($N = J_2(0) \oplus 0$; $x = Q^{-1}z$ gives back the block form): infinite divisors $[1, 2]$,
//!   finite part similar to $A_f$ (`pencil_structure`: the product of its Jordan factors is
//!   $\chi_{A_f}$), standard form $(A_f, B_f, C_f, D - C_\infty B_\infty)$ up
//!   to coordinates (equal transfer matrices); an output that sees $N B_\infty$ is improper
//!   (`ImproperTransfer`);
//! * mnf (`mechanical_normal_form`): a controllable single-input system of even order has a mechanical normal form
//!   ($t A t^{-1} = \tilde A$, $t B = \tilde B$, same characteristic polynomial); odd order
//!   has none (`exists = false`, the `n_even` condition).

use crate::common::{Rng, elem};
use exactlti::error::Error;
use exactlti::field::Field;
use exactlti::io::GroundField;
use exactlti::matrix::Matrix;
use exactlti::pencil::{kronecker_structure, pencil_structure};
use exactlti::poly::Poly;
use exactlti::realization::{
    JordanMethod, MinrealMethod, SystemField, controllability_matrix, controllability_structure,
    descriptor_to_standard, kalman_decomposition, mcmillan_degree, minimal, observability_matrix,
    observability_structure, pbh_controllable, pbh_observable, realize_state_space,
};
use exactlti::report::Value;
use exactlti::report::sections::tf_report;
use exactlti::structure::mechanical::mechanical_normal_form;
use exactlti::structure::scb::scb;
use exactlti::structure::zeros::{invariant_zeros, invariant_zeros_smith};
use exactlti::system::discrete::stability::Domain;
use exactlti::system::transfer::RationalFunction;
use exactlti::system::{Descriptor, StateSpace};

/// A planted system: `sys` in scrambled coordinates and the answers chosen for it.
struct Planted<F: Field> {
    sys: StateSpace<F>,
    /// $n(s)$, $d(s)$ of the controllable-observable part ($\deg n < \deg d$, coprime).
    num: Poly<F>,
    den: Poly<F>,
    /// The product of $(x - \lambda)$ over the uncontrollable modes, the unobservable ones.
    unc: Poly<F>,
    unobs: Poly<F>,
    /// The product over every hidden mode ($\chi_A / d$).
    hidden: Poly<F>,
    /// $(n_{co}, n_{c\bar o}, n_{\bar co}, n_{\bar c\bar o})$.
    dims: [usize; 4],
    /// The roots of $d$, repeated by multiplicity.
    roots: Vec<F::Elem>,
}

fn nonzero<F: Field>(k: &F, g: &Option<F::Elem>, rng: &mut Rng) -> F::Elem {
    loop {
        let x = elem(k, g, rng);
        if !k.is_zero(&x) {
            return x;
        }
    }
}

fn linear<F: Field>(k: &F, root: &F::Elem) -> Poly<F> {
    Poly::new(k.clone(), vec![k.neg(root), k.one()])
}

fn pow<F: Field>(p: &Poly<F>, e: usize) -> Poly<F> {
    (0..e).fold(Poly::one(p.field().clone()), |acc, _| acc.mul(p))
}

/// A random invertible $T = L U$ ($L$ unit lower, $U$ unit upper, entries in the field).
fn scramble<F: Field>(k: &F, g: &Option<F::Elem>, n: usize, rng: &mut Rng) -> Matrix<F> {
    let mut tri = |lower: bool| {
        Matrix::from_fn(k.clone(), n, n, |i, j| {
            if i == j {
                k.one()
            } else if (i > j) == lower && rng.int(0, 2) > 0 {
                elem(k, g, rng)
            } else {
                k.zero()
            }
        })
    };
    let l = tri(true);
    &l * &tri(false)
}

/// The controller form of `num / den` (`den` monic): ones on the superdiagonal, last row
/// $-d_i$, $B = e_n$, $C = (n_0, \dots, n_{n-1})$.
fn controller_form<F: Field>(num: &Poly<F>, den: &Poly<F>) -> [Matrix<F>; 3] {
    let k = den.field().clone();
    let n = den.deg();
    let a = Matrix::from_fn(k.clone(), n, n, |i, j| {
        if i + 1 == n {
            k.neg(&den.coeff(j))
        } else if j == i + 1 {
            k.one()
        } else {
            k.zero()
        }
    });
    let b = Matrix::from_fn(
        k.clone(),
        n,
        1,
        |i, _| {
            if i + 1 == n { k.one() } else { k.zero() }
        },
    );
    let c = Matrix::from_fn(k.clone(), 1, n, |_, j| num.coeff(j));
    [a, b, c]
}

/// `den` (1..=3 chosen poles), `num` (a non-zero constant times fewer chosen zeros, none a
/// pole).
fn planted_tf<F: Field>(
    k: &F,
    g: &Option<F::Elem>,
    rng: &mut Rng,
) -> (Poly<F>, Poly<F>, Vec<F::Elem>) {
    let n1 = rng.int(1, 3) as usize;
    let roots: Vec<F::Elem> = (0..n1).map(|_| elem(k, g, rng)).collect();
    let den = roots
        .iter()
        .fold(Poly::one(k.clone()), |acc, z| acc.mul(&linear(k, z)));
    let nz = rng.int(0, n1 as i64 - 1) as usize;
    let mut num = Poly::constant(k.clone(), nonzero(k, g, rng));
    while num.deg() < nz {
        let z = elem(k, g, rng);
        if !k.is_zero(&den.eval(&z)) {
            num = num.mul(&linear(k, &z));
        }
    }
    (num, den, roots)
}

/// The Kalman canonical structure of the module docs, scrambled by [`scramble`]; drawn
/// again when a random coupling happens to break the planted (un)controllability.
fn planted<F: Field>(k: &F, g: &Option<F::Elem>, rng: &mut Rng) -> Planted<F> {
    loop {
        let (num, den, roots) = planted_tf(k, g, rng);
        let dims = [den.deg(), rng.int(0, 1) as usize, rng.int(0, 1) as usize, {
            rng.int(0, 1) as usize
        }];
        let lams: Vec<F::Elem> = (0..3).map(|_| elem(k, g, rng)).collect();
        let n: usize = dims.iter().sum();
        let off = [0, dims[0], dims[0] + dims[1], dims[0] + dims[1] + dims[2]];
        let [a1, b1, c1] = controller_form(&num, &den);
        let mut a = Matrix::zeros(k.clone(), n, n);
        let mut b = Matrix::zeros(k.clone(), n, 1);
        let mut c = Matrix::zeros(k.clone(), 1, n);
        for i in 0..dims[0] {
            b.set(i, 0, b1.get(i, 0).clone());
            c.set(0, i, c1.get(0, i).clone());
            for j in 0..dims[0] {
                a.set(i, j, a1.get(i, j).clone());
            }
        }
        for (blk, lam) in lams.iter().enumerate() {
            if dims[blk + 1] == 1 {
                a.set(off[blk + 1], off[blk + 1], lam.clone());
            }
        }
        // the couplings the Kalman form allows: A13, A21, A23, A24, A43, B2, C3
        let allowed = |i: usize, j: usize| {
            let (bi, bj) = (block(&off, i), block(&off, j));
            matches!((bi, bj), (0, 2) | (1, 0) | (1, 2) | (1, 3) | (3, 2))
        };
        for i in 0..n {
            for j in 0..n {
                if allowed(i, j) {
                    a.set(i, j, elem(k, g, rng));
                }
            }
            match block(&off, i) {
                1 => b.set(i, 0, nonzero(k, g, rng)),
                2 => c.set(0, i, nonzero(k, g, rng)),
                _ => {}
            }
        }
        let d = Matrix::from_fn(k.clone(), 1, 1, |_, _| match rng.int(0, 2) {
            0 => elem(k, g, rng),
            _ => k.zero(),
        });
        let plain = StateSpace::new(a, b, c, d).unwrap();
        if controllability_matrix(&plain.a, &plain.b).rank() != dims[0] + dims[1]
            || observability_matrix(&plain.a, &plain.c).rank() != dims[0] + dims[2]
        {
            continue;
        }
        let hidden = |i: usize, blk: usize| pow(&linear(k, &lams[i]), dims[blk]);
        let unc = hidden(1, 2).mul(&hidden(2, 3));
        let unobs = hidden(0, 1).mul(&hidden(2, 3));
        let all = hidden(0, 1).mul(&hidden(1, 2)).mul(&hidden(2, 3));
        let t = scramble(k, g, n, rng);
        let sys = plain.transform(&t).unwrap();
        return Planted {
            sys,
            num,
            den,
            unc,
            unobs,
            hidden: all,
            dims,
            roots,
        };
    }
}

/// The Kalman block (0..4) of state `i`.
fn block(off: &[usize; 4], i: usize) -> usize {
    off.iter().rposition(|&o| o <= i).unwrap()
}

impl<F: Field> Planted<F> {
    fn d(&self) -> F::Elem {
        self.sys.d.get(0, 0).clone()
    }
    /// $n + D d$.
    fn total_num(&self) -> Poly<F> {
        self.num.add(&self.den.scale(&self.d()))
    }
    /// The planted transfer function $(n + Dd)/d$ in lowest terms.
    fn tf(&self) -> RationalFunction<F> {
        RationalFunction::new(self.total_num(), self.den.clone())
    }
    /// The monic invariant zero polynomial: $(n + Dd)\,\chi_{hidden}$.
    fn zero_polynomial(&self) -> Poly<F> {
        self.total_num().mul(&self.hidden).monic()
    }
    fn n(&self) -> usize {
        self.sys.nstates()
    }
}

/// tf: the planted $G$ exactly, and its Laurent coefficients are the Markov parameters.
fn check_tf<F: Field>(p: &Planted<F>) {
    let g = p.sys.transfer_matrix().unwrap();
    assert_eq!(
        g.entries,
        vec![vec![p.tf()]],
        "G = (n + D d)/d, sys = {:?}",
        p.sys
    );
    assert!(g.matches_markov(&p.sys));
    assert_eq!(p.sys.a.charpoly().unwrap(), p.den.mul(&p.hidden), "chi_A");
}

/// The `tf` report over the field: verified (Markov parameters too), McMillan degree and
/// order $\deg d$, pole polynomial $d$, the poles' values exactly the planted roots of $d$
/// (each linear over the field) with their multiplicities, the transmission zeros' degrees
/// times multiplicities summing to $\deg(n + Dd)$.
fn check_tf_report<F: GroundField>(p: &Planted<F>) {
    let k = p.sys.a.field().clone();
    let g = p.sys.transfer_matrix().unwrap();
    let r = realize_state_space(&p.sys, &g).unwrap();
    let rep = tf_report(&g, &r, Some(g.matches_markov(&p.sys)), Domain::Continuous).unwrap();
    let get = |key: &str| rep.get(key).unwrap_or_else(|| panic!("no {key}: {rep:?}"));
    assert!(matches!(get("verified"), Value::Bool(true)), "{rep:?}");
    assert!(matches!(get("markov_verified"), Value::Bool(true)));
    let deg = p.den.deg() as i64;
    assert!(matches!(get("mcmillan_degree"), Value::Int(d) if *d == deg));
    assert!(matches!(get("order"), Value::Int(d) if *d == deg));
    assert!(
        matches!(get("pole_polynomial"), Value::Str(s) if *s == p.den.monic().to_string_var("s"))
    );
    let items = |key: &str| -> Vec<(String, i64, i64)> {
        let Value::List(v) = get(key) else {
            panic!("{key}: not a list")
        };
        v.iter()
            .map(|x| {
                let Value::Obj(o) = x else {
                    panic!("{key}: item")
                };
                let s = |k: &str| match o.get(k) {
                    Some(Value::Str(s)) => s.clone(),
                    other => panic!("{key}.{k}: {other:?}"),
                };
                let i = |k: &str| match o.get(k) {
                    Some(Value::Int(i)) => *i,
                    other => panic!("{key}.{k}: {other:?}"),
                };
                (s("value"), i("degree"), i("algebraic_multiplicity"))
            })
            .collect()
    };
    // the planted roots of d, counted, against the report's linear pole factors
    let mut want: Vec<(String, i64)> = vec![];
    for z in &p.roots {
        let v = k.fmt_elem(z);
        match want.iter_mut().find(|w| w.0 == v) {
            Some(w) => w.1 += 1,
            None => want.push((v, 1)),
        }
    }
    let mut got: Vec<(String, i64)> = items("poles")
        .into_iter()
        .map(|(v, d, m)| {
            assert_eq!(d, 1, "every planted pole is in the field: {v}");
            (v, m)
        })
        .collect();
    want.sort();
    got.sort();
    assert_eq!(got, want, "poles");
    let zdeg: i64 = items("transmission_zeros").iter().map(|x| x.1 * x.2).sum();
    assert_eq!(zdeg, p.total_num().deg() as i64, "transmission zeros");
}

/// minreal by every method: order = McMillan degree = deg d, Markov parameters, D and the
/// transfer matrix unchanged.
fn check_minreal<F: SystemField>(p: &Planted<F>) {
    let n = p.n();
    let order = p.den.deg();
    assert_eq!(mcmillan_degree(&p.sys), order, "McMillan degree");
    for method in [
        MinrealMethod::Kalman,
        MinrealMethod::Rosenbrock,
        MinrealMethod::HoKalman,
        MinrealMethod::Jordan,
    ] {
        let r = minimal(&p.sys, method).unwrap();
        assert!(r.verified, "{}", method.name());
        assert_eq!(r.order, order, "{} order", method.name());
        assert!(r.system.same_markov(&p.sys, 2 * n + 2), "{}", method.name());
        assert_eq!(r.system.d, p.sys.d);
        let g = r.system.transfer_matrix().unwrap();
        assert_eq!(g.entries, vec![vec![p.tf()]], "{} keeps G", method.name());
        // the Jordan method keeps its own result: its checks and its McMillan degree
        match (&r.jordan, method) {
            (Some(JordanMethod::Modal(m)), MinrealMethod::Jordan) => {
                assert!(m.verified && m.mcmillan_degree == order && m.order() == order);
            }
            (Some(JordanMethod::Primary(j)), MinrealMethod::Jordan) => {
                assert!(j.verified && j.mcmillan_degree == order);
                assert_eq!(j.system, r.system, "the primary blocks are the system");
            }
            (None, MinrealMethod::Jordan) => panic!("the Jordan method keeps its result"),
            (Some(_), _) => panic!("{}: no Jordan result", method.name()),
            (None, _) => {}
        }
    }
}

/// PBH: $(A, B)$ controllable iff no uncontrollable mode was planted, and the test agrees
/// with the rank of the controllability matrix; the same for $(A, C)$.
fn check_pbh<F: SystemField>(p: &Planted<F>) {
    let s = &p.sys;
    let n = p.n();
    let pc = pbh_controllable(&s.a, &s.b).unwrap();
    assert_eq!(pc, p.unc.deg() == 0, "PBH controllable");
    assert_eq!(pc, controllability_matrix(&s.a, &s.b).rank() == n);
    let po = pbh_observable(&s.a, &s.c).unwrap();
    assert_eq!(po, p.unobs.deg() == 0, "PBH observable");
    assert_eq!(po, observability_matrix(&s.a, &s.c).rank() == n);
}

/// The Kalman decomposition: `A T = T A~`, `B = T B~`, `C T = C~`, its part dimensions the
/// planted ones (order: controllable-unobservable, minimal, uncontrollable-unobservable,
/// uncontrollable-observable) and the zero blocks of the form: `B~` on the uncontrollable
/// rows, `A~` below-left of the controllable block, `C~` on the unobservable columns.
fn check_kalman<F: Field>(p: &Planted<F>) {
    let (s, n) = (&p.sys, p.n());
    let k = s.field();
    let kd = kalman_decomposition(s).unwrap();
    let (t, st) = (&kd.t, &kd.system);
    assert_eq!(&s.a * t, t * &st.a, "A T = T A~");
    assert_eq!(s.b, t * &st.b, "B = T B~");
    assert_eq!(&s.c * t, st.c, "C T = C~");
    assert_eq!(st.d, s.d);
    let [co, c_unobs, unc_obs, neither] = p.dims;
    assert_eq!(kd.dims, [c_unobs, co, neither, unc_obs], "Kalman parts");
    let ctrl = co + c_unobs;
    for i in ctrl..n {
        assert!(
            k.is_zero(st.b.get(i, 0)),
            "B~ zero on the uncontrollable rows"
        );
        for j in 0..ctrl {
            assert!(k.is_zero(st.a.get(i, j)), "A~ block triangular");
        }
    }
    for j in (0..c_unobs).chain(ctrl..ctrl + neither) {
        assert!(
            k.is_zero(st.c.get(0, j)),
            "C~ zero on the unobservable columns"
        );
    }
}

/// zeros: the planted zero polynomial (transmission and decoupling zeros), normal rank
/// $n + 1$, the Smith-form oracle agrees.
fn check_zeros<F: Field>(p: &Planted<F>) {
    let s = &p.sys;
    let z = invariant_zeros(&s.a, &s.b, &s.c, &s.d).unwrap();
    assert_eq!(z.polynomial, p.zero_polynomial(), "zeros, sys = {s:?}");
    assert_eq!(z.normal_rank, p.n() + 1);
    let zs = invariant_zeros_smith(&s.a, &s.b, &s.c, &s.d).unwrap();
    assert_eq!(
        (zs.polynomial, zs.normal_rank),
        (z.polynomial, z.normal_rank)
    );
}

/// scb: its identities, $\det(sI - A_{aa})$ = the zero polynomial, the chain of the
/// relative degree.
fn check_scb<F: Field>(p: &Planted<F>) {
    let s = &p.sys;
    let b = scb(&s.a, &s.b, &s.c, &s.d).unwrap();
    b.check().unwrap();
    assert!(b.verified && b.left_invertible && b.right_invertible);
    let zp = p.zero_polynomial();
    assert_eq!(b.invariant_zero_polynomial().monic(), zp);
    let k = s.field();
    let rel = if k.is_zero(&p.d()) {
        p.den.deg() - p.num.deg()
    } else {
        0
    };
    assert_eq!(b.dims, [zp.deg(), 0, 0, rel], "SCB dims, sys = {s:?}");
    assert_eq!(b.m0, usize::from(rel == 0));
    let chains: Vec<usize> = if rel > 0 { vec![rel] } else { vec![] };
    assert_eq!(b.chains, chains);
}

/// ctrb / obsv: the planted orders, indices and hidden parts, with $LB = 0$,
/// $LA = A_{\bar c} L$; the pencil $[A - sI, B]$ carries the same structure.
fn check_ctrb_obsv<F: Field>(p: &Planted<F>) {
    let s = &p.sys;
    let [n1, n2, n3, _] = p.dims;
    let c = controllability_structure(&s.a, &s.b).unwrap();
    assert!(c.verified);
    assert_eq!((c.order, c.indices.clone()), (n1 + n2, vec![n1 + n2]));
    assert_eq!(c.block_dims, vec![1; n1 + n2]);
    assert_eq!(
        c.uncontrollable.charpoly().unwrap(),
        p.unc,
        "uncontrollable modes"
    );
    assert!((&c.left * &s.b).is_zero(), "L B = 0");
    assert_eq!(
        &c.left * &s.a,
        &c.uncontrollable * &c.left,
        "L A = A_cbar L"
    );
    assert_eq!(c.left.rank(), p.n() - c.order);
    let o = observability_structure(&s.a, &s.c).unwrap();
    assert!(o.verified);
    assert_eq!((o.order, o.indices.clone()), (n1 + n3, vec![n1 + n3]));
    assert_eq!(
        o.uncontrollable.charpoly().unwrap(),
        p.unobs,
        "unobservable modes"
    );
    // [A - sI, B]: right index = controllability index, finite part = uncontrollable part
    let k = s.field().clone();
    let n = p.n();
    let ab = s.a.hstack(&s.b).unwrap();
    let e = Matrix::identity(k.clone(), n)
        .hstack(&Matrix::zeros(k, n, 1))
        .unwrap();
    let ks = kronecker_structure(&ab, &e).unwrap();
    assert!(ks.verified);
    assert_eq!(
        ks.right_indices,
        vec![n1 + n2],
        "right index of [A - sI, B]"
    );
    assert!(ks.left_indices.is_empty() && ks.infinite_divisors.is_empty());
    assert_eq!(ks.finite_part.charpoly().unwrap(), p.unc);
}

/// The descriptor system of the module docs around `p`'s system, with `improper` an output
/// that sees $N B_\infty$; returns it with the planted standard form.
fn planted_descriptor<F: Field>(
    p: &Planted<F>,
    g: &Option<F::Elem>,
    improper: bool,
    rng: &mut Rng,
) -> (Descriptor<F>, StateSpace<F>) {
    let s = &p.sys;
    let k = s.field().clone();
    let (nf, ni) = (p.n(), 3);
    let n = nf + ni;
    // diag(I, N), N = J_2(0) + 0; diag(A_f, I)
    let mut e0 = Matrix::zeros(k.clone(), n, n);
    let mut a0 = Matrix::zeros(k.clone(), n, n);
    for i in 0..nf {
        e0.set(i, i, k.one());
        for j in 0..nf {
            a0.set(i, j, s.a.get(i, j).clone());
        }
    }
    e0.set(nf, nf + 1, k.one());
    for i in nf..n {
        a0.set(i, i, k.one());
    }
    let b_inf = Matrix::from_fn(k.clone(), ni, 1, |i, _| {
        if i == 0 {
            elem(&k, g, rng)
        } else {
            nonzero(&k, g, rng)
        }
    });
    // C_inf N B_inf = c_0 b_1: zero unless `improper`
    let c_inf = Matrix::from_fn(k.clone(), 1, ni, |_, j| {
        if j == 0 && !improper {
            k.zero()
        } else {
            nonzero(&k, g, rng)
        }
    });
    let b0 = s.b.vstack(&b_inf).unwrap();
    let c0 = s.c.hstack(&c_inf).unwrap();
    let pl = scramble(&k, g, n, rng);
    let q = scramble(&k, g, n, rng).transpose();
    let desc = Descriptor::new(
        &(&pl * &e0) * &q,
        &(&pl * &a0) * &q,
        &pl * &b0,
        &c0 * &q,
        s.d.clone(),
    )
    .unwrap();
    let std = StateSpace::new(
        s.a.clone(),
        s.b.clone(),
        s.c.clone(),
        &s.d - &(&c_inf * &b_inf),
    )
    .unwrap();
    (desc, std)
}

/// pencil and standard on the planted descriptor system; the improper one is refused.
fn check_descriptor<F: SystemField>(p: &Planted<F>, g: &Option<F::Elem>, rng: &mut Rng) {
    let (desc, std) = planted_descriptor(p, g, false, rng);
    let chi = p.sys.a.charpoly().unwrap();
    let ks = kronecker_structure(&desc.a, &desc.e).unwrap();
    assert!(ks.verified && ks.is_regular());
    assert_eq!(ks.infinite_divisors, vec![1, 2], "N = J_2(0) + 0");
    // with the Jordan form of the finite part: prod g^(sum of blocks) = chi_A
    let ps = pencil_structure(&desc.a, &desc.e).unwrap();
    assert!(ps.verified && ps.structure == ks, "pencil_structure");
    let fk = ps.finite.base().clone();
    let mut prod = Poly::new(fk.clone(), vec![fk.one()]);
    for c in &ps.finite.components {
        let e: usize = c.blocks.iter().sum();
        prod = prod.mul(&pow(&c.factor, e));
    }
    assert_eq!(
        prod.coeffs(),
        chi.coeffs(),
        "finite part: the factors of chi_A"
    );
    assert!(ks.right_indices.is_empty() && ks.left_indices.is_empty());
    assert_eq!(ks.finite_part.charpoly().unwrap(), chi, "finite part ~ A_f");
    let f = descriptor_to_standard(&desc).unwrap();
    assert!(f.verified);
    assert_eq!(f.removed_infinite, 3);
    assert_eq!(f.system.a.charpoly().unwrap(), chi);
    assert_eq!(
        f.system.transfer_matrix().unwrap(),
        std.transfer_matrix().unwrap(),
        "standard form = (A_f, B_f, C_f, D - C_inf B_inf) up to coordinates"
    );
    let (bad, _) = planted_descriptor(p, g, true, rng);
    match descriptor_to_standard(&bad) {
        Err(Error::ImproperTransfer(m)) => assert!(m.contains("degree 1"), "{m}"),
        other => panic!("expected ImproperTransfer, got {other:?}"),
    }
}

/// mnf: a controllable single-input system of even order has the form; odd order has none.
fn check_mnf<F: Field>(k: &F, g: &Option<F::Elem>, rng: &mut Rng) {
    let (num, den, _) = planted_tf(k, g, rng);
    let [a, b, c] = controller_form(&num, &den);
    let n = den.deg();
    let d = Matrix::zeros(k.clone(), 1, 1);
    let sys = StateSpace::new(a, b, c, d)
        .unwrap()
        .transform(&scramble(k, g, n, rng))
        .unwrap();
    let r = mechanical_normal_form(&sys.a, &sys.b, &sys.c, &sys.d).unwrap();
    if n % 2 == 1 {
        assert!(!r.exists, "odd order: no mechanical normal form");
        assert!(
            r.conditions
                .iter()
                .any(|c| c.name() == "n_even" && !c.holds)
        );
        return;
    }
    assert!(
        r.exists && r.verified,
        "controllable, single input, n = {n}"
    );
    assert!(r.verify());
    let f = r.form.unwrap();
    assert!((&f.t_inv * &f.t).is_identity());
    assert_eq!(&(&f.t * &sys.a) * &f.t_inv, f.a_tilde, "t A t^-1 = A~");
    assert_eq!(&f.t * &sys.b, f.b_tilde, "t B = B~");
    assert_eq!(&sys.c * &f.t_inv, f.output, "C t^-1 = C~");
    assert_eq!(
        f.a_tilde.charpoly().unwrap(),
        den,
        "same characteristic polynomial"
    );
    let h = n / 2;
    assert!(f.a_tilde.submatrix(0, h, 0, h).is_zero());
    assert!(f.a_tilde.submatrix(0, h, h, n).is_identity());
}

/// Every operation on `cases` planted systems over `k` (generator `g`).
fn check_systems<F: GroundField>(k: &F, g: &Option<F::Elem>, seed: u64, cases: usize) {
    let mut rng = Rng(seed);
    for _ in 0..cases {
        let p = planted(k, g, &mut rng);
        check_tf(&p);
        check_tf_report(&p);
        check_minreal(&p);
        check_pbh(&p);
        check_kalman(&p);
        check_zeros(&p);
        check_scb(&p);
        check_ctrb_obsv(&p);
        check_descriptor(&p, g, &mut rng);
        check_mnf(k, g, &mut rng);
    }
}

crate::for_each_field!(check_systems, 2351, 8, 4; system_operations_over_q, system_operations_over_q_sqrt2,
    system_operations_over_q_i, system_operations_over_q_p);
