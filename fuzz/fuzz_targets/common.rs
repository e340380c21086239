//! What every reader target checks on what a reader accepted: ids in range, then a level-3
//! build (CHE for triangles, CHF for tetrahedra) that validates. Errors are fine; panics,
//! aborts and out-of-range ids are not.
#![allow(dead_code, reason = "each target uses the part it needs")]

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
