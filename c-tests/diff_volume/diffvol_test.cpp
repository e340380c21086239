// Differential test of topomesh's CHF (C API, levels 1, 2, 3) against CGAL's
// Triangulation_3 (built by CGAL::build_triangulation from the same soup) and against a
// brute-force oracle computed from the soup alone.
//
//   diffvol_test cases                       the pathological cases, written here
//   diffvol_test mesh <dir/name> [--genus g] a tetgen mesh <dir/name>.node/.ele; g: the
//                                            genus of its (single, closed) boundary
//
// Compared per element, in input ids: TT (per face slot, NONE on the boundary), VT, VV, ET
// (as sets, and the rotation order checked as a valid cycle or boundary-to-boundary chain
// and matched with CGAL's circulator up to start and direction), boundary faces (sorted
// triples), V E F T and V - E + F - T; topomesh's summary against the oracle and hand
// counts; the three levels against each other (same answers in the same order); at level 3
// the boundary surface (chf_mesh_boundary). CGAL refuses some non-manifold cases or
// represents them wrongly: that is recorded and printed, and only topomesh is then checked
// (against the oracle and the hand counts). Exit status 1 on any mismatch of topomesh.
#include "answers.hpp"
#include "peer_cgal.hpp"
#include "tet_soup.hpp"
#include "tm_vol.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace diffvol;

