//! Special coordinate basis of the linear single-track (bicycle) model, Grip & Saberi sec. IV.
//!
//! States $(v_y, r, F_f, F_r)$, input front steering angle $\delta_f$ (and optionally rear
//! steering $\delta_r$), outputs yaw rate $r$ and lateral acceleration $a_y = (F_f + F_r)/m$.
//! With front steering only the SCB has dims $(0, 3, 0, 1)$: left invertible, not right
//! invertible, no finite zeros. Adding rear steering gives dims $(1, 0, 0, 3)$, chains of
//! lengths 1 and 2, and $A_{aa} = 0$: a zero at the origin (non-minimum phase).
//!
//! Run: `cargo run --example scb_single_track`

use exactlti::field::{Q, Rational, parse_rational};
use exactlti::matrix::Matrix;
use exactlti::structure::scb::scb;
use exactlti::structure::zeros::invariant_zeros;

fn q(s: &str) -> Rational {
    parse_rational(s).expect("rational literal")
}

fn main() -> exactlti::Result<()> {
    let (m, j, lf, lr) = (q("1500"), q("2500"), q("1.2"), q("1.4"));
    let (cf, cr, vx, tr) = (q("80000"), q("80000"), q("20"), q("1/10"));
    let (z, one) = (q("0"), q("1"));
    let a = Matrix::from_rows(
        Q,
        vec![
            vec![z.clone(), -vx.clone(), &one / &m, &one / &m],
            vec![z.clone(), z.clone(), &lf / &j, -(&lr / &j)],
            vec![
                -(&cf / (&tr * &vx)),
                -(&lf * &cf / (&tr * &vx)),
                -(&one / &tr),
                z.clone(),
            ],
            vec![
                -(&cr / (&tr * &vx)),
                &lr * &cr / (&tr * &vx),
                z.clone(),
                -(&one / &tr),
            ],
        ],
    )?;
    let c = Matrix::from_rows(
        Q,
        vec![
            vec![z.clone(), one.clone(), z.clone(), z.clone()],
            vec![z.clone(), z.clone(), &one / &m, &one / &m],
        ],
    )?;
    for rear in [false, true] {
        let mut rows = vec![
            vec![z.clone()],
            vec![z.clone()],
            vec![&cf / &tr],
            vec![z.clone()],
        ];
        if rear {
            for (i, row) in rows.iter_mut().enumerate() {
                row.push(if i == 3 { &cr / &tr } else { z.clone() });
            }
        }
        let b = Matrix::from_rows(Q, rows)?;
        let d = Matrix::zeros(Q, 2, b.ncols());
        let s = scb(&a, &b, &c, &d)?;
        println!(
            "== {} steering",
            if rear { "front and rear" } else { "front" }
        );
        println!("{}", s.report().to_text());
        let z = invariant_zeros(&a, &b, &c, &d)?;
        println!(
            "Rosenbrock check: zero polynomial {} (normal rank {})\n",
            z.polynomial.to_string_var("s"),
            z.normal_rank
        );
    }
    Ok(())
}
