//! Mechanical normal form (Mayet & Kammermeier) of three systems:
//!
//! 1. a two-mass oscillator M q'' + D q' + K q = W u, written in first-order form and
//!    scrambled by a state transformation x = S x' (a "black box" model): the normal form
//!    q'' + D~ q' + K~ q = [0; 1] u comes back, with the same eigenvalues and Markov
//!    parameters (checked exactly);
//! 2. the paper's App. B system (w1 = 2, w2 = 3), where the natural choice X = [e1, e3] gives a
//!    singular T;
//! 3. a system meeting all of Theorem 2.1's conditions that has no normal form (two
//!    uncontrollable modes at the same eigenvalue), reported with its reason.
//!
//! Run: `cargo run --release --example mechanical_normal_form`.

use exactlti::field::Q;
use exactlti::matrix::Matrix;
use exactlti::qmat;
use exactlti::structure::mechanical::mechanical_normal_form;
use std::time::Instant;

fn main() -> exactlti::Result<()> {
    // 1. masses 1 and 2, springs 3 (to ground) and 1 (between), damper 1/2 on mass 2,
    //    force on mass 2, position of mass 1 measured.
    let m = qmat![[1, 0], [0, 2]];
    let k = qmat![[4, -1], [-1, 1]];
    let d = Matrix::from_fn(Q, 2, 2, |i, j| {
        if i == 1 && j == 1 {
            exactlti::field::Rational::new(1.into(), 2.into())
        } else {
            exactlti::field::Rational::from_integer(0.into())
        }
    });
    let w = qmat![[0], [1]];
    let mi = m.inverse()?;
    let zero = Matrix::zeros(Q, 2, 2);
    let id = Matrix::identity(Q, 2);
    let a = Matrix::block(
        Q,
        &[vec![&zero, &id], vec![&(-&(&mi * &k)), &(-&(&mi * &d))]],
    )?;
    let b = zero.submatrix(0, 2, 0, 1).vstack(&(&mi * &w))?;
    let c = qmat![[1, 0, 0, 0]];
    let s = qmat![[1, 1, 0, 0], [0, 1, 2, 0], [0, 0, 1, -1], [1, 0, 0, 1]];
    let si = s.inverse()?;
    let (a2, b2, c2) = (&(&si * &a) * &s, &si * &b, &c * &s);
    println!("scrambled A = {a2}\nscrambled B = {b2}\n");
    let t0 = Instant::now();
    let r = mechanical_normal_form(&a2, &b2, &c2, &qmat![[0]])?;
    let dt = t0.elapsed();
    println!("{}", r.report().to_text());
    println!("(computed and verified in {dt:?})\n");

    // 2. App. B
    let a = qmat![[0, 0, 1, 0], [0, 0, 0, 1], [-4, 0, 0, 0], [0, -9, 0, 0]];
    let b = qmat![[0], [0], [0], [1]];
    let x = qmat![[1, 0], [0, 0], [0, 1], [0, 0]];
    let t_bad = exactlti::structure::mechanical::transform::transformation_from_x(&a, &x)?;
    println!("App. B: X = [e1, e3] gives det T = {}", t_bad.det()?);
    let r = mechanical_normal_form(&a, &b, &qmat![[1, 0, 0, 0]], &qmat![[0]])?;
    let f = r.form.as_ref().expect("exists");
    println!(
        "App. B: the search found T = {} (det {}) after {} candidate(s), verified = {}\n",
        f.t,
        f.t.det()?,
        f.candidates,
        r.verified
    );

    // 3. Theorem 2.1's conditions hold, but no transformation exists
    let a = qmat![[2, 0, 0, 0], [0, 2, 0, 0], [0, 0, 0, 1], [0, 0, -1, 0]];
    let r = mechanical_normal_form(&a, &b, &qmat![[1, 1, 1, 1]], &qmat![[0]])?;
    println!("{}", r.report().to_text());
    Ok(())
}
