//! A one-parameter family of systems: the state matrix $A(v)$ with entries in
//! $\mathbb{Q}(v)$, read from a system file with one parameter left symbolic.
//!
//! First-order files give $A(v)$ (and $E(v)$: $A \leftarrow E^{-1} A$); second-order files
//! $M q'' + L q' + K q = F u$ give
//! $$A(v) = \begin{bmatrix} 0 & I \\ -M^{-1}K & -M^{-1}L \end{bmatrix}.$$
//! The characteristic polynomial is that of the pencil: $\det(x E - A)$, resp.
//! $\det(x^2 M + x L + K)$, up to a factor in $\mathbb{Q}(v)$ without $x$.
//!
//! | entry point | does |
//! |---|---|
//! | [`ParamFamily::from_file`] | reads a system file, `param` symbolic, other parameters exact |
//! | [`ParamFamily::second_order`], [`ParamFamily::first_order`] | builds from matrices |
//! | [`ParamFamily::state_matrix_in`] | $A(v_0)$ over any field holding $v_0$ |
//! | [`ParamFamily::state_matrix_f64`] | $A(v)$ in floating point (sweeps) |

use super::family_read::{RatFuncReader, read_file_matrices};
use super::finite::{finite_part, linearize_second_order};
use super::qv::{coeffs_f64, den_q, eval_in, upoly};
use crate::algebraic::NumberField;
use crate::error::{Error, Result};
use crate::field::{Field, Q, Rational};
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::ratfunc::kernels::clear_rows;
use crate::ratfunc::{RatFunc, RatFuncField};
use nalgebra::DMatrix;
use std::path::Path;

/// A square matrix over $\mathbb{Q}(v)$ (the tower's [`RatFuncField`], one symbol).
pub type RatMatrix = Matrix<RatFuncField>;

/// The matrices that define $A(v)$.
#[derive(Clone, Debug, PartialEq)]
pub enum FamilyForm {
    /// $E x' = A x$ (`e = None`: the identity).
    First { a: RatMatrix, e: Option<RatMatrix> },
    /// $M q'' + L q' + K q = 0$.
    Second {
        m: RatMatrix,
        l: RatMatrix,
        k: RatMatrix,
    },
}

/// A system whose state matrix depends on one parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct ParamFamily {
    /// The system's `name`, for titles.
    pub name: Option<String>,
    /// The parameter's name (`v` in `--param v`).
    pub param: String,
    /// Its value in the file, when it has one.
    pub nominal: Option<Rational>,
    pub form: FamilyForm,
}

fn zeros(k: &RatFuncField, n: usize) -> RatMatrix {
    Matrix::zeros(k.clone(), n, n)
}

impl ParamFamily {
    /// The second-order family $M(v) q'' + L(v) q' + K(v) q = 0$.
    ///
    /// # Errors
    /// `Shape` unless `m`, `l`, `k` are square of one size.
    pub fn second_order(
        param: &str,
        m: RatMatrix,
        l: RatMatrix,
        k: RatMatrix,
    ) -> Result<ParamFamily> {
        let n = m.nrows();
        for x in [&m, &l, &k] {
            check_square(x, n)?;
        }
        Ok(ParamFamily {
            name: None,
            param: param.into(),
            nominal: None,
            form: FamilyForm::Second { m, l, k },
        })
    }

    /// The first-order family $E(v) x' = A(v) x$.
    ///
    /// # Errors
    /// `Shape` unless `a` (and `e`) are square of one size.
    pub fn first_order(param: &str, a: RatMatrix, e: Option<RatMatrix>) -> Result<ParamFamily> {
        let n = a.nrows();
        check_square(&a, n)?;
        if let Some(e) = &e {
            check_square(e, n)?;
        }
        Ok(ParamFamily {
            name: None,
            param: param.into(),
            nominal: None,
            form: FamilyForm::First { a, e },
        })
    }

    /// Number of states $n$.
    pub fn nstates(&self) -> usize {
        match &self.form {
            FamilyForm::First { a, .. } => a.nrows(),
            FamilyForm::Second { m, .. } => 2 * m.nrows(),
        }
    }

    /// The pencil $\sum_j x^j P_j(v)$ whose determinant is the characteristic polynomial up
    /// to a factor free of $x$: `[-A, E]` or `[K, L, M]`.
    pub fn pencil(&self) -> Vec<RatMatrix> {
        match &self.form {
            FamilyForm::First { a, e } => {
                let k = a.field();
                let neg = a.scale(&k.from_i64(-1));
                let e = e
                    .clone()
                    .unwrap_or_else(|| Matrix::identity(k.clone(), a.nrows()));
                vec![neg, e]
            }
            FamilyForm::Second { m, l, k } => vec![k.clone(), l.clone(), m.clone()],
        }
    }

