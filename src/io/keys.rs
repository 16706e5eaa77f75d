//! The keys a system file may have, checked strictly (CLI contract: unknown keys are an
//! error, with a suggestion for a near miss).
//!
//! | key | meaning |
//! |---|---|
//! | `A`, `B`, `C`, `D`, `E` | first-order (descriptor) form |
//! | `M`, `L`, `K`, `F` | second-order form |
//! | `G` | transfer matrix (rational functions of `s`) |
//! | `parameters`, `symbols` | named values; symbolic parameters |
//! | `name`, `inputs`, `outputs`, `states` | descriptive: the system's and the signals' names |
//! | `dt` | sample time of a discrete-time system (a positive exact number; absent or 0: continuous) |
//!
//! A file with the bicycle benchmark's raw matrices (`M`, `C1`, `K0`, `K2`) is recognised and
//! refused with a pointer to the system form of the same data.

use super::raw::Raw;
use super::{InputError, InputErrorKind};
use crate::field::Rational;
use num_traits::{Signed, Zero};

/// The key `dt`: a positive exact number (decimal or fraction, `0.1` is 1/10); `0` is
/// continuous time (python-control's `dt = 0`).
///
/// # Errors
/// A value that is not a number, or a negative one (`dt = True`, python-control's
/// unspecified sample time, is refused: give the number).
pub(crate) fn read_dt(
    file: &str,
    entries: &[(String, Raw)],
) -> Result<Option<Rational>, InputError> {
    let Some((_, v)) = entries.iter().find(|(k, _)| k == "dt") else {
        return Ok(None);
    };
    let bad = |what: String| InputError::key(file, "dt", what);
    let text = match v {
        Raw::Number(s) | Raw::Str(s) => s,
        other => {
            return Err(bad(format!(
                "expected the sample time (a positive number, or 0 for continuous time), \
                 found {}",
                other.kind()
            )));
        }
    };
    let dt = crate::field::parse_rational(text).map_err(|e| bad(format!("'{text}': {e}")))?;
    if dt.is_negative() {
        return Err(bad(format!(
            "the sample time must be positive (or 0 for continuous time), found {text}"
        )));
    }
    Ok((!dt.is_zero()).then_some(dt))
}

/// Every key a system file may have.
pub const SYSTEM_KEYS: [&str; 18] = [
    "A",
    "B",
    "C",
    "D",
    "E",
    "M",
    "L",
    "K",
    "F",
    "G",
    "parameters",
    "symbols",
    "name",
    "inputs",
    "outputs",
    "states",
    "dt",
    "realize",
];

/// The keys of a table in file order.
pub(crate) fn keys_of(entries: &[(String, Raw)]) -> Vec<&str> {
    entries.iter().map(|(k, _)| k.as_str()).collect()
}

/// Checks that every key is a system-file key.
///
/// # Errors
/// The bicycle benchmark's raw data (keys `C1`, `K0`, `K2`): a [`InputErrorKind::NotASystem`]
/// naming the system form to use; else the first unknown key, with the closest known key
/// when one is near (`unknown key 'Bee'; did you mean 'B'?`).
pub(crate) fn check_keys(file: &str, keys: &[&str]) -> Result<(), InputError> {
    if ["C1", "K0", "K2"].iter().all(|k| keys.contains(k)) {
        return Err(InputError::file(
            file,
            "these are the bicycle benchmark's raw matrices (M, C1, K0, K2 of \
             M q'' + v C1 q' + (g K0 + v^2 K2) q = f), not a system file: use the system form \
             data/bicycle-whipple.json (second-order keys M, L, K, F with the parameter v), \
             e.g. `exactlti critical data/bicycle-whipple.json --param v --from 0 --to 10`",
        )
        .with_kind(InputErrorKind::NotASystem));
    }
    for k in keys {
        if SYSTEM_KEYS.contains(k) {
            continue;
        }
        let up = k.to_ascii_uppercase();
        if up.len() == 1 && SYSTEM_KEYS[..10].contains(&up.as_str()) {
            return Err(InputError::key(
                file,
                k,
                format!("matrix keys are upper case: did you mean '{up}'?"),
            )
            .with_kind(InputErrorKind::UnknownKey));
        }
        let hint = suggest(k, &SYSTEM_KEYS)
            .map(|s| format!("; did you mean '{s}'?"))
            .unwrap_or_else(|| {
                "; a system file has the keys A, B, C, D, E (or M, L, K, F, or G), parameters, \
                 symbols, name, inputs, outputs, states, dt"
                    .to_string()
            });
        return Err(InputError::file(file, format!("unknown key '{k}'{hint}"))
            .with_kind(InputErrorKind::UnknownKey));
    }
    Ok(())
}

