//! Mutation fuzzer (issue 17, item 7): byte flips, token swaps, number and row edits of the
//! example and test system files, fed to the library loader and, when they load as a small
//! system, to every command in-process. A fixed seed, a few thousand cases, a per-run time
//! bound: no panic, no hang, and every error a one-line message. Longer runs through the
//! binary: `scripts/fuzz.sh`.
//!
//! `EXACTLTI_FUZZ_CASES` and `EXACTLTI_FUZZ_SEED` change the run.

use exactlti::cli::{Command, LinalgOp, MethodArg, execute};
use exactlti::io::{SystemFormat, load_system_str};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// SplitMix64.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E3779B97F4A7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58476D1CE4E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D049BB133111EB);
        z ^ (z >> 31)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

const CHARS: &[u8] = b"0123456789-+./*^()[]{},:\"eEi =#\nsqrt";
const NUMBERS: &[&str] = &[
    "0",
    "-1",
    "1",
    "2",
    "1e300",
    "-1e-300",
    "0.0",
    "1/3",
    "\"1/0\"",
    "\"0/0\"",
    "3.5e7",
    "123456789012345678901234567890",
    "\"x\"",
    "\"i\"",
    "\"sqrt(2)\"",
    "\"2i^2\"",
    "null",
    "[]",
    "[[]]",
    "true",
    "\"1e99999\"",
    "-0",
    "\"(1+i)^40\"",
];

/// Spans of numbers, quoted strings and bare words.
fn tokens(t: &[u8]) -> Vec<(usize, usize)> {
    let mut out = vec![];
    let mut i = 0;
    while i < t.len() {
        let c = t[i];
        if c == b'"' {
            let s = i;
            i += 1;
            while i < t.len() && t[i] != b'"' {
                i += 1;
            }
            i = (i + 1).min(t.len());
            out.push((s, i));
        } else if c.is_ascii_alphanumeric() || c == b'-' || c == b'.' {
            let s = i;
            while i < t.len() && (t[i].is_ascii_alphanumeric() || b"-.+/".contains(&t[i])) {
                i += 1;
            }
            out.push((s, i));
        } else {
            i += 1;
        }
    }
    out
}

/// Innermost `[...]` spans (matrix rows).
fn rows(t: &[u8]) -> Vec<(usize, usize)> {
    let mut out = vec![];
    let mut open = None;
    for (i, &c) in t.iter().enumerate() {
        if c == b'[' {
            open = Some(i);
        } else if c == b']'
            && let Some(s) = open.take()
        {
            out.push((s, i + 1));
        }
    }
    out
}

fn mutate(src: &[u8], g: &mut Rng) -> Vec<u8> {
    let mut t = src.to_vec();
    for _ in 0..1 + g.below(2) {
        if t.is_empty() {
            break;
        }
        match g.below(8) {
            0 if g.below(3) == 0 => {
                let i = g.below(t.len());
                t[i] = CHARS[g.below(CHARS.len())];
            }
            1 if g.below(3) == 0 => {
                let i = g.below(t.len());
                t.remove(i);
            }
            0 | 1 => {}
            2 => {
                let tk = tokens(&t);
                if tk.len() >= 2 {
                    let (a, b) = (tk[g.below(tk.len())], tk[g.below(tk.len())]);
                    let (x, y) = if a.0 < b.0 { (a, b) } else { (b, a) };
                    if x.1 <= y.0 {
                        let mut n = t[..x.0].to_vec();
                        n.extend_from_slice(&t[y.0..y.1]);
                        n.extend_from_slice(&t[x.1..y.0]);
                        n.extend_from_slice(&t[x.0..x.1]);
                        n.extend_from_slice(&t[y.1..]);
                        t = n;
                    }
                }
            }
            3 | 6 | 7 => {
                let tk = tokens(&t);
                if !tk.is_empty() {
                    let (s, e) = tk[g.below(tk.len())];
                    let mut n = t[..s].to_vec();
                    n.extend_from_slice(NUMBERS[g.below(NUMBERS.len())].as_bytes());
                    n.extend_from_slice(&t[e..]);
                    t = n;
                }
            }
            4 => {
                // delete or duplicate a row
                let r = rows(&t);
                if !r.is_empty() {
                    let (s, e) = r[g.below(r.len())];
                    let mut n = t[..s].to_vec();
                    if g.below(2) == 0 {
                        n.extend_from_slice(&t[s..e]);
                        n.extend_from_slice(b", ");
                        n.extend_from_slice(&t[s..e]);
                    } else {
                        // drop the row and a following comma
                        let mut e2 = e;
                        while e2 < t.len() && (t[e2] == b',' || t[e2] == b' ') {
                            e2 += 1;
                        }
                        n.extend_from_slice(&t[e2..]);
                        t = n;
                        continue;
                    }
                    n.extend_from_slice(&t[e..]);
                    t = n;
                }
            }
            _ => {
                // change a key: E = 0, drop a key, rename one
                let keys: &[&[u8]] = &[b"\"A\"", b"\"B\"", b"\"C\"", b"\"D\"", b"\"E\""];
                let k = keys[g.below(keys.len())];
                let k2 = keys[g.below(keys.len())];
                if let Some(p) = t.windows(k.len()).position(|w| w == k) {
                    t.splice(p..p + k.len(), k2.iter().copied());
                } else if t.first() == Some(&b'{') {
                    t.splice(1..1, b"\"E\": [[0]], ".iter().copied());
                }
            }
        }
    }
    t
}

