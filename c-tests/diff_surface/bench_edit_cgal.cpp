// The editing benchmark's CGAL adapter (edit_policy.hpp): Surface_mesh with the Euler
// operations. CGAL has no flip check: an interior edge whose flipped edge does not exist
// yet, what OpenMesh's is_flip_ok and topomesh check; collapse_edge after
// does_satisfy_link_condition (the other end merges into the target of halfedge(e));
// split_edge then split_face on each side (a triangle pair into four, as the others do).
#include "bench_edit_peers.hpp"
#include "cgal_mesh.hpp"

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>

#include <memory>

namespace diffmesh {
namespace {

using Mesh = cg::Mesh;
using VI = Mesh::Vertex_index;
using HI = Mesh::Halfedge_index;
using EI = Mesh::Edge_index;
using FI = Mesh::Face_index;

class CgalEdit {
public:
  explicit CgalEdit(const PeerInput &in) {
    PeerBuild b;
    cg::build(in, m_, b, nullptr);
  }
  uint32_t n_edges() const { return uint32_t(m_.num_edges()); }
  uint32_t n_triangles() const { return uint32_t(m_.num_faces()); }
  size_t live_triangles() const { return m_.number_of_faces(); }
  bool edge_removed(uint32_t e) const { return m_.is_removed(EI(e)); }
  uint32_t edge_half_edge(uint32_t e) const { return uint32_t(m_.halfedge(EI(e))); }
  uint32_t edge_of(uint32_t h) const { return h / 2; }
  bool half_edge_removed(uint32_t h) const { return m_.is_removed(HI(h)); }
  uint32_t origin(uint32_t h) const { return uint32_t(m_.source(HI(h))); }
  uint32_t target(uint32_t h) const { return uint32_t(m_.target(HI(h))); }
  void apexes(uint32_t h, uint32_t out[2]) const {
    int k = 0;
    for (HI g : {HI(h), m_.opposite(HI(h))}) out[k++] = m_.is_border(g) ? ~0u : uint32_t(m_.target(m_.next(g)));
  }
  P3 point(uint32_t v) const {
    const auto &p = m_.point(VI(v));
    return {p.x(), p.y(), p.z()};
  }
  void set_point(uint32_t v, const P3 &p) { m_.point(VI(v)) = cg::K::Point_3(p[0], p[1], p[2]); }
  bool flip_ok(uint32_t e) const {
    const HI h = m_.halfedge(EI(e)), o = m_.opposite(h);
    if (m_.is_border(h) || m_.is_border(o)) return false;
    const VI a = m_.target(m_.next(h)), b = m_.target(m_.next(o));
    return a != b && !CGAL::halfedge(a, b, m_).second;
  }
  void flip(uint32_t e) { CGAL::Euler::flip_edge(m_.halfedge(EI(e)), m_); }
  void split(uint32_t e, const P3 &p) {
    const HI h = m_.halfedge(EI(e));
    const HI hnew = CGAL::Euler::split_edge(h, m_); // source(h) -> new vertex, then h
    m_.point(m_.target(hnew)) = cg::K::Point_3(p[0], p[1], p[2]);
    if (!m_.is_border(hnew)) CGAL::Euler::split_face(hnew, m_.next(h), m_);
    const HI o = m_.opposite(h); // target(h) -> new vertex
    if (!m_.is_border(o)) CGAL::Euler::split_face(o, m_.next(m_.opposite(hnew)), m_);
  }
  bool collapse_ok(uint32_t h) const { return CGAL::Euler::does_satisfy_link_condition(m_.edge(HI(h)), m_); }
  uint32_t collapse(uint32_t h) { return uint32_t(CGAL::Euler::collapse_edge(m_.edge(HI(h)), m_)); }
  template <class F> void each_triangle_around(uint32_t v, F f) const {
    for (HI g : CGAL::halfedges_around_target(VI(v), m_)) {
      if (m_.is_border(g)) continue;
      f(uint32_t(m_.source(g)), uint32_t(m_.target(g)), uint32_t(m_.target(m_.next(g))));
    }
  }
  template <class F> void each_out_half_edge(uint32_t v, F f) const {
    for (HI g : CGAL::halfedges_around_source(VI(v), m_)) f(uint32_t(g));
  }
  void remove_triangle(uint32_t t) { CGAL::Euler::remove_face(m_.halfedge(FI(t)), m_); }
  void garbage_collect() { m_.collect_garbage(); }
  // As bench.cpp counts it: a half-edge index per vertex and face, four per half-edge, and
  // a removed bit per vertex, edge and face.
  size_t structure_bytes() const {
    const size_t idx = sizeof(HI);
    return m_.num_vertices() * idx + m_.num_halfedges() * 4 * idx + m_.num_faces() * idx +
           (m_.num_vertices() + m_.num_edges() + m_.num_faces()) / 8;
  }

private:
  Mesh m_;
};

} // namespace

EditRow cgal_edits(const PeerInput &in, const EditParams &p, double threshold, int reps) {
  return run_edits("CGAL", [&] { return std::make_unique<CgalEdit>(in); }, p, threshold, reps);
}

} // namespace diffmesh
