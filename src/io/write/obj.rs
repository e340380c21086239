//! Wavefront OBJ: `v x y z` per vertex, `f a b c` per triangle (1-based). OBJ has no
//! vertex attribute for an id, so origins are not written.

use super::Mesh;
use super::text::write_elements;
use std::io::Write;

pub(super) fn write(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    for p in mesh.positions {
        writeln!(w, "v {} {} {}", p.x, p.y, p.z)?;
    }
    write_elements(w, mesh.triangles, ("f ", 1, ""))
}
