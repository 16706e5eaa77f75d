//! Matrices over Q(p) on the user's path (`Matrix<RatFuncField>`, whose charpoly, det, RREF
//! and rank go to the evaluation/interpolation kernels registered on the field), beside
//! `scripts/anchors/qp_matrix.py` (SymPy's DomainMatrix on the same matrices).
//!
//! Cases:
//! - `dense N charpoly|det|rref`: dense N x N (N = 6, 7, 8), entries linear in a, b, c
//!   (goal: >= 10x faster than SymPy's DomainMatrix); `dense N charpoly display`: the
//!   characteristic polynomial's text (what `linalg charpoly` prints);
//! - `diag10 tf|minreal|scb|zeros|jordan|minreal rosenbrock|minreal ho-kalman|mnf`:
//!   A = diag(p0..p9), B = ones, C = ones (goal <= 1 s);
//! - `chain10 tf|minreal`: the 10-mass chain in symbolic m, k, c (goal <= 2 s);
//! - `file dense 8 charpoly|det|rref load|execute|render`: the command line's phases on the
//!   dense 8 x 8 file (`{"parameters": {"a": null, ...}, "A": ...}`): reading and typing the
//!   file, the whole command in process (`execute_ctx`: read, kernel, report) and rendering
//!   the report as JSON.
//!
//! Output lines: `<label>: <best> ms (median <ms> ms, <reps> reps)`; the dense inputs are
//! written to `target/qp-matrix-cases.txt` (`name<TAB>n<TAB>entries;...`) for the anchor.
//!
//! Run: `cargo bench --bench qp_matrix [FILTER]`.
#[path = "common.rs"]
mod common;
#[path = "../tests/common/systems.rs"]
mod systems;

use common::{bench, selected};
use exactlti::api::{Command, Format, LinalgOp, RunContext, execute_ctx};
use exactlti::jordan::jordan_qp;
use exactlti::matrix::Matrix;
use exactlti::ratfunc::RatFuncField;
use exactlti::realization::{MinrealMethod, minimal};
use exactlti::rng::SplitMix64;
use exactlti::structure::mechanical::{DEFAULT_MAX_CANDIDATES, mechanical_normal_form_in};
use exactlti::structure::scb::scb;
use exactlti::structure::zeros::invariant_zeros;
use std::fmt::Write as _;

/// Entries `c0 + c1*a + c2*b + c3*c` with coefficients in -5..=5 (row-major text).
fn dense_entries(n: usize, seed: u64) -> Vec<String> {
    let mut rng = SplitMix64(seed);
    (0..n * n)
        .map(|_| {
            let c: Vec<i64> = (0..4).map(|_| rng.int(-5, 5)).collect();
            format!("{} + {}*a + {}*b + {}*c", c[0], c[1], c[2], c[3])
        })
        .collect()
}

fn main() {
    let k = RatFuncField::new(&["a", "b", "c"]).unwrap();
    let mut cases = String::new();
    for n in [6usize, 7, 8] {
        let ents = dense_entries(n, 1000 + n as u64);
        writeln!(cases, "dense {n}\t{n}\t{}", ents.join(";")).unwrap();
        let m = Matrix::from_vec(
            k.clone(),
            n,
            n,
            ents.iter().map(|s| k.parse(s).unwrap()).collect(),
        );
        let label = format!("dense {n} charpoly");
        if selected(&label) {
            bench(&label, 3, 1500.0, || m.charpoly().unwrap());
        }
        let label = format!("dense {n} charpoly display");
        if selected(&label) {
            let c = m.charpoly().unwrap();
            bench(&label, 3, 1000.0, || c.to_string());
        }
        let label = format!("dense {n} det");
        if selected(&label) {
            bench(&label, 3, 1500.0, || m.det().unwrap());
        }
        let label = format!("dense {n} rref");
        if selected(&label) {
            bench(&label, 3, 1500.0, || m.rref());
        }
    }
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target");
    std::fs::create_dir_all(&dir).ok();
    std::fs::write(dir.join("qp-matrix-cases.txt"), cases).expect("cases file");
    file_phases(&dir);

    let s = systems::diag_qp(10);
    for (label, run) in [
        ("diag10 tf", 0),
        ("diag10 minreal", 1),
        ("diag10 scb", 2),
        ("diag10 zeros", 3),
        ("diag10 jordan", 4),
        ("diag10 minreal rosenbrock", 5),
        ("diag10 minreal ho-kalman", 6),
        ("diag10 mnf", 7),
    ] {
        if !selected(label) {
            continue;
        }
        bench(label, 1, 2000.0, || match run {
            0 => s.transfer_matrix().map(|t| t.entries.len()).unwrap(),
            1 => minimal(&s, MinrealMethod::Kalman).unwrap().order,
            2 => scb(&s.a, &s.b, &s.c, &s.d).unwrap().dims[0],
            4 => jordan_qp(&s.a).unwrap().components.len(),
            5 => minimal(&s, MinrealMethod::Rosenbrock).unwrap().order,
            6 => minimal(&s, MinrealMethod::HoKalman).unwrap().order,
            7 => mechanical_normal_form_in(None, &s.a, &s.b, &s.c, &s.d, DEFAULT_MAX_CANDIDATES)
                .unwrap()
                .form
                .map_or(0, |f| f.t.nrows()),
            _ => invariant_zeros(&s.a, &s.b, &s.c, &s.d)
                .unwrap()
                .polynomial
                .degree()
                .unwrap_or(0),
        });
    }
    let s = systems::chain_qp(10);
    for (label, run) in [("chain10 tf", 0), ("chain10 minreal", 1)] {
        if !selected(label) {
            continue;
        }
        bench(label, 1, 2000.0, || match run {
            0 => s.transfer_matrix().map(|t| t.entries.len()).unwrap(),
            _ => minimal(&s, MinrealMethod::Kalman).unwrap().order,
        });
    }
}

/// The command line's phases on the dense 8 x 8 file (see the module docs).
fn file_phases(dir: &std::path::Path) {
    let ents = dense_entries(8, 1008);
    let rows: Vec<String> = ents
        .chunks(8)
        .map(|r| {
            format!(
                "[{}]",
                r.iter()
                    .map(|e| format!("\"{e}\""))
                    .collect::<Vec<_>>()
                    .join(", ")
            )
        })
        .collect();
    let text = format!(
        "{{\"parameters\": {{\"a\": null, \"b\": null, \"c\": null}}, \"A\": [{}]}}",
        rows.join(", ")
    );
    let path = dir.join("qp-matrix-dense8.json");
    std::fs::write(&path, &text).expect("dense file");
    if selected("file dense 8 load") {
        bench("file dense 8 load", 3, 1000.0, || {
            exactlti::api::System::open(&path, &Default::default()).expect("loads")
        });
    }
    for (name, op) in [
        ("charpoly", LinalgOp::Charpoly),
        ("det", LinalgOp::Det),
        ("rref", LinalgOp::Rref),
    ] {
        let label = format!("file dense 8 {name}");
        if !selected(&label) {
            continue;
        }
        let cmd = Command::Linalg {
            op,
            file: path.clone(),
        };
        let ctx = RunContext {
            stdout: Some(Format::Json),
            ..RunContext::default()
        };
        let out = execute_ctx(&cmd, None, None, &ctx).expect("runs");
        bench(&format!("{label} execute"), 3, 1000.0, || {
            execute_ctx(&cmd, None, None, &ctx).expect("runs")
        });
        bench(&format!("{label} render"), 3, 1000.0, || {
            exactlti::cli::render_full(&out.report, Format::Json, false, false)
        });
    }
}
