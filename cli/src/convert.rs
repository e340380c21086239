//! `topomesh convert`: read one format, write another (the formats by file extension).

use crate::input::load;
use crate::progress::Progress;
use std::path::PathBuf;
use std::process::ExitCode;
use topomesh::Error;
use topomesh::io;

#[derive(clap::Args)]
pub struct ConvertOptions {
    input: PathBuf,
    output: PathBuf,
}

pub fn run(options: &ConvertOptions) -> Result<ExitCode, Error> {
    let ConvertOptions { input, output } = options;
    let progress = Progress::new();
    let (_, data) = load(Some(input), &progress)?;
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
