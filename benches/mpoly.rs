//! Multivariate polynomials and Q(p): wall-clock timings (release build, std::time).
//!
//! `cargo bench --bench mpoly` prints `name: X ms` (median of repeated runs) per case and
//! writes the inputs to `target/mpoly-bench-cases.txt` (tab-separated: kind, name, variables,
//! then the data) so `scripts/anchors/mpoly.py` times SymPy and FLINT on the same inputs.
//!
//! Cases: charpoly of an 8x8 matrix with entries linear in 3 parameters and of a 12x12 in 2
//! (evaluation/interpolation, `charpoly_zp`); gcd and factorization of those charpolys and of
//! products such as (a*b + c^2 + 1)^3 (a - b + 2c)^2; rank/RREF of a 10x10 of rank 6 over
//! Q(a, b, c) with the conditions.

use exactlti::field::Field;
use exactlti::matrix::Matrix;
use exactlti::matrix::params::{charpoly_zp, rref_params};
use exactlti::mpoly::{MPoly, factor, gcd, parse_mpoly_in};
use exactlti::ratfunc::RatFuncField;
use std::fmt::Write as _;
use std::hint::black_box;
use std::time::{Duration, Instant};

struct SplitMix(u64);
impl SplitMix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn int(&mut self, r: i64) -> i64 {
        (self.next() % (2 * r as u64 + 1)) as i64 - r
    }
}

fn median_ms(mut f: impl FnMut()) -> f64 {
    let mut ts = Vec::new();
    let start = Instant::now();
    while ts.len() < 3 || (start.elapsed() < Duration::from_millis(1500) && ts.len() < 200) {
        let t = Instant::now();
        f();
        ts.push(t.elapsed().as_secs_f64() * 1e3);
    }
    ts.sort_by(|a, b| a.partial_cmp(b).unwrap());
    ts[ts.len() / 2]
}

/// Random entry linear in the parameters: `c0 + c1*p1 + ...`.
fn linear_entry(rng: &mut SplitMix, params: &[&str]) -> String {
    let mut s = format!("{}", rng.int(5));
    for p in params {
        let c = rng.int(3);
        if c != 0 {
            write!(s, " + {c}*{p}").unwrap();
        }
    }
    s.replace("+ -", "- ")
}

/// The charpoly as one polynomial in (x, params).
fn charpoly_in_x(cs: &[MPoly], np: usize) -> MPoly {
    let map: Vec<usize> = (1..=np).collect();
    let mut acc = MPoly::zero(np + 1);
    for (k, c) in cs.iter().enumerate() {
        let lifted = c.remap(np + 1, &map);
        acc = acc.add(&lifted.mul(&MPoly::var(np + 1, 0).pow(k as u32)));
    }
    acc
}

/// The staged gcd's parts alone: heuristic, Brown's modular, subresultant (ms).
fn gcd_variants(f: &MPoly, g: &MPoly) -> String {
    let (cf, pf) = f.content_primitive();
    let (cg, pg) = g.content_primitive();
    let want = gcd(f, g);
    let c = exactlti::mpoly::gcd::integer_gcd(&cf, &cg);
    let heu = exactlti::mpoly::gcd::gcd_heuristic(&pf, &pg);
    let th = median_ms(|| {
        black_box(exactlti::mpoly::gcd::gcd_heuristic(&pf, &pg));
    });
    let br = exactlti::mpoly::brown::gcd_brown(&pf, &pg);
    assert_eq!(br.as_ref().map(|h| h.scale(&c)), Some(want.clone()));
    let tb = median_ms(|| {
        black_box(exactlti::mpoly::brown::gcd_brown(&pf, &pg));
    });
    format!(
        "heuristic {th:.3} ms{}, Brown {tb:.3} ms",
        if heu.is_some() { "" } else { " (failed)" }
    )
}

