// CGAL's Triangulation_3 built from a tetrahedron soup by CGAL::build_triangulation
// (CGAL/Mesh_3/tet_soup_to_c3t3.h, CGAL 5.5), behind a small interface so that CGAL's
// headers are compiled in few translation units only (peer_cgal.cpp, peer_cgal_edit.cpp).
//
// The triangulation is the leanest one the builder accepts: Triangulation_3<Epick, Tds> with
// the plain Triangulation_vertex_base_3 / Triangulation_cell_base_3, extended only by the
// no-op setters the builder calls (no subdomain or surface-patch storage). It holds an
// infinite vertex and one infinite cell per boundary face: every answer leaves them out.
#pragma once

#include "answers.hpp"
#include "edit_policy.hpp"
#include "tet_soup.hpp"

#include <cstdint>
#include <memory>
#include <string>

namespace diffvol {

struct CgalStats {
  bool ok = false;
  std::string refusal;         // why build_triangulation said no
  double convert_ms = 0;       // soup -> std::vector<Point_3>, std::vector<std::array<int,5>>
                               // (oriented positively), part of build_ms
  double build_ms = 0;         // conversion + build_triangulation
  size_t vertices = 0;         // including the infinite vertex
  size_t cells = 0;            // including the infinite cells
  size_t finite_cells = 0;
  size_t vertex_capacity = 0;  // Compact_container capacities
  size_t cell_capacity = 0;
  size_t sizeof_vertex = 0;    // sizeof(Tr::Vertex), point included
  size_t sizeof_point = 0;     // sizeof(Tr::Point)
  size_t sizeof_cell = 0;      // sizeof(Tr::Cell)
};

class CgalVol {
public:
  // Builds from the soup (nullptr when CGAL refuses; `stats` says why).
  static std::unique_ptr<CgalVol> build(const TetSoup &s, CgalStats &stats);
  ~CgalVol();

  // Every relation in input ids (maps CGAL vertex handles through the builder's
  // vertex_handles vector and cells through their sorted vertex quadruples).
  Answers answers(const TetSoup &s) const;
  // VT of one input vertex as CGAL sees it (for reporting non-manifold vertices).
  size_t vertex_star_size(uint32_t v) const;

  // Benchmark sweeps over all finite elements; each returns the number of entries visited
  // (the checksum: the same for every library on a manifold mesh).
  uint64_t sweep_tt() const;  // cell->neighbor(i), finite neighbours counted
  uint64_t sweep_vt() const;  // finite_incident_cells(v) into a reused vector
  uint64_t sweep_et() const;  // incident_cells(edge) circulator, finite cells counted
  uint64_t sweep_vv() const;  // finite_adjacent_vertices(v) into a reused vector

  // The editing benchmark (edit_policy.hpp). Both edit the triangulation in place; the
  // finite cells are kept in a list (the handles, updated in O(1) per operation) to draw
  // from uniformly.
  // `n` 1-4 splits (Triangulation_3::insert_in_cell) of random finite cells at their
  // centroids.
  EditRun split_storm(uint64_t n, uint64_t seed);
  // `attempts` random flips: Triangulation_3::flip(Cell_handle, int) for a 2-3 flip and
  // flip(Cell_handle, int, int) for a 3-2 flip, each checking (finite, degree 3, convex
  // position) and refusing by returning false.
  EditRun flip_storm(uint64_t attempts, uint64_t seed);
  // Counts and capacities as they are now (after edits too); the timings stay 0.
  CgalStats stats() const;

private:
  friend class CgalEdit; // edits the triangulation (peer_cgal_edit.hpp)
  struct Impl;
  std::unique_ptr<Impl> p_;
  CgalVol();
};

} // namespace diffvol
