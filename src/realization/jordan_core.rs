//! The Jordan-method minimal realization written once over any field $F$ with a Jordan
//! decomposition ([`crate::jordan::EigenField`]: $\mathbb{Q}$, $\mathbb{Q}(\sqrt d)$,
//! $\mathbb{Q}(i)$); [`super::minimal_jordan`] writes its result as modal blocks.
//!
//! For each irreducible factor $g$ of $\chi_A$ over $F$, in $E = F\[t\]/(g)$ (all roots of $g$
//! at once, conjugates by embedding):
//!
//! 1. the modal data $(J_t, W B, C V)$, the products taken on coefficient matrices over $F$
//!    (the field's product kernel, no product in $E$);
//! 2. per Jordan block the states from the first observed to the last excited one are kept
//!    ([`drop_modes`]: the others never reach $y$ or are never excited);
//! 3. the repeated modes are compacted by a Kalman minimal realization of $(N, WB, CV)$, $N$
//!    the nilpotent part, put back in Jordan form by its chains.
//!
//! # Verification
//! Exact: $\sum_g \mathrm{Tr}_{E/F}(C_g J_g^k B_g) = C A^k B$ for $k < n + r$ (the trace over
//! the roots of $g$ lies in $F$: $\mathrm{Tr}(\sum_i c_i t^i) = \sum_i c_i s_i$ with the Newton
//! power sums $s_i$ of $g$), and the order $r$ equals the McMillan degree (Hankel rank), so
//! the result is minimal.

use super::controllability::mcmillan_degree;
use super::kalman::kalman_decomposition;
use crate::algebraic::{Ext, ExtElem};
use crate::error::Result;
use crate::field::{Field, Rational};
use crate::jordan::chains::{jordan_block_matrix, jordan_chains};
use crate::jordan::coeffs::{coeff_cols, elem_of_col};
use crate::jordan::primary::Component;
use crate::jordan::{EigenField, JordanForm, jordan_over};
use crate::matrix::Matrix;
use crate::system::StateSpace;

/// One compacted component: $(J, B, C)$ over $E$ (marked at its first root), its Jordan
/// block sizes and the index of its component in the Jordan form.
#[derive(Clone, Debug)]
pub(super) struct Compact<F: Field> {
    pub comp: usize,
    pub blocks: Vec<usize>,
    pub a: Matrix<Ext<F>>,
    pub b: Matrix<Ext<F>>,
    pub c: Matrix<Ext<F>>,
}

/// The method's result over $F$: the Jordan form, the compacted components, the orders
/// (original, after dropping modes, after compaction), the McMillan degree and the exact
/// verification; `markov` holds $C A^k B$ for $k <$ `markov.len()` $= n + r$.
pub(super) struct Core<F: Field> {
    pub jf: JordanForm<F>,
    pub comps: Vec<Compact<F>>,
    pub stages: [usize; 3],
    pub mcmillan_degree: usize,
    pub markov: Vec<Matrix<F>>,
    pub verified: bool,
}

/// Keeps, per Jordan block, the states from the first observed to the last excited one.
pub(super) fn drop_modes<K: Field>(
    blocks: &[usize],
    b: &Matrix<K>,
    c: &Matrix<K>,
) -> (Vec<usize>, Vec<usize>) {
    let k = b.field().clone();
    let (mut keep, mut sizes, mut start) = (vec![], vec![], 0);
    for &s in blocks {
        let idx: Vec<usize> = (start..start + s).collect();
        let excited = idx
            .iter()
            .rposition(|&i| b.row(i).iter().any(|x| !k.is_zero(x)));
        let observed = idx
            .iter()
            .position(|&i| (0..c.nrows()).any(|r| !k.is_zero(c.get(r, i))));
        if let (Some(hi), Some(lo)) = (excited, observed)
            && lo <= hi
        {
            keep.extend(start + lo..=start + hi);
            sizes.push(hi - lo + 1);
        }
        start += s;
    }
    (keep, sizes)
}

/// $W B$ for $W$ over $E$ and $B$ over $F$, as products of coefficient matrices over $F$
/// (row $r$ of $W$ as the $d \times n$ matrix of its coefficients, times $B$).
pub(super) fn times_base<F: Field>(w: &Matrix<Ext<F>>, b: &Matrix<F>) -> Matrix<Ext<F>> {
    let e = w.field().clone();
    let mut out = Matrix::zeros(e.clone(), w.nrows(), b.ncols());
    for r in 0..w.nrows() {
        let prod = &coeff_cols(&e, w.row(r)) * b;
        for j in 0..b.ncols() {
            out.set(r, j, elem_of_col(&prod, j));
        }
    }
    out
}

/// $C V$ for $C$ over $F$ and $V$ over $E$, as [`times_base`] does $W B$.
pub(super) fn base_times<F: Field>(c: &Matrix<F>, v: &Matrix<Ext<F>>) -> Matrix<Ext<F>> {
    let e = v.field().clone();
    let ct = c.transpose();
    let mut out = Matrix::zeros(e.clone(), c.nrows(), v.ncols());
    for r in 0..v.ncols() {
        let prod = &coeff_cols(&e, &v.col(r)) * &ct;
        for i in 0..c.nrows() {
            out.set(i, r, elem_of_col(&prod, i));
        }
    }
    out
}

