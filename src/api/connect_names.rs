//! Connection by signal names (python-control's `interconnect`): the systems side by side,
//! each connection `[input, output, -output, ...]` feeding the sum of the named outputs
//! (a leading `-` subtracts) into every subsystem input of that name, the external inputs
//! driving the subsystem inputs of their names, the external outputs picking outputs by
//! name. The names become the 0/1 routing of [`crate::system::interconnect::connect`],
//! which closes the loop exactly and checks it at points.

use super::common::with_path;
use super::{Failure, System};
use crate::io::combine::{SystemsVisitor, common_field};
use crate::io::{SignalNames, TypedSystem};
use crate::matrix::Matrix;
use crate::system::interconnect::append;
use crate::system::interconnect::connect::{Routing, close, routing_holds};
use std::path::Path;

/// What to connect, by names.
#[derive(Clone, Debug, Default)]
pub struct NamedConnection {
    /// Each: a subsystem input name, then the outputs summed into it (`-y` subtracts).
    pub connections: Vec<Vec<String>>,
    /// External inputs: each drives every subsystem input of its name.
    pub inputs: Vec<String>,
    /// External outputs: subsystem output names.
    pub outputs: Vec<String>,
}

fn bad(message: String) -> Failure {
    Failure::input(format!("interconnect: {message}"))
}

/// The names of every input and output of the systems side by side (`u[i]`, `y[i]` where a
/// system has none); output names must be unique.
fn all_names(systems: &[&System]) -> Result<(Vec<String>, Vec<String>), Failure> {
    let (mut ins, mut outs) = (vec![], vec![]);
    for s in systems {
        let (m, p) = shape(s);
        let sig = &s.file().signals;
        ins.extend(
            sig.inputs
                .clone()
                .unwrap_or_else(|| (0..m).map(|i| format!("u[{i}]")).collect()),
        );
        outs.extend(
            sig.outputs
                .clone()
                .unwrap_or_else(|| (0..p).map(|i| format!("y[{i}]")).collect()),
        );
    }
    for (j, o) in outs.iter().enumerate() {
        if outs[..j].contains(o) {
            return Err(bad(format!(
                "the output name '{o}' is used twice: give the systems distinct output names"
            )));
        }
    }
    Ok((ins, outs))
}

fn shape(s: &System) -> (usize, usize) {
    use crate::io::TypedAny;
    match &s.loaded().system {
        TypedAny::Rational(t) => (t.ss.ninputs(), t.ss.noutputs()),
        TypedAny::Quadratic(t) => (t.ss.ninputs(), t.ss.noutputs()),
        TypedAny::RatFunc(t) => (t.ss.ninputs(), t.ss.noutputs()),
    }
}

/// The routing as integer matrices `(K, E, F)`.
type IntRouting = (Vec<Vec<i64>>, Vec<Vec<i64>>, Vec<Vec<i64>>);

fn routing(ins: &[String], outs: &[String], c: &NamedConnection) -> Result<IntRouting, Failure> {
    let (m, p) = (ins.len(), outs.len());
    let out_index = |name: &str| {
        outs.iter().position(|o| o == name).ok_or_else(|| {
            bad(format!(
                "unknown output '{name}' (outputs: {})",
                outs.join(", ")
            ))
        })
    };
    let in_rows = |name: &str| -> Result<Vec<usize>, Failure> {
        let rows: Vec<usize> = (0..m).filter(|i| ins[*i] == name).collect();
        if rows.is_empty() {
            return Err(bad(format!(
                "unknown input '{name}' (inputs: {})",
                ins.join(", ")
            )));
        }
        Ok(rows)
    };
    let mut k = vec![vec![0i64; p]; m];
    for conn in &c.connections {
        let Some((dest, srcs)) = conn.split_first() else {
            return Err(bad("an empty connection".into()));
        };
        let rows = in_rows(dest)?;
        for src in srcs {
            let (sign, name) = match src.strip_prefix('-') {
                Some(n) => (-1, n),
                None => (1, src.as_str()),
            };
            let j = out_index(name)?;
            for &i in &rows {
                k[i][j] += sign;
            }
        }
    }
    let mut e = vec![vec![0i64; c.inputs.len()]; m];
    for (col, name) in c.inputs.iter().enumerate() {
        for i in in_rows(name)? {
            e[i][col] = 1;
        }
    }
    let mut f = vec![vec![0i64; p]; c.outputs.len()];
    for (row, name) in c.outputs.iter().enumerate() {
        f[row][out_index(name)?] = 1;
    }
    Ok((k, e, f))
}

/// The systems connected by names, as a system whose signals are the external inputs and
/// outputs (and the common sample time).
///
/// # Errors
/// Unknown or duplicate names, mixed time domains or fields, an ill-posed algebraic loop,
/// a failed exact check.
pub fn connect_named(systems: &[&System], c: &NamedConnection) -> Result<System, Failure> {
    if systems.is_empty() {
        return Err(bad("no systems".into()));
    }
    let names: Vec<String> = (1..=systems.len()).map(|i| format!("system {i}")).collect();
    let dt = super::interconnect_common::common_dt(
        crate::system::interconnect::Operation::Append,
        &names,
        systems,
    )?;
    let (ins, outs) = all_names(systems)?;
    let r = routing(&ins, &outs, c)?;
    let loaded: Vec<_> = systems.iter().map(|s| s.loaded()).collect();
    let sys = common_field(&loaded)?.run(Close { r })?;
    Ok(sys.with_signals(SignalNames {
        inputs: Some(c.inputs.clone()),
        outputs: Some(c.outputs.clone()),
        states: None,
        dt,
    }))
}

struct Close {
    r: IntRouting,
}

impl SystemsVisitor for Close {
    type Output = Result<System, Failure>;
    fn visit<K: crate::io::GroundField>(self, systems: &[TypedSystem<K>]) -> Self::Output {
        let path = Path::new("interconnect");
        let e = |err| with_path(path, err);
        let parts: Vec<_> = systems.iter().map(|t| t.ss.clone()).collect();
        let all = append(&parts).map_err(e)?;
        let k = all.field().clone();
        let mat = |rows: &[Vec<i64>], r: usize, c: usize| {
            let mut m = Matrix::zeros(k.clone(), r, c);
            for (i, row) in rows.iter().enumerate() {
                for (j, x) in row.iter().enumerate() {
                    m.set(i, j, k.from_i64(*x));
                }
            }
            m
        };
        let (m, p) = (all.ninputs(), all.noutputs());
        let routing = Routing {
            k: mat(&self.r.0, m, p),
            e: mat(&self.r.1, m, self.r.1.first().map_or(0, Vec::len)),
            f: mat(&self.r.2, self.r.2.len(), p),
        };
        let closed = close(&all, &routing).map_err(e)?;
        let points: Vec<K::Elem> = [3, -7, 11, 5]
            .iter()
            .map(|x| {
                k.div(&k.from_i64(*x), &k.from_i64(2))
                    .unwrap_or_else(|| k.zero())
            })
            .collect();
        if !routing_holds(&all, &routing, &closed, &points) {
            return Err(Failure::verification(
                "interconnect: the exact check F (I - G K)^-1 G E failed".into(),
            ));
        }
        let typed = TypedSystem {
            descriptor: None,
            a_raw: closed.a.clone(),
            ss: closed,
        };
        Ok(System::from_ground("interconnect", typed))
    }
}
