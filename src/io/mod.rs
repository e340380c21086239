//! Mesh files: one reader (and writer) per format, chosen by the file's extension.
//! A parse error names the file and the line (or byte offset); no reader panics.

mod gmsh;
pub mod load;
mod medit;
mod obj;
mod off;
mod ply;
mod stl;
#[cfg(test)]
mod tests;
mod tetgen;
mod text;
mod vtk;
mod warning;
pub mod write;

pub use warning::Warning;
pub use write::{Mesh, WriteOptions, write, write_mesh, write_to};

use crate::error::{Error, Result};
use glam::DVec3;
use std::path::Path;

/// What a file holds: points, and triangles and/or tetrahedra over them (0-based ids).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    pub positions: Vec<DVec3>,
    pub triangles: Vec<[u32; 3]>,
    pub tetrahedra: Vec<[u32; 4]>,
    /// What the reader read past or found odd (`file:line: ...` when shown), in file order,
    /// then the checks every format shares (non-finite coordinates, no elements).
    pub warnings: Vec<Warning>,
}

impl MeshData {
    pub fn num_vertices(&self) -> usize {
        self.positions.len()
    }
    /// A volume file is one with tetrahedra; anything else is read as a surface.
    pub fn is_volume(&self) -> bool {
        !self.tetrahedra.is_empty()
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    Off,
    Obj,
    Ply,
    Stl,
    /// TetGen `.node` + `.ele` (either path, or the stem).
    TetGen,
    /// Medit `.mesh`.
    Medit,
    /// Gmsh `.msh` 2.2 and 4.1, ASCII.
    Gmsh,
    /// VTK legacy unstructured grid `.vtk`.
    Vtk,
}

impl Format {
    pub fn from_path(path: &Path) -> Result<Format> {
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(|e| e.to_ascii_lowercase())
            .unwrap_or_default();
        Ok(match ext.as_str() {
            "off" => Format::Off,
            "obj" => Format::Obj,
            "ply" => Format::Ply,
            "stl" => Format::Stl,
            "node" | "ele" => Format::TetGen,
            "mesh" => Format::Medit,
            "msh" => Format::Gmsh,
            "vtk" => Format::Vtk,
            _ => {
                return Err(Error::invalid(format!(
                    "{}: unknown mesh format (extension '{ext}'; known: off obj ply stl node ele mesh msh vtk)",
                    path.display()
                )));
            }
        })
    }
}

/// Reads a mesh file, the format chosen by its extension.
pub fn read(path: &Path) -> Result<MeshData> {
    let format = Format::from_path(path);
    // A missing file is reported as missing before its extension is judged; TetGen names
    // both of its files itself.
    if format != Ok(Format::TetGen) {
        std::fs::metadata(path).map_err(|e| Error::io(format!("{}: {e}", path.display())))?;
    }
    let name = path.display().to_string();
    let mut data = match format? {
        Format::TetGen => tetgen::read(path)?,
        format => parse_only(&read_bytes(path)?, format, &name)?,
    };
    warning::add_common(&mut data, &name);
    Ok(data)
}

/// Reads a whole file, naming it in the error; a file too large for memory is an
/// out-of-memory error (the standard library asks for the buffer fallibly).
pub(crate) fn read_bytes(path: &Path) -> Result<Vec<u8>> {
    std::fs::read(path).map_err(|e| match e.kind() {
        std::io::ErrorKind::OutOfMemory => {
            let len = std::fs::metadata(path).map_or(0, |m| m.len());
            Error::out_of_memory(len, &format!("the bytes of {}", path.display()))
        }
        _ => Error::io(format!("{}: {e}", path.display())),
    })
}

/// Parses a mesh held in memory (`name` appears in errors), as [`read`] parses a file's
/// bytes. TetGen needs two files, so it is read from paths only.
pub fn parse(bytes: &[u8], format: Format, name: &str) -> Result<MeshData> {
    let mut data = parse_only(bytes, format, name)?;
    warning::add_common(&mut data, name);
    Ok(data)
}

/// The reader of `format` on `bytes`, without the checks every format shares. The text
/// formats read bytes that are not UTF-8 as U+FFFD, so that such a file gets a parse
/// error with a line.
fn parse_only(bytes: &[u8], format: Format, name: &str) -> Result<MeshData> {
    match format {
        Format::Off => off::parse(bytes, name),
        Format::Obj => obj::parse(bytes, name),
        Format::Ply => ply::parse(bytes, name),
        Format::Stl => stl::parse(bytes, name),
        Format::Medit => medit::parse(&text::lossy(bytes)?, name),
        Format::Gmsh => gmsh::parse(&text::lossy(bytes)?, name),
        Format::Vtk => vtk::parse(&text::lossy(bytes)?, name),
        Format::TetGen => Err(Error::invalid(format!(
            "{name}: TetGen meshes are two files (.node and .ele): read them from a path"
        ))),
    }
}
