//! Controllability structure of $(A, B)$: controllable order, controllability (Kronecker /
//! Brunovsky) indices, staircase block dimensions, uncontrollable part; observability by
//! duality; finite and infinite controllability of regular descriptor systems.
//!
//! # Algorithm
//! Luenberger's greedy Krylov selection, exact: level $k$ holds the candidates
//! $A^kb_j$ of the inputs whose chain is still alive; a candidate dependent on all
//! earlier columns (exact RREF pivots of $[S \mid \text{candidates}]$) ends its chain (and
//! every later one of that input would be dependent too). Chain $j$ has length
//! $\kappa_j$ (the controllability index of input $j$; $0$ for an input in the span of the
//! earlier ones); the staircase block dimensions are $\rho_k = \#\{j : \kappa_j \ge k\}$,
//! $\rho_1 = \mathrm{rank}\,B$; the indices are the right Kronecker indices of
//! $[sI - A, B]$ (SLICOT AB01ND / AB01OD report the same $\rho_k$).
//!
//! # Verification
//! With $S$ the selected Krylov columns and $L$ ($n - \sum\kappa_j$ rows, the identity on
//! some columns, so of full row rank): $\mathrm{rank}\,S = \sum\kappa_j$, $LB = 0$ and
//! $LA = A_{\bar c}L$; so $\ker L$ contains $B$ and is $A$-invariant, hence contains the
//! controllable subspace, which contains $\mathrm{span}\,S$; the dimensions agree, so all
//! three are equal and $A_{\bar c}$ is the uncontrollable part (its eigenvalues are the
//! uncontrollable eigenvalues). Over $\mathbb{Q}$ the rank of $S$ is bounded below by one
//! elimination modulo a prime, and $L$ and the coefficients that place each rejected
//! Krylov candidate in the span of the earlier picks are guessed modulo primes and then
//! checked by exact products (the Krylov vectors have large entries, their relations small
//! ones: no certified RREF of $S$ is needed).

use super::weierstrass::weierstrass_split;
use crate::error::Result;
use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::Descriptor;

/// The controllability structure of $(A, B)$.
#[derive(Clone, Debug)]
pub struct ControllabilityStructure<K: Field> {
    /// $\dim$ of the controllable subspace.
    pub order: usize,
    /// Controllability indices $\kappa_j$, largest first (one per input; zeros for inputs
    /// dependent on earlier ones).
    pub indices: Vec<usize>,
    /// Staircase block dimensions $\rho_1 \ge \rho_2 \ge \dots$ ($\rho_1 = \mathrm{rank}\,B$).
    pub block_dims: Vec<usize>,
    /// Selected Krylov columns: a basis of the controllable subspace ($n \times$ `order`).
    pub basis: Matrix<K>,
    /// $L$ with $LS = 0$ of full row rank, $LA = A_{\bar c}L$.
    pub left: Matrix<K>,
    /// The uncontrollable part $A_{\bar c}$ ($(n - \text{order})$ square).
    pub uncontrollable: Matrix<K>,
    pub verified: bool,
}

impl<K: Field> ControllabilityStructure<K> {
    /// The largest controllability index (0 without inputs).
    pub fn controllability_index(&self) -> usize {
        self.indices.first().copied().unwrap_or(0)
    }
}

