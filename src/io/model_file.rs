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

use super::raw::{Raw, from_json_text, from_toml_text};
use super::subst::{Substitution, SymbolicOptions};
use super::{Ground, InputError, SystemFormat};
use crate::field::{Field, Q};
use crate::matrix::Matrix;
use crate::multibody::{Body, LineItem, LineKind, Load, Model, PointItem, PointKind, Vec3};
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
    let raw = match format {
        SystemFormat::Json => from_json_text(text, ""),
        SystemFormat::Toml => from_toml_text(text, ""),
    };
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
    let raw = match format {
        SystemFormat::Json => from_json_text(text, name)?,
        SystemFormat::Toml => from_toml_text(text, name)?,
    };
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
            let (x, _) = super::eval_expr(&text, &[], &Ground::Rational).map_err(|e| e.msg)?;
            x.to_rational()
                .ok_or_else(|| "expected a rational number".to_string())
        };
        return Ok(ModelAny::Rational(build(name, &top, &Q, &eval)?));
    }
    let vars: Vec<&str> = symbols.iter().map(String::as_str).collect();
    let k =
        RatFuncField::new(&vars).map_err(|e| InputError::key(name, "symbols", e.to_string()))?;
    let eval = |t: &str| {
        let text = subst.apply(t)?;
        k.parse(&text).map_err(|e| e.to_string())
    };
    Ok(ModelAny::RatFunc(build(name, &top, &k, &eval)?))
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
    let known = |n: &str, params: &[(String, Option<String>)]| params.iter().any(|(p, _)| p == n);
    match &opts.symbolic {
        Some(list) if list.is_empty() => symbols.extend(params.iter().map(|(n, _)| n.clone())),
        Some(list) => {
            for n in list {
                if !known(n, &params) {
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
    for (n, v) in &opts.at {
        if !known(n, &params) && !symbols.contains(n) {
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
    let valued = params
        .into_iter()
        .filter(|(n, _)| !symbols.contains(n))
        .filter_map(|(n, v)| v.map(|v| (n, v)))
        .collect();
    Ok((valued, symbols))
}

/// Reading context: the file, the field and the scalar evaluator.
struct Reader<'a, K: Field> {
    file: &'a str,
    k: &'a K,
    eval: &'a dyn Fn(&str) -> Result<K::Elem, String>,
    bodies: Vec<String>,
}

type Table = [(String, Raw)];

impl<K: Field> Reader<'_, K> {
    fn err(&self, key: &str, msg: impl Into<String>) -> InputError {
        InputError::key(self.file, key, msg)
    }
    fn get<'t>(&self, t: &'t Table, key: &str) -> Option<&'t Raw> {
        t.iter().find(|(k, _)| k == key).map(|(_, v)| v)
    }
    fn check(&self, t: &Table, at: &str, allowed: &[&str]) -> Result<(), InputError> {
        match t
            .iter()
            .find(|(k, _)| !allowed.contains(&k.as_str()) && k != "name" && k != "description")
        {
            Some((k, _)) => Err(self.err(&format!("{at}.{k}"), "unknown key")),
            None => Ok(()),
        }
    }
    fn scalar_raw(&self, v: &Raw, at: &str) -> Result<K::Elem, InputError> {
        match v {
            Raw::Number(s) | Raw::Str(s) => (self.eval)(s).map_err(|e| self.err(at, e)),
            other => Err(self.err(
                at,
                format!("expected a number or an expression, found {}", other.kind()),
            )),
        }
    }
    fn scalar(
        &self,
        t: &Table,
        at: &str,
        key: &str,
        default: Option<K::Elem>,
    ) -> Result<K::Elem, InputError> {
        match (self.get(t, key), default) {
            (Some(v), _) => self.scalar_raw(v, &format!("{at}.{key}")),
            (None, Some(d)) => Ok(d),
            (None, None) => Err(self.err(&format!("{at}.{key}"), "missing")),
        }
    }
    fn list<'t>(&self, v: &'t Raw, at: &str, n: Option<usize>) -> Result<&'t [Raw], InputError> {
        match v {
            Raw::Array(xs) if n.is_none_or(|n| xs.len() == n) => Ok(xs),
            other => Err(self.err(
                at,
                format!(
                    "expected {}, found {}",
                    n.map_or("a list".to_string(), |n| format!("a list of {n}")),
                    match other {
                        Raw::Array(xs) => format!("a list of {}", xs.len()),
                        o => o.kind().to_string(),
                    }
                ),
            )),
        }
    }
    fn vec3_raw(&self, v: &Raw, at: &str) -> Result<Vec3<K>, InputError> {
        let xs = self.list(v, at, Some(3))?;
        Ok([
            self.scalar_raw(&xs[0], at)?,
            self.scalar_raw(&xs[1], at)?,
            self.scalar_raw(&xs[2], at)?,
        ])
    }
    fn vec3(&self, t: &Table, at: &str, key: &str, default: bool) -> Result<Vec3<K>, InputError> {
        match self.get(t, key) {
            Some(v) => self.vec3_raw(v, &format!("{at}.{key}")),
            None if default => Ok([self.k.zero(), self.k.zero(), self.k.zero()]),
            None => Err(self.err(&format!("{at}.{key}"), "missing")),
        }
    }
    fn name(&self, t: &Table, at: &str) -> Result<String, InputError> {
        match self.get(t, "name") {
            Some(Raw::Str(s)) => Ok(s.clone()),
            Some(other) => Err(self.err(
                &format!("{at}.name"),
                format!("expected a string, found {}", other.kind()),
            )),
            None => Ok(at.to_string()),
        }
    }
    fn body_index(&self, s: &Raw, at: &str) -> Result<usize, InputError> {
        let Raw::Str(s) = s else {
            return Err(self.err(at, "expected a body name"));
        };
        if s == "ground" {
            return Ok(self.bodies.len());
        }
        self.bodies
            .iter()
            .position(|b| b == s)
            .ok_or_else(|| self.err(at, format!("unknown body '{s}'")))
    }
    fn two_bodies(&self, t: &Table, at: &str) -> Result<[usize; 2], InputError> {
        let key = format!("{at}.bodies");
        let v = self
            .get(t, "bodies")
            .ok_or_else(|| self.err(&key, "missing"))?;
        let xs = self.list(v, &key, Some(2))?;
        Ok([
            self.body_index(&xs[0], &key)?,
            self.body_index(&xs[1], &key)?,
        ])
    }
    fn small(
        &self,
        t: &Table,
        at: &str,
        key: &str,
        max: u8,
        default: u8,
    ) -> Result<u8, InputError> {
        match self.get(t, key) {
            None => Ok(default),
            Some(Raw::Number(s)) => s.parse::<u8>().ok().filter(|n| *n <= max).ok_or_else(|| {
                self.err(
                    &format!("{at}.{key}"),
                    format!("expected an integer from 0 to {max}"),
                )
            }),
            Some(o) => Err(self.err(
                &format!("{at}.{key}"),
                format!("expected an integer, found {}", o.kind()),
            )),
        }
    }
    fn flag(&self, t: &Table, at: &str, key: &str) -> Result<bool, InputError> {
        match self.get(t, key) {
            None => Ok(false),
            Some(Raw::Other { json, .. }) if json.is_boolean() => Ok(json.as_bool() == Some(true)),
            Some(o) => Err(self.err(
                &format!("{at}.{key}"),
                format!("expected true or false, found {}", o.kind()),
            )),
        }
    }
    /// `[force, moment]` from a number or a list of two.
    fn pair(&self, t: &Table, at: &str, key: &str) -> Result<[K::Elem; 2], InputError> {
        let at = format!("{at}.{key}");
        match self.get(t, key) {
            None => Ok([self.k.zero(), self.k.zero()]),
            Some(Raw::Array(xs)) if xs.len() == 2 => {
                Ok([self.scalar_raw(&xs[0], &at)?, self.scalar_raw(&xs[1], &at)?])
            }
            Some(v @ (Raw::Number(_) | Raw::Str(_))) => {
                Ok([self.scalar_raw(v, &at)?, self.k.zero()])
            }
            Some(o) => Err(self.err(
                &at,
                format!("expected a number or [force, moment], found {}", o.kind()),
            )),
        }
    }
    fn locations(&self, t: &Table, at: &str) -> Result<[Vec3<K>; 2], InputError> {
        let key = format!("{at}.locations");
        let v = self
            .get(t, "locations")
            .ok_or_else(|| self.err(&key, "missing"))?;
        let xs = self.list(v, &key, Some(2))?;
        Ok([self.vec3_raw(&xs[0], &key)?, self.vec3_raw(&xs[1], &key)?])
    }
}

