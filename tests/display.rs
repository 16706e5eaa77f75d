//! One display per quadratic number (issue 11, item 4): every element of $\mathbb{Q}(\sqrt d)$
//! is shown as [`quadratic_display`] (`-6 + sqrt(1598)/10`, `-sqrt(3)/24`, `sqrt(2)*i/2`) in
//! every formatter (quadratic fields, radical-named number fields, algebraic numbers, the
//! Jordan form's closed forms, LaTeX), and every display reads back to the same number.
use exactlti::algebraic::{AlgebraicNumber, ExtElem, NumberField};
use exactlti::field::ElemDisplay;
use exactlti::field::{Field, Q, Quadratic, QuadraticField, Rational, radical_text};
use exactlti::io::{Ground, eval_expr};
use exactlti::poly::Poly;
use exactlti::report::display::{quadratic_display, quadratic_latex};
use exactlti::report::latex::to_math;
use num_bigint::BigInt;
use num_traits::Zero;
use proptest::prelude::*;
use std::process::Command;

/// The fields of the issue: Q(i), Q(sqrt 2), Q(sqrt -3), Q(sqrt 1598).
const RADICANDS: [i64; 4] = [-1, 2, -3, 1598];

fn r(n: i64, d: i64) -> Rational {
    Rational::new(n.into(), d.into())
}

/// $\mathbb{Q}(\sqrt d)$ as the Jordan form builds it: modulus $t^2 - d$, variable the radical.
fn radical_field(d: i64) -> NumberField {
    let m = Poly::new(Q, vec![r(-d, 1), r(0, 1), r(1, 1)]);
    let root = if d < 0 {
        (0.0, (-d as f64).sqrt())
    } else {
        ((d as f64).sqrt(), 0.0)
    };
    NumberField::with_var(&m, root, &radical_text(&BigInt::from(d)))
}

/// The four formatters of one number agree, the display reads back to it, and its LaTeX is
/// the report's typesetting of the display.
fn check_one(a: &Rational, b: &Rational, d: i64) -> Result<(), TestCaseError> {
    let dd = BigInt::from(d);
    let shown = quadratic_display(a, b, &dd);
    let k = QuadraticField::new(d).unwrap();
    prop_assert_eq!(&k.fmt_elem(&Quadratic::new(a.clone(), b.clone())), &shown);
    let nf = radical_field(d);
    let mut cs = vec![a.clone(), b.clone()];
    while cs.last().is_some_and(|c| c.is_zero()) {
        cs.pop();
    }
    prop_assert_eq!(&nf.fmt_elem(&ExtElem(cs.clone())), &shown);
    prop_assert_eq!(nf.latex_elem(&ExtElem(cs)), quadratic_latex(a, b, &dd));
    prop_assert_eq!(
        Some(quadratic_latex(a, b, &dd)),
        to_math(&shown),
        "{}",
        &shown
    );
    // reads back
    let (x, g) = eval_expr(&shown, &[], &Ground::Rational)
        .map_err(|e| TestCaseError::fail(format!("{shown}: {e}")))?;
    prop_assert_eq!(&x.a, a, "{}", &shown);
    prop_assert_eq!(&x.b, b, "{}", &shown);
    if b.is_zero() {
        prop_assert_eq!(g, Ground::Rational);
    } else {
        prop_assert_eq!(g, Ground::Quadratic(k));
    }
    Ok(())
}

#[test]
fn examples_of_the_one_display() {
    let d = |a: Rational, b: Rational, d: i64| quadratic_display(&a, &b, &BigInt::from(d));
    assert_eq!(d(r(-6, 1), r(1, 10), 1598), "-6 + sqrt(1598)/10");
    assert_eq!(d(r(0, 1), r(-1, 24), 3), "-sqrt(3)/24");
    assert_eq!(d(r(0, 1), r(1, 2), -2), "sqrt(2)*i/2");
    assert_eq!(d(r(-3, 20), r(-1, 20), -1991), "-3/20 - sqrt(1991)*i/20");
    assert_eq!(d(r(1, 2), r(3, 2), 5), "1/2 + 3*sqrt(5)/2");
    assert_eq!(d(r(-1, 2), r(3, 1), -1), "-1/2 + 3*i");
    assert_eq!(d(r(7, 3), r(0, 1), 2), "7/3");
    let l = |a: Rational, b: Rational, d: i64| quadratic_latex(&a, &b, &BigInt::from(d));
    assert_eq!(l(r(0, 1), r(-1, 24), 3), "-\\frac{\\sqrt{3}}{24}");
    assert_eq!(l(r(-6, 1), r(1, 10), 1598), "-6 + \\frac{\\sqrt{1598}}{10}");
    assert_eq!(
        l(r(-1, 2), r(3, 2), -3),
        "-\\frac{1}{2} + \\frac{3 \\sqrt{3}\\,\\mathrm{i}}{2}"
    );
    for d in RADICANDS {
        for (a, b) in [(r(0, 1), r(0, 1)), (r(0, 1), r(1, 1)), (r(-1, 1), r(-1, 1))] {
            check_one(&a, &b, d).unwrap();
        }
    }
}

