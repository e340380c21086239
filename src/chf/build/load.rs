//! A volume file to a CHF: the reader by extension, then the build of its tetrahedra.

use crate::chf::{BuildOptions, Chf};
use crate::error::Result;
use std::path::Path;

impl Chf {
    /// Reads a volume file (the format from the extension: .mesh, .msh, .vtk, .node/.ele)
    /// and builds its tetrahedra; triangles the file also holds are ignored. A file without
    /// tetrahedra (a surface) is an [`ErrorKind::InvalidInput`](crate::ErrorKind) error.
    pub fn load(path: &Path, options: BuildOptions) -> Result<Chf> {
        let data = crate::io::load::read_volume(path)?;
        Chf::from_tetrahedra(
            &data.tetrahedra,
            data.num_vertices(),
            &data.positions,
            options,
        )
    }
}
