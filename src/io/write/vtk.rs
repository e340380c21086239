//! VTK legacy 3.0 ASCII unstructured grid: triangles are cell type 5, tetrahedra 10; the
//! vertex origins, when the mesh carries them, are `POINT_DATA` scalars named `origin`.

use super::Mesh;
use super::text::{write_elements, write_points};
use std::io::Write;

pub(super) fn write(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    writeln!(
        w,
        "# vtk DataFile Version 3.0\ntopomesh\nASCII\nDATASET UNSTRUCTURED_GRID"
    )?;
    writeln!(w, "POINTS {} double", mesh.positions.len())?;
    write_points(w, mesh.positions, "")?;
    let (nt, nk) = (mesh.triangles.len(), mesh.tetrahedra.len());
    if nt + nk > 0 {
        writeln!(w, "CELLS {} {}", nt + nk, 4 * nt + 5 * nk)?;
        write_elements(w, mesh.triangles, ("3 ", 0, ""))?;
        write_elements(w, mesh.tetrahedra, ("4 ", 0, ""))?;
        writeln!(w, "CELL_TYPES {}", nt + nk)?;
        for _ in 0..nt {
            writeln!(w, "5")?;
        }
        for _ in 0..nk {
            writeln!(w, "10")?;
        }
    }
    if mesh.origin.is_some() && !mesh.positions.is_empty() {
        writeln!(w, "POINT_DATA {}", mesh.positions.len())?;
        writeln!(w, "SCALARS origin unsigned_int 1\nLOOKUP_TABLE default")?;
        for v in 0..mesh.positions.len() {
            writeln!(w, "{}", mesh.origin_of(v).unwrap_or(0))?;
        }
    }
    Ok(())
}
