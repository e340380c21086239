//! What every subcommand starts from: a mesh read from a file (or the embedded torus) and
//! the structure built over it.

use crate::progress::Progress;
use std::fs::File;
use std::io::{ErrorKind, Read};
use std::path::Path;
use topomesh::io::{self, Format, MeshData};
use topomesh::{BuildOptions, Che, Chf, Error, chf};

/// Bytes read between two steps of the progress bar.
const CHUNK: u64 = 1 << 22;

/// The mesh `topomesh info` describes when no file is given: a 24 x 12 torus.
const DEFAULT_MESH: &str = include_str!("../../data/default.off");
const DEFAULT_NAME: &str = "<embedded torus>";

/// Reads `file`, or parses the embedded torus when there is none; returns the name to print
/// and the mesh.
pub fn load(file: Option<&Path>, progress: &Progress) -> Result<(String, MeshData), Error> {
    match file {
        None => Ok((
            DEFAULT_NAME.to_string(),
            io::parse(DEFAULT_MESH.as_bytes(), io::Format::Off, DEFAULT_NAME)?,
        )),
        Some(path) => Ok((path.display().to_string(), read(path, progress)?)),
    }
}

/// Reads `path` under a percentage bar of its bytes, then parses them. The library's
/// reader does both for what cannot be parsed from memory (TetGen's two files, text
/// formats that are not UTF-8, which it reads leniently) and for every failure, so that
/// the messages are its own.
fn read(path: &Path, progress: &Progress) -> Result<MeshData, Error> {
    let name = path.display().to_string();
    let from_path = |progress: &Progress| {
        progress.step(format!("reading {name}"));
        io::read(path)
    };
    let format = match Format::from_path(path) {
        Ok(Format::TetGen) | Err(_) => return from_path(progress),
        Ok(format) => format,
    };
    let bytes = match read_bytes(path, progress) {
        Ok(bytes) => bytes,
        Err(e) if e.kind() == ErrorKind::OutOfMemory => {
            return Err(Error::too_large(format!(
                "{name}: the file does not fit in memory"
            )));
        }
        Err(_) => return from_path(progress),
    };
    let text = matches!(format, Format::Medit | Format::Gmsh | Format::Vtk);
    if text && std::str::from_utf8(&bytes).is_err() {
        return from_path(progress);
    }
    progress.step(format!("parsing {name}"));
    io::parse(&bytes, format, &name)
}

/// The bytes of `path`, read in chunks that advance the progress bar.
fn read_bytes(path: &Path, progress: &Progress) -> std::io::Result<Vec<u8>> {
    let mut file = File::open(path)?;
    let size = file.metadata()?.len();
    let mut bytes = Vec::new();
    usize::try_from(size)
        .ok()
        .and_then(|n| bytes.try_reserve_exact(n).ok())
        .ok_or(ErrorKind::OutOfMemory)?;
    progress.start(format!("reading {}", path.display()), size);
    loop {
        match (&mut file).take(CHUNK).read_to_end(&mut bytes)? {
            0 => return Ok(bytes),
            n => progress.advance(n as u64),
        }
    }
}

pub fn build_surface(data: &MeshData, options: BuildOptions) -> Result<Che, Error> {
    Che::from_triangles(
        &data.triangles,
        data.num_vertices(),
        &data.positions,
        options,
    )
}

pub fn build_volume(data: &MeshData, options: chf::BuildOptions) -> Result<Chf, Error> {
    Chf::from_tetrahedra(
        &data.tetrahedra,
        data.num_vertices(),
        &data.positions,
        options,
    )
}
