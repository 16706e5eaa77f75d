//! The Jordan decomposition step by step (`jordan --steps`), over $\mathbb{Q}$ and
//! $\mathbb{Q}(p)$, recorded as a [`Derivation`].
//!
//! Steps: $\chi_A = \det(xI - A)$ (checked by Cayley–Hamilton $\chi_A(A) = 0$); its factors
//! ($\prod p_i^{e_i} = \chi_A$); per eigenvalue $\theta$ of multiplicity $m$ the kernel
//! sequence $\dim\ker N^k$, $N = A - \theta I$, from ranks of the powers $N^k$ (equal to the
//! flag the chains are built on, ending at $m$); the Weyr characteristic $w_k$ and its
//! conjugate partition, the Segre characteristic (the block sizes); each chain built top-down
//! ($N v_1 = 0$, $N v_j = v_{j-1}$, $v_1 \ne 0$); $A V = V J_\theta$, $W V = I$; finally
//! $A T = T J$.
//!
//! Over $\mathbb{Q}$ an irreducible factor $p$ of degree $d \ge 2$ is worked once in
//! $K_p = \mathbb{Q}\[t\]/(p)$ at the generic root $t$ (the conjugate roots by the
//! embeddings $t \mapsto \theta_j$), so the derivation is over number fields (a rational
//! eigenvalue in $\mathbb{Q}$ as a field of degree 1). Over $\mathbb{Q}(p)$ a factor of degree
//! $\ge 2$ gives its primary block ($\dim\ker f(A)^k$, $A B = B M$); every step lists the
//! polynomials in the parameters it assumes nonzero.
//!
//! The chains are those of [`super::chains::jordan_chains`], the primitive [`super::jordan`]
//! and [`super::jordan_qp`] use.

pub use super::chains::is_chain;
use super::chains::{jordan_block_matrix, jordan_chains};
use super::derivation::{Derivation, Method, Object, Recorder, StepKind, ratfunc_log};
use super::normalize::{Normalization, UnitLength, normalize_chain, normalized_holds};
use super::primary::{named_field, rational_field};
use crate::algebraic::NumberField;
use crate::error::Result;
use crate::field::{Field, Q};
use crate::matrix::Matrix;
use crate::mpoly::MPoly;
use crate::mpoly::resultant::{discriminant, resultant};
use crate::poly::Poly;
use crate::ratfunc::RatFuncField;

/// $M - \theta I$.
fn shift<K: Field>(m: &Matrix<K>, theta: &K::Elem) -> Matrix<K> {
    let k = m.field().clone();
    let mut out = m.clone();
    for i in 0..m.nrows() {
        let v = k.sub(out.get(i, i), theta);
        out.set(i, i, v);
    }
    out
}

/// Ranks of $N, N^2, \dots$ until $\dim\ker N^k \ge m$ (at most $m$ powers).
fn kernel_sequence<K: Field>(nm: &Matrix<K>, m: usize) -> (Vec<usize>, Vec<usize>) {
    let n = nm.nrows();
    let (mut ranks, mut dims) = (vec![], vec![]);
    let mut pw = nm.clone();
    loop {
        let r = pw.rank();
        ranks.push(r);
        dims.push(n - r);
        if n - r >= m || dims.len() >= m.max(1) {
            return (ranks, dims);
        }
        pw = &pw * nm;
    }
}

/// Weyr characteristic ($w_k = d_k - d_{k-1}$) and its conjugate partition (Segre
/// characteristic: $s_j = \#\{k : w_k \ge j\}$, the block sizes, largest first).
pub fn weyr_segre(dims: &[usize]) -> (Vec<usize>, Vec<usize>) {
    let mut weyr = vec![];
    let mut prev = 0;
    for &d in dims {
        weyr.push(d.saturating_sub(prev));
        prev = d;
    }
    let top = weyr.first().copied().unwrap_or(0);
    let segre = (1..=top)
        .map(|j| weyr.iter().filter(|&&w| w >= j).count())
        .collect();
    (weyr, segre)
}

