//! `dcgain FILE`: thin wrapper over [`crate::system::dcgain::dc_gain`] and its report.

use super::SystemVisitor;
use super::common::with_path;
use super::{Failure, Outcome};
use crate::io::{SystemFile, TypedSystem};
use crate::system::dcgain::{dc_gain, gain_at};
use std::path::Path;

/// Runs `dcgain` on a system (read by [`super::System::open_or_gain`]: a file with only `D`
/// is a static gain).
pub fn run(sys: &super::System) -> Result<Outcome, Failure> {
    sys.run(Dc { path: sys.path() })
}

struct Dc<'a> {
    path: &'a Path,
}

impl SystemVisitor for Dc<'_> {
    type Output = Result<Outcome, Failure>;
    fn visit<K: crate::io::GroundField>(self, f: &SystemFile, t: &TypedSystem<K>) -> Self::Output {
        let e = |err| with_path(self.path, err);
        // discrete time: the DC gain is G(z = 1)
        let g = match f.signals.dt {
            Some(_) => gain_at(&t.ss, &t.ss.field().one()).map_err(e)?,
            None => dc_gain(&t.ss).map_err(e)?,
        };
        let mut r = g.report(t.ss.field());
        // over Q(p): what the gain assumes nonzero (A invertible, the denominators at 0)
        if let Some(k) = t.ss.field().symbolic() {
            let conds = k.conditions_strings().map_err(e)?;
            r = r
                .str("field", k.to_string())
                .with("conditions", crate::report::str_list(conds));
        }
        Ok(Outcome::new(r, g.verified))
    }
}
