//! Every linear-algebra operation of `Matrix<K>` (det, rank, rref, nullspace, inverse,
//! charpoly, minpoly, solve) over Q, Q(sqrt 2), Q(i) and Q(p) from one generic function
//! (issue 23, "Done when"). The generator plants each answer, and [`check_linalg`] asserts
//! that the operation returns it, with the operation's defining identity:
//!
//! * det: $A = L U$ ($L$ unit lower, $U$ upper triangular with a chosen diagonal $d$) has
//!   $\det A = \prod d_i$, also after row operations; one zero on the diagonal: rank $n - 1$,
//!   no inverse;
//! * inverse: $A A^{-1} = A^{-1} A = I$, $(A^{-1})^{-1} = A$, $\det A \det A^{-1} = 1$;
//! * rank, rref, nullspace: $A = X [I_r \mid M]$ ($X$ of full column rank $r$) has rank $r$,
//!   pivots $0..r$, RREF $[I_r \mid M; 0]$ and nullspace spanned by $[-M; I]$ ($A N = 0$);
//! * charpoly: the companion matrix of a chosen monic $p$ and every matrix similar to it
//!   have characteristic polynomial $p$; $\chi_A(0) = (-1)^n \det A$;
//! * minpoly: $\mathrm{diag}(C_p, C_p)$ has minimal polynomial $p$ and characteristic
//!   polynomial $p^2$; $\lambda I$ has $x - \lambda$;
//! * solve: $A X = B$ with a planted $X$ returns $X$ exactly (no nullspace) for invertible
//!   $A$; for $A = X [I_r \mid M]$ a consistent right-hand side gives a solution and the
//!   nullspace, one outside the column space gives `None`.

use crate::common::{self, Rng, elem, unimodular};
use exactlti::field::Field;
use exactlti::matrix::Matrix;
use exactlti::poly::Poly;

fn nonzero<K: Field>(k: &K, g: &Option<K::Elem>, rng: &mut Rng) -> K::Elem {
    loop {
        let x = elem(k, g, rng);
        if !k.is_zero(&x) {
            return x;
        }
    }
}

/// $L U$: `L` unit lower triangular, `U` upper triangular with diagonal `d`, random entries.
fn planted_lu<K: Field>(k: &K, g: &Option<K::Elem>, d: &[K::Elem], rng: &mut Rng) -> Matrix<K> {
    let n = d.len();
    let l = Matrix::from_fn(k.clone(), n, n, |i, j| match i.cmp(&j) {
        std::cmp::Ordering::Equal => k.one(),
        std::cmp::Ordering::Greater => elem(k, g, rng),
        std::cmp::Ordering::Less => k.zero(),
    });
    let u = Matrix::from_fn(k.clone(), n, n, |i, j| match i.cmp(&j) {
        std::cmp::Ordering::Equal => d[i].clone(),
        std::cmp::Ordering::Less => elem(k, g, rng),
        std::cmp::Ordering::Greater => k.zero(),
    });
    &l * &u
}

/// The companion matrix of the monic `p`: ones on the subdiagonal, last column $-c_i$.
fn companion<K: Field>(p: &Poly<K>) -> Matrix<K> {
    let k = p.field().clone();
    let n = p.deg();
    Matrix::from_fn(k.clone(), n, n, |i, j| {
        if j + 1 == n {
            k.neg(&p.coeff(i))
        } else if i == j + 1 {
            k.one()
        } else {
            k.zero()
        }
    })
}

/// The RREF of the rows of `m^T`: equal for two matrices exactly when their columns span
/// the same space.
fn column_span<K: Field>(m: &Matrix<K>) -> Matrix<K> {
    m.transpose().rref().0
}

fn check_det_inverse<K: Field>(k: &K, g: &Option<K::Elem>, n: usize, rng: &mut Rng) {
    let d: Vec<K::Elem> = (0..n).map(|_| nonzero(k, g, rng)).collect();
    let prod = d.iter().fold(k.one(), |acc, x| k.mul(&acc, x));
    let a = planted_lu(k, g, &d, rng);
    assert_eq!(a.det().unwrap(), prod, "det of L U = prod diag, A = {a}");
    let t = unimodular(k, n, rng);
    assert_eq!((&t * &a).det().unwrap(), prod, "det after row additions");
    assert_eq!(a.rank(), n);
    let inv = a.inverse().unwrap();
    assert!((&a * &inv).is_identity(), "A A^-1 = I, A = {a}");
    assert!((&inv * &a).is_identity(), "A^-1 A = I, A = {a}");
    assert_eq!(inv.inverse().unwrap(), a, "(A^-1)^-1 = A");
    assert!(k.is_one(&k.mul(&inv.det().unwrap(), &prod)));
    // chi_A(0) = (-1)^n det A
    let c0 = a.charpoly().unwrap().coeff(0);
    let sign = if n.is_multiple_of(2) {
        k.one()
    } else {
        k.neg(&k.one())
    };
    assert_eq!(c0, k.mul(&sign, &prod), "chi_A(0) = (-1)^n det A");
    if n > 0 {
        let mut d0 = d.clone();
        d0[rng.int(0, n as i64 - 1) as usize] = k.zero();
        let s = planted_lu(k, g, &d0, rng);
        assert!(k.is_zero(&s.det().unwrap()), "singular planted, A = {s}");
        assert_eq!(s.rank(), n - 1, "one zero pivot: rank n - 1, A = {s}");
        assert!(s.inverse().is_err(), "no inverse of a singular matrix");
    }
}

