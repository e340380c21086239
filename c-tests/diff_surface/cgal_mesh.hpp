// CGAL's mesh of the differential tests (Surface_mesh of Epick points) and its build from
// the shared arrays, for the translation units that use CGAL.
#pragma once

#include "peers.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace diffmesh {
namespace cg {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

// Builds from the arrays; `face_input[f]` is the submitted index of face f.
void build(const PeerInput &in, Mesh &m, PeerBuild &b, std::vector<uint32_t> *face_input);

} // namespace cg
} // namespace diffmesh
