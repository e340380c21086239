//! Sparse matrices of the structure, in CSR with sorted columns (see `SparseMatrix`).

use crate::NONE;
use crate::che::Che;
use crate::che::Csr;
use crate::che::export::ExportTables;
use crate::che::ids::{next, tri};
use crate::error::Result;
use crate::util::sparse::{
    Assembled, Entries, Put, Shape, SparseMatrix, Storage, Values, assemble,
};

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

impl Che {
    /// The matrix `kind`, in CSR with sorted columns; see [`MatrixKind`].
    pub fn matrix(&self, kind: MatrixKind) -> Result<SparseMatrix> {
        self.matrix_into(kind, &mut |_, _| None)?.owned()
    }

    /// The matrix `kind` in the storage `offer` gives once the size is known (see
    /// [`Storage`]), else in memory of its own.
    pub fn matrix_into(&self, kind: MatrixKind, offer: Storage) -> Result<Assembled> {
        self.check_collected("the matrix export")?;
        let (nv, ne, nt) = (self.n_vertices, self.num_edges, self.num_triangles());
        let pattern = |off| Values::Pattern {
            off,
            degree_diagonal: false,
        };
        let shape = |n_rows, n_cols, values| Shape {
            n_rows,
            n_cols,
            values,
        };
        match kind {
            MatrixKind::VertexAdjacency | MatrixKind::Laplacian => {
                let laplacian = kind == MatrixKind::Laplacian;
                let values = match laplacian {
                    true => Values::Pattern {
                        off: -1.0,
                        degree_diagonal: true,
                    },
                    false => pattern(1.0),
                };
                let o = self.try_opposites_or_computed()?;
                let diagonal = laplacian.then_some(nv as u32);
                // A half-edge gives one entry, a boundary one two; an edge has two
                // half-edges or is a boundary one, so 2E - 3T half-edges are.
                let boundary = (2 * ne).checked_sub(3 * nt);
                let pairs = VertexPairs {
                    v: &self.v,
                    o: &o,
                    diagonal,
                    total: boundary.map(|b| 3 * nt + b + diagonal.map_or(0, |n| n as usize)),
                };
                assemble(shape(nv, nv, values), &pairs, offer)
            }
            MatrixKind::EdgeAdjacency => {
                let ve = self.all_vertex_edges()?;
                assemble(shape(ne, ne, pattern(1.0)), &EdgePairs(&ve), offer)
            }
            MatrixKind::D1 | MatrixKind::D2 | MatrixKind::DualAdjacency => {
                let t = self.export_tables()?;
                let entries = Incidence {
                    che: self,
                    t: &t,
                    kind,
                };
                let size = match kind {
                    MatrixKind::D1 => shape(nv, ne, Values::Summed),
                    MatrixKind::D2 => shape(ne, nt, Values::Summed),
                    _ => shape(nt, nt, pattern(1.0)),
                };
                assemble(size, &entries, offer)
            }
        }
    }
}

/// The vertex adjacency's entries from the half-edges: row `V[h]` takes the head of every
/// `h`; a boundary half-edge also gives its tail to its head's row, which no half-edge
/// leaving the head reaches back to. With `diagonal` (the number of vertices), every row
/// also holds its own vertex. Repeats (an edge split by the build) merge in the rows.
struct VertexPairs<'a> {
    v: &'a [u32],
    o: &'a [u32],
    diagonal: Option<u32>,
    /// The number of entries, from the counts of the mesh.
    total: Option<usize>,
}

impl Entries for VertexPairs<'_> {
    fn total(&self) -> Option<usize> {
        self.total
    }

    fn each<P: Put>(&self, p: &mut P) {
        for v in 0..self.diagonal.unwrap_or(0) {
            p.put(v, v, 0.0);
        }
        // A triangle at a time: its three half-edges without an index computation each.
        for (c, o) in self.v.chunks_exact(3).zip(self.o.chunks_exact(3)) {
            for (i, j) in [(0, 1), (1, 2), (2, 0)] {
                p.put(c[i], c[j], 1.0);
                if o[i] == NONE {
                    p.put(c[j], c[i], 1.0);
                }
            }
        }
    }
}

/// The edge adjacency's entries: every two edges of a vertex's star.
struct EdgePairs<'a>(&'a Csr);

impl Entries for EdgePairs<'_> {
    fn each<P: Put>(&self, p: &mut P) {
        for v in 0..self.0.len() {
            let row = self.0.get(v);
            for &a in row {
                row.iter()
                    .filter(|&&b| b != a)
                    .for_each(|&b| p.put(a, b, 1.0));
            }
        }
    }
}

/// The entries of d1, d2 or the dual graph, from the export tables.
struct Incidence<'a> {
    che: &'a Che,
    t: &'a ExportTables<'a>,
    kind: MatrixKind,
}

impl Entries for Incidence<'_> {
    // The dual graph's rows come in order (one triangle's half-edges after another's).
    fn rows_in_order(&self) -> bool {
        self.kind == MatrixKind::DualAdjacency
    }

    fn each<P: Put>(&self, p: &mut P) {
        let (v, t) = (&self.che.v, self.t);
        match self.kind {
            MatrixKind::D1 => {
                for (id, &h) in t.eh.iter().enumerate() {
                    let (a, b) = (v[h as usize], v[next(h) as usize]);
                    p.put(a, id as u32, -1.0);
                    p.put(b, id as u32, 1.0);
                }
            }
            MatrixKind::D2 => {
                for h in 0..t.o.len() {
                    let along = crate::che::tables::is_canonical(&t.o, h);
                    p.put(t.edge[h], tri(h as u32), if along { 1.0 } else { -1.0 });
                }
            }
            _ => {
                for (h, &g) in t.o.iter().enumerate().filter(|(_, g)| **g != NONE) {
                    p.put(tri(h as u32), tri(g), 1.0);
                }
            }
        }
    }
}
