//! Symbolic (over Q(p)) benchmarks of issue 13, beside `scripts/anchors/symbolic.py` (SymPy on
//! the same matrices).
//!
//! Cases (data files in `data/`):
//! - `scb dc motor`: Grip & Saberi's DC motor with LuGre friction, SCB over
//!   QQ(J, alpha2, sigma0, sigma1) (goal <= 50 ms);
//! - `scb single track rear` / `front`: the single-track model, SCB over 8 parameters
//!   (goal <= 200 ms);
//! - `minreal sliding masses`: the 10-DOF sliding masses (20 states) with symbolic mass `m`
//!   and stiffness `k`, Kalman minimal realization, order 8 (goal <= 2 s);
//! - `bifurcations dc motor`: the generic SCB and every branch to depth 2.
//!
//! Output lines: `<label>: <best> ms (median <ms> ms, <reps> reps)` then
//! `result <label>: <what>` (parsed by the anchor script).
//!
//! Run: `cargo bench --bench symbolic [FILTER]`.
#[path = "common.rs"]
mod common;

use common::{bench, selected};
use exactlti::io::TypedAny;
use exactlti::io::symbolic::{SymbolicOptions, load_symbolic_path};
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::{MinrealMethod, minimal};
use exactlti::structure::bifurcation::{Limits, bifurcations};
use exactlti::structure::scb::scb;
use exactlti::system::StateSpace;
use std::path::Path;

fn load(path: &str) -> StateSpace<RatFuncField> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let l = load_symbolic_path(&root.join(path), &SymbolicOptions::default()).expect(path);
    let TypedAny::RatFunc(t) = l.system else {
        panic!("{path}: expected symbolic parameters")
    };
    t.ss
}

fn main() {
    for (label, file) in [
        ("scb dc motor", "data/dc-motor-lugre.json"),
        ("scb single track front", "data/scb/single-track-front.json"),
        ("scb single track rear", "data/scb/single-track-rear.json"),
    ] {
        if !selected(label) {
            continue;
        }
        let s = load(file);
        let mut last = None;
        bench(label, 5, 2000.0, || {
            let r = scb(&s.a, &s.b, &s.c, &s.d).expect("scb");
            last = Some((r.dims, r.verified));
        });
        let (dims, ok) = last.expect("ran");
        println!("result {label}: dims {dims:?}, verified {ok}");
    }
    let label = "minreal sliding masses";
    if selected(label) {
        let s = load("data/sliding-masses-symbolic.json");
        let mut last = None;
        bench(label, 3, 5000.0, || {
            let r = minimal(&s, MinrealMethod::Kalman).expect("minreal");
            last = Some((r.order, r.verified));
        });
        let (order, ok) = last.expect("ran");
        println!("result {label}: order {order}, verified {ok}");
    }
    let label = "bifurcations dc motor";
    if selected(label) {
        let s = load("data/dc-motor-lugre.json");
        let f = |s: &StateSpace<RatFuncField>| scb(&s.a, &s.b, &s.c, &s.d).map(|r| r.dims);
        let mut nb = 0;
        bench(label, 3, 3000.0, || {
            let t = bifurcations(&s, &f, Limits::default()).expect("bifurcations");
            nb = t.branches.len();
        });
        println!("result {label}: {nb} branches");
    }
}
