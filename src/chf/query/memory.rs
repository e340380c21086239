//! Exact memory of each container, so the cost of every level is visible.

use crate::chf::Chf;

/// Bytes held by each container (lengths, not capacities).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Memory {
    /// `V`, level 0.
    pub half_face_vertices: usize,
    /// `O`, level 1.
    pub opposites: usize,
    /// `VH`, level 2.
    pub vertex_half_faces: usize,
    /// The canonical-slot rank bits and the tetrahedron of each edge, level 2; once edited,
    /// the explicit edge ids and the removed marks.
    pub edges: usize,
    /// The canonical-half-face rank bits and `FH`, level 2; once edited, the explicit face
    /// ids.
    pub faces: usize,
    /// The boundary CHE's topology, the boundary rank bits, the triangle -> half-face map
    /// and the component of each vertex, level 3.
    pub boundary: usize,
    /// The sum of the above: the topology.
    pub topology: usize,
    /// Positions (not topology).
    pub positions: usize,
    /// Origin maps, the non-manifold and seam flags, the several-fan pairs (not topology).
    pub maps: usize,
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
