//! The exit codes every subcommand shares, and the failures they come from.

use std::io::{self, Write};
use std::process::ExitCode;
use topomesh::{Error, ErrorKind};

/// The mesh has a problem `check` looks for (or `--strict` refused it).
pub const PROBLEM: u8 = 1;
/// Unknown option, missing or bad argument (clap's own code).
pub const USAGE: u8 = 2;
/// Unreadable or invalid input, or output that cannot be written.
pub const INPUT: u8 = 3;

/// The table `--help` ends with; the README has the same.
macro_rules! exit_code_table {
    () => {
        "Exit codes:
  0  success (check: the mesh is a clean manifold)
  1  the mesh has a problem check looks for (also info --strict on such a mesh)
  2  usage error: unknown option, missing or bad argument
  3  unreadable or invalid input (missing file, I/O, parse error, invalid or too large
     mesh) or output that cannot be written"
    };
}
pub(crate) use exit_code_table;

/// Why a subcommand stopped: the library refused the input, or stdout could not be written.
pub enum Failure {
    Mesh(Error),
    Output(io::Error),
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        Failure::Mesh(e)
    }
}

impl From<io::Error> for Failure {
    fn from(e: io::Error) -> Self {
        Failure::Output(e)
    }
}

/// The exit code of a subcommand's result, after one line on stderr for a failure. A
/// reader that closed the pipe early (`topomesh info | head -n1`) wanted no more: that is
/// a quiet success, not an error.
pub fn code(result: Result<ExitCode, Failure>) -> ExitCode {
    let (code, message) = match result {
        Ok(code) => return code,
        Err(Failure::Output(e)) if e.kind() == io::ErrorKind::BrokenPipe => {
            return ExitCode::SUCCESS;
        }
        Err(Failure::Output(e)) => (INPUT, format!("writing the output: {e}")),
        Err(Failure::Mesh(e)) if e.kind == ErrorKind::NonManifold => (PROBLEM, e.message),
        Err(Failure::Mesh(e)) => (INPUT, e.message),
    };
    // Nothing is left to tell if stderr is gone too: the exit code still says it.
    let _ = writeln!(io::stderr().lock(), "topomesh: error: {message}");
    ExitCode::from(code)
}

/// What clap stopped on: `--help` and `--version` on stdout (0, or as any output failure
/// when stdout cannot take them), a usage error on stderr (2).
pub fn usage(e: clap::Error) -> ExitCode {
    let printed = e.print();
    if e.use_stderr() {
        return ExitCode::from(USAGE);
    }
    code(printed.map(|()| ExitCode::SUCCESS).map_err(Failure::from))
}