/// Steps 1-3 of the module docs for one component; `stage1` counts the states kept by
/// step 2 (times the degree of the factor).
pub(super) fn compact_component<F: Field + 'static>(
    sys: &StateSpace<F>,
    ci: usize,
    comp: &Component<F>,
    stage1: &mut usize,
) -> Result<Option<Compact<F>>> {
    let e = &comp.field;
    let bk = times_base(&comp.left_chains, &sys.b);
    let ck = base_times(&sys.c, &comp.chains);
    let (keep, sizes) = drop_modes(&comp.blocks, &bk, &ck);
    *stage1 += keep.len() * comp.degree();
    if keep.is_empty() {
        return Ok(None);
    }
    let theta = comp.root_elem();
    if keep.len() == 1 {
        // one excited and observed mode (a simple eigenvalue): already minimal
        return Ok(Some(Compact {
            comp: ci,
            blocks: vec![1],
            a: Matrix::from_vec(e.clone(), 1, 1, vec![theta]),
            b: bk.select_rows(&keep),
            c: ck.select_cols(&keep),
        }));
    }
    let nilp = jordan_block_matrix(e, &e.zero(), &sizes);
    let trimmed =
        StateSpace::new_strictly_proper(nilp, bk.select_rows(&keep), ck.select_cols(&keep))?;
    let min = kalman_decomposition(&trimmed)?.minimal_part();
    let r = min.nstates();
    if r == 0 {
        return Ok(None);
    }
    let ch = jordan_chains(&min.a, r)?;
    Ok(Some(Compact {
        comp: ci,
        a: jordan_block_matrix(e, &theta, &ch.blocks),
        blocks: ch.blocks,
        b: &ch.w * &min.b,
        c: &min.c * &ch.v,
    }))
}

/// $\mathrm{Tr}_{E/F}(t^e x) = \sum_c x_c s_{e+c}$.
pub(super) fn trace_shifted<F: Field>(
    k: &F,
    x: &ExtElem<F::Elem>,
    e: usize,
    s: &[F::Elem],
) -> F::Elem {
    x.0.iter()
        .enumerate()
        .fold(k.zero(), |acc, (c, xc)| k.add(&acc, &k.mul(xc, &s[e + c])))
}

/// Adds $\mathrm{Tr}_{E/F}(C J^k B)$ to `sum[k]` for every $k$ without a product in $E$ per
/// $k$: inside a Jordan block $(J^k)_{l, l+r} = \binom kr t^{k-r}$, so each entry is
/// $\sum_r \binom kr \mathrm{Tr}(t^{k-r} x_r)$ with $x_r = \sum_l C_{il} B_{l+r,j}$
/// (products computed once) and the power sums of the factor $g$.
fn add_traces<F: Field>(c: &Compact<F>, comp: &Component<F>, sum: &mut [Matrix<F>]) {
    let kmax = sum.len();
    let g = &comp.factor;
    let k = g.field().clone();
    let e = &comp.field;
    let (p, m) = (c.c.nrows(), c.b.ncols());
    let smax = c.blocks.iter().copied().max().unwrap_or(0);
    let mut s = crate::poly::newton_power_sums(&g.monic(), kmax + g.deg());
    s.truncate(kmax + g.deg() + 1);
    // binomials C(kk, r) for kk < kmax, r < smax, in F
    let binom: Vec<Vec<F::Elem>> = (0..kmax)
        .map(|kk| {
            let mut b = Rational::from_integer(1.into());
            (0..smax.min(kk + 1))
                .map(|r| {
                    let x = k.from_rational(&b);
                    b = &b * Rational::from_integer((kk - r).into())
                        / Rational::from_integer((r + 1).into());
                    x
                })
                .collect()
        })
        .collect();
    for i in 0..p {
        for j in 0..m {
            let mut x = vec![e.zero(); smax];
            let mut off = 0;
            for &bs in &c.blocks {
                for (r, xr) in x.iter_mut().enumerate().take(bs) {
                    for l in off..off + bs - r {
                        *xr = e.add(xr, &e.mul(c.c.get(i, l), c.b.get(l + r, j)));
                    }
                }
                off += bs;
            }
            for (kk, term) in sum.iter_mut().enumerate() {
                let mut v = term.get(i, j).clone();
                for (r, xr) in x.iter().enumerate().take(kk + 1) {
                    if e.is_zero(xr) {
                        continue;
                    }
                    let tr = trace_shifted(&k, xr, kk - r, &s);
                    v = k.add(&v, &k.mul(&binom[kk][r], &tr));
                }
                term.set(i, j, v);
            }
        }
    }
}

/// The compaction of given components and the exact check (the method without the
/// decomposition): compacted components, orders, McMillan degree, Markov parameters.
pub(super) struct Compacted<F: Field> {
    pub comps: Vec<Compact<F>>,
    pub stages: [usize; 3],
    pub mcmillan_degree: usize,
    pub markov: Vec<Matrix<F>>,
    pub verified: bool,
}

