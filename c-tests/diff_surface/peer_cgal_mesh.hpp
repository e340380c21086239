// CGAL's Surface_mesh (Epick points) and its build from the arrays: shared by the
// differential answers (peer_cgal.cpp) and the editing benchmark (edit_cgal.cpp), so that
// every CGAL mesh is built the same way.
#pragma once

#include "peers.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace diffmesh {

using CgalKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;

// Builds from the arrays (reserve, add_vertex, add_face); `face_input[f]` is the submitted
// index of face f.
inline void build_cgal(const PeerInput &in, CgalMesh &m, PeerBuild &b, std::vector<uint32_t> *face_input) {
  using VI = CgalMesh::Vertex_index;
  m.reserve(CgalMesh::size_type(in.n_vertices), CgalMesh::size_type(in.n_triangles * 3 / 2 + 16),
            CgalMesh::size_type(in.n_triangles));
  for (size_t v = 0; v < in.n_vertices; ++v) {
    const double *p = in.positions + 3 * v;
    VI h = m.add_vertex(CgalKernel::Point_3(p[0], p[1], p[2]));
    if (size_t(h) != v) b.vertices_in_order = false;
  }
  add_triangles(in, b, face_input, [&](const uint32_t *c) {
    return m.add_face(VI(c[0]), VI(c[1]), VI(c[2])) != CgalMesh::null_face();
  });
}

} // namespace diffmesh
