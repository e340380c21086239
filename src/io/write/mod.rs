//! Mesh files written: one writer per format, the format chosen by the extension or named
//! in [`WriteOptions`], every file written whole or not at all (`atomic.rs`).
//!
//! What is written is a [`Mesh`]: positions, triangles and/or tetrahedra, and optionally
//! the input vertex each vertex comes from (`origin`), written where the format has a
//! vertex attribute: a PLY `origin` property, VTK `POINT_DATA` scalars, the Medit vertex
//! reference, a TetGen point attribute. OBJ, OFF, STL and Gmsh carry none (Gmsh's only
//! per-node data is a post-processing view of real numbers, not an id).
//!
//! Positions are written so that they read back bit-exact: `{}` in the text formats, `f64`
//! in binary PLY; binary STL stores `f32` by its specification, so STL rounds them.
//! Built structures are written by `Che::write`, `Chf::write` and `Chf::write_boundary`
//! (`built.rs`), the input soup by [`write()`](fn@write).

pub(crate) mod atomic;
mod built;
mod chunked;
mod gmsh;
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

pub use built::BoundaryMesh;

use super::{Format, MeshData};
use crate::error::{Error, Result};
use crate::util::origin::origin;
use glam::DVec3;
use std::io::Write;
use std::path::Path;

/// How to write a mesh file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WriteOptions {
    /// The format; `None`: from the path's extension.
    pub format: Option<Format>,
    /// Binary PLY (little-endian) instead of ASCII. STL is always binary; other formats
    /// refuse it.
    pub binary: bool,
    /// Leave the input vertex of each vertex out, even where the format has an attribute
    /// for it.
    pub no_origin: bool,
}

/// A mesh to write, borrowed: positions, elements over them (0-based), and the vertex
/// origins.
#[derive(Clone, Copy, Debug, Default)]
pub struct Mesh<'a> {
    pub positions: &'a [DVec3],
    pub triangles: &'a [[u32; 3]],
    pub tetrahedra: &'a [[u32; 4]],
    /// The input vertex of each vertex, written as a vertex attribute: `None` writes none,
    /// an empty slice is the identity.
    pub origin: Option<&'a [u32]>,
}

impl<'a> Mesh<'a> {
    /// The input soup as read: no origins.
    pub fn from_data(data: &'a MeshData) -> Mesh<'a> {
        Mesh {
            positions: &data.positions,
            triangles: &data.triangles,
            tetrahedra: &data.tetrahedra,
            origin: None,
        }
    }

    /// The input vertex of vertex `v`, when the mesh carries origins.
    pub(crate) fn origin_of(&self, v: usize) -> Option<u32> {
        self.origin.map(|map| origin(map, v as u32))
    }
}

/// Writes the input soup `data` to `path`, the format from its extension.
pub fn write(path: &Path, data: &MeshData) -> Result<()> {
    write_mesh(path, &Mesh::from_data(data), &WriteOptions::default())
}

/// Writes `mesh` to `path` (both files of a TetGen mesh: `.node` and `.ele` beside each
/// other), whole or not at all.
pub fn write_mesh(path: &Path, mesh: &Mesh, options: &WriteOptions) -> Result<()> {
    let format = match options.format {
        Some(f) => f,
        None => Format::from_path(path)?,
    };
    let name = path.display().to_string();
    let mesh = checked(mesh, format, options, &name)?;
    if format == Format::TetGen {
        return tetgen::write_files(path, &mesh);
    }
    atomic::write(path, &mut |w| body(w, &mesh, format, options))
}

/// Writes `mesh` in `format` to a stream (standard output); `name` appears in errors.
/// TetGen, being two files, is refused.
pub fn write_to(
    w: &mut dyn Write, mesh: &Mesh, format: Format, options: &WriteOptions, name: &str,
) -> Result<()> {
    let mesh = checked(mesh, format, options, name)?;
    if format == Format::TetGen {
        return Err(Error::invalid(format!(
            "{name}: a TetGen mesh is two files (.node and .ele): write it to a path"
        )));
    }
    body(w, &mesh, format, options).map_err(|e| Error::io(format!("{name}: {e}")))
}

/// The writer of `format` (TetGen aside).
fn body(
    w: &mut dyn Write, mesh: &Mesh, format: Format, options: &WriteOptions,
) -> std::io::Result<()> {
    match format {
        Format::Off => off::write(w, mesh),
        Format::Obj => obj::write(w, mesh),
        Format::Ply if options.binary => ply::write_binary(w, mesh),
        Format::Ply => ply::write_ascii(w, mesh),
        Format::Stl => stl::write(w, mesh),
        Format::Medit => medit::write(w, mesh),
        Format::Gmsh => gmsh::write(w, mesh),
        Format::Vtk => vtk::write(w, mesh),
        // Two files: `write_mesh` and `write_to` take TetGen before coming here.
        Format::TetGen => Err(std::io::Error::other("a TetGen mesh is two files")),
    }
}

/// The name of a format in messages.
fn label(format: Format) -> &'static str {
    match format {
        Format::Off => "OFF",
        Format::Obj => "OBJ",
        Format::Ply => "PLY",
        Format::Stl => "STL",
        Format::TetGen => "TetGen .node/.ele",
        Format::Medit => "Medit .mesh",
        Format::Gmsh => "Gmsh .msh",
        Format::Vtk => "VTK",
    }
}

