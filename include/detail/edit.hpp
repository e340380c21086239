// Surface editing (included by topomesh.hpp; see the che_mesh_* edit functions of
// topomesh.h). Each edit throws Error on a refusal, leaving the surface unchanged, and
// fetches the zero-copy views again whatever its outcome: spans taken before an edit are
// invalid after it. Ids stay valid until garbage_collect().
#pragma once

namespace topomesh {

namespace detail {
inline const double *xyz(const Vec3 *p, double (&buf)[3]) noexcept {
    if (p == nullptr) return nullptr;
    buf[0] = p->x;
    buf[1] = p->y;
    buf[2] = p->z;
    return buf;
}
} // namespace detail

inline void Surface::edited(topomesh_status s) {
    views_.fetch(m_);
    detail::check(s);
}
inline VertexId Surface::add_vertex(const Vec3 *position) {
    double buf[3];
    std::uint32_t v = none;
    edited(che_mesh_add_vertex(m_, detail::xyz(position, buf), &v));
    return VertexId{v};
}
inline TriangleId Surface::add_triangle(VertexId a, VertexId b, VertexId c) {
    std::uint32_t t = none;
    edited(che_mesh_add_triangle(m_, a.value(), b.value(), c.value(), &t));
    return TriangleId{t};
}
inline void Surface::remove(TriangleId t) { edited(che_mesh_remove_triangle(m_, t.value())); }
inline void Surface::remove(VertexId v) { edited(che_mesh_remove_vertex(m_, v.value())); }
inline void Surface::flip(EdgeId e) { edited(che_mesh_flip_edge(m_, e.value())); }
inline VertexId Surface::split(EdgeId e, const Vec3 *position) {
    double buf[3];
    std::uint32_t v = none;
    edited(che_mesh_split_edge(m_, e.value(), detail::xyz(position, buf), &v));
    return VertexId{v};
}
inline VertexId Surface::split(TriangleId t, const Vec3 *position) {
    double buf[3];
    std::uint32_t v = none;
    edited(che_mesh_split_triangle(m_, t.value(), detail::xyz(position, buf), &v));
    return VertexId{v};
}
inline VertexId Surface::collapse(HalfEdgeId h) {
    std::uint32_t v = none;
    edited(che_mesh_collapse_edge(m_, h.value(), &v));
    return VertexId{v};
}
inline void Surface::set_position(VertexId v, Vec3 p) {
    const double xyz[3] = {p.x, p.y, p.z};
    edited(che_mesh_set_position(m_, v.value(), xyz));
}
// The checks never modify: the views stay valid.
inline bool Surface::is_flip_ok(EdgeId e) {
    bool ok = false;
    detail::check(che_mesh_is_flip_ok(m_, e.value(), &ok));
    return ok;
}
inline bool Surface::is_collapse_ok(HalfEdgeId h) {
    bool ok = false;
    detail::check(che_mesh_is_collapse_ok(m_, h.value(), &ok));
    return ok;
}
inline bool Surface::is_removed(VertexId v) const {
    return detail::flag(che_vertex_is_removed, m_, v.value());
}
// In range, the flags read the views as the library does (a removed triangle's corners
// and a removed edge's half-edge are TOPOMESH_NONE); out of range, the call says why.
inline bool Surface::is_removed(TriangleId t) const {
    if (views_.V != nullptr && views_.triangle(t.value())) return views_.V[3 * std::size_t(t.value())] == none;
    return detail::flag(che_triangle_is_removed, m_, t.value());
}
inline bool Surface::is_removed(EdgeId e) const {
    if (views_.EH != nullptr && views_.edge(e.value())) return views_.EH[e.value()] == none;
    return detail::flag(che_edge_is_removed, m_, e.value());
}
inline std::size_t Surface::num_live_vertices() const noexcept {
    return che_mesh_num_live_vertices(m_);
}
inline std::size_t Surface::num_live_triangles() const noexcept {
    return che_mesh_num_live_triangles(m_);
}
inline std::size_t Surface::num_live_edges() const noexcept { return che_mesh_num_live_edges(m_); }
inline Surface::GarbageMaps Surface::garbage_collect() {
    GarbageMaps maps;
    maps.vertices.resize(num_vertices());
    maps.triangles.resize(num_triangles());
    maps.edges.resize(num_edges());
    edited(che_mesh_garbage_collect(m_, maps.vertices.data(), maps.vertices.size(),
                                    maps.triangles.data(), maps.triangles.size(),
                                    maps.edges.data(), maps.edges.size()));
    return maps;
}

} // namespace topomesh
