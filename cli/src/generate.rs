//! `topomesh generate`: a mesh of known topology and a chosen size (a torus, a sphere, a
//! tetrahedralised box), written in any mesh format or saved built as a level file, so that
//! anyone can make the meshes of the benchmarks and the scale runs again.

use crate::convert::{emit, save_level_file};
use crate::exit::Failure;
use crate::input::LevelFile;
use crate::output::Out;
use crate::progress::Progress;
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use topomesh::io::{Mesh, MeshData, WriteOptions};
use topomesh::levelfile::{StreamOptions, save_streamed, save_streamed_chf};
use topomesh::{Error, chf, generate};

/// The shapes `generate` makes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Shape {
    /// A closed surface of genus 1 (quads of a ring and its tube, two triangles each).
    Torus,
    /// A closed surface of genus 0 (meridians and bands, two poles).
    Sphere,
    /// A volume: a box of unit cubes, six tetrahedra each (Kuhn's subdivision).
    Box,
}

#[derive(clap::Args)]
pub struct GenerateOptions {
    shape: Shape,
    /// At least this many triangles (torus, sphere), as close as the grid allows.
    #[arg(long, value_name = "N", conflicts_with = "tetrahedra")]
    triangles: Option<u64>,
    /// At least this many tetrahedra (box): the smallest box of n^3 cubes that has them.
    #[arg(long, value_name = "N")]
    tetrahedra: Option<u64>,
    /// The file to write, its format by extension (off obj ply stl node mesh msh vtk), or a
    /// level file (.che for a surface, .chf for a volume) holding the built structure.
    #[arg(short, long, value_name = "FILE")]
    output: PathBuf,
    /// Binary PLY (STL is always binary).
    #[arg(long)]
    binary: bool,
    /// Saved as a level file by the streaming build (a torus to .che at level 1 or 2, a box
    /// to .chf at level 1): the elements go from the generator straight into the file and
    /// are paired there, so that a mesh larger than memory is built.
    #[arg(long)]
    stream: bool,
    /// The level of a level file (0-3; with --stream 1 or 2 for a torus, 1 for a box);
    /// default: the library's.
    #[arg(long, value_name = "LEVEL")]
    level: Option<u8>,
}

/// The default size: a mesh that builds in a blink.
const DEFAULT_COUNT: u64 = 100_000;

pub fn run(options: &GenerateOptions) -> Result<ExitCode, Failure> {
    if options.stream {
        return stream(options);
    }
    let data = shape_data(options)?;
    let progress = Progress::new();
    let output = &options.output;
    progress.step(format!("writing {}", output.display()));
    let counts = match LevelFile::of(output) {
        Some(kind) => {
            let volume = options.shape == Shape::Box;
            let shown = output.display();
            if volume != (kind == LevelFile::Volume) {
                let (what, ext) = if volume {
                    ("volume", ".chf")
                } else {
                    ("surface", ".che")
                };
                let shape = name(options.shape);
                return Err(Failure::from(Error::invalid(format!(
                    "{shown}: a {shape} is a {what}: its level file is {ext}"
                ))));
            }
            if options.binary {
                return Err(Failure::from(Error::invalid(format!(
                    "{shown}: --binary does not apply to a level file"
                ))));
            }
            save_level_file(output, kind, data, options.level, &progress)?
        }
        None if options.level.is_some() => {
            return Err(Failure::from(Error::invalid(format!(
                "{}: --level applies to a level file (.che, .chf)",
                output.display()
            ))));
        }
        None => {
            let write = WriteOptions {
                binary: options.binary,
                ..WriteOptions::default()
            };
            emit(output, &Mesh::from_data(&data), &write)?
        }
    };
    drop(progress);
    let mut out = Out::new();
    writeln!(
        out,
        "{} -> {}: {} vertices, {} triangles, {} tetrahedra",
        name(options.shape),
        output.display(),
        counts[0],
        counts[1],
        counts[2]
    )?;
    out.finish()?;
    Ok(ExitCode::SUCCESS)
}

/// `--stream`: the torus or the box built into its level file by the streaming build.
fn stream(options: &GenerateOptions) -> Result<ExitCode, Failure> {
    let output = &options.output;
    let kind = LevelFile::of(output);
    let fits = match options.shape {
        Shape::Torus => kind == Some(LevelFile::Surface),
        Shape::Box => kind == Some(LevelFile::Volume),
        Shape::Sphere => false,
    };
    if !fits {
        return Err(Failure::from(Error::invalid(format!(
            "{}: --stream writes a torus to a .che or a box to a .chf level file",
            output.display()
        ))));
    }
    let progress = Progress::new();
    progress.step(format!("streaming the build into {}", output.display()));
    let line = if options.shape == Shape::Box {
        stream_box(options)?
    } else {
        stream_torus(options)?
    };
    drop(progress);
    let mut out = Out::new();
    writeln!(out, "{line}")?;
    out.finish()?;
    Ok(ExitCode::SUCCESS)
}

fn stream_torus(options: &GenerateOptions) -> Result<String, Error> {
    let grid = generate::TorusGrid::of(options.triangles.unwrap_or(DEFAULT_COUNT))?;
    let stream = StreamOptions {
        level: options.level.unwrap_or(StreamOptions::default().level),
        ..StreamOptions::default()
    };
    let report = save_streamed(&grid, &options.output, stream)?;
    Ok(format!(
        "torus -> {}: {} vertices, {} triangles, {} edges (streamed)",
        options.output.display(),
        report.input_vertices,
        report.input_triangles,
        report.input_edges
    ))
}

fn stream_box(options: &GenerateOptions) -> Result<String, Error> {
    if options.level.is_some_and(|l| l != 1) {
        return Err(Error::invalid(format!(
            "{}: the streaming build writes a volume at level 1",
            options.output.display()
        )));
    }
    let grid = generate::CubeGrid::of(options.tetrahedra.unwrap_or(DEFAULT_COUNT))?;
    let report = save_streamed_chf(&grid, &options.output, chf::SweepLimits::default())?;
    Ok(format!(
        "box -> {}: {} vertices, {} tetrahedra, {} faces, {} edges (streamed)",
        options.output.display(),
        report.input_vertices,
        report.input_tetrahedra,
        report.input_faces,
        report.input_edges
    ))
}

fn name(shape: Shape) -> &'static str {
    match shape {
        Shape::Torus => "torus",
        Shape::Sphere => "sphere",
        Shape::Box => "box",
    }
}

/// The generated mesh, its size from the option that counts its elements.
fn shape_data(options: &GenerateOptions) -> Result<MeshData, Error> {
    let wrong = |flag: &str| {
        Error::invalid(format!(
            "{flag} does not size a {}; use {}",
            name(options.shape),
            if options.shape == Shape::Box {
                "--tetrahedra"
            } else {
                "--triangles"
            }
        ))
    };
    let mut data = MeshData::default();
    match options.shape {
        Shape::Box => {
            if options.triangles.is_some() {
                return Err(wrong("--triangles"));
            }
            let v = generate::cube_grid_of(options.tetrahedra.unwrap_or(DEFAULT_COUNT))?;
            (data.positions, data.tetrahedra) = (v.positions, v.tetrahedra);
        }
        shape => {
            if options.tetrahedra.is_some() {
                return Err(wrong("--tetrahedra"));
            }
            let n = options.triangles.unwrap_or(DEFAULT_COUNT);
            let s = match shape {
                Shape::Torus => generate::torus_of(n)?,
                _ => generate::sphere_of(n)?,
            };
            (data.positions, data.triangles) = (s.positions, s.triangles);
        }
    }
    Ok(data)
}
