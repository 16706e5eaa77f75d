//! Raw proxy tree of a system file: one shape for JSON and TOML, numbers kept as text.
//!
//! JSON numbers come from serde_json with `arbitrary_precision`, which stores the number
//! exactly as written; TOML numbers come from `toml::de::DeTable`, whose integer and float
//! tokens keep their source text (underscores removed, radix prefixes decoded here). No
//! number ever passes through `f64`.

use super::InputError;
use num_bigint::BigInt;
use serde_json::Value as Json;
use std::borrow::Cow;
use toml::de::{DeTable, DeValue};

/// A parsed, not yet validated, value.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Raw {
    /// A number token, exact text (e.g. `1.5e-3`; TOML may also give `inf`, `nan`).
    Number(String),
    Str(String),
    Array(Vec<Raw>),
    /// Key-value pairs in file order.
    Table(Vec<(String, Raw)>),
    /// Anything else (boolean, null, datetime): its kind and a JSON rendering.
    Other {
        kind: &'static str,
        json: Json,
    },
}

impl Raw {
    /// A short description for error messages: "a number", "an array", ...
    pub(crate) fn kind(&self) -> &'static str {
        match self {
            Raw::Number(_) => "a number",
            Raw::Str(_) => "a string",
            Raw::Array(_) => "an array",
            Raw::Table(_) => "a table",
            Raw::Other { kind, .. } => kind,
        }
    }
    /// The JSON rendering (numbers exact when they are valid JSON numbers).
    pub(crate) fn to_json(&self) -> Json {
        match self {
            Raw::Number(s) => s
                .parse::<serde_json::Number>()
                .map_or_else(|_| Json::String(s.clone()), Json::Number),
            Raw::Str(s) => Json::String(s.clone()),
            Raw::Array(xs) => Json::Array(xs.iter().map(Raw::to_json).collect()),
            Raw::Table(kv) => {
                Json::Object(kv.iter().map(|(k, v)| (k.clone(), v.to_json())).collect())
            }
            Raw::Other { json, .. } => json.clone(),
        }
    }
}

/// Parses JSON text into the proxy tree.
pub(crate) fn from_json_text(text: &str, file: &str) -> Result<Raw, InputError> {
    let v: Json = serde_json::from_str(text)
        .map_err(|e| InputError::file(file, format!("invalid JSON: {e}")))?;
    Ok(from_json(v))
}

fn from_json(v: Json) -> Raw {
    match v {
        // arbitrary_precision: to_string gives the number's text as written
        Json::Number(n) => Raw::Number(n.to_string()),
        Json::String(s) => Raw::Str(s),
        Json::Array(xs) => Raw::Array(xs.into_iter().map(from_json).collect()),
        Json::Object(m) => Raw::Table(m.into_iter().map(|(k, v)| (k, from_json(v))).collect()),
        Json::Bool(_) => Raw::Other {
            kind: "a boolean",
            json: v,
        },
        Json::Null => Raw::Other {
            kind: "null",
            json: v,
        },
    }
}

/// Parses TOML text into the proxy tree.
pub(crate) fn from_toml_text(text: &str, file: &str) -> Result<Raw, InputError> {
    let doc = DeTable::parse(text).map_err(|e| {
        let at = e
            .span()
            .map(|s| {
                let before = text.get(..s.start).unwrap_or(text);
                let line = before.matches('\n').count() + 1;
                let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
                format!(" at line {line}, column {col}")
            })
            .unwrap_or_default();
        InputError::file(file, format!("invalid TOML{at}: {}", e.message().trim()))
    })?;
    Ok(from_toml_table(doc.into_inner()))
}

fn from_toml_table(t: DeTable<'_>) -> Raw {
    // the map is ordered by key; restore file order from the key spans
    let mut kv: Vec<_> = t.into_iter().collect();
    kv.sort_by_key(|(k, _)| k.span().start);
    Raw::Table(
        kv.into_iter()
            .map(|(k, v)| (k.into_inner().into_owned(), from_toml(v.into_inner())))
            .collect(),
    )
}

fn from_toml(v: DeValue<'_>) -> Raw {
    match v {
        DeValue::String(s) => Raw::Str(Cow::into_owned(s)),
        DeValue::Integer(i) => {
            if i.radix() == 10 {
                Raw::Number(i.as_str().to_string())
            } else {
                // 0x.., 0o.., 0b..: exact conversion to decimal text
                match BigInt::parse_bytes(i.as_str().as_bytes(), i.radix()) {
                    Some(n) => Raw::Number(n.to_string()),
                    None => Raw::Str(i.to_string()),
                }
            }
        }
        DeValue::Float(f) => Raw::Number(f.as_str().to_string()),
        DeValue::Boolean(b) => Raw::Other {
            kind: "a boolean",
            json: Json::Bool(b),
        },
        DeValue::Datetime(d) => Raw::Other {
            kind: "a date",
            json: Json::String(d.to_string()),
        },
        DeValue::Array(xs) => {
            Raw::Array(xs.into_iter().map(|x| from_toml(x.into_inner())).collect())
        }
        DeValue::Table(t) => from_toml_table(t),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn numbers_keep_their_text() {
        let j = from_json_text(
            r#"{"x": [0.08, 1.5e-3, 123456789012345678901234567890, -1E+2]}"#,
            "f",
        )
        .unwrap();
        let Raw::Table(kv) = j else { panic!() };
        assert_eq!(
            kv[0].1,
            Raw::Array(vec![
                Raw::Number("0.08".into()),
                Raw::Number("1.5e-3".into()),
                Raw::Number("123456789012345678901234567890".into()),
                Raw::Number("-1e+2".into()),
            ])
        );
        let t = from_toml_text("x = [0.08, 1.5e-3, 1_000, 0xff, -7, +1.25, inf]", "f").unwrap();
        let Raw::Table(kv) = t else { panic!() };
        let Raw::Array(xs) = &kv[0].1 else { panic!() };
        let texts: Vec<String> = xs
            .iter()
            .map(|x| match x {
                Raw::Number(s) => s.clone(),
                other => format!("{other:?}"),
            })
            .collect();
        assert_eq!(
            texts,
            ["0.08", "1.5e-3", "1000", "255", "-7", "+1.25", "inf"]
        );
    }
    #[test]
    fn syntax_errors_are_one_line() {
        let e = from_toml_text("a = [1,\nb = ", "f.toml").unwrap_err();
        assert!(
            e.to_string().starts_with("f.toml: invalid TOML at line"),
            "{e}"
        );
        assert!(!e.to_string().contains('\n'));
        let e = from_json_text("{\"a\": [1,]}", "f.json").unwrap_err();
        assert!(e.to_string().starts_with("f.json: invalid JSON: "), "{e}");
    }
}