    /// The pencil's rows, each multiplied by the lcm of its denominators over all $P_j$
    /// (the tower's [`clear_rows`]): `rows[i][j][c]` is $d_i$ times entry $(i, c)$ of
    /// $P_j$, in $\mathbb{Q}[v]$.
    pub fn poly_rows(&self) -> Vec<Vec<Vec<Poly<Q>>>> {
        let pencil = self.pencil();
        let (n, nj) = (pencil[0].nrows(), pencil.len());
        let wide: Vec<RatFunc> = (0..n)
            .flat_map(|i| pencil.iter().flat_map(move |p| p.row(i).to_vec()))
            .collect();
        let (b, _) = clear_rows(1, n, nj * n, &wide);
        (0..n)
            .map(|i| {
                (0..nj)
                    .map(|j| (0..n).map(|c| upoly(&b[(i * nj + j) * n + c])).collect())
                    .collect()
            })
            .collect()
    }

    /// Every denominator of every entry (the family is undefined at their roots).
    pub fn denominators(&self) -> Vec<Poly<Q>> {
        let mut out = vec![];
        for p in self.pencil() {
            for x in p.as_slice() {
                if !x.den().is_one() {
                    let d = den_q(x);
                    if !out.contains(&d) {
                        out.push(d);
                    }
                }
            }
        }
        out
    }

    /// $A(v_0)$ over the field `k`, where `v0` is an element of `k`: $E(v_0)^{-1} A(v_0)$
    /// (resp. the companion form of $M, L, K$), or where $E(v_0)$ (resp. $M(v_0)$) is
    /// singular the finite part $A_f$ of the pencil ([`finite_part`]), whose order is the
    /// number of finite eigenvalues $\deg \det(xE - A)$.
    ///
    /// # Errors
    /// `DivisionByZero` at a pole of an entry; `Singular` where the pencil is singular
    /// ($\det(xE(v_0) - A(v_0)) = 0$ for every $x$).
    pub fn state_matrix_in<K: Field>(&self, k: &K, v0: &K::Elem) -> Result<Matrix<K>> {
        let ev = |m: &RatMatrix| -> Result<Matrix<K>> {
            let data = m
                .as_slice()
                .iter()
                .map(|f| eval_in(k, f, v0))
                .collect::<Result<Vec<_>>>()?;
            Ok(Matrix::from_vec(k.clone(), m.nrows(), m.ncols(), data))
        };
        match &self.form {
            FamilyForm::First { a, e } => state_first(ev(a)?, e.as_ref().map(ev).transpose()?),
            FamilyForm::Second { m, l, k: kk } => state_second(ev(m)?, ev(l)?, ev(kk)?),
        }
    }

    /// $A(v_0)$ over $\mathbb{Q}$ for a rational `v0`.
    ///
    /// # Errors
    /// As [`Self::state_matrix_in`].
    pub fn state_matrix_q(&self, v0: &Rational) -> Result<Matrix<Q>> {
        self.state_matrix_in(&Q, v0)
    }

    /// $A(v_0)$ over $\mathbb{Q}(v_0) = \mathbb{Q}[t]/(f)$, `v0` the field's generator.
    ///
    /// # Errors
    /// As [`Self::state_matrix_in`].
    pub fn state_matrix_nf(&self, k: &NumberField) -> Result<Matrix<NumberField>> {
        self.state_matrix_in(k, &k.generator())
    }

    /// $A(v)$ in floating point.
    ///
    /// # Errors
    /// `Singular` where $E(v)$ or $M(v)$ is numerically singular.
    pub fn state_matrix_f64(&self, v: f64) -> Result<DMatrix<f64>> {
        let ev = |m: &RatMatrix| {
            let h = |c: &[f64]| c.iter().rev().fold(0.0, |acc, x| acc * v + x);
            let n = m.nrows();
            DMatrix::from_fn(n, n, |i, j| {
                let f = m.get(i, j);
                h(&coeffs_f64(f.num())) / h(&coeffs_f64(f.den()))
            })
        };
        match &self.form {
            FamilyForm::First { a, e } => {
                let a = ev(a);
                match e {
                    None => Ok(a),
                    Some(e) => ev(e).lu().solve(&a).ok_or(Error::Singular),
                }
            }
            FamilyForm::Second { m, l, k } => second_order_state_matrix(&ev(m), &ev(l), &ev(k)),
        }
    }

    /// Reads the system file at `path` with parameter `param` symbolic. Other parameters
    /// take their exact values (expressions over each other and over `param` allowed).
    ///
    /// # Errors
    /// `Invalid` naming the file and key for unreadable or malformed files, unknown names,
    /// cycles; `Unsupported` for `sqrt`/`i` entries or a transfer-matrix file.
    pub fn from_file(path: &Path, param: &str) -> Result<ParamFamily> {
        Self::from_file_at(path, param, &[])
    }

