//! `exactlti connect CONNECTION_FILE`: systems connected by signal names from a connection
//! file (python-control's `interconnect(syslist, connections, inplist, outlist)`), closed
//! exactly by [`super::connect_names::connect_named`] (checked there:
//! $F (I - G K)^{-1} G E$ at points), reported with its transfer matrix in lowest terms,
//! optionally its exact minimal realization and written as a system file.
//!
//! The file (JSON, or TOML by its extension):
//! `systems` (paths, relative to the connection file), `connections` (each a subsystem
//! input name followed by the output names summed into it, `-y` subtracting), `inputs`
//! (external inputs, each driving every subsystem input of its name), `outputs` (output
//! names picked as external outputs).

use super::common::with_path;
use super::connect_names::{NamedConnection, connect_named};
use super::interconnect_common::InterconnectOpts;
use super::{Failure, Outcome, System, SystemVisitor};
use crate::io::symbolic::SymbolicOptions;
use crate::io::{SystemFile, TypedSystem};
use crate::realization::{MinrealMethod, minimal};
use crate::report::{Report, Value, str_list};
use crate::system::discrete::stability::Domain;
use serde_json::Value as J;
use std::path::Path;

fn bad(path: &Path, message: String) -> Failure {
    Failure::input(format!("{}: {message}", path.display()))
}

/// The connection file as JSON (TOML converted).
fn read_json(path: &Path) -> Result<J, Failure> {
    let text = crate::io::read_text(path).map_err(|e| bad(path, e.to_string()))?;
    if path
        .extension()
        .is_some_and(|x| x.eq_ignore_ascii_case("toml"))
    {
        let v: toml::Value = toml::from_str(&text).map_err(|e| {
            bad(
                path,
                format!("not TOML: {}", e.to_string().replace('\n', " ")),
            )
        })?;
        serde_json::to_value(v).map_err(|e| bad(path, e.to_string()))
    } else {
        serde_json::from_str(&text).map_err(|e| bad(path, format!("not JSON: {e}")))
    }
}

/// A list of strings under `key` (`where_` names it in errors).
fn strings(path: &Path, v: &J, where_: &str) -> Result<Vec<String>, Failure> {
    let J::Array(xs) = v else {
        return Err(bad(path, format!("key {where_}: must be a list of names")));
    };
    xs.iter()
        .enumerate()
        .map(|(i, x)| match x {
            J::String(s) if !s.trim().is_empty() => Ok(s.trim().to_string()),
            _ => Err(bad(
                path,
                format!("key {where_}[{i}]: must be a non-empty string, found {x}"),
            )),
        })
        .collect()
}

/// The systems' paths and the connection by names.
fn parse(path: &Path, v: &J) -> Result<(Vec<String>, NamedConnection), Failure> {
    let J::Object(o) = v else {
        return Err(bad(
            path,
            "a connection file is an object with keys systems, connections, inputs, outputs".into(),
        ));
    };
    for k in o.keys() {
        if !["systems", "connections", "inputs", "outputs", "name"].contains(&k.as_str()) {
            return Err(bad(
                path,
                format!("key {k}: unknown (keys: systems, connections, inputs, outputs, name)"),
            ));
        }
    }
    let need = |k: &str| {
        o.get(k)
            .ok_or_else(|| bad(path, format!("key {k}: missing")))
    };
    let systems = strings(path, need("systems")?, "systems")?;
    if systems.is_empty() {
        return Err(bad(
            path,
            "key systems: needs at least one system file".into(),
        ));
    }
    let mut connections = vec![];
    if let Some(c) = o.get("connections") {
        let J::Array(cs) = c else {
            return Err(bad(
                path,
                "key connections: must be a list of lists [input, output, -output, ...]".into(),
            ));
        };
        for (i, x) in cs.iter().enumerate() {
            let names = strings(path, x, &format!("connections[{i}]"))?;
            if names.len() < 2 {
                return Err(bad(
                    path,
                    format!(
                        "key connections[{i}]: needs an input name and at least one output name"
                    ),
                ));
            }
            connections.push(names);
        }
    }
    let inputs = strings(path, need("inputs")?, "inputs")?;
    let outputs = strings(path, need("outputs")?, "outputs")?;
    Ok((
        systems,
        NamedConnection {
            connections,
            inputs,
            outputs,
        },
    ))
}

