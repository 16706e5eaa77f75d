//! Displays of matrices and systems: `[[1, -1/2], [0, 1]]`, one line a matrix of a state-space
//! or descriptor system, transfer matrices entry by entry (`(s + 1)/(s^2 + 3*s + 2)`).

use crate::field::Field;
use crate::matrix::Matrix;
use crate::system::transfer::{RationalFunction, TransferMatrix};
use crate::system::{Descriptor, StateSpace};
use std::fmt;

impl<K: Field> Matrix<K> {
    /// Display entries with the field's exact display, `[[1, 2], [3, 4]]`.
    pub fn to_rows_strings(&self) -> Vec<Vec<String>> {
        let k = self.field();
        (0..self.nrows())
            .map(|i| self.row(i).iter().map(|x| k.fmt_elem(x)).collect())
            .collect()
    }
}

impl<K: Field> fmt::Display for Matrix<K> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let rows: Vec<String> = self
            .to_rows_strings()
            .into_iter()
            .map(|r| format!("[{}]", r.join(", ")))
            .collect();
        write!(f, "[{}]", rows.join(", "))
    }
}

impl<K: Field> fmt::Display for StateSpace<K> {
    /// `state space over QQ: 2 states, 1 input, 1 output` then `A = [[..]]`, `B`, `C`, `D`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "state space over {}: {} states, {} inputs, {} outputs",
            self.a.field(),
            self.nstates(),
            self.ninputs(),
            self.noutputs()
        )?;
        writeln!(f, "A = {}", self.a)?;
        writeln!(f, "B = {}", self.b)?;
        writeln!(f, "C = {}", self.c)?;
        write!(f, "D = {}", self.d)
    }
}

impl<K: Field> fmt::Display for Descriptor<K> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "descriptor system over {}: {} states",
            self.a.field(),
            self.nstates()
        )?;
        writeln!(f, "E = {}", self.e)?;
        writeln!(f, "A = {}", self.a)?;
        writeln!(f, "B = {}", self.b)?;
        writeln!(f, "C = {}", self.c)?;
        write!(f, "D = {}", self.d)
    }
}

impl<K: Field> RationalFunction<K> {
    /// `n(var)` or `(n(var))/(d(var))`.
    pub fn to_string_var(&self, var: &str) -> String {
        if self.den.is_one() {
            return self.num.to_string_var(var);
        }
        format!(
            "({})/({})",
            self.num.to_string_var(var),
            self.den.to_string_var(var)
        )
    }
}

impl<K: Field> TransferMatrix<K> {
    /// Entries as strings in the variable `s`.
    pub fn to_strings(&self) -> Vec<Vec<String>> {
        self.to_strings_var("s")
    }

    /// Entries as strings in the variable `var` (`z` for a discrete-time system).
    pub fn to_strings_var(&self, var: &str) -> Vec<Vec<String>> {
        self.entries
            .iter()
            .map(|r| r.iter().map(|f| f.to_string_var(var)).collect())
            .collect()
    }
}