    /// [`ParamFamily::from_file`] with values for other parameters first (`--at`: they
    /// override the file's; exact text, decimals are exact).
    ///
    /// # Errors
    /// As [`ParamFamily::from_file`]; a value for `param` itself (it is swept), or for a
    /// name that is not a parameter of the file.
    pub fn from_file_at(path: &Path, param: &str, at: &[(String, String)]) -> Result<ParamFamily> {
        if !crate::io::expr::is_parameter_name(param) {
            return Err(Error::Invalid(format!("'{param}' cannot name a parameter")));
        }
        let k = super::qv::field(param)?;
        let m = read_file_matrices(&RatFuncReader { k: k.clone() }, path, param, at)?;
        let nominal = match m.nominal {
            None => None,
            Some(f) if f.to_rational().is_some() => f.to_rational(),
            Some(_) => {
                return Err(Error::Invalid(format!(
                    "{}: key parameters.{param}: the swept parameter needs a number",
                    m.file
                )));
            }
        };
        let mat = |rows: Vec<Vec<RatFunc>>| -> Result<RatMatrix> {
            let n = rows.len();
            if rows.iter().any(|r| r.len() != n) {
                return Err(Error::Shape {
                    op: "parameter family",
                    expected: (n, n),
                    found: (n, rows.first().map_or(0, Vec::len)),
                });
            }
            Ok(Matrix::from_vec(k.clone(), n, n, rows.concat()))
        };
        let form = if let Some(mm) = m.m {
            let mm = mat(mm)?;
            let n = mm.nrows();
            let l = m.l.map(mat).transpose()?.unwrap_or_else(|| zeros(&k, n));
            let kk = m.k.map(mat).transpose()?.unwrap_or_else(|| zeros(&k, n));
            ParamFamily::second_order(param, mm, l, kk)?.form
        } else if let Some(a) = m.a {
            ParamFamily::first_order(param, mat(a)?, m.e.map(mat).transpose()?)?.form
        } else {
            return Err(Error::Invalid(format!(
                "{}: no system: give A (first-order form) or M (second-order form)",
                m.file
            )));
        };
        Ok(ParamFamily {
            name: m.name,
            param: param.into(),
            nominal,
            form,
        })
    }
}

/// $A = E^{-1} A$ of the evaluated first-order form (`e = None`: the identity), or where
/// $E$ is singular the finite part of the pencil ([`finite_part`]).
///
/// # Errors
/// `Singular` for a singular pencil; shape errors.
pub fn state_first<K: Field>(a: Matrix<K>, e: Option<Matrix<K>>) -> Result<Matrix<K>> {
    match e {
        None => Ok(a),
        Some(e) => match e.inverse() {
            Ok(ei) => ei.try_mul(&a),
            Err(Error::Singular) => finite_part(e, a),
            Err(err) => Err(err),
        },
    }
}

/// The companion form of the evaluated $M q'' + L q' + K q$, or where $M$ is singular the
/// finite part of its linearization.
///
/// # Errors
/// `Singular` for a singular pencil; shape errors.
pub fn state_second<K: Field>(mm: Matrix<K>, l: Matrix<K>, kk: Matrix<K>) -> Result<Matrix<K>> {
    let k = mm.field().clone();
    let n = mm.nrows();
    let minv = match mm.inverse() {
        Ok(x) => x,
        Err(Error::Singular) => {
            let (e, a) = linearize_second_order(&mm, &l, &kk);
            return finite_part(e, a);
        }
        Err(err) => return Err(err),
    };
    let mk = minv.try_mul(&kk)?.scale(&k.neg(&k.one()));
    let ml = minv.try_mul(&l)?.scale(&k.neg(&k.one()));
    let mut a = Matrix::zeros(k.clone(), 2 * n, 2 * n);
    a.set_block(0, n, &Matrix::identity(k.clone(), n));
    a.set_block(n, 0, &mk);
    a.set_block(n, n, &ml);
    Ok(a)
}

fn check_square(m: &RatMatrix, n: usize) -> Result<()> {
    if m.shape() != (n, n) {
        return Err(Error::Shape {
            op: "parameter family",
            expected: (n, n),
            found: m.shape(),
        });
    }
    Ok(())
}

/// $A = \begin{pmatrix} 0 & I \\ -M^{-1}K & -M^{-1}L \end{pmatrix}$ of $M\ddot q + L\dot q + K q$
/// in floating point.
///
/// # Errors
/// `Singular` when the LU factorization of $M$ cannot solve.
pub(crate) fn second_order_state_matrix(
    m: &DMatrix<f64>,
    l: &DMatrix<f64>,
    k: &DMatrix<f64>,
) -> Result<DMatrix<f64>> {
    let n = m.nrows();
    let lu = m.clone().lu();
    let mk = lu.solve(k).ok_or(Error::Singular)?;
    let ml = lu.solve(l).ok_or(Error::Singular)?;
    let mut a = DMatrix::zeros(2 * n, 2 * n);
    for i in 0..n {
        a[(i, n + i)] = 1.0;
        for j in 0..n {
            a[(n + i, j)] = -mk[(i, j)];
            a[(n + i, n + j)] = -ml[(i, j)];
        }
    }
    Ok(a)
}
