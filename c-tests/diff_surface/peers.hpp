// The two peers, OpenMesh (TriMesh, ArrayKernel) and CGAL (Surface_mesh), behind one small
// interface so that their heavy headers stay in one translation unit each.
#pragma once

#include "answers.hpp"
#include "bench_util.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>

namespace diffmesh {

// The same arrays for every library. Degenerate triangles are not offered to the peers
// (CGAL refuses them; OpenMesh corrupts itself on them) and are counted as skipped.
struct PeerInput {
  size_t n_vertices = 0;
  const double *positions = nullptr; // 3 per vertex
  const uint32_t *triangles = nullptr;
  size_t n_triangles = 0;
};

// Builds the peer from `in` and returns every answer in common ids.
Answers openmesh_answers(const PeerInput &in, PeerBuild &build);
Answers cgal_answers(const PeerInput &in, PeerBuild &build);

// The peers as benchmark subjects (one row each: VV, VF, FF, EF and curve sweeps). `in`
// must outlive them.
std::unique_ptr<Subject> openmesh_subject(const PeerInput &in);
std::unique_ptr<Subject> cgal_subject(const PeerInput &in);

} // namespace diffmesh
