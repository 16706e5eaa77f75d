//! Output a person reads (issue 28 item 5): float series as a summary and a sample of rows
//! (JSON keeps every sample), floats by significant digits, `analyze` as a summary first
//! (`--full` for everything), and no line of any text output longer than 200 columns on the
//! repository's example files.

use crate::common::cli::run;
use std::path::Path;

/// The longest line a text output may have.
const MAX_LINE: usize = 200;

/// The repository's example system files (bad-input and fuzz reproducers left out).
fn examples() -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out = vec![];
    for dir in [
        "data",
        "data/models",
        "data/scb",
        "tests/data",
        "tests/data/everyday",
    ] {
        let Ok(rd) = std::fs::read_dir(root.join(dir)) else {
            continue;
        };
        for e in rd.flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            let ext_ok = name.ends_with(".json") || name.ends_with(".toml");
            if ext_ok && !name.starts_with("invalid_") && !name.starts_with("fuzz_") {
                out.push(format!("{dir}/{name}"));
            }
        }
    }
    out.sort();
    out
}

fn longest(text: &str) -> usize {
    text.lines().map(|l| l.chars().count()).max().unwrap_or(0)
}

/// Every command's text on every example: no line over [`MAX_LINE`] characters, whatever
/// the command answers (a refusal prints nothing on stdout).
#[test]
fn no_text_line_over_200_columns_on_the_examples() {
    let files = examples();
    assert!(files.len() >= 20, "{files:?}");
    let commands: &[&[&str]] = &[
        &["analyze", "--section-seconds", "2", "--max-seconds", "20"],
        &["tf"],
        &["minreal"],
        &["jordan"],
        &["zeros"],
        &["scb"],
        &["mnf"],
        &["modes"],
        &["ctrb"],
        &["pzmap"],
        &["step"],
        &["impulse"],
        &["freqresp"],
        &["dcgain"],
        &["check"],
        // the toolbox and the derivations (issue 28 item 5 audit)
        &["margin"],
        &["stepinfo"],
        &["damp"],
        &["gram"],
        &["stability"],
        &["obsv"],
        &["pencil"],
        &["tf", "--steps"],
        &["jordan", "--steps"],
    ];
    let jobs: Vec<(Vec<&str>, &str)> = files
        .iter()
        .flat_map(|f| {
            commands.iter().map(move |c| {
                let mut a = vec![c[0], f.as_str()];
                a.extend(&c[1..]);
                if c[0] != "analyze" {
                    a.extend(["--max-seconds", "20"]);
                }
                (a, f.as_str())
            })
        })
        .collect();
    let bad = std::sync::Mutex::new(vec![]);
    let next = std::sync::atomic::AtomicUsize::new(0);
    std::thread::scope(|s| {
        for _ in 0..4 {
            s.spawn(|| {
                loop {
                    let k = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                    let Some((args, _)) = jobs.get(k) else { break };
                    let (_, out, _) = run(args);
                    let w = longest(&out);
                    if w > MAX_LINE {
                        bad.lock().unwrap().push(format!("{}: {w}", args.join(" ")));
                    }
                }
            });
        }
    });
    let bad = bad.into_inner().unwrap();
    assert!(bad.is_empty(), "lines over {MAX_LINE} columns: {bad:#?}");
}

