// topomesh C++ wrapper, implementation: the classic representations exported from a built
// Surface or Volume (half-edge, winged-edge, corner table, lists, sparse matrices, Betti
// numbers, triangle strips; half-face arrays, dual graph, matrices, Betti numbers). Each is
// one size query and one fill through the C calls che_mesh_export_* / chf_mesh_export_*,
// whose documentation in topomesh.h gives the exact layouts.
//
// Included by topomesh.hpp; not a header of its own.
#ifndef TOPOMESH_DETAIL_EXPORT_HPP
#define TOPOMESH_DETAIL_EXPORT_HPP

#include <cstddef>
#include <cstdint>
#include <vector>

namespace topomesh {
namespace detail {

/// The vector an `(buf, cap, out_len)` export fills: a size query, then the fill.
template <class F> std::vector<std::uint32_t> exported(F fill) {
    std::size_t len = 0;
    check(fill(nullptr, 0, &len));
    std::vector<std::uint32_t> out(len);
    std::uint32_t dummy = 0;
    check(fill(out.empty() ? &dummy : out.data(), len, &len));
    out.resize(len);
    return out;
}

/// A matrix export (che_mesh_export_matrix or chf_mesh_export_matrix) of `cols` columns.
template <class M, class F>
CsrMatrix exported_matrix(F f, const M *m, std::uint32_t kind, std::size_t cols) {
    std::size_t n_offsets = 0, n_entries = 0;
    check(f(m, kind, nullptr, 0, nullptr, 0, nullptr, 0, &n_offsets, &n_entries));
    CsrMatrix out;
    out.offsets.resize(n_offsets);
    out.columns.resize(n_entries);
    out.values.resize(n_entries);
    std::uint64_t o = 0;
    std::uint32_t c = 0;
    double v = 0;
    check(f(m, kind, out.offsets.empty() ? &o : out.offsets.data(), n_offsets,
            out.columns.empty() ? &c : out.columns.data(), n_entries,
            out.values.empty() ? &v : out.values.data(), n_entries, &n_offsets, &n_entries));
    out.rows = n_offsets == 0 ? 0 : n_offsets - 1;
    out.cols = cols;
    return out;
}

} // namespace detail

// Surface.

inline HalfEdges Surface::halfedge(HalfEdgeOptions options) const {
    che_half_edge_options o{};
    o.explicit_boundary = options.explicit_boundary;
    auto array = [&](che_half_edge_array which) {
        return detail::exported([&](std::uint32_t *b, std::size_t c, std::size_t *n) {
            return che_mesh_export_half_edges(m_, &o, which, b, c, n);
        });
    };
    HalfEdges out;
    out.next = array(CHE_HALF_EDGE_ARRAY_NEXT);
    out.prev = array(CHE_HALF_EDGE_ARRAY_PREV);
    out.twin = array(CHE_HALF_EDGE_ARRAY_TWIN);
    out.vertex = array(CHE_HALF_EDGE_ARRAY_VERTEX);
    out.face = array(CHE_HALF_EDGE_ARRAY_FACE);
    out.edge = array(CHE_HALF_EDGE_ARRAY_EDGE);
    out.vertex_half_edge = array(CHE_HALF_EDGE_ARRAY_VERTEX_HALF_EDGE);
    out.face_half_edge = array(CHE_HALF_EDGE_ARRAY_FACE_HALF_EDGE);
    return out;
}

inline WingedEdges Surface::winged() const {
    auto array = [&](che_winged_array which) {
        return detail::exported([&](std::uint32_t *b, std::size_t c, std::size_t *n) {
            return che_mesh_export_winged_edges(m_, which, b, c, n);
        });
    };
    WingedEdges out;
    out.vertices = array(CHE_WINGED_ARRAY_VERTICES);
    out.faces = array(CHE_WINGED_ARRAY_FACES);
    out.wings = array(CHE_WINGED_ARRAY_WINGS);
    out.vertex_edge = array(CHE_WINGED_ARRAY_VERTEX_EDGE);
    out.face_edge = array(CHE_WINGED_ARRAY_FACE_EDGE);
    return out;
}

inline CornerTable Surface::corner() const {
    CornerTable out;
    out.V = detail::exported([&](std::uint32_t *b, std::size_t c, std::size_t *n) {
        return che_mesh_export_half_edges(m_, nullptr, CHE_HALF_EDGE_ARRAY_VERTEX, b, c, n);
    });
    out.O = detail::exported([&](std::uint32_t *b, std::size_t c, std::size_t *n) {
        return che_mesh_export_corner_opposites(m_, b, c, n);
    });
    return out;
}

inline std::vector<std::uint32_t> Surface::edge_list() const {
    return detail::exported([&](std::uint32_t *b, std::size_t c, std::size_t *n) {
        return che_mesh_export_edge_list(m_, b, c, n);
    });
}

inline std::vector<std::uint32_t> Surface::triangle_edges() const {
    return detail::exported([&](std::uint32_t *b, std::size_t c, std::size_t *n) {
        return che_mesh_export_triangle_edges(m_, b, c, n);
    });
}

inline std::vector<std::uint32_t> Surface::strips(StripList which) const {
    return detail::exported([&](std::uint32_t *b, std::size_t c, std::size_t *n) {
        return che_mesh_export_strips(m_, static_cast<std::uint32_t>(which), b, c, n);
    });
}

inline CsrMatrix Surface::matrix(che_matrix_kind kind) const {
    std::size_t cols = num_vertices();
    if (kind == CHE_MATRIX_KIND_EDGE_ADJACENCY || kind == CHE_MATRIX_KIND_D1) cols = num_edges();
    if (kind == CHE_MATRIX_KIND_D2 || kind == CHE_MATRIX_KIND_DUAL_ADJACENCY)
        cols = num_triangles();
    return detail::exported_matrix(che_mesh_export_matrix, m_, kind, cols);
}

inline SurfaceBetti Surface::betti() const {
    che_betti b{};
    detail::check(che_mesh_betti_numbers(m_, &b));
    return SurfaceBetti{b.b0, b.b1, b.b2};
}

// Volume.

inline HalfFaces Volume::halfface() const {
    auto array = [&](chf_half_face_array which) {
        return detail::exported([&](std::uint32_t *b, std::size_t c, std::size_t *n) {
            return chf_mesh_export_half_faces(m_, which, b, c, n);
        });
    };
    HalfFaces out;
    out.twin = array(CHF_HALF_FACE_ARRAY_TWIN);
    out.vertices = array(CHF_HALF_FACE_ARRAY_VERTICES);
    out.face = array(CHF_HALF_FACE_ARRAY_FACE);
    return out;
}

inline std::vector<std::uint32_t> Volume::dual_graph() const {
    return detail::exported([&](std::uint32_t *b, std::size_t c, std::size_t *n) {
        return chf_mesh_export_dual_graph(m_, b, c, n);
    });
}

inline CsrMatrix Volume::matrix(chf_matrix_kind kind) const {
    std::size_t cols = num_edges();
    if (kind == CHF_MATRIX_KIND_D2) cols = num_faces();
    if (kind == CHF_MATRIX_KIND_D3 || kind == CHF_MATRIX_KIND_DUAL_ADJACENCY)
        cols = num_tetrahedra();
    return detail::exported_matrix(chf_mesh_export_matrix, m_, kind, cols);
}

inline VolumeBetti Volume::betti() const {
    chf_betti b{};
    detail::check(chf_mesh_betti_numbers(m_, &b));
    return VolumeBetti{b.b0, b.b1, b.b2, b.b3};
}

} // namespace topomesh

#endif // TOPOMESH_DETAIL_EXPORT_HPP
