// The relations of a tetrahedral mesh in INPUT ids (input vertex and tetrahedron numbers),
// as each side answers them: the brute-force oracle (from the soup alone), CGAL's
// Triangulation_3, and topomesh through the C API. compare() reports every difference.
#pragma once

#include "tet_soup.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace diffvol {

constexpr uint32_t NONE = UINT32_MAX;

// Rows of ids, one row per element.
struct Rows {
  std::vector<uint32_t> offsets{0};
  std::vector<uint32_t> ids;
  size_t size() const { return offsets.size() - 1; }
  void push_row() { offsets.push_back(uint32_t(ids.size())); }
  const uint32_t *begin(size_t i) const { return ids.data() + offsets[i]; }
  const uint32_t *end(size_t i) const { return ids.data() + offsets[i + 1]; }
  std::vector<uint32_t> row(size_t i) const { return {begin(i), end(i)}; }
};

inline uint64_t edge_key(uint32_t a, uint32_t b) {
  if (a > b) std::swap(a, b);
  return (uint64_t(a) << 32) | b;
}

struct Answers {
  std::string side;   // "oracle", "CGAL", "topomesh L2", ...
  // TT: for tetrahedron t and local slot j of the INPUT tetrahedron, the tetrahedron across
  // the face opposite input vertex tets[4t+j]; NONE on the boundary (and, for topomesh and
  // the oracle, on a non-manifold face).
  std::vector<uint32_t> tt;
  Rows vt;  // per input vertex, sorted
  Rows vv;  // per input vertex, sorted
  // Edges sorted by key; one entry per fan (topomesh may keep several fans of one input
  // edge: the same key repeated). Tetrahedra in the side's rotation order.
  std::vector<std::pair<uint64_t, std::vector<uint32_t>>> et;
  bool et_ordered = false; // the side gives a rotation order (check it)
  // Boundary faces (sorted vertex triples), sorted; a non-manifold face appears once per
  // unpaired half-face (topomesh, oracle), a boundary face once.
  std::vector<std::array<uint32_t, 3>> boundary_faces;
  long V = 0, E = 0, F = 0, T = 0; // counts of the complex (E, F: unique input edges, faces)
  long euler() const { return V - E + F - T; }
};

// The truth computed from the soup alone (sorting, no topology library): VT and VV by
// scanning tetrahedra, ET per vertex pair, a face paired iff exactly two tetrahedra hold it.
Answers oracle_answers(const TetSoup &s);

// Extra counts of the oracle for the summary checks.
struct OracleSummary {
  long boundary_faces = 0, boundary_edges = 0, boundary_vertices = 0;
  long boundary_components = 0, components = 0, isolated = 0;
  long non_manifold_faces = 0;
  long boundary_euler = 0; // V - E + F of the boundary faces
};
OracleSummary oracle_summary(const TetSoup &s, const Answers &oracle);

// Differences between two answer sets, at most `limit` lines kept (counts are exact).
struct Diff {
  size_t count = 0;
  std::vector<std::string> lines;
  size_t limit = 12;
  void add(const std::string &what) {
    if (lines.size() < limit) lines.push_back(what);
    count++;
  }
};

// Compares `got` with `want`, both in input ids: TT per slot, VT, VV, ET (fans grouped by
// edge: the union of a key's fans must equal the other side's union, fans of one key
// disjoint), boundary faces, V E F T.
void compare(const TetSoup &s, const Answers &want, const Answers &got, Diff &d);

// Checks every fan of `a` whose side claims a rotation order: consecutive tetrahedra share
// a face holding the edge, and the fan is a closed cycle (first and last share such a
// face, 3+ tetrahedra) or a chain whose two ends each have a face holding the edge with no
// tetrahedron across (oracle TT). `truth` gives the adjacency.
void check_rotations(const TetSoup &s, const Answers &truth, const Answers &a, Diff &d);

// CGAL's and topomesh's rotations agree up to where they start and their direction.
void compare_rotations(const Answers &a, const Answers &b, Diff &d);

} // namespace diffvol
