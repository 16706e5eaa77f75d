//! Exact 3-vectors and the small matrices of a linear multibody model: the skew matrix
//! $[r]_\times$ ($[r]_\times \theta = r \times \theta$), the projections $d d^T / (d \cdot d)$
//! and $I - d d^T / (d \cdot d)$ (rational for every rational $d$), and the point Jacobian
//! $[I, -[r]_\times; 0, I]$ that maps a body's motion (translation of its centre of mass,
//! small rotation) to the motion of a point at radius $r$ from it.

use crate::field::Field;
use crate::matrix::Matrix;

/// A point or vector in space, entries in the model's field.
pub type Vec3<K> = [<K as Field>::Elem; 3];

/// `a - b`.
pub fn sub3<K: Field>(k: &K, a: &Vec3<K>, b: &Vec3<K>) -> Vec3<K> {
    [
        k.sub(&a[0], &b[0]),
        k.sub(&a[1], &b[1]),
        k.sub(&a[2], &b[2]),
    ]
}

/// `a . b`.
pub fn dot3<K: Field>(k: &K, a: &Vec3<K>, b: &Vec3<K>) -> K::Elem {
    let mut s = k.mul(&a[0], &b[0]);
    k.mul_add_assign(&mut s, &a[1], &b[1]);
    k.mul_add_assign(&mut s, &a[2], &b[2]);
    s
}

/// `c a`.
pub fn scale3<K: Field>(k: &K, c: &K::Elem, a: &Vec3<K>) -> Vec3<K> {
    [k.mul(c, &a[0]), k.mul(c, &a[1]), k.mul(c, &a[2])]
}

/// Is every entry zero?
pub fn is_zero3<K: Field>(k: &K, a: &Vec3<K>) -> bool {
    a.iter().all(|x| k.is_zero(x))
}

/// The zero vector.
pub fn zero3<K: Field>(k: &K) -> Vec3<K> {
    [k.zero(), k.zero(), k.zero()]
}

/// $[v]_\times$: the matrix with $[v]_\times w = v \times w$.
pub fn skew<K: Field>(k: &K, v: &Vec3<K>) -> Matrix<K> {
    let z = k.zero();
    Matrix::from_vec(
        k.clone(),
        3,
        3,
        vec![
            z.clone(),
            k.neg(&v[2]),
            v[1].clone(),
            v[2].clone(),
            z.clone(),
            k.neg(&v[0]),
            k.neg(&v[1]),
            v[0].clone(),
            z,
        ],
    )
}

/// $d d^T / (d \cdot d)$; `None` when `d` is zero.
pub fn along<K: Field>(k: &K, d: &Vec3<K>) -> Option<Matrix<K>> {
    let inv = k.inv(&dot3(k, d, d))?;
    Some(Matrix::from_fn(k.clone(), 3, 3, |i, j| {
        k.mul(&k.mul(&d[i], &d[j]), &inv)
    }))
}

/// The projection onto the directions a connection carries: 3 -> $I$, 2 -> the plane
/// normal to `axis` ($I - d d^T/(d \cdot d)$), 1 -> `axis` ($d d^T/(d \cdot d)$), 0 -> 0.
/// `None` when 1 or 2 directions are asked and the axis is zero.
pub fn carried<K: Field>(k: &K, n: u8, axis: &Vec3<K>) -> Option<Matrix<K>> {
    match n {
        0 => Some(Matrix::zeros(k.clone(), 3, 3)),
        1 => along(k, axis),
        2 => Some(&Matrix::identity(k.clone(), 3) - &along(k, axis)?),
        _ => Some(Matrix::identity(k.clone(), 3)),
    }
}

/// Independent rows spanning the directions a connection carries (`n x 3`): the rows of
/// [`carried`] at the pivots of its RREF (the projection is symmetric, so these rows are
/// independent and span its row space). A constraint writes one equation per direction,
/// so its Jacobian has no dependent rows of its own; the force it carries is
/// $P_{sel}^T \lambda$.
pub fn carried_rows<K: Field>(k: &K, n: u8, axis: &Vec3<K>) -> Option<Matrix<K>> {
    let p = carried(k, n, axis)?;
    let (_, piv) = p.rref();
    Some(p.select_rows(&piv))
}

/// `m[r0.., c0..] += s * b` for `s = +1` (`neg = false`) or `-1`.
pub fn add_block<K: Field>(m: &mut Matrix<K>, r0: usize, c0: usize, b: &Matrix<K>, neg: bool) {
    let k = m.field().clone();
    for i in 0..b.nrows() {
        for j in 0..b.ncols() {
            let x = b.get(i, j);
            if k.is_zero(x) {
                continue;
            }
            let cur = m.get(r0 + i, c0 + j);
            let v = if neg { k.sub(cur, x) } else { k.add(cur, x) };
            m.set(r0 + i, c0 + j, v);
        }
    }
}

/// `[I, -[r]x; 0, I]`: body motion (centre of mass translation, rotation) to the motion
/// (translation, rotation) of the point at radius `r`.
pub fn point_map<K: Field>(k: &K, r: &Vec3<K>) -> Matrix<K> {
    let mut t = Matrix::identity(k.clone(), 6);
    add_block(&mut t, 0, 3, &skew(k, r), true);
    t
}

/// `a b`, skipping the zero entries of both factors.
pub fn sparse_mul<K: Field>(a: &Matrix<K>, b: &Matrix<K>) -> Matrix<K> {
    let k = a.field().clone();
    let nz: Vec<Vec<(usize, K::Elem)>> = (0..b.nrows())
        .map(|i| {
            b.row(i)
                .iter()
                .enumerate()
                .filter(|(_, x)| !k.is_zero(x))
                .map(|(j, x)| (j, x.clone()))
                .collect()
        })
        .collect();
    let mut out = vec![k.zero(); a.nrows() * b.ncols()];
    for i in 0..a.nrows() {
        let orow = &mut out[i * b.ncols()..(i + 1) * b.ncols()];
        for (l, x) in a.row(i).iter().enumerate() {
            if k.is_zero(x) {
                continue;
            }
            for (j, y) in &nz[l] {
                k.mul_add_assign(&mut orow[*j], x, y);
            }
        }
    }
    Matrix::from_vec(k, a.nrows(), b.ncols(), out)
}
