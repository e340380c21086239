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

} // namespace om
} // namespace diffmesh
