//! The layering of `src/` cannot regress: `scripts/layers.py` (the import graph between
//! top-level modules) finds no cycle and no arrow up a floor (field -> poly -> matrix ->
//! jordan -> system -> realization -> structure; io, study; report, cli on top), and it does
//! report a planted violation.

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
}

#[test]
fn a_planted_arrow_up_a_floor_and_a_cycle_are_reported() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-layers");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("scripts")).unwrap();
    std::fs::create_dir_all(dir.join("src/field")).unwrap();
    std::fs::create_dir_all(dir.join("src/jordan")).unwrap();
    std::fs::copy(
        root.join("scripts/layers.py"),
        dir.join("scripts/layers.py"),
    )
    .unwrap();
    // field (floor 1) reaching up into jordan (floor 5), and jordan using field: a cycle
    std::fs::write(dir.join("src/field/mod.rs"), "use crate::jordan::x;\n").unwrap();
    std::fs::write(dir.join("src/jordan/mod.rs"), "use crate::field::y;\n").unwrap();
    let (code, text) = layers(&dir.join("scripts/layers.py"));
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(code, 1, "{text}");
    assert!(text.contains("arrows up a floor: 1"), "{text}");
    assert!(text.contains("field <-> jordan"), "{text}");
}