/// Monic `x^2 - 2 a x + (a^2 - d b^2)`, the minimal polynomial of `a +- b sqrt(d)`.
fn minpoly(a: &Rational, b: &Rational, d: i64) -> Poly<Q> {
    let two = r(2, 1);
    let c0 = a * a - r(d, 1) * b * b;
    Poly::new(Q, vec![c0, -(&two * a), r(1, 1)])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn displays_agree_and_read_back(
        di in 0usize..4,
        an in -5000i64..5000, ad in 1i64..300,
        bn in -5000i64..5000, bd in 1i64..300,
    ) {
        let d = RADICANDS[di];
        check_one(&r(an, ad), &r(bn, bd), d)?;
    }

    /// The roots of a quadratic, as algebraic numbers (exact root choice) and as the Jordan
    /// form shows them (`report::numbers::canonical`, root chosen by its approximation): the
    /// same display, which is the element's.
    #[test]
    fn algebraic_numbers_show_the_same_display(
        di in 0usize..4,
        an in -500i64..500, ad in 1i64..30,
        bn in 1i64..500, bd in 1i64..30,
    ) {
        let d = RADICANDS[di];
        let (a, b) = (r(an, ad), r(bn, bd));
        let p = minpoly(&a, &b, d);
        let want = [
            quadratic_display(&a, &b, &BigInt::from(d)),
            quadratic_display(&a, &(-&b), &BigInt::from(d)),
        ];
        let roots = AlgebraicNumber::roots_of_irreducible(&p).unwrap();
        prop_assert_eq!(roots.len(), 2);
        for z in &roots {
            let shown = z.value_string();
            prop_assert!(want.contains(&shown), "{} not in {:?}", shown, want);
            let jordan = exactlti::report::numbers::canonical(&p.to_string(), z.approx());
            prop_assert_eq!(jordan.as_ref(), Some(&shown));
            // the display reads back to this root: same approximation
            let (x, _) = eval_expr(&shown, &[], &Ground::Rational).unwrap();
            let k = QuadraticField::new(d).unwrap();
            let (re, im) = k.approx(&Quadratic::new(x.a, x.b));
            let (zr, zi) = z.approx();
            prop_assert!((re - zr).abs() <= 1e-9 * (1.0 + zr.abs()));
            prop_assert!((im - zi).abs() <= 1e-9 * (1.0 + zi.abs()));
        }
    }
}

/// The issue's example: the roots of `x^2 + 12 x + 1001/50` in every formatter.
#[test]
fn the_issue_example() {
    let p = Poly::new(Q, vec![r(1001, 50), r(12, 1), r(1, 1)]);
    let mut shown: Vec<String> = AlgebraicNumber::roots_of_irreducible(&p)
        .unwrap()
        .iter()
        .map(|z| z.value_string())
        .collect();
    shown.sort();
    assert_eq!(shown, ["-6 + sqrt(1598)/10", "-6 - sqrt(1598)/10"]);
    let k = radical_field(1598);
    assert_eq!(
        k.fmt_elem(&ExtElem(vec![r(-6, 1), r(1, 10)])),
        "-6 + sqrt(1598)/10"
    );
    // a field variable that is not the radical keeps the polynomial display
    let t = NumberField::with_var(&p, (-2.0, 0.0), "r1");
    assert_eq!(t.radicand(), None);
    assert_eq!(
        t.fmt_elem(&ExtElem(vec![r(-6, 1), r(1, 10)])),
        "1/10*r1 - 6"
    );
}