/// Records the steps of the eigenvalue `theta` (multiplicity `m`) of `a` and returns its
/// chains $V$ and block sizes.
///
/// # Errors
/// As [`jordan_chains`] (a wrong multiplicity).
pub fn eigenvalue_steps<K: Field + 'static>(
    rec: &mut Recorder<'_, K>,
    part: usize,
    a: &Matrix<K>,
    theta: &K::Elem,
    m: usize,
) -> Result<(Matrix<K>, Vec<usize>)> {
    let k = a.field().clone();
    let n = a.nrows();
    let nm = shift(a, theta);
    let (ranks, dims) = kernel_sequence(&nm, m);
    let ch = jordan_chains(&nm, m)?;
    let ok = dims == ch.kernel_dims && dims.last() == Some(&m);
    rec.push(
        StepKind::KernelSequence,
        Some(part),
        vec![
            ("theta", Object::Scalar(theta.clone())),
            ("N", Object::Matrix(nm.clone())),
            ("ranks", Object::Counts(ranks)),
            ("dims", Object::Counts(dims.clone())),
            ("m", Object::Count(m)),
        ],
        Some(ok),
    );
    let (weyr, segre) = weyr_segre(&dims);
    let ok = segre == ch.blocks && segre.iter().sum::<usize>() == m;
    rec.push(
        StepKind::WeyrSegre,
        Some(part),
        vec![
            ("weyr", Object::Counts(weyr)),
            ("segre", Object::Counts(segre)),
        ],
        Some(ok),
    );
    // the free constants of a generalized eigenvector (the vehicle paper's eq. 30, 32):
    // N v_j = v_(j-1) holds for v_j + K c with K a basis of ker N and any c
    let ker = nm.nullspace();
    let ker_ok = (&nm * &ker).is_zero() && ker.ncols() == dims.first().copied().unwrap_or(0);
    let mut off = 0;
    for &s in &ch.blocks {
        let v = ch.v.submatrix(0, n, off, off + s);
        let mut objects = vec![("V", Object::Matrix(v.clone())), ("top", Object::Count(s))];
        let mut ok = is_chain(&nm, &v);
        if s > 1 {
            objects.push(("K", Object::Matrix(ker.clone())));
            ok = ok && ker_ok;
        }
        rec.push(StepKind::Chain, Some(part), objects, Some(ok));
        off += s;
    }
    let j = jordan_block_matrix(&k, theta, &ch.blocks);
    let ok = a * &ch.v == &ch.v * &j && (&ch.w * &ch.v).is_identity();
    rec.push(
        StepKind::EigenCheck,
        Some(part),
        vec![
            ("V", Object::Matrix(ch.v.clone())),
            ("J", Object::Matrix(j)),
        ],
        Some(ok),
    );
    Ok((ch.v, ch.blocks))
}

