//! The worker thread with a deadline: the one place where a computation is run off the
//! caller's thread (256 MiB stack, a panic caught and turned into a message) and waited for
//! at most until a deadline.
//!
//! The exact algorithms cannot be interrupted, so work past its deadline is abandoned, not
//! stopped: the caller stops waiting and goes on, the thread finishes (or not) in the
//! background and its result is dropped. The command line ([`crate::cli::run`], bounded by
//! `--max-seconds`), the sections of `analyze` ([`super::budget::Budget`]) and the Python
//! package (bounded by `max_seconds`, polling for Ctrl-C between waits) all wait this way.
//!
//! # Examples
//! ```
//! use exactlti::api::runner::{Poll, Worker};
//! use std::time::Duration;
//! let w = Worker::spawn("sum", None, || (1..=10).sum::<u32>()).unwrap();
//! let got = loop {
//!     match w.poll(Duration::from_millis(10)) {
//!         Poll::Pending => continue,
//!         other => break other,
//!     }
//! };
//! assert!(matches!(got, Poll::Done(55)));
//! ```

use std::sync::{Mutex, mpsc};
use std::time::{Duration, Instant};

/// Stack of a worker thread (deep recursion in the exact kernels on large inputs).
pub const WORKER_STACK: usize = 256 << 20;

/// A computation running on its own thread.
#[derive(Debug)]
pub struct Worker<T> {
    rx: Mutex<mpsc::Receiver<std::thread::Result<T>>>,
    deadline: Option<Instant>,
}

/// What a wait on a [`Worker`] found.
#[derive(Debug)]
pub enum Poll<T> {
    /// The work finished with this result.
    Done(T),
    /// The work panicked (the panic's message; the process's panic hook has run).
    Panicked(String),
    /// Still working; the deadline has not passed.
    Pending,
    /// The deadline passed before the work finished (the work is abandoned).
    TimedOut,
}

impl<T: Send + 'static> Worker<T> {
    /// Starts `work` on a thread named `name`; `deadline`: when [`Worker::poll`] gives up.
    ///
    /// # Errors
    /// The thread could not be started (the message says so).
    pub fn spawn(
        name: &str,
        deadline: Option<Instant>,
        work: impl FnOnce() -> T + Send + 'static,
    ) -> Result<Self, String> {
        let (tx, rx) = mpsc::channel();
        std::thread::Builder::new()
            .name(name.into())
            .stack_size(WORKER_STACK)
            .spawn(move || {
                let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(work));
                let _ = tx.send(r);
            })
            .map_err(|_| "could not start the worker thread".to_string())?;
        Ok(Worker {
            rx: Mutex::new(rx),
            deadline,
        })
    }

    /// A deadline `seconds` from now (`None` for no bound: not finite or not positive).
    pub fn deadline_in(seconds: Option<f64>) -> Option<Instant> {
        seconds
            .filter(|s| s.is_finite() && *s > 0.0)
            .map(|s| Instant::now() + Duration::from_secs_f64(s.min(1e7)))
    }

    /// Waits at most `wait` (and never past the deadline) for the result.
    pub fn poll(&self, wait: Duration) -> Poll<T> {
        let wait = match self.deadline {
            None => wait,
            Some(d) => match d.checked_duration_since(Instant::now()) {
                Some(left) if !left.is_zero() => wait.min(left),
                _ => return Poll::TimedOut,
            },
        };
        let Ok(rx) = self.rx.lock() else {
            return Poll::Panicked("the worker's channel is poisoned".into());
        };
        match rx.recv_timeout(wait) {
            Ok(Ok(v)) => Poll::Done(v),
            Ok(Err(panic)) => Poll::Panicked(panic_message(panic.as_ref())),
            Err(mpsc::RecvTimeoutError::Timeout) => match self.deadline {
                Some(d) if Instant::now() >= d => Poll::TimedOut,
                _ => Poll::Pending,
            },
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                Poll::Panicked("the worker thread stopped".into())
            }
        }
    }

    /// Waits until the work finishes or the deadline passes (no deadline: until it finishes).
    pub fn wait(&self) -> Poll<T> {
        loop {
            match self.poll(Duration::from_millis(100)) {
                Poll::Pending => continue,
                other => return other,
            }
        }
    }
}

/// The text of a panic's payload (`&str` or `String`; otherwise empty).
pub fn panic_message(p: &(dyn std::any::Any + Send)) -> String {
    p.downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| p.downcast_ref::<String>().cloned())
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn done_panicked_and_timed_out() {
        let w = Worker::spawn("t", None, || 2 + 2).unwrap();
        assert!(matches!(w.wait(), Poll::Done(4)));
        let w = Worker::spawn("t", None, || -> u8 {
            std::panic::panic_any("expected here")
        })
        .unwrap();
        assert!(matches!(w.wait(), Poll::Panicked(m) if m == "expected here"));
        let (tx, rx) = mpsc::channel::<()>();
        let d = Worker::<bool>::deadline_in(Some(0.02));
        // blocked until the sender drops: abandoned at the deadline, not waited for
        let w = Worker::spawn("t", d, move || rx.recv().is_ok()).unwrap();
        assert!(matches!(w.wait(), Poll::TimedOut));
        drop(tx);
        assert!(Worker::<u8>::deadline_in(Some(f64::NAN)).is_none());
        assert!(Worker::<u8>::deadline_in(Some(-1.0)).is_none());
    }
}
