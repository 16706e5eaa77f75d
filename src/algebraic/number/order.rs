//! Exact equality and order of [`AlgebraicNumber`]s: regions refined until nested or
//! disjoint (a region holds exactly one root, so inclusion proves the same root and
//! disjointness a different one).

use super::{AlgebraicNumber, Loc, pow2};
use crate::algebraic::isolate_complex::CBox;
use std::cmp::Ordering;

/// Same root of the same minimal polynomial (regions refined until nested or disjoint).
fn same_root(a: &AlgebraicNumber, b: &AlgebraicNumber) -> bool {
    match (&a.loc, &b.loc) {
        (Loc::Exact(x), Loc::Exact(y)) => x == y,
        (Loc::Real(_), Loc::Real(_)) | (Loc::Complex { .. }, Loc::Complex { .. }) => {
            let mut a = a.clone();
            for _ in 0..100_000 {
                let (ar, ai) = a.bounding_box();
                let (br, bi) = b.bounding_box();
                let aa = CBox { re: ar, im: ai };
                let bb = CBox { re: br, im: bi };
                if !aa.intersects(&bb) {
                    return false;
                }
                if bb.contains_box(&aa) {
                    return true;
                }
                a = a.step();
            }
            false
        }
        _ => false,
    }
}

impl PartialEq for AlgebraicNumber {
    fn eq(&self, o: &Self) -> bool {
        self.minpoly == o.minpoly && same_root(self, o)
    }
}
impl Eq for AlgebraicNumber {}

/// Exact order of two real algebraic numbers.
fn cmp_real(a: &AlgebraicNumber, b: &AlgebraicNumber) -> Ordering {
    if a == b {
        return Ordering::Equal;
    }
    let (mut a, mut b) = (a.clone(), b.clone());
    loop {
        let (al, ah) = a.interval().unwrap_or_default();
        let (bl, bh) = b.interval().unwrap_or_default();
        if ah < bl {
            return Ordering::Less;
        }
        if bh < al {
            return Ordering::Greater;
        }
        if a.width() >= b.width() {
            a = a.step();
        } else {
            b = b.step();
        }
    }
}

impl PartialOrd for AlgebraicNumber {
    /// Exact order for two reals; `None` when either is non-real (and they differ).
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        if self.is_real() && o.is_real() {
            Some(cmp_real(self, o))
        } else if self == o {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

/// Order of two real parts, exact: boxes separated, or exact real parts compared.
fn cmp_re_part(a: &AlgebraicNumber, b: &AlgebraicNumber) -> Ordering {
    if a.is_pure_imaginary() && b.is_pure_imaginary() {
        return Ordering::Equal;
    }
    // conjugates share their real part
    if a.minpoly == b.minpoly && same_root(&a.conj(), b) {
        return Ordering::Equal;
    }
    let (mut a2, mut b2) = (a.clone(), b.clone());
    let (wa, wb) = (a.width(), b.width());
    for j in 1..=8 {
        let ((al, ah), _) = a2.bounding_box();
        let ((bl, bh), _) = b2.bounding_box();
        if ah < bl {
            return Ordering::Less;
        }
        if bh < al {
            return Ordering::Greater;
        }
        a2 = a2.refined(&(&wa * pow2(-16 * j))).unwrap_or(a2);
        b2 = b2.refined(&(&wb * pow2(-16 * j))).unwrap_or(b2);
    }
    // possibly equal: compare the exact real parts
    match (a.try_re(), b.try_re()) {
        (Ok(x), Ok(y)) => cmp_real(&x, &y),
        _ => Ordering::Equal,
    }
}

/// Sort key order for non-real numbers: (real part, imaginary part), reals first.
pub(crate) fn cmp_complex(a: &AlgebraicNumber, b: &AlgebraicNumber) -> Ordering {
    match (a.is_real(), b.is_real()) {
        (true, true) => return cmp_real(a, b),
        (true, false) => return Ordering::Less,
        (false, true) => return Ordering::Greater,
        _ => {}
    }
    if a == b {
        return Ordering::Equal;
    }
    let c = cmp_re_part(a, b);
    if c != Ordering::Equal {
        return c;
    }
    // equal real parts, different numbers: imaginary parts differ
    let (mut a2, mut b2) = (a.clone(), b.clone());
    loop {
        let (_, (al, ah)) = a2.bounding_box();
        let (_, (bl, bh)) = b2.bounding_box();
        if ah < bl {
            return Ordering::Less;
        }
        if bh < al {
            return Ordering::Greater;
        }
        a2 = a2.step();
        b2 = b2.step();
    }
}
