//! Linear multibody models (issue 26): `cargo bench --bench multibody`.
//!
//! Targets: the quarter car of the minimal-realizations paper (sec. 4.3) from its model
//! file to the minimal realization (read, assemble the 11x11 descriptor over Q, index-1
//! standard form 8x8, Kalman minimal realization 7x7) in < 100 ms; a 40-body chain
//! (descriptor 81x81 from 240 body coordinates) assembled and brought to standard form in
//! < 2 s. Output: `name: best ms (median ms, reps)`.

#[path = "common.rs"]
mod common;

use common::{bench, selected};
use exactlti::field::Q;
use exactlti::io::{SystemFormat, load_system_str};
use exactlti::multibody::{assemble, chain};
use exactlti::realization::{MinrealMethod, descriptor_to_standard, minimal};

fn main() {
    let qc = std::fs::read_to_string("data/models/quarter-car-a-arm-pushrod.toml")
        .expect("run from the repository root");
    if selected("quarter_car_file_to_minimal") {
        bench("quarter_car_file_to_minimal", 10, 100.0, || {
            let l = load_system_str(&qc, SystemFormat::Toml, "qc.toml").expect("valid");
            let r = minimal(&l.rational().expect("Q").ss, MinrealMethod::Kalman).expect("ok");
            assert_eq!(r.system.nstates(), 7);
            r
        });
    }
    if selected("chain_40_assemble_standard") {
        let m = chain(&Q, 40);
        bench("chain_40_assemble_standard", 3, 2000.0, || {
            let a = assemble(&m).expect("valid");
            let sf = descriptor_to_standard(&a.descriptor).expect("index 1");
            assert!(sf.verified);
            assert_eq!(sf.system.nstates(), 80);
            sf
        });
    }
}
