//! The layering of `src/` cannot regress: `scripts/layers.py` (the import graph between
//! top-level modules) finds no cycle and no arrow up a floor (field -> poly -> matrix ->
//! jordan -> system -> realization -> structure; io, study; report, cli on top), and it does
//! report a planted violation; no two files of `src/` reach each other either (a file-level
//! cycle fails the script too).

use std::path::Path;
use std::process::Command;

fn layers(script: &Path) -> (i32, String) {
    let out = Command::new("python3")
        .arg(script)
        .output()
        .expect("python3 runs scripts/layers.py");
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    (out.status.code().unwrap_or(-1), text)
}

#[test]
fn src_has_no_layer_cycle_and_no_arrow_up_a_floor() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let (code, text) = layers(&root.join("scripts/layers.py"));
    assert_eq!(code, 0, "{text}");
    assert!(text.contains("top-level cycles: 0"), "{text}");
    assert!(text.contains("arrows up a floor: 0"), "{text}");
    assert!(text.contains("file-level cycles: 0"), "{text}");
}

/// `scripts/layers.py` run on a tree of its own holding only `files` (path, text) under
/// `src/`: its exit code and output.
fn layers_of_planted(name: &str, files: &[(&str, &str)]) -> (i32, String) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("scripts")).unwrap();
    std::fs::copy(
        root.join("scripts/layers.py"),
        dir.join("scripts/layers.py"),
    )
    .unwrap();
    for (path, text) in files {
        let p = dir.join("src").join(path);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, text).unwrap();
    }
    let out = layers(&dir.join("scripts/layers.py"));
    let _ = std::fs::remove_dir_all(&dir);
    out
}

#[test]
fn a_planted_arrow_up_a_floor_and_a_cycle_are_reported() {
    // field (floor 1) reaching up into jordan (floor 5), and jordan using field: a cycle
    let (code, text) = layers_of_planted(
        "exactlti-layers",
        &[
            ("field/mod.rs", "use crate::jordan::x;\n"),
            ("jordan/mod.rs", "use crate::field::y;\n"),
        ],
    );
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("arrows up a floor: 1"), "{text}");
    assert!(text.contains("field <-> jordan"), "{text}");
}

#[test]
fn a_planted_file_level_cycle_fails_the_check() {
    // two files of one module that use each other: no top-level cycle, no arrow up
    let (code, text) = layers_of_planted(
        "exactlti-layers-files",
        &[
            ("jordan/mod.rs", "mod a;\nmod b;\n"),
            ("jordan/a.rs", "use super::b::x;\n"),
            ("jordan/b.rs", "use super::a::y;\n"),
        ],
    );
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("top-level cycles: 0"), "{text}");
    assert!(text.contains("arrows up a floor: 0"), "{text}");
    assert!(text.contains("file-level cycles: 1"), "{text}");
    assert!(text.contains("jordan::a <-> jordan::b"), "{text}");
}
