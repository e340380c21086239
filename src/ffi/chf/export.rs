//! Classic representations of a CHF into caller buffers: half-face arrays, the dual graph
//! of the tetrahedra, the incidence matrices and Betti numbers (the layouts are stated on
//! each call and in the core, `crate::chf::export`). The matrix body is the CHE one.

use super::ChfMesh;
use crate::chf::{HalfFaceArrays, VolumeMatrixKind};
use crate::error::Result;
use crate::ffi::boundary::report_kind;
use crate::ffi::declare::exports;

/// Which array `chf_mesh_export_half_faces` writes. Half-face hf = 4t + i is face i of
/// tetrahedron t (opposite its vertex i).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChfHalfFaceArray {
    /// 1 per half-face: its twin (the same face in the other tetrahedron), TOPOMESH_NONE on
    /// the boundary.
    Twin = 0,
    /// 3 per half-face: its vertices, in the order that points out of its tetrahedron.
    Vertices = 1,
    /// 1 per half-face: its face id.
    Face = 2,
}

/// Betti numbers over Z/2.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ChfBetti {
    pub b0: u64,
    pub b1: u64,
    pub b2: u64,
    pub b3: u64,
}

fn half_face_array(a: HalfFaceArrays, which: u32) -> Result<Vec<u32>> {
    report_kind([a.twin, a.vertices, a.face], which, "chf_half_face_array")
}

exports! { ChfMesh;
    /// Half-face array `which` (a `chf_half_face_array`). O(T) at every level.
    ids fn chf_mesh_export_half_faces(which) {
        try |c| c.half_face_arrays().and_then(|a| half_face_array(a, which))
    }
    /// The dual graph: 4 entries per tetrahedron t, the tetrahedron across each of its faces
    /// (TOPOMESH_NONE on the boundary), as `chf_tetrahedron_tetrahedra`. O(T) at every level.
    ids fn chf_mesh_export_dual_graph() { try |c| c.tetrahedron_dual_graph() }
    /// Betti numbers over Z/2 of the structure's complex into `*out`; b0 - b1 + b2 - b3 is
    /// its Euler characteristic.
    value fn chf_mesh_betti_numbers() -> ChfBetti {
        |c| c.betti_numbers().map(|[b0, b1, b2, b3]| ChfBetti { b0, b1, b2, b3 })
    }
}

exports! { ChfMesh;
    /// Sparse matrix `kind` (a `chf_matrix_kind`) in CSR, with the layout and buffer rules of
    /// `che_mesh_export_matrix`.
    matrix fn chf_mesh_export_matrix(kind) {
        |c, offer| {
            let kind = report_kind(VolumeMatrixKind::ALL, kind, "chf_matrix_kind")?;
            c.volume_matrix_into(kind, offer)
        }
    }
}
