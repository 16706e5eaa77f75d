//! The items of a model file (bodies, rigid, flexible and nonholonomic points, springs,
//! links, actuators, sensors, loads and gravity) read into a [`Model`] over the field of
//! the [`Reader`].

use super::super::InputError;
use super::super::raw::Raw;
use super::reader::{Reader, Table};
use crate::field::Field;
use crate::matrix::Matrix;
use crate::multibody::{Body, LineItem, LineKind, Load, Model, PointItem, PointKind};

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

pub(super) fn build<K: Field>(
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
            let order = r.small(t, at, "order", 3, 1)?;
            if order == 0 {
                return Err(r.err(
                    &format!("{at}.order"),
                    "expected 1 (position), 2 (velocity) or 3 (acceleration)",
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
