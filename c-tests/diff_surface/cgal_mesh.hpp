// CGAL's mesh of the differential tests (Surface_mesh of Epick points) and its build from
// the shared arrays, for the translation units that use CGAL.
#pragma once

#include "peers.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>

namespace diffmesh {
namespace cg {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

// Builds from the arrays; `face_input[f]` is the submitted index of face f.
void build(const PeerInput &in, Mesh &m, PeerBuild &b, std::vector<uint32_t> *face_input);

// The answers of every vertex, face and edge of m into `a` (sized for them); `fid` gives a
// face's common id (NONE for none), which is also where its answers go.
template <class Fid> void element_answers(const Mesh &m, Answers &a, Fid fid) {
  using VI = Mesh::Vertex_index;
  using HI = Mesh::Halfedge_index;
  auto vid = [](VI v) { return uint32_t(size_t(v)); };
  for (VI v : m.vertices()) {
    const size_t i = size_t(v);
    a.have_v[i] = 1;
    const HI h = m.halfedge(v);
    if (h == Mesh::null_halfedge()) continue;
    // Around the target, CGAL's circulators run clockwise: reverse them.
    for (VI w : CGAL::vertices_around_target(h, m)) {
      a.vv[i].push_back(vid(w));
      a.ve[i].push_back(mkpair(uint32_t(i), vid(w)));
    }
    for (Mesh::Face_index f : CGAL::faces_around_target(h, m))
      if (f != Mesh::null_face()) a.vf[i].push_back(fid(f));
    std::reverse(a.vv[i].begin(), a.vv[i].end());
    std::reverse(a.ve[i].begin(), a.ve[i].end());
    std::reverse(a.vf[i].begin(), a.vf[i].end());
    a.v_boundary[i] = m.is_border(v);
  }
  for (auto f : m.faces())
    face_answers(
        a, fid(f), m.halfedge(f), [&](HI h) { return m.next(h); },
        [&](HI h) { return std::make_pair(vid(m.source(h)), vid(m.target(h))); },
        [&](HI h) { return fid(m.face(m.opposite(h))); });
  for (auto e : m.edges())
    edge_answers(
        a, size_t(e), m.halfedge(e), m.opposite(m.halfedge(e)), [&](HI h) { return fid(m.face(h)); },
        [&](HI h) { return mkpair(vid(m.source(h)), vid(m.target(h))); },
        [&](HI h) { return std::array<HI, 2>{m.next(h), m.prev(h)}; });
}

} // namespace cg
} // namespace diffmesh
