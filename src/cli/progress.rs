//! What the command line shows while a command works: streamed text sections on stdout and,
//! when stderr is a terminal and the work passes a second, a progress line on stderr
//! (indicatif) naming the section being computed.

use super::budget::Event;
use super::write_stdout;
use crate::report::escape::escape_control_report;
use crate::report::{Report, TextOptions, Value};
use std::io::IsTerminal;
use std::time::Duration;

/// Prints streamed events and keeps the progress line.
pub struct Printer {
    /// `--full`: every matrix of the text in full.
    pub full: bool,
    title: bool,
    items: usize,
    working: Option<String>,
    tty: bool,
    bar: Option<indicatif::ProgressBar>,
}

impl Printer {
    pub fn new(full: bool) -> Self {
        Printer {
            full,
            title: false,
            items: 0,
            working: None,
            tty: std::io::stderr().is_terminal(),
            bar: None,
        }
    }

    /// Whether anything was printed as it came.
    pub fn streamed(&self) -> bool {
        self.title || self.items > 0
    }

    fn write(&self, text: &str) -> std::io::Result<()> {
        match &self.bar {
            Some(b) => b.suspend(|| write_stdout(text)),
            None => write_stdout(text),
        }
    }

    fn text(&self, r: &Report) -> String {
        escape_control_report(r).to_text_with(&TextOptions::cli(self.full))
    }

    /// Handles one event.
    pub fn event(&mut self, ev: Event) -> std::io::Result<()> {
        match ev {
            Event::Title(t) => {
                self.title = true;
                self.write(&self.text(&Report::titled(t)))
            }
            Event::Working(w) => {
                if let Some(b) = &self.bar {
                    b.set_message(w.clone());
                }
                self.working = Some(w);
                Ok(())
            }
            Event::Item(k, v) => {
                self.items += 1;
                self.write(&self.text(&single(k, v)))
            }
        }
    }

    /// The work goes on: after a second, a spinner on a terminal's stderr.
    pub fn tick(&mut self, elapsed: Duration) {
        if !self.tty || elapsed < Duration::from_secs(1) {
            return;
        }
        let bar = self.bar.get_or_insert_with(|| {
            // The clock counts from the start of the command, not from the spinner's first frame.
            let b = indicatif::ProgressBar::new_spinner().with_elapsed(elapsed);
            b.set_style(
                indicatif::ProgressStyle::with_template("{spinner} {elapsed} {msg}")
                    .unwrap_or_else(|_| indicatif::ProgressStyle::default_spinner()),
            );
            b.set_message(self.working.clone().unwrap_or_else(|| "working".into()));
            b
        });
        bar.tick();
    }

    /// Removes the progress line.
    pub fn clear(&mut self) {
        if let Some(b) = self.bar.take() {
            b.finish_and_clear();
        }
    }

    /// Prints the items of the final report that did not stream.
    pub fn rest(&self, r: &Report) -> std::io::Result<()> {
        let mut text = String::new();
        if !self.title
            && let Some(t) = &r.title
        {
            text.push_str(&self.text(&Report::titled(t.clone())));
        }
        for (k, v) in r.items.iter().skip(self.items) {
            text.push_str(&self.text(&single(k.clone(), v.clone())));
        }
        self.write(&text)
    }
}

/// A report of one untitled item.
fn single(k: String, v: Value) -> Report {
    Report {
        title: None,
        items: vec![(k, v)],
    }
}
