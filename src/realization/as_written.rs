//! The realization of a transfer matrix AS WRITTEN: nothing cancelled between a numerator and
//! its denominator (MATLAB's and python-control's `ss(tf(...))` before any `minreal`).
//!
//! Entry $(i, j)$ is the pair $n_{ij}/d_{ij}$ as the user wrote it (not in lowest terms),
//! proper. Per input column $j$ the common denominator is $d_j = \mathrm{lcm}_i\, d_{ij}$
//! (monic; each root with the largest multiplicity it has in one entry of the column: the
//! denominators python-control's `TransferFunction.poles()` takes, and slycot's `td04ad('C')`
//! realizes before its minimal step). With $D_{ij}$ the value at infinity and
//! $r_{ij} = n_{ij} - D_{ij}\,d_{ij}$, column $j$ is the strictly proper
//! $N_j(s)/d_j(s)$, $N_{ij} = r_{ij}\, d_j / d_{ij}$, realized in controllable companion form:
//! $A_j$ the companion matrix of $d_j$ (last row $-d_{j,0}, \dots, -d_{j,k-1}$),
//! $b_j = e_k$, row $i$ of $C_j$ the coefficients of $N_{ij}$; $A = \mathrm{diag}(A_j)$,
//! $B = \mathrm{diag}(b_j)$, $C = [C_1 \cdots C_m]$.
//!
//! Identities: $\det(sI - A) = \prod_j d_j$ (the poles are the written denominators' roots
//! with multiplicity) and $C(sI - A)^{-1}B + D = G$, i.e. the Markov parameters equal those
//! of $G$ in lowest terms, hence those of its minimal realization. `verified` checks both
//! exactly.

use crate::error::{Error, Result};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::poly::Poly;
use crate::system::StateSpace;
use crate::system::transfer::{RationalFunction, TransferMatrix};

/// How a transfer matrix given as text becomes a state-space system.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Realize {
    /// The exact minimal realization (order = McMillan degree): what `minreal` returns.
    #[default]
    Minimal,
    /// Every written denominator kept ([`realize_as_written`]).
    AsWritten,
}

impl Realize {
    /// `"minimal"` or `"as_written"` (the file key `realize`, Python's `tf(realize=...)`).
    pub fn parse(text: &str) -> Option<Self> {
        match text {
            "minimal" => Some(Self::Minimal),
            "as_written" => Some(Self::AsWritten),
            _ => None,
        }
    }
    pub fn name(self) -> &'static str {
        match self {
            Self::Minimal => "minimal",
            Self::AsWritten => "as_written",
        }
    }
}

/// A transfer matrix as written: entry $(i, j)$ is `(num, den)`, not reduced.
#[derive(Clone, Debug, PartialEq)]
pub struct WrittenTransfer<K: Field> {
    pub entries: Vec<Vec<(Poly<K>, Poly<K>)>>,
}

impl<K: Field> WrittenTransfer<K> {
    /// The same matrix in lowest terms.
    pub fn reduced(&self) -> TransferMatrix<K> {
        TransferMatrix {
            entries: self
                .entries
                .iter()
                .map(|r| {
                    r.iter()
                        .map(|(n, d)| RationalFunction::new(n.clone(), d.clone()))
                        .collect()
                })
                .collect(),
        }
    }
}

/// The realization of a transfer matrix as written.
#[derive(Clone, Debug)]
pub struct WrittenRealization<K: Field> {
    pub system: StateSpace<K>,
    /// $d_j$ per input column, monic; $\det(sI - A) = \prod_j d_j$.
    pub column_denominators: Vec<Poly<K>>,
    /// $\det(sI - A) = \prod_j d_j$ and the Markov parameters equal those of $G$, exactly.
    pub verified: bool,
}

