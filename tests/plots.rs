//! Plots a control engineer expects (issue 15, item 3): step and impulse responses from the
//! exact closed form of e^{At}, the pole-zero map, the Bode plot. The exact side is checked by
//! identities (final value = D - C A^{-1} B, impulse at 0 = C B); the SVGs are checked as
//! XML (tags balance), for their titles, axis labels, channel names and marker counts.

use exactlti::field::{Q, rational_to_f64};
use exactlti::matrix::Matrix;
use exactlti::qmat;
use exactlti::system::StateSpace;
use exactlti::system::time_response::{ClosedFormResponse, time_grid};
use std::path::PathBuf;

/// Checks that `svg` is well-formed as far as tags go: every element closed in order, one
/// root `<svg>`, attribute quotes paired, no stray `<` or `&` in text. Returns the number of
/// elements.
fn well_formed(svg: &str) -> usize {
    let mut stack: Vec<String> = vec![];
    let mut count = 0;
    let mut roots = 0;
    let mut rest = svg;
    while let Some(start) = rest.find('<') {
        let text = &rest[..start];
        for (k, _) in text.match_indices('&') {
            let ent = &text[k..];
            assert!(
                ["&amp;", "&lt;", "&gt;", "&quot;", "&#"]
                    .iter()
                    .any(|e| ent.starts_with(e)),
                "raw & in text: {text}"
            );
        }
        let end = rest[start..].find('>').expect("unclosed tag") + start;
        let tag = &rest[start + 1..end];
        assert!(!tag.contains('<'), "'<' inside a tag: {tag}");
        assert_eq!(tag.matches('"').count() % 2, 0, "unpaired quote in {tag}");
        if let Some(name) = tag.strip_prefix('/') {
            let open = stack.pop().expect("closing tag without an opening one");
            assert_eq!(open, name.trim(), "tags cross");
        } else if !tag.starts_with('?') && !tag.starts_with('!') {
            let name: String = tag
                .chars()
                .take_while(|c| !c.is_whitespace() && *c != '/')
                .collect();
            if stack.is_empty() {
                roots += 1;
                assert_eq!(name, "svg", "the root element is <svg>");
            }
            count += 1;
            if !tag.ends_with('/') {
                stack.push(name);
            }
        }
        rest = &rest[end + 1..];
    }
    assert!(stack.is_empty(), "unclosed elements: {stack:?}");
    assert_eq!(roots, 1, "one root element");
    count
}

fn tmp(name: &str, text: &str) -> PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-plots");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let p = dir.join(name);
    std::fs::write(&p, text).expect("write");
    p
}

fn run(args: &[&str]) -> serde_json::Value {
    crate::common::cli::run_json(args)
}

/// Two inputs, two outputs, a complex pair, a 2x2 Jordan block at -1, feedthrough; stable.
const MIMO: &str = r#"{
  "name": "test rig <A&B>",
  "inputs": ["force", "torque"],
  "outputs": ["position", "angle"],
  "A": [[-1, 1, 0, 0], [0, -1, 0, 0], [0, 0, "-1/2", 3], [0, 0, -3, "-1/2"]],
  "B": [[0, 1], [1, 0], [1, 0], [0, 2]],
  "C": [[1, 0, 1, 0], [0, 1, 0, 1]],
  "D": [[0, 0], ["1/4", 0]]
}"#;

fn mimo_ss() -> StateSpace<Q> {
    let a = qmat![
        [-1, 1, 0, 0],
        [0, -1, 0, 0],
        [0, 0, "-1/2", 3],
        [0, 0, -3, "-1/2"]
    ];
    let b = qmat![[0, 1], [1, 0], [1, 0], [0, 2]];
    let c = qmat![[1, 0, 1, 0], [0, 1, 0, 1]];
    let d = qmat![[0, 0], ["1/4", 0]];
    StateSpace::new(a, b, c, d).expect("shapes")
}

fn approx(m: &Matrix<Q>) -> Vec<Vec<f64>> {
    (0..m.nrows())
        .map(|i| {
            (0..m.ncols())
                .map(|j| rational_to_f64(m.get(i, j)))
                .collect()
        })
        .collect()
}

