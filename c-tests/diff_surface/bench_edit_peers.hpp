// The editing benchmark's peers (bench_edit_openmesh.cpp, bench_edit_cgal.cpp): every operation of
// edit_policy.hpp on fresh builds of OpenMesh's TriMesh and CGAL's Surface_mesh from `in`,
// behind one call each so that their heavy headers stay in their own translation units.
#pragma once

#include "edit_policy.hpp"
#include "peers.hpp"

namespace diffmesh {

EditRow openmesh_edits(const PeerInput &in, const EditParams &p, double threshold, int reps);
EditRow cgal_edits(const PeerInput &in, const EditParams &p, double threshold, int reps);

} // namespace diffmesh