/// One step per chain of `theta` normalised as `how` asks (nothing when it asks nothing):
/// the chain before and after, eq. 31's constants, the row made 1 or $n = v_1 \cdot v_1$
/// with $\sqrt n$ when it lies in the field; returns the normalised columns (divided by
/// $\sqrt n$ only when exact). The identity: a chain of $N$ spanning the same space ($A V' =
/// V' J_\theta$ follows), orthogonal, entry 1 or $v_1' \cdot v_1' = 1$ (or $= n$ in closed form).
///
/// # Errors
/// As [`normalize_chain`].
pub fn normalization_steps<K: Field + 'static>(
    rec: &mut Recorder<'_, K>,
    part: usize,
    a: &Matrix<K>,
    theta: &K::Elem,
    (v, blocks): (&Matrix<K>, &[usize]),
    how: &Normalization,
    real: bool,
) -> Result<Matrix<K>> {
    if how.is_none() {
        return Ok(v.clone());
    }
    let k = a.field().clone();
    let (n, nm) = (a.nrows(), shift(a, theta));
    let mut out = v.clone();
    let mut off = 0;
    for &s in blocks {
        let chain = v.submatrix(0, n, off, off + s);
        let c = normalize_chain(&chain, how, real)?;
        let ok = normalized_holds(&nm, &chain, &c, how);
        out.set_block(0, off, &c.v);
        let mut objects = vec![
            ("V", Object::Matrix(chain)),
            ("Vn", Object::Matrix(c.v.clone())),
            ("top", Object::Count(s)),
            ("orth", Object::Count(usize::from(how.orthogonal))),
        ];
        if !c.constants.is_empty() {
            let b = Matrix::from_vec(k.clone(), 1, s - 1, c.constants.clone());
            objects.push(("b", Object::Matrix(b)));
        }
        if let Some(r) = c.entry_row {
            objects.push(("row", Object::Count(r + 1)));
        }
        match c.unit {
            UnitLength::NotAsked => {}
            UnitLength::Exact { n, root } => {
                objects.push(("n2", Object::Scalar(n)));
                objects.push(("root", Object::Scalar(root)));
            }
            UnitLength::ClosedForm { n } => objects.push(("n2", Object::Scalar(n))),
            UnitLength::Refused => objects.push(("refused", Object::Count(1))),
        }
        rec.push(StepKind::Normalization, Some(part), objects, Some(ok));
        off += s;
    }
    Ok(out)
}

/// $p(A)$ is zero (Cayley–Hamilton for $p = \chi_A$), checked for $n \le$ `max_n`.
fn annihilates<K: Field>(a: &Matrix<K>, p: &Poly<K>, max_n: usize) -> Option<bool> {
    if a.nrows() > max_n {
        return None;
    }
    a.eval_poly(p).ok().map(|m| m.is_zero())
}

/// The step $\chi(s) = \det(sI - A)$, checked by $\chi(A) = 0$ (Cayley–Hamilton) for
/// $n \le$ `max_n`.
pub(crate) fn charpoly_step<K: Field>(
    rec: &mut Recorder<'_, K>,
    a: &Matrix<K>,
    chi: &Poly<K>,
    max_n: usize,
) {
    let objects = vec![
        ("A", Object::Matrix(a.clone())),
        ("chi", Object::Poly(chi.clone())),
    ];
    rec.push(
        StepKind::CharPoly,
        None,
        objects,
        annihilates(a, chi, max_n),
    );
}

/// The product $\prod p_i^{e_i}$.
fn product<K: Field>(k: &K, factors: &[(Poly<K>, usize)]) -> Poly<K> {
    factors.iter().fold(Poly::one(k.clone()), |acc, (p, e)| {
        acc.mul(&p.pow(*e as u32))
    })
}

/// The Jordan decomposition of a rational matrix, step by step (module docs).
///
/// # Errors
/// As [`super::jordan`].
pub fn jordan_steps(a: &Matrix<Q>) -> Result<Derivation<NumberField>> {
    jordan_steps_with(a, &Normalization::default())
}

