// Volume editing (included by topomesh.hpp; see the chf_mesh_* edit functions of
// topomesh.h). Each edit throws Error on a refusal, leaving the volume unchanged. Ids stay
// valid until garbage_collect().
#pragma once

namespace topomesh {

inline VertexId Volume::add_vertex(const Vec3 *position) {
    double buf[3];
    std::uint32_t v = none;
    detail::check(chf_mesh_add_vertex(m_, detail::xyz(position, buf), &v));
    return VertexId{v};
}
inline TetrahedronId Volume::add_tetrahedron(VertexId a, VertexId b, VertexId c, VertexId d) {
    const std::uint32_t q[4] = {a.value(), b.value(), c.value(), d.value()};
    std::uint32_t t = none;
    detail::check(chf_mesh_add_tetrahedron(m_, q, &t));
    return TetrahedronId{t};
}
inline void Volume::remove(TetrahedronId t) {
    detail::check(chf_mesh_remove_tetrahedron(m_, t.value()));
}
inline void Volume::remove(VertexId v) { detail::check(chf_mesh_remove_vertex(m_, v.value())); }
inline VertexId Volume::split(TetrahedronId t, const Vec3 *position) {
    double buf[3];
    std::uint32_t v = none;
    detail::check(chf_mesh_split_tetrahedron(m_, t.value(), detail::xyz(position, buf), &v));
    return VertexId{v};
}
inline VertexId Volume::split(FaceId f, const Vec3 *position) {
    double buf[3];
    std::uint32_t v = none;
    detail::check(chf_mesh_split_face(m_, f.value(), detail::xyz(position, buf), &v));
    return VertexId{v};
}
inline VertexId Volume::split(EdgeId e, const Vec3 *position) {
    double buf[3];
    std::uint32_t v = none;
    detail::check(chf_mesh_split_edge(m_, e.value(), detail::xyz(position, buf), &v));
    return VertexId{v};
}
inline std::array<TetrahedronId, 3> Volume::flip_23(FaceId f) {
    std::uint32_t t[3] = {none, none, none};
    detail::check(chf_mesh_flip_23(m_, f.value(), t));
    return {TetrahedronId{t[0]}, TetrahedronId{t[1]}, TetrahedronId{t[2]}};
}
inline std::array<TetrahedronId, 2> Volume::flip_32(EdgeId e) {
    std::uint32_t t[2] = {none, none};
    detail::check(chf_mesh_flip_32(m_, e.value(), t));
    return {TetrahedronId{t[0]}, TetrahedronId{t[1]}};
}
inline VertexId Volume::collapse(std::uint64_t he) {
    std::uint32_t v = none;
    detail::check(chf_mesh_collapse_edge(m_, he, &v));
    return VertexId{v};
}
inline bool Volume::can_split(TetrahedronId t, const Vec3 *position) const {
    double buf[3];
    return chf_mesh_check_split_tetrahedron(m_, t.value(), detail::xyz(position, buf)) ==
           TOPOMESH_STATUS_OK;
}
// The yes-or-no calls word no refusal: cheaper than the checks, which write the detail.
inline bool Volume::can_flip_23(FaceId f) const {
    bool ok = false;
    return chf_mesh_is_flip_23_ok(m_, f.value(), &ok) == TOPOMESH_STATUS_OK && ok;
}
inline bool Volume::can_flip_32(EdgeId e) const {
    bool ok = false;
    return chf_mesh_is_flip_32_ok(m_, e.value(), &ok) == TOPOMESH_STATUS_OK && ok;
}
inline bool Volume::can_collapse(std::uint64_t he) const {
    bool ok = false;
    return chf_mesh_is_collapse_ok(m_, he, &ok) == TOPOMESH_STATUS_OK && ok;
}
inline bool Volume::is_flip_23_ok(FaceId f) const {
    bool ok = false;
    detail::check(chf_mesh_is_flip_23_ok(m_, f.value(), &ok));
    return ok;
}
inline bool Volume::is_flip_32_ok(EdgeId e) const {
    bool ok = false;
    detail::check(chf_mesh_is_flip_32_ok(m_, e.value(), &ok));
    return ok;
}
inline bool Volume::is_collapse_ok(std::uint64_t he) const {
    bool ok = false;
    detail::check(chf_mesh_is_collapse_ok(m_, he, &ok));
    return ok;
}
inline bool Volume::is_removed(VertexId v) const {
    return detail::flag(chf_vertex_is_removed, m_, v.value());
}
inline bool Volume::is_removed(TetrahedronId t) const {
    return detail::flag(chf_tetrahedron_is_removed, m_, t.value());
}
inline bool Volume::is_removed(FaceId f) const {
    return detail::flag(chf_face_is_removed, m_, f.value());
}
inline bool Volume::is_removed(EdgeId e) const {
    return detail::flag(chf_edge_is_removed, m_, e.value());
}
inline std::size_t Volume::num_live_vertices() const noexcept {
    return chf_mesh_num_live_vertices(m_);
}
inline std::size_t Volume::num_live_tetrahedra() const noexcept {
    return chf_mesh_num_live_tetrahedra(m_);
}
inline std::size_t Volume::num_live_faces() const noexcept { return chf_mesh_num_live_faces(m_); }
inline std::size_t Volume::num_live_edges() const noexcept { return chf_mesh_num_live_edges(m_); }
inline Volume::GarbageMaps Volume::garbage_collect() {
    GarbageMaps maps;
    maps.vertices.resize(num_vertices());
    maps.tetrahedra.resize(num_tetrahedra());
    maps.faces.resize(num_faces());
    maps.edges.resize(num_edges());
    detail::check(chf_mesh_garbage_collect(
        m_, maps.vertices.data(), maps.vertices.size(), maps.tetrahedra.data(),
        maps.tetrahedra.size(), maps.faces.data(), maps.faces.size(), maps.edges.data(),
        maps.edges.size()));
    return maps;
}

} // namespace topomesh
