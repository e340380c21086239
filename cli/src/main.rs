//! The `topomesh` command: summaries, checks, conversions and timings of mesh files.
//! One module per subcommand; `input`, `progress`, `print` and `json` are shared by them.

mod bench;
mod check;
mod convert;
mod info;
mod input;
mod json;
mod print;
mod progress;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "topomesh",
    version,
    about = "Compact half-edge and half-face topology of meshes"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Topology summary and build report of a mesh (the embedded torus when no file).
    Info(info::InfoOptions),
    /// Exit 0 when the mesh is a clean manifold, 1 and a list of problems otherwise.
    Check(check::CheckOptions),
    /// Write the built (repaired) mesh in another format (off obj ply stl node/ele mesh msh vtk).
    Convert(convert::ConvertOptions),
    /// Time the build of every level and full sweeps of the relations.
    Bench(bench::BenchOptions),
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let command = cli
        .command
        .unwrap_or(Command::Info(info::InfoOptions::default()));
    let result = match command {
        Command::Info(options) => info::run(&options),
        Command::Check(options) => check::run(&options),
        Command::Convert(options) => convert::run(&options),
        Command::Bench(options) => bench::run(&options),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("topomesh: error: {}", e.message);
            ExitCode::FAILURE
        }
    }
}
