//! The incidence matrices of a CHF, in CSR with sorted columns (see `SparseMatrix`).

use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::{half_edge, he_origin, he_target, tet};
use crate::chf::query::view::{Need, View};
use crate::error::Result;
use crate::util::alloc::try_collect;
use crate::util::sparse::{
    Assembled, Entry, Shape, SparseMatrix, Storage, Values, assemble, reserve,
};

/// Which matrix `chf_mesh_export_matrix` writes (the structure's elements).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VolumeMatrixKind {
    /// V x E: edge e from a to b (chf_edge_vertices) has -1 in row a, +1 in row b.
    D1 = 0,
    /// E x F: +1 where the face's cycle (chf_face_vertices) runs along the edge, -1
    /// against it.
    D2 = 1,
    /// F x T: +1 where the tetrahedron holds the face's canonical half-face, -1 where it
    /// holds the twin. d1 * d2 == 0 and d2 * d3 == 0.
    D3 = 2,
    /// T x T, the dual graph: 1 where two tetrahedra share a face.
    DualAdjacency = 3,
}

// cbindgen reads this file for the C enum (`tests/header_drift.rs`); the list is Rust's.
/// cbindgen:ignore
impl VolumeMatrixKind {
    pub const ALL: [VolumeMatrixKind; 4] = [
        VolumeMatrixKind::D1,
        VolumeMatrixKind::D2,
        VolumeMatrixKind::D3,
        VolumeMatrixKind::DualAdjacency,
    ];
}

impl Chf {
    /// The matrix `kind`; see [`VolumeMatrixKind`].
    pub fn volume_matrix(&self, kind: VolumeMatrixKind) -> Result<SparseMatrix> {
        self.volume_matrix_into(kind, &mut |_, _| None)?.owned()
    }

    /// The matrix `kind` in the storage `offer` gives once the size is known (see
    /// [`Storage`]), else in memory of its own.
    pub fn volume_matrix_into(&self, kind: VolumeMatrixKind, offer: Storage) -> Result<Assembled> {
        self.check_collected("the matrix export")?;
        let (view, [nv, ne, nf, nt]) = self.complex()?;
        let e = |row: u32, col: u32, value: f64| Entry { row, col, value };
        let summed = |n_rows, n_cols| Shape {
            n_rows,
            n_cols,
            values: Values::Summed,
        };
        let mut out = Vec::new();
        match kind {
            VolumeMatrixKind::D1 => {
                reserve(&mut out, 2 * ne, "matrix entries")?;
                for (id, [a, b]) in edge_ends(&view, ne)?.into_iter().enumerate() {
                    out.extend([e(a, id as u32, -1.0), e(b, id as u32, 1.0)]);
                }
                assemble(summed(nv, ne), &out[..], offer)
            }
            VolumeMatrixKind::D2 => {
                let ends = edge_ends(&view, ne)?;
                reserve(&mut out, 3 * nf, "matrix entries")?;
                for f in 0..nf as u32 {
                    let hf = view.face_half_face(f);
                    for j in 0..3 {
                        let he = half_edge(hf, j);
                        let id = view.edge_of(he);
                        let along = he_origin(view.v, he) == ends[id as usize][0];
                        out.push(e(id, f, if along { 1.0 } else { -1.0 }));
                    }
                }
                assemble(summed(ne, nf), &out[..], offer)
            }
            VolumeMatrixKind::D3 => {
                reserve(&mut out, view.o.len(), "matrix entries")?;
                for hf in 0..view.o.len() as u32 {
                    let sign = if view.canonical_half_face(hf) == hf {
                        1.0
                    } else {
                        -1.0
                    };
                    out.push(e(view.face_of(hf), tet(hf), sign));
                }
                assemble(summed(nf, nt), &out[..], offer)
            }
            VolumeMatrixKind::DualAdjacency => {
                reserve(&mut out, view.o.len(), "matrix entries")?;
                for (hf, &g) in view.o.iter().enumerate() {
                    if g != NONE {
                        out.push(e(tet(hf as u32), tet(g), 1.0));
                    }
                }
                let pattern = Values::Pattern {
                    off: 1.0,
                    degree_diagonal: false,
                };
                let shape = Shape {
                    values: pattern,
                    ..summed(nt, nt)
                };
                assemble(shape, &out[..], offer)
            }
        }
    }
}

impl Chf {
    /// What the matrices and the Betti numbers read: the view with face and edge ids, and
    /// the counts of vertices, edges, faces and tetrahedra.
    pub(super) fn complex(&self) -> Result<(View<'_>, [usize; 4])> {
        let view = self.try_view(Need {
            faces: true,
            edges: true,
        })?;
        let counts = [
            self.n_vertices,
            self.num_edges(),
            self.num_faces(),
            self.num_tetrahedra(),
        ];
        Ok((view, counts))
    }
}

/// The ends of every edge, in the direction of its canonical half-edge.
pub(super) fn edge_ends(view: &View, ne: usize) -> Result<Vec<[u32; 2]>> {
    let ends = (0..ne as u32).map(|e| {
        let he = view.edge_half_edge(e);
        [he_origin(view.v, he), he_target(view.v, he)]
    });
    try_collect(ends, "the edge ends")
}
