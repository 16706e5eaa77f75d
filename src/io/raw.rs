//! Raw proxy tree of a system file: one shape for JSON and TOML, numbers kept as text.
//!
//! JSON numbers come from serde_json with `arbitrary_precision`, which stores the number
//! exactly as written; TOML numbers come from `toml::de::DeTable`, whose integer and float
//! tokens keep their source text (underscores removed, radix prefixes decoded here). No
//! number ever passes through `f64`.

use super::{InputError, InputErrorKind};
use num_bigint::BigInt;
use serde::de::{self, DeserializeSeed, Deserializer, MapAccess, SeqAccess, Visitor};
use serde_json::Value as Json;
use std::borrow::Cow;
use std::cell::RefCell;
use std::collections::HashSet;
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

/// `text` read as `format` ([`from_json_text`] or [`from_toml_text`]).
///
/// # Errors
/// As the reader of the format.
pub(crate) fn from_text(
    text: &str,
    format: super::read::SystemFormat,
    file: &str,
) -> Result<Raw, InputError> {
    match format {
        super::read::SystemFormat::Json => from_json_text(text, file),
        super::read::SystemFormat::Toml => from_toml_text(text, file),
    }
}

/// Parses JSON text into the proxy tree, in one pass (no intermediate `serde_json::Value`).
///
/// A key given twice in one object is an error naming the key (`serde_json::Value` would
/// silently keep the last one).
pub(crate) fn from_json_text(text: &str, file: &str) -> Result<Raw, InputError> {
    let dup = RefCell::new(None);
    let mut de = serde_json::Deserializer::from_str(text);
    let parsed = JsonSeed { dup: &dup }
        .deserialize(&mut de)
        .and_then(|r| de.end().map(|()| r));
    parsed.map_err(|e| {
        if let Some(k) = dup.borrow_mut().take() {
            return InputError::key(
                file,
                &k,
                format!(
                    "key given twice (second time at line {}, column {})",
                    e.line(),
                    e.column()
                ),
            )
            .with_kind(InputErrorKind::DuplicateKey);
        }
        InputError::file(file, format!("invalid JSON: {e}")).with_kind(InputErrorKind::Syntax)
    })
}

/// serde_json's marker key for a number under `arbitrary_precision` (the number's text is
/// the map's one value).
const JSON_NUMBER_TOKEN: &str = "$serde_json::private::Number";

#[derive(Clone, Copy)]
struct JsonSeed<'a> {
    dup: &'a RefCell<Option<String>>,
}

impl<'de> DeserializeSeed<'de> for JsonSeed<'_> {
    type Value = Raw;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Raw, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for JsonSeed<'_> {
    type Value = Raw;
    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a JSON value")
    }
    fn visit_bool<E: de::Error>(self, b: bool) -> Result<Raw, E> {
        Ok(Raw::Other {
            kind: "a boolean",
            json: Json::Bool(b),
        })
    }
    fn visit_unit<E: de::Error>(self) -> Result<Raw, E> {
        Ok(Raw::Other {
            kind: "null",
            json: Json::Null,
        })
    }
    // without arbitrary_precision numbers would arrive here; keep them exact anyway
    fn visit_i64<E: de::Error>(self, n: i64) -> Result<Raw, E> {
        Ok(Raw::Number(n.to_string()))
    }
    fn visit_u64<E: de::Error>(self, n: u64) -> Result<Raw, E> {
        Ok(Raw::Number(n.to_string()))
    }
    fn visit_str<E: de::Error>(self, s: &str) -> Result<Raw, E> {
        Ok(Raw::Str(s.to_string()))
    }
    fn visit_string<E: de::Error>(self, s: String) -> Result<Raw, E> {
        Ok(Raw::Str(s))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Raw, A::Error> {
        let mut xs = Vec::with_capacity(seq.size_hint().unwrap_or(0));
        while let Some(x) = seq.next_element_seed(self)? {
            xs.push(x);
        }
        Ok(Raw::Array(xs))
    }
    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Raw, A::Error> {
        let mut kv: Vec<(String, Raw)> = Vec::new();
        let mut seen: HashSet<String> = HashSet::new();
        while let Some(k) = map.next_key::<String>()? {
            if k == JSON_NUMBER_TOKEN && kv.is_empty() {
                let text: String = map.next_value()?;
                return Ok(Raw::Number(text));
            }
            if !seen.insert(k.clone()) {
                *self.dup.borrow_mut() = Some(k.clone());
                return Err(de::Error::custom(format!("duplicate key '{k}'")));
            }
            let v = map.next_value_seed(self)?;
            kv.push((k, v));
        }
        Ok(Raw::Table(kv))
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
            .with_kind(InputErrorKind::Syntax)
    })?;
    let raw = from_toml_table(doc.into_inner());
    toml_header_trap(&raw, file)?;
    Ok(raw)
}

