//! The open intervals between consecutive critical values, and the excluded points: one
//! code path for every coefficient field. At a rational sample point of each interval the
//! field's counter gives the eigenvalue counts, Routh–Hurwitz stability and whether the two
//! agree (over $\mathbb{Q}$ from $P(x, s)$ by certified root isolation; over $K$ see
//! [`super::over_k`]); a degenerate sample (a Hurwitz minor vanishes) is moved towards the
//! right end of the interval.

use super::roots::rational_between;
use super::{CriticalValue, SingularReason, StudyInterval};
use crate::algebraic::AlgebraicNumber;
use crate::error::{Error, Result};
use crate::field::Rational;
use crate::study::hurwitz::RootCounts;
use std::cmp::Ordering;

/// What a sample gives: counts, Routh–Hurwitz stability, consistency; `None` when the
/// sample is degenerate.
pub(super) type Counts = Option<(RootCounts, bool, bool)>;

/// The intervals of $[a, b]$ cut at the critical and singular values, counted by `count`
/// at a rational sample; `verified` is cleared when a sample's counts disagree with
/// Routh–Hurwitz.
///
/// # Errors
/// `Limit` when no sample with nonzero Hurwitz minors is found; errors of `count`.
pub(super) fn intervals_between(
    a: &Rational,
    b: &Rational,
    critical: &[CriticalValue],
    singular: &[AlgebraicNumber],
    verified: &mut bool,
    count: &dyn Fn(&Rational) -> Result<Counts>,
) -> Result<Vec<StudyInterval>> {
    let mut pts: Vec<AlgebraicNumber> = vec![AlgebraicNumber::from_rational(a)];
    let mut inner: Vec<AlgebraicNumber> = critical
        .iter()
        .map(|c| c.value.clone())
        .chain(singular.iter().cloned())
        .collect();
    inner.sort_by(|x, y| x.partial_cmp(y).unwrap_or(Ordering::Equal));
    inner.push(AlgebraicNumber::from_rational(b));
    for x in inner {
        if pts.last() != Some(&x) {
            pts.push(x);
        }
    }
    let mut out = vec![];
    for w in pts.windows(2) {
        let mut s = rational_between(&w[0], &w[1])?;
        let mut found = None;
        for _ in 0..16 {
            if let Some(c) = count(&s)? {
                found = Some(c);
                break;
            }
            s = rational_between(&AlgebraicNumber::from_rational(&s), &w[1])?;
        }
        let Some((counts, stable, consistent)) = found else {
            return Err(Error::Limit(
                "no sample point with nonzero Hurwitz minors between two critical values".into(),
            ));
        };
        *verified &= consistent && stable == counts.is_stable();
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

/// The excluded points with their first reason, ascending and without repeats.
pub(super) fn singular_sorted(
    found: Vec<(AlgebraicNumber, SingularReason)>,
) -> (Vec<AlgebraicNumber>, Vec<SingularReason>) {
    let mut out: Vec<(AlgebraicNumber, SingularReason)> = vec![];
    for (r, why) in found {
        if !out.iter().any(|(x, _)| *x == r) {
            out.push((r, why));
        }
    }
    out.sort_by(|x, y| x.0.partial_cmp(&y.0).unwrap_or(Ordering::Equal));
    out.into_iter().unzip()
}
