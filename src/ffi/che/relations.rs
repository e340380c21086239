//! The nine relations, boundary curves and the half-edge helpers, one element at a time
//! (answers into caller buffers, see `ids!`).

use super::CheMesh;
use crate::ffi::declare::exports;

exports! { CheMesh;
    /// VV: the vertices around `v`, counter-clockwise seen from outside. On a boundary vertex
    /// the list starts at the far end of its outgoing boundary edge and ends at the near end of
    /// its incoming one (d + 1 vertices for d triangles). Empty for an isolated vertex.
    /// O(d) at levels 2-3; O(T) at level 1 (a scan of `V` for the start); O(T) time and memory at level 0 (`O` computed for the call).
    ids fn che_vertex_vertices(v) { check_vertex(v) => |c, s| c.vertex_vertices_into(v, s) }
    /// VE: the edges around `v`, the edge to each vertex of `che_vertex_vertices`, in the same
    /// order. O(d) at levels 2-3; O(T) at level 1 (a scan of `V` for the start; edge ids
    /// from the level-1 directory, computed in O(T) by the first request and kept); O(T) time
    /// and memory at level 0.
    ids fn che_vertex_edges(v) { check_vertex(v) => |c, s| c.vertex_edges_into(v, s) }
    /// VF: the triangles around `v`, counter-clockwise, from the boundary on a boundary vertex.
    /// O(d) at levels 2-3; O(T) at level 1 (a scan of `V` for the start); O(T) time and memory at level 0 (`O` computed for the call).
    ids fn che_vertex_triangles(v) { check_vertex(v) => |c, s| c.vertex_triangles_into(v, s) }
    /// EV: the 2 ends of edge `e`, in the direction of its canonical half-edge (the boundary
    /// half-edge on a boundary edge). O(1) at levels 2-3; O(T) at level 1 (a count of the
    /// canonical half-edges); O(T) time and memory at level 0 (`O` computed for the call).
    ids fn che_edge_vertices(e) { check_edge(e) => |c| c.edge_vertices(e) }
    /// EE: the wings of edge `e` (4 entries, 2 on a boundary edge): the next and previous edges
    /// in the canonical half-edge's triangle, then in the opposite triangle. O(1) at levels
    /// 2-3; O(T) at level 1 (finding the canonical half-edge; edge ids from the level-1
    /// directory); O(T) time and memory at level 0 (`O` computed for the call).
    ids fn che_edge_edges(e) { check_edge(e) => |c| c.edge_edges(e) }
    /// EF: the triangles of edge `e` (2 entries, 1 on a boundary edge), the canonical
    /// half-edge's first. O(1) at levels 2-3; O(T) at level 1 (finding the canonical
    /// half-edge); O(T) time and memory at level 0 (`O` computed for the call).
    ids fn che_edge_triangles(e) { check_edge(e) => |c| c.edge_triangles(e) }
    /// FV: the 3 corners of triangle `t`, counter-clockwise (corner i is the origin of
    /// half-edge 3t + i). O(1) at every level.
    ids fn che_triangle_vertices(t) { check_triangle(t) => |c| c.triangle_vertices(t) }
    /// FE: the 3 edges of triangle `t`; edge i runs from corner i to corner i + 1. O(1) at
    /// levels 2-3; O(1) at level 1 once the level-1 edge-id directory exists (the first
    /// request computes it, O(T), and keeps it); O(T) time and memory at level 0 (`O` computed for the call).
    ids fn che_triangle_edges(t) { check_triangle(t) => |c| c.triangle_edges(t) }
    /// FF: always 3 entries, the triangle across edge i of `t` (see `che_triangle_edges`), or
    /// `TOPOMESH_NONE` across a boundary edge (also across non-manifold and non-orientable
    /// seam edges, which the structure keeps unpaired). O(1) at levels 1-3; O(T) at level 0
    /// (a scan of `V` per edge).
    ids fn che_triangle_triangles(t) { check_triangle(t) => |c| c.triangle_triangles(t) }
    /// The vertices of boundary curve `curve` (0..che_mesh_num_boundary_curves), in order, the
    /// interior on the left; curves are numbered by their smallest half-edge. O(length) at
    /// level 3; O(T) at level 2 (finding the curves' starts) and level 1 (the walk rotates
    /// around each boundary vertex); O(T) time and memory at level 0 (`O` computed for the call).
    ids fn che_boundary_curve_vertices(curve) { try |c| c.boundary_curve_vertices(curve) }
    /// The opposite of half-edge `h` into `*out` (`TOPOMESH_NONE` on the boundary).
    /// O(1) at levels 1-3; O(T) at level 0 (a scan of `V`).
    value fn che_half_edge_opposite(h) -> u32 { check_half_edge(h) => |c| c.opposite(h) }
    /// The edge of half-edge `h` into `*out`. O(1) at levels 2-3; O(1) at level 1 once the
    /// level-1 edge-id directory exists (the first request computes it, O(T), and keeps it);
    /// O(T) time and memory at level 0 (`O` computed for the call).
    value fn che_half_edge_edge(h) -> u32 { check_half_edge(h) => |c| c.edge_of(h) }
    /// The boundary curve of half-edge `h` into `*out` (`TOPOMESH_NONE` when `h` is not on the
    /// boundary). O(1) at level 3; O(T) at levels 1-2 (the curves are walked); O(T) time and memory at level 0 (`O` computed for the call).
    value fn che_half_edge_curve(h) -> u32 { check_half_edge(h) => |c| c.curve_of(h) }
    /// The outgoing half-edge of vertex `v` a rotation starts at into `*out`: the boundary one
    /// on a boundary vertex, `TOPOMESH_NONE` for an isolated vertex. O(1) at levels 2-3; O(T)
    /// at level 1 (a scan of `V`); O(T) time and memory at level 0 (`O` computed for the call).
    value fn che_vertex_half_edge(v) -> u32 { check_vertex(v) => |c| c.vertex_half_edge(v) }
    /// The canonical half-edge of edge `e` into `*out` (the boundary one on a boundary edge,
    /// else the smaller of the two). O(1) at levels 2-3; O(T) at level 1 (a count of the
    /// canonical half-edges); O(T) time and memory at level 0 (`O` computed for the call).
    value fn che_edge_half_edge(e) -> u32 { check_edge(e) => |c| c.edge_half_edge(e) }
    /// Is vertex `v` on the boundary? (`false` for an isolated vertex.) O(1) at levels 2-3;
    /// O(T) at level 1 (a scan of `V`); O(T) time and memory at level 0 (`O` computed for the call).
    value fn che_vertex_is_boundary(v) -> bool { check_vertex(v) => |c| c.is_boundary_vertex(v) }
    /// Is edge `e` on the boundary (one triangle)? O(1) at levels 2-3; O(T) at level 1
    /// (finding the canonical half-edge); O(T) time and memory at level 0 (`O` computed for the call).
    value fn che_edge_is_boundary(e) -> bool { check_edge(e) => |c| c.is_boundary_edge(e) }
}
