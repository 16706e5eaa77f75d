//! Test triad for the generic matrix algorithms over Q, Q(sqrt 2), Q(i) and Q(p) (one generic
//! function, `for_each_field!`: over Q(p) the registered kernels of `RatFuncField` run).
use crate::common;
use common::*;
use exactlti::field::{Field, Q};
use exactlti::matrix::Matrix;
use exactlti::qmat;

#[test]
fn rref_examples() {
    let a = qmat![[1, 2], [2, 4]];
    let (r, p) = a.rref();
    assert_eq!(r.to_string(), "[[1, 2], [0, 0]]");
    assert_eq!(p, vec![0]);
    let e = Matrix::zeros(Q, 0, 3);
    assert_eq!(e.rank(), 0);
    assert_eq!(e.nullspace().shape(), (3, 3));
    let e = Matrix::zeros(Q, 3, 0);
    assert_eq!(e.rank(), 0);
    assert_eq!(e.left_nullspace().shape(), (3, 3));
    let z = Matrix::zeros(Q, 0, 0);
    assert_eq!(z.det().unwrap(), Q.one());
    assert!(z.inverse().unwrap().shape() == (0, 0));
    assert_eq!(z.charpoly().unwrap().to_string(), "1");
    assert_eq!(qmat![[5]].inverse().unwrap().to_string(), "[[1/5]]");
    assert_eq!(
        qmat![[1, 2], [3, 4]].charpoly().unwrap().to_string(),
        "x^2 - 5*x - 2"
    );
    assert_eq!(qmat![[1, 2], [3, 4]].det().unwrap().to_string(), "-2");
    assert!(qmat![[1, 2], [2, 4]].inverse().is_err());
    assert!(qmat![[1, 2, 3], [2, 4, 5]].inverse().is_err());
    // minpoly of a matrix with a repeated eigenvalue in two 1x1 blocks
    assert_eq!(
        qmat![[2, 0], [0, 2]].minpoly().unwrap().to_string(),
        "x - 2"
    );
    assert_eq!(
        qmat![[2, 1], [0, 2]].minpoly().unwrap().to_string(),
        "x^2 - 4*x + 4"
    );
}

fn properties<K: Field>(k: &K, g: &Option<K::Elem>, seed: u64, cases: usize) {
    let mut rng = Rng(seed);
    for _ in 0..cases {
        let n = rng.int(0, 5) as usize;
        let m = rng.int(0, 5) as usize;
        let a = random_matrix(k, g, m, n, &mut rng);
        let (r, piv) = a.rref();
        assert_eq!(r.rref().0, r, "RREF idempotent, A = {a}");
        let ns = a.nullspace();
        assert_eq!(piv.len() + ns.ncols(), n, "rank + nullity, A = {a}");
        assert!((&a * &ns).is_zero(), "A N = 0, A = {a}");
        let ln = a.left_nullspace();
        assert!((&ln * &a).is_zero(), "W A = 0, A = {a}");
        assert_eq!(ln.nrows() + piv.len(), m);
        // canonical: RREF of P A equals RREF of A
        let p = unimodular(k, m, &mut rng);
        assert_eq!((&p * &a).rref().0, r, "RREF canonical, A = {a}");
        // square properties
        let s = random_matrix(k, g, n, n, &mut rng);
        let cp = s.charpoly().unwrap();
        assert_eq!(
            cp,
            s.charpoly_berkowitz().unwrap(),
            "Hessenberg = Berkowitz, A = {s}"
        );
        assert!(
            s.eval_poly(&cp).unwrap().is_zero(),
            "Cayley-Hamilton, A = {s}"
        );
        let mp = s.minpoly().unwrap();
        assert!(cp.rem(&mp).is_zero(), "minpoly | charpoly, A = {s}");
        assert!(s.eval_poly(&mp).unwrap().is_zero());
        let t = unimodular(k, n, &mut rng);
        // det is multiplicative: det(S T) = det S det T
        assert_eq!(
            (&s * &t).det().unwrap(),
            k.mul(&s.det().unwrap(), &t.det().unwrap()),
            "det(S T) = det S det T, S = {s}"
        );
        let st = s.similar_by(&t).unwrap();
        assert_eq!(st.charpoly().unwrap(), cp, "similarity invariance");
        assert_eq!(st.rank(), s.rank());
        match s.inverse() {
            Ok(si) => {
                assert!((&s * &si).is_identity());
                assert!(!k.is_zero(&s.det().unwrap()));
            }
            Err(_) => assert!(k.is_zero(&s.det().unwrap())),
        }
        // solve
        let b = random_matrix(k, g, n, 2, &mut rng);
        let rhs = &s * &b;
        let (x0, nn) = s.solve(&rhs).unwrap().expect("consistent");
        assert_eq!(&s * &x0, rhs);
        assert!((&s * &nn).is_zero());
        // kron / vec identity: vec(A X B) = (B^T kron A) vec(X)
        let x = random_matrix(k, g, n, 2, &mut rng);
        let bb = random_matrix(k, g, 2, 1, &mut rng);
        let lhs = (&(&s * &x) * &bb).vec();
        let rhs = &bb.transpose().kron(&s) * &x.vec();
        assert_eq!(lhs, rhs);
        assert_eq!(x.vec().unvec(n, 2).unwrap(), x);
    }
}

crate::for_each_field!(properties, 1, 30, 8; matrix_properties_q, matrix_properties_qsqrt2,
    matrix_properties_qi, matrix_properties_qp);
