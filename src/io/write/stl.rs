//! Binary STL: an 80-byte header, the triangle count, then per triangle its unit normal
//! and its three corners as `f32` (the format's only number type: positions are rounded
//! to `f32`, and a vertex has no identity of its own, so readers weld equal corners back
//! and split or isolated vertices are not kept). A triangle of zero area gets a zero
//! normal.

use super::Mesh;
use glam::DVec3;
use std::io::Write;

/// What the header says; the rest of its 80 bytes are spaces. It must not start with
/// `solid`, which marks ASCII STL.
const HEADER: &[u8] = b"binary STL written by topomesh";

pub(super) fn write(w: &mut dyn Write, mesh: &Mesh) -> std::io::Result<()> {
    let count = u32::try_from(mesh.triangles.len()).map_err(|_| {
        std::io::Error::other("more triangles than binary STL can count (2^32 - 1)")
    })?;
    let mut header = [b' '; 80];
    header[..HEADER.len()].copy_from_slice(HEADER);
    w.write_all(&header)?;
    w.write_all(&count.to_le_bytes())?;
    for t in mesh.triangles {
        let [a, b, c] = t.map(|v| mesh.positions[v as usize]);
        let normal = (b - a).cross(c - a).normalize_or_zero();
        let mut record = [0u8; 50];
        for (k, p) in [normal, a, b, c].iter().enumerate() {
            put(&mut record[12 * k..12 * k + 12], *p);
        }
        w.write_all(&record)?;
    }
    Ok(())
}

/// Three `f32` little-endian.
fn put(out: &mut [u8], p: DVec3) {
    for (k, x) in [p.x, p.y, p.z].into_iter().enumerate() {
        out[4 * k..4 * k + 4].copy_from_slice(&(x as f32).to_le_bytes());
    }
}
