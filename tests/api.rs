//! The front door (`exactlti::api`, issue 24): one loader that decides the field from what
//! the file says, one dispatch over the fields, commands parsed from their arguments and run
//! on a system already read, `--at` accepted by every command (the same report as the
//! file with the value written in), and the worker with a deadline.

use exactlti::api::runner::{Poll, Worker};
use exactlti::api::{Command, Options, RunContext, System, execute_on, execute_with};
use exactlti::io::{Ground, SystemFormat};
use exactlti::rng::SplitMix64;

const FAMILY: &str = r#"{"parameters": {"c": "3"},
 "A": [[0, 1, 0], [-2, "-c", 0], [0, 0, -1]], "B": [[0], [1], [1]], "C": [[1, 0, 0]], "D": [[0]]}"#;

fn temp_file(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-api");
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

fn json(cmd: &Command, at: Option<&str>) -> Result<serde_json::Value, String> {
    execute_with(cmd, None, at)
        .map(|o| o.report.to_json())
        .map_err(|f| f.message)
}

#[test]
fn the_field_is_what_the_file_says() {
    let o = Options::default();
    let q = System::from_text(FAMILY, SystemFormat::Json, "f.json", &o).unwrap();
    assert_eq!(q.ground(), &Ground::Rational);
    // the word "null" or "symbols" inside a name is not a symbol (no sniffing of the text)
    let named = FAMILY.replace(
        r#"{"parameters""#,
        r#"{"name": "null symbols", "parameters""#,
    );
    let s = System::from_text(&named, SystemFormat::Json, "n.json", &o).unwrap();
    assert_eq!(s.ground(), &Ground::Rational);
    assert_eq!(s.file().name.as_deref(), Some("null symbols"));
    // a null value, a `symbols` list, or --symbolic keep symbols
    let null = FAMILY.replace(r#""c": "3""#, r#""c": null"#);
    let s = System::from_text(&null, SystemFormat::Json, "s.json", &o).unwrap();
    assert_eq!(s.ground().to_string(), "QQ(c)");
    let listed = FAMILY.replace(r#"{"parameters""#, r#"{"symbols": ["c"], "parameters""#);
    let s = System::from_text(&listed, SystemFormat::Json, "l.json", &o).unwrap();
    assert_eq!(s.ground().to_string(), "QQ(c)");
    let sym = Options::from_args(Some("c"), None).unwrap();
    let s = System::from_text(FAMILY, SystemFormat::Json, "f.json", &sym).unwrap();
    assert_eq!(s.ground().to_string(), "QQ(c)");
    // --at gives the value back
    let at = Options::from_args(None, Some("c=1/2")).unwrap();
    let s = System::from_text(&null, SystemFormat::Json, "s.json", &at).unwrap();
    assert_eq!(s.ground(), &Ground::Rational);
    assert_eq!(
        s.loaded().rational().unwrap().ss.a.get(1, 1).to_string(),
        "-1/2"
    );
    // open reads the file once and remembers it
    let p = temp_file("f.json", FAMILY);
    let f = System::open(&p, &o).unwrap();
    assert!(f.from_file() && f.path() == p.as_path());
    assert!(!q.from_file());
}

#[test]
fn every_command_takes_at_like_the_file_with_the_value() {
    // a generator of values for c (fixed seed): `CMD FILE --at c=v` reports exactly what
    // `CMD FILE'` reports for FILE' = FILE with c = v written in
    let mut rng = SplitMix64(24);
    let p = temp_file("at.json", FAMILY);
    for case in 0..4 {
        let v = format!("{}/{}", rng.int(-4, 4), rng.int(1, 3));
        let written = temp_file(
            &format!("w{case}.json"),
            &FAMILY.replace(r#""3""#, &format!("\"{v}\"")),
        );
        for op in ["tf", "ctrb", "obsv", "pencil", "zeros", "minreal", "scb"] {
            let at = Command::parse_args(&[op, p.to_str().unwrap()]).unwrap();
            let direct = Command::parse_args(&[op, written.to_str().unwrap()]).unwrap();
            let a = json(&at, Some(&format!("c={v}")));
            let b = json(&direct, None);
            assert_eq!(a, b, "{op} --at c={v}");
            assert!(a.is_ok(), "{op}: {a:?}");
        }
    }
    // an unknown name is one line naming it
    let cmd = Command::parse_args(&["tf", p.to_str().unwrap()]).unwrap();
    let e = json(&cmd, Some("x=1")).unwrap_err();
    assert!(e.contains("--at: unknown parameter 'x'"), "{e}");
}

#[test]
fn commands_run_on_a_system_already_read() {
    // a system from text (no file): the same report as from its file
    let o = Options::default();
    let text = FAMILY.replace("-c", "-c*sqrt(2)");
    let s = System::from_text(&text, SystemFormat::Json, "k.json", &o).unwrap();
    assert_eq!(s.ground().to_string(), "QQ(sqrt(2))");
    let p = temp_file("k.json", &text);
    for args in [
        vec!["jordan"],
        vec!["modes"],
        vec!["mnf"],
        vec!["zeros"],
        vec!["minreal", "--method", "jordan"],
        vec!["pencil"],
        vec!["tf"],
    ] {
        let mut a = vec![args[0], "k.json"];
        a.extend(&args[1..]);
        let on = execute_on(
            &Command::parse_args(&a).unwrap(),
            &s,
            &RunContext::default(),
        );
        let on = on
            .map(|o| (o.verified, o.report.to_json()))
            .map_err(|f| f.message);
        let mut b = vec![args[0], p.to_str().unwrap()];
        b.extend(&args[1..]);
        let from_file = json(&Command::parse_args(&b).unwrap(), None);
        let (ok, on) = on.unwrap_or_else(|m| panic!("{args:?}: {m}"));
        assert!(ok, "{args:?} verified");
        assert_eq!(Ok(on), from_file, "{args:?}");
    }
    // a sweep over Q(sqrt 2) reads the system's own text again at each value: the same
    // report from text as from the file
    let sweep = |f: &str| {
        Command::parse_args(&[
            "sweep", f, "--param", "c", "--from", "0", "--to", "1", "--points", "5",
        ])
        .unwrap()
    };
    let on = execute_on(&sweep("k.json"), &s, &RunContext::default()).unwrap();
    assert_eq!(
        Ok(on.report.to_json()),
        json(&sweep(p.to_str().unwrap()), None)
    );
    // the exact study over Q(v) reads its file: a system from text is refused
    let q = System::from_text(FAMILY, SystemFormat::Json, "q.json", &o).unwrap();
    let e = execute_on(&sweep("q.json"), &q, &RunContext::default()).unwrap_err();
    assert!(e.message.contains("reads its system file"), "{}", e.message);
}

#[test]
fn arguments_parse_like_the_command_line() {
    assert!(matches!(
        Command::parse_args(&["step", "f.json", "--to", "2"]),
        Ok(Command::Step { .. })
    ));
    let e = Command::parse_args(&["nosuch", "f.json"]).unwrap_err();
    assert!(e.contains("nosuch"), "{e}");
    assert_eq!(e.lines().count(), 1);
}

#[test]
fn the_worker_stops_waiting_at_the_deadline() {
    let w = Worker::spawn("t", Worker::<()>::deadline_in(Some(0.05)), || {
        std::thread::sleep(std::time::Duration::from_secs(5))
    })
    .unwrap();
    let t = std::time::Instant::now();
    assert!(matches!(w.wait(), Poll::TimedOut));
    assert!(t.elapsed().as_secs_f64() < 4.0);
}

/// A random system over Q(p) (`A0`, `B0`, `C1`, algebraic weights `w`, gain `c`) as two files:
/// the descriptor system with one algebraic state $0 = w x - x_{n+1}$ and $y = C_1 x + c\,x_{n+1}$,
/// and the standard system $(A_0, B_0, C_1 + c w)$ it eliminates to.
fn descriptor_and_eliminated(rng: &mut SplitMix64, n: usize) -> (String, String) {
    let int = |rng: &mut SplitMix64| rng.int(-3, 3);
    let entry = |rng: &mut SplitMix64, i: usize, j: usize| -> String {
        // one symbolic entry on the diagonal, integers elsewhere
        if i == j && i == 0 {
            format!("\"p + {}\"", int(rng))
        } else {
            int(rng).to_string()
        }
    };
    let a0: Vec<Vec<String>> = (0..n)
        .map(|i| (0..n).map(|j| entry(rng, i, j)).collect())
        .collect();
    let b0: Vec<i64> = (0..n).map(|_| int(rng)).collect();
    let c1: Vec<i64> = (0..n).map(|_| int(rng)).collect();
    let w: Vec<i64> = (0..n).map(|_| int(rng)).collect();
    let c = rng.int(1, 3);
    let row = |v: Vec<String>| format!("[{}]", v.join(", "));
    let mut a = Vec::new();
    let mut e = Vec::new();
    for (i, r) in a0.iter().enumerate() {
        let mut r = r.clone();
        r.push("0".into());
        a.push(row(r));
        e.push(row((0..=n).map(|j| u8::from(i == j).to_string()).collect()));
    }
    let mut last: Vec<String> = w.iter().map(i64::to_string).collect();
    last.push("-1".into());
    a.push(row(last));
    e.push(row(vec!["0".to_string(); n + 1]));
    let bcol = |v: &[i64], extra: bool| {
        let mut rows: Vec<String> = v.iter().map(|x| format!("[{x}]")).collect();
        if extra {
            rows.push("[0]".into());
        }
        format!("[{}]", rows.join(", "))
    };
    let mut cd: Vec<String> = c1.iter().map(i64::to_string).collect();
    cd.push(c.to_string());
    let desc = format!(
        r#"{{"parameters": {{"p": null}}, "E": [{}], "A": [{}], "B": {}, "C": [{}], "D": [[0]]}}"#,
        e.join(", "),
        a.join(", "),
        bcol(&b0, true),
        row(cd)
    );
    let cs: Vec<String> = (0..n).map(|j| (c1[j] + c * w[j]).to_string()).collect();
    let std = format!(
        r#"{{"parameters": {{"p": null}}, "A": [{}], "B": {}, "C": [{}], "D": [[0]]}}"#,
        a0.iter()
            .map(|r| row(r.clone()))
            .collect::<Vec<_>>()
            .join(", "),
        bcol(&b0, false),
        row(cs)
    );
    (desc, std)
}

#[test]
fn tf_of_a_descriptor_over_qp_is_the_pencils() {
    // class: index-1 descriptor systems over Q(p) (one algebraic state); `tf` gives the
    // transfer matrix of the pencil, which is that of the eliminated standard system, and
    // with `--at p=v` the numeric `tf` of the same file
    let mut rng = SplitMix64(2424);
    for case in 0..6 {
        let (desc, std) = descriptor_and_eliminated(&mut rng, 1 + case % 3);
        let d = temp_file(&format!("qpd{case}.json"), &desc);
        let s = temp_file(&format!("qps{case}.json"), &std);
        let tf = |p: &std::path::Path, at: Option<&str>| {
            let cmd = Command::parse_args(&["tf", p.to_str().unwrap()]).unwrap();
            json(&cmd, at).unwrap_or_else(|m| panic!("{desc}: {m}"))
        };
        let (gd, gs) = (tf(&d, None), tf(&s, None));
        assert_eq!(gd["verified"], true, "{desc}");
        assert_eq!(gd["field"], "QQ(p)");
        assert_eq!(
            gd["transfer_matrix"], gs["transfer_matrix"],
            "{desc}\n{std}"
        );
        assert_eq!(gd["mcmillan_degree"], gs["mcmillan_degree"], "{desc}");
        let (nd, ns) = (tf(&d, Some("p=2/3")), tf(&s, Some("p=2/3")));
        assert_eq!(nd["transfer_matrix"], ns["transfer_matrix"], "{desc}");
        assert_eq!(nd["verified"], true);
    }
}
