// CGAL's triangulation type of the volume peers and CgalVol's insides, shared by the
// translation units that include CGAL (peer_cgal.cpp, peer_cgal_edit.cpp) and by nothing
// else: CGAL's headers are slow to compile.
#pragma once

#include "peer_cgal.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/Triangulation_cell_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_3.h>
#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>

#include <vector>

namespace diffvol {

namespace cgal {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

// What build_triangulation calls on vertices and cells, as no-ops: the lean bases keep no
// Mesh_3 data (a Mesh_3 cell would cost far more per tetrahedron).
template <class Gt, class Vb = CGAL::Triangulation_vertex_base_3<Gt>>
struct Soup_vertex_base : Vb {
  template <class TDS2> struct Rebind_TDS {
    using Vb2 = typename Vb::template Rebind_TDS<TDS2>::Other;
    using Other = Soup_vertex_base<Gt, Vb2>;
  };
  using Vb::Vb;
  void set_dimension(int) {}
};

template <class Gt, class Cb = CGAL::Triangulation_cell_base_3<Gt>>
struct Soup_cell_base : Cb {
  using Surface_patch_index = int;
  using Subdomain_index = int;
  template <class TDS2> struct Rebind_TDS {
    using Cb2 = typename Cb::template Rebind_TDS<TDS2>::Other;
    using Other = Soup_cell_base<Gt, Cb2>;
  };
  using Cb::Cb;
  void set_subdomain_index(int) {}
  void set_surface_patch_index(int, int) {}
  int surface_patch_index(int) const { return 0; }
};

using Tds = CGAL::Triangulation_data_structure_3<Soup_vertex_base<K>, Soup_cell_base<K>>;
using Tr = CGAL::Triangulation_3<K, Tds>;
using Vh = Tr::Vertex_handle;
using Ch = Tr::Cell_handle;

} // namespace cgal

struct CgalVol::Impl {
  cgal::Tr tr;
  std::vector<cgal::Vh> handles; // input vertex i -> handles[i + 1]; handles[0] is the infinite one
};

} // namespace diffvol