/// `(A, X, M, U)`: $A = X [I_r \mid M]$ with $X$ the first `r` columns of the invertible `U`.
fn planted_rank<K: Field>(
    k: &K,
    g: &Option<K::Elem>,
    (m, n, r): (usize, usize, usize),
    rng: &mut Rng,
) -> (Matrix<K>, Matrix<K>, Matrix<K>) {
    let u = unimodular(k, m, rng);
    let x = u.submatrix(0, m, 0, r);
    let mm = common::random_matrix(k, g, r, n - r, rng);
    let y = Matrix::identity(k.clone(), r).hstack(&mm).unwrap();
    (&x * &y, mm, u)
}

fn check_rank_rref_nullspace_solve<K: Field>(k: &K, g: &Option<K::Elem>, rng: &mut Rng) {
    let (m, n) = (rng.int(0, 4) as usize, rng.int(0, 4) as usize);
    let r = rng.int(0, m.min(n) as i64) as usize;
    let (a, mm, u) = planted_rank(k, g, (m, n, r), rng);
    assert_eq!(a.rank(), r, "planted rank, A = {a}");
    let (rr, piv) = a.rref();
    assert_eq!(piv, (0..r).collect::<Vec<_>>(), "pivots, A = {a}");
    let want = Matrix::identity(k.clone(), r)
        .hstack(&mm)
        .unwrap()
        .vstack(&Matrix::zeros(k.clone(), m - r, n))
        .unwrap();
    assert_eq!(rr, want, "RREF = [I M; 0], A = {a}");
    let ns = a.nullspace();
    assert_eq!(ns.ncols(), n - r, "nullity, A = {a}");
    assert!((&a * &ns).is_zero(), "A N = 0, A = {a}");
    let basis = mm
        .scale(&k.neg(&k.one()))
        .vstack(&Matrix::identity(k.clone(), n - r))
        .unwrap();
    assert_eq!(column_span(&ns), column_span(&basis), "N spans [-M; I]");
    // solve: a consistent right-hand side, then one outside the column space
    let x = common::random_matrix(k, g, n, 1, rng);
    let b = &a * &x;
    let (x0, nn) = a.solve(&b).unwrap().expect("consistent");
    assert_eq!(&a * &x0, b, "A x0 = b, A = {a}");
    assert_eq!(column_span(&nn), column_span(&ns), "solve's nullspace");
    if r < m {
        let off = u.submatrix(0, m, r, r + 1);
        assert!(
            a.solve(&off).unwrap().is_none(),
            "b outside the columns, A = {a}"
        );
    }
}

fn check_solve_invertible<K: Field>(k: &K, g: &Option<K::Elem>, n: usize, rng: &mut Rng) {
    let d: Vec<K::Elem> = (0..n).map(|_| nonzero(k, g, rng)).collect();
    let a = planted_lu(k, g, &d, rng);
    let x = common::random_matrix(k, g, n, 2, rng);
    let (x0, nn) = a.solve(&(&a * &x)).unwrap().expect("invertible");
    assert_eq!(x0, x, "the planted solution, A = {a}");
    assert_eq!(nn.ncols(), 0);
}

fn check_charpoly_minpoly<K: Field>(k: &K, g: &Option<K::Elem>, n: usize, rng: &mut Rng) {
    let mut cs: Vec<K::Elem> = (0..n).map(|_| elem(k, g, rng)).collect();
    cs.push(k.one());
    let p = Poly::new(k.clone(), cs);
    let c = companion(&p);
    assert_eq!(c.charpoly().unwrap(), p, "charpoly of the companion of p");
    let t = unimodular(k, n, rng);
    let s = c.similar_by(&t).unwrap();
    assert_eq!(s.charpoly().unwrap(), p, "similarity invariance, A = {s}");
    assert_eq!(s.minpoly().unwrap(), p, "a companion matrix is cyclic");
    if n > 0 {
        let cc = Matrix::block_diag(k.clone(), &[s.clone(), c.clone()]);
        assert_eq!(cc.minpoly().unwrap(), p, "minpoly of diag(C, C)");
        assert_eq!(cc.charpoly().unwrap(), p.mul(&p), "charpoly of diag(C, C)");
    }
    let lam = elem(k, g, rng);
    let scalar = Matrix::identity(k.clone(), n.max(1)).scale(&lam);
    let x_minus = Poly::new(k.clone(), vec![k.neg(&lam), k.one()]);
    assert_eq!(scalar.minpoly().unwrap(), x_minus, "minpoly of lambda I");
}

/// Every operation's planted answer over the field `k` with generator `g`.
fn check_linalg<K: Field>(k: &K, g: &Option<K::Elem>, seed: u64, cases: usize) {
    let mut rng = Rng(seed);
    for case in 0..cases {
        let n = case % 5;
        check_det_inverse(k, g, n, &mut rng);
        check_solve_invertible(k, g, n, &mut rng);
        check_charpoly_minpoly(k, g, n, &mut rng);
        check_rank_rref_nullspace_solve(k, g, &mut rng);
    }
}

crate::for_each_field!(check_linalg, 2311, 10, 5; linalg_over_q, linalg_over_q_sqrt2,
    linalg_over_q_i, linalg_over_q_p);
