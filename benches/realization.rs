//! Exact realization benchmarks: the 10-DOF sliding masses (20 states, McMillan degree 8).
//! Run: `cargo bench --bench realization`.
#[path = "common.rs"]
mod common;
#[path = "../tests/common/systems.rs"]
mod systems;

use exactlti::realization::{MinrealMethod, mcmillan_degree, minimal};

fn main() {
    let sys = systems::sliding_masses();
    if common::selected("mcmillan") {
        common::bench("exact mcmillan degree sliding 20x20", 3, 500.0, || {
            mcmillan_degree(&sys)
        });
    }
    for (name, m) in [
        ("kalman", MinrealMethod::Kalman),
        ("rosenbrock", MinrealMethod::Rosenbrock),
        ("ho-kalman", MinrealMethod::HoKalman),
    ] {
        let label = format!("exact minreal {name} sliding 20x20");
        if common::selected(&label) {
            common::bench(&label, 3, 1000.0, || {
                let r = minimal(&sys, m).unwrap();
                assert_eq!(r.order, 8);
                assert!(r.verified);
            });
        }
    }
}