/// The known word closest to `word`, when it is close: same letters up to case, or an edit
/// distance of at most 1 for words of 1-2 characters and 2 for longer ones, or `word`
/// starting with the known word (`Bee` → `B`, `output` → `outputs`).
pub(crate) fn suggest<'a>(word: &str, known: &[&'a str]) -> Option<&'a str> {
    if let Some(k) = known.iter().find(|k| k.eq_ignore_ascii_case(word)) {
        return Some(k);
    }
    let limit = if word.chars().count() <= 2 { 1 } else { 2 };
    let best = known
        .iter()
        .map(|k| (edit_distance(word, k), *k))
        .filter(|(d, _)| *d <= limit)
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k);
    best.or_else(|| {
        // a longest known prefix (single upper-case letters only match an upper-case start)
        known
            .iter()
            .filter(|k| word.len() > k.len() && word.starts_with(**k))
            .max_by_key(|k| k.len())
            .copied()
    })
}

/// Levenshtein distance (insertions, deletions, substitutions), O(|a| |b|); the words here
/// are keys (short), and anything longer than 64 characters is not compared.
fn edit_distance(a: &str, b: &str) -> usize {
    let (a, b): (Vec<char>, Vec<char>) = (a.chars().collect(), b.chars().collect());
    if a.len() > 64 || b.len() > 64 {
        return usize::MAX;
    }
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.iter().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != cb);
            cur[j + 1] = sub.min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// Signal names of a system file: `inputs`, `outputs`, `states` (each a list of strings),
/// and the signals' sample time `dt` (python-control's and MATLAB's `Ts`).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SignalNames {
    pub inputs: Option<Vec<String>>,
    pub outputs: Option<Vec<String>>,
    pub states: Option<Vec<String>>,
    /// Sample time of a discrete-time system $x_{k+1} = A x_k + B u_k$ (exact, $> 0$);
    /// `None`: continuous time ($\dot x = A x + B u$).
    pub dt: Option<Rational>,
}

impl SignalNames {
    /// Reads the three keys from a table.
    ///
    /// # Errors
    /// A key whose value is not a list of strings.
    pub(crate) fn read(file: &str, entries: &[(String, Raw)]) -> Result<Self, InputError> {
        let list = |key: &str| -> Result<Option<Vec<String>>, InputError> {
            let Some((_, v)) = entries.iter().find(|(k, _)| k == key) else {
                return Ok(None);
            };
            let bad = || {
                InputError::key(
                    file,
                    key,
                    format!("expected a list of names (strings), found {}", v.kind()),
                )
            };
            let Raw::Array(xs) = v else {
                return Err(bad());
            };
            xs.iter()
                .map(|x| match x {
                    Raw::Str(s) => Ok(s.clone()),
                    _ => Err(bad()),
                })
                .collect::<Result<Vec<_>, _>>()
                .map(Some)
        };
        Ok(SignalNames {
            inputs: list("inputs")?,
            outputs: list("outputs")?,
            states: list("states")?,
            dt: read_dt(file, entries)?,
        })
    }

    /// Checks the counts against the system's `(states, inputs, outputs)`.
    ///
    /// # Errors
    /// A list whose length differs from its count, as a [`InputErrorKind::Shape`] error.
    pub fn check(&self, file: &str, n: usize, m: usize, p: usize) -> Result<(), InputError> {
        for (key, names, want, what) in [
            ("states", &self.states, n, "states"),
            ("inputs", &self.inputs, m, "inputs"),
            ("outputs", &self.outputs, p, "outputs"),
        ] {
            if let Some(xs) = names
                && xs.len() != want
            {
                return Err(InputError::key(
                    file,
                    key,
                    format!("{} names for {want} {what}", xs.len()),
                )
                .with_kind(InputErrorKind::Shape));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn suggestions() {
        assert_eq!(suggest("Bee", &SYSTEM_KEYS), Some("B"));
        assert_eq!(suggest("b", &SYSTEM_KEYS), Some("B"));
        assert_eq!(suggest("output", &SYSTEM_KEYS), Some("outputs"));
        assert_eq!(suggest("paramters", &SYSTEM_KEYS), Some("parameters"));
        assert_eq!(suggest("nmae", &SYSTEM_KEYS), Some("name"));
        assert_eq!(suggest("zzzz", &SYSTEM_KEYS), None);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
    }
}
