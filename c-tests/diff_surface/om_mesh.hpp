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

} // namespace om
} // namespace diffmesh