fn analyze_json(file: &str) -> serde_json::Value {
    let out = Command::new(env!("CARGO_BIN_EXE_exactlti"))
        .args(["analyze", file, "--format", "json"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{file}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("JSON")
}

fn strings<'a>(v: &'a serde_json::Value, out: &mut Vec<&'a str>) {
    match v {
        serde_json::Value::String(s) => out.push(s),
        serde_json::Value::Array(xs) => xs.iter().for_each(|x| strings(x, out)),
        serde_json::Value::Object(m) => m.values().for_each(|x| strings(x, out)),
        _ => {}
    }
}

/// What is wrong with the quadratic numbers inside `s`, if anything: a coefficient written
/// before the radical (`1/24*sqrt(3)`) or a rational part after it (`sqrt(1598) - 6`,
/// `1/10*sqrt(1598) - 6`).
fn non_canonical(s: &str) -> Option<String> {
    if let Some(why) = non_canonical_near(s) {
        return Some(why);
    }
    let b = s.as_bytes();
    let mut from = 0;
    while let Some(k) = s[from..].find("sqrt(") {
        let at = from + k;
        from = at + 5;
        // before: `N/M*sqrt(` or `N/M*i*sqrt(` (a fraction as a factor in front)
        let head = s[..at].trim_end_matches("i*");
        if let Some(h) = head.strip_suffix('*') {
            let tok: String = h
                .chars()
                .rev()
                .take_while(|c| c.is_ascii_digit() || *c == '/')
                .collect();
            if tok.contains('/') {
                return Some(format!("fraction before the radical in {s:?}"));
            }
        }
        // after: sqrt(<digits>) [*i] [/<digits>] then ` + <digit>` or ` - <digit>`
        let mut j = from;
        if !b.get(j).is_some_and(u8::is_ascii_digit) {
            continue;
        }
        while b.get(j).is_some_and(u8::is_ascii_digit) {
            j += 1;
        }
        if b.get(j) != Some(&b')') {
            continue;
        }
        j += 1;
        if s[j..].starts_with("*i") {
            j += 2;
        }
        if b.get(j) == Some(&b'/') {
            j += 1;
            while b.get(j).is_some_and(u8::is_ascii_digit) {
                j += 1;
            }
        }
        let rest = &s[j..];
        if (rest.starts_with(" + ") || rest.starts_with(" - "))
            && rest[3..].starts_with(|c: char| c.is_ascii_digit())
        {
            return Some(format!("rational part after the radical in {s:?}"));
        }
    }
    // a whole string that is a quadratic number must be its one display
    if let Ok((x, Ground::Quadratic(k))) = eval_expr(s, &[], &Ground::Rational) {
        let want = quadratic_display(&x.a, &x.b, k.d());
        if want != s {
            return Some(format!("{s:?} is shown as {want:?} elsewhere"));
        }
    }
    None
}

/// What is wrong with the approximations in `s`: every `near X` (and `near X + Y*i`) writes
/// at most 10 significant digits, as [`AlgebraicNumber::value_string`] does, and a
/// `root of P` is not followed by an isolating interval (the old real Jordan form legends:
/// `root of P in [a, b], near -1.7239457174`).
fn non_canonical_near(s: &str) -> Option<String> {
    if s.contains("root of") && s.contains(" in [") {
        return Some(format!("an isolating interval in {s:?}"));
    }
    let mut from = 0;
    while let Some(k) = s[from..].find("near ") {
        from += k + 5;
        // the real part, then an optional ` + Y*i` / ` - Y*i`
        for (n, num) in s[from..]
            .split([' ', ','])
            .filter(|w| !matches!(*w, "" | "+" | "-"))
            .take(2)
            .enumerate()
        {
            let num = num.trim_end_matches("*i");
            let Some(mantissa) = num
                .trim_start_matches('-')
                .split(['e', 'E'])
                .next()
                .filter(|m| !m.is_empty() && m.chars().all(|c| c.is_ascii_digit() || c == '.'))
            else {
                break; // not a number (the next word of the text)
            };
            let sig = mantissa.trim_start_matches(['0', '.']).replace('.', "");
            if sig.len() > 10 {
                return Some(format!("{} significant digits in {s:?}", sig.len()));
            }
            if n == 0 && !s[from..].contains("*i") {
                break;
            }
        }
    }
    None
}

#[test]
fn the_pattern_check_finds_the_old_displays() {
    for bad in [
        "-1/24*sqrt(3)",
        "1/10*sqrt(1598) - 6",
        "sqrt(1598)/10 - 6",
        "1/3192*sqrt(399)*i - 1/8",
        "(1 + sqrt(5))/2",
        "-1/2*sqrt(2)*i",
        "a1 = Re r1 = root of x^6 + 87/2*x^5 + 141015625/4 in [-99/57, -19/11], near -1.7239457174",
        "b1 = Im r1, near 7.5522983973",
        "root of x^4 + 1 near 0.7071067812 + 0.70710678119*i",
    ] {
        assert!(non_canonical(bad).is_some(), "{bad}");
    }
    for good in [
        "-sqrt(3)/24",
        "-6 + sqrt(1598)/10",
        "-1/8 + sqrt(399)*i/3192",
        "i*sqrt(2 - sqrt(3))",
        "s^2 - sqrt(3)/2*s - 3/2",
        "(sqrt(3)/12*s^2 + (-49/8 + sqrt(3)/10)*s + (1/5 + 45*sqrt(3)/8))/(s^2 - 3/2)",
        "QQ(sqrt(1598))",
        "a1 = Re r1 = root of x^6 + 87/2*x^5 + 141015625/4 near -1.723945717",
        "b1 = Im r1, near 7.552298397",
        "root of x^4 + 1 near 0.7071067812 + 0.7071067812*i",
        "near 0.001234567890 and more",
        "near 1.5e-12",
    ] {
        assert_eq!(non_canonical(good), None, "{good}");
    }
}

/// Every quadratic number in the whole JSON report of `analyze`, on the seeds' two examples,
/// a damped model with complex quadratic eigenvalues and a system over Q(sqrt 3), is in its
/// one display.
#[test]
fn analyze_reports_show_each_quadratic_number_one_way() {
    for file in [
        "data/sliding-masses.json",
        "data/yaw-plane-single-wheel.json",
        "tests/data/everyday/damped_chain_5_mimo.json",
        "tests/data/sqrt3.json",
    ] {
        let j = analyze_json(file);
        let mut all = vec![];
        strings(&j, &mut all);
        let bad: Vec<String> = all.iter().filter_map(|s| non_canonical(s)).collect();
        assert!(bad.is_empty(), "{file}: {}", bad.join("\n"));
        if file.contains("sliding") {
            // the entries of the Jordan form's T over Q(sqrt -3) and Q(sqrt -2)
            assert!(all.contains(&"-sqrt(3)*i/24"), "{file}");
            assert!(all.contains(&"sqrt(2)*i/12"), "{file}");
        }
        if file.contains("sqrt3") {
            assert!(all.contains(&"-sqrt(3)/2"), "{file}");
            assert!(all.contains(&"-6 + sqrt(3)/10"), "{file}");
        }
    }
}

/// The Jordan-method minimal realization writes a real quadratic mode in its closed form
/// over Q(sqrt 2) (it showed `r1 = root of x^2 - 2 near 1.41...` and entries `r1 + 2`).
#[test]
fn jordan_method_real_quadratic_modes_in_closed_form() {
    use exactlti::qmat;
    use exactlti::realization::minimal_jordan;
    use exactlti::system::StateSpace;
    let sys =
        StateSpace::new_strictly_proper(qmat![[0, 1], [2, 0]], qmat![[0], [1]], qmat![[1, 1]])
            .unwrap();
    let jm = minimal_jordan(&sys).unwrap();
    assert!(jm.verified);
    let value = |b: &exactlti::realization::ModalBlock| {
        exactlti::report::sections::eigenvalue_text(&jm.jordan.eigenvalues[b.eigenvalue])
    };
    let evs: Vec<String> = jm.blocks.iter().map(value).collect();
    assert_eq!(evs, ["sqrt(2)", "-sqrt(2)"]);
    for b in &jm.blocks {
        let f = &b.field;
        assert_eq!(f.radicand(), Some(BigInt::from(2)));
        assert_eq!(f.fmt_elem(b.a.get(0, 0)), value(b));
        let want = if value(b) == "sqrt(2)" {
            "2 + sqrt(2)"
        } else {
            "2 - sqrt(2)"
        };
        assert_eq!(f.fmt_elem(b.c.get(0, 0)), want);
    }
    // the two blocks (both over Q(sqrt 2)) reproduce the Markov parameters C A^k B exactly
    let f = &jm.blocks[0].field;
    for (k, mk) in sys.markov(4).iter().enumerate() {
        let mut sum = f.zero();
        for b in &jm.blocks {
            let mut x = f.mul(b.c.get(0, 0), b.b.get(0, 0));
            for _ in 0..k {
                x = f.mul(&x, b.a.get(0, 0));
            }
            sum = f.add(&sum, &x);
        }
        assert_eq!(f.to_rational(&sum).as_ref(), Some(mk.get(0, 0)), "k = {k}");
    }
}

/// The Jordan-method realization of the sliding masses lists only the symbols its entries
/// use: the pair at +/- sqrt(3)*i is expanded over Q(sqrt 3) and shown with the radical, so
/// no `r1 = root of x^2 - 3 near ...` is left in the legend.
#[test]
fn jordan_method_legend_lists_used_symbols_only() {
    let out = Command::new(env!("CARGO_BIN_EXE_exactlti"))
        .args([
            "minreal",
            "--method",
            "jordan",
            "data/sliding-masses.json",
            "--format",
            "json",
        ])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(0));
    let j: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let mut entries = vec![];
    for k in ["A", "B", "C"] {
        strings(&j[k], &mut entries);
    }
    assert!(entries.contains(&"sqrt(3)/6"), "{entries:?}");
    let mut legend = vec![];
    strings(&j["symbols"], &mut legend);
    assert!(!legend.is_empty());
    for s in legend {
        assert!(!s.contains("root of x^2"), "{s}");
        let name = s.split(" = ").next().unwrap();
        assert!(
            entries.iter().any(|e| e.contains(name)),
            "{name} is not used: {s}"
        );
    }
}

