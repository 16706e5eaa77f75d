//! Transfer matrices as rational functions: parsing, exact minimal realization (order =
//! McMillan degree), round trip through the transfer matrix of the realization.
use exactlti::field::{Q, Rational};
use exactlti::io::transfer_expr::parse_rational_function;
use exactlti::realization::{descriptor_transfer_matrix, realize_transfer};
use exactlti::system::transfer::TransferMatrix;

fn tm(rows: &[&[&str]]) -> TransferMatrix<Q> {
    TransferMatrix {
        entries: rows
            .iter()
            .map(|r| {
                r.iter()
                    .map(|s| parse_rational_function(s, &[]).unwrap())
                    .collect()
            })
            .collect(),
    }
}

fn roundtrip(rows: &[&[&str]], order: usize, mcmillan: usize) {
    let g = tm(rows);
    let r = realize_transfer(&g).unwrap();
    assert!(r.verified, "{rows:?}");
    assert_eq!(r.minimal.order, order, "{rows:?}");
    assert_eq!(r.mcmillan_degree, mcmillan, "{rows:?}");
    let back = descriptor_transfer_matrix(&r.minimal.system).unwrap();
    assert_eq!(back, g, "{rows:?}");
}

#[test]
fn transfer_examples() {
    roundtrip(&[&["(s^2 + 5*s + 7)/(s^2 + 5*s + 6)"]], 2, 2);
    roundtrip(&[&["1/(s+1)", "1/(s+2)"]], 2, 2);
    // a common pole shared by a column: McMillan degree 1 (Kailath's classic rank-1 residue)
    roundtrip(&[&["1/(s+1)"], &["2/(s+1)"]], 1, 1);
    // [[1/(s+1), 1/(s+1)], [1/(s+1), 1/(s+1)]]: rank-one residue, degree 1
    roundtrip(&[&["1/(s+1)", "1/(s+1)"], &["1/(s+1)", "1/(s+1)"]], 1, 1);
    // diag(1/(s+1), 1/(s+1)): degree 2
    roundtrip(&[&["1/(s+1)", "0"], &["0", "1/(s+1)"]], 2, 2);
    // improper: s + 1/(s+1): one pole at infinity of order 1 (descriptor order 1 + 2)
    roundtrip(&[&["s + 1/(s+1)"]], 3, 2);
    // constant
    roundtrip(&[&["3/2"]], 0, 0);
    // decimals are exact: 0.5/(s + 0.25)
    let g = parse_rational_function("0.5/(s + 0.25)", &[]).unwrap();
    assert_eq!(g.to_string_var("s"), "(1/2)/(s + 1/4)");
    // parameters
    let g = parse_rational_function(
        "k/(s + a)",
        &[
            ("k".into(), Rational::from_integer(2.into())),
            ("a".into(), Rational::from_integer(3.into())),
        ],
    )
    .unwrap();
    assert_eq!(g.to_string_var("s"), "(2)/(s + 3)");
}

#[test]
fn transfer_parse_errors() {
    for bad in [
        "1/(s - s)",
        "s^(1/2)",
        "x + 1",
        "s^100",
        "(s + 1",
        "1 +",
        "s^s",
    ] {
        assert!(parse_rational_function(bad, &[]).is_err(), "{bad}");
    }
}