/// Refuses what `format` cannot hold (tetrahedra in a surface format, triangles in
/// TetGen, binary text), ids naming no point, and an OFF file of no vertices; returns the
/// mesh with its origins dropped when the options say so.
fn checked<'a>(
    mesh: &Mesh<'a>, format: Format, options: &WriteOptions, name: &str,
) -> Result<Mesh<'a>> {
    let surface_only = matches!(
        format,
        Format::Off | Format::Obj | Format::Ply | Format::Stl
    );
    if surface_only && !mesh.tetrahedra.is_empty() {
        return Err(Error::invalid(format!(
            "{name}: {} holds surfaces only, but the mesh has {} tetrahedra (write .mesh, .msh, .node or .vtk, or its boundary)",
            label(format),
            mesh.tetrahedra.len()
        )));
    }
    if format == Format::TetGen && !mesh.triangles.is_empty() {
        return Err(Error::invalid(format!(
            "{name}: {} holds tetrahedra only, but the mesh has {} triangles (write .mesh, .msh or .vtk)",
            label(format),
            mesh.triangles.len()
        )));
    }
    if options.binary && !matches!(format, Format::Ply | Format::Stl) {
        return Err(Error::invalid(format!(
            "{name}: {} is written as text only (binary output: .ply; .stl is always binary)",
            label(format)
        )));
    }
    if format == Format::Off && mesh.positions.is_empty() {
        return Err(Error::invalid(format!("{name}: no vertices to write")));
    }
    check_ids(mesh, name)?;
    let origin = mesh.origin.filter(|_| !options.no_origin);
    Ok(Mesh { origin, ..*mesh })
}

/// Errors if a triangle or tetrahedron names a point that does not exist.
fn check_ids(mesh: &Mesh, name: &str) -> Result<()> {
    let n = mesh.positions.len();
    let bad = |kind: &str, i: usize, id: u32| {
        Error::out_of_range(format!(
            "{name}: {kind} {i} names vertex {id}, but there are {n} vertices"
        ))
    };
    for (i, t) in mesh.triangles.iter().enumerate() {
        if let Some(&id) = t.iter().find(|&&v| v as usize >= n) {
            return Err(bad("triangle", i, id));
        }
    }
    for (i, t) in mesh.tetrahedra.iter().enumerate() {
        if let Some(&id) = t.iter().find(|&&v| v as usize >= n) {
            return Err(bad("tetrahedron", i, id));
        }
    }
    if let Some(map) = mesh.origin.filter(|m| !m.is_empty() && m.len() != n) {
        return Err(Error::invalid(format!(
            "{name}: {} vertex origins for {n} vertices",
            map.len()
        )));
    }
    Ok(())
}