fn corpus() -> Vec<(PathBuf, Vec<u8>)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut out = vec![];
    for dir in ["data", "tests/data"] {
        let mut files: Vec<PathBuf> = std::fs::read_dir(root.join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| {
                matches!(
                    p.extension().and_then(|e| e.to_str()),
                    Some("json" | "toml")
                )
            })
            // the fuzzer's own reproducers are regression cases, not seeds
            .filter(|p| {
                !p.file_name()
                    .unwrap()
                    .to_string_lossy()
                    .starts_with("fuzz_")
            })
            .collect();
        files.sort();
        for p in files {
            let t = std::fs::read(&p).unwrap();
            out.push((p, t));
        }
    }
    out
}

fn commands(file: &Path) -> Vec<Command> {
    let f = || file.to_path_buf();
    let mut v = vec![
        Command::Jordan {
            file: f(),
            real: false,
            expand: false,
            normalize: None,
        },
        Command::Standard { file: f() },
        Command::Scb { file: f() },
        Command::Mnf { file: f() },
        Command::Zeros { file: f() },
        Command::Modes { file: f() },
        Command::Freqresp {
            file: f(),
            from: Some(0.1),
            to: Some(10.0),
            points: 5,
            svg: None,
            csv: None,
        },
        Command::Check { file: f() },
        Command::Pencil { file: f() },
        Command::Ctrb { file: f() },
        Command::Obsv { file: f() },
        Command::Tf { file: f() },
    ];
    // `jordan --real` and Jordan-method `minreal`: re-enabled once the real-field marking
    // (`fuzz_jordan_marking.json`) and the slow real Jordan form (`fuzz_slow_real_jordan.json`,
    // `-1e-300` entries) were confirmed fixed (tests/slowpaths.rs). `analyze` runs every
    // section in one call and passes 10 s in a debug build on some mutants (its per-section
    // budgets are issue 11 item 3); `scripts/fuzz.sh` runs it through the release binary.
    v.push(Command::Jordan {
        file: f(),
        real: true,
        expand: false,
        normalize: None,
    });
    for method in [
        MethodArg::Kalman,
        MethodArg::Rosenbrock,
        MethodArg::HoKalman,
        MethodArg::Era,
        MethodArg::Jordan,
    ] {
        v.push(Command::Minreal {
            file: f(),
            method,
            hankel: None,
            descriptor: false,
        });
    }
    for op in [
        LinalgOp::Rank,
        LinalgOp::Det,
        LinalgOp::Charpoly,
        LinalgOp::Minpoly,
        LinalgOp::Inverse,
        LinalgOp::Nullspace,
        LinalgOp::Rref,
    ] {
        v.push(Command::Linalg { op, file: f() });
    }
    v
}

