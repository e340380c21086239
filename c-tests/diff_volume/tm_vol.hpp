// topomesh's CHF through the C API: every relation the differential test compares, mapped
// back to input ids with chf_mesh_vertex_origins / chf_mesh_tetrahedron_origins, plus the
// consistency of the bulk (CSR) calls and the zero-copy views with the per-element calls.
#pragma once

#include "answers.hpp"

#include <topomesh/topomesh.h>

#include <string>

namespace diffvol {

// Owns a chf_mesh.
struct TmMesh {
  chf_mesh *m = nullptr;
  TmMesh() = default;
  TmMesh(const TmMesh &) = delete;
  TmMesh &operator=(const TmMesh &) = delete;
  ~TmMesh() { chf_mesh_free(m); }
};

// The status string and topomesh_last_error, for messages.
std::string tm_error(topomesh_status st);

// Builds from the soup with positions at `level`; on failure returns false with the status
// string and topomesh_last_error in `err`.
bool tm_build(const TetSoup &s, uint32_t level, TmMesh &out, std::string &err);

// Every relation in input ids. A split vertex's copies are merged back into their input
// vertex (VT, VV: union; each copy's rows must be disjoint from the others'). Differences
// between the C calls themselves (CSR rows vs per-element rows, O and V views vs TT and TV,
// a failing call) go to `internal`. `side` names the answers ("topomesh L2").
// VT, VV and ET come from the bulk (CSR) calls, O(T) at every level; the per-element calls
// are checked against them for every element from level 2 and for a sample below (there
// each costs O(T)). Below level 2 the mesh is then raised to level 2 in place
// (chf_mesh_build_level; ids do not change) to name the ends of every edge.
Answers tm_answers(const TetSoup &s, chf_mesh *m, const std::string &side, Diff &internal);

// With TOPOMESH_DIFFVOL_SELFTEST set, a few answers are corrupted on purpose (the test of
// the comparison itself: the run must then fail).
void corrupt_for_selftest(Answers &a);

} // namespace diffvol
