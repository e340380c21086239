//! Sparse matrices of the structure, in CSR with sorted columns (see `SparseMatrix`).

use crate::NONE;
use crate::che::Che;
use crate::che::ids::{next, tri};
use crate::error::Result;
use crate::util::sparse::{Entry, SparseMatrix, reserve};

/// Which matrix `che_mesh_export_matrix` writes (vertices, edges and triangles are the
/// structure's).
#[repr(u32)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MatrixKind {
    /// V x V: 1 where an edge joins two vertices (several edges count once).
    VertexAdjacency = 0,
    /// E x E: 1 where two edges share a vertex.
    EdgeAdjacency = 1,
    /// V x E, the boundary operator d1: edge e from a to b (its canonical direction,
    /// che_edge_vertices) has -1 in row a and +1 in row b.
    D1 = 2,
    /// E x T, the boundary operator d2: +1 where the triangle runs along the edge's
    /// canonical direction, -1 where it runs against it. d1 * d2 == 0.
    D2 = 3,
    /// V x V, the combinatorial Laplacian: the number of neighbours on the diagonal, -1
    /// where the vertex adjacency has 1.
    Laplacian = 4,
    /// T x T, the dual graph: 1 where two triangles share an edge.
    DualAdjacency = 5,
}

// cbindgen reads this file for the C enum (`tests/header_drift.rs`); the list is Rust's.
/// cbindgen:ignore
impl MatrixKind {
    pub const ALL: [MatrixKind; 6] = [
        MatrixKind::VertexAdjacency,
        MatrixKind::EdgeAdjacency,
        MatrixKind::D1,
        MatrixKind::D2,
        MatrixKind::Laplacian,
        MatrixKind::DualAdjacency,
    ];
}

/// Sets every stored value to 1: the pattern of an adjacency, whatever the multiplicity.
fn pattern(mut m: SparseMatrix) -> SparseMatrix {
    m.values.iter_mut().for_each(|x| *x = 1.0);
    m
}

impl Che {
    /// The matrix `kind`, in CSR with sorted columns; see [`MatrixKind`].
    pub fn matrix(&self, kind: MatrixKind) -> Result<SparseMatrix> {
        let (nv, ne, nt) = (self.n_vertices, self.num_edges, self.num_triangles());
        let entries = self.matrix_entries(kind)?;
        match kind {
            MatrixKind::VertexAdjacency => {
                Ok(pattern(SparseMatrix::from_entries(nv, nv, &entries)?))
            }
            MatrixKind::EdgeAdjacency => Ok(pattern(SparseMatrix::from_entries(ne, ne, &entries)?)),
            MatrixKind::D1 => SparseMatrix::from_entries(nv, ne, &entries),
            MatrixKind::D2 => SparseMatrix::from_entries(ne, nt, &entries),
            MatrixKind::DualAdjacency => Ok(pattern(SparseMatrix::from_entries(nt, nt, &entries)?)),
            MatrixKind::Laplacian => {
                let a = self.matrix(MatrixKind::VertexAdjacency)?;
                let mut e = Vec::new();
                reserve(&mut e, a.nnz() + nv, "Laplacian entries")?;
                for r in 0..nv {
                    let (cols, _) = a.row(r);
                    let row = r as u32;
                    e.push(Entry {
                        row,
                        col: row,
                        value: cols.len() as f64,
                    });
                    e.extend(cols.iter().map(|&col| Entry {
                        row,
                        col,
                        value: -1.0,
                    }));
                }
                SparseMatrix::from_entries(nv, nv, &e)
            }
        }
    }

    /// The (row, column, value) entries of `kind` (none for the Laplacian, made from the
    /// adjacency).
    fn matrix_entries(&self, kind: MatrixKind) -> Result<Vec<Entry>> {
        let t = self.export_tables()?;
        let e = |row: u32, col: u32, value: f64| Entry { row, col, value };
        let mut out = Vec::new();
        match kind {
            MatrixKind::VertexAdjacency | MatrixKind::D1 => {
                reserve(&mut out, 2 * t.eh.len(), "matrix entries")?;
                for (id, &h) in t.eh.iter().enumerate() {
                    let (a, b) = (self.v[h as usize], self.v[next(h) as usize]);
                    if kind == MatrixKind::D1 {
                        out.extend([e(a, id as u32, -1.0), e(b, id as u32, 1.0)]);
                    } else {
                        out.extend([e(a, b, 1.0), e(b, a, 1.0)]);
                    }
                }
            }
            MatrixKind::D2 => {
                reserve(&mut out, self.v.len(), "matrix entries")?;
                for (h, &g) in t.o.iter().enumerate() {
                    let sign = if g == NONE || (h as u32) < g {
                        1.0
                    } else {
                        -1.0
                    };
                    out.push(e(t.edge[h], tri(h as u32), sign));
                }
            }
            MatrixKind::DualAdjacency => {
                reserve(&mut out, self.v.len(), "matrix entries")?;
                for (h, &g) in t.o.iter().enumerate() {
                    if g != NONE {
                        out.push(e(tri(h as u32), tri(g), 1.0));
                    }
                }
            }
            MatrixKind::EdgeAdjacency => {
                let ve = self.all_vertex_edges()?;
                for v in 0..ve.len() {
                    let row = ve.get(v);
                    reserve(&mut out, row.len() * row.len(), "matrix entries")?;
                    for &a in row {
                        out.extend(row.iter().filter(|&&b| b != a).map(|&b| e(a, b, 1.0)));
                    }
                }
            }
            MatrixKind::Laplacian => {}
        }
        Ok(out)
    }
}