/// Controllability structure of $(A, B)$.
///
/// # Errors
/// `NotSquare`/`Shape` when the matrices do not fit.
///
/// # Examples
/// ```
/// use exactlti::{qmat, realization::controllability_structure};
/// let c = controllability_structure(&qmat![[0, 1, 0], [0, 0, 0], [0, 0, 5]], &qmat![[0], [1], [0]]).unwrap();
/// assert_eq!((c.order, c.indices.clone(), c.block_dims.clone()), (2, vec![2], vec![1, 1]));
/// assert_eq!(c.uncontrollable.to_string(), "[[5]]");
/// assert!(c.verified);
/// ```
pub fn controllability_structure<K: Field>(
    a: &Matrix<K>,
    b: &Matrix<K>,
) -> Result<ControllabilityStructure<K>> {
    a.check_square("controllability A")?;
    let n = a.nrows();
    b.check_shape("controllability B", (n, b.ncols()))?;
    let m = b.ncols();
    // Krylov selection: over Q first modulo word-size primes (certified below, exactly),
    // then, if no prime gives a certified selection, by exact elimination per level.
    let mut found = None;
    for pr in crate::qkernels::prime::primes(7).take(3) {
        let Some((ap, bp)) = a.image_mod_p(&pr).zip(b.image_mod_p(&pr)) else {
            continue;
        };
        if let Some(levels) = krylov_levels_mod_p(&pr, n, m, &ap, &bp)
            && let Some(sel) = certify_levels(a, b, &levels)
        {
            found = Some(sel);
            break;
        }
    }
    let (kappa, basis, block_dims) = match found {
        Some(sel) => sel,
        None => krylov_levels_exact(a, b)?,
    };
    let order = basis.ncols();
    // L with the identity on the columns `unit` (so of full row rank n - order) and
    // A_c̄ = (L A) restricted to those columns: first guessed modulo primes over Q, else
    // the exact left null space in RREF (unit columns = its pivots)
    let check = |left: &Matrix<K>, unit: &[usize]| {
        let la = left * a;
        let unc = la.select_cols(unit);
        let ok = left.nrows() == n - order
            && unit.len() == n - order
            && left.is_identity_on_cols(unit)
            && (left * b).is_zero()
            && la == &unc * left;
        ok.then_some(unc)
    };
    let guessed =
        left_kernel_guess(&basis).and_then(|(l, unit)| check(&l, &unit).map(|unc| (l, unc)));
    let (left, uncontrollable, left_ok) = match guessed {
        Some((l, unc)) => (l, unc, true),
        None => {
            let left = basis.left_nullspace();
            let (_, lpiv) = left.rref();
            match check(&left, &lpiv) {
                Some(unc) => (left, unc, true),
                None => {
                    let unc = (&left * a).select_cols(&lpiv);
                    (left, unc, false)
                }
            }
        }
    };
    // `basis.rank() == order` holds by the selection (certified independent columns)
    let verified = left_ok && kappa.iter().sum::<usize>() == order;
    let mut indices = kappa;
    indices.sort_unstable_by(|x, y| y.cmp(x));
    Ok(ControllabilityStructure {
        order,
        indices,
        block_dims,
        basis,
        left,
        uncontrollable,
        verified,
    })
}

/// Observability structure of $(C, A)$: the controllability structure of $(A^T, C^T)$
/// (indices = observability indices, `uncontrollable` = the unobservable part transposed).
///
/// # Errors
/// As [`controllability_structure`].
pub fn observability_structure<K: Field>(
    a: &Matrix<K>,
    c: &Matrix<K>,
) -> Result<ControllabilityStructure<K>> {
    controllability_structure(&a.transpose(), &c.transpose())
}

/// Finite and infinite controllability of a regular descriptor system (the counts of
/// SLICOT TG01HD): the finite part $(A_f, B_f)$ and the infinite part $(N, B_\infty)$ of the
/// Weierstrass split, each with its controllability structure.
#[derive(Clone, Debug)]
pub struct DescriptorControllability<K: Field> {
    pub finite: ControllabilityStructure<K>,
    pub infinite: ControllabilityStructure<K>,
    /// $n_f$ and $n_\infty$.
    pub finite_order: usize,
    pub infinite_order: usize,
}

impl<K: Field> DescriptorControllability<K> {
    /// Controllable finite plus controllable infinite order.
    pub fn controllable_order(&self) -> usize {
        self.finite.order + self.infinite.order
    }
    /// Number of uncontrollable infinite eigenvalues.
    pub fn uncontrollable_infinite(&self) -> usize {
        self.infinite_order - self.infinite.order
    }
    pub fn verified(&self) -> bool {
        self.finite.verified && self.infinite.verified
    }
}

/// Finite and infinite controllability structure of $E\dot x = Ax + Bu$; with `dual` the
/// observability structure of $(C, A, E)$.
///
/// # Errors
/// `Invalid` for a singular pencil.
pub fn descriptor_controllability<K: Field>(
    sys: &Descriptor<K>,
    dual: bool,
) -> Result<DescriptorControllability<K>> {
    let split = weierstrass_split(sys)?;
    let f = &split.finite;
    let (finite, infinite) = if dual {
        (
            observability_structure(&f.a, &f.c)?,
            observability_structure(&split.n, &split.c_inf)?,
        )
    } else {
        (
            controllability_structure(&f.a, &f.b)?,
            controllability_structure(&split.n, &split.b_inf)?,
        )
    };
    Ok(DescriptorControllability {
        finite,
        infinite,
        finite_order: f.nstates(),
        infinite_order: split.n.nrows(),
    })
}

