// The editing benchmark's OpenMesh adapter (edit_policy.hpp): TriMesh's is_flip_ok/flip,
// split(EdgeHandle, Point), is_collapse_ok/collapse (from-vertex into to-vertex),
// delete_face and garbage_collection.
#include "bench_edit_peers.hpp"
#include "om_mesh.hpp"

#include <memory>

namespace diffmesh {
namespace {

using Mesh = om::Mesh;
using OpenMesh::EdgeHandle;
using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;

// The mesh with the status flags that deletion needs (requested before the timing: an
// editing user holds them), and its live face count (n_faces() counts deleted ones until
// garbage_collection()).
class OmEdit {
public:
  explicit OmEdit(const PeerInput &in) {
    om::build_editable(in, m_);
    live_ = m_.n_faces();
  }
  uint32_t n_edges() const { return uint32_t(m_.n_edges()); }
  uint32_t n_triangles() const { return uint32_t(m_.n_faces()); }
  size_t live_triangles() const { return live_; }
  bool edge_removed(uint32_t e) const { return m_.status(EdgeHandle(int(e))).deleted(); }
  uint32_t edge_half_edge(uint32_t e) const { return uint32_t(m_.halfedge_handle(EdgeHandle(int(e)), 0).idx()); }
  uint32_t edge_of(uint32_t h) const { return h / 2; }
  bool half_edge_removed(uint32_t h) const { return m_.status(HalfedgeHandle(int(h))).deleted(); }
  uint32_t origin(uint32_t h) const { return uint32_t(m_.from_vertex_handle(HalfedgeHandle(int(h))).idx()); }
  uint32_t target(uint32_t h) const { return uint32_t(m_.to_vertex_handle(HalfedgeHandle(int(h))).idx()); }
  void apexes(uint32_t h, uint32_t out[2]) const {
    const HalfedgeHandle hh{int(h)};
    int k = 0;
    for (HalfedgeHandle g : {hh, m_.opposite_halfedge_handle(hh)})
      out[k++] = m_.is_boundary(g) ? ~0u : uint32_t(m_.to_vertex_handle(m_.next_halfedge_handle(g)).idx());
  }
  P3 point(uint32_t v) const {
    const auto &p = m_.point(VertexHandle(int(v)));
    return {p[0], p[1], p[2]};
  }
  void set_point(uint32_t v, const P3 &p) { m_.set_point(VertexHandle(int(v)), Mesh::Point(p[0], p[1], p[2])); }
  bool flip_ok(uint32_t e) const { return m_.is_flip_ok(EdgeHandle(int(e))); }
  void flip(uint32_t e) { m_.flip(EdgeHandle(int(e))); }
  void split(uint32_t e, const P3 &p) {
    const EdgeHandle eh{int(e)};
    live_ += size_t(!m_.is_boundary(m_.halfedge_handle(eh, 0))) + size_t(!m_.is_boundary(m_.halfedge_handle(eh, 1)));
    m_.split(eh, Mesh::Point(p[0], p[1], p[2]));
  }
  bool collapse_ok(uint32_t h) { return m_.is_collapse_ok(HalfedgeHandle(int(h))); }
  uint32_t collapse(uint32_t h) {
    const HalfedgeHandle hh{int(h)};
    const VertexHandle kept = m_.to_vertex_handle(hh);
    live_ -= size_t(!m_.is_boundary(hh)) + size_t(!m_.is_boundary(m_.opposite_halfedge_handle(hh)));
    m_.collapse(hh);
    return uint32_t(kept.idx());
  }
  template <class F> void each_triangle_around(uint32_t v, F f) const {
    for (FaceHandle fh : m_.vf_range(VertexHandle(int(v)))) {
      uint32_t c[3];
      int k = 0;
      for (VertexHandle w : m_.fv_range(fh)) c[k++] = uint32_t(w.idx());
      f(c[0], c[1], c[2]);
    }
  }
  template <class F> void each_out_half_edge(uint32_t v, F f) const {
    for (HalfedgeHandle g : m_.voh_range(VertexHandle(int(v)))) f(uint32_t(g.idx()));
  }
  void remove_triangle(uint32_t t) {
    m_.delete_face(FaceHandle(int(t)), false);
    --live_;
  }
  void garbage_collect() { m_.garbage_collection(); }
  // Connectivity (as bench.cpp counts it) and the four status properties.
  size_t structure_bytes() const {
    const size_t st = sizeof(OpenMesh::Attributes::StatusInfo);
    return m_.n_vertices() * (sizeof(Mesh::Vertex) + st) + m_.n_edges() * (sizeof(Mesh::Edge) + st) +
           m_.n_halfedges() * st + m_.n_faces() * (sizeof(Mesh::Face) + st);
  }

private:
  Mesh m_;
  size_t live_ = 0;
};

} // namespace

EditRow openmesh_edits(const PeerInput &in, const EditParams &p, double threshold, int reps) {
  return run_edits("OpenMesh", [&] { return std::make_unique<OmEdit>(in); }, p, threshold, reps);
}

} // namespace diffmesh