fn items<'t>(file: &str, top: &'t Table, key: &str) -> Result<Vec<&'t Table>, InputError> {
    let Some((_, v)) = top.iter().find(|(k, _)| k == key) else {
        return Ok(vec![]);
    };
    let Raw::Array(xs) = v else {
        return Err(InputError::key(
            file,
            key,
            format!("expected a list of tables, found {}", v.kind()),
        ));
    };
    xs.iter()
        .enumerate()
        .map(|(i, x)| match x {
            Raw::Table(t) => Ok(t.as_slice()),
            o => Err(InputError::key(
                file,
                &format!("{key}[{}]", i + 1),
                format!("expected a table, found {}", o.kind()),
            )),
        })
        .collect()
}

fn build<K: Field>(
    file: &str,
    top: &Table,
    k: &K,
    eval: &dyn Fn(&str) -> Result<K::Elem, String>,
) -> Result<Model<K>, InputError> {
    let mut r = Reader {
        file,
        k,
        eval,
        bodies: vec![],
    };
    let name = match top.iter().find(|(x, _)| x == "name") {
        Some((_, Raw::Str(s))) => Some(s.clone()),
        _ => None,
    };
    let mut m = Model {
        field: k.clone(),
        name,
        bodies: vec![],
        points: vec![],
        lines: vec![],
        loads: vec![],
    };
    for (i, t) in items(file, top, "bodies")?.into_iter().enumerate() {
        let at = format!("bodies[{}]", i + 1);
        let b = body(&r, t, &at)?;
        if b.name == "ground" || r.bodies.contains(&b.name) {
            return Err(r.err(
                &format!("{at}.name"),
                format!("'{}' is the ground or already a body", b.name),
            ));
        }
        r.bodies.push(b.name.clone());
        m.bodies.push(b);
    }
    if m.bodies.is_empty() {
        return Err(r.err("bodies", "a model needs at least one body"));
    }
    for (key, kind) in [
        ("rigid_points", PointKind::Rigid),
        ("flex_points", PointKind::Flexible),
        ("nh_points", PointKind::Nonholonomic),
    ] {
        for (i, t) in items(file, top, key)?.into_iter().enumerate() {
            m.points
                .push(point(&r, t, &format!("{key}[{}]", i + 1), kind)?);
        }
    }
    for key in ["springs", "links", "actuators", "sensors"] {
        for (i, t) in items(file, top, key)?.into_iter().enumerate() {
            let at = format!("{key}[{}]", i + 1);
            let l = line(&r, t, &at, key, &m)?;
            m.lines.push(l);
        }
    }
    loads(&r, top, &mut m)?;
    Ok(m)
}

