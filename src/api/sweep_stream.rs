//! Row-by-row output of long sweeps (more than [`super::sweep::STREAM_POINTS`] points): the
//! report on stdout and the CSV file are written as the rows are computed, so that memory
//! stays bounded by one batch whatever `--points` is.
//!
//! JSON: the fields of the in-memory report (`param`, `points`, `values`,
//! `eigenvalues_approx`, `stable_points`) in one object, `stable_points` last (it is known at
//! the end) and `"streamed": true`. Text: the same items, one row of `eigenvalues_approx` per
//! line. A reader that went away (broken pipe) ends the output quietly.

use super::Failure;
use num_complex::Complex;
use std::io::{BufWriter, Write};
use std::path::Path;

fn failure(what: &str, e: &std::io::Error) -> Failure {
    Failure::input(format!("{what}: cannot write: {e}"))
}

fn json_num(x: f64) -> String {
    serde_json::Number::from_f64(x).map_or_else(|| "null".into(), |n| n.to_string())
}

/// The report written to stdout as it is computed.
pub struct Sink {
    out: BufWriter<std::io::Stdout>,
    json: bool,
    first: bool,
    /// The reader went away: nothing more is written.
    closed: bool,
}

impl Sink {
    /// Writes the head of the report (title, `param`, `points`, `values`).
    ///
    /// # Errors
    /// A write error other than a broken pipe.
    pub fn start(json: bool, title: &str, param: &str, values: &[f64]) -> Result<Self, Failure> {
        let mut s = Sink {
            out: BufWriter::with_capacity(1 << 16, std::io::stdout()),
            json,
            first: true,
            closed: false,
        };
        let head = if json {
            format!(
                "{{\n  \"param\": {},\n  \"points\": {},\n  \"streamed\": true,\n  \"values\": [",
                serde_json::Value::String(param.into()),
                values.len()
            )
        } else {
            let t = crate::report::escape::escape_control(title);
            let p = crate::report::escape::escape_control(param);
            format!("== {t} ==\nparam: {p}\npoints: {}\nvalues: [", values.len())
        };
        s.put(&head)?;
        for (i, v) in values.iter().enumerate() {
            let sep = if i == 0 { "" } else { ", " };
            let x = if json {
                json_num(*v)
            } else {
                format!("{v:.10}")
            };
            s.put(&format!("{sep}{x}"))?;
        }
        s.put(if json {
            "],\n  \"eigenvalues_approx\": ["
        } else {
            "]\neigenvalues_approx:"
        })?;
        Ok(s)
    }

    fn put(&mut self, text: &str) -> Result<(), Failure> {
        if self.closed {
            return Ok(());
        }
        match self.out.write_all(text.as_bytes()) {
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {
                self.closed = true;
                Ok(())
            }
            r => r.map_err(|e| failure("stdout", &e)),
        }
    }

    /// One row: the eigenvalues at one parameter value.
    ///
    /// # Errors
    /// As [`Sink::start`].
    pub fn row(&mut self, ev: &[Complex<f64>]) -> Result<(), Failure> {
        let cells: Vec<String> = ev
            .iter()
            .map(|z| {
                if self.json {
                    format!("[{}, {}]", json_num(z.re), json_num(z.im))
                } else {
                    format!("[{:.10}, {:.10}]", z.re, z.im)
                }
            })
            .collect();
        let sep = if self.json && !self.first { "," } else { "" };
        self.first = false;
        let line = format!("{sep}\n    [{}]", cells.join(", "));
        self.put(&line)
    }

    /// Writes the tail (the fields `extra`, then `stable_points`) and flushes.
    ///
    /// # Errors
    /// As [`Sink::start`].
    pub fn finish(
        mut self,
        extra: &[(&str, crate::report::Value)],
        stable: usize,
    ) -> Result<(), Failure> {
        let mut tail = String::from(if self.json { "\n  ]" } else { "\n" });
        for (key, v) in extra {
            if matches!(v, crate::report::Value::List(l) if l.is_empty()) {
                continue;
            }
            let json = crate::report::Report::new().with(*key, v.clone()).to_json();
            let v = &json[*key];
            if self.json {
                tail += &format!(",\n  {}: {}", serde_json::Value::String((*key).into()), v);
            } else {
                tail += &format!("{key}: {v}\n");
            }
        }
        tail += &if self.json {
            format!(",\n  \"stable_points\": {stable}\n}}\n")
        } else {
            format!("stable_points: {stable}\n")
        };
        self.put(&tail)?;
        if self.closed {
            return Ok(());
        }
        match self.out.flush() {
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
            r => r.map_err(|e| failure("stdout", &e)),
        }
    }
}

/// The `--csv` file written row by row (parameter value, then re/im of each eigenvalue).
pub struct CsvSink {
    out: BufWriter<std::fs::File>,
    shown: String,
}

impl CsvSink {
    /// Creates the file and writes the header for `n` eigenvalues.
    ///
    /// # Errors
    /// The file cannot be created or written.
    pub fn start(path: &Path, param: &str, n: usize) -> Result<Self, Failure> {
        let shown = path.display().to_string();
        let f = std::fs::File::create(path).map_err(|e| failure(&shown, &e))?;
        let mut s = CsvSink {
            out: BufWriter::with_capacity(1 << 16, f),
            shown,
        };
        let mut head = param.to_string();
        for k in 1..=n {
            head.push_str(&format!(",re{k},im{k}"));
        }
        head.push('\n');
        s.put(&head)?;
        Ok(s)
    }

    fn put(&mut self, text: &str) -> Result<(), Failure> {
        self.out
            .write_all(text.as_bytes())
            .map_err(|e| failure(&self.shown, &e))
    }

    /// One row.
    ///
    /// # Errors
    /// A write error.
    pub fn row(&mut self, v: f64, ev: &[Complex<f64>]) -> Result<(), Failure> {
        let mut line = format!("{v}");
        for z in ev {
            line.push_str(&format!(",{},{}", z.re, z.im));
        }
        line.push('\n');
        self.put(&line)
    }

    /// Flushes the file.
    ///
    /// # Errors
    /// A write error.
    pub fn finish(mut self) -> Result<(), Failure> {
        self.out.flush().map_err(|e| failure(&self.shown, &e))
    }
}
