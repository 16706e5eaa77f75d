//! The display order of the terms of an [`MPoly`] (total degree, largest first, then lex:
//! univariate polynomials list as [`crate::poly::zpoly::ZPoly`] does) and the sign
//! normalization it implies; the text and LaTeX themselves are made in
//! `report::display::mpoly`.

use super::MPoly;
use num_traits::Signed;

impl MPoly {
    /// Term indices in display order (total degree descending, then lex descending).
    pub(crate) fn display_order(&self) -> Vec<usize> {
        let tdeg = |m: u128| (0..self.nvars).map(|i| self.exp(m, i)).sum::<u32>();
        let mut idx: Vec<(u32, u128, usize)> = self
            .terms
            .iter()
            .enumerate()
            .map(|(i, t)| (tdeg(t.0), t.0, i))
            .collect();
        idx.sort_unstable_by(|a, b| b.0.cmp(&a.0).then(b.1.cmp(&a.1)));
        idx.into_iter().map(|t| t.2).collect()
    }

    /// Is the first displayed term (largest total degree, then lex) negative?
    pub fn display_lead_negative(&self) -> bool {
        self.display_order()
            .first()
            .is_some_and(|&i| self.terms[i].1.is_negative())
    }

    /// `f` or `-f`, whichever displays with a positive first term (for lists of factors and
    /// conditions, where the sign is immaterial or carried elsewhere).
    pub fn display_normalized(&self) -> MPoly {
        if self.display_lead_negative() {
            self.neg()
        } else {
            self.clone()
        }
    }

    /// Is the display a single term (no `+`/`-` between terms)?
    pub fn is_monomial_term(&self) -> bool {
        self.len() <= 1
    }
}
