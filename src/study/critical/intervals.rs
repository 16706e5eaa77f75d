//! The open intervals between consecutive critical values: root counts at a rational
//! sample point, cross-checked with Routh–Hurwitz.

use super::roots::rational_between;
use super::{CriticalValue, StudyInterval};
use crate::algebraic::AlgebraicNumber;
use crate::error::Result;
use crate::field::Rational;
use crate::study::bivar::BiPoly;
use crate::study::hurwitz::{hurwitz_stable, root_counts};
use std::cmp::Ordering;

/// The intervals of $[a, b]$ cut at the critical and singular values; `verified` is
/// cleared when a sample's counts disagree with Routh–Hurwitz.
pub(super) fn intervals_between(
    p: &BiPoly,
    a: &Rational,
    b: &Rational,
    critical: &[CriticalValue],
    singular: &[AlgebraicNumber],
    verified: &mut bool,
) -> Result<Vec<StudyInterval>> {
    let mut pts: Vec<AlgebraicNumber> = vec![AlgebraicNumber::from_rational(a)];
    let mut inner: Vec<AlgebraicNumber> = critical
        .iter()
        .map(|c| c.value.clone())
        .chain(singular.iter().cloned())
        .collect();
    inner.sort_by(|x, y| x.partial_cmp(y).unwrap_or(Ordering::Equal));
    for x in inner {
        if pts.last() != Some(&x) {
            pts.push(x);
        }
    }
    let last = AlgebraicNumber::from_rational(b);
    if pts.last() != Some(&last) {
        pts.push(last);
    }
    let mut out = vec![];
    for w in pts.windows(2) {
        let s = rational_between(&w[0], &w[1])?;
        let ps = p.at(&s);
        let counts = root_counts(&ps)?;
        let stable = hurwitz_stable(&ps)?;
        *verified &= stable == counts.is_stable();
        out.push(StudyInterval {
            from: w[0].clone(),
            to: w[1].clone(),
            sample: s,
            counts,
            stable,
        });
    }
    Ok(out)
}
