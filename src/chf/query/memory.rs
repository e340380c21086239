//! Exact memory of each container, so the cost of every level is visible.

use crate::chf::Chf;

/// The fields of [`Memory`], once for it and for its C mirror in `ffi` (see
/// `util::fields`).
macro_rules! memory_fields {
    ($int:ty; $($head:tt)*) => {
        $crate::util::fields::fields_struct! { $($head)* {
            /// `V`, level 0.
            half_face_vertices: $int,
            /// `O`, level 1.
            opposites: $int,
            /// `VH`, level 2.
            vertex_half_faces: $int,
            /// The canonical-slot rank bits and the tetrahedron of each edge, level 2; once edited,
            /// the explicit edge ids and the removed marks.
            edges: $int,
            /// The canonical-half-face rank bits and `FH`, level 2; once edited, the explicit face
            /// ids.
            faces: $int,
            /// The boundary CHE's topology, the boundary rank bits, the triangle -> half-face map
            /// and the component of each vertex, level 3.
            boundary: $int,
            /// The sum of the above: the topology.
            topology: $int,
            /// Positions (not topology).
            positions: $int,
            /// Origin maps, the non-manifold and seam flags, the several-fan pairs (not topology).
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

impl Chf {
    /// On a structure opened mapped, takes the file's pages out of the resident set, as
    /// [`Che::release_mapped_pages`](crate::Che::release_mapped_pages) does.
    pub fn release_mapped_pages(&self) -> crate::error::Result<()> {
        self.v
            .mapping()
            .map_or(Ok(()), crate::levelfile::map::release)
    }

    pub fn memory_bytes(&self) -> Memory {
        let ints = |n: usize| 4 * n;
        let mut m = Memory {
            half_face_vertices: ints(self.v.len()),
            opposites: ints(self.o.len()),
            vertex_half_faces: ints(self.vh.len()),
            edges: ints(self.eh.len())
                + self.edge_bits.memory_bytes()
                + self.edit.as_ref().map_or(0, |s| s.edge_bytes()),
            faces: ints(self.fh.len())
                + self.face_bits.memory_bytes()
                + self.edit.as_ref().map_or(0, |s| s.face_bytes()),
            boundary: self.boundary.as_ref().map_or(0, |b| b.memory_bytes())
                + self.edit.as_ref().map_or(0, |s| s.boundary.memory_bytes()),
            positions: std::mem::size_of_val(&self.positions[..]),
            maps: ints(
                self.vertex_origin.len()
                    + self.tet_origin.len()
                    + self.non_manifold.len()
                    + self.seams.len(),
            ) + std::mem::size_of_val(&self.multi_fan[..]),
            topology: 0,
        };
        m.topology = m.half_face_vertices
            + m.opposites
            + m.vertex_half_faces
            + m.edges
            + m.faces
            + m.boundary;
        m
    }
}
