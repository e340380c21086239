//! Where the subcommands write: stdout through one lock, every write's error returned
//! (never `println!`, which panics on a closed pipe or a full disk), and nothing at all
//! under `--quiet`.

use std::io::{self, StdoutLock, Write};
use std::sync::OnceLock;

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verbosity {
    /// Errors only: nothing on stdout, no progress bar.
    Quiet,
    Normal,
    /// The build report in full.
    Verbose,
}

static VERBOSITY: OnceLock<Verbosity> = OnceLock::new();

/// Set once, from the command line, before any subcommand runs.
pub fn set_verbosity(v: Verbosity) {
    let _ = VERBOSITY.set(v);
}

pub fn verbosity() -> Verbosity {
    VERBOSITY.get().copied().unwrap_or(Verbosity::Normal)
}

pub fn verbose() -> bool {
    verbosity() == Verbosity::Verbose
}

/// Locked stdout, or a sink under `--quiet`.
pub struct Out {
    lock: StdoutLock<'static>,
    quiet: bool,
}

impl Out {
    pub fn new() -> Self {
        Out {
            lock: io::stdout().lock(),
            quiet: verbosity() == Verbosity::Quiet,
        }
    }

    /// Flushes what is buffered: the last chance for a write error to show.
    pub fn finish(mut self) -> io::Result<()> {
        self.lock.flush()
    }
}

impl Write for Out {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.quiet {
            return Ok(buf.len());
        }
        self.lock.write(buf)
    }

    fn flush(&mut self) -> io::Result<()> {
        self.lock.flush()
    }
}
