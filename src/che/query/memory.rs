//! Exact memory of each container, so the cost of every level is visible.

use crate::che::Che;

/// The fields of [`Memory`], once for it and for its C mirror in `ffi` (see
/// `util::fields`).
macro_rules! memory_fields {
    ($int:ty; $($head:tt)*) => {
        $crate::util::fields::fields_struct! { $($head)* {
            /// `V`, level 0.
            half_edge_vertices: $int,
            /// `O`, level 1; at level 0 once edited, the `O` the edits keep.
            opposites: $int,
            /// `VH`, level 2; below once edited, the `VH` the edits keep.
            vertex_half_edges: $int,
            /// `EH` and the canonical-half-edge rank bits, level 2; once edited, `EH`, the
            /// edge id of each half-edge and the removed-vertex flags (the ids replace the
            /// bits until `garbage_collect`), and below level 2 the live edges' counts.
            edges: $int,
            /// `CH`, the boundary rank bits and the curve of each boundary half-edge, level 3;
            /// once edited, also the boundary half-edges the edits noted and the curves
            /// computed from them.
            curves: $int,
            /// The sum of the above: the topology.
            topology: $int,
            /// Positions (not topology).
            positions: $int,
            /// Origin maps and the non-manifold and seam flags (not topology).
            maps: $int,
        }}
    };
}
pub(crate) use memory_fields;

memory_fields! { usize;
    /// Bytes held by each container (lengths, not capacities).
    #[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
    pub struct Memory
}

impl Che {
    /// On a structure opened mapped, takes the file's pages out of the process's resident
    /// set: they come back from the file (usually from the page cache) when a query next
    /// reads them. A sweep over a file larger than memory calls it every so often to keep
    /// its resident set bounded. Nothing happens on a structure in memory, nor on a system other
    /// than Unix (where the pages stay until the system wants them).
    pub fn release_mapped_pages(&self) -> crate::error::Result<()> {
        match self.v.mapping() {
            Some(map) => crate::levelfile::map::release(map),
            None => Ok(()),
        }
    }

    pub fn memory_bytes(&self) -> Memory {
        let ints = |n: usize| 4 * n;
        let kept = |t: Option<&[u32]>| t.map_or(0, <[u32]>::len);
        let mut m = Memory {
            half_edge_vertices: ints(self.v.len()),
            opposites: ints(self.o.len() + kept(self.kept_opposites())),
            vertex_half_edges: ints(self.vh.len() + kept(self.kept_vertex_half_edges())),
            edges: ints(self.eh.len())
                + self.edge_bits.memory_bytes()
                + self.edits().map_or(0, |s| s.edge_bytes()),
            curves: ints(self.ch.len())
                + ints(self.curve_of.len())
                + self.boundary_bits.memory_bytes()
                + self.edits().map_or(0, |s| s.curve_bytes()),
            positions: std::mem::size_of_val(&self.positions[..]),
            maps: ints(
                self.vertex_origin.len()
                    + self.triangle_origin.len()
                    + self.non_manifold.len()
                    + self.seams.len(),
            ),
            topology: 0,
        };
        m.topology = m.half_edge_vertices + m.opposites + m.vertex_half_edges + m.edges + m.curves;
        m
    }
}
