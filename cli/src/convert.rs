//! `topomesh convert`: read a mesh, build it, and write what was built (the oriented,
//! repaired structure, split vertices as vertices of their own) in another format; or the
//! input soup as read (`--as-read`), or a volume's boundary surface (`--boundary`). The
//! formats come from the extensions; `-` is standard input or output, its format named by
//! `--from` or `--format`.

use crate::exit::Failure;
use crate::input::{LevelFile, build_surface, build_volume, load};
use crate::output::Out;
use crate::progress::Progress;
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use topomesh::io::{self, Format, Mesh, MeshData, WriteOptions};
use topomesh::{BuildOptions, BuildProgress, Che, Chf, Error, chf};

#[derive(clap::Args)]
pub struct ConvertOptions {
    /// The mesh to read; `-` for standard input (with --from).
    input: PathBuf,
    /// The file to write; `-` for standard output (with --format). A level file (.che for a
    /// surface, .chf for a volume) saves the built structure, which `info` opens.
    output: PathBuf,
    /// Write the input as read (the soup), not the built mesh.
    #[arg(long, conflicts_with = "boundary")]
    as_read: bool,
    /// Write the boundary surface of a volume mesh.
    #[arg(long)]
    boundary: bool,
    /// The format of the output, by extension (off obj ply stl node mesh msh vtk); needed
    /// for `-`, and wins over the output's extension.
    #[arg(long, value_name = "EXT")]
    format: Option<String>,
    /// The format of standard input, by extension (off obj ply stl mesh msh vtk).
    #[arg(long, value_name = "EXT")]
    from: Option<String>,
    /// Binary PLY (STL is always binary).
    #[arg(long)]
    binary: bool,
    /// Leave out the input vertex of each vertex (otherwise written in PLY, VTK, Medit and
    /// TetGen files of the built mesh).
    #[arg(long)]
    no_origin: bool,
    /// Weld vertices at most TOLERANCE apart: every corner goes to its cluster's smallest
    /// vertex id and the others are left out of the output (0: off).
    #[arg(long, value_name = "TOLERANCE", default_value_t = 0.0)]
    weld: f64,
}

/// The standard stream's name in messages.
const STDIN: &str = "<stdin>";
const STDOUT: &str = "<stdout>";

