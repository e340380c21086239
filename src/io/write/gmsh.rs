//! Gmsh `.msh` 4.1 ASCII: one node block (entity of the mesh's dimension, tags 1..n), then
//! a triangle block (type 2) and a tetrahedron block (type 4), element tags 1.. in order.
//! No `$Entities` section: Gmsh reads a mesh without one, its elements on one discrete
//! entity per dimension. Origins are not written (see the module `write`).

use super::Mesh;
use super::text::{write_elements, write_points};
use std::io::Write;

pub(super) fn write(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    writeln!(w, "$MeshFormat\n4.1 0 8\n$EndMeshFormat")?;
    let nv = mesh.positions.len();
    let dim = if mesh.tetrahedra.is_empty() { 2 } else { 3 };
    writeln!(w, "$Nodes\n{} {nv} {} {nv}", (nv > 0) as u8, nv.min(1))?;
    if nv > 0 {
        writeln!(w, "{dim} 1 0 {nv}")?;
        for tag in 1..=nv {
            writeln!(w, "{tag}")?;
        }
        write_points(w, mesh.positions, "")?;
    }
    writeln!(w, "$EndNodes")?;
    let (nt, nk) = (mesh.triangles.len(), mesh.tetrahedra.len());
    let blocks = (nt > 0) as u8 + (nk > 0) as u8;
    writeln!(
        w,
        "$Elements\n{blocks} {} {} {}",
        nt + nk,
        (nt + nk).min(1),
        nt + nk
    )?;
    write_block(w, (2, 2, 1), mesh.triangles)?;
    write_block(w, (3, 4, 1 + nt), mesh.tetrahedra)?;
    writeln!(w, "$EndElements")
}

/// One element block: `(entity dimension, element type, first tag)`, then per element its
/// tag and 1-based node tags.
fn write_block<const K: usize>(
    w: &mut dyn Write, (dim, ty, first): (u8, u8, usize), elements: &[[u32; K]],
) -> std::io::Result<()> {
    if elements.is_empty() {
        return Ok(());
    }
    writeln!(w, "{dim} 1 {ty} {}", elements.len())?;
    for (i, e) in elements.iter().enumerate() {
        write!(w, "{} ", first + i)?;
        write_elements(w, std::slice::from_ref(e), ("", 1, ""))?;
    }
    Ok(())
}
