//! Model files: a linear multibody model (bodies, connections, loads, actuators, sensors)
//! in JSON or TOML with the same keys, read exactly into a [`Model`] over $\mathbb{Q}$ or,
//! when a parameter is `null` (or named in `symbols` / `--symbolic`), over
//! $\mathbb{Q}(p_1, \dots, p_k)$. A file is a model file when it has the top-level key
//! `bodies`. Keys, units and conventions: `docs/models.md`.
//!
//! Every scalar is a number (decimals exact: `0.3` is $3/10$) or an expression over the
//! parameters (`"cf/u"`); valued parameters are substituted as text, as in system files.
//!
//! | entry point | does |
//! |---|---|
//! | [`is_model_text`] | does the text hold a model (top-level `bodies`)? |
//! | [`read_model_str`] | text -> [`ModelAny`] (the model over its field) |
//! | [`super::load::load_model_str`] | text -> [`super::LoadedSystem`] (assembled, typed, standard form) |

mod items;
mod reader;

use super::raw::{Raw, from_text};
use super::subst::{Substitution, SymbolicOptions};
use super::{Ground, InputError, SystemFormat};
use crate::field::Q;
use crate::multibody::Model;
use crate::ratfunc::RatFuncField;
use std::collections::BTreeSet;

/// A model over its field.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)]
pub enum ModelAny {
    Rational(Model<Q>),
    RatFunc(Model<RatFuncField>),
}

const TOP_KEYS: [&str; 14] = [
    "name",
    "parameters",
    "symbols",
    "bodies",
    "rigid_points",
    "flex_points",
    "nh_points",
    "springs",
    "links",
    "actuators",
    "sensors",
    "loads",
    "gravity",
    "description",
];

/// Does `text` (JSON or TOML) hold a model file (a top-level key `bodies`)?
pub fn is_model_text(text: &str, format: SystemFormat) -> bool {
    let raw = from_text(text, format, "");
    matches!(raw, Ok(Raw::Table(t)) if t.iter().any(|(k, _)| k == "bodies"))
}

/// Reads a model file into a [`Model`] over $\mathbb{Q}$, or over $\mathbb{Q}(p)$ when
/// symbols remain.
///
/// # Errors
/// Syntax errors, unknown keys, a missing or malformed value (named by its key, e.g.
/// `springs[2].stiffness`), an unknown body name, a scalar that is not a rational number
/// (over $\mathbb{Q}$) or a rational function of the symbols.
pub fn read_model_str(
    text: &str,
    format: SystemFormat,
    name: &str,
    opts: &SymbolicOptions,
) -> Result<ModelAny, InputError> {
    let raw = from_text(text, format, name)?;
    let Raw::Table(top) = raw else {
        return Err(InputError::file(name, "expected a table at the top level"));
    };
    if let Some((k, _)) = top.iter().find(|(k, _)| !TOP_KEYS.contains(&k.as_str())) {
        return Err(InputError::key(name, k, "unknown key in a model file"));
    }
    let (valued, symbols) = parameters(name, &top, opts)?;
    let subst = Substitution::new(name, &valued)?;
    if symbols.is_empty() {
        let eval = |t: &str| -> Result<crate::field::Rational, String> {
            let text = subst.apply(t)?;
            let (x, _) =
                super::eval_expr(&text, &[], &Ground::Rational).map_err(|e| e.to_string())?;
            x.to_rational()
                .ok_or_else(|| "expected a rational number".to_string())
        };
        return Ok(ModelAny::Rational(items::build(name, &top, &Q, &eval)?));
    }
    let vars: Vec<&str> = symbols.iter().map(String::as_str).collect();
    let k =
        RatFuncField::new(&vars).map_err(|e| InputError::key(name, "symbols", e.to_string()))?;
    let eval = |t: &str| {
        let text = subst.apply(t)?;
        k.parse(&text).map_err(|e| e.to_string())
    };
    Ok(ModelAny::RatFunc(items::build(name, &top, &k, &eval)?))
}

type Params = (Vec<(String, String)>, BTreeSet<String>);

fn parameters(
    file: &str,
    top: &[(String, Raw)],
    opts: &SymbolicOptions,
) -> Result<Params, InputError> {
    let mut params: Vec<(String, Option<String>)> = vec![];
    let mut symbols = BTreeSet::new();
    for (key, v) in top {
        match (key.as_str(), v) {
            ("parameters", Raw::Table(kv)) => {
                for (n, v) in kv {
                    let val = match v {
                        Raw::Number(s) | Raw::Str(s) => Some(s.clone()),
                        Raw::Other { json, .. } if json.is_null() => None,
                        other => {
                            return Err(InputError::key(
                                file,
                                &format!("parameters.{n}"),
                                format!(
                                    "expected a number, a string or null, found {}",
                                    other.kind()
                                ),
                            ));
                        }
                    };
                    if !super::expr::is_parameter_name(n) {
                        return Err(InputError::key(
                            file,
                            &format!("parameters.{n}"),
                            "not a name",
                        ));
                    }
                    params.push((n.clone(), val));
                }
            }
            ("parameters", other) => {
                return Err(InputError::key(
                    file,
                    "parameters",
                    format!("expected a table, found {}", other.kind()),
                ));
            }
            ("symbols", Raw::Array(xs)) => {
                for x in xs {
                    let Raw::Str(s) = x else {
                        return Err(InputError::key(file, "symbols", "expected a list of names"));
                    };
                    symbols.insert(s.clone());
                }
            }
            ("symbols", _) => {
                return Err(InputError::key(file, "symbols", "expected a list of names"));
            }
            _ => {}
        }
    }
    opts.apply_to(file, &mut params, &mut symbols)?;
    let valued = params
        .into_iter()
        .filter(|(n, _)| !symbols.contains(n))
        .filter_map(|(n, v)| v.map(|v| (n, v)))
        .collect();
    Ok((valued, symbols))
}
