//! Brown's recursive gcd over $\mathbb{Z}_p$ on dense arrays, with the cofactors.
//!
//! For $A, B$ in variables $x_0, \dots, x_v$ (index order = lex): remove the contents in
//! $x_v$, let $\gamma$ be the gcd of the leading coefficients (univariate in $x_v$), evaluate
//! $x_v = \beta$ at random points, recurse, scale the gcd image to leading coefficient
//! $\gamma(\beta)$ and Newton-interpolate the gcd **and both cofactors** in $x_v$. Images
//! with a larger leading monomial are unlucky and skipped; a smaller one restarts. As soon as
//! one of the three interpolants takes the new image's values already (it is stable), its
//! primitive part is tested by exact division mod $p$ ([`super::dense::div_dense`]): when the
//! cofactor $B / G$ is small (the bench's charpoly products) two or three points per variable
//! suffice instead of $\deg \gamma + \min(\deg A, \deg B) + 1$.

use super::dense::{Dense, Interp, Up, Zp, div_dense, udivrem, ueval, ugcd, umul};

/// Unlucky or failed evaluation points tolerated per level.
const MAX_BAD: usize = 48;

/// A gcd with its cofactors: $G$ monic (lex), $A = G \bar A$, $B = G \bar B$.
pub(super) type Triple = (Dense, Dense, Dense);

/// Pseudo-random evaluation point in $[1, p)$ (SplitMix64 on `state`).
fn next_point(zp: Zp, state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    1 + (z ^ (z >> 31)) % (zp.p - 1)
}

fn min_dims(a: &[usize], b: &[usize]) -> Vec<usize> {
    a.iter().zip(b).map(|(x, y)| *x.min(y)).collect()
}

