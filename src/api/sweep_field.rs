//! `sweep` of a system whose entries lie in an extension field ($\mathbb{Q}(\sqrt d)$,
//! $\mathbb{Q}(i)$): at each value $v$ of the parameter the system is read again from its
//! text with $v$ given (the one reader, [`System::with_values`]: the decimal that prints
//! $v$, an exact rational) and typed over its field $K$; the eigenvalues of $A(v)$ are then
//! computed in floating point, complex ones for a non-real $A(v)$ (complex Schur). A
//! descriptor system gives the finite eigenvalues of its pencil (the standard form's $A$)
//! and counts the infinite ones; a value where the system cannot be read (a pole, a
//! singular mass matrix, a pencil that is not regular) has no eigenvalues and a note.

use super::Failure;
use super::common::with_path;
use super::system::{System, SystemVisitor};
use crate::float::{to_cmatrix, to_dmatrix};
use crate::io::{SystemFile, TypedSystem};
use crate::realization::SystemField;
use crate::study::{PointStatus, SweepResult};
use num_complex::Complex;

/// The family $v \mapsto$ the system read with the parameter `param` $= v$.
pub struct FieldFamily<'a> {
    pub sys: &'a System,
    pub param: &'a str,
}

impl<'a> FieldFamily<'a> {
    /// The family of `sys` along `param`, which must be a parameter of the file.
    ///
    /// # Errors
    /// `param` names no parameter of the file (the message lists those it has).
    pub fn new(sys: &'a System, param: &'a str) -> Result<Self, Failure> {
        let f = sys.file();
        let names: Vec<&str> = f.parameters.iter().map(|(n, _)| n.as_str()).collect();
        if !names.contains(&param) {
            let has = if names.is_empty() {
                "the file has no parameters".to_string()
            } else {
                format!("the file has: {}", names.join(", "))
            };
            return Err(Failure::input(format!(
                "{}: key parameters: no parameter '{param}' to vary ({has})",
                f.path
            )));
        }
        Ok(FieldFamily { sys, param })
    }

    /// The number of states of the system as read (the columns of the CSV).
    pub fn dim(&self) -> usize {
        self.sys.run(Dim)
    }

    /// The system's `name`.
    pub fn name(&self) -> Option<String> {
        self.sys.file().name.clone()
    }

    /// The eigenvalues at each of `values`, sorted by (real, imaginary) part.
    ///
    /// # Errors
    /// A failure of the float eigenvalue computation other than at one point.
    pub fn sweep(&self, values: &[f64], tick: &dyn Fn(usize)) -> Result<SweepResult, Failure> {
        let mut out = SweepResult {
            param: self.param.to_string(),
            values: values.to_vec(),
            eigenvalues: vec![],
            status: vec![],
        };
        for (k, v) in values.iter().enumerate() {
            tick(k);
            let (ev, st) = match self.sys.with_values(&[(self.param.into(), format!("{v}"))]) {
                Ok(s) => s.run(Eigen)?,
                Err(_) => (vec![], PointStatus::Failed),
            };
            out.eigenvalues.push(ev);
            out.status.push(st);
        }
        Ok(out)
    }
}

struct Dim;

impl SystemVisitor for Dim {
    type Output = usize;
    fn visit<K: SystemField>(self, _f: &SystemFile, t: &TypedSystem<K>) -> usize {
        t.descriptor
            .as_ref()
            .map_or(t.ss.nstates(), |d| d.e.nrows())
    }
}

/// The float eigenvalues of one system (finite ones of a descriptor system).
struct Eigen;

impl SystemVisitor for Eigen {
    type Output = Result<(Vec<Complex<f64>>, PointStatus), Failure>;
    fn visit<K: SystemField>(self, f: &SystemFile, t: &TypedSystem<K>) -> Self::Output {
        let path = std::path::Path::new(&f.path);
        let a = &t.ss.a;
        let mut ev = match to_dmatrix(a) {
            Ok(_) if a.nrows() == 0 => vec![],
            Ok(r) => crate::float::eigenvalues(&r).map_err(|e| with_path(path, e))?,
            Err(_) => {
                let c = to_cmatrix(a).map_err(|e| with_path(path, e))?;
                match c.eigenvalues() {
                    Some(v) => v.iter().copied().collect(),
                    None => return Ok((vec![], PointStatus::Failed)),
                }
            }
        };
        if ev.iter().any(|z| !(z.re.is_finite() && z.im.is_finite())) {
            return Ok((vec![], PointStatus::Failed));
        }
        ev.sort_by(|x, y| {
            (x.re, x.im)
                .partial_cmp(&(y.re, y.im))
                .unwrap_or(std::cmp::Ordering::Equal)
        });
        let st = match &t.descriptor {
            Some(d) if d.e.nrows() > a.nrows() => PointStatus::Descriptor {
                infinite: d.e.nrows() - a.nrows(),
            },
            _ => PointStatus::Regular,
        };
        Ok((ev, st))
    }
}
