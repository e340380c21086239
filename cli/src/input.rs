//! What every subcommand starts from: a mesh read from a file (or the embedded torus) and
//! the structure built over it.

use crate::progress::Progress;
use std::path::Path;
use topomesh::io::{self, MeshData};
use topomesh::{BuildOptions, Che, Chf, Error, chf};

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
        Some(path) => {
            progress.step(format!("reading {}", path.display()));
            Ok((path.display().to_string(), io::read(path)?))
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
