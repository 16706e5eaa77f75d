//! `Display` of systems: one line per matrix, exact entries in the field's display.

use super::{Descriptor, StateSpace};
use crate::field::Field;
use std::fmt;

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
