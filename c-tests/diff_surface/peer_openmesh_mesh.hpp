// OpenMesh's TriMesh (ArrayKernel, double points) and its build from the arrays: shared by
// the differential answers (peer_openmesh.cpp), the editing benchmark (edit_openmesh.cpp)
// and the export benchmark, so that every OpenMesh mesh is built the same way.
#pragma once

#include "peers.hpp"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

namespace diffmesh {

struct OpenMeshTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
};
using OpenMeshMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshTraits>;

// Builds from the arrays (reserve, add_vertex, add_face); `face_input[f]` is the submitted
// index of face f.
inline void build_openmesh(const PeerInput &in, OpenMeshMesh &m, PeerBuild &b, std::vector<uint32_t> *face_input) {
  static bool quiet = (::omerr().disable(), true); // "complex edge" etc.
  (void)quiet;
  m.reserve(in.n_vertices, in.n_triangles * 3 / 2 + 16, in.n_triangles);
  for (size_t v = 0; v < in.n_vertices; ++v) {
    const double *p = in.positions + 3 * v;
    auto h = m.add_vertex(OpenMeshMesh::Point(p[0], p[1], p[2]));
    if ((size_t)h.idx() != v) b.vertices_in_order = false;
  }
  add_triangles(in, b, face_input, [&](const uint32_t *c) {
    return m.add_face(OpenMesh::VertexHandle(int(c[0])), OpenMesh::VertexHandle(int(c[1])),
                      OpenMesh::VertexHandle(int(c[2])))
        .is_valid();
  });
}

} // namespace diffmesh
