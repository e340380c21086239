//! The winged-edge table (Baumgart): per edge its ends, its two faces and its four wings.

use crate::NONE;
use crate::che::Che;
use crate::che::ids::{next, prev, tri};
use crate::error::Result;
use crate::util::alloc::try_collect;
use crate::util::sparse::reserve;

/// A winged-edge table over the structure's edge ids. Edge `e` has the canonical
/// half-edge `h` (`Che::edge_half_edge`) from `vertices[2e]` to `vertices[2e + 1]`; its
/// left face `faces[2e] = h / 3` runs along it that way, its right face `faces[2e + 1]` the
/// other way (`NONE` on the boundary). The wings are `wings[4e..4e + 4]`: the predecessor
/// and successor of `e` round the left face (the edges before and after it
/// counter-clockwise), then the predecessor and successor round the right face (`NONE`
/// twice on the boundary).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct WingedEdges {
    pub vertices: Vec<u32>,
    pub faces: Vec<u32>,
    pub wings: Vec<u32>,
    /// One edge per vertex (the edge of its starting half-edge), `NONE` when isolated.
    pub vertex_edge: Vec<u32>,
    /// One edge per triangle: the edge of its first half-edge `3t`.
    pub face_edge: Vec<u32>,
}

impl Che {
    /// The winged-edge table; see [`WingedEdges`] for the layout.
    pub fn winged_edges(&self) -> Result<WingedEdges> {
        self.check_collected("the winged-edge export")?;
        let t = self.export_tables()?;
        let mut w = WingedEdges::default();
        let ne = self.num_edges;
        reserve(&mut w.vertices, 2 * ne, "winged-edge vertices")?;
        reserve(&mut w.faces, 2 * ne, "winged-edge faces")?;
        reserve(&mut w.wings, 4 * ne, "winged-edge wings")?;
        for &h in t.eh.iter() {
            let g = t.o[h as usize];
            w.vertices
                .extend([self.v[h as usize], self.v[next(h) as usize]]);
            let edge = |x: u32| t.edge[x as usize];
            w.wings.extend([edge(prev(h)), edge(next(h))]);
            if g == NONE {
                w.faces.extend([tri(h), NONE]);
                w.wings.extend([NONE, NONE]);
            } else {
                w.faces.extend([tri(h), tri(g)]);
                w.wings.extend([edge(prev(g)), edge(next(g))]);
            }
        }
        let of = |h: u32| if h == NONE { NONE } else { t.edge[h as usize] };
        w.vertex_edge = try_collect(t.vh.iter().map(|&h| of(h)), "winged-edge vertex edges")?;
        let first_edges = (0..self.num_triangles()).map(|f| t.edge[3 * f]);
        w.face_edge = try_collect(first_edges, "winged-edge face edges")?;
        Ok(w)
    }
}
