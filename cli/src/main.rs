//! The `topomesh` command: summaries, checks, conversions and timings of mesh files.
//! One module per subcommand; `input`, `output`, `progress`, `print`, `report`, `json` and
//! `exit` are shared by them.

mod bench;
mod check;
mod convert;
mod exit;
mod info;
mod input;
mod json;
mod output;
mod print;
mod progress;
mod report;

use clap::{Parser, Subcommand};
use exit::exit_code_table;
use output::Verbosity;
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "topomesh",
    version,
    about = "Compact half-edge and half-face topology of meshes",
    after_help = concat!("With no subcommand: info on the embedded torus.\n\n", exit_code_table!())
)]
struct Cli {
    /// Print nothing on stdout and no progress: errors only (check answers by its exit
    /// code alone).
    #[arg(short, long, global = true, conflicts_with = "verbose")]
    quiet: bool,
    /// Print the build report in full: every example id it kept (check: the whole report;
    /// info: also the memory of each container; bench: the fastest and slowest runs).
    #[arg(short, long, global = true)]
    verbose: bool,
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Topology summary and build report of a mesh (the embedded torus when no file).
    #[command(after_help = concat!(
        "Examples:
  topomesh info                          the embedded torus, level 3
  topomesh info bunny.off --level 1      a surface at level 1
  topomesh info --json part.mesh         a volume, as JSON (\"schema\" first)
  topomesh info --strict scan.ply        exit 1 if it is not manifold\n\n",
        exit_code_table!()
    ))]
    Info(info::InfoOptions),
    /// Exit 0 when the mesh is a clean manifold, 1 and a list of problems otherwise.
    #[command(after_help = concat!(
        "Examples:
  topomesh check scan.obj                one line per kind of problem
  topomesh -q check scan.obj && echo ok  the exit code alone
  topomesh check --json part.msh         ok, and each problem with its first ids
  topomesh -v check scan.obj             and the whole build report\n\n",
        exit_code_table!()
    ))]
    Check(check::CheckOptions),
    /// Write the built (repaired) mesh in another format (off obj ply stl node/ele mesh msh vtk).
    #[command(after_help = concat!(
        "Examples:
  topomesh convert scan.ply scan.off     the repaired mesh
  topomesh convert --as-read a.stl a.off the input as read
  topomesh convert part.node - --format vtk  to standard output
  topomesh convert part.node part.vtk    a TetGen pair (part.node and part.ele)\n\n",
        exit_code_table!()
    ))]
    Convert(convert::ConvertOptions),
    /// Time the build of every level and full sweeps of the relations.
    #[command(after_help = concat!(
        "Examples:
  topomesh bench bunny.off --repeat 9    the median of 9 runs, after a warm-up run
  topomesh bench --threads 1 --json      the embedded torus on one thread, as JSON\n\n",
        exit_code_table!()
    ))]
    Bench(bench::BenchOptions),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return exit::usage(e),
    };
    output::set_verbosity(match (cli.quiet, cli.verbose) {
        (true, _) => Verbosity::Quiet,
        (false, true) => Verbosity::Verbose,
        (false, false) => Verbosity::Normal,
    });
    let command = cli
        .command
        .unwrap_or(Command::Info(info::InfoOptions::default()));
    exit::code(match command {
        Command::Info(options) => info::run(&options),
        Command::Check(options) => check::run(&options),
        Command::Convert(options) => convert::run(&options),
        Command::Bench(options) => bench::run(&options),
    })
}
