//! Placeholder: the vtk reader is being written.

use super::MeshData;
use crate::error::{Error, Result};
use std::path::Path;

pub fn read(path: &Path) -> Result<MeshData> {
    Err(Error::invalid(format!(
        "{}: vtk reader not written yet",
        path.display()
    )))
}

pub fn write(path: &Path, _data: &MeshData) -> Result<()> {
    Err(Error::invalid(format!(
        "{}: vtk writer not written yet",
        path.display()
    )))
}
