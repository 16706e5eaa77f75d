//! `sweep --locus-svg`: a cross at the first parameter value, a square at the last, and a
//! black circle at each finite limit of the branches as the parameter grows without bound
//! (for a gain sweep $A - kbc$: the open-loop zeros, the roots of $n(s)$ in
//! $\det(sI - A + kbc) = d(s) + k\,n(s)$).

use crate::common::cli::{run, temp_file};

/// $G(s) = n(s)/((s+1)(s+2)(s+3))$ in controller form, closed by the gain $k$:
/// the last row of $A - kbc$ is $-(d_0 + k n_0), -(d_1 + k n_1), -(d_2 + k n_2)$.
fn gain_family(n: [i64; 3]) -> String {
    format!(
        r#"{{"parameters": {{"k": null}},
 "A": [[0, 1, 0], [0, 0, 1], ["-6 - {n0}*k", "-11 - {n1}*k", "-6 - {n2}*k"]],
 "B": [[0], [0], [1]], "C": [[{n0}, {n1}, {n2}]], "D": [[0]]}}"#,
        n0 = n[0],
        n1 = n[1],
        n2 = n[2]
    )
}

fn locus(tag: &str, n: [i64; 3]) -> String {
    let f = temp_file("root_locus", &format!("{tag}.json"), &gain_family(n));
    let svg = f.with_extension("svg");
    let (code, _out, err) = run(&[
        "sweep",
        f.to_str().unwrap(),
        "--param",
        "k",
        "--from",
        "0",
        "--to",
        "10",
        "--points",
        "41",
        "--locus-svg",
        svg.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    std::fs::read_to_string(&svg).unwrap()
}

fn black_circles(svg: &str) -> usize {
    svg.lines()
        .filter(|l| l.starts_with("<circle") && l.contains(r##"stroke="#000""##))
        .count()
}

#[test]
fn one_zero_one_circle_and_every_branch_marked_at_both_ends() {
    // n(s) = s + 4: one finite limit, s = -4
    let svg = locus("zero1", [4, 1, 0]);
    assert_eq!(black_circles(&svg), 1);
    // one square per branch at k = 10 (3 branches)
    assert_eq!(svg.matches(r#"width="8" height="8""#).count(), 3);
    assert!(svg.contains("(x)") && svg.contains("(square)"));
    assert!(svg.contains("o: limits as k grows without bound"));
}

#[test]
fn two_zeros_two_circles_and_none_without_zeros() {
    // n(s) = s^2 + 5 s + 6 = (s + 2)(s + 3): two finite limits
    assert_eq!(black_circles(&locus("zero2", [6, 5, 1])), 2);
    // n(s) = 1: every branch goes to infinity, no circle
    assert_eq!(black_circles(&locus("zero0", [1, 0, 0])), 0);
}
