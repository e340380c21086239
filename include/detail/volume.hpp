// topomesh C++ wrapper, implementation: the member functions of topomesh::Volume (each one
// C call).
//
// Included by topomesh.hpp; not a header of its own.
#ifndef TOPOMESH_DETAIL_VOLUME_HPP
#define TOPOMESH_DETAIL_VOLUME_HPP

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace topomesh {

// Create and free.

inline Volume Volume::from_tetrahedra(const std::uint32_t *tetrahedra, std::size_t n_tets,
                                      std::size_t n_vertices, const double *positions,
                                      Options options) {
    chf_build_options o = detail::chf_options(options);
    chf_mesh *m = nullptr;
    detail::check(
        chf_mesh_from_tetrahedra_ex(tetrahedra, n_tets, n_vertices, positions, &o, &m));
    return Volume(m);
}

inline Volume Volume::from_tetrahedra(const std::vector<std::uint32_t> &tetrahedra,
                                      std::size_t n_vertices,
                                      const std::vector<double> &positions, Options options) {
    detail::check_arrays(tetrahedra.size(), 4, "tetrahedron", positions.size(), n_vertices);
    return from_tetrahedra(tetrahedra.data(), tetrahedra.size() / 4, n_vertices,
                           positions.empty() ? nullptr : positions.data(), options);
}

inline Volume Volume::load(const std::string &path, Options options) {
    chf_build_options o = detail::chf_options(options);
    chf_mesh *m = nullptr;
    detail::check(chf_mesh_load_ex(path.c_str(), &o, &m));
    return Volume(m);
}

inline Volume Volume::open(const std::string &path, std::uint32_t flags) {
    chf_mesh *m = nullptr;
    detail::check(chf_mesh_open(path.c_str(), flags, &m));
    return Volume(m);
}

inline Volume::Volume(Volume &&other) noexcept : m_(std::exchange(other.m_, nullptr)) {}

inline Volume &Volume::operator=(Volume &&other) noexcept {
    if (this != &other) {
        chf_mesh_free(m_);
        m_ = std::exchange(other.m_, nullptr);
    }
    return *this;
}

inline Volume::~Volume() { chf_mesh_free(m_); }

inline chf_mesh *Volume::release() noexcept { return std::exchange(m_, nullptr); }

// Level and counts.

inline std::uint32_t Volume::level() const noexcept { return chf_mesh_level(m_); }
inline void Volume::build_level(std::uint32_t level) {
    detail::check(chf_mesh_build_level(m_, level));
}
inline std::size_t Volume::num_vertices() const noexcept { return chf_mesh_num_vertices(m_); }
inline std::size_t Volume::num_input_vertices() const noexcept {
    return chf_mesh_num_input_vertices(m_);
}
inline std::size_t Volume::num_tetrahedra() const noexcept { return chf_mesh_num_tetrahedra(m_); }
inline std::size_t Volume::num_faces() const noexcept { return chf_mesh_num_faces(m_); }
inline std::size_t Volume::num_edges() const noexcept { return chf_mesh_num_edges(m_); }
inline std::size_t Volume::num_half_faces() const noexcept { return chf_mesh_num_half_faces(m_); }
inline std::size_t Volume::num_boundary_faces() const noexcept {
    return chf_mesh_num_boundary_faces(m_);
}
inline std::size_t Volume::num_boundary_triangles() const noexcept {
    return chf_mesh_num_boundary_triangles(m_);
}
inline std::size_t Volume::num_non_manifold_half_faces() const noexcept {
    return chf_mesh_num_non_manifold_half_faces(m_);
}
inline std::size_t Volume::num_seam_half_faces() const noexcept {
    return chf_mesh_num_seam_half_faces(m_);
}
inline std::size_t Volume::num_boundary_vertices() const noexcept {
    return chf_mesh_num_boundary_vertices(m_);
}
inline std::size_t Volume::num_boundary_components() const noexcept {
    return chf_mesh_num_boundary_components(m_);
}

// Per-element relations.

// Each is one C call of the same name; the result type comes last (it has commas).
#define TOPOMESH_VOLUME_RELATION(name, Arg, ...)                                           \
    inline __VA_ARGS__ Volume::name(Arg x) const {                                         \
        return detail::relation<__VA_ARGS__>(chf_##name, m_, x.value());                   \
    }
TOPOMESH_VOLUME_RELATION(vertex_vertices, VertexId, Ids<VertexId>)
TOPOMESH_VOLUME_RELATION(vertex_edges, VertexId, Ids<EdgeId>)
TOPOMESH_VOLUME_RELATION(vertex_faces, VertexId, Ids<FaceId>)
TOPOMESH_VOLUME_RELATION(vertex_tetrahedra, VertexId, Ids<TetrahedronId>)
TOPOMESH_VOLUME_RELATION(edge_vertices, EdgeId, Ids<VertexId, 2>)
TOPOMESH_VOLUME_RELATION(edge_edges, EdgeId, Ids<EdgeId>)
TOPOMESH_VOLUME_RELATION(edge_faces, EdgeId, Ids<FaceId>)
TOPOMESH_VOLUME_RELATION(edge_tetrahedra, EdgeId, Ids<TetrahedronId>)
TOPOMESH_VOLUME_RELATION(face_vertices, FaceId, Ids<VertexId, 3>)
TOPOMESH_VOLUME_RELATION(face_edges, FaceId, Ids<EdgeId, 3>)
TOPOMESH_VOLUME_RELATION(face_faces, FaceId, Ids<FaceId, 6>)
TOPOMESH_VOLUME_RELATION(face_tetrahedra, FaceId, Ids<TetrahedronId, 2>)
TOPOMESH_VOLUME_RELATION(tetrahedron_vertices, TetrahedronId, Ids<VertexId, 4>)
TOPOMESH_VOLUME_RELATION(tetrahedron_edges, TetrahedronId, Ids<EdgeId, 6>)
TOPOMESH_VOLUME_RELATION(tetrahedron_faces, TetrahedronId, Ids<FaceId, 4>)
TOPOMESH_VOLUME_RELATION(tetrahedron_tetrahedra, TetrahedronId, Ids<TetrahedronId, 4>)
#undef TOPOMESH_VOLUME_RELATION

// Half-faces and boundary tests.

inline HalfFaceId Volume::opposite(HalfFaceId hf) const {
    return HalfFaceId{detail::value(chf_half_face_opposite, m_, hf.value())};
}
inline FaceId Volume::face(HalfFaceId hf) const {
    return FaceId{detail::value(chf_half_face_face, m_, hf.value())};
}
inline HalfFaceId Volume::half_face(FaceId f) const {
    return HalfFaceId{detail::value(chf_face_half_face, m_, f.value())};
}
inline HalfFaceId Volume::half_face(VertexId v) const {
    return HalfFaceId{detail::value(chf_vertex_half_face, m_, v.value())};
}
inline bool Volume::is_boundary(VertexId v) const {
    return detail::flag(chf_vertex_is_boundary, m_, v.value());
}
inline bool Volume::is_boundary(EdgeId e) const {
    return detail::flag(chf_edge_is_boundary, m_, e.value());
}
inline bool Volume::is_boundary(FaceId f) const {
    return detail::flag(chf_face_is_boundary, m_, f.value());
}

// The boundary surface and its maps.

inline Surface Volume::boundary() const {
    che_mesh *s = nullptr;
    detail::check(chf_mesh_boundary(m_, &s));
    return Surface(s);
}
inline TriangleId Volume::boundary_triangle(HalfFaceId hf) const {
    return TriangleId{detail::value(chf_half_face_boundary_triangle, m_, hf.value())};
}
inline TriangleId Volume::boundary_triangle(FaceId f) const {
    return TriangleId{detail::value(chf_face_boundary_triangle, m_, f.value())};
}
inline HalfFaceId Volume::boundary_half_face(TriangleId k) const {
    return HalfFaceId{detail::value(chf_boundary_triangle_half_face, m_, k.value())};
}
inline FaceId Volume::boundary_face(TriangleId k) const {
    return FaceId{detail::value(chf_boundary_triangle_face, m_, k.value())};
}
inline std::uint32_t Volume::boundary_component(VertexId v) const {
    return detail::value(chf_vertex_boundary_component, m_, v.value());
}
inline VertexId Volume::boundary_vertex(VertexId v) const {
    return VertexId{detail::value(chf_vertex_boundary_vertex, m_, v.value())};
}
inline VertexId Volume::volume_vertex(VertexId b) const {
    return VertexId{detail::value(chf_boundary_vertex_vertex, m_, b.value())};
}

// Zero-copy views.

#define TOPOMESH_VOLUME_VIEW(name)                                                         \
    inline Span<std::uint32_t> Volume::name() const {                                      \
        return detail::view(chf_mesh_##name, m_);                                          \
    }
TOPOMESH_VOLUME_VIEW(half_face_vertices)
TOPOMESH_VOLUME_VIEW(opposites)
TOPOMESH_VOLUME_VIEW(vertex_half_faces)
TOPOMESH_VOLUME_VIEW(face_half_faces)
TOPOMESH_VOLUME_VIEW(boundary_half_faces)
TOPOMESH_VOLUME_VIEW(boundary_vertices)
TOPOMESH_VOLUME_VIEW(boundary_vertex_components)
TOPOMESH_VOLUME_VIEW(vertex_origins)
TOPOMESH_VOLUME_VIEW(tetrahedron_origins)
#undef TOPOMESH_VOLUME_VIEW

inline Span<double> Volume::positions() const {
    std::size_t len = 0;
    const double *p = chf_mesh_positions(m_, &len);
    return Span<double>(p, p ? len : 0);
}

// Bulk relations.

#define TOPOMESH_VOLUME_CSR(name)                                                          \
    inline Csr Volume::name##_csr() const { return detail::csr(chf_mesh_##name##_csr, m_); }
TOPOMESH_VOLUME_CSR(vertex_vertices)
TOPOMESH_VOLUME_CSR(vertex_edges)
TOPOMESH_VOLUME_CSR(vertex_faces)
TOPOMESH_VOLUME_CSR(vertex_tetrahedra)
TOPOMESH_VOLUME_CSR(edge_faces)
TOPOMESH_VOLUME_CSR(edge_tetrahedra)
TOPOMESH_VOLUME_CSR(tetrahedron_tetrahedra)
#undef TOPOMESH_VOLUME_CSR

// Summary, build report, memory.

inline void Volume::validate() const { detail::check(chf_mesh_validate(m_)); }

inline void Volume::write(const std::string &path, std::uint32_t flags) const {
    detail::check(chf_mesh_write(m_, path.c_str(), flags));
}
inline void Volume::write_boundary(const std::string &path, std::uint32_t flags) const {
    detail::check(chf_mesh_write_boundary(m_, path.c_str(), flags));
}
inline void Volume::save(const std::string &path) const {
    detail::check(chf_mesh_save(m_, path.c_str()));
}

inline chf_summary Volume::raw_summary() const {
    chf_summary s{};
    detail::check(chf_mesh_summary(m_, &s));
    return s;
}
inline VolumeSummary Volume::summary() const {
    const chf_summary s = raw_summary();
    VolumeSummary out;
    out.vertices = s.vertices;
    out.edges = s.edges;
    out.faces = s.faces;
    out.tetrahedra = s.tetrahedra;
    out.boundary_faces = s.boundary_faces;
    out.boundary_edges = s.boundary_edges;
    out.boundary_vertices = s.boundary_vertices;
    out.boundary_components = s.boundary_components;
    out.components = s.components;
    out.isolated_vertices = s.isolated_vertices;
    out.euler_characteristic = s.euler_characteristic;
    out.manifold = s.manifold;
    out.orientable = s.orientable;
    out.dropped_degenerate = s.dropped_degenerate;
    out.zero_volume = s.zero_volume;
    out.inverted_tetrahedra = s.inverted_tetrahedra;
    out.non_manifold_faces = s.non_manifold_faces;
    out.non_manifold_edges = s.non_manifold_edges;
    out.split_vertices = s.split_vertices;
    out.flipped_tetrahedra = s.flipped_tetrahedra;
    out.non_orientable_components = s.non_orientable_components;
    return out;
}
inline chf_build_report Volume::raw_report() const {
    chf_build_report r{};
    detail::check(chf_mesh_report(m_, &r));
    return r;
}
inline VolumeReport Volume::report() const {
    const chf_build_report r = raw_report();
    VolumeReport out;
    out.input_tetrahedra = r.input_tetrahedra;
    out.input_vertices = r.input_vertices;
    out.dropped_degenerate = r.dropped_degenerate;
    out.zero_volume = r.zero_volume;
    out.inverted_tetrahedra = r.inverted_tetrahedra;
    out.duplicate_tetrahedra = r.duplicate_tetrahedra;
    out.input_faces = r.input_faces;
    out.boundary_faces = r.boundary_faces;
    out.non_manifold_faces = r.non_manifold_faces;
    out.input_edges = r.input_edges;
    out.non_manifold_edges = r.non_manifold_edges;
    out.kept_non_manifold_edges = r.kept_non_manifold_edges;
    out.split_vertices = r.split_vertices;
    out.seam_split_vertices = r.seam_split_vertices;
    out.added_vertices = r.added_vertices;
    out.flipped_tetrahedra = r.flipped_tetrahedra;
    out.non_orientable_components = r.non_orientable_components;
    out.seam_faces = r.seam_faces;
    out.welded_vertices = r.welded_vertices;
    return out;
}
inline std::vector<std::uint32_t> Volume::report_examples(chf_report_kind kind) const {
    std::size_t len = 0;
    detail::check(chf_mesh_report_examples(m_, kind, nullptr, 0, &len));
    std::vector<std::uint32_t> out(len);
    detail::check(chf_mesh_report_examples(m_, kind, out.data(), out.size(), &len));
    return out;
}
inline chf_memory Volume::memory() const {
    chf_memory mem{};
    detail::check(chf_mesh_memory(m_, &mem));
    return mem;
}

} // namespace topomesh

#endif // TOPOMESH_DETAIL_VOLUME_HPP