/// With the field's RREF guess ($\mathbb{Q}$, [`Matrix::rref_guess`]): a basis $L$ of the left null space of `basis` ($n \times s$) guessed
/// from its images modulo primes (the canonical null space of $S^T$, identity on the
/// non-pivot columns, returned with them). Nothing is trusted: the caller checks
/// $LB = 0$ and $LA = \bar A L$ exactly, which with $\mathrm{rank}\,L = n - s$ and
/// $\mathrm{rank}\,S = s$ make $\ker L$ the controllable subspace.
fn left_kernel_guess<K: Field>(basis: &Matrix<K>) -> Option<(Matrix<K>, Vec<usize>)> {
    let k = basis.field().clone();
    let (n, s) = basis.shape();
    let (piv, r) = basis.transpose().rref_guess(24)?;
    if piv.len() != s {
        return None;
    }
    let free: Vec<usize> = (0..n).filter(|c| !piv.contains(c)).collect();
    let mut l = Matrix::zeros(k.clone(), free.len(), n);
    for (i, &f) in free.iter().enumerate() {
        l.set(i, f, k.one());
        for (row, &c) in piv.iter().enumerate() {
            l.set(i, c, k.neg(r.get(row, f)));
        }
    }
    Some((l, free))
}

/// With the field's RREF guess ($\mathbb{Q}$): is every column $t$ of `rej` in the span of the first `lim[t]`
/// columns of `basis`, with `basis` of full column rank? Coefficients $C$ are guessed
/// modulo primes and $S C = R$ is checked exactly (with $C$ zero below `lim`); the rank by
/// one elimination modulo a prime (a lower bound). `None`: undecided (not over
/// $\mathbb{Q}$, or no stable guess), the caller falls back to the certified RREF.
fn contained_guess<K: Field>(basis: &Matrix<K>, rej: &Matrix<K>, lim: &[usize]) -> Option<bool> {
    let k = basis.field().clone();
    let (_, s) = basis.shape();
    let t = rej.ncols();
    if t == 0 {
        return basis.rank_at_least_mod_p(s).then_some(true);
    }
    let both = basis.hstack(rej).ok()?;
    let (piv, r) = both.rref_guess(24)?;
    if piv.len() < s || piv[..s].iter().enumerate().any(|(i, &c)| i != c) {
        return None;
    }
    if !basis.rank_at_least_mod_p(s) {
        return None;
    }
    let mut coef = Matrix::zeros(k.clone(), s, t);
    for i in 0..s {
        for j in 0..t {
            let x = r.get(i, s + j);
            if i < lim[j] {
                coef.set(i, j, x.clone());
            } else if !k.is_zero(x) {
                return Some(false);
            }
        }
    }
    Some(&(basis * &coef) == rej)
}

/// A Krylov selection: per level, the positions (in the level's candidate list) of the
/// picked candidates.  Level 0's candidates are the columns of $B$, level $k+1$'s are $A$
/// times level $k$'s picks, in order.
type Levels = Vec<Vec<usize>>;

/// (indices per input, selected columns, block dimensions).
type Selection<K> = (Vec<usize>, Matrix<K>, Vec<usize>);

/// The greedy Krylov selection of the images $(A \bmod p, B \bmod p)$ (row-major; incremental
/// echelon form over $\mathbb{F}_p$).
fn krylov_levels_mod_p(
    pr: &crate::qkernels::prime::Prime,
    n: usize,
    m: usize,
    ap: &[u64],
    bp: &[u64],
) -> Option<Levels> {
    // echelon rows: (pivot position, vector with 1 at the pivot)
    let mut ech: Vec<(usize, Vec<u64>)> = Vec::new();
    let mut cand: Vec<Vec<u64>> = (0..m)
        .map(|j| (0..n).map(|i| bp[i * m + j]).collect())
        .collect();
    let mut levels = Vec::new();
    while !cand.is_empty() && ech.len() < n {
        let mut picked = Vec::new();
        let mut picked_vecs = Vec::new();
        for (c, v0) in cand.iter().enumerate() {
            let mut v = v0.clone();
            for (piv, w) in &ech {
                let f = v[*piv];
                if f != 0 {
                    pr.axpy_neg(&mut v, w, f);
                }
            }
            if let Some(piv) = v.iter().position(|&x| x != 0) {
                let inv = pr.inv(v[piv])?;
                pr.scale(&mut v, inv);
                ech.push((piv, v));
                picked.push(c);
                picked_vecs.push(v0.clone());
            }
        }
        if picked.is_empty() {
            break;
        }
        levels.push(picked);
        cand = picked_vecs
            .iter()
            .map(|v| {
                (0..n)
                    .map(|i| {
                        let row = &ap[i * n..(i + 1) * n];
                        row.iter()
                            .zip(v)
                            .fold(0u64, |s, (&x, &y)| pr.add(s, pr.mul(x, y)))
                    })
                    .collect()
            })
            .collect();
    }
    Some(levels)
}

