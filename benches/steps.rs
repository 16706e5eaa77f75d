//! The cost of `--steps` (issue 27): each command's algorithm run plain (no recorder: what
//! the command does without `--steps`) and with its derivation recorded, on the same input.
//! `cargo bench --bench steps`. Output per command: `name plain: best ms (...)`,
//! `name steps: best ms (...)` and `name: steps / plain = R`.
//!
//! Inputs: the quarter car of the minimal-realizations paper (an 11x11 descriptor from its
//! model file, standard form 8x8) and the sliding masses (20 states).

#[path = "common.rs"]
mod common;

use common::{bench, selected};
use exactlti::field::{Field, Q};
use exactlti::io::{SystemFormat, load_system_str};
use exactlti::jordan::derivation::{Method, Recorder};
use exactlti::realization::{
    descriptor_to_standard_recorded, minimal_ho_kalman_recorded, minimal_rosenbrock_recorded,
};
use exactlti::structure::mechanical::{DEFAULT_MAX_CANDIDATES, mechanical_normal_form_recorded};
use exactlti::structure::scb::scb_recorded;
use exactlti::system::StateSpace;

/// Times `f(None)` and `f(Some(recorder))`, prints both and their ratio.
fn pair<K: Field, T>(
    name: &str,
    method: Method,
    k: &K,
    reps: usize,
    f: impl Fn(Option<&mut Recorder<'_, K>>) -> T,
) {
    if !selected(name) {
        return;
    }
    let plain = bench(&format!("{name} plain"), reps, 300.0, || f(None));
    let steps = bench(&format!("{name} steps"), reps, 300.0, || {
        let mut rec = Recorder::new(method, k.clone());
        let out = f(Some(&mut rec));
        (out, rec.finish())
    });
    println!("{name}: steps / plain = {:.2}", steps / plain);
}

fn load(path: &str, format: SystemFormat) -> exactlti::io::LoadedSystem {
    let text = std::fs::read_to_string(path).expect("run from the repository root");
    load_system_str(&text, format, path).expect("valid")
}

fn main() {
    let qc = load(
        "data/models/quarter-car-a-arm-pushrod.toml",
        SystemFormat::Toml,
    );
    let qc = qc.rational().expect("Q").clone();
    let desc = qc.descriptor.clone().expect("a descriptor model");
    let sm = load("data/sliding-masses.json", SystemFormat::Json);
    let sm: StateSpace<Q> = sm.rational().expect("Q").ss.clone();
    let q = Q;
    pair("quarter_car standard", Method::Standard, &q, 5, |r| {
        descriptor_to_standard_recorded(&desc, r).expect("index 1")
    });
    for (tag, s) in [("quarter_car", &qc.ss), ("sliding_masses", &sm)] {
        pair(&format!("{tag} tf"), Method::Transfer, &q, 5, |r| {
            s.transfer_matrix_recorded(r).expect("ok")
        });
        pair(&format!("{tag} scb"), Method::Scb, &q, 5, |r| {
            scb_recorded(&s.a, &s.b, &s.c, &s.d, r).expect("ok")
        });
        pair(
            &format!("{tag} rosenbrock"),
            Method::Rosenbrock,
            &q,
            5,
            |r| minimal_rosenbrock_recorded(s, r).expect("ok"),
        );
        pair(&format!("{tag} ho_kalman"), Method::HoKalman, &q, 3, |r| {
            minimal_ho_kalman_recorded(s, r).expect("ok")
        });
        pair(&format!("{tag} mnf"), Method::Mnf, &q, 3, |r| {
            mechanical_normal_form_recorded(
                None,
                [&s.a, &s.b, &s.c, &s.d],
                DEFAULT_MAX_CANDIDATES,
                r,
            )
            .expect("ok")
        });
    }
}