#[test]
fn closed_form_identities_hold_exactly() {
    let ss = mimo_ss();
    let cf = ClosedFormResponse::new(&ss).expect("closed form");
    assert!(cf.verified);
    // the impulse response at 0+ is C B, the step response's limit D - C A^{-1} B
    assert_eq!(cf.impulse_at_zero, &ss.c * &ss.b);
    let dc = &ss.d - &(&(&ss.c * &ss.a.inverse().expect("invertible")) * &ss.b);
    assert_eq!(cf.dc_gain.as_ref().expect("A invertible"), &dc);
    // the float evaluations agree with them
    let h0 = cf.impulse_at(0.0);
    let s_inf = cf.step_at(60.0);
    let s0 = cf.step_at(0.0);
    for (i, (row, want)) in approx(&(&ss.c * &ss.b))
        .iter()
        .zip(&approx(&dc))
        .enumerate()
    {
        for j in 0..2 {
            assert!((h0[i][j] - row[j]).abs() < 1e-12);
            assert!((s_inf[i][j] - want[j]).abs() < 1e-12);
            assert!((s0[i][j] - rational_to_f64(ss.d.get(i, j))).abs() < 1e-14);
        }
    }
}

#[test]
fn closed_form_agrees_with_the_matrix_exponential() {
    let ss = mimo_ss();
    let cf = ClosedFormResponse::new(&ss).expect("closed form");
    let f = |m: &Matrix<Q>| exactlti::float::to_dmatrix(m).expect("finite");
    let (a, b, c, d) = (f(&ss.a), f(&ss.b), f(&ss.c), f(&ss.d));
    let ts = time_grid(12.0, 400);
    let st = exactlti::float::time_response(exactlti::float::Input::Step, [&a, &b, &c, &d], &ts)
        .expect("step");
    let im = exactlti::float::time_response(exactlti::float::Input::Impulse, [&a, &b, &c, &d], &ts)
        .expect("impulse");
    for (k, &t) in ts.iter().enumerate() {
        let (se, ie) = (cf.step_at(t), cf.impulse_at(t));
        for i in 0..2 {
            for j in 0..2 {
                assert!((se[i][j] - st[k][(i, j)]).abs() < 1e-9, "step at {t}");
                assert!((ie[i][j] - im[k][(i, j)]).abs() < 1e-9, "impulse at {t}");
            }
        }
    }
}

#[test]
fn integrator_has_no_dc_gain_and_a_ramp_step_response() {
    // 1/s^2 (double integrator): step response t^2/2 from the t^k term with theta = 0
    let ss = StateSpace::new(
        qmat![[0, 1], [0, 0]],
        qmat![[0], [1]],
        qmat![[1, 0]],
        qmat![[0]],
    )
    .expect("shapes");
    let cf = ClosedFormResponse::new(&ss).expect("closed form");
    assert!(cf.verified && cf.dc_gain.is_none());
    for t in [0.0, 0.5, 3.0] {
        assert!((cf.step_at(t)[0][0] - t * t / 2.0).abs() < 1e-12);
        assert!((cf.impulse_at(t)[0][0] - t).abs() < 1e-12);
    }
}

#[test]
fn step_command_plot_and_values() {
    let file = tmp("mimo.json", MIMO);
    let svg = file.with_extension("step.svg");
    let csv = file.with_extension("step.csv");
    let j = run(&[
        "step",
        file.to_str().unwrap(),
        "--points",
        "300",
        "--svg",
        svg.to_str().unwrap(),
        "--csv",
        csv.to_str().unwrap(),
    ]);
    assert_eq!(j["verified"], true);
    assert_eq!(j["stable"], true);
    assert!(j["method"].as_str().unwrap().starts_with("exact"));
    // the exact DC gain D - C A^{-1} B and the response's last value (the horizon covers
    // seven time constants of the slowest pole: within e^-7 times a modest factor)
    let ss = mimo_ss();
    let dc = &ss.d - &(&(&ss.c * &ss.a.inverse().unwrap()) * &ss.b);
    let want = approx(&dc);
    for i in 0..2 {
        for jj in 0..2 {
            assert_eq!(
                j["dc_gain"][i][jj].as_str().unwrap(),
                dc.get(i, jj).to_string()
            );
            let last = j["response"][299][i][jj].as_f64().unwrap();
            assert!((last - want[i][jj]).abs() < 0.02 * (1.0 + want[i][jj].abs()));
        }
    }
    assert!(j["float_max_difference"].as_f64().unwrap() < 1e-8);
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(well_formed(&text) > 20);
    for want in [
        "test rig &lt;A&amp;B&gt;: step response",
        "time [s]",
        "position",
        "angle",
        "force \u{2192} angle",
        "final value (exact DC gain)",
    ] {
        assert!(text.contains(want), "missing {want}");
    }
    // four panels: one per channel
    assert_eq!(text.matches(" \u{2192} ").count(), 4);
    let table = std::fs::read_to_string(&csv).unwrap();
    assert!(table.starts_with(
        "time_s,force -> position,torque -> position,force -> angle,torque -> angle\n"
    ));
    assert_eq!(table.lines().count(), 301);
}

