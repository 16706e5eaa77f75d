//! Example systems from the papers, built exactly.
#![allow(dead_code)]

use exactlti::field::{Q, Rational};
use exactlti::matrix::Matrix;
use exactlti::system::StateSpace;

/// 10-DOF sliding masses (Minaker & Gonzalez sec. 4.1): two fixed-fixed chains of five unit
/// masses and unit springs; actuator pushes sliders 4 and 7 apart; output x9 - x2.
pub fn sliding_masses() -> StateSpace<Q> {
    let n = 10;
    let mut k = Matrix::zeros(Q, n, n);
    for g in [0, 5] {
        for i in 0..5 {
            k.set(g + i, g + i, Rational::from_integer(2.into()));
            if i < 4 {
                k.set(g + i, g + i + 1, Rational::from_integer((-1).into()));
                k.set(g + i + 1, g + i, Rational::from_integer((-1).into()));
            }
        }
    }
    let mut a = Matrix::zeros(Q, 20, 20);
    a.set_block(0, 10, &Matrix::identity(Q, 10));
    a.set_block(10, 0, &-&k);
    let mut b = Matrix::zeros(Q, 20, 1);
    b.set(13, 0, Rational::from_integer((-1).into()));
    b.set(16, 0, Rational::from_integer(1.into()));
    let mut c = Matrix::zeros(Q, 1, 20);
    c.set(0, 8, Rational::from_integer(1.into()));
    c.set(0, 1, Rational::from_integer((-1).into()));
    StateSpace::new_strictly_proper(a, b, c).unwrap()
}
