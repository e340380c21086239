//! Betti numbers over Z/2 of a CHF's complex.

use crate::NONE;
use crate::chf::Chf;
use crate::chf::ids::{half_edge, tet};
use crate::error::Result;
use crate::util::alloc::try_collect;
use crate::util::betti::{forest_lines, peeled_rank};

impl Chf {
    /// `[b0, b1, b2, b3]` over Z/2 of the structure's complex (its vertices, an isolated
    /// one a component of its own, edges, faces and tetrahedra; what the build split stays
    /// apart). `b0 - b1 + b2 - b3` is its Euler characteristic.
    ///
    /// `rank d1` and `rank d3` come from spanning forests (an edge has two ends, a face one
    /// or two tetrahedra). `rank d2` is the rank of `d2` without the forests' lines: the
    /// faces of the forest of tetrahedra are sums of the other faces' columns and the edges
    /// of the forest of vertices carry no boundary (see `forest_lines`); what is left is
    /// peeled of its rows and columns with one entry, and the column reduction of
    /// persistent homology runs on the core only.
    pub fn betti_numbers(&self) -> Result<[u64; 4]> {
        self.check_collected("the Betti numbers")?;
        let (view, [nv, ne, nf, nt]) = self.complex()?;
        let ends = super::matrices::edge_ends(&view, ne)?;
        let edge_forest = forest_lines(nv, ends.iter().map(|&[a, b]| (a, b)))?;
        let face_forest = forest_lines(
            nt,
            (0..nf as u32).map(|f| {
                let hf = view.face_half_face(f);
                let g = view.opposite(hf);
                (tet(hf), if g == NONE { NONE } else { tet(g) })
            }),
        )?;
        let columns = try_collect(
            (0..nf as u32)
                .filter(|&f| !face_forest[f as usize])
                .map(|f| {
                    let hf = view.face_half_face(f);
                    [0, 1, 2].map(|j| {
                        let e = view.edge_of(half_edge(hf, j));
                        if edge_forest[e as usize] { NONE } else { e }
                    })
                }),
            "the columns of d2",
        )?;
        let r2 = peeled_rank(ne, &columns)? as u64;
        let count = |forest: &[bool]| forest.iter().filter(|&&x| x).count() as u64;
        let (r1, r3) = (count(&edge_forest), count(&face_forest));
        Ok([
            nv as u64 - r1,
            ne as u64 - r1 - r2,
            nf as u64 - r2 - r3,
            nt as u64 - r3,
        ])
    }
}