fn main() {
    let mut cases = String::new();
    let mut rng = SplitMix(2026);
    let mut charpolys = Vec::new();
    for (name, n, params) in [
        ("charpoly 8x8 3p", 8usize, vec!["a", "b", "c"]),
        ("charpoly 12x12 2p", 12, vec!["a", "b"]),
    ] {
        let entries: Vec<String> = (0..n * n)
            .map(|_| linear_entry(&mut rng, &params))
            .collect();
        let polys: Vec<MPoly> = entries
            .iter()
            .map(|e| {
                parse_mpoly_in(e, &params)
                    .unwrap()
                    .prim
                    .scale(&parse_mpoly_in(e, &params).unwrap().content.to_integer())
            })
            .collect();
        let ms = median_ms(|| {
            black_box(charpoly_zp(params.len(), n, &polys).unwrap());
        });
        println!("{name}: {ms:.3} ms");
        writeln!(
            cases,
            "charpoly\t{name}\t{}\t{n}\t{}",
            params.join(","),
            entries.join(";")
        )
        .unwrap();
        let cs = charpoly_zp(params.len(), n, &polys).unwrap();
        charpolys.push((name, params.clone(), charpoly_in_x(&cs, params.len())));
    }
    // gcd and factor of the charpolys
    for (name, params, cp) in &charpolys {
        let mut vars = vec!["x".to_string()];
        vars.extend(params.iter().map(|s| s.to_string()));
        let nv = vars.len();
        let vrefs: Vec<&str> = vars.iter().map(|s| s.as_str()).collect();
        let g1 = parse_mpoly_in("x^2 + a*x - 3", &vrefs).unwrap().prim;
        let g2 = parse_mpoly_in("x - 2*b + 1", &vrefs).unwrap().prim;
        let (f, g) = (cp.mul(&g1), cp.mul(&g2));
        let ms = median_ms(|| {
            black_box(gcd(&f, &g));
        });
        let gname = format!("gcd({name} * f, {name} * g)");
        println!("{gname}: {ms:.3} ms");
        println!("  ({})", gcd_variants(&f, &g));
        assert_eq!(gcd(&f, &g), cp.abs_lc());
        writeln!(
            cases,
            "gcd\t{gname}\t{}\t{}\t{}",
            vars.join(","),
            f.to_string_vars(&vars),
            g.to_string_vars(&vars)
        )
        .unwrap();
        let fname = format!("factor {name}");
        let ms = median_ms(|| {
            black_box(factor(cp).unwrap());
        });
        let fz = factor(cp).unwrap();
        assert_eq!(fz.expand(nv), *cp);
        println!("{fname}: {ms:.3} ms");
        println!("  ({} factors)", fz.factors.len());
        writeln!(
            cases,
            "factor\t{fname}\t{}\t{}",
            vars.join(","),
            cp.to_string_vars(&vars)
        )
        .unwrap();
    }
    // products
    let v3 = ["a", "b", "c"];
    let vs: Vec<String> = v3.iter().map(|s| s.to_string()).collect();
    let prods = [
        (
            "factor (ab+c^2+1)^3 (a-b+2c)^2",
            "(a*b + c^2 + 1)^3*(a - b + 2*c)^2",
        ),
        (
            "factor (a^2b+c+3)(ac^2-b+1)(a+bc)",
            "(a^2*b + c + 3)*(a*c^2 - b + 1)*(a + b*c)",
        ),
        (
            "factor (a+b+c+1)^4 (a^2-bc+2)^3",
            "(a + b + c + 1)^4*(a^2 - b*c + 2)^3",
        ),
    ];
    for (name, text) in prods {
        let f = parse_mpoly_in(text, &v3).unwrap().prim;
        let ms = median_ms(|| {
            black_box(factor(&f).unwrap());
        });
        assert_eq!(factor(&f).unwrap().expand(3), f);
        println!("{name}: {ms:.3} ms");
        writeln!(cases, "factor\t{name}\ta,b,c\t{}", f.to_string_vars(&vs)).unwrap();
    }
    let f = parse_mpoly_in("(a*b + c^2 + 1)^3*(a - b + 2*c)^2", &v3)
        .unwrap()
        .prim;
    let g = parse_mpoly_in("(a*b + c^2 + 1)^2*(a + b + c)^3", &v3)
        .unwrap()
        .prim;
    let name = "gcd((ab+c^2+1)^3 (a-b+2c)^2, (ab+c^2+1)^2 (a+b+c)^3)";
    let ms = median_ms(|| {
        black_box(gcd(&f, &g));
    });
    println!("{name}: {ms:.3} ms");
    println!("  ({})", gcd_variants(&f, &g));
    writeln!(
        cases,
        "gcd\t{name}\ta,b,c\t{}\t{}",
        f.to_string_vars(&vs),
        g.to_string_vars(&vs)
    )
    .unwrap();
    // rank/RREF 10x10 of rank 6 over Q(a, b, c): L (10x6 constants) * R (6x10 linear)
    let k = RatFuncField::new(&v3).unwrap();
    let l: Vec<Vec<i64>> = (0..10)
        .map(|_| (0..6).map(|_| rng.int(2)).collect())
        .collect();
    let r: Vec<Vec<String>> = (0..6)
        .map(|_| (0..10).map(|_| linear_entry(&mut rng, &v3)).collect())
        .collect();
    let cols: Vec<Vec<&String>> = (0..10)
        .map(|j| r.iter().map(|row| &row[j]).collect())
        .collect();
    let mut entries = Vec::new();
    for li in &l {
        for col in &cols {
            let mut s = String::from("0");
            for (t, c) in li.iter().enumerate() {
                if *c != 0 {
                    write!(s, " + ({c})*({})", col[t]).unwrap();
                }
            }
            entries.push(s);
        }
    }
    let elems: Vec<_> = entries.iter().map(|e| k.parse(e).unwrap()).collect();
    let mut rank = 0;
    let mut nconds = 0;
    let ms = median_ms(|| {
        let kk = k.fresh();
        let m = Matrix::from_vec(kk.clone(), 10, 10, elems.clone());
        let (rr, piv) = rref_params(&m);
        rank = piv.len();
        nconds = kk.conditions().unwrap().len();
        black_box(rr);
    });
    let generic = median_ms(|| {
        let kk = k.fresh();
        let m = Matrix::from_vec(kk.clone(), 10, 10, elems.clone());
        black_box(m.rref_gauss_jordan());
        black_box(kk.conditions().unwrap());
    });
    let name = "rref 10x10 rank 6 over QQ(a,b,c)";
    println!("{name}: {ms:.3} ms");
    println!("  (rank {rank}, {nconds} conditions; generic Gauss-Jordan {generic:.1} ms)");
    let m = Matrix::from_vec(k.clone(), 10, 10, elems.clone());
    assert_eq!(rref_params(&m), m.rref_gauss_jordan());
    let m = Matrix::from_vec(k.clone(), 10, 10, elems.clone());
    assert_eq!(m.rank(), 6);
    let _ = k.one();
    writeln!(cases, "rref\t{name}\ta,b,c\t10\t10\t{}", entries.join(";")).unwrap();
    let target = std::env::var("CARGO_TARGET_DIR").unwrap_or_else(|_| "target".into());
    std::fs::write(format!("{target}/mpoly-bench-cases.txt"), cases).unwrap();
}
