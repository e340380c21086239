// OpenMesh's mesh of the differential tests (TriMesh_ArrayKernelT with double points) and
// its build from the shared arrays, for the translation units that use OpenMesh.
#pragma once

#include "peers.hpp"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace diffmesh {
namespace om {

struct Traits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;

// Builds from the arrays; `face_input[f]` is the submitted index of face f.
void build(const PeerInput &in, Mesh &m, PeerBuild &b, std::vector<uint32_t> *face_input);

// Builds for editing, with the status flags that deletion and garbage collection need
// requested up front (as an editing user holds them).
inline void build_editable(const PeerInput &in, Mesh &m) {
  PeerBuild b;
  build(in, m, b, nullptr);
  m.request_vertex_status();
  m.request_edge_status();
  m.request_halfedge_status();
  m.request_face_status();
}

// The answers of every vertex, face and edge of m into `a` (sized for them); `fid` gives a
// face's common id (NONE for none), which is also where its answers go.
template <class Fid> void element_answers(const Mesh &m, Answers &a, Fid fid) {
  using HH = OpenMesh::HalfedgeHandle;
  auto vid = [](OpenMesh::VertexHandle v) { return uint32_t(v.idx()); };
  for (auto v : m.vertices()) {
    const size_t i = size_t(v.idx());
    a.have_v[i] = 1;
    // An isolated vertex has no half-edge; OpenMesh's circulators must not start there
    // (they return neighbours of half-edge -1's vertex).
    if (!m.halfedge_handle(v).is_valid()) continue;
    for (auto it = m.cvv_ccwiter(v); it.is_valid(); ++it) {
      a.vv[i].push_back(vid(*it));
      a.ve[i].push_back(mkpair(uint32_t(i), vid(*it)));
    }
    for (auto it = m.cvf_ccwiter(v); it.is_valid(); ++it) a.vf[i].push_back(fid(*it));
    a.v_boundary[i] = m.is_boundary(v);
  }
  for (auto f : m.faces())
    face_answers(
        a, fid(f), HH(m.halfedge_handle(f)), [&](HH h) { return m.next_halfedge_handle(h); },
        [&](HH h) { return std::make_pair(vid(m.from_vertex_handle(h)), vid(m.to_vertex_handle(h))); },
        [&](HH h) { return fid(m.face_handle(m.opposite_halfedge_handle(h))); });
  for (auto e : m.edges())
    edge_answers(
        a, size_t(e.idx()), HH(m.halfedge_handle(e, 0)), HH(m.halfedge_handle(e, 1)),
        [&](HH h) { return fid(m.face_handle(h)); },
        [&](HH h) { return mkpair(vid(m.from_vertex_handle(h)), vid(m.to_vertex_handle(h))); },
        [&](HH h) { return std::array<HH, 2>{m.next_halfedge_handle(h), m.prev_halfedge_handle(h)}; });
}

} // namespace om
} // namespace diffmesh