/// Internal failures already filed against another part (printed, not failed here); empty
/// since the real-field marking was fixed.
const KNOWN: &[&str] = &[];

/// Runs one command in a worker thread; `Err` describes a panic, a hang or a bad message.
fn run_bounded(cmd: Command, limit: Duration) -> Result<(), String> {
    let (tx, rx) = mpsc::channel();
    let what = format!("{cmd:?}");
    std::thread::Builder::new()
        .stack_size(64 << 20)
        .spawn(move || {
            let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| execute(&cmd)));
            let _ = tx.send(r);
        })
        .unwrap();
    match rx.recv_timeout(limit) {
        Ok(Ok(Ok(_))) => Ok(()),
        Ok(Ok(Err(f))) => {
            if f.message.contains('\n') || f.message.is_empty() {
                Err(format!("{what}: message not one line: {:?}", f.message))
            } else if f.code == 1 && KNOWN.iter().any(|k| f.message.contains(k)) {
                eprintln!("fuzz: known failure: {what}: {}", f.message);
                Ok(())
            } else if f.code == 1 {
                Err(format!("{what}: internal failure: {}", f.message))
            } else {
                Ok(())
            }
        }
        Ok(Err(_)) => Err(format!("{what}: panicked")),
        Err(_) => Err(format!("{what}: still running after {limit:?}")),
    }
}

#[test]
fn mutation_fuzz_loader_and_every_command() {
    let cases: usize = std::env::var("EXACTLTI_FUZZ_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1500);
    let seed: u64 = std::env::var("EXACTLTI_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(17);
    let corpus = corpus();
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-fuzz");
    std::fs::create_dir_all(&dir).unwrap();
    let mut g = Rng(seed);
    let mut failures = vec![];
    let (mut loaded, mut ran) = (0usize, 0usize);
    let start = Instant::now();
    for case in 0..cases {
        let (path, src) = &corpus[g.below(corpus.len())];
        let text = mutate(src, &mut g);
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("json");
        let format = if ext == "toml" {
            SystemFormat::Toml
        } else {
            SystemFormat::Json
        };
        let Ok(s) = String::from_utf8(text.clone()) else {
            continue;
        };
        let name = format!("case{case}.{ext}");
        let l = std::panic::catch_unwind(|| load_system_str(&s, format, &name));
        let l = match l {
            Err(_) => {
                failures.push(format!("{name} (from {}): loader panicked", path.display()));
                std::fs::write(dir.join(&name), &text).unwrap();
                continue;
            }
            Ok(Err(e)) => {
                let m = e.to_string();
                if m.contains('\n') {
                    failures.push(format!("{name}: loader message not one line: {m:?}"));
                }
                continue;
            }
            Ok(Ok(l)) => l,
        };
        loaded += 1;
        // commands on every third case, small systems only (the budget of the suite)
        let n = exactlti::api::System::from(l.clone()).run(Size);
        if n > 8 || case % 3 != 0 {
            continue;
        }
        let file = dir.join(&name);
        std::fs::write(&file, &text).unwrap();
        for cmd in commands(&file) {
            ran += 1;
            if let Err(e) = run_bounded(cmd, Duration::from_secs(10)) {
                eprintln!("FUZZ FAILURE {name} (from {}): {e}", path.display());
                failures.push(format!("{name} (from {}): {e}", path.display()));
            }
        }
        if failures.is_empty() {
            let _ = std::fs::remove_file(&file);
        }
    }
    eprintln!(
        "fuzz: {cases} cases, {loaded} loaded, {ran} command runs, {:?}",
        start.elapsed()
    );
    assert!(
        failures.is_empty(),
        "{} failures (kept in {}):\n{}",
        failures.len(),
        dir.display(),
        failures.join("\n")
    );
    let _ = std::fs::remove_dir_all(&dir);
}

struct Size;
impl exactlti::api::SystemVisitor for Size {
    type Output = usize;
    fn visit<K: exactlti::field::Field + 'static>(
        self,
        _f: &exactlti::io::SystemFile,
        t: &exactlti::io::TypedSystem<K>,
    ) -> usize {
        t.ss.nstates().max(t.ss.ninputs()).max(t.ss.noutputs())
    }
}
