//! Reading a file as the kind of mesh the caller asked for: a surface file for CHE, a
//! volume file for CHF (the C API's load calls and any host that wants the same checks).

use super::{MeshData, read};
use crate::che::{BuildOptions, Che};
use crate::chf::Chf;
use crate::error::{Error, Result};
use std::path::Path;

/// Reads `path` and checks that it holds a surface (no tetrahedra).
pub fn read_surface(path: &Path) -> Result<MeshData> {
    let data = read(path)?;
    if data.is_volume() {
        return Err(Error::invalid(format!(
            "{}: holds {} tetrahedra (a volume mesh), not a surface",
            path.display(),
            data.tetrahedra.len()
        )));
    }
    Ok(data)
}

/// Reads `path` and checks that it holds a volume (tetrahedra).
pub fn read_volume(path: &Path) -> Result<MeshData> {
    let data = read(path)?;
    if !data.is_volume() {
        return Err(Error::invalid(format!(
            "{}: holds no tetrahedra ({} triangles: a surface, not a volume mesh)",
            path.display(),
            data.triangles.len()
        )));
    }
    Ok(data)
}

/// Reads a surface file and builds its CHE.
pub fn che(path: &Path, options: BuildOptions) -> Result<Che> {
    let data = read_surface(path)?;
    Che::from_triangles(
        &data.triangles,
        data.num_vertices(),
        &data.positions,
        options,
    )
}

/// Reads a volume file and builds its CHF; triangles the file also holds are ignored.
pub fn chf(path: &Path, options: BuildOptions) -> Result<Chf> {
    let data = read_volume(path)?;
    Chf::from_tetrahedra(
        &data.tetrahedra,
        data.num_vertices(),
        &data.positions,
        options,
    )
}
