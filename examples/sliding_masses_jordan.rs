//! The 10-DOF sliding masses (Minaker & Gonzalez, minimal-realizations paper sec. 4.1):
//! two fixed-fixed chains of five unit masses and unit springs, A = [[0, I], [-K, 0]]
//! (20x20). Eigenvalues +/- i sqrt(2 - 2 cos(k pi / 6)), k = 1..5, each twice, all
//! diagonalizable (Table 1); the real Jordan form is exact, including the blocks of the
//! factor s^4 + 4 s^2 + 1 whose imaginary parts are sqrt(2 +/- sqrt 3).
//!
//! Run: `cargo run --example sliding_masses_jordan`

use exactlti::field::{Q, Rational};
use exactlti::jordan::jordan;
use exactlti::matrix::Matrix;

fn main() {
    let mut a = Matrix::zeros(Q, 20, 20);
    a.set_block(0, 10, &Matrix::identity(Q, 10));
    for g in [0, 5] {
        for i in 0..5 {
            a.set(10 + g + i, g + i, Rational::from_integer((-2).into()));
            if i < 4 {
                a.set(10 + g + i, g + i + 1, Rational::from_integer(1.into()));
                a.set(10 + g + i + 1, g + i, Rational::from_integer(1.into()));
            }
        }
    }
    let jf = jordan(&a).expect("jordan");
    assert!(jf.verified);
    println!("charpoly = {}", jf.charpoly);
    // Table 1 of the paper (positive imaginary parts), as printed
    #[allow(clippy::approx_constant)]
    let table = [
        1.9318516526,
        1.7320508076,
        1.4142135624,
        1.0000000000,
        0.51763809021,
    ];
    for w in table {
        let e = jf
            .eigenvalues
            .iter()
            .find(|e| (e.approx.1 - w).abs() < 1e-9)
            .unwrap_or_else(|| panic!("no eigenvalue {w}i"));
        assert_eq!(e.approx.0, 0.0);
        assert_eq!((e.algebraic_multiplicity, e.geometric_multiplicity), (2, 2));
        assert_eq!(e.blocks, [1, 1]);
        println!(
            "{:<22} minpoly {:<18} blocks {:?}",
            exactlti::report::sections::eigenvalue_text(e),
            e.minpoly.to_string(),
            e.blocks
        );
    }
    for k in 1..=5 {
        let w = (2.0 - 2.0 * (k as f64 * std::f64::consts::PI / 6.0).cos()).sqrt();
        assert!(
            jf.eigenvalues
                .iter()
                .any(|e| (e.approx.1 - w).abs() < 1e-12)
        );
    }
    assert_eq!(jf.eigenvalues.len(), 10);
    let rf = jf.real_form().expect("real form");
    assert!(rf.exact && rf.verified, "{:?}", rf.notes);
    let rep = rf.report().to_json();
    println!("real form fields: {}", rep["fields"]);
    println!("real J diagonal blocks: {}", rf.blocks.len());
    assert!(jf.free_response().verify(&jf));
    println!("verified: A T = T J per component, W V = I, real blocks exact");
}