fn is_stream(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// The format an extension names, for `--format` and `--from`.
fn format_named(flag: &str, ext: &str) -> Result<Format, Error> {
    Format::from_path(Path::new("x").with_extension(ext).as_path()).map_err(|_| {
        Error::invalid(format!(
            "{flag} {ext}: unknown mesh format (known: off obj ply stl node ele mesh msh vtk)"
        ))
    })
}

pub fn run(options: &ConvertOptions) -> Result<ExitCode, Failure> {
    let progress = Progress::new();
    let (name, mut data) = read_input(options, &progress)?;
    if options.weld != 0.0 {
        let MeshData {
            positions,
            triangles,
            tetrahedra,
            ..
        } = &mut data;
        topomesh::weld_arrays(positions, triangles, tetrahedra, options.weld)?;
    }
    let write = WriteOptions {
        format: options
            .format
            .as_deref()
            .map(|ext| format_named("--format", ext))
            .transpose()?,
        binary: options.binary,
        no_origin: options.no_origin,
    };
    let output = &options.output;
    let shown = if is_stream(output) {
        Path::new(STDOUT)
    } else {
        output.as_path()
    };
    progress.step(format!("writing {}", shown.display()));
    let counts = if let Some(kind) = level_file_output(options, &name, &data)? {
        save_level_file(output, kind, std::mem::take(&mut data), None, &progress)?
    } else if options.as_read {
        emit(output, &Mesh::from_data(&data), &write)?
    } else if data.is_volume() {
        let volume = build_volume(
            &data,
            chf::BuildOptions {
                level: 0,
                ..Default::default()
            },
        )?;
        if options.boundary {
            emit(output, &volume.boundary_to_write()?.mesh(shown)?, &write)?
        } else {
            emit(output, &volume.to_write(shown)?, &write)?
        }
    } else if options.boundary {
        return Err(Failure::from(Error::invalid(format!(
            "{name}: --boundary needs a volume mesh (tetrahedra); this is a surface"
        ))));
    } else {
        let surface = build_surface(
            &data,
            BuildOptions {
                level: 0,
                ..Default::default()
            },
        )?;
        emit(output, &surface.to_write(shown)?, &write)?
    };
    drop(progress);
    let line = format!(
        "{name} -> {}: {} vertices, {} triangles, {} tetrahedra",
        shown.display(),
        counts[0],
        counts[1],
        counts[2]
    );
    if is_stream(output) {
        // The mesh went to stdout; a failure to note it on stderr loses nothing.
        let _ = writeln!(std::io::stderr(), "{line}");
    } else {
        let mut out = Out::new();
        writeln!(out, "{line}")?;
        out.finish()?;
    }
    Ok(ExitCode::SUCCESS)
}

/// The input file, or standard input parsed as `--from` says.
fn read_input(options: &ConvertOptions, progress: &Progress) -> Result<(String, MeshData), Error> {
    if !is_stream(&options.input) {
        return load(Some(&options.input), progress);
    }
    let Some(ext) = options.from.as_deref() else {
        return Err(Error::invalid(
            "reading standard input (-) needs its format: --from EXT",
        ));
    };
    let format = format_named("--from", ext)?;
    let mut bytes = Vec::new();
    std::io::stdin()
        .lock()
        .read_to_end(&mut bytes)
        .map_err(|e| Error::io(format!("{STDIN}: {e}")))?;
    Ok((STDIN.to_string(), io::parse(&bytes, format, STDIN)?))
}

/// The level file `convert` is asked for (`.che`, `.chf`), if any, once it is one the input
/// can fill: a surface for `.che`, a volume for `.chf`, none of the options that shape a
/// mesh file.
fn level_file_output(
    options: &ConvertOptions, name: &str, data: &MeshData,
) -> Result<Option<LevelFile>, Error> {
    let Some(kind) = LevelFile::of(&options.output) else {
        return Ok(None);
    };
    let shown = options.output.display();
    if options.as_read || options.boundary || options.binary || options.no_origin {
        return Err(Error::invalid(format!(
            "{shown}: a level file holds the built structure; --as-read, --boundary, --binary and --no-origin do not apply"
        )));
    }
    match (kind, data.is_volume()) {
        (LevelFile::Surface, true) => Err(Error::invalid(format!(
            "{name}: a volume mesh (tetrahedra) goes to a .chf level file, not {shown}"
        ))),
        (LevelFile::Volume, false) => Err(Error::invalid(format!(
            "{name}: a surface mesh goes to a .che level file, not {shown}"
        ))),
        _ => Ok(Some(kind)),
    }
}

/// Builds `data` at `level` (`None`: the library's default) and saves it to `output`; the
/// counts of the structure. The arrays are handed to the build, so that the input is not
/// held twice (a generated mesh near the machine's memory builds).
pub(crate) fn save_level_file(
    output: &Path, kind: LevelFile, data: MeshData, level: Option<u8>, progress: &Progress,
) -> Result<[usize; 3], Error> {
    let n = data.num_vertices();
    let (positions, triangles, tetrahedra) = (data.positions, data.triangles, data.tetrahedra);
    let surface = BuildOptions {
        level: level.unwrap_or(BuildOptions::default().level),
        ..BuildOptions::default()
    };
    let volume = chf::BuildOptions {
        level: level.unwrap_or(chf::BuildOptions::default().level),
        ..chf::BuildOptions::default()
    };
    let hook = progress.build_hook(format!("building level {}", surface.level));
    let shown = BuildProgress::new(&hook);
    let counts = match kind {
        LevelFile::Surface => {
            let che = Che::from_vecs_with_progress(triangles, n, positions, surface, shown)?;
            progress.step(format!("writing {}", output.display()));
            che.save(output)?;
            [che.num_vertices(), che.num_triangles(), 0]
        }
        LevelFile::Volume => {
            let chf = Chf::from_vecs_with_progress(tetrahedra, n, positions, volume, shown)?;
            progress.step(format!("writing {}", output.display()));
            chf.save(output)?;
            [chf.num_vertices(), 0, chf.num_tetrahedra()]
        }
    };
    Ok(counts)
}

/// Writes `mesh` to `output` (a file, or standard output for `-`); the counts written.
pub(crate) fn emit(
    output: &Path, mesh: &Mesh, options: &WriteOptions,
) -> Result<[usize; 3], Error> {
    if is_stream(output) {
        let Some(format) = options.format else {
            return Err(Error::invalid(
                "writing standard output (-) needs a format: --format EXT",
            ));
        };
        let stdout = std::io::stdout();
        let mut w = std::io::BufWriter::new(stdout.lock());
        io::write_to(&mut w, mesh, format, options, STDOUT)?;
        w.flush().map_err(|e| Error::io(format!("{STDOUT}: {e}")))?;
    } else {
        io::write_mesh(output, mesh, options)?;
    }
    Ok([
        mesh.positions.len(),
        mesh.triangles.len(),
        mesh.tetrahedra.len(),
    ])
}