/// The keys of a system file that hold matrices (top level only).
const MATRIX_KEYS: [&str; 10] = ["A", "B", "C", "D", "E", "M", "L", "K", "F", "G"];

/// TOML's ordering trap: every key after a `[table]` header belongs to that table, so a
/// matrix written below `[parameters]` becomes `parameters.A`. When a table holds a matrix
/// key as an array and the top level lacks it, the error says so and how to fix it.
fn toml_header_trap(raw: &Raw, file: &str) -> Result<(), InputError> {
    let Raw::Table(top) = raw else { return Ok(()) };
    let at_top = |k: &str| top.iter().any(|(t, _)| t == k);
    for (table, value) in top {
        let Raw::Table(inner) = value else { continue };
        let trapped: Vec<&str> = inner
            .iter()
            .filter(|(k, v)| {
                MATRIX_KEYS.contains(&k.as_str()) && matches!(v, Raw::Array(_)) && !at_top(k)
            })
            .map(|(k, _)| k.as_str())
            .collect();
        if let Some(first) = trapped.first() {
            return Err(InputError::key(
                file,
                &format!("{table}.{first}"),
                format!(
                    "{} written after the [{table}] header belong to that table (in TOML every \
                     key after a [table] header is part of it); move {} above [{table}]",
                    trapped.join(", "),
                    if trapped.len() == 1 { "it" } else { "them" }
                ),
            ));
        }
    }
    Ok(())
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
    fn toml_matrix_below_a_table_header_gets_the_hint() {
        let text =
            "name = \"t\"\n[parameters]\nm = \"2\"\nA = [[0, 1], [\"-1/m\", 0]]\nB = [[0], [1]]\n";
        let e = from_toml_text(text, "t.toml").unwrap_err().to_string();
        assert!(e.contains("parameters.A"), "{e}");
        assert!(
            e.contains("A, B written after the [parameters] header"),
            "{e}"
        );
        assert!(e.contains("move them above [parameters]"), "{e}");
        // the same keys before the header are fine
        let ok = "A = [[0, 1], [\"-1/m\", 0]]\nB = [[0], [1]]\n[parameters]\nm = \"2\"\n";
        assert!(from_toml_text(ok, "t.toml").is_ok());
        // a table holding a scalar A (a parameter named A) is not the trap
        let param = "A = [[0, 1], [\"-1/A\", 0]]\n[parameters]\nA = \"2\"\n";
        assert!(from_toml_text(param, "t.toml").is_ok());
    }
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
        let e = from_json_text("{\"a\": [1, {\"b\": 1, \"b\": 2}]}", "f.json").unwrap_err();
        assert_eq!(e.kind, InputErrorKind::DuplicateKey);
        assert_eq!(
            e.to_string(),
            "f.json: key b: key given twice (second time at line 1, column 22)"
        );
        let e = from_json_text("{\"a\": [1,]}", "f.json").unwrap_err();
        assert!(e.to_string().starts_with("f.json: invalid JSON: "), "{e}");
    }
}
