//! The command line's floor of `linalg` on a rational matrix file (issue 29):
//! `cargo bench --bench linalg_cli [NAME]`.
//!
//! The file of the anchor sweep (`scripts/anchors/matrix.py`: entries `"p/q"`, |p|, q <=
//! 10^6, the generator of `benches/matrix.rs`) at n = 50, 100, 200, in its phases:
//! reading it with the general reader (`load_system_str`, proxy tree and typing) and with the
//! fast reader (`plain_square_matrix`, one pass straight to a rational matrix); the whole
//! command in process (`execute_ctx`: read, kernel, report) for `rank`, `rref`, `rref` of a
//! rank-deficient matrix (long entries, n = 50) and `nullspace`; rendering its report as the command
//! line prints it (text, JSON). Output: `name: best ms (median ms, reps)`.

#[path = "common.rs"]
mod common;

use common::{bench, selected};
use exactlti::api::{Command, Format, LinalgOp, RunContext, execute_ctx};
use exactlti::io::plain_matrix::plain_square_matrix;
use exactlti::io::{SystemFormat, load_system_str};

/// The anchor's 64-bit LCG (`x <- 6364136223846793005 x + 1442695040888963407`).
struct Lcg(u64);

impl Lcg {
    fn u31(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }
}

/// `{"A": [["p/q", ...], ...]}` as the anchor writes it (lowest terms, like Python's
/// `str(Fraction)`); the last row of a deficient matrix is row 0 + row 1.
fn anchor_file(n: usize, deficient: bool) -> String {
    let mut g = Lcg(1000 + n as u64 + if deficient { 500 } else { 0 });
    let mut a: Vec<exactlti::field::Rational> = (0..n * n)
        .map(|_| {
            let p = (g.u31() % 2_000_001) as i64 - 1_000_000;
            let q = (g.u31() % 1_000_000) as i64 + 1;
            exactlti::field::Rational::new(p.into(), q.into())
        })
        .collect();
    if deficient {
        for j in 0..n {
            a[(n - 1) * n + j] = &a[j] + &a[n + j];
        }
    }
    let rows: Vec<String> = a
        .chunks(n)
        .map(|r| {
            let xs: Vec<String> = r
                .iter()
                .map(|x| format!("\"{}\"", exactlti::report::display::fmt_rational(x)))
                .collect();
            format!("[{}]", xs.join(", "))
        })
        .collect();
    format!("{{\"A\": [{}]}}", rows.join(", "))
}

fn main() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-bench-linalg");
    std::fs::create_dir_all(&dir).expect("temp dir");
    for n in [50, 100, 200] {
        let text = anchor_file(n, false);
        let name = format!("rat{n}.json");
        if selected(&format!("read_general_rat{n}")) {
            bench(&format!("read_general_rat{n}"), 5, 1000.0, || {
                load_system_str(&text, SystemFormat::Json, &name).expect("valid")
            });
        }
        if selected(&format!("read_plain_rat{n}")) {
            bench(&format!("read_plain_rat{n}"), 5, 1000.0, || {
                plain_square_matrix(&text, "A").expect("plain")
            });
        }
        let sq = dir.join(&name);
        std::fs::write(&sq, &text).expect("write");
        let def = dir.join(format!("rat{n}_def.json"));
        std::fs::write(&def, anchor_file(n, true)).expect("write");
        let cases = [
            ("rank", LinalgOp::Rank, &sq),
            ("rref", LinalgOp::Rref, &sq),
            ("nullspace", LinalgOp::Nullspace, &sq),
            ("rref_def", LinalgOp::Rref, &def),
        ];
        for (op_name, op, path) in cases {
            // the deficient RREF is output-heavy (entries of ~n^2 20 bits): n = 50 only
            if (n == 50) != (op_name == "rref_def") {
                continue;
            }
            let cmd = Command::Linalg {
                op,
                file: path.to_path_buf(),
            };
            for format in [Format::Text, Format::Json] {
                let f = format!("{format:?}").to_lowercase();
                let case = format!("linalg_{op_name}_rat{n}_{f}");
                if !selected(&case) {
                    continue;
                }
                let ctx = RunContext {
                    stdout: Some(format),
                    ..RunContext::default()
                };
                let out = execute_ctx(&cmd, None, None, &ctx).expect("runs");
                bench(&format!("{case} execute"), 3, 1000.0, || {
                    execute_ctx(&cmd, None, None, &ctx).expect("runs")
                });
                bench(&format!("{case} render"), 3, 1000.0, || {
                    exactlti::cli::render_full(&out.report, format, false, false)
                });
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
