//! The reading context of a model file: scalars (numbers or expressions over the
//! parameters, evaluated in the model's field), 3-vectors, body names, small integers and
//! flags, each error naming its key (`springs[2].stiffness`).

use super::super::InputError;
use super::super::raw::Raw;
use crate::field::Field;
use crate::multibody::Vec3;

/// Reading context: the file, the field and the scalar evaluator.
pub(super) struct Reader<'a, K: Field> {
    pub file: &'a str,
    pub k: &'a K,
    pub eval: &'a dyn Fn(&str) -> Result<K::Elem, String>,
    /// The bodies read so far (their index; the ground is `bodies.len()`).
    pub bodies: Vec<String>,
}

/// A table of a model file: its keys and values in file order.
pub(super) type Table = [(String, Raw)];

impl<K: Field> Reader<'_, K> {
    pub fn err(&self, key: &str, msg: impl Into<String>) -> InputError {
        InputError::key(self.file, key, msg)
    }
    pub fn get<'t>(&self, t: &'t Table, key: &str) -> Option<&'t Raw> {
        t.iter().find(|(k, _)| k == key).map(|(_, v)| v)
    }
    pub fn check(&self, t: &Table, at: &str, allowed: &[&str]) -> Result<(), InputError> {
        match t
            .iter()
            .find(|(k, _)| !allowed.contains(&k.as_str()) && k != "name" && k != "description")
        {
            Some((k, _)) => Err(self.err(&format!("{at}.{k}"), "unknown key")),
            None => Ok(()),
        }
    }
    pub fn scalar_raw(&self, v: &Raw, at: &str) -> Result<K::Elem, InputError> {
        match v {
            Raw::Number(s) | Raw::Str(s) => (self.eval)(s).map_err(|e| self.err(at, e)),
            other => Err(self.err(
                at,
                format!("expected a number or an expression, found {}", other.kind()),
            )),
        }
    }
    pub fn scalar(
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
    pub fn list<'t>(
        &self,
        v: &'t Raw,
        at: &str,
        n: Option<usize>,
    ) -> Result<&'t [Raw], InputError> {
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
    pub fn vec3_raw(&self, v: &Raw, at: &str) -> Result<Vec3<K>, InputError> {
        let xs = self.list(v, at, Some(3))?;
        Ok([
            self.scalar_raw(&xs[0], at)?,
            self.scalar_raw(&xs[1], at)?,
            self.scalar_raw(&xs[2], at)?,
        ])
    }
    pub fn vec3(
        &self,
        t: &Table,
        at: &str,
        key: &str,
        default: bool,
    ) -> Result<Vec3<K>, InputError> {
        match self.get(t, key) {
            Some(v) => self.vec3_raw(v, &format!("{at}.{key}")),
            None if default => Ok([self.k.zero(), self.k.zero(), self.k.zero()]),
            None => Err(self.err(&format!("{at}.{key}"), "missing")),
        }
    }
    pub fn name(&self, t: &Table, at: &str) -> Result<String, InputError> {
        match self.get(t, "name") {
            Some(Raw::Str(s)) => Ok(s.clone()),
            Some(other) => Err(self.err(
                &format!("{at}.name"),
                format!("expected a string, found {}", other.kind()),
            )),
            None => Ok(at.to_string()),
        }
    }
    pub fn body_index(&self, s: &Raw, at: &str) -> Result<usize, InputError> {
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
    pub fn two_bodies(&self, t: &Table, at: &str) -> Result<[usize; 2], InputError> {
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
    pub fn small(
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
    pub fn flag(&self, t: &Table, at: &str, key: &str) -> Result<bool, InputError> {
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
    pub fn pair(&self, t: &Table, at: &str, key: &str) -> Result<[K::Elem; 2], InputError> {
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
    pub fn locations(&self, t: &Table, at: &str) -> Result<[Vec3<K>; 2], InputError> {
        let key = format!("{at}.locations");
        let v = self
            .get(t, "locations")
            .ok_or_else(|| self.err(&key, "missing"))?;
        let xs = self.list(v, &key, Some(2))?;
        Ok([self.vec3_raw(&xs[0], &key)?, self.vec3_raw(&xs[1], &key)?])
    }
}
