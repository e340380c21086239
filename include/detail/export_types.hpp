// topomesh C++ wrapper: the types of the exports (Surface::halfedge(), winged(), corner(),
// matrix(), betti(), strips(); Volume::halfface(), matrix(), betti()). Each holds plain
// vectors in the layouts that topomesh.h documents for che_mesh_export_* and
// chf_mesh_export_*.
//
// Included by topomesh.hpp; not a header of its own.
#ifndef TOPOMESH_DETAIL_EXPORT_TYPES_HPP
#define TOPOMESH_DETAIL_EXPORT_TYPES_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

namespace topomesh {

/// How Surface::halfedge() shows the boundary (che_half_edge_options).
struct HalfEdgeOptions {
    /// false: only the 3T half-edges of the triangles, twin `none` on the boundary; true
    /// (OpenMesh style): one extra half-edge per boundary half-edge, numbered from 3T,
    /// face `none`, linked by next and prev round each hole.
    bool explicit_boundary = false;
};

/// Half-edge (DCEL) arrays: per half-edge next, prev, twin, vertex (its tail), face,
/// edge; per vertex one outgoing half-edge; per triangle t its half-edge 3t.
struct HalfEdges {
    std::vector<std::uint32_t> next, prev, twin, vertex, face, edge;
    std::vector<std::uint32_t> vertex_half_edge, face_half_edge;
};

/// Winged-edge table: per edge 2 vertices, 2 faces (left, right) and 4 wings (before and
/// after it round the left face, then the right one); per vertex and triangle one edge.
struct WingedEdges {
    std::vector<std::uint32_t> vertices, faces, wings, vertex_edge, face_edge;
};

/// Rossignac's corner table: corner c is half-edge c, V[c] its vertex, O[c] the opposite
/// corner (`none` on the boundary).
struct CornerTable {
    std::vector<std::uint32_t> V, O;
};

/// A sparse matrix in CSR: row r holds columns[offsets[r] .. offsets[r + 1]] (sorted) with
/// values at the same places (Eigen: see <topomesh/eigen.hpp>; SciPy: csr_matrix((values,
/// columns, offsets), shape=(rows, cols))).
struct CsrMatrix {
    std::size_t rows = 0, cols = 0;
    std::vector<std::uint64_t> offsets;
    std::vector<std::uint32_t> columns;
    std::vector<double> values;
    std::size_t nonzeros() const noexcept { return columns.size(); }
};

/// Betti numbers over Z/2.
struct SurfaceBetti {
    std::uint64_t b0 = 0, b1 = 0, b2 = 0;
};
struct VolumeBetti {
    std::uint64_t b0 = 0, b1 = 0, b2 = 0, b3 = 0;
};

/// Which strip list Surface::strips() gives (che_strip_list).
enum class StripList : std::uint32_t {
    /// The strips one after another, separated by `none` (primitive restart).
    restarts = CHE_STRIP_LIST_RESTARTS,
    /// One strip, the strips joined by degenerate triangles.
    joined = CHE_STRIP_LIST_JOINED,
};

/// Half-face arrays: per half-face its twin and face, 3 vertices per half-face (outward).
struct HalfFaces {
    std::vector<std::uint32_t> twin, vertices, face;
};

} // namespace topomesh

#endif // TOPOMESH_DETAIL_EXPORT_TYPES_HPP
