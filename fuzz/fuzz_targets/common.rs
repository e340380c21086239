//! What every reader target checks on what a reader accepted: ids in range, then a level-3
//! build (CHE for triangles, CHF for tetrahedra) that validates. Errors are fine; panics,
//! aborts and out-of-range ids are not.
#![allow(dead_code, reason = "each target uses the part it needs")]

use glam::DVec3;
use topomesh::io::{Format, MeshData, parse};
use topomesh::{BuildOptions, Che, Chf, chf};

/// Parses `bytes` as `format` and checks the result.
pub fn check_parse(bytes: &[u8], format: Format, name: &str) {
    if let Ok(mesh) = parse(bytes, format, name) {
        check_mesh(&mesh);
    }
}

pub fn check_mesh(mesh: &MeshData) {
    let n = mesh.num_vertices();
    let in_range = |ids: &[u32]| ids.iter().all(|&v| (v as usize) < n);
    assert!(
        mesh.triangles.iter().all(|t| in_range(t)),
        "a triangle id past {n} vertices"
    );
    assert!(
        mesh.tetrahedra.iter().all(|t| in_range(t)),
        "a tetrahedron id past {n} vertices"
    );
    // Bigger inputs only slow the search: the builders have targets of their own.
    if n > 1 << 12 || mesh.triangles.len() + mesh.tetrahedra.len() > 1 << 12 {
        return;
    }
    if !mesh.triangles.is_empty() {
        let options = BuildOptions {
            threads: 1,
            ..BuildOptions::level(3)
        };
        if let Ok(che) = Che::from_triangles(&mesh.triangles, n, &mesh.positions, options) {
            che.validate().expect("a built CHE validates");
        }
    }
    if !mesh.tetrahedra.is_empty() {
        let options = chf::BuildOptions {
            threads: 1,
            ..chf::BuildOptions::level(3)
        };
        if let Ok(chf) = Chf::from_tetrahedra(&mesh.tetrahedra, n, &mesh.positions, options) {
            chf.validate().expect("a built CHF validates");
        }
    }
}

/// A point of a coarse grid from three bytes: many coincident, collinear and coplanar
/// points, the cases geometric checks get wrong; the byte 255 gives a NaN coordinate.
pub fn grid_point(b: [u8; 3]) -> DVec3 {
    let c = |x: u8| {
        if x == 255 {
            f64::NAN
        } else {
            f64::from(x % 5) / 2.0
        }
    };
    DVec3::new(c(b[0]), c(b[1]), c(b[2]))
}

/// With the top bit of `head` set, `n` grid points taken from the front of `bytes`
/// (`None`: too few bytes); else no positions. The rest of `bytes` follows.
pub fn grid_points(head: u8, n: usize, bytes: &[u8]) -> Option<(Vec<DVec3>, &[u8])> {
    let len = if head & 0x80 != 0 { 3 * n } else { 0 };
    if bytes.len() < len {
        return None;
    }
    let (coords, rest) = bytes.split_at(len);
    let points = coords
        .chunks_exact(3)
        .map(|c| grid_point([c[0], c[1], c[2]]));
    Some((points.collect(), rest))
}