/// gcd and cofactors of nonzero `a`, `b` (same number of variables); shapes: $G$ in the
/// elementwise minimum of the two shapes, $\bar A$ in `a`'s, $\bar B$ in `b`'s. `None` when
/// too many evaluation points failed.
pub(super) fn gcd_rec(zp: Zp, a: &Dense, b: &Dense, rng: &mut u64) -> Option<Triple> {
    let k = a.dims.len();
    let gdims = min_dims(&a.dims, &b.dims);
    if k == 1 {
        let g = ugcd(zp, &a.c, &b.c);
        let (qa, _) = udivrem(zp, &a.c, &g);
        let (qb, _) = udivrem(zp, &b.c, &g);
        let pad = |u: Up, n: usize| {
            let mut c = u;
            c.resize(n, 0);
            Dense { dims: vec![n], c }
        };
        return Some((pad(g, gdims[0]), pad(qa, a.dims[0]), pad(qb, b.dims[0])));
    }
    let v = k - 1;
    // both free of the last variable: one variable less
    if a.dims[v] == 1 && b.dims[v] == 1 {
        let drop = |d: &Dense| Dense {
            dims: d.dims[..v].to_vec(),
            c: d.c.clone(),
        };
        let (g, x, y) = gcd_rec(zp, &drop(a), &drop(b), rng)?;
        let add = |d: Dense| {
            let mut dims = d.dims;
            dims.push(1);
            Dense { dims, c: d.c }
        };
        return Some((add(g), add(x), add(y)));
    }
    let (ca, cb) = (a.content_last(zp), b.content_last(zp));
    let ap = if ca.len() > 1 {
        a.div_fibers(zp, &ca)
    } else {
        a.clone()
    };
    let bp = if cb.len() > 1 {
        b.div_fibers(zp, &cb)
    } else {
        b.clone()
    };
    let cg = ugcd(zp, &ca, &cb);
    let (lca, lcb) = (ap.lead_fiber(), bp.lead_fiber());
    let gamma = ugcd(zp, &lca, &lcb);
    let len = gamma.len() - 1 + ap.deg_last().max(bp.deg_last()) + 1;
    let (pa, pb, pg) = (&a.dims[..v], &b.dims[..v], &gdims[..v]);
    let size = |d: &[usize]| d.iter().product::<usize>();
    let mut ig = Interp::new(size(pg), len);
    let mut ia = Interp::new(size(pa), len);
    let mut ib = Interp::new(size(pb), len);
    let mut m: Up = vec![1];
    let mut lead: Option<usize> = None;
    let mut bad = 0;
    let finish = |(g, x, y): Triple| -> Option<Triple> {
        // G = cg * g made monic; A = G * (ca / cg) x / s, ...
        let mut gf = g.mul_fibers(zp, &cg, gdims[v])?;
        let s = gf.c[gf.lead()?];
        let sinv = zp.inv(s);
        gf.scale(zp, sinv);
        let cofactor = |x: Dense, c: &[u64], n: usize| -> Option<Dense> {
            let (r, _) = udivrem(zp, c, &cg);
            let mut d = x.mul_fibers(zp, &r, n)?;
            d.scale(zp, s);
            Some(d)
        };
        Some((
            gf,
            cofactor(x, &ca, a.dims[v])?,
            cofactor(y, &cb, b.dims[v])?,
        ))
    };
    loop {
        if bad > MAX_BAD {
            return None;
        }
        let beta = next_point(zp, rng);
        let gb = ueval(zp, &gamma, beta);
        if gb == 0 || ueval(zp, &lca, beta) == 0 || ueval(zp, &lcb, beta) == 0 {
            bad += 1;
            continue;
        }
        let (ae, be) = (ap.eval_last(zp, beta), bp.eval_last(zp, beta));
        let Some((mut g, x, y)) = gcd_rec(zp, &ae, &be, rng) else {
            bad += 1;
            continue;
        };
        let li = g.lead()?;
        if li == 0 {
            // coprime primitive parts: G = cg
            let mut one = Dense::zeros(gdims.clone());
            one.c[0] = 1;
            let g1 = one.reshape(&gdims)?;
            let (xa, ya) = (ap.clone(), bp.clone());
            return finish((g1, xa, ya));
        }
        match lead {
            Some(l) if li > l => {
                bad += 1;
                continue;
            }
            Some(l) if li == l => {}
            _ => {
                lead = Some(li);
                ig.clear();
                ia.clear();
                ib.clear();
                m = vec![1];
            }
        }
        g.scale(zp, gb);
        let s = zp.inv(ueval(zp, &m, beta));
        let cg_ = ig.add(zp, &g.c, beta, &m, s);
        let ca_ = ia.add(zp, &x.c, beta, &m, s);
        let cb_ = ib.add(zp, &y.c, beta, &m, s);
        m = umul(zp, &m, &[zp.sub(0, beta), 1]);
        let npts = m.len() - 1;
        let full = npts >= len;
        if npts >= 2 || full {
            // candidates, the stable ones first by size
            let mut order: Vec<(usize, usize)> = Vec::new();
            if !cb_ || full {
                order.push((size(pb), 2));
            }
            if !ca_ || full {
                order.push((size(pa), 1));
            }
            if !cg_ || full {
                order.push((size(pg), 0));
            }
            order.sort();
            for (_, which) in order {
                let t = match which {
                    0 => {
                        let gc = ig.to_dense(pg).pp_last(zp);
                        div_dense(zp, &ap, &gc).and_then(|x| {
                            let y = div_dense(zp, &bp, &gc)?;
                            Some((gc, x, y))
                        })
                    }
                    1 => try_cofactor(zp, &ia.to_dense(pa), &ap, &bp),
                    _ => try_cofactor(zp, &ib.to_dense(pb), &bp, &ap).map(|(gc, y, x)| (gc, x, y)),
                };
                if let Some((gc, x, y)) = t {
                    let gc = gc.reshape(&gdims)?;
                    return finish((gc, x.reshape(&a.dims)?, y.reshape(&b.dims)?));
                }
            }
            if full {
                return None;
            }
        }
    }
}

/// From a cofactor candidate `xc` of `a`: $G = a / \operatorname{pp}(x_c)$, then $b / G$.
fn try_cofactor(zp: Zp, xc: &Dense, a: &Dense, b: &Dense) -> Option<Triple> {
    let x = xc.pp_last(zp);
    let g = div_dense(zp, a, &x)?;
    let y = div_dense(zp, b, &g)?;
    Some((g, x, y))
}