/// Numbers without a closed form: the algebraic number and the Jordan form's display
/// (`report::numbers::canonical`) write the same `root of P near X`, 10 significant digits.
#[test]
fn root_of_displays_agree() {
    for s in [
        "x^3 - 2",
        "x^5 - x - 1",
        "x^4 + x + 1",
        "x^3 - 3/1000000",
        "x^3 + 7000*x + 1",
    ] {
        let p = exactlti::poly::parse_poly_q(s).unwrap();
        for z in AlgebraicNumber::roots_of_irreducible(&p).unwrap() {
            let shown = z.value_string();
            assert!(shown.starts_with(&format!("root of {p} near ")), "{shown}");
            let jordan = exactlti::report::numbers::canonical(&p.to_string(), z.approx());
            assert_eq!(jordan.as_deref(), Some(shown.as_str()), "{s}");
        }
    }
    let p = exactlti::poly::parse_poly_q("x^3 - 2").unwrap();
    let z = &AlgebraicNumber::roots_of_irreducible(&p).unwrap()[0];
    assert_eq!(z.value_string(), "root of x^3 - 2 near 1.259921050");
}

/// The real Jordan form's legends (`jordan --real`: `symbols` and `parts`) show each number
/// as the other sections do: closed forms for the parts of a quartic's roots, `root of P
/// near X` (10 significant digits, no interval) for parts of degree 6 and 12, `near X` for
/// parts not computed (a sextic's roots).
#[test]
fn real_jordan_legends_show_each_number_one_way() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("exactlti-display");
    std::fs::create_dir_all(&dir).expect("temp dir");
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).expect("write");
        p.to_str().expect("utf-8").to_string()
    };
    let quartic = write(
        "quartic.json",
        r#"{"A": [[0,1,0,0],[0,0,1,0],[0,0,0,1],[-2,0,-1,0]]}"#,
    );
    let sextic = write(
        "sextic.json",
        r#"{"A": [[0,1,0,0,0,0],[0,0,1,0,0,0],[0,0,0,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1],[-1,-1,0,0,0,0]]}"#,
    );
    let quarter_car = "tests/data/everyday/quarter_car.json".to_string();
    for (file, want) in [
        (&quartic, "a1 = Re r1 = sqrt(-1/4 + sqrt(2)/2)"),
        (&sextic, "a1 = Re r1, near 0.9454023333"),
        (
            &quarter_car,
            "a1 = Re r1 = root of x^6 + 87/2*x^5 + 12951/4*x^4 + 629213/8*x^3 + 4411343/2*x^2 + 192275771/8*x + 141015625/4 near -1.723945717",
        ),
    ] {
        let out = Command::new(env!("CARGO_BIN_EXE_exactlti"))
            .args(["jordan", file, "--real", "--format", "json"])
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .output()
            .expect("runs");
        assert_eq!(out.status.code(), Some(0), "{file}");
        let j: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
        let mut all = vec![];
        strings(&j, &mut all);
        let bad: Vec<String> = all.iter().filter_map(|s| non_canonical(s)).collect();
        assert!(bad.is_empty(), "{file}: {}", bad.join("\n"));
        let parts: Vec<&str> = j["parts"]
            .as_array()
            .expect("parts")
            .iter()
            .filter_map(|v| v.as_str())
            .collect();
        assert!(parts.contains(&want), "{file}: {parts:?}");
    }
}
