//! Placeholder: the gmsh reader is being written.

use super::MeshData;
use crate::error::{Error, Result};
use std::path::Path;

pub fn read(path: &Path) -> Result<MeshData> {
    Err(Error::invalid(format!(
        "{}: gmsh reader not written yet",
        path.display()
    )))
}
