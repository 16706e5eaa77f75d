//! Degenerate shapes through every library command (issue 17): n = 0 finite states, no
//! inputs, no outputs, E = 0, empty matrices. Each answers or errs with a typed error; no panic.

use exactlti::float;
use nalgebra::DMatrix;

#[test]
fn float_freqresp_with_no_states() {
    let a = DMatrix::<f64>::zeros(0, 0);
    let b = DMatrix::<f64>::zeros(0, 1);
    let c = DMatrix::<f64>::zeros(1, 0);
    let d = DMatrix::from_element(1, 1, 2.0);
    let g = float::freqresp(&a, &b, &c, &d, &[0.1, 1.0]).unwrap();
    assert_eq!(g.len(), 2);
    assert_eq!(g[1][(0, 0)].re, 2.0);
    // no inputs, no outputs
    let g = float::freqresp(
        &DMatrix::from_element(1, 1, -1.0),
        &DMatrix::zeros(1, 0),
        &DMatrix::zeros(0, 1),
        &DMatrix::zeros(0, 0),
        &[1.0],
    )
    .unwrap();
    assert_eq!(g[0].shape(), (0, 0));
}