fn body<K: Field>(r: &Reader<'_, K>, t: &Table, at: &str) -> Result<Body<K>, InputError> {
    r.check(
        t,
        at,
        &[
            "mass",
            "location",
            "inertia",
            "velocity",
            "angular_velocity",
        ],
    )?;
    let k = r.k;
    let inertia = match r.get(t, "inertia") {
        None => Matrix::zeros(k.clone(), 3, 3),
        Some(v) => {
            let key = format!("{at}.inertia");
            let xs = r.list(v, &key, None)?;
            if xs.len() != 3 && xs.len() != 6 {
                return Err(r.err(
                    &key,
                    "expected [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Iyz, Izx]",
                ));
            }
            let e: Vec<K::Elem> = xs
                .iter()
                .map(|x| r.scalar_raw(x, &key))
                .collect::<Result<_, _>>()?;
            let p = |i: usize| e.get(i).map_or_else(|| k.zero(), |x| k.neg(x));
            let (xy, yz, zx) = (p(3), p(4), p(5));
            Matrix::from_vec(
                k.clone(),
                3,
                3,
                vec![
                    e[0].clone(),
                    xy.clone(),
                    zx.clone(),
                    xy,
                    e[1].clone(),
                    yz.clone(),
                    zx,
                    yz,
                    e[2].clone(),
                ],
            )
        }
    };
    Ok(Body {
        name: r.name(t, at)?,
        mass: r.scalar(t, at, "mass", Some(k.zero()))?,
        location: r.vec3(t, at, "location", false)?,
        inertia,
        velocity: r.vec3(t, at, "velocity", true)?,
        angular_velocity: r.vec3(t, at, "angular_velocity", true)?,
    })
}

