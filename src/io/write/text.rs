//! The lines the ASCII writers share: points in the shortest text that reads back to the
//! same `f64` (Rust's `{}` for `f64` round-trips exactly), and elements as id lists.

use super::Mesh;
use glam::DVec3;
use std::io::Write;

/// Writes one line per point, `x y z` and then `suffix`.
pub(super) fn write_points(
    w: &mut dyn Write, points: &[DVec3], suffix: &str,
) -> std::io::Result<()> {
    for p in points {
        writeln!(w, "{} {} {}{suffix}", p.x, p.y, p.z)?;
    }
    Ok(())
}

/// Writes one line per point, `x y z`, then ` ` and the input vertex it comes from when the
/// mesh carries origins, else ` ` and `otherwise` (when given).
pub(super) fn write_points_with_origin(
    w: &mut dyn Write, mesh: &Mesh, otherwise: Option<u32>,
) -> std::io::Result<()> {
    for (i, p) in mesh.positions.iter().enumerate() {
        write!(w, "{} {} {}", p.x, p.y, p.z)?;
        match mesh.origin_of(i).or(otherwise) {
            Some(o) => writeln!(w, " {o}")?,
            None => writeln!(w)?,
        }
    }
    Ok(())
}

/// Writes one line per element: `prefix`, its ids plus `add` (1 for 1-based formats), then
/// `suffix`.
pub(super) fn write_elements<const K: usize>(
    w: &mut dyn Write, elements: &[[u32; K]], (prefix, add, suffix): (&str, u32, &str),
) -> std::io::Result<()> {
    for e in elements {
        w.write_all(prefix.as_bytes())?;
        for (i, id) in e.iter().enumerate() {
            let sep = if i == 0 { "" } else { " " };
            write!(w, "{sep}{}", id + add)?;
        }
        writeln!(w, "{suffix}")?;
    }
    Ok(())
}
