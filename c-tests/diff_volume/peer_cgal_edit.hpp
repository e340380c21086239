// CGAL's Triangulation_3 (built by CgalVol from a soup) edited in place: 1-4 splits
// (insert_in_cell), 2-3 flips (flip(Facet)) and 3-2 flips (flip(Edge)), addressed by vertex
// tuples, for the editing differential test (edit_diffvol.cpp). CGAL's headers stay in
// peer_cgal_edit.cpp.
//
// Vertex ids: soup vertex i is CGAL vertex i; each split's new vertex takes the next id.
// The triangulation is the soup's own tetrahedra with infinite cells glued to its (usually
// non-convex) boundary, not a Delaunay triangulation: insert_in_cell and flip are local and
// use the orientation predicate only, so they do not care; locate and insert(p), which need
// the convex hull, are never called.
#pragma once

#include "peer_cgal.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace diffvol {

using Quad = std::array<uint32_t, 4>;

// CGAL's answer to one operation: the addressed element is not there, or the operation
// was refused, or done.
enum class CgalOutcome { Missing, Refused, Done };

class CgalEdit {
public:
  // Nullptr with a reason in `err` when CGAL refuses the soup.
  static std::unique_ptr<CgalEdit> build(const TetSoup &s, std::string &err);
  ~CgalEdit();

  // The 1-4 split of cell q at p. insert_in_cell has no refusal, only the precondition that
  // p is strictly inside the cell (side_of_tetrahedron == ON_BOUNDED_SIDE, unchecked under
  // NDEBUG): that precondition, evaluated by CGAL's own predicate, is CGAL's refusal here.
  CgalOutcome split(const Quad &q, const std::array<double, 3> &p, uint32_t &new_v);
  // flip(Facet) on the facet (a, b, c): false on a facet with an infinite cell or a union
  // not strictly convex.
  CgalOutcome flip_23(const std::array<uint32_t, 3> &f);
  // flip(Edge) on the edge (a, b): false unless three finite cells around it and both new
  // cells positive.
  CgalOutcome flip_32(const std::array<uint32_t, 2> &e);

  bool has_cell(const Quad &q) const;
  size_t num_vertices() const; // finite vertices

  struct Counts {
    long V = 0, E = 0, F = 0, T = 0;
    long euler() const { return V - E + F - T; }
  };
  Counts counts() const; // finite elements
  // Every finite cell as its vertex ids, in CGAL's order.
  std::vector<Quad> cells() const;
  // Finite cells not positive by the exact predicate are counted in `negative`, not in
  // the answer (the caller decides).
  // Empty when every cell and vertex passes Tds::is_valid(c) / is_valid(v) (neighbours and
  // indices consistent) and every finite cell is positive by the exact predicate; else what
  // is wrong. The global Tds::is_valid() is not used: its Euler relation holds for a 3-sphere,
  // i.e. only when the boundary coned to the infinite vertex is one sphere (not for the
  // genus-1 and genus-2 meshes, a cavity, or an isolated vertex).
  std::string check(size_t &negative) const;

private:
  std::unique_ptr<CgalVol> vol_;
  CgalEdit();
};

} // namespace diffvol
