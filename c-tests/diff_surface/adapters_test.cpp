// The adapters <topomesh/openmesh.hpp> and <topomesh/cgal.hpp> on one mesh at one level:
//
//   topomesh_adapters MESH.off LEVEL
//
// 1. The half-edge export loaded into an OpenMesh TriMesh and a CGAL Surface_mesh through
//    the adapters (to_openmesh, to_surface_mesh) answers every relation as the CHE does,
//    element by element, in the structure's own ids (the adapters keep vertex, triangle and
//    edge ids), compared by compare.cpp.
// 2. Round trips CHE -> OpenMesh -> CHE and CHE -> Surface_mesh -> CHE give the arrays of
//    a fresh build from the CHE's own triangles (V), and V and the positions unchanged.
// 3. Given a volume file instead, to_triangulation() fills a Mesh_3 triangulation whose
//    finite cells and vertices are the volume's, combinatorially valid, positively oriented.
// Exit status 1 on any mismatch.
#include "cgal_mesh.hpp"
#include "compare.hpp"
#include "om_mesh.hpp"
#include "tm_answers.hpp"

#include <topomesh/cgal.hpp>
#include <topomesh/openmesh.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Labeled_mesh_domain_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/boost/graph/iterator.h>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace diffmesh;

namespace {

using OmMesh = om::Mesh;
using K = cg::K;
using SmMesh = cg::Mesh;

Answers openmesh_answers_of(const OmMesh &m) {
  Answers a;
  a.lib = "OpenMesh (adapter)";
  a.resize(m.n_vertices(), m.n_edges(), m.n_faces());
  auto vid = [](OpenMesh::VertexHandle v) { return uint32_t(v.idx()); };
  auto fid = [](OpenMesh::FaceHandle f) { return f.is_valid() ? uint32_t(f.idx()) : NONE; };
  om::element_answers(m, a, fid);
  a.have_curves = true;
  std::vector<uint8_t> seen(m.n_halfedges(), 0);
  for (auto h : m.halfedges()) {
    if (!m.is_boundary(h) || seen[size_t(h.idx())]) continue;
    std::vector<uint32_t> loop;
    for (auto g = h; !seen[size_t(g.idx())]; g = m.next_halfedge_handle(g)) {
      seen[size_t(g.idx())] = 1;
      loop.push_back(vid(m.from_vertex_handle(g)));
    }
    std::reverse(loop.begin(), loop.end()); // holes run against topomesh's curves
    a.curves.push_back(loop);
  }
  return a;
}

Answers cgal_answers_of(const SmMesh &m) {
  using VI = SmMesh::Vertex_index;
  using FI = SmMesh::Face_index;
  using HI = SmMesh::Halfedge_index;
  Answers a;
  a.lib = "CGAL (adapter)";
  a.resize(m.number_of_vertices(), m.number_of_edges(), m.number_of_faces());
  auto vid = [](VI v) { return uint32_t(size_t(v)); };
  auto fid = [](FI f) { return f == SmMesh::null_face() ? NONE : uint32_t(size_t(f)); };
  cg::element_answers(m, a, fid);
  a.have_curves = true;
  std::vector<uint8_t> seen(m.number_of_halfedges(), 0);
  for (HI h : m.halfedges()) {
    if (!m.is_border(h) || seen[size_t(h)]) continue;
    std::vector<uint32_t> loop;
    for (HI g = h; !seen[size_t(g)]; g = m.next(g)) {
      seen[size_t(g)] = 1;
      loop.push_back(vid(m.source(g)));
    }
    std::reverse(loop.begin(), loop.end());
    a.curves.push_back(loop);
  }
  return a;
}

// compare() matches edges by vertex pair, which a CHE's non-manifold edge (kept as one
// edge per pair of triangles) repeats. The adapters keep edge ids, so those edges are
// compared here by id instead, and left out of compare().
void compare_repeated_edges(Answers &tm, Answers &peer, Checker &chk) {
  std::vector<Pair> pairs;
  for (size_t e = 0; e < tm.ev.size(); ++e)
    if (tm.have_e[e]) pairs.push_back(tm.ev[e]);
  std::sort(pairs.begin(), pairs.end());
  for (size_t e = 0; e < tm.ev.size() && e < peer.ev.size(); ++e) {
    if (!tm.have_e[e]) continue;
    const auto range = std::equal_range(pairs.begin(), pairs.end(), tm.ev[e]);
    if (range.second - range.first < 2) continue;
    DIFF_CHECK(chk, tm.ev[e] == peer.ev[e] && tm.ef[e] == peer.ef[e] && tm.ee[e] == peer.ee[e],
               "repeated edge " + peer.lib, "edge " + std::to_string(e) + " " + str(tm.ev[e]));
    tm.have_e[e] = peer.have_e[e] = 0;
  }
}

std::vector<uint32_t> vec(topomesh::Span<uint32_t> s) { return std::vector<uint32_t>(s.begin(), s.end()); }

// `back` (a round trip through `lib`) against `fresh` (built from s's triangles) and `s`.
void check_round_trip(const char *lib, const topomesh::Surface &s, const topomesh::Surface &fresh,
                      const topomesh::Surface &back, Checker &chk) {
  const std::string kind = std::string("round trip ") + lib;
  DIFF_CHECK(chk, vec(back.half_edge_vertices()) == vec(s.half_edge_vertices()), kind, "V differs");
  const std::vector<double> p(s.positions().begin(), s.positions().end()),
      q(back.positions().begin(), back.positions().end());
  DIFF_CHECK(chk, p == q, kind, "positions differ");
  DIFF_CHECK(chk, back.halfedge().twin == fresh.halfedge().twin, kind, "twins differ");
  DIFF_CHECK(chk, back.halfedge().edge == fresh.halfedge().edge, kind, "edge ids differ");
  DIFF_CHECK(chk, vec(back.opposites()) == vec(fresh.opposites()), kind, "O differs");
  DIFF_CHECK(chk, vec(back.vertex_half_edges()) == vec(fresh.vertex_half_edges()), kind, "VH differs");
  DIFF_CHECK(chk, vec(back.edge_half_edges()) == vec(fresh.edge_half_edges()), kind, "EH differs");
  DIFF_CHECK(chk, vec(back.curve_half_edges()) == vec(fresh.curve_half_edges()), kind, "CH differs");
}

bool is_volume(const std::string &path) {
  for (const char *ext : {".node", ".mesh", ".msh", ".ele"})
    if (path.size() > std::strlen(ext) && path.compare(path.size() - std::strlen(ext), std::string::npos, ext) == 0)
      return true;
  return false;
}

void volume_check(const std::string &path, Checker &chk) {
  using Tr = CGAL::Mesh_triangulation_3<CGAL::Labeled_mesh_domain_3<K>>::type;
  const topomesh::Volume vol = topomesh::Volume::load(path);
  Tr tr;
  DIFF_CHECK(chk, topomesh::cgal::to_triangulation(vol, tr), "Triangulation_3",
             "build_triangulation failed");
  DIFF_CHECK(chk, tr.number_of_finite_cells() == vol.num_tetrahedra(), "Triangulation_3",
             std::to_string(tr.number_of_finite_cells()) + " cells");
  DIFF_CHECK(chk, tr.number_of_vertices() == vol.num_vertices(), "Triangulation_3",
             std::to_string(tr.number_of_vertices()) + " vertices");
  // The combinatorial checks (a tetrahedral mesh need not be a regular triangulation, which
  // tr.is_valid() also asks), and every finite cell positively oriented.
  DIFF_CHECK(chk, tr.tds().is_valid(), "Triangulation_3", "tds().is_valid() is false");
  auto point = tr.geom_traits().construct_point_3_object();
  size_t negative = 0;
  for (auto c : tr.finite_cell_handles())
    negative += CGAL::orientation(point(tr.point(c, 0)), point(tr.point(c, 1)), point(tr.point(c, 2)),
                                  point(tr.point(c, 3))) != CGAL::POSITIVE;
  DIFF_CHECK(chk, negative == 0, "Triangulation_3", std::to_string(negative) + " cells not positive");
  std::printf("%s: %zu tetrahedra through build_triangulation\n", path.c_str(), vol.num_tetrahedra());
}

} // namespace

