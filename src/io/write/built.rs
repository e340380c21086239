//! The built structures written: what the build made, not what was read. A CHE is its
//! oriented triangles (degenerate ones dropped, orientation repaired) over its vertices,
//! split copies included as vertices of their own with their positions; a CHF its
//! oriented tetrahedra likewise; the origins are the input vertex each vertex comes from.

use super::{Mesh, WriteOptions, write_mesh};
use crate::che::Che;
use crate::chf::Chf;
use crate::error::{Error, Result};
use crate::util::structure::as_elements;
use glam::DVec3;
use std::path::Path;

/// The positions of a structure's vertices, or an error naming `path` when it was built
/// without them: a mesh file needs a position for every vertex, and zeros would be a
/// made-up geometry.
fn positions<'a>(positions: &'a [DVec3], n_vertices: usize, path: &Path) -> Result<&'a [DVec3]> {
    if positions.len() != n_vertices {
        return Err(Error::invalid(format!(
            "{}: the mesh has no positions (it was built from ids alone), and a mesh file needs them",
            path.display()
        )));
    }
    Ok(positions)
}

/// `write`, `write_with` and `to_write` of a built structure `$ty`, whose `V` array
/// (`$ids`) is its elements of `$k` vertices, written as the mesh's `$field`; `$what` names
/// the structure ("surface") and `$element` an element ("triangle") in docs and errors.
macro_rules! write_methods {
    ($ty:ident, $what:literal, $field:ident, $k:literal, $ids:ident, $element:literal) => {
        impl $ty {
            #[doc = concat!("Writes the built ", $what, " to `path`, the format from its extension (see")]
            #[doc = concat!("[`", stringify!($ty), "::write_with`]).")]
            pub fn write(&self, path: &Path) -> Result<()> {
                self.write_with(path, &WriteOptions::default())
            }

            #[doc = concat!("Writes the built ", $what, ": its oriented ", stringify!($field), " over its vertices (split")]
            /// copies as vertices of their own), and, where the format has a vertex attribute,
            /// the input vertex each comes from. Whole or not at all; a mesh built without
            /// positions is refused (`InvalidInput`).
            pub fn write_with(&self, path: &Path, options: &WriteOptions) -> Result<()> {
                write_mesh(path, &self.to_write(path)?, options)
            }

            #[doc = concat!("The ", $what, " as a [`Mesh`] to write (borrowed); `path` names it in the error for a")]
            /// mesh without positions.
            pub fn to_write(&self, path: &Path) -> Result<Mesh<'_>> {
                self.check_collected("writing the mesh")?;
                Ok(Mesh {
                    positions: positions(self.positions(), self.num_vertices(), path)?,
                    $field: as_elements::<$k>(self.$ids(), $element)?,
                    origin: Some(self.vertex_origins().unwrap_or(&[])),
                    ..Mesh::default()
                })
            }
        }
    };
}

write_methods!(Che, "surface", triangles, 3, half_edge_vertices, "triangle");
write_methods!(
    Chf,
    "volume",
    tetrahedra,
    4,
    half_face_vertices,
    "tetrahedron"
);

impl Chf {
    /// Writes the boundary surface to `path`, the format from its extension (see
    /// [`Chf::write_boundary_with`]).
    pub fn write_boundary(&self, path: &Path) -> Result<()> {
        self.write_boundary_with(path, &WriteOptions::default())
    }

    /// Writes the boundary surface ([`Chf::boundary_surface`], built below level 3) as a
    /// surface file; the origin of each of its vertices is the input vertex of the volume
    /// mesh it lies on.
    pub fn write_boundary_with(&self, path: &Path, options: &WriteOptions) -> Result<()> {
        write_mesh(path, &self.boundary_to_write()?.mesh(path)?, options)
    }

    /// The boundary surface and the input vertex of the volume each of its vertices lies
    /// on: what [`Chf::write_boundary_with`] writes.
    pub fn boundary_to_write(&self) -> Result<BoundaryMesh> {
        self.check_collected("writing the boundary")?;
        let surface = self.boundary_surface()?;
        let volume_vertex = self.boundary_vertices();
        let n = surface.num_vertices();
        let mut origin = crate::util::alloc::try_with_capacity(n, "the boundary vertex origins")?;
        origin.extend((0..n as u32).map(|b| {
            let v = volume_vertex[surface.vertex_origin(b) as usize];
            self.vertex_origin(v)
        }));
        Ok(BoundaryMesh { surface, origin })
    }
}

/// The boundary surface of a volume mesh, with the input vertex of the volume for each of
/// its vertices.
pub struct BoundaryMesh {
    pub surface: Che,
    pub origin: Vec<u32>,
}

impl BoundaryMesh {
    /// The surface as a [`Mesh`] to write, its origins those of the volume; `path` names
    /// it in the error for a mesh without positions.
    pub fn mesh(&self, path: &Path) -> Result<Mesh<'_>> {
        Ok(Mesh {
            origin: Some(&self.origin),
            ..self.surface.to_write(path)?
        })
    }
}