/// [`jordan_steps`] with the chains normalised as `how` asks ([`super::normalize`]): one
/// step per chain with the new chain and its identities.
///
/// # Errors
/// As [`super::jordan`]; as [`super::normalize::normalize_chain`].
pub fn jordan_steps_with(a: &Matrix<Q>, how: &Normalization) -> Result<Derivation<NumberField>> {
    a.check_square("jordan")?;
    let n = a.nrows();
    let q = rational_field();
    let lift = |m: &Matrix<Q>, f: &NumberField| m.map(f, |x| f.from_rational(x));
    let lift_poly = |p: &Poly<Q>| p.map(&q, |x| q.from_rational(x));
    let mut rec = Recorder::new(Method::Jordan, q.clone());
    let chi = a.charpoly()?;
    let chi_k = lift_poly(&chi);
    charpoly_step(&mut rec, &lift(a, &q), &chi_k, 40);
    let factors = super::roots::factor_q(&chi)?;
    let fk: Vec<(Poly<NumberField>, usize)> =
        factors.iter().map(|(p, e)| (lift_poly(p), *e)).collect();
    let ok = product(&q, &fk) == chi_k;
    rec.push(
        StepKind::Factorization,
        None,
        vec![("factors", Object::Factors(fk))],
        Some(ok),
    );
    let mut dims = vec![];
    for (part, (p, e)) in factors.iter().enumerate() {
        let (field, theta, real) = if p.deg() == 1 {
            (q.clone(), q.from_rational(&-p.coeff(0)), true)
        } else {
            let roots = super::roots::certified_roots(p)?;
            let real = roots.first().is_some_and(|z| z.0.is_real());
            let root = roots.first().map_or((0.0, 0.0), |z| z.1);
            let f = named_field(p, root, "t");
            let t = f.generator();
            (f, t, real)
        };
        let af = lift(a, &field);
        let (v, blocks) = eigenvalue_steps(&mut rec, part, &af, &theta, *e)?;
        normalization_steps(&mut rec, part, &af, &theta, (&v, &blocks), how, real)?;
        dims.push(p.deg() * e);
    }
    // every part's A V = V J (W V = I: independent columns) and the dimensions fill K^n
    let ok = dims.iter().sum::<usize>() == n && rec_all_hold(&rec, StepKind::EigenCheck);
    rec.push(
        StepKind::Similarity,
        None,
        vec![("n", Object::Count(n)), ("dims", Object::Counts(dims))],
        Some(ok),
    );
    Ok(rec.finish())
}

fn rec_all_hold<K: Field>(rec: &Recorder<'_, K>, kind: StepKind) -> bool {
    rec.peek().of_kind(kind).all(|s| s.holds == Some(true))
}

/// Drops the last variable (free in it) of a polynomial in the parameters and $x$.
fn drop_last(f: &MPoly) -> MPoly {
    let n = f.nvars() - 1;
    let map: Vec<usize> = (0..n).collect();
    f.remap(n, &map)
}

/// The Jordan decomposition over $\mathbb{Q}(p)$, step by step (module docs): the factors of
/// [`super::jordan_qp`], each worked again with its conditions recorded.
///
/// # Errors
/// As [`super::jordan_qp`].
pub fn jordan_steps_params(a_in: &Matrix<RatFuncField>) -> Result<Derivation<RatFuncField>> {
    jordan_steps_params_with(a_in, &Normalization::default())
}

