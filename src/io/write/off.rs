//! OFF: `OFF`, `nv nf 0`, the vertices, then `3 a b c` per triangle.

use super::Mesh;
use super::text::{write_elements, write_points};
use std::io::Write;

pub(super) fn write(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    writeln!(
        w,
        "OFF\n{} {} 0",
        mesh.positions.len(),
        mesh.triangles.len()
    )?;
    write_points(w, mesh.positions, "")?;
    write_elements(w, mesh.triangles, ("3 ", 0, ""))
}
