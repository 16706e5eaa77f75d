//! Minimal realizations of the 10-DOF sliding masses (minimal-realizations paper sec. 4.1).
//!
//! Two fixed-fixed chains of five unit masses and unit springs; an actuator pushes sliders 4
//! and 7 apart; the output is x9 - x2. The 20-state model has McMillan degree 8. Every exact
//! method finds 8 and is verified (controllable, observable, equal Markov parameters); the
//! Jordan-form method passes through 16 (the four modes at ±i√2 have nodes at the sensor and
//! the actuator) and ends with the sparse real Jordan pattern of eq. 48.
//!
//! Run: `cargo run --release --example sliding_masses_minreal`
use exactlti::io::parse_system_json;
use exactlti::matrix::Matrix;
use exactlti::realization::{MinrealMethod, mcmillan_degree, minimal, minimal_jordan, modal_table};
use exactlti::system::StateSpace;

fn main() {
    let f = parse_system_json(
        include_str!("../data/sliding-masses.json"),
        "sliding-masses.json",
    )
    .expect("valid file");
    let conv = |m: &exactlti::io::MatrixEntries| {
        Matrix::from_vec(
            exactlti::field::Q,
            m.nrows,
            m.ncols,
            m.data.iter().map(|x| x.a.clone()).collect(),
        )
    };
    let (m, l, k, ff) = (
        conv(f.m.as_ref().unwrap()),
        conv(f.l.as_ref().unwrap()),
        conv(f.k.as_ref().unwrap()),
        conv(f.f.as_ref().unwrap()),
    );
    let sys = StateSpace::from_second_order(
        &m,
        &l,
        &k,
        &ff,
        f.c.as_ref().map(conv).as_ref(),
        f.d.as_ref().map(conv).as_ref(),
    )
    .unwrap();
    assert_eq!(sys.nstates(), 20);
    assert_eq!(mcmillan_degree(&sys), 8);
    println!(
        "McMillan degree (exact Hankel rank): {}",
        mcmillan_degree(&sys)
    );
    for method in [
        MinrealMethod::Kalman,
        MinrealMethod::Rosenbrock,
        MinrealMethod::HoKalman,
    ] {
        let r = minimal(&sys, method).unwrap();
        assert_eq!(r.order, 8);
        assert!(r.verified);
        println!(
            "{:>10}: order {} (verified {})",
            method.name(),
            r.order,
            r.verified
        );
    }
    let j = minimal_jordan(&sys).unwrap();
    assert_eq!(j.stages, [20, 16, 8]);
    assert!(j.verified);
    println!(
        "    jordan: {} -> {} -> {} (verified {})",
        j.stages[0], j.stages[1], j.stages[2], j.verified
    );
    print!("{}", j.report().to_text());
    print!("{}", modal_table(&sys.a).unwrap().report().to_text());
}