int main(int argc, char **argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s MESH.off LEVEL\n", argv[0]);
    return 2;
  }
  ::omerr().disable();
  topomesh::Options opts;
  opts.level = uint32_t(std::atoi(argv[2]));
  Checker chk;
  chk.context = std::string(argv[1]) + " L" + argv[2];
  try {
    if (is_volume(argv[1])) {
      volume_check(argv[1], chk);
      return chk.failures ? 1 : 0;
    }
    const topomesh::Surface s = topomesh::Surface::load(argv[1], opts);
    const size_t nv = s.num_vertices(), nt = s.num_triangles();
    std::vector<uint32_t> ident_v(nv), ident_t(nt);
    for (size_t i = 0; i < nv; ++i) ident_v[i] = uint32_t(i);
    for (size_t i = 0; i < nt; ++i) ident_t[i] = uint32_t(i);
    // Below level 2 the CHE answers vertex and edge queries by scanning: its answers come
    // from a level 2 build of the same file (the same vertices and triangles), while the
    // adapters load the export of level `opts.level`.
    topomesh::Options asked = opts;
    asked.level = std::max<uint32_t>(opts.level, 2);
    const topomesh::Surface answering = topomesh::Surface::load(argv[1], asked);
    DIFF_CHECK(chk, vec(answering.half_edge_vertices()) == vec(s.half_edge_vertices()), "levels",
               "the level 2 build has other triangles");
    const Answers tm = topomesh_answers(answering.handle(), ident_v, ident_t, nt, Sampling{}, chk);

    const OmMesh om = topomesh::openmesh::to_openmesh<OmMesh>(s);
    const SmMesh sm = topomesh::cgal::to_surface_mesh<SmMesh>(s);
    DIFF_CHECK(chk, sm.is_valid(false), "CGAL validity", "Surface_mesh::is_valid() is false");
    Answers om_answers = openmesh_answers_of(om), sm_answers = cgal_answers_of(sm);
    Answers tm_om = tm, tm_sm = tm;
    compare_repeated_edges(tm_om, om_answers, chk);
    compare_repeated_edges(tm_sm, sm_answers, chk);
    compare(tm_om, om_answers, chk);
    compare(tm_sm, sm_answers, chk);

    const std::vector<double> pos(s.positions().begin(), s.positions().end());
    const topomesh::Surface fresh =
        topomesh::Surface::from_triangles(s.halfedge().vertex, nv, pos, opts);
    check_round_trip("OpenMesh", s, fresh, topomesh::openmesh::from_openmesh(om, opts), chk);
    check_round_trip("CGAL", s, fresh, topomesh::cgal::from_surface_mesh(sm, opts), chk);
    std::printf("%s: %zu vertices, %zu triangles: every relation through both adapters, both "
                "round trips\n",
                chk.context.c_str(), nv, nt);
  } catch (const std::exception &e) {
    std::printf("FAIL %s: %s\n", chk.context.c_str(), e.what());
    return 1;
  }
  if (chk.failures) {
    std::printf("FAIL %s: %zu mismatches\n", chk.context.c_str(), chk.failures);
    return 1;
  }
  return 0;
}
