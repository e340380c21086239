//! Medit `.mesh` (ASCII, version 2): vertices with their reference, then the triangles
//! and tetrahedra (1-based, reference 0). The vertex reference is the input vertex the
//! vertex comes from when the mesh carries origins, 0 otherwise.

use super::Mesh;
use super::text::{write_elements, write_points_with_origin};
use std::io::Write;

pub(super) fn write(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    writeln!(w, "MeshVersionFormatted 2\n\nDimension 3\n")?;
    writeln!(w, "Vertices\n{}", mesh.positions.len())?;
    write_points_with_origin(w, mesh, Some(0))?;
    write_section(w, "Triangles", mesh.triangles)?;
    write_section(w, "Tetrahedra", mesh.tetrahedra)?;
    writeln!(w, "\nEnd")
}

/// A section of elements (1-based ids, ref 0), if there are any.
fn write_section<const K: usize>(
    w: &mut dyn Write, keyword: &str, elements: &[[u32; K]],
) -> std::io::Result<()> {
    if elements.is_empty() {
        return Ok(());
    }
    writeln!(w, "\n{keyword}\n{}", elements.len())?;
    write_elements(w, elements, ("", 1, " 0"))
}
