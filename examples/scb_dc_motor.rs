//! DC motor with LuGre friction, Grip & Saberi sec. V: the SCB reveals a structural
//! bifurcation in $\sigma_1$.
//!
//! $\dot\Omega = \omega$, $J\dot\omega = u - F$, $F = \sigma_0 z + \sigma_1 \dot z + \alpha_2\omega$,
//! linear part with the perturbation as input. For $\sigma_1 = 0.6$: dims $(1, 0, 0, 2)$ and
//! $A_{aa} = -\sigma_0/\sigma_1$ (fast zero dynamics, large entries with powers of
//! $\sigma_1$ in the denominators); for $\sigma_1 = 0$ one integrator chain of length 3.
//!
//! Run: `cargo run --example scb_dc_motor`

use exactlti::field::{Q, parse_rational};
use exactlti::matrix::Matrix;
use exactlti::structure::scb::scb;

fn main() -> exactlti::Result<()> {
    let q = |s: &str| parse_rational(s).expect("rational literal");
    let (j, s0, a2) = (q("0.0023"), q("260"), q("0.176"));
    for s1 in ["0.6", "0"] {
        let s1 = q(s1);
        let (z, one) = (q("0"), q("1"));
        let a = Matrix::from_rows(
            Q,
            vec![
                vec![z.clone(), one.clone(), z.clone()],
                vec![z.clone(), -((&a2 + &s1) / &j), -(&s0 / &j)],
                vec![z.clone(), one.clone(), z.clone()],
            ],
        )?;
        let b = Matrix::from_rows(Q, vec![vec![z.clone()], vec![&s1 / &j], vec![-one.clone()]])?;
        let c = Matrix::from_rows(Q, vec![vec![one, z.clone(), z]])?;
        let s = scb(&a, &b, &c, &Matrix::zeros(Q, 1, 1))?;
        println!("== sigma1 = {s1}");
        println!("{}", s.report().to_text());
        println!("minimum phase: {:?}\n", s.minimum_phase());
    }
    Ok(())
}
