//! The report of `dcgain`: $G(0)$ per channel (`inf` at a pole at $s = 0$), the matrix
//! $D - C A^{-1} B$ when $A$ is invertible, and the exact check.

use crate::field::Field;
use crate::report::{Report, Value};
use crate::system::dcgain::DcGain;

impl<K: Field> DcGain<K> {
    /// `dc_gain` (exact strings, `inf` for a pole at 0), `finite`, `matrix` (with its
    /// approximations) when $A$ is invertible, `verified`.
    pub fn report(&self, k: &K) -> Report {
        let rows = self
            .entries
            .iter()
            .map(|row| {
                Value::List(
                    row.iter()
                        .map(|x| Value::Str(x.as_ref().map_or("inf".into(), |x| k.fmt_elem(x))))
                        .collect(),
                )
            })
            .collect();
        let finite = self.entries.iter().flatten().all(Option::is_some);
        let title = format!("DC gain G({})", k.fmt_elem(&self.point));
        let mut r = Report::titled(title)
            .list("dc_gain", rows)
            .bool("finite", finite);
        if let Some(m) = &self.matrix {
            r = r.matrix("matrix", m);
        }
        r.bool("verified", self.verified)
    }
}
