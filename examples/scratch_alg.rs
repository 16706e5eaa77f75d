use exactlti::algebraic::*;
use exactlti::poly::parse_poly_q;
fn main() {
    let s = std::env::args().nth(1).unwrap();
    let p = parse_poly_q(&s).unwrap();
    let t = std::time::Instant::now();
    let rs = AlgebraicNumber::roots_of_irreducible(&p).unwrap();
    eprintln!("got {} {:?}", rs.len(), t.elapsed());
    for z in rs {
        eprintln!("z {} {:?}", z, z.approx());
        let re = z.try_re().unwrap();
        eprintln!("re {re} {:?}", t.elapsed());
        let im = z.try_im().unwrap();
        eprintln!("im {im} {:?}", t.elapsed());
    }
}