/// `step` prints a summary and a sample of rows; the rows are the JSON's samples.
#[test]
fn step_text_is_a_summary_with_sampled_rows_and_json_keeps_every_sample() {
    let f = "data/quarter-car.json";
    let (code, text, err) = run(&["step", f]);
    assert_eq!(code, 0, "{err}");
    assert!(text.lines().count() <= 60, "{text}");
    assert!(longest(&text) <= MAX_LINE, "{text}");
    assert!(text.contains("horizon: t = 0 .. "), "{text}");
    assert!(text.contains("--format json or --csv FILE"), "{text}");
    assert!(
        text.contains("road height [m] -> body height [m]: max "),
        "{text}"
    );
    assert!(!text.contains("0.0000000000"), "{text}");
    let (code, js, _) = run(&["step", f, "--format", "json"]);
    assert_eq!(code, 0);
    let j: serde_json::Value = serde_json::from_str(&js).unwrap();
    let times = j["times_s"].as_array().unwrap();
    let resp = j["response"].as_array().unwrap();
    assert!(times.len() > 100 && resp.len() == times.len());
    // each table row: a time of the grid and the four channels at that time (6 digits)
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip_while(|l| !l.contains("samples ("))
        .skip(2)
        .filter_map(|l| l.split_whitespace().map(|x| x.parse().ok()).collect())
        .collect();
    assert!(rows.len() >= 21, "{text}");
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-5 * b.abs().max(1e-300);
    for r in &rows {
        let k = times
            .iter()
            .position(|t| close(r[0], t.as_f64().unwrap()))
            .unwrap_or_else(|| panic!("{r:?} not on the grid"));
        let want: Vec<f64> = resp[k]
            .as_array()
            .unwrap()
            .iter()
            .flat_map(|row| row.as_array().unwrap().iter().map(|x| x.as_f64().unwrap()))
            .collect();
        assert_eq!(r.len(), 1 + want.len());
        for (got, w) in r[1..].iter().zip(&want) {
            assert!(
                close(*got, *w) || (got.abs() < 1e-300 && w.abs() < 1e-300),
                "{r:?}"
            );
        }
    }
    // the extremes are among the rows: the largest body height is in the table
    let body: Vec<f64> = resp.iter().map(|g| g[0][0].as_f64().unwrap()).collect();
    let max = body.iter().copied().fold(f64::MIN, f64::max);
    assert!(rows.iter().any(|r| close(r[1], max)), "max {max}");
}

/// `impulse` and `freqresp` text: sampled too, within the line limit.
#[test]
fn impulse_and_freqresp_text_are_sampled() {
    for args in [
        &["impulse", "data/quarter-car.json"][..],
        &["freqresp", "data/quarter-car.json", "--points", "2000"][..],
    ] {
        let (code, text, err) = run(args);
        assert_eq!(code, 0, "{err}");
        assert!(text.lines().count() <= 60, "{args:?}: {text}");
        assert!(
            text.contains("rows: evenly spaced and the extremes"),
            "{text}"
        );
    }
    let (_, js, _) = run(&[
        "freqresp",
        "data/quarter-car.json",
        "--points",
        "2000",
        "--format",
        "json",
    ]);
    let j: serde_json::Value = serde_json::from_str(&js).unwrap();
    assert_eq!(j["frequencies_hz"].as_array().unwrap().len(), 2000);
}

/// The README's first command: a summary on one screen; `--full` prints every section.
#[test]
fn analyze_is_a_summary_first_and_full_has_everything() {
    let (code, short, err) = run(&["analyze"]);
    assert_eq!(code, 0, "{err}");
    let n = short.lines().count();
    assert!(n <= 40, "{n} lines:\n{short}");
    assert!(longest(&short) <= MAX_LINE);
    for want in [
        "field QQ, order 20",
        "McMillan degree 8",
        "chi(s) = s^20 + 20*s^18",
        "stability (exact): marginally stable",
        "Jordan structure: diagonalizable",
        "zero polynomial z(s) = s^14 + 14*s^12",
        "--full",
    ] {
        assert!(short.contains(want), "{want}:\n{short}");
    }
    // each polynomial printed once (named), not once per section
    assert_eq!(short.matches("s^20 + 20*s^18").count(), 1, "{short}");
    assert_eq!(short.matches("s^14 + 14*s^12").count(), 1, "{short}");
    let (code, full, _) = run(&["analyze", "--full"]);
    assert_eq!(code, 0);
    assert!(full.lines().count() > 10 * n, "{}", full.lines().count());
    for section in [
        "== system ==",
        "== realization ==",
        "== special coordinate basis ==",
        "== eigenvalues and Jordan form ==",
        "== modal table ==",
    ] {
        assert!(full.contains(section), "{section}");
    }
    // JSON is complete either way
    let (_, js, _) = run(&["analyze", "--format", "json"]);
    let j: serde_json::Value = serde_json::from_str(&js).unwrap();
    assert_eq!(j["realization"]["mcmillan_degree"], 8);
    assert!(j["jordan"]["T"].as_array().is_some_and(|t| t.len() == 20));
}
