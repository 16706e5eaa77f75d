//! `poly factor` / `poly gcd` on multivariate input (CLI contract, second wave).

use crate::common::cli::run;

fn json(args: &[&str]) -> serde_json::Value {
    crate::common::cli::run_json(args)
}

#[test]
fn factor_multivariate() {
    let v = json(&["poly", "factor", "-2*(a*b + c^2 + 1)^3*(a - b + 2*c)^2"]);
    assert_eq!(v["content"], "-2");
    let fs: Vec<(String, i64)> = v["factors"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| {
            (
                f["poly"].as_str().unwrap().to_string(),
                f["multiplicity"].as_i64().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        fs,
        [
            ("a - b + 2*c".to_string(), 2),
            ("a*b + c^2 + 1".to_string(), 3)
        ]
    );
    assert_eq!(v["verified"], true);
    // vehicle-style names
    let v = json(&["poly", "factor", "m^2*u^2 - cr^2"]);
    assert_eq!(v["factors"].as_array().unwrap().len(), 2);
}

#[test]
fn gcd_multivariate() {
    let v = json(&["poly", "gcd", "(m*u - cr)*(m + 1)", "(m*u - cr)*(u - 2)^2"]);
    assert_eq!(v["gcd"], "m*u - cr");
    assert_eq!(v["cofactor_f"], "m + 1");
    assert_eq!(v["verified"], true);
    let (code, _, err) = run(&["poly", "gcd", "x +", "y"]);
    assert_eq!(code, 2);
    assert!(err.contains("polynomial"), "{err}");
}