fn point<K: Field>(
    r: &Reader<'_, K>,
    t: &Table,
    at: &str,
    kind: PointKind,
) -> Result<PointItem<K>, InputError> {
    r.check(
        t,
        at,
        &[
            "bodies",
            "location",
            "forces",
            "moments",
            "axis",
            "rolling_axis",
            "stiffness",
            "damping",
        ],
    )?;
    if kind != PointKind::Flexible
        && (r.get(t, "stiffness").is_some() || r.get(t, "damping").is_some())
    {
        return Err(r.err(
            &format!("{at}.stiffness"),
            "only flexible points have stiffness and damping",
        ));
    }
    let forces = r.small(t, at, "forces", 3, 0)?;
    let moments = r.small(t, at, "moments", 3, 0)?;
    let needs_axis = [forces, moments].iter().any(|n| *n == 1 || *n == 2);
    let axis = r.vec3(t, at, "axis", !needs_axis)?;
    if needs_axis && axis.iter().all(|x| r.k.is_zero(x)) {
        return Err(r.err(&format!("{at}.axis"), "must be non-zero"));
    }
    let rolling_axis = match r.get(t, "rolling_axis") {
        Some(v) => Some(r.vec3_raw(v, &format!("{at}.rolling_axis"))?),
        None => None,
    };
    Ok(PointItem {
        name: r.name(t, at)?,
        kind,
        bodies: r.two_bodies(t, at)?,
        location: r.vec3(t, at, "location", false)?,
        forces,
        moments,
        axis,
        rolling_axis,
        stiffness: r.pair(t, at, "stiffness")?,
        damping: r.pair(t, at, "damping")?,
    })
}

