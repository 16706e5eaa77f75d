//! Square-free decomposition over $\mathbb{Z}$ (Yun's algorithm).
//!
//! For primitive $f$ with $\operatorname{lc}(f) > 0$: $f = \prod_i a_i^i$ with $a_i$
//! primitive, square-free and pairwise coprime. Yun: $c_1 = f / \gcd(f, f')$,
//! $d_1 = f'/\gcd(f, f') - c_1'$; then $a_i = \gcd(c_i, d_i)$, $c_{i+1} = c_i / a_i$,
//! $d_{i+1} = d_i / a_i - c_{i+1}'$. All divisions are exact in $\mathbb{Z}\lbrack x\rbrack$ by Gauss's
//! lemma, because every divisor is primitive.

use super::super::zpoly::ZPoly;

/// Yun's decomposition of a primitive `f` of degree $\ge 1$ with positive leading
/// coefficient: the pairs $(a_i, i)$ with $\deg a_i \ge 1$, in increasing $i$.
pub(crate) fn yun(f: &ZPoly) -> Vec<(ZPoly, usize)> {
    let df = f.derivative();
    let g = f.gcd(&df);
    if g.deg0() == 0 {
        return vec![(f.clone(), 1)];
    }
    let exact = |a: &ZPoly, b: &ZPoly| {
        a.div_exact(b)
            .expect("Yun: exact division by a primitive divisor")
    };
    let mut c = exact(f, &g);
    let mut d = &exact(&df, &g) - &c.derivative();
    let mut out = Vec::new();
    let mut i = 1;
    while c.deg0() > 0 {
        let a = c.gcd(&d);
        c = exact(&c, &a);
        d = &exact(&d, &a) - &c.derivative();
        if a.deg0() > 0 {
            out.push((a, i));
        }
        i += 1;
    }
    out
}