/// The realization of `g` keeping every written denominator (module docs).
///
/// # Errors
/// `Invalid` for an empty or ragged matrix, a zero denominator, or an improper entry (no
/// state-space realization).
pub fn realize_as_written<K: Field>(g: &WrittenTransfer<K>) -> Result<WrittenRealization<K>> {
    let p = g.entries.len();
    let m = g.entries.first().map_or(0, |r| r.len());
    if p == 0 || m == 0 || g.entries.iter().any(|r| r.len() != m) {
        return Err(Error::Invalid(
            "a transfer matrix needs non-empty rows of equal length".into(),
        ));
    }
    let fld = g.entries[0][0].1.field().clone();
    for (i, row) in g.entries.iter().enumerate() {
        for (j, (n, d)) in row.iter().enumerate() {
            if d.is_zero() {
                return Err(Error::Invalid(format!(
                    "entry ({}, {}): zero denominator",
                    i + 1,
                    j + 1
                )));
            }
            if !n.is_zero() && n.deg() > d.deg() {
                return Err(Error::Invalid(format!(
                    "entry ({}, {}) is improper (numerator degree {} > denominator degree {}): \
                     it has no state-space realization",
                    i + 1,
                    j + 1,
                    n.deg(),
                    d.deg()
                )));
            }
        }
    }
    let mut dmat = Matrix::zeros(fld.clone(), p, m);
    let mut cols = Vec::with_capacity(m);
    for j in 0..m {
        let dj = g
            .entries
            .iter()
            .fold(Poly::one(fld.clone()), |acc, row| lcm(&acc, &row[j].1));
        let mut nums = Vec::with_capacity(p);
        for (i, row) in g.entries.iter().enumerate() {
            let (n, d) = &row[j];
            let dinf = if !n.is_zero() && n.deg() == d.deg() {
                fld.div(&n.lc(), &d.lc())
                    .expect("non-zero leading coefficient")
            } else {
                fld.zero()
            };
            dmat.set(i, j, dinf.clone());
            let r = n.sub(&d.scale(&dinf));
            let cof = dj.div_exact(d).expect("lcm is a multiple");
            nums.push(r.mul(&cof));
        }
        cols.push((dj, nums));
    }
    let system = assemble(&fld, &cols, dmat)?;
    let column_denominators: Vec<Poly<K>> = cols.into_iter().map(|(d, _)| d).collect();
    let det = column_denominators
        .iter()
        .fold(Poly::one(fld.clone()), |acc, d| acc.mul(d));
    let verified = system.a.charpoly()? == det && g.reduced().matches_markov(&system);
    Ok(WrittenRealization {
        system,
        column_denominators,
        verified,
    })
}

/// Monic least common multiple.
fn lcm<K: Field>(a: &Poly<K>, b: &Poly<K>) -> Poly<K> {
    let g = a.gcd(b);
    a.mul(&b.div_exact(&g).expect("gcd divides")).monic()
}

/// `diag(A_j)`, `diag(b_j)`, `[C_1 .. C_m]` of the column companion blocks.
fn assemble<K: Field>(
    fld: &K,
    cols: &[(Poly<K>, Vec<Poly<K>>)],
    d: Matrix<K>,
) -> Result<StateSpace<K>> {
    let (p, m) = d.shape();
    let n: usize = cols.iter().map(|(dj, _)| dj.deg()).sum();
    let mut a = Matrix::zeros(fld.clone(), n, n);
    let mut b = Matrix::zeros(fld.clone(), n, m);
    let mut c = Matrix::zeros(fld.clone(), p, n);
    let mut off = 0;
    for (j, (dj, nums)) in cols.iter().enumerate() {
        let k = dj.deg();
        if k == 0 {
            continue;
        }
        for t in 0..k {
            if t + 1 < k {
                a.set(off + t, off + t + 1, fld.one());
            }
            a.set(off + k - 1, off + t, fld.neg(&dj.coeff(t)));
        }
        b.set(off + k - 1, j, fld.one());
        for (i, nij) in nums.iter().enumerate() {
            for t in 0..k {
                c.set(i, off + t, nij.coeff(t));
            }
        }
        off += k;
    }
    StateSpace::new(a, b, c, d)
}
