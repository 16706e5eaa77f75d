//! Timings for root isolation, algebraic-number operations and Trager factorization
//! (`cargo bench --bench algebraic`; plain std::time, best of a few runs).

use exactlti::algebraic::NumberField;
use exactlti::algebraic::{AlgebraicNumber, factor_over_number_field, roots};
use exactlti::field::Field;
use exactlti::poly::parse_poly_q;
use std::time::Instant;

fn best<T>(runs: usize, mut f: impl FnMut() -> T) -> f64 {
    let mut b = f64::INFINITY;
    for _ in 0..runs {
        let t = Instant::now();
        std::hint::black_box(f());
        b = b.min(t.elapsed().as_secs_f64());
    }
    b
}

fn main() {
    let cases = [
        (
            "sliding-mass charpoly (deg 20)",
            "((s^2+1)*(s^2+2)*(s^2+3)*(s^4+4*s^2+1))^2",
        ),
        (
            "Wilkinson-like prod (x - k), k=1..12",
            "(x-1)*(x-2)*(x-3)*(x-4)*(x-5)*(x-6)*(x-7)*(x-8)*(x-9)*(x-10)*(x-11)*(x-12)",
        ),
        ("x^16 + x + 1", "x^16 + x + 1"),
        ("x^24 - 3*x^7 + 2", "x^24 - 3*x^7 + 2"),
        (
            "Mignotte-like x^10 - 2*(50*x - 1)^2",
            "x^10 - 2*(50*x - 1)^2",
        ),
    ];
    for (name, s) in cases {
        let p = parse_poly_q(s).unwrap();
        let t = best(3, || roots(&p).unwrap());
        println!("roots        {name:<40} {:>10.3} ms", t * 1e3);
    }
    let p = parse_poly_q("x^4 + x + 1").unwrap();
    let z = AlgebraicNumber::roots_of_irreducible(&p).unwrap()[2].clone();
    println!(
        "re(z)        {:<40} {:>10.3} ms",
        "root of x^4 + x + 1",
        best(3, || z.try_re().unwrap()) * 1e3
    );
    println!(
        "im(z)        {:<40} {:>10.3} ms",
        "root of x^4 + x + 1",
        best(3, || z.try_im().unwrap()) * 1e3
    );
    println!(
        "digits(100)  {:<40} {:>10.3} ms",
        "root of x^4 + x + 1",
        best(3, || z.digits(100)) * 1e3
    );
    let k = NumberField::new(&parse_poly_q("t^2 - 3").unwrap(), (1.732, 0.0)).unwrap();
    let f = parse_poly_q("x^4 + 4*x^2 + 1")
        .unwrap()
        .map(&k, |c| k.from_rational(c));
    println!(
        "nf factor    {:<40} {:>10.3} ms",
        "x^4+4x^2+1 over Q(sqrt 3)",
        best(3, || factor_over_number_field(&f).unwrap()) * 1e3
    );
    let k3 = NumberField::new(&parse_poly_q("t^3 - 2").unwrap(), (1.26, 0.0)).unwrap();
    let g = parse_poly_q("x^6 - 4")
        .unwrap()
        .map(&k3, |c| k3.from_rational(c));
    println!(
        "nf factor    {:<40} {:>10.3} ms",
        "x^6 - 4 over Q(cbrt 2)",
        best(3, || factor_over_number_field(&g).unwrap()) * 1e3
    );
}