/// [`jordan_steps_params`] with the chains of the eigenvalues in $\mathbb{Q}(p)$ normalised as
/// `how` asks (the parameters taken real; a factor of degree $\ge 2$ keeps its primary block).
///
/// # Errors
/// As [`super::jordan_qp`]; as [`super::normalize::normalize_chain`].
pub fn jordan_steps_params_with(
    a_in: &Matrix<RatFuncField>,
    how: &Normalization,
) -> Result<Derivation<RatFuncField>> {
    let pj = super::jordan_qp(a_in)?;
    let n = pj.n();
    let k = a_in.field().fresh();
    let a = Matrix::from_vec(k.clone(), n, n, a_in.as_slice().to_vec());
    let mut rec = Recorder::with_log(Method::Jordan, k.clone(), ratfunc_log(&k));
    let chi = Poly::new(k.clone(), pj.charpoly.coeffs().to_vec());
    charpoly_step(&mut rec, &a, &chi, 8);
    let nv = k.nvars();
    let facs: Vec<(Poly<RatFuncField>, usize)> = pj
        .components
        .iter()
        .map(|c| {
            let p = Poly::new(k.clone(), c.factor.coeffs().to_vec());
            (p, c.multiplicity)
        })
        .collect();
    let integral: Vec<MPoly> = pj
        .components
        .iter()
        .map(|c| super::qp_form::integral(&c.factor))
        .collect();
    for (i, f) in integral.iter().enumerate() {
        k.record_condition(&drop_last(&f.lc_in(nv)));
        if f.deg(nv) >= 2 {
            k.record_condition(&drop_last(&discriminant(f, nv)));
        }
        for g in &integral[i + 1..] {
            k.record_condition(&drop_last(&resultant(f, g, nv)));
        }
    }
    let ok = product(&k, &facs) == chi;
    rec.push(
        StepKind::Factorization,
        None,
        vec![("factors", Object::Factors(facs.clone()))],
        Some(ok),
    );
    let (mut t_cols, mut j_blocks) = (vec![], vec![]);
    for (part, (value, (f, m))) in pj.values().into_iter().zip(&facs).enumerate() {
        match &value {
            Some(theta) => {
                let (v, blocks) = eigenvalue_steps(&mut rec, part, &a, theta, *m)?;
                let v = normalization_steps(&mut rec, part, &a, theta, (&v, &blocks), how, true)?;
                j_blocks.push(jordan_block_matrix(&k, theta, &blocks));
                t_cols.push(v);
            }
            None => {
                let (b, mm) = primary_block_steps(&mut rec, part, &a, f, *m)?;
                j_blocks.push(mm);
                t_cols.push(b);
            }
        }
    }
    let width: usize = t_cols.iter().map(|c| c.ncols()).sum();
    let mut t = Matrix::zeros(k.clone(), n, width);
    let mut c0 = 0;
    for c in &t_cols {
        t.set_block(0, c0, c);
        c0 += c.ncols();
    }
    let j = Matrix::block_diag(k.clone(), &j_blocks);
    let mut ok = width == n && a.try_mul(&t)? == t.try_mul(&j)?;
    if ok {
        let det = t.det()?;
        ok = !k.is_zero(&det);
        k.record_condition(det.num());
    }
    rec.push(
        StepKind::Similarity,
        None,
        vec![("T", Object::Matrix(t)), ("J", Object::Matrix(j))],
        Some(ok),
    );
    Ok(rec.finish())
}

/// The primary block of an irreducible factor `f` of degree $d \ge 2$ and multiplicity `e`
/// over $\mathbb{Q}(p)$: $\dim\ker f(A)^k$, the block sizes of each root, a basis $B$ of
/// $\ker f(A)^e$ and $M$ with $A B = B M$.
fn primary_block_steps(
    rec: &mut Recorder<'_, RatFuncField>,
    part: usize,
    a: &Matrix<RatFuncField>,
    f: &Poly<RatFuncField>,
    e: usize,
) -> Result<(Matrix<RatFuncField>, Matrix<RatFuncField>)> {
    let n = a.nrows();
    let d = f.deg();
    let fa = a.eval_poly(f)?;
    let (mut dims, mut pw) = (vec![], fa.clone());
    loop {
        dims.push(n - pw.rank());
        if *dims.last().expect("one") >= d * e || dims.len() >= e {
            break;
        }
        pw = pw.try_mul(&fa)?;
    }
    let per_root: Vec<usize> = dims.iter().map(|x| x / d).collect();
    let (_, segre) = weyr_segre(&per_root);
    let basis = pw.nullspace();
    let (_, rows) = basis.transpose().rref();
    let ab = a.try_mul(&basis)?;
    let mm = basis
        .select_rows(&rows)
        .inverse()?
        .try_mul(&ab.select_rows(&rows))?;
    let ok = basis.ncols() == d * e && ab == basis.try_mul(&mm)?;
    rec.push(
        StepKind::PrimaryBlock,
        Some(part),
        vec![
            ("f", Object::Poly(f.clone())),
            ("dims", Object::Counts(dims)),
            ("segre", Object::Counts(segre)),
            ("B", Object::Matrix(basis.clone())),
            ("M", Object::Matrix(mm.clone())),
        ],
        Some(ok),
    );
    Ok((basis, mm))
}
