#[path = "../tests/common/pencils.rs"]
mod pencils;
use std::time::Instant;
fn main() {
    let args: Vec<usize> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let (scale, ops) = (args[0], args[1]);
    let mut eps = Vec::new();
    for k in 0..4 {
        eps.extend(std::iter::repeat_n(k, 6 * scale / 4));
    }
    let p = pencils::Planted {
        eps,
        eta: vec![1, 2],
        inf: vec![1, 2, 3],
        jordan: vec![(0, 2), (1, 3), (2, 1)],
        companions: (0..3 * scale / 4)
            .map(|i| vec![-[2, 3, 5][i % 3], 0])
            .collect(),
    };
    let (a, e) = p.scrambled(1, ops);
    println!("shape {:?}", a.shape());
    let t = Instant::now();
    let k = exactlti::pencil::kronecker_structure(&a, &e).unwrap();
    println!(
        "structure+verify {:.3}s verified {}",
        t.elapsed().as_secs_f64(),
        k.verified
    );
    let bits = k
        .finite_part
        .as_slice()
        .iter()
        .map(|x| x.numer().bits() + x.denom().bits())
        .max();
    println!("finite part bits {bits:?}");
}
