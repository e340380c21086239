//! Progress on stderr while slow work runs: a spinner with a message, or a percentage bar
//! when the work has a known size (bytes read, builds run). Only on a terminal, and never
//! under `--quiet`: a script and a test see nothing.

use crate::output::{Verbosity, verbosity};
use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::time::Duration;

pub struct Progress(Option<ProgressBar>);

const SPINNER: &str = "{spinner} {msg} {elapsed}";
const BAR: &str = "{msg} [{bar:30}] {percent:>3}% {elapsed}";

impl Progress {
    pub fn new() -> Self {
        if verbosity() == Verbosity::Quiet || !std::io::stderr().is_terminal() {
            return Progress(None);
        }
        let bar = ProgressBar::new_spinner();
        if let Ok(style) = ProgressStyle::with_template(SPINNER) {
            bar.set_style(style);
        }
        bar.enable_steady_tick(Duration::from_millis(120));
        Progress(Some(bar))
    }

    /// A spinner with `msg`.
    pub fn step(&self, msg: String) {
        if let Some(bar) = &self.0 {
            if let Ok(style) = ProgressStyle::with_template(SPINNER) {
                bar.set_style(style);
            }
            bar.set_message(msg);
        }
    }

    /// A percentage bar with `msg`, for `total` units of work, at zero.
    pub fn start(&self, msg: String, total: u64) {
        if let Some(bar) = &self.0 {
            // Message and length first: the ticking thread may draw between two calls.
            bar.set_message(msg);
            bar.set_length(total);
            bar.set_position(0);
            if let Ok(style) = ProgressStyle::with_template(BAR) {
                bar.set_style(style.progress_chars("=> "));
            }
        }
    }

    /// A percentage bar with `msg` for a build, and the hook the build calls between its
    /// steps to move it (`topomesh::BuildProgress`).
    pub fn build_hook(&self, msg: String) -> impl Fn(f64, &str) + Sync + '_ {
        self.start(msg.clone(), 100);
        move |fraction, step| {
            if let Some(bar) = &self.0 {
                bar.set_message(format!("{msg}: {step}"));
                bar.set_position((fraction * 100.0) as u64);
            }
        }
    }

    /// `n` more units of the bar's work done.
    pub fn advance(&self, n: u64) {
        if let Some(bar) = &self.0 {
            bar.inc(n);
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Some(bar) = &self.0 {
            bar.finish_and_clear();
        }
    }
}