#[test]
fn impulse_command_starts_at_cb() {
    let file = tmp("mimo-impulse.json", MIMO);
    let svg = file.with_extension("impulse.svg");
    let j = run(&[
        "impulse",
        file.to_str().unwrap(),
        "--to",
        "5",
        "--points",
        "101",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    let ss = mimo_ss();
    let cb = &ss.c * &ss.b;
    let want = approx(&cb);
    for i in 0..2 {
        for jj in 0..2 {
            assert_eq!(
                j["initial_value"][i][jj].as_str().unwrap(),
                cb.get(i, jj).to_string()
            );
            let v = j["response"][0][i][jj].as_f64().unwrap();
            assert!((v - want[i][jj]).abs() < 1e-12);
        }
    }
    assert_eq!(j["times_s"][100].as_f64(), Some(5.0));
    assert!(j["note"].as_str().unwrap().contains("delta"));
    let text = std::fs::read_to_string(&svg).unwrap();
    well_formed(&text);
    assert!(text.contains("torque \u{2192} position"));
}

#[test]
fn float_only_step_for_a_quadratic_field() {
    let file = tmp(
        "sqrt2.json",
        r#"{"A": [["-sqrt(2)", 1], [0, -1]], "B": [[0], [1]], "C": [[1, 0]], "D": [[0]]}"#,
    );
    // issue 23: the closed form is exact over Q(sqrt 2) too; --float keeps the float path
    let j = run(&["step", file.to_str().unwrap(), "--points", "50"]);
    assert!(
        j["method"]
            .as_str()
            .unwrap()
            .starts_with("exact closed form")
    );
    assert_eq!(j["dc_gain"], serde_json::json!([["sqrt(2)/2"]]));
    let jf = run(&["step", file.to_str().unwrap(), "--points", "50", "--float"]);
    assert!(jf["method"].as_str().unwrap().starts_with("float"));
    // DC gain of 1/((s + sqrt 2)(s + 1)) is 1/sqrt(2)
    for j in [j, jf] {
        let last = j["response"][49][0][0].as_f64().unwrap();
        assert!((last - 0.5f64.sqrt()).abs() < 1e-2);
    }
}

#[test]
fn pzmap_markers_match_the_poles() {
    // 2x2 Jordan block at -1 (one marker, multiplicity 2), a complex pair, zeros
    let file = tmp("mimo-pz.json", MIMO);
    let svg = file.with_extension("pz.svg");
    let j = run(&[
        "pzmap",
        file.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(j["exact"], true);
    assert_eq!(j["pole_count"], 4);
    let poles = j["poles"].as_array().unwrap();
    assert_eq!(poles.len(), 3);
    let values: Vec<&str> = poles.iter().map(|p| p["value"].as_str().unwrap()).collect();
    assert!(
        values.contains(&"-1") && values.contains(&"-1/2 + 3*i"),
        "{values:?}"
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    well_formed(&text);
    assert_eq!(text.matches("class=\"pole\"").count(), poles.len());
    let mult: usize = text
        .match_indices("class=\"pole\" data-multiplicity=\"")
        .map(|(k, m)| {
            let rest = &text[k + m.len()..];
            rest[..rest.find('"').unwrap()].parse::<usize>().unwrap()
        })
        .sum();
    assert_eq!(mult, 4);
    let zeros = j["zeros"].as_array().unwrap();
    assert_eq!(text.matches("class=\"zero\"").count(), zeros.len());
    for want in [
        "test rig &lt;A&amp;B&gt;: poles and zeros",
        "real part [1/s]",
        "imaginary part [rad/s]",
        "poles (4)",
    ] {
        assert!(text.contains(want), "missing {want}");
    }
}

#[test]
fn bode_svg_has_both_panels_and_named_channels() {
    let file = tmp("mimo-bode.json", MIMO);
    let svg = file.with_extension("bode.svg");
    let j = run(&[
        "freqresp",
        file.to_str().unwrap(),
        "--from",
        "0.01",
        "--to",
        "10",
        "--points",
        "50",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    // the JSON keeps the requested log grid; the plot's grid is refined near the pair
    assert_eq!(j["frequencies_hz"].as_array().unwrap().len(), 50);
    let text = std::fs::read_to_string(&svg).unwrap();
    well_formed(&text);
    for want in [
        "test rig &lt;A&amp;B&gt;: Bode plot",
        "magnitude [dB]",
        "phase [deg]",
        "frequency [Hz]",
        "torque \u{2192} angle",
    ] {
        assert!(text.contains(want), "missing {want}");
    }
    let grid = exactlti::cli::plots::bode_grid(0.01, 10.0, 50, &[(-0.5, 3.0), (-0.5, -3.0)]);
    let wn = 9.25f64.sqrt();
    let (fnat, zeta) = (wn / (2.0 * std::f64::consts::PI), 0.5 / wn);
    let near = grid
        .iter()
        .filter(|f| (**f / fnat - 1.0).abs() <= 8.0 * zeta + 1e-12)
        .count();
    // 41 added across f_n (1 +- 8 zeta), besides the log grid's own
    assert!(near >= 41 + 5, "{near} points near the resonance");
}

/// The x pixel of the tick label `label` (a `<text>` element with that exact content).
fn tick_x(svg: &str, label: &str) -> Option<f64> {
    svg.lines()
        .find(|l| l.starts_with("<text x=\"") && l.ends_with(&format!(">{label}</text>")))
        .and_then(|l| l[9..].split('"').next()?.parse().ok())
}

#[test]
fn bode_svg_of_a_complex_system_is_two_sided() {
    // poles -1/10 + 2i (resonance at +2 rad/s) and -1/20 - i (at -1 rad/s)
    let file = tmp(
        "qi-bode.json",
        r#"{"name": "over Q(i)", "inputs": ["u"], "outputs": ["y", "z"],
            "A": [["-1/10 + 2*i", 1], [0, "-1/20 - i"]], "B": [[1], [1]],
            "C": [[1, "i"], [0, 1]]}"#,
    );
    let svg = file.with_extension("bode.svg");
    let j = run(&[
        "freqresp",
        file.to_str().unwrap(),
        "--from",
        "0.01",
        "--to",
        "10",
        "--points",
        "60",
        "--svg",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(j["two_sided"], true);
    let text = std::fs::read_to_string(&svg).unwrap();
    well_formed(&text);
    for want in [
        "over Q(i): Bode plot",
        "negative frequencies (f &lt; 0)",
        "positive frequencies (f &gt; 0)",
        "frequency [Hz], f &lt; 0",
        "frequency [Hz], f &gt; 0",
        "magnitude [dB]",
        "phase [deg]",
        "u \u{2192} y",
        "u \u{2192} z",
    ] {
        assert!(text.contains(want), "missing {want}");
    }
    // two channels in four panels (magnitude and phase, each side)
    assert_eq!(text.matches("<polyline").count(), 8);
    // the negative side's axis is mirrored: -10 Hz on its left, -0.01 Hz on its right, and
    // both left of the positive side's 0.01 Hz
    let (a, b, c) = (
        tick_x(&text, "-10").expect("tick -10"),
        tick_x(&text, "-0.01").expect("tick -0.01"),
        tick_x(&text, "0.01").expect("tick 0.01"),
    );
    assert!(a < b && b < c, "{a} {b} {c}");
    // the grid is refined near each resonance on its own side
    let poles = [(-0.1, 2.0), (-0.05, -1.0)];
    let grid = exactlti::cli::plots::bode_grid_two_sided(0.01, 10.0, 60, &poles);
    assert!(grid.windows(2).all(|w| w[0] < w[1]), "increasing");
    let near = |f0: f64| grid.iter().filter(|f| (**f / f0 - 1.0).abs() < 0.2).count();
    let tau = 2.0 * std::f64::consts::PI;
    assert!(near(2.0 / tau) >= 20, "{}", near(2.0 / tau));
    assert!(near(-1.0 / tau) >= 20, "{}", near(-1.0 / tau));
    assert!(near(-2.0 / tau) < 10 && near(1.0 / tau) < 10);
}

#[test]
fn bode_svg_of_a_real_system_stays_one_sided() {
    let file = tmp("mimo-bode-1.json", MIMO);
    let svg = file.with_extension("bode1.svg");
    run(&[
        "freqresp",
        file.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
    ]);
    let text = std::fs::read_to_string(&svg).unwrap();
    well_formed(&text);
    assert!(!text.contains("negative frequencies"));
    assert!(!text.contains("f &lt; 0"));
    assert!(text.contains(">frequency [Hz]</text>"));
    // four channels as a 2 x 2 output x input grid, each a magnitude and a phase panel
    assert_eq!(text.matches("<polyline").count(), 8);
    assert_eq!(text.matches(r##"fill="none" stroke="#333""##).count(), 8);
    assert!(tick_x(&text, "-10").is_none() && tick_x(&text, "-0.01").is_none());
}
