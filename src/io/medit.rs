//! Placeholder: the medit reader is being written.

use super::MeshData;
use crate::error::{Error, Result};
use std::path::Path;

pub fn read(path: &Path) -> Result<MeshData> {
    Err(Error::invalid(format!(
        "{}: medit reader not written yet",
        path.display()
    )))
}

pub fn write(path: &Path, _data: &MeshData) -> Result<()> {
    Err(Error::invalid(format!(
        "{}: medit writer not written yet",
        path.display()
    )))
}
