//! Parameter substitution shared by the system-file and model-file readers: the command
//! line's say on symbols ([`SymbolicOptions`]) and valued parameters substituted into entry
//! text as `(value)` until no name is left (cycles are errors).

use super::InputError;

/// The command line's say on symbols.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SymbolicOptions {
    /// `--symbolic`: `None` when not given, `Some(vec![])` for every parameter, else the names.
    pub symbolic: Option<Vec<String>>,
    /// `--at "m=1500, u=20"`: values (exact text) for parameters or symbols.
    pub at: Vec<(String, String)>,
}

impl SymbolicOptions {
    /// Parses `--symbolic` and `--at` values.
    ///
    /// # Errors
    /// An `--at` item without `=` or with an empty name or value.
    pub fn from_args(symbolic: Option<&str>, at: Option<&str>) -> Result<Self, String> {
        let names = |s: &str| -> Vec<String> {
            s.split(',')
                .map(|x| x.trim().to_string())
                .filter(|x| !x.is_empty())
                .collect()
        };
        let mut out = SymbolicOptions {
            symbolic: symbolic.map(names),
            at: vec![],
        };
        for item in at.unwrap_or("").split(',').filter(|x| !x.trim().is_empty()) {
            let Some((n, v)) = item.split_once('=') else {
                return Err(format!(
                    "--at: expected name=value, found '{}'",
                    item.trim()
                ));
            };
            let (n, v) = (n.trim(), v.trim());
            if n.is_empty() || v.is_empty() {
                return Err(format!(
                    "--at: expected name=value, found '{}'",
                    item.trim()
                ));
            }
            out.at.push((n.to_string(), v.to_string()));
        }
        Ok(out)
    }
    /// Nothing asked on the command line.
    pub fn is_empty(&self) -> bool {
        self.symbolic.is_none() && self.at.is_empty()
    }

    /// Applies these options to a file's `params` (value text, `None` for `null`) and its
    /// `symbols`, for every reader: `--symbolic` names become symbols (every parameter for an
    /// empty list), parameters without a value are symbols, then `--at` values replace
    /// values and symbols. A name the file does not declare is an error naming `file`.
    pub(crate) fn apply_to(
        &self,
        file: &str,
        params: &mut Vec<(String, Option<String>)>,
        symbols: &mut std::collections::BTreeSet<String>,
    ) -> Result<(), InputError> {
        let known = |n: &str,
                     params: &[(String, Option<String>)],
                     symbols: &std::collections::BTreeSet<String>| {
            params.iter().any(|(p, _)| p == n) || symbols.contains(n)
        };
        match &self.symbolic {
            Some(list) if list.is_empty() => symbols.extend(params.iter().map(|(n, _)| n.clone())),
            Some(list) => {
                for n in list {
                    if !known(n, params, symbols) {
                        return Err(InputError::file(
                            file,
                            format!("--symbolic: unknown parameter '{n}'"),
                        ));
                    }
                    symbols.insert(n.clone());
                }
            }
            None => {}
        }
        symbols.extend(
            params
                .iter()
                .filter(|(_, v)| v.is_none())
                .map(|(n, _)| n.clone()),
        );
        for (n, v) in &self.at {
            if !known(n, params, symbols) {
                return Err(InputError::file(
                    file,
                    format!("--at: unknown parameter '{n}'"),
                ));
            }
            symbols.remove(n);
            match params.iter_mut().find(|(p, _)| p == n) {
                Some(p) => p.1 = Some(v.clone()),
                None => params.push((n.clone(), Some(v.clone()))),
            }
        }
        Ok(())
    }
}

/// Valued parameters, substituted into entry text as `(value)` until no name is left.
pub(crate) struct Substitution {
    valued: Vec<(String, String)>,
}

impl Substitution {
    pub(crate) fn new(file: &str, valued: &[(String, String)]) -> Result<Self, InputError> {
        let s = Substitution {
            valued: valued.to_vec(),
        };
        for (n, v) in valued {
            s.apply(v)
                .map_err(|e| InputError::key(file, &format!("parameters.{n}"), e))?;
        }
        Ok(s)
    }
    fn lookup(&self, ident: &str) -> Option<&str> {
        self.valued
            .iter()
            .find(|(n, _)| n == ident)
            .map(|(_, v)| v.as_str())
    }
    /// The text with every valued parameter replaced (at most one round per parameter).
    pub(crate) fn apply(&self, text: &str) -> Result<String, String> {
        let mut cur = text.to_string();
        for _ in 0..=self.valued.len() {
            let (next, changed) = self.once(&cur);
            if !changed {
                return Ok(next);
            }
            cur = next;
        }
        Err("parameters depend on each other in a cycle".to_string())
    }
    fn once(&self, text: &str) -> (String, bool) {
        let b = text.as_bytes();
        let mut out = String::with_capacity(text.len());
        let mut changed = false;
        let mut i = 0;
        while i < b.len() {
            let c = b[i];
            if c.is_ascii_alphabetic() || c == b'_' {
                // an exponent marker inside a number (1e-3) is not a name
                let in_number = i > 0 && (b[i - 1].is_ascii_digit() || b[i - 1] == b'.');
                let start = i;
                while i < b.len() && (b[i].is_ascii_alphanumeric() || b[i] == b'_') {
                    i += 1;
                }
                let ident = &text[start..i];
                match self.lookup(ident) {
                    Some(v) if !in_number => {
                        out.push('(');
                        out.push_str(v);
                        out.push(')');
                        changed = true;
                    }
                    _ => out.push_str(ident),
                }
            } else {
                let ch = text[i..].chars().next().unwrap_or(' ');
                out.push(ch);
                i += ch.len_utf8();
            }
        }
        (out, changed)
    }
}
