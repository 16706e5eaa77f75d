//! The library-facing API: loading system files without the CLI, the one dispatch point,
//! `qmat!` with exact text, `minimal(.., MinrealMethod::Jordan)`, `Display` of results.

use exactlti::api::{System, SystemVisitor};
use exactlti::field::{Field, Q};
use exactlti::io::{
    SystemFile, SystemFormat, TypedAny, TypedSystem, as_rational, load_system_path, load_system_str,
};
use exactlti::jordan::jordan;
use exactlti::matrix::Matrix;
use exactlti::qmat;
use exactlti::realization::{JordanMethod, MinrealMethod, mcmillan_degree, minimal};
use exactlti::system::StateSpace;
use exactlti::{Error, Result};
use std::path::Path;

fn data(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

/// A visitor written once for every field: order, field name, and whether it saw Q.
struct Summary;
impl SystemVisitor for Summary {
    type Output = (usize, String, bool);
    fn visit<K: Field + 'static>(self, _f: &SystemFile, t: &TypedSystem<K>) -> Self::Output {
        (
            t.ss.nstates(),
            t.ss.a.field().to_string(),
            as_rational(t).is_some(),
        )
    }
}

#[test]
fn load_from_path_and_text_agree() {
    let p = data("yaw_contract.json");
    let from_path = load_system_path(&p).unwrap();
    let text = std::fs::read_to_string(&p).unwrap();
    let from_text = load_system_str(&text, SystemFormat::Json, "yaw.json").unwrap();
    let (a, b) = (from_path.rational().unwrap(), from_text.rational().unwrap());
    assert_eq!(a.ss, b.ss);
    // the TOML twin of the same file gives the same exact system
    let toml = load_system_path(&data("yaw_contract.toml")).unwrap();
    assert_eq!(toml.rational().unwrap().ss, a.ss);
    let (n, field, is_q) = System::from(from_path.clone()).run(Summary);
    assert_eq!((n, field.as_str(), is_q), (a.ss.nstates(), "QQ", true));
}

#[test]
fn quadratic_file_dispatches_over_its_field() {
    let l = load_system_path(&data("sqrt2.toml")).unwrap();
    assert!(matches!(l.system, TypedAny::Quadratic(_)));
    assert!(l.rational().is_none());
    let (_, field, is_q) = System::from(l.clone()).run(Summary);
    assert!(!is_q);
    assert_eq!(field, l.ground().to_string());
}

#[test]
fn load_errors_are_one_line_with_location() {
    let e = load_system_str(
        r#"{"A": [[0, 1], [-2, "c"]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#,
        SystemFormat::Json,
        "m.json",
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "m.json: key A, row 2, column 2: unknown parameter 'c'"
    );
    // a singular mass matrix is found while typing the system
    let e = load_system_str(
        "M = [[0]]\nL = [[1]]\nK = [[1]]\nF = [[1]]\n",
        SystemFormat::Toml,
        "s.toml",
    )
    .unwrap_err();
    assert_eq!(e.to_string(), "s.toml: key M: the mass matrix is singular");
    let e = load_system_path(Path::new("/nonexistent/x.json")).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("/nonexistent/x.json: cannot read the file")
    );
    assert!(!e.to_string().contains('\n'));
}

#[test]
fn qmat_reads_decimals_exactly() {
    let a = qmat![[0, 1], ["-0.08", "1/3"]];
    let want = Matrix::from_rows(
        Q,
        vec![
            vec![Q.from_i64(0), Q.from_i64(1)],
            vec![
                Q.div(&Q.from_i64(-2), &Q.from_i64(25)).unwrap(),
                Q.div(&Q.from_i64(1), &Q.from_i64(3)).unwrap(),
            ],
        ],
    )
    .unwrap();
    assert_eq!(a, want);
    assert_eq!(
        Matrix::<Q>::from_str_rows(&[["0", "1"], ["-0.08", "1/3"]]).unwrap(),
        want
    );
    // 0.1 + 0.2 = 0.3 exactly, unlike binary floats
    let s = qmat![["0.1"]].try_add(&qmat![["0.2"]]).unwrap();
    assert_eq!(s, qmat![["0.3"]]);
    let e = Matrix::<Q>::from_str_rows(&[vec!["1", "2"], vec!["3", "x"]]).unwrap_err();
    assert!(
        matches!(
            e,
            Error::Parse {
                line: 2,
                col: 2,
                ..
            }
        ),
        "{e:?}"
    );
    assert!(Matrix::<Q>::from_str_rows(&[vec!["1", "2"], vec!["3"]]).is_err());
}

/// A non-minimal rational system with rational eigenvalues: diag(-1, -2, -3) with the
/// -3 mode unobservable and a repeated -1 mode uncontrollable in one direction.
fn nonminimal() -> StateSpace<Q> {
    let a = qmat![[-1, 0, 0, 0], [0, -1, 0, 0], [0, 0, -2, 0], [0, 0, 0, -3]];
    let b = qmat![[1], [2], [1], [1]];
    let c = qmat![[1, 1, "0.5", 0]];
    StateSpace::new(a, b, c, qmat![[0]]).unwrap()
}

#[test]
fn minimal_jordan_method_gives_a_verified_rational_realization() -> Result<()> {
    let sys = nonminimal();
    let r = minimal(&sys, MinrealMethod::Jordan)?;
    assert!(r.verified);
    assert_eq!(r.order, mcmillan_degree(&sys));
    assert_eq!(r.order, 2);
    // same Markov parameters as the original (an identity, checked here independently)
    assert_eq!(r.system.markov(8), sys.markov(8));
    assert_eq!(r.system.d, sys.d);
    // the Kalman method agrees on the order
    assert_eq!(minimal(&sys, MinrealMethod::Kalman)?.order, r.order);
    Ok(())
}

#[test]
fn minimal_jordan_method_writes_irrational_blocks_over_the_base_field() {
    // eigenvalues ±sqrt(2): the modal blocks live in Q(sqrt 2) (kept in `r.jordan`); the
    // system over Q is their primary block (the dispatcher refused this before issue 23)
    let sys = StateSpace::new(
        qmat![[0, 1], [2, 0]],
        qmat![[0], [1]],
        qmat![[1, 0]],
        qmat![[0]],
    )
    .unwrap();
    let r = minimal(&sys, MinrealMethod::Jordan).unwrap();
    assert!(r.verified && r.order == 2);
    assert_eq!(r.system.markov(8), sys.markov(8));
    let Some(JordanMethod::Modal(m)) = &r.jordan else {
        panic!("the modal result is kept: {:?}", r.jordan)
    };
    assert!(m.verified && m.real_to_base().is_none());
    assert_eq!(m.blocks.len(), 2);
    assert!(m.blocks.iter().all(|b| b.field.degree() == 2));
}

#[test]
fn display_of_systems_and_results() {
    let sys = nonminimal();
    let s = sys.to_string();
    assert!(s.starts_with("state space over QQ: 4 states, 1 inputs, 1 outputs\n"));
    assert!(s.contains("C = [[1, 1, 1/2, 0]]"));
    let jf = jordan(&sys.a).unwrap();
    let t = jf.to_string();
    assert!(t.contains("verified"), "{t}");
    let m = minimal(&sys, MinrealMethod::Kalman).unwrap();
    assert!(m.to_string().contains("verified"));
}
