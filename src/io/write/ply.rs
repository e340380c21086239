//! PLY, ASCII or binary little-endian: an element `vertex` of `double` x, y, z (and a
//! `uint origin` property when the mesh carries origins), an element `face` with the list
//! `vertex_indices` (`uchar` count, `uint` ids). Doubles keep positions exact in both.

use super::Mesh;
use std::io::Write;

fn write_header(w: &mut dyn Write, mesh: &Mesh, encoding: &str) -> std::io::Result<()> {
    writeln!(w, "ply\nformat {encoding} 1.0\ncomment written by topomesh")?;
    writeln!(w, "element vertex {}", mesh.positions.len())?;
    writeln!(w, "property double x\nproperty double y\nproperty double z")?;
    if mesh.origin.is_some() {
        writeln!(w, "property uint origin")?;
    }
    writeln!(w, "element face {}", mesh.triangles.len())?;
    writeln!(w, "property list uchar uint vertex_indices\nend_header")
}

pub(super) fn write_ascii(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    write_header(w, mesh, "ascii")?;
    super::text::write_points_with_origin(w, mesh, None)?;
    super::text::write_elements(w, mesh.triangles, ("3 ", 0, ""))
}

pub(super) fn write_binary(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    write_header(w, mesh, "binary_little_endian")?;
    for (i, p) in mesh.positions.iter().enumerate() {
        let mut record = [0u8; 28];
        for (k, x) in [p.x, p.y, p.z].into_iter().enumerate() {
            record[8 * k..8 * k + 8].copy_from_slice(&x.to_le_bytes());
        }
        let len = match mesh.origin_of(i) {
            Some(o) => {
                record[24..].copy_from_slice(&o.to_le_bytes());
                28
            }
            None => 24,
        };
        w.write_all(&record[..len])?;
    }
    for t in mesh.triangles {
        let mut record = [3u8; 13];
        for (k, id) in t.iter().enumerate() {
            record[1 + 4 * k..5 + 4 * k].copy_from_slice(&id.to_le_bytes());
        }
        w.write_all(&record)?;
    }
    Ok(())
}
