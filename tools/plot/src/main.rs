//! topomesh-plot --results FILE --out-dir DIR --prefix NAME [--element triangle|tetrahedron]
//!
//! Reads a results file (see results.rs for the format) and writes the three charts of a
//! benchmark page into DIR. Used by scripts/bench.sh and scripts/bench-volumes.sh.

use std::path::PathBuf;
use std::process::ExitCode;

struct Args {
    results: PathBuf,
    out_dir: PathBuf,
    prefix: String,
    element: String,
}

fn parse_args() -> Result<Args, String> {
    let mut it = std::env::args().skip(1);
    let (mut results, mut out_dir, mut prefix, mut element) =
        (None, None, None, "triangle".to_string());
    while let Some(a) = it.next() {
        let mut value = || it.next().ok_or(format!("{a} needs a value"));
        match a.as_str() {
            "--results" => results = Some(PathBuf::from(value()?)),
            "--out-dir" => out_dir = Some(PathBuf::from(value()?)),
            "--prefix" => prefix = Some(value()?),
            "--element" => element = value()?,
            _ => return Err(format!("unknown argument {a}")),
        }
    }
    Ok(Args {
        results: results.ok_or("--results FILE is required")?,
        out_dir: out_dir.ok_or("--out-dir DIR is required")?,
        prefix: prefix.ok_or("--prefix NAME is required")?,
        element,
    })
}

fn run() -> Result<(), String> {
    let args = parse_args()?;
    let text = std::fs::read_to_string(&args.results)
        .map_err(|e| format!("{}: {e}", args.results.display()))?;
    let res = topomesh_plot::results::Results::parse(&text)
        .map_err(|e| format!("{}: {e}", args.results.display()))?;
    for p in topomesh_plot::write_charts(&res, &args.out_dir, &args.prefix, &args.element)? {
        println!("{}", p.display());
    }
    Ok(())
}

fn main() -> ExitCode {
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("topomesh-plot: {e}");
            eprintln!(
                "usage: topomesh-plot --results FILE --out-dir DIR --prefix NAME [--element NAME]"
            );
            ExitCode::from(2)
        }
    }
}
