//! `topomesh convert`: read one format, write another (the formats by file extension).

use crate::input::load;
use crate::progress::Progress;
use std::path::PathBuf;
use std::process::ExitCode;
use topomesh::Error;
use topomesh::io;
use topomesh::io::MeshData;

#[derive(clap::Args)]
pub struct ConvertOptions {
    input: PathBuf,
    output: PathBuf,
    /// Weld vertices at most TOLERANCE apart: every corner goes to its cluster's smallest
    /// vertex id and the others are left out of the output (0: off).
    #[arg(long, value_name = "TOLERANCE", default_value_t = 0.0)]
    weld: f64,
}

pub fn run(options: &ConvertOptions) -> Result<ExitCode, Error> {
    let ConvertOptions {
        input,
        output,
        weld,
    } = options;
    let progress = Progress::new();
    let (_, mut data) = load(Some(input), &progress)?;
    if *weld != 0.0 {
        let MeshData {
            positions,
            triangles,
            tetrahedra,
        } = &mut data;
        topomesh::weld_arrays(positions, triangles, tetrahedra, *weld)?;
    }
    progress.step(format!("writing {}", output.display()));
    io::write(output, &data)?;
    drop(progress);
    println!(
        "{} -> {}: {} vertices, {} triangles, {} tetrahedra",
        input.display(),
        output.display(),
        data.num_vertices(),
        data.triangles.len(),
        data.tetrahedra.len()
    );
    Ok(ExitCode::SUCCESS)
}