/// Steps 1-3 of the module docs on the components of $A$ over any field, and the exact check.
///
/// # Errors
/// Those of the Kalman decomposition.
pub(super) fn compact_components<F: Field + 'static>(
    sys: &StateSpace<F>,
    components: &[Component<F>],
) -> Result<Compacted<F>> {
    let n = sys.nstates();
    let mut stage1 = 0;
    let mut comps = vec![];
    for (ci, comp) in components.iter().enumerate() {
        if let Some(c) = compact_component(sys, ci, comp, &mut stage1)? {
            comps.push(c);
        }
    }
    let r: usize = comps
        .iter()
        .map(|c| c.a.nrows() * components[c.comp].degree())
        .sum();
    let kmax = n + r;
    let markov = sys.markov(kmax);
    let k = sys.a.field().clone();
    let mut sum: Vec<Matrix<F>> = (0..kmax)
        .map(|_| Matrix::zeros(k.clone(), sys.noutputs(), sys.ninputs()))
        .collect();
    for c in &comps {
        add_traces(c, &components[c.comp], &mut sum);
    }
    let mcm = mcmillan_degree(sys);
    let verified = sum == markov && r == mcm;
    Ok(Compacted {
        comps,
        stages: [n, stage1, r],
        mcmillan_degree: mcm,
        markov,
        verified,
    })
}

/// The Jordan method over $F$ (module docs): decomposition, compaction and the exact check.
///
/// # Errors
/// Those of [`jordan_over`] and of the Kalman decomposition.
pub(super) fn jordan_core<F: EigenField>(sys: &StateSpace<F>) -> Result<Core<F>> {
    let jf = jordan_over(&sys.a)?;
    let Compacted {
        comps,
        stages,
        mcmillan_degree,
        markov,
        verified,
    } = compact_components(sys, &jf.components)?;
    Ok(Core {
        jf,
        comps,
        stages,
        mcmillan_degree,
        markov,
        verified,
    })
}

/// The real block of a complex pair from the complex block $(A, B, C)$ of its upper root:
/// with `re_im` the exact real and imaginary parts of an entry in the real field `t`,
/// $A_r = [[\mathrm{Re}, \mathrm{Im}], [-\mathrm{Im}, \mathrm{Re}]]$ per entry,
/// $B_r = [\mathrm{Re}\, B; -\mathrm{Im}\, B]$, $C_r = [2\,\mathrm{Re}\, C, 2\,\mathrm{Im}\, C]$,
/// interleaved per state ($x = [\mathrm{Re}\, z; -\mathrm{Im}\, z]$).
pub(super) fn real_pair_block<E: Field, T: Field>(
    t: &T,
    [a, b, c]: [&Matrix<E>; 3],
    re_im: impl Fn(&E::Elem) -> (T::Elem, T::Elem),
) -> [Matrix<T>; 3] {
    let s = a.nrows();
    let (m, p) = (b.ncols(), c.nrows());
    let two = t.from_i64(2);
    let mut ar = Matrix::zeros(t.clone(), 2 * s, 2 * s);
    let mut br = Matrix::zeros(t.clone(), 2 * s, m);
    let mut cr = Matrix::zeros(t.clone(), p, 2 * s);
    for i in 0..s {
        for j in 0..s {
            let (x, y) = re_im(a.get(i, j));
            // z = x1 - i x2: [[Re, -Im], [Im, Re]] acting on (x1, -x2) -> [[Re, Im], [-Im, Re]]
            ar.set(2 * i, 2 * j, x.clone());
            ar.set(2 * i, 2 * j + 1, y.clone());
            ar.set(2 * i + 1, 2 * j, t.neg(&y));
            ar.set(2 * i + 1, 2 * j + 1, x);
        }
        for col in 0..m {
            let (x, y) = re_im(b.get(i, col));
            br.set(2 * i, col, x);
            br.set(2 * i + 1, col, t.neg(&y));
        }
        for row in 0..p {
            let (x, y) = re_im(c.get(row, i));
            cr.set(row, 2 * i, t.mul(&two, &x));
            cr.set(row, 2 * i + 1, t.mul(&two, &y));
        }
    }
    [ar, br, cr]
}

#[cfg(test)]
mod tests {
    use crate::field::{Q, Rational};
    use crate::poly::Poly;
    #[test]
    fn power_sums_of_quadratic() {
        // x^2 - 3x + 2: roots 1, 2 -> p0 = 2, p1 = 3, p2 = 5, p3 = 9 (the traces' power sums)
        let p: Poly<Q> = Poly::from_i64s(&[2, -3, 1]);
        let s = crate::poly::newton_power_sums(&p.monic(), 3);
        let want: Vec<Rational> = [2, 3, 5, 9]
            .iter()
            .map(|&v: &i64| Rational::from_integer(v.into()))
            .collect();
        assert_eq!(s, want);
    }
}
