//! Sparse matrices of the structure, in CSR with sorted columns (see `SparseMatrix`).

use crate::NONE;
use crate::che::Che;
use crate::che::ids::{next, tri};
use crate::error::Result;
use crate::util::sparse::{Entry, SparseMatrix, filled, reserve};

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
        self.check_collected("the matrix export")?;
        let (nv, ne, nt) = (self.n_vertices, self.num_edges, self.num_triangles());
        let entries = match kind {
            MatrixKind::VertexAdjacency | MatrixKind::Laplacian => return self.vertex_rows(kind),
            _ => self.matrix_entries(kind)?,
        };
        match kind {
            MatrixKind::EdgeAdjacency => Ok(pattern(SparseMatrix::from_entries(ne, ne, &entries)?)),
            MatrixKind::D1 => SparseMatrix::from_entries(nv, ne, &entries),
            MatrixKind::D2 => SparseMatrix::from_entries(ne, nt, &entries),
            _ => Ok(pattern(SparseMatrix::from_entries(nt, nt, &entries)?)),
        }
    }

    /// The vertex adjacency, or the Laplacian (`kind`), straight from the half-edges: a
    /// counting pass sizes the rows, a second fills them, and each short row is sorted and
    /// rid of repeats in place, so no entry list is built or sorted as a whole.
    fn vertex_rows(&self, kind: MatrixKind) -> Result<SparseMatrix> {
        let o = self.opposites_or_computed();
        let nv = self.n_vertices;
        let diagonal = kind == MatrixKind::Laplacian;
        // Row `V[h]` takes the head of every `h`; a boundary half-edge also gives its tail
        // to its head's row, which no half-edge leaving the head reaches back to. Repeats
        // (an edge split by the build) go in the per-row pass.
        let mut offsets = filled(nv + 1, u64::from(diagonal), "matrix offsets")?;
        offsets[0] = 0;
        for (h, &g) in o.iter().enumerate() {
            offsets[self.v[h] as usize + 1] += 1;
            if g == NONE {
                offsets[self.v[next(h as u32) as usize] as usize + 1] += 1;
            }
        }
        for r in 0..nv {
            offsets[r + 1] += offsets[r];
        }
        let mut columns = filled(offsets[nv] as usize, 0u32, "matrix columns")?;
        // `offsets[r]` walks row r as a cursor, ending at the start of row r + 1.
        let mut put = |row: u32, col: u32| {
            let slot = &mut offsets[row as usize];
            columns[*slot as usize] = col;
            *slot += 1;
        };
        for v in (0..nv as u32).filter(|_| diagonal) {
            put(v, v);
        }
        for (h, &g) in o.iter().enumerate() {
            let (a, b) = (self.v[h], self.v[next(h as u32) as usize]);
            put(a, b);
            if g == NONE {
                put(b, a);
            }
        }
        let values = compact_rows(&mut offsets, &mut columns, diagonal)?;
        Ok(SparseMatrix {
            n_rows: nv,
            n_cols: nv,
            offsets,
            columns,
            values,
        })
    }

    /// The (row, column, value) entries of `kind` (none for the vertex adjacency and the
    /// Laplacian, made from the half-edges directly).
    fn matrix_entries(&self, kind: MatrixKind) -> Result<Vec<Entry>> {
        let t = self.export_tables()?;
        let e = |row: u32, col: u32, value: f64| Entry { row, col, value };
        let mut out = Vec::new();
        match kind {
            MatrixKind::D1 => {
                reserve(&mut out, 2 * t.eh.len(), "matrix entries")?;
                for (id, &h) in t.eh.iter().enumerate() {
                    let (a, b) = (self.v[h as usize], self.v[next(h) as usize]);
                    out.extend([e(a, id as u32, -1.0), e(b, id as u32, 1.0)]);
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
            MatrixKind::VertexAdjacency | MatrixKind::Laplacian => {}
        }
        Ok(out)
    }
}

/// Sorts every row of `columns` and keeps each column once, in place; rows end where
/// `offsets` says (`offsets[r]` the end of row r, as the filling cursors leave them), and
/// `offsets` becomes the CSR offsets of what is kept. The values are 1 (an adjacency), or
/// with `diagonal` -1 off the diagonal and the number of other columns on it (the
/// Laplacian, whose rows hold their own vertex).
fn compact_rows(offsets: &mut [u64], columns: &mut Vec<u32>, diagonal: bool) -> Result<Vec<f64>> {
    let n = offsets.len() - 1;
    let mut values = Vec::new();
    reserve(&mut values, columns.len(), "matrix values")?;
    let (mut start, mut w) = (0usize, 0usize);
    for (r, slot) in offsets[..n].iter_mut().enumerate() {
        let (end, first) = (*slot as usize, w);
        *slot = w as u64;
        columns[start..end].sort_unstable();
        let mut diag = None;
        for i in start..end {
            let c = columns[i];
            if w > first && columns[w - 1] == c {
                continue;
            }
            if c as usize == r && diagonal {
                diag = Some(w);
            }
            columns[w] = c;
            values.push(if diagonal { -1.0 } else { 1.0 });
            w += 1;
        }
        if let Some(d) = diag {
            values[d] = (w - first - 1) as f64;
        }
        start = end;
    }
    offsets[n] = w as u64;
    columns.truncate(w);
    Ok(values)
}