/// Replays `levels` exactly and certifies it: with $S_{\le k}$ the picks of levels
/// $\le k$ and $R_k$ the rejected candidates of level $k$ (also those of the level after
/// the last one when $S$ is not square), $S$ must have full column rank and every column
/// of $R_k$ lie in $\mathrm{span}\,S_{\le k}$: over $\mathbb{Q}$ by exhibited coefficients
/// $SC = R$ (exact product) and a rank modulo a prime ([`contained_guess`]), else by one
/// exact RREF of $[S \mid R]$.  Then by
/// induction on $K_{k+1} = \mathrm{span}\,B + A K_k$, the Krylov spaces are
/// $K_k = \mathrm{span}\,S_{\le k}$, so the block dimensions and indices are exact.
fn certify_levels<K: Field>(a: &Matrix<K>, b: &Matrix<K>, levels: &Levels) -> Option<Selection<K>> {
    let n = a.nrows();
    let m = b.ncols();
    let mut kappa = vec![0usize; m];
    let mut alive: Vec<usize> = (0..m).collect();
    let mut cand = b.clone();
    let mut blocks: Vec<Matrix<K>> = Vec::new();
    let mut block_dims = Vec::new();
    // (column of R, number of S columns it may use)
    let mut rejected: Vec<Matrix<K>> = Vec::new();
    let mut rej_limit: Vec<usize> = Vec::new();
    let mut s = 0usize;
    for pick in levels.iter().map(Some).chain(std::iter::once(None)) {
        let pick: &[usize] = pick.map_or(&[], |p| p.as_slice());
        if pick.iter().any(|&c| c >= cand.ncols()) {
            return None;
        }
        let last = pick.is_empty();
        if last && s == n {
            break;
        }
        s += pick.len();
        let rej: Vec<usize> = (0..cand.ncols()).filter(|c| !pick.contains(c)).collect();
        if !rej.is_empty() {
            rejected.push(cand.select_cols(&rej));
            rej_limit.extend(std::iter::repeat_n(s, rej.len()));
        }
        if last {
            break;
        }
        let survivors: Vec<usize> = pick.iter().map(|&c| alive[c]).collect();
        for &j in &survivors {
            kappa[j] += 1;
        }
        block_dims.push(pick.len());
        let picked = cand.select_cols(pick);
        cand = a * &picked;
        blocks.push(picked);
        alive = survivors;
    }
    let mut basis = Matrix::zeros(a.field().clone(), n, 0);
    for blk in &blocks {
        basis = basis.hstack(blk).ok()?;
    }
    let mut rej_all = Matrix::zeros(a.field().clone(), n, 0);
    for r in &rejected {
        rej_all = rej_all.hstack(r).ok()?;
    }
    // a guess that fails its check is no proof of the contrary: the RREF decides
    if contained_guess(&basis, &rej_all, &rej_limit) == Some(true) {
        return Some((kappa, basis, block_dims));
    }
    let both = basis.hstack(&rej_all).ok()?;
    let (r, piv) = both.rref();
    if piv.len() != s || piv.iter().enumerate().any(|(i, &c)| i != c) {
        return None;
    }
    let fld = a.field();
    for (t, &lim) in rej_limit.iter().enumerate() {
        let col = s + t;
        if (lim..s).any(|i| !fld.is_zero(r.get(i, col))) {
            return None;
        }
    }
    Some((kappa, basis, block_dims))
}

/// The greedy Krylov selection by one exact RREF of $[S \mid \text{candidates}]$ per level.
fn krylov_levels_exact<K: Field>(a: &Matrix<K>, b: &Matrix<K>) -> Result<Selection<K>> {
    let n = a.nrows();
    let m = b.ncols();
    let fld = a.field().clone();
    let mut kappa = vec![0usize; m];
    let mut basis = Matrix::zeros(fld, n, 0);
    let mut alive: Vec<usize> = (0..m).collect();
    let mut cand = b.clone();
    let mut block_dims = Vec::new();
    while !alive.is_empty() && basis.ncols() < n {
        let both = basis.hstack(&cand)?;
        let (_, piv) = both.rref();
        let s = basis.ncols();
        let new: Vec<usize> = piv.into_iter().filter(|&c| c >= s).map(|c| c - s).collect();
        if new.is_empty() {
            break;
        }
        let survivors: Vec<usize> = new.iter().map(|&c| alive[c]).collect();
        for &j in &survivors {
            kappa[j] += 1;
        }
        block_dims.push(new.len());
        let picked = cand.select_cols(&new);
        basis = basis.hstack(&picked)?;
        cand = a * &picked;
        alive = survivors;
    }
    Ok((kappa, basis, block_dims))
}
