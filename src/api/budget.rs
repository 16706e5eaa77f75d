//! Bounded work: a piece of exact work run in its own thread under a time budget.
//!
//! The exact algorithms cannot be interrupted, so a piece of work that runs out of time is
//! abandoned, not stopped: the caller stops waiting at the deadline and goes on, the thread
//! finishes (or not) in the background and its result is dropped; the process exit ends it.
//! `analyze` gives each section such a budget ([`Budget`]): its own share (`--section-seconds`,
//! default 10 s) and never more than what is left of `--max-seconds`.
//!
//! [`Event`]s tell the command line what is going on while a command works (which section
//! runs, which section is done), so that text output streams and a progress line can say
//! what is being computed.

use super::runner::Poll;
use crate::report::Value;
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// What a command reports while it works (read by [`crate::cli::run`]).
#[derive(Debug)]
pub enum Event {
    /// The report's title (text mode prints it first).
    Title(String),
    /// A section starts (shown on the progress line).
    Working(String),
    /// A finished item of the report, in report order (text mode prints it at once).
    Item(String, Value),
}

/// Where events go (none: nothing streams).
pub type Events = Option<mpsc::Sender<Event>>;

/// How a piece of bounded work ended.
#[derive(Debug)]
pub enum Ran<T> {
    Done(T),
    /// Out of time after this many seconds; `whole` when the bound of the whole command
    /// (`--max-seconds`) was the binding one rather than the section's own share.
    OutOfTime {
        seconds: f64,
        whole: bool,
    },
    /// The work panicked (an internal failure; its message went to stderr).
    Panicked,
}

/// The time budget of the pieces of a command.
#[derive(Clone, Debug)]
pub struct Budget {
    /// Each piece's own share in seconds.
    pub section_seconds: f64,
    /// The bound of the whole command (`--max-seconds` from the start), if any.
    pub deadline: Option<Instant>,
    /// `--max-seconds` as given (for messages).
    pub max_seconds: Option<f64>,
}

impl Default for Budget {
    fn default() -> Self {
        Budget {
            section_seconds: DEFAULT_SECTION_SECONDS,
            deadline: None,
            max_seconds: None,
        }
    }
}

/// Default share of one `analyze` section in seconds.
pub const DEFAULT_SECTION_SECONDS: f64 = 10.0;

/// Time kept back from `--max-seconds` so that a command with budgets reports what it has
/// before the hard stop of the whole command.
fn reserve(max_seconds: f64) -> Duration {
    Duration::from_secs_f64((max_seconds * 0.05).min(0.25))
}

impl Budget {
    /// A budget whose whole bound is `max_seconds` from `start` (less a small reserve for
    /// printing).
    pub fn new(section_seconds: f64, start: Instant, max_seconds: f64) -> Self {
        let whole = Duration::from_secs_f64(max_seconds.min(1e7));
        Budget {
            section_seconds,
            deadline: Some(start + whole.saturating_sub(reserve(max_seconds))),
            max_seconds: Some(max_seconds),
        }
    }

    /// The time the next piece may take and whether the whole bound is the binding one;
    /// `None` when the whole bound has passed.
    fn next(&self) -> Option<(Duration, bool)> {
        let own = Duration::from_secs_f64(self.section_seconds.clamp(0.0, 1e7));
        match self.deadline {
            None => Some((own, false)),
            Some(d) => {
                let left = d.checked_duration_since(Instant::now())?;
                if left.is_zero() {
                    None
                } else if left < own {
                    Some((left, true))
                } else {
                    Some((own, false))
                }
            }
        }
    }

    /// Runs `work` in its own thread and waits for it within the budget (see the module
    /// docs: work that runs out of time is abandoned).
    pub fn run<T: Send + 'static>(&self, work: impl FnOnce() -> T + Send + 'static) -> Ran<T> {
        let Some((wait, whole)) = self.next() else {
            return Ran::OutOfTime {
                seconds: 0.0,
                whole: true,
            };
        };
        let start = Instant::now();
        let Ok(w) = super::runner::Worker::spawn("exactlti-section", Some(start + wait), work)
        else {
            return Ran::Panicked;
        };
        match w.wait() {
            // a result that arrives after the whole bound (this thread was not scheduled in
            // time) is not used: the bound holds however the threads are scheduled
            Poll::Done(_) if whole && self.deadline.is_some_and(|d| Instant::now() > d) => {
                Ran::OutOfTime {
                    seconds: start.elapsed().as_secs_f64(),
                    whole,
                }
            }
            Poll::Done(v) => Ran::Done(v),
            Poll::TimedOut | Poll::Pending => Ran::OutOfTime {
                seconds: start.elapsed().as_secs_f64(),
                whole,
            },
            Poll::Panicked(_) => Ran::Panicked,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn done_out_of_time_and_panicked() {
        let b = Budget {
            section_seconds: 5.0,
            ..Budget::default()
        };
        assert!(matches!(b.run(|| 2 + 2), Ran::Done(4)));
        let (tx, rx) = mpsc::channel::<()>();
        let short = Budget {
            section_seconds: 0.01,
            ..Budget::default()
        };
        // blocked until the test ends: abandoned, not waited for
        let r = short.run(move || rx.recv().is_ok());
        assert!(matches!(r, Ran::OutOfTime { whole: false, .. }), "{r:?}");
        drop(tx);
        let r = b.run(|| -> u8 { std::panic::panic_any("expected in this test") });
        assert!(matches!(r, Ran::Panicked));
        // the whole bound passed: nothing runs
        let past = Budget::new(5.0, Instant::now() - Duration::from_secs(2), 1.0);
        assert!(matches!(
            past.run(|| 1),
            Ran::OutOfTime {
                whole: true,
                seconds: 0.0
            }
        ));
    }
}