namespace {

int g_failures = 0;

void report(const std::string &what, const Diff &d) {
  if (d.count == 0) return;
  g_failures++;
  std::printf("  FAIL %s: %zu differences\n", what.c_str(), d.count);
  for (auto &l : d.lines) std::printf("    %s\n", l.c_str());
}

void expect_eq(Diff &d, const char *field, long want, long got) {
  if (want >= 0 && want != got)
    d.add(std::string(field) + ": expected " + std::to_string(want) + ", got " + std::to_string(got));
}

// Same answers and the same rotation orders.
void compare_levels(const TetSoup &s, const Answers &a, const Answers &b, Diff &d) {
  compare(s, a, b, d);
  if (a.et.size() == b.et.size())
    for (size_t i = 0; i < a.et.size(); ++i)
      if (a.et[i] != b.et[i]) {
        d.add(b.side + " vs " + a.side + ": ET rotation of edge entry " + std::to_string(i) + " differs");
        break;
      }
}

void run(const TetSoup &s, const Expect &ex, CgalExpect cgal_expect, const std::string &why, long genus) {
  std::printf("== %s: %zu vertices, %zu tetrahedra\n", s.name.c_str(), s.n_vertices, s.n_tets());
  const Answers oracle = oracle_answers(s);
  const OracleSummary os = oracle_summary(s, oracle);
  std::printf("  oracle: V=%ld E=%ld F=%ld T=%ld chi=%ld boundary faces=%ld components=%ld "
              "boundary components=%ld boundary chi=%ld non-manifold faces=%ld\n",
              oracle.V, oracle.E, oracle.F, oracle.T, oracle.euler(), os.boundary_faces, os.components,
              os.boundary_components, os.boundary_euler, os.non_manifold_faces);
  // The oracle against the hand counts (checks the test's own arithmetic).
  {
    Diff d;
    expect_eq(d, "V", ex.vertices, oracle.V);
    expect_eq(d, "E", ex.edges, oracle.E);
    expect_eq(d, "F", ex.faces, oracle.F);
    expect_eq(d, "T", ex.tetrahedra, oracle.T);
    expect_eq(d, "boundary faces", ex.boundary_faces, os.boundary_faces);
    expect_eq(d, "boundary components", ex.boundary_components, os.boundary_components);
    expect_eq(d, "components", ex.components, os.components);
    if (ex.euler != -1) expect_eq(d, "euler", 0, ex.euler - oracle.euler());
    if (ex.boundary_euler != -1) expect_eq(d, "boundary euler", 0, ex.boundary_euler - os.boundary_euler);
    expect_eq(d, "non-manifold faces", ex.non_manifold_faces, os.non_manifold_faces);
    report("oracle vs hand counts", d);
  }

  // CGAL.
  CgalStats st;
  std::unique_ptr<CgalVol> cgal = CgalVol::build(s, st);
  Answers cg;
  bool cgal_trusted = false;
  if (!cgal) {
    std::printf("  CGAL: refused (%s)%s%s\n", st.refusal.c_str(),
                cgal_expect == CgalExpect::Refuse ? "; expected: " : "; NOT expected",
                cgal_expect == CgalExpect::Refuse ? why.c_str() : "");
  } else {
    cg = cgal->answers(s);
    Diff d;
    compare(s, oracle, cg, d);
    check_rotations(s, oracle, cg, d);
    if (cgal_expect == CgalExpect::AcceptButWrong) {
      std::printf("  CGAL: built, %zu differences from the oracle (expected: %s)\n", d.count, why.c_str());
      for (auto &l : d.lines) std::printf("    %s\n", l.c_str());
    } else if (d.count) {
      std::printf("  CGAL: built, but differs from the oracle (the harness or CGAL is wrong)\n");
      report("CGAL vs oracle", d);
    } else {
      cgal_trusted = true;
      std::printf("  CGAL: built in %.1f ms, agrees with the oracle (V-E+F-T = %ld)\n", st.build_ms, cg.euler());
    }
  }

  // topomesh at levels 1, 2, 3.
  Answers first;
  for (uint32_t level = 1; level <= 3; ++level) {
    const std::string side = "topomesh L" + std::to_string(level);
    TmMesh tm;
    std::string err;
    if (!tm_build(s, level, tm, err)) {
      g_failures++;
      std::printf("  FAIL %s: build failed: %s\n", side.c_str(), err.c_str());
      continue;
    }
    Diff internal;
    Answers a = tm_answers(s, tm.m, side, internal);
    if (std::getenv("TOPOMESH_DIFFVOL_SELFTEST")) corrupt_for_selftest(a);
    report(side + " C API consistency", internal);

    Diff d;
    compare(s, oracle, a, d);
    check_rotations(s, oracle, a, d);
    report(side + " vs oracle", d);
    if (cgal_trusted) {
      Diff c;
      compare(s, cg, a, c);
      compare_rotations(a, cg, c);
      report(side + " vs CGAL", c);
    }
    if (level == 1) first = a;
    else {
      Diff l;
      compare_levels(s, first, a, l);
      report(side + " vs topomesh L1", l);
    }

    // The summary.
    chf_summary sum{};
    chf_mesh_summary(tm.m, &sum);
    Diff sd;
    expect_eq(sd, "vertices", oracle.V, long(sum.vertices));
    expect_eq(sd, "edges", oracle.E, long(sum.edges));
    expect_eq(sd, "faces", oracle.F, long(sum.faces));
    expect_eq(sd, "tetrahedra", oracle.T, long(sum.tetrahedra));
    expect_eq(sd, "boundary_faces", os.boundary_faces, long(sum.boundary_faces));
    expect_eq(sd, "boundary_edges", os.boundary_edges, long(sum.boundary_edges));
    expect_eq(sd, "boundary_vertices", os.boundary_vertices, long(sum.boundary_vertices));
    expect_eq(sd, "boundary_components", os.boundary_components, long(sum.boundary_components));
    expect_eq(sd, "components", os.components, long(sum.components));
    expect_eq(sd, "isolated_vertices", os.isolated, long(sum.isolated_vertices));
    expect_eq(sd, "non_manifold_faces", os.non_manifold_faces, long(sum.non_manifold_faces));
    if (sum.euler_characteristic != oracle.euler())
      sd.add("euler_characteristic: expected " + std::to_string(oracle.euler()) + ", got " +
             std::to_string(sum.euler_characteristic));
    if (ex.euler != -1 && sum.euler_characteristic != ex.euler)
      sd.add("euler_characteristic: hand count " + std::to_string(ex.euler) + ", got " +
             std::to_string(sum.euler_characteristic));
    if (ex.manifold != -1) expect_eq(sd, "manifold", ex.manifold, sum.manifold ? 1 : 0);
    expect_eq(sd, "split_vertices", ex.split_vertices, long(sum.split_vertices));
    expect_eq(sd, "non_manifold_edges", ex.non_manifold_edges, long(sum.non_manifold_edges));
    expect_eq(sd, "structure vertices (chf_mesh_num_vertices)", ex.structure_vertices,
              long(chf_mesh_num_vertices(tm.m)));
    if (cgal_trusted && cg.euler() != sum.euler_characteristic)
      sd.add("euler_characteristic: CGAL says " + std::to_string(cg.euler()) + ", got " +
             std::to_string(sum.euler_characteristic));
    report(side + " summary", sd);

    // Level 3: the boundary surface as a CHE (manifold inputs: its topology is the oracle's).
    if (level == 3) {
      Diff bd;
      che_mesh *b = nullptr;
      topomesh_status bs = chf_mesh_boundary(tm.m, &b);
      if (bs != TOPOMESH_STATUS_OK || !b) {
        bd.add(std::string("chf_mesh_boundary failed: ") + topomesh_status_str(bs));
      } else {
        che_summary cs{};
        che_mesh_summary(b, &cs);
        expect_eq(bd, "boundary triangles (che) vs chf_mesh_num_boundary_triangles",
                  long(chf_mesh_num_boundary_triangles(tm.m)), long(cs.triangles));
        // Faces with one tetrahedron, whatever the non-manifold faces and seams.
        expect_eq(bd, "chf_mesh_num_boundary_faces", os.boundary_faces, long(chf_mesh_num_boundary_faces(tm.m)));
        expect_eq(bd, "boundary faces + non-manifold + seam half-faces = boundary triangles",
                  long(chf_mesh_num_boundary_triangles(tm.m)),
                  long(chf_mesh_num_boundary_faces(tm.m) + chf_mesh_num_non_manifold_half_faces(tm.m) +
                       chf_mesh_num_seam_half_faces(tm.m)));
        // Only boundary vertices in the surface.
        expect_eq(bd, "isolated vertices of the boundary surface", 0, long(cs.isolated_vertices));
        expect_eq(bd, "chf_mesh_num_boundary_vertices vs the surface's input vertices",
                  long(chf_mesh_num_boundary_vertices(tm.m)), long(che_mesh_num_input_vertices(b)));
        if (sum.manifold) {
          expect_eq(bd, "boundary triangles", os.boundary_faces, long(cs.triangles));
          expect_eq(bd, "boundary vertices", os.boundary_vertices, long(cs.vertices));
          expect_eq(bd, "boundary chi (che: V - E + T)", os.boundary_euler, long(cs.euler_characteristic));
          expect_eq(bd, "boundary curves of the boundary surface", 0, long(cs.boundary_curves));
          expect_eq(bd, "chf_mesh_num_boundary_components", os.boundary_components,
                    long(chf_mesh_num_boundary_components(tm.m)));
          if (genus >= 0) expect_eq(bd, "boundary genus (che)", genus, long(cs.genus));
        }
        std::printf("  %s boundary surface: %lu triangles, %lu edges, genus %ld, %lu components\n", side.c_str(),
                    (unsigned long)cs.triangles, (unsigned long)cs.edges, (long)cs.genus,
                    (unsigned long)cs.components);
        che_mesh_free(b);
      }
      report(side + " boundary surface", bd);
    }
    std::printf("  %s: V=%lu E=%lu F=%lu T=%lu chi=%ld manifold=%d split=%lu non-manifold edges=%lu faces=%lu "
                "(structure: %zu vertices, %zu edges, %zu faces)\n",
                side.c_str(), (unsigned long)sum.vertices, (unsigned long)sum.edges, (unsigned long)sum.faces,
                (unsigned long)sum.tetrahedra, (long)sum.euler_characteristic, int(sum.manifold),
                (unsigned long)sum.split_vertices, (unsigned long)sum.non_manifold_edges,
                (unsigned long)sum.non_manifold_faces, chf_mesh_num_vertices(tm.m), chf_mesh_num_edges(tm.m),
                chf_mesh_num_faces(tm.m));
  }
}

} // namespace

