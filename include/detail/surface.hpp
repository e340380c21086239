// topomesh C++ wrapper, implementation: the member functions of topomesh::Surface.
//
// Included by topomesh.hpp; not a header of its own.
#ifndef TOPOMESH_DETAIL_SURFACE_HPP
#define TOPOMESH_DETAIL_SURFACE_HPP

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace topomesh {

// Create and free.

inline Surface Surface::from_triangles(const std::uint32_t *triangles, std::size_t n_triangles,
                                       std::size_t n_vertices, const double *positions,
                                       Options options) {
    che_build_options o = detail::che_options(options);
    che_mesh *m = nullptr;
    detail::check(
        che_mesh_from_triangles_ex(triangles, n_triangles, n_vertices, positions, &o, &m));
    return Surface(m);
}

inline Surface Surface::from_triangles(const std::vector<std::uint32_t> &triangles,
                                       std::size_t n_vertices,
                                       const std::vector<double> &positions, Options options) {
    detail::check_arrays(triangles.size(), 3, "triangle", positions.size(), n_vertices);
    return from_triangles(triangles.data(), triangles.size() / 3, n_vertices,
                          positions.empty() ? nullptr : positions.data(), options);
}

inline Surface Surface::load(const std::string &path, Options options) {
    che_build_options o = detail::che_options(options);
    che_mesh *m = nullptr;
    detail::check(che_mesh_load_ex(path.c_str(), &o, &m));
    return Surface(m);
}

inline Surface Surface::open(const std::string &path, std::uint32_t flags) {
    che_mesh *m = nullptr;
    detail::check(che_mesh_open(path.c_str(), flags, &m));
    return Surface(m);
}

inline Surface::Surface(che_mesh *adopt) noexcept : m_(adopt) { views_.fetch(m_); }

inline Surface::Surface(Surface &&other) noexcept
    : m_(std::exchange(other.m_, nullptr)), views_(std::exchange(other.views_, {})) {}

inline Surface &Surface::operator=(Surface &&other) noexcept {
    if (this != &other) {
        che_mesh_free(m_);
        m_ = std::exchange(other.m_, nullptr);
        views_ = std::exchange(other.views_, {});
    }
    return *this;
}

inline Surface::~Surface() { che_mesh_free(m_); }

inline che_mesh *Surface::release() noexcept {
    views_ = {};
    return std::exchange(m_, nullptr);
}

// Level and counts.

inline std::uint32_t Surface::level() const noexcept { return che_mesh_level(m_); }
inline void Surface::build_level(std::uint32_t level) {
    const topomesh_status s = che_mesh_build_level(m_, level);
    views_.fetch(m_);
    detail::check(s);
}
// The counts the views were fetched with (every edit and change of level fetches them
// again): no call into the library in a loop over the ids.
inline std::size_t Surface::num_vertices() const noexcept { return views_.nv; }
inline std::size_t Surface::num_input_vertices() const noexcept {
    return che_mesh_num_input_vertices(m_);
}
inline std::size_t Surface::num_triangles() const noexcept { return views_.nt; }
inline std::size_t Surface::num_edges() const noexcept { return views_.ne; }
inline std::size_t Surface::num_half_edges() const noexcept { return che_mesh_num_half_edges(m_); }
inline std::size_t Surface::num_boundary_curves() const noexcept {
    return che_mesh_num_boundary_curves(m_);
}

// Per-element relations: inline where the level stores what they read, else the C call.
// Each fills one `out` (returned by every path, so never copied). Writing ids into it:
// detail::IdsWriter.
using detail::IdsWriter;

inline Ids<VertexId> Surface::vertex_vertices(VertexId v) const {
    Ids<VertexId> out;
    if (views_.star(v.value()))
        detail::walk_star<detail::StarPart::vertex>(views_, v.value(), out);
    else
        IdsWriter::call(out, che_vertex_vertices, m_, v.value());
    return out;
}

inline Ids<EdgeId> Surface::vertex_edges(VertexId v) const {
    Ids<EdgeId> out;
    if (views_.star(v.value())) { // the edge ids need the directory: the C step, inline
        che_star_iter it;
        detail::check(che_star_begin(m_, v.value(), &it));
        che_star_step s;
        while (che_star_next(&it, &s)) IdsWriter::push(out, s.edge);
    } else {
        IdsWriter::call(out, che_vertex_edges, m_, v.value());
    }
    return out;
}

inline Ids<TriangleId> Surface::vertex_triangles(VertexId v) const {
    Ids<TriangleId> out;
    if (views_.star(v.value()))
        detail::walk_star<detail::StarPart::triangle>(views_, v.value(), out);
    else
        IdsWriter::call(out, che_vertex_triangles, m_, v.value());
    return out;
}

inline Ids<VertexId, 2> Surface::edge_vertices(EdgeId e) const {
    Ids<VertexId, 2> out;
    if (views_.EH != nullptr && views_.edge(e.value())) {
        const std::uint32_t h = views_.EH[e.value()];
        IdsWriter::set(out, views_.V[h], views_.V[che_next(h)]);
    } else {
        IdsWriter::call_exact(out, che_edge_vertices, m_, e.value());
    }
    return out;
}

inline Ids<EdgeId, 4> Surface::edge_edges(EdgeId e) const {
    Ids<EdgeId, 4> out;
    IdsWriter::call(out, che_edge_edges, m_, e.value());
    return out;
}

inline Ids<TriangleId, 2> Surface::edge_triangles(EdgeId e) const {
    Ids<TriangleId, 2> out;
    if (views_.EH != nullptr && views_.edge(e.value())) {
        const std::uint32_t h = views_.EH[e.value()], g = views_.O[h];
        if (g != none)
            IdsWriter::set(out, che_tri(h), che_tri(g));
        else
            IdsWriter::set(out, che_tri(h));
    } else {
        IdsWriter::call(out, che_edge_triangles, m_, e.value());
    }
    return out;
}

inline Ids<VertexId, 3> Surface::triangle_vertices(TriangleId t) const {
    Ids<VertexId, 3> out;
    if (views_.V != nullptr && views_.triangle(t.value())) {
        const std::uint32_t *c = views_.V + che_first(t.value());
        IdsWriter::set(out, c[0], c[1], c[2]);
    } else {
        IdsWriter::call_exact(out, che_triangle_vertices, m_, t.value());
    }
    return out;
}

inline Ids<EdgeId, 3> Surface::triangle_edges(TriangleId t) const {
    Ids<EdgeId, 3> out;
    IdsWriter::call_exact(out, che_triangle_edges, m_, t.value());
    return out;
}

inline Ids<TriangleId, 3> Surface::triangle_triangles(TriangleId t) const {
    Ids<TriangleId, 3> out;
    if (views_.O != nullptr && views_.triangle(t.value())) {
        const std::uint32_t *o = views_.O + che_first(t.value());
        const auto across = [](std::uint32_t g) { return g == none ? none : che_tri(g); };
        IdsWriter::set(out, across(o[0]), across(o[1]), across(o[2]));
    } else {
        IdsWriter::call_exact(out, che_triangle_triangles, m_, t.value());
    }
    return out;
}

inline Ids<VertexId> Surface::boundary_curve_vertices(std::uint32_t curve) const {
    Ids<VertexId> out;
    IdsWriter::call(out, che_boundary_curve_vertices, m_, curve);
    return out;
}

// Half-edges and boundary tests.

inline HalfEdgeId Surface::opposite(HalfEdgeId h) const {
    if (views_.O != nullptr && views_.half_edge(h.value())) return HalfEdgeId{views_.O[h.value()]};
    return HalfEdgeId{detail::value(che_half_edge_opposite, m_, h.value())};
}
inline EdgeId Surface::edge(HalfEdgeId h) const {
    return EdgeId{detail::value(che_half_edge_edge, m_, h.value())};
}
inline std::uint32_t Surface::curve(HalfEdgeId h) const {
    return detail::value(che_half_edge_curve, m_, h.value());
}
inline HalfEdgeId Surface::half_edge(VertexId v) const {
    if (views_.star(v.value())) return HalfEdgeId{views_.VH[v.value()]};
    return HalfEdgeId{detail::value(che_vertex_half_edge, m_, v.value())};
}
inline HalfEdgeId Surface::half_edge(EdgeId e) const {
    if (views_.EH != nullptr && views_.edge(e.value())) return HalfEdgeId{views_.EH[e.value()]};
    return HalfEdgeId{detail::value(che_edge_half_edge, m_, e.value())};
}
inline VertexId Surface::origin(HalfEdgeId h) const {
    if (views_.V != nullptr && views_.half_edge(h.value())) return VertexId{views_.V[h.value()]};
    return VertexId{half_edge_vertices().at(h.value())};
}
inline bool Surface::is_boundary(VertexId v) const {
    if (views_.star(v.value())) {
        const std::uint32_t h = views_.VH[v.value()];
        return h != none && views_.O[h] == none;
    }
    return detail::flag(che_vertex_is_boundary, m_, v.value());
}
inline bool Surface::is_boundary(EdgeId e) const {
    if (views_.EH != nullptr && views_.edge(e.value())) return views_.O[views_.EH[e.value()]] == none;
    return detail::flag(che_edge_is_boundary, m_, e.value());
}

// Zero-copy views.

inline Span<std::uint32_t> Surface::half_edge_vertices() const {
    return detail::view(che_mesh_half_edge_vertices, m_);
}
inline Span<std::uint32_t> Surface::opposites() const { return detail::view(che_mesh_opposites, m_); }
inline Span<std::uint32_t> Surface::vertex_half_edges() const {
    return detail::view(che_mesh_vertex_half_edges, m_);
}
inline Span<std::uint32_t> Surface::edge_half_edges() const {
    return detail::view(che_mesh_edge_half_edges, m_);
}
inline Span<std::uint32_t> Surface::curve_half_edges() const {
    return detail::view(che_mesh_curve_half_edges, m_);
}
inline Span<std::uint32_t> Surface::vertex_origins() const {
    return detail::view(che_mesh_vertex_origins, m_);
}
inline Span<std::uint32_t> Surface::triangle_origins() const {
    return detail::view(che_mesh_triangle_origins, m_);
}
inline Span<double> Surface::positions() const {
    std::size_t len = 0;
    const double *p = che_mesh_positions(m_, &len);
    return Span<double>(p, p ? len : 0);
}

// Bulk relations.

inline Csr Surface::vertex_vertices_csr() const { return detail::csr(che_mesh_vertex_vertices_csr, m_); }
inline Csr Surface::vertex_edges_csr() const { return detail::csr(che_mesh_vertex_edges_csr, m_); }
inline Csr Surface::vertex_triangles_csr() const {
    return detail::csr(che_mesh_vertex_triangles_csr, m_);
}
inline Csr Surface::triangle_triangles_csr() const {
    return detail::csr(che_mesh_triangle_triangles_csr, m_);
}

// Summary, build report, memory.

inline void Surface::validate() const { detail::check(che_mesh_validate(m_)); }

inline void Surface::write(const std::string &path, std::uint32_t flags) const {
    detail::check(che_mesh_write(m_, path.c_str(), flags));
}
inline void Surface::save(const std::string &path) const {
    detail::check(che_mesh_save(m_, path.c_str()));
}

inline che_summary Surface::raw_summary() const {
    che_summary s{};
    detail::check(che_mesh_summary(m_, &s));
    return s;
}
inline SurfaceSummary Surface::summary() const {
    const che_summary s = raw_summary();
    SurfaceSummary out;
    out.vertices = s.vertices;
    out.edges = s.edges;
    out.triangles = s.triangles;
    out.boundary_edges = s.boundary_edges;
    out.boundary_curves = s.boundary_curves;
    out.components = s.components;
    out.isolated_vertices = s.isolated_vertices;
    out.euler_characteristic = s.euler_characteristic;
    out.genus = s.genus;
    out.orientable = s.orientable;
    out.manifold = s.manifold;
    out.dropped_degenerate = s.dropped_degenerate;
    out.non_manifold_edges = s.non_manifold_edges;
    out.split_vertices = s.split_vertices;
    out.flipped_triangles = s.flipped_triangles;
    out.non_orientable_components = s.non_orientable_components;
    return out;
}
inline che_build_report Surface::raw_report() const {
    che_build_report r{};
    detail::check(che_mesh_report(m_, &r));
    return r;
}
inline SurfaceReport Surface::report() const {
    const che_build_report r = raw_report();
    SurfaceReport out;
    out.input_triangles = r.input_triangles;
    out.input_vertices = r.input_vertices;
    out.dropped_degenerate = r.dropped_degenerate;
    out.duplicate_triangles = r.duplicate_triangles;
    out.input_edges = r.input_edges;
    out.boundary_edges = r.boundary_edges;
    out.non_manifold_edges = r.non_manifold_edges;
    out.split_vertices = r.split_vertices;
    out.seam_split_vertices = r.seam_split_vertices;
    out.added_vertices = r.added_vertices;
    out.flipped_triangles = r.flipped_triangles;
    out.non_orientable_components = r.non_orientable_components;
    out.seam_edges = r.seam_edges;
    out.welded_vertices = r.welded_vertices;
    return out;
}
inline std::vector<std::uint32_t> Surface::report_examples(che_report_kind kind) const {
    std::size_t len = 0;
    detail::check(che_mesh_report_examples(m_, kind, nullptr, 0, &len));
    std::vector<std::uint32_t> out(len);
    detail::check(che_mesh_report_examples(m_, kind, out.data(), out.size(), &len));
    return out;
}
inline che_memory Surface::memory() const {
    che_memory mem{};
    detail::check(che_mesh_memory(m_, &mem));
    return mem;
}

} // namespace topomesh

#endif // TOPOMESH_DETAIL_SURFACE_HPP
