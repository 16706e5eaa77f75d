//! Running the `exactlti` binary from the integration tests.
use std::process::Command;

/// Runs `exactlti ARGS` in the crate's directory: exit code (-1 when killed by a signal),
/// stdout and stderr.
pub fn run(args: &[&str]) -> (i32, String, String) {
    let out = limited(args).output().expect("runs");
    outputs(&out)
}

/// The address-space limit of every binary run by the suite (issue 22: no command aborts on
/// a 4 GB machine; past its `--max-memory` or this limit it refuses with exit 2).
pub const ADDRESS_SPACE_BYTES: u64 = 4 << 30;

/// `exactlti ARGS` in the crate's directory under [`ADDRESS_SPACE_BYTES`].
fn limited(args: &[&str]) -> Command {
    use std::os::unix::process::CommandExt;
    let mut c = Command::new(env!("CARGO_BIN_EXE_exactlti"));
    c.args(args).current_dir(env!("CARGO_MANIFEST_DIR"));
    // SAFETY: setrlimit is async-signal-safe; nothing else runs between fork and exec.
    unsafe {
        c.pre_exec(|| {
            let lim = libc::rlimit {
                rlim_cur: ADDRESS_SPACE_BYTES as libc::rlim_t,
                rlim_max: ADDRESS_SPACE_BYTES as libc::rlim_t,
            };
            if libc::setrlimit(libc::RLIMIT_AS, &lim) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    c
}

/// As [`run`], with `input` written to the program's stdin through a pipe.
pub fn run_stdin(args: &[&str], input: &str) -> (i32, String, String) {
    use std::io::Write;
    use std::process::Stdio;
    let mut child = limited(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("runs");
    let mut stdin = child.stdin.take().unwrap();
    let text = input.to_string();
    let writer = std::thread::spawn(move || {
        let _ = stdin.write_all(text.as_bytes());
    });
    let out = child.wait_with_output().expect("runs");
    writer.join().unwrap();
    outputs(&out)
}

fn outputs(out: &std::process::Output) -> (i32, String, String) {
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Writes `text` to `name` in a directory of its own per test module (`tag`) under cargo's
/// `target/tmp` (so modules running in parallel never share a file, and a test run leaves
/// nothing in the system's temporary directory: the files are overwritten by the next run).
pub fn temp_file(tag: &str, name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("exactlti-{tag}"));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// Runs the CLI with `--format json` appended, asserts exit 0, and parses the output.
pub fn run_json(args: &[&str]) -> serde_json::Value {
    let mut a = args.to_vec();
    a.extend(["--format", "json"]);
    json_of(&a)
}

/// The `step` names of a derivation's JSON (`steps: [{step, ...}]`), in order.
pub fn step_names(j: &serde_json::Value) -> Vec<String> {
    j["steps"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["step"].as_str().unwrap().to_string())
        .collect()
}

/// Runs the CLI with `args` as given (they name `--format json`), asserts exit 0, and parses
/// the output (the message names the arguments, stderr, and the text that is not JSON).
pub fn json_of(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("invalid JSON for {args:?}: {e}\n{out}"))
}
