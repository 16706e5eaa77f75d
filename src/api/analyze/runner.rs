//! The sections of one `analyze` report, each computed under its own budget.
//!
//! [`Sections::run`] runs one piece of exact work in its own thread ([`Budget::run`]); a piece
//! that runs out of time or fails is reported in place (`skipped` with the reason and the
//! command that insists, or `error` with the reason), never dropped, and the report goes on.
//! [`Sections::push`] adds a finished section and streams it (text mode prints it at once).

use crate::api::budget::{Budget, Event, Events, Ran};
use crate::report::{Report, Value};

/// How a section is computed on its own, to insist when `analyze` skipped it.
#[derive(Clone, Copy, Debug)]
pub enum Insist {
    /// `exactlti <command> FILE`.
    Command(&'static str),
    /// Only inside `analyze`: `exactlti analyze FILE --section-seconds 600`.
    Analyze,
}

/// One section of the table: its title, the command that insists, and the checked work
/// (whether its exact check held, and its report).
pub struct Section {
    pub title: &'static str,
    pub insist: Insist,
    pub work: Box<dyn FnOnce() -> crate::Result<(bool, Report)> + Send>,
}

impl Section {
    pub fn new(
        title: &'static str,
        insist: Insist,
        work: impl FnOnce() -> crate::Result<(bool, Report)> + Send + 'static,
    ) -> Self {
        Section {
            title,
            insist,
            work: Box::new(work),
        }
    }
}

/// The report under construction.
pub struct Sections<'a> {
    pub report: Report,
    /// The conjunction of every exact check made.
    pub verified: bool,
    budget: &'a Budget,
    events: &'a Events,
    /// The file as typed (for the commands that insist); `None` for the built-in example.
    file: Option<String>,
    /// Pieces of work that finished.
    pub done: usize,
    /// Titles of the sections skipped because `--max-seconds` (the whole bound) ran out.
    pub cut: Vec<String>,
    /// Items sent to `events` (the title goes with the first).
    streamed: usize,
}

impl<'a> Sections<'a> {
    pub fn new(
        report: Report,
        budget: &'a Budget,
        events: &'a Events,
        file: Option<String>,
    ) -> Self {
        Sections {
            streamed: 0,
            report,
            verified: true,
            budget,
            events,
            file,
            done: 0,
            cut: vec![],
        }
    }

    /// Adds a finished section and streams what is ready: nothing before some work is done
    /// (a report cut by `--max-seconds` before any section finished is not printed).
    pub fn push(&mut self, key: &str, v: Value) {
        let v = crate::report::numbers::unify(v);
        // compact text: a few lines per section (`--full`: all of it; JSON: unchanged)
        self.report
            .push(key, crate::report::summary::analyze_section(key, v));
        let Some(tx) = self.events else { return };
        if self.done == 0 {
            return;
        }
        if self.streamed == 0
            && let Some(t) = &self.report.title
        {
            let _ = tx.send(Event::Title(t.clone()));
        }
        for (k, v) in &self.report.items[self.streamed..] {
            let _ = tx.send(Event::Item(k.clone(), v.clone()));
        }
        self.streamed = self.report.items.len();
    }

    /// Runs `work` within the budget: its result, or the section to report in its place
    /// (titled `title`).
    pub fn run<T: Send + 'static>(
        &mut self,
        title: &str,
        insist: Insist,
        work: impl FnOnce() -> T + Send + 'static,
    ) -> Result<T, Value> {
        if let Some(tx) = self.events {
            let _ = tx.send(Event::Working(title.to_string()));
        }
        match self.budget.run(work) {
            Ran::Done(v) => {
                self.done += 1;
                Ok(v)
            }
            Ran::OutOfTime { seconds, whole } => {
                if whole {
                    self.cut.push(title.to_string());
                }
                Err(self.skipped(title, insist, seconds, whole))
            }
            Ran::Panicked => Err(failed_msg(
                title,
                "internal failure: the computation panicked (please report it)",
            )),
        }
    }

    /// Runs checked `work` within the budget: its report (its check joins
    /// [`Sections::verified`]) or the section reported in its place; `Err` is the work's own
    /// error, for the caller to word.
    pub fn checked(
        &mut self,
        title: &str,
        insist: Insist,
        work: impl FnOnce() -> crate::Result<(bool, Report)> + Send + 'static,
    ) -> crate::Result<Value> {
        match self.run(title, insist, work) {
            Ok(Ok((ok, rep))) => {
                self.verified &= ok;
                Ok(Value::Obj(rep))
            }
            Ok(Err(e)) => Err(e),
            Err(v) => Ok(v),
        }
    }

    /// [`Sections::checked`], a failure reported in place (`error`), the section pushed
    /// under `key`.
    pub fn section(&mut self, key: &str, s: Section) {
        let v = self
            .checked(s.title, s.insist, s.work)
            .unwrap_or_else(|e| failed_msg(s.title, &e.to_string()));
        self.push(key, v);
    }

    /// The report of a section that ran out of time.
    fn skipped(&self, title: &str, insist: Insist, seconds: f64, whole: bool) -> Value {
        let file = self.file.as_deref();
        let cmd = match (insist, file) {
            (Insist::Command(c), Some(f)) => format!("exactlti {c} {f} --max-seconds 600"),
            (Insist::Analyze, Some(f)) => {
                format!("exactlti analyze {f} --section-seconds 600 --max-seconds 3600")
            }
            (_, None) => "exactlti analyze --section-seconds 600 --max-seconds 3600".to_string(),
        };
        let reason = match (whole, self.budget.max_seconds) {
            (true, Some(m)) => format!("--max-seconds {m} (the bound of the whole report) ran out"),
            _ => format!(
                "its budget of {} s (--section-seconds) ran out",
                self.budget.section_seconds
            ),
        };
        Value::Obj(
            Report::titled(title)
                .str(
                    "skipped",
                    format!("after {}; run `{cmd}` to insist", fmt_seconds(seconds)),
                )
                .str("reason", reason),
        )
    }
}

/// `10 s`, `0.5 s`.
fn fmt_seconds(s: f64) -> String {
    if s >= 9.5 {
        format!("{s:.0} s")
    } else {
        format!("{s:.1} s")
    }
}

/// A section that failed: the title and the reason.
pub fn failed_msg(title: &str, why: &str) -> Value {
    Value::Obj(Report::titled(title).str("error", why))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn skipped_sections_say_why_and_how_to_insist() {
        let b = Budget {
            section_seconds: 0.01,
            ..Budget::default()
        };
        let ev = None;
        let mut s = Sections::new(Report::titled("t"), &b, &ev, Some("f.json".into()));
        let (tx, rx) = std::sync::mpsc::channel::<()>();
        let r = s.run("Jordan form", Insist::Command("jordan --real"), move || {
            rx.recv().is_ok()
        });
        drop(tx);
        let Err(Value::Obj(v)) = r else {
            panic!("{r:?}")
        };
        let Some(Value::Str(t)) = v.get("skipped") else {
            panic!("{v:?}")
        };
        assert!(
            t.contains("run `exactlti jordan --real f.json --max-seconds 600` to insist"),
            "{t}"
        );
        assert!(matches!(v.get("reason"), Some(Value::Str(r)) if r.contains("--section-seconds")));
        assert_eq!(s.done, 0);
        assert!(s.cut.is_empty());
        let long = Budget::default();
        let mut s = Sections::new(Report::titled("t"), &long, &ev, None);
        assert_eq!(s.run("x", Insist::Analyze, || 3).unwrap_or(0), 3);
        assert_eq!(s.done, 1);
    }
}