fn line<K: Field>(
    r: &Reader<'_, K>,
    t: &Table,
    at: &str,
    key: &str,
    m: &Model<K>,
) -> Result<LineItem<K>, InputError> {
    let k = r.k;
    let kind = match key {
        "springs" => {
            r.check(
                t,
                at,
                &["bodies", "locations", "stiffness", "damping", "twist"],
            )?;
            LineKind::Spring {
                stiffness: r.scalar(t, at, "stiffness", Some(k.zero()))?,
                damping: r.scalar(t, at, "damping", Some(k.zero()))?,
            }
        }
        "links" => {
            r.check(t, at, &["bodies", "locations"])?;
            LineKind::Link
        }
        "actuators" => {
            r.check(
                t,
                at,
                &["bodies", "locations", "gain", "rate_gain", "twist"],
            )?;
            LineKind::Actuator {
                gain: r.scalar(t, at, "gain", Some(k.one()))?,
                rate_gain: r.scalar(t, at, "rate_gain", Some(k.zero()))?,
            }
        }
        _ => {
            r.check(
                t,
                at,
                &[
                    "bodies",
                    "locations",
                    "gain",
                    "order",
                    "frame",
                    "twist",
                    "actuator",
                    "actuator_gain",
                ],
            )?;
            let gain = r.scalar(t, at, "gain", Some(k.one()))?;
            let local = match r.get(t, "frame") {
                None => false,
                Some(Raw::Str(s)) if s == "global" => false,
                Some(Raw::Str(s)) if s == "local" => true,
                Some(_) => {
                    return Err(r.err(&format!("{at}.frame"), "expected \"global\" or \"local\""));
                }
            };
            let order = r.small(t, at, "order", 2, 1)?;
            if order == 0 {
                return Err(r.err(
                    &format!("{at}.order"),
                    "expected 1 (position) or 2 (velocity)",
                ));
            }
            let actuator = match r.get(t, "actuator") {
                None => None,
                Some(Raw::Str(s)) => {
                    let i = m.actuators().position(|a| &a.name == s).ok_or_else(|| {
                        r.err(
                            &format!("{at}.actuator"),
                            format!("unknown actuator '{s}' (actuators come before sensors)"),
                        )
                    })?;
                    Some((i, r.scalar(t, at, "actuator_gain", Some(gain.clone()))?))
                }
                Some(o) => {
                    return Err(r.err(
                        &format!("{at}.actuator"),
                        format!("expected a name, found {}", o.kind()),
                    ));
                }
            };
            LineKind::Sensor {
                gain,
                order,
                local,
                actuator,
            }
        }
    };
    Ok(LineItem {
        name: r.name(t, at)?,
        kind,
        bodies: r.two_bodies(t, at)?,
        locations: r.locations(t, at)?,
        twist: r.flag(t, at, "twist")?,
    })
}

/// `gravity = [gx, gy, gz]`: a weight `m g` at every body's centre of mass; `[[loads]]`.
fn loads<K: Field>(r: &Reader<'_, K>, top: &Table, m: &mut Model<K>) -> Result<(), InputError> {
    let k = r.k;
    if let Some(v) = r.get(top, "gravity") {
        let g = r.vec3_raw(v, "gravity")?;
        for b in &m.bodies {
            if k.is_zero(&b.mass) || g.iter().all(|x| k.is_zero(x)) {
                continue;
            }
            let force = [
                k.mul(&b.mass, &g[0]),
                k.mul(&b.mass, &g[1]),
                k.mul(&b.mass, &g[2]),
            ];
            m.loads.push(Load {
                name: format!("{} weight", b.name),
                body: r.bodies.iter().position(|x| x == &b.name).unwrap_or(0),
                location: b.location.clone(),
                force,
                moment: [k.zero(), k.zero(), k.zero()],
            });
        }
    }
    for (i, t) in items(r.file, top, "loads")?.into_iter().enumerate() {
        let at = format!("loads[{}]", i + 1);
        r.check(t, &at, &["body", "location", "force", "moment"])?;
        let key = format!("{at}.body");
        let body = r.body_index(
            r.get(t, "body").ok_or_else(|| r.err(&key, "missing"))?,
            &key,
        )?;
        if body >= m.bodies.len() {
            return Err(r.err(&key, "a load acts on a body, not on the ground"));
        }
        let location = match r.get(t, "location") {
            Some(v) => r.vec3_raw(v, &format!("{at}.location"))?,
            None => m.bodies[body].location.clone(),
        };
        m.loads.push(Load {
            name: r.name(t, &at)?,
            body,
            location,
            force: r.vec3(t, &at, "force", true)?,
            moment: r.vec3(t, &at, "moment", true)?,
        });
    }
    Ok(())
}
