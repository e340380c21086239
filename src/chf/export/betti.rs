//! Betti numbers over Z/2 of a CHF's complex.

use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::{half_edge, tet};
use crate::chf::query::view::Need;
use crate::error::Result;
use crate::util::betti::{Grounded, column_rank};

impl Chf {
    /// `[b0, b1, b2, b3]` over Z/2 of the structure's complex (its vertices, an isolated
    /// one a component of its own, edges, faces and tetrahedra; what the build split stays
    /// apart). `b0 - b1 + b2 - b3` is its Euler characteristic.
    ///
    /// `rank d1` and `rank d3` come from union-finds (an edge has two ends, a face one or
    /// two tetrahedra); `rank d2` from the column reduction of persistent homology over the
    /// faces' edges, which is not linear: reduced columns grow with the mesh, so on large
    /// meshes this is much slower than the other exports (which is why `topomesh info`
    /// prints Betti numbers for surfaces only).
    pub fn betti_numbers(&self) -> Result<[u64; 4]> {
        let view = self.view(Need {
            faces: true,
            edges: true,
        });
        let (nv, ne, nf, nt) = (
            self.n_vertices,
            self.num_edges(),
            self.num_faces(),
            self.num_tetrahedra(),
        );
        let ends = super::matrices::edge_ends(&view, ne);
        let r1 = Grounded::new(nv, ends.iter().map(|&[a, b]| (a, b)))?.rank();
        let tets = (0..view.o.len() as u32)
            .filter(|&hf| view.canonical_half_face(hf) == hf)
            .map(|hf| {
                let g = view.opposite(hf);
                (tet(hf), if g == NONE { NONE } else { tet(g) })
            });
        let r3 = Grounded::new(nt, tets)?.rank();
        let columns = (0..nf as u32).map(|f| {
            let hf = view.face_half_face(f);
            let mut c: Vec<u32> = (0..3).map(|j| view.edge_of(half_edge(hf, j))).collect();
            c.sort_unstable();
            c
        });
        let r2 = column_rank(ne, columns);
        let (r1, r2, r3) = (r1 as u64, r2 as u64, r3 as u64);
        Ok([
            nv as u64 - r1,
            ne as u64 - r1 - r2,
            nf as u64 - r2 - r3,
            nt as u64 - r3,
        ])
    }
}
