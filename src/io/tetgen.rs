//! Placeholder: the tetgen reader is being written.

use super::MeshData;
use crate::error::{Error, Result};
use std::path::Path;

pub fn read(path: &Path) -> Result<MeshData> {
    Err(Error::invalid(format!(
        "{}: tetgen reader not written yet",
        path.display()
    )))
}
