//! Reading system files (issue 17 item 6): `cargo bench --bench io`.
//!
//! Target: a 200x200 integer system file (A, B 200x5, C 5x200; entries in [-99, 99]) read,
//! validated and typed over Q (`load_system_str`, the library path of every command) in
//! <= 20 ms. Also the same as a MATLAB-style string, a 100x100 file with 20-digit decimals,
//! and a TOML file. Output: `name: best ms (median ms, reps)`.

#[path = "common.rs"]
mod common;

use common::{bench, selected};
use exactlti::io::{SystemFormat, load_system_str};
use exactlti::rng::SplitMix64 as Rng;

fn rows(rng: &mut Rng, r: usize, c: usize, entry: &mut dyn FnMut(&mut Rng) -> String) -> String {
    let rows: Vec<String> = (0..r)
        .map(|_| {
            let xs: Vec<String> = (0..c).map(|_| entry(rng)).collect();
            format!("[{}]", xs.join(", "))
        })
        .collect();
    format!("[{}]", rows.join(",\n "))
}

fn system_json(n: usize, entry: &mut dyn FnMut(&mut Rng) -> String) -> String {
    let mut rng = Rng(17);
    let a = rows(&mut rng, n, n, entry);
    let b = rows(&mut rng, n, 5, entry);
    let c = rows(&mut rng, 5, n, entry);
    format!("{{\"A\": {a},\n\"B\": {b},\n\"C\": {c}}}")
}

fn main() {
    let mut int = |r: &mut Rng| r.int(-99, 99).to_string();
    let json200 = system_json(200, &mut int);
    if selected("read_200x200_int_json") {
        println!("file size {} bytes", json200.len());
        bench("read_200x200_int_json", 5, 2000.0, || {
            load_system_str(&json200, SystemFormat::Json, "b.json").expect("valid")
        });
    }
    if selected("read_200x200_int_toml") {
        let toml = json200
            .trim_start_matches('{')
            .trim_end_matches('}')
            .replace("\"A\": ", "A = ")
            .replace(",\n\"B\": ", "\nB = ")
            .replace(",\n\"C\": ", "\nC = ");
        bench("read_200x200_int_toml", 5, 2000.0, || {
            load_system_str(&toml, SystemFormat::Toml, "b.toml").expect("valid")
        });
    }
    if selected("read_200x200_int_strings") {
        let quoted = system_json(200, &mut |r: &mut Rng| format!("\"{}\"", r.int(-99, 99)));
        bench("read_200x200_int_strings", 5, 2000.0, || {
            load_system_str(&quoted, SystemFormat::Json, "s.json").expect("valid")
        });
    }
    if selected("read_100x100_decimal_json") {
        let dec = system_json(100, &mut |r: &mut Rng| {
            format!(
                "{}.{:010}{:010}",
                r.int(0, 999),
                r.int(0, 1 << 30),
                r.int(0, 1 << 30)
            )
        });
        bench("read_100x100_decimal_json", 5, 2000.0, || {
            load_system_str(&dec, SystemFormat::Json, "d.json").expect("valid")
        });
    }
}