int main(int argc, char **argv) {
  if (argc >= 2 && std::strcmp(argv[1], "cases") == 0) {
    for (const Case &c : pathological_cases()) run(c.soup, c.expect, c.cgal, c.why, -1);
  } else if (argc >= 3 && std::strcmp(argv[1], "mesh") == 0) {
    long genus = -1;
    for (int i = 3; i + 1 < argc; ++i)
      if (std::strcmp(argv[i], "--genus") == 0) genus = std::atol(argv[i + 1]);
    TetSoup s;
    std::string err;
    if (!read_tetgen(argv[2], s, err)) {
      std::printf("FAIL: %s\n  The tetrahedral meshes are made by scripts/fetch-tets.sh (into "
                  "${TOPOMESH_MESH_DIR:-$HOME/.cache/topomesh/meshes}/tets): run it first.\n",
                  err.c_str());
      return 1;
    }
    Expect ex;
    if (genus >= 0) {
      // A closed surface of genus g bounding a handlebody: chi = 1 - g, boundary chi 2 - 2g.
      ex.euler = 1 - genus;
      ex.boundary_euler = 2 - 2 * genus;
      ex.boundary_components = 1;
      ex.components = 1;
      ex.manifold = 1;
      ex.split_vertices = 0;
      ex.non_manifold_faces = 0;
      ex.non_manifold_edges = 0;
      ex.structure_vertices = long(s.n_vertices);
    }
    run(s, ex, CgalExpect::Accept, "", genus);
  } else {
    std::fprintf(stderr, "usage: diffvol_test cases | mesh <dir/name> [--genus g]\n");
    return 2;
  }
  if (g_failures) {
    std::printf("diffvol: %d FAILED checks\n", g_failures);
    return 1;
  }
  std::printf("diffvol: all checks passed\n");
  return 0;
}