/// One connection as text: `e <- v - y` (the outputs summed into the input `e`; an
/// external input of the same name adds to it).
fn connection_text(c: &[String]) -> String {
    let mut s = format!("{} <-", c[0]);
    for (i, src) in c[1..].iter().enumerate() {
        match (src.strip_prefix('-'), i) {
            (Some(n), 0) => s.push_str(&format!(" -{n}")),
            (Some(n), _) => s.push_str(&format!(" - {n}")),
            (None, 0) => s.push_str(&format!(" {src}")),
            (None, _) => s.push_str(&format!(" + {src}")),
        }
    }
    s
}

/// Runs `connect` on its connection file.
///
/// # Errors
/// The connection file's errors (one line naming the key), the systems' own, unknown or
/// duplicate signal names, mixed time domains, an ill-posed algebraic loop.
pub fn run(
    file: &Path,
    opts: &InterconnectOpts,
    sym: &SymbolicOptions,
) -> Result<Outcome, Failure> {
    let (paths, conn) = parse(file, &read_json(file)?)?;
    let dir = file.parent().unwrap_or(Path::new(""));
    let systems = paths
        .iter()
        .map(|p| System::open_or_gain(&dir.join(p), sym).map_err(Failure::from))
        .collect::<Result<Vec<_>, _>>()?;
    let refs: Vec<&System> = systems.iter().collect();
    let closed = connect_named(&refs, &conn)
        .map_err(|f| Failure::new(f.class, format!("{}: {}", file.display(), f.message)))?;
    let parts: Vec<Value> = paths
        .iter()
        .zip(&systems)
        .map(|(p, s)| {
            let sig = &s.file().signals;
            let mut r = Report::new()
                .str("file", p.clone())
                .int("states", s.nstates());
            if let Some(i) = &sig.inputs {
                r = r.with("inputs", str_list(i.clone()));
            }
            if let Some(o) = &sig.outputs {
                r = r.with("outputs", str_list(o.clone()));
            }
            Value::Obj(r)
        })
        .collect();
    let head = Report::titled("connect (by signal names)")
        .str("connection_file", file.display().to_string())
        .list("parts", parts)
        .with(
            "connections",
            str_list(conn.connections.iter().map(|c| connection_text(c))),
        )
        .with("inputs", str_list(conn.inputs.clone()))
        .with("outputs", str_list(conn.outputs.clone()))
        .str(
            "identity",
            "G_closed = F (I - G K)^-1 G E with G = diag(parts), K, E, F the 0/1 routing of the names (checked exactly at points)",
        );
    closed.run(Finish {
        head,
        opts,
        name: file.display().to_string(),
    })
}

struct Finish<'a> {
    head: Report,
    opts: &'a InterconnectOpts,
    name: String,
}

impl SystemVisitor for Finish<'_> {
    type Output = Result<Outcome, Failure>;
    fn visit<K: crate::io::GroundField>(self, f: &SystemFile, t: &TypedSystem<K>) -> Self::Output {
        let path = Path::new(&self.name);
        let e = |err| with_path(path, err);
        let sys = &t.ss;
        let domain = Domain::of(f.signals.dt.as_ref());
        let g = sys.transfer_matrix().map_err(e)?;
        let min = if self.opts.minreal {
            Some(minimal(sys, MinrealMethod::Kalman).map_err(e)?)
        } else {
            None
        };
        let mut r = self
            .head
            .str("field", sys.field().to_string())
            .with("variable", crate::report::sections::variable(domain));
        if let Some(dt) = &f.signals.dt {
            r = r.rational("dt", dt);
        }
        r = r
            .int("states", sys.nstates())
            .matrix("A", &sys.a)
            .matrix("B", &sys.b)
            .matrix("C", &sys.c)
            .matrix("D", &sys.d)
            .with(
                "transfer_matrix",
                Value::List(
                    g.to_strings_var(domain.var())
                        .into_iter()
                        .map(str_list)
                        .collect(),
                ),
            )
            .bool("verified", true);
        let symbols = sys
            .field()
            .symbolic()
            .map(|k| k.vars().to_vec())
            .unwrap_or_default();
        if let Some(m) = &min {
            r = r.obj("minimal", m.report());
        }
        if let Some(out) = &self.opts.out {
            let written = min.as_ref().map_or(sys, |m| &m.system);
            let name = format!("connect {}", self.name);
            super::interconnect_common::write_system_file(
                out, &name, written, &symbols, &f.signals,
            )?;
            r = r.str("written", out.display().to_string());
        }
        let ok = min.as_ref().is_none_or(|m| m.verified);
        Ok(Outcome::new(r, ok))
    }
}
