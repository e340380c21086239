// Differential test of topomesh against OpenMesh and CGAL on one mesh at one CHE level.
//
//   topomesh_diff MESH.off LEVEL
//
// 1. Reads the OFF once (fan-triangulating polygons); every library gets these arrays.
// 2. Brute-force facts of the input complex vs che_mesh_summary; topomesh must keep every
//    non-degenerate triangle, in order, and its triangles must be the input ones (oriented
//    or flipped; the flips counted must equal flipped_triangles).
// 3. Input build: OpenMesh and CGAL from the arrays. When both accept every face and
//    topomesh neither split nor flipped, every relation is compared element by element.
//    A refused face changes a peer's adjacency everywhere around it, so otherwise only the
//    facts are compared (and what each library kept is printed).
// 4. Canonical build: OpenMesh and CGAL from topomesh's own oriented, split triangles (the
//    V array); they must accept all of it, and every relation is compared again, now on
//    every mesh (shuffled and non-manifold ones included).
// 5. Zero-copy views and level changes (build at 0, raise to LEVEL: the same views).
// Exit status 1 on any mismatch; every mismatch prints the mesh, the element, both answers.
#include "compare.hpp"
#include "facts.hpp"
#include "off_reader.hpp"
#include "peers.hpp"
#include "tm_answers.hpp"

#include <cmath>
#include <cstdlib>
#include <cstring>

using namespace diffmesh;

namespace {

struct Tm {
  che_mesh *m = nullptr;
  Tm() = default;
  Tm(const Tm &) = delete;
  ~Tm() { che_mesh_free(m); }
};

std::vector<uint32_t> view(const uint32_t *(*f)(const che_mesh *, size_t *), const che_mesh *m) {
  size_t n = 0;
  const uint32_t *p = f(m, &n);
  return p ? std::vector<uint32_t>(p, p + n) : std::vector<uint32_t>();
}

void check_summary(const che_summary &s, const Facts &f, Checker &chk) {
  auto eq = [&](const char *name, long long got, long long want) {
    DIFF_CHECK(chk, got == want, std::string("summary ") + name,
              "topomesh " + std::to_string(got) + ", brute force " + std::to_string(want));
  };
  eq("vertices", s.vertices, f.vertices);
  eq("edges", s.edges, f.edges);
  eq("triangles", s.triangles, f.triangles);
  eq("boundary_edges", s.boundary_edges, f.boundary_edges);
  eq("boundary_curves", s.boundary_curves, f.boundary_curves);
  eq("components", s.components, f.components);
  eq("isolated_vertices", s.isolated_vertices, f.isolated_vertices);
  eq("euler_characteristic", s.euler_characteristic, f.euler);
  eq("genus", s.genus, f.genus);
  eq("dropped_degenerate", s.dropped_degenerate, f.degenerate);
  eq("non_manifold_edges", s.non_manifold_edges, f.non_manifold_edges);
  eq("split_vertices", s.split_vertices, f.non_manifold_vertices);
  eq("non_orientable_components", s.non_orientable_components, f.non_orientable_components);
  eq("orientable", s.orientable, f.non_orientable_components == 0);
  eq("manifold", s.manifold, f.non_manifold_edges == 0 && f.non_manifold_vertices == 0);
}

// Level 1 answers vertex and edge queries by scanning all half-edges: sample so that a test
// stays within a few seconds.
Sampling sampling_for(uint32_t level, size_t nv, size_t ne, size_t nt, uint64_t boundary_edges) {
  Sampling s;
  if (level >= 2) return s;
  const double budget = 4e8, scan = 3.0 * double(nt);
  auto stride = [&](size_t n, double per) {
    return std::max<size_t>(1, size_t(std::ceil(double(n) * per * scan / budget)));
  };
  s.vertex_stride = stride(nv, 14);
  s.edge_stride = stride(ne, 8);
  s.face_stride = stride(nt, 5);
  s.curves = double(boundary_edges) * scan <= 2 * budget;
  return s;
}

void print_build(const char *lib, const PeerBuild &b) {
  std::printf("  %-8s offered %zu triangles (skipped %zu degenerate), refused %zu", lib, b.submitted,
              b.skipped_degenerate, b.refused);
  if (b.refused) {
    std::printf(" (first:");
    for (uint32_t t : b.refused_examples) std::printf(" %u", t);
    std::printf(")");
  }
  std::printf("%s\n", b.vertices_in_order ? "" : "  VERTICES NOT IN ORDER");
}

// TOPOMESH_DIFF_SELFTEST=1 corrupts a few of topomesh's answers so that a test proves the
// comparison catches them (registered with WILL_FAIL).
void maybe_corrupt(Answers &a) {
  static const bool on = std::getenv("TOPOMESH_DIFF_SELFTEST") != nullptr;
  if (!on) return;
  for (size_t v = 0; v < a.have_v.size(); ++v)
    if (a.have_v[v] && a.vv[v].size() >= 3) { // clockwise instead of counter-clockwise
      std::reverse(a.vv[v].begin(), a.vv[v].end());
      break;
    }
  for (size_t f = 0; f < a.have_f.size(); ++f)
    if (a.have_f[f]) {
      std::swap(a.ff[f][0], a.ff[f][1]);
      break;
    }
  for (size_t e = 0; e < a.have_e.size(); ++e)
    if (a.have_e[e]) {
      a.ef[e].push_back(0);
      break;
    }
  if (!a.curves.empty() && a.curves[0].size() > 3) std::reverse(a.curves[0].begin(), a.curves[0].end());
}

} // namespace

int main(int argc, char **argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s MESH.off LEVEL\n", argv[0]);
    return 2;
  }
  const std::string path = argv[1];
  const uint32_t level = uint32_t(std::atoi(argv[2]));
  Soup soup;
  std::string err;
  if (!read_off(path, soup, err)) {
    std::printf("FAIL: %s\n(the mesh cache is made by scripts/fetch-meshes.sh; set TOPOMESH_MESH_DIR "
                "or the CMake cache variable TOPOMESH_MESH_DIR)\n",
                err.c_str());
    return 1;
  }
  Checker chk;
  chk.context = soup.name + " L" + std::to_string(level);
  std::printf("%s: %s, %zu vertices, %zu faces (", soup.name.c_str(), soup.header.c_str(), soup.n_vertices,
              soup.n_faces);
  for (auto [n, c] : soup.face_sizes) std::printf(" %zu %d-gons", c, n);
  std::printf(" ) -> %zu triangles, %zu degenerate%s%s\n", soup.n_triangles(), soup.degenerate,
              soup.vertex_extras ? ", extra vertex data" : "", soup.face_extras ? ", face colours" : "");

  const Facts facts = brute_force_facts(soup);
  std::printf("  facts: V %llu E %llu F %llu chi %lld genus %lld, %llu components, %llu isolated, "
              "%llu boundary edges in %llu curves, %llu non-manifold edges, %llu non-manifold vertices, "
              "%llu non-orientable components\n",
              (unsigned long long)facts.vertices, (unsigned long long)facts.edges,
              (unsigned long long)facts.triangles, (long long)facts.euler, (long long)facts.genus,
              (unsigned long long)facts.components, (unsigned long long)facts.isolated_vertices,
              (unsigned long long)facts.boundary_edges, (unsigned long long)facts.boundary_curves,
              (unsigned long long)facts.non_manifold_edges, (unsigned long long)facts.non_manifold_vertices,
              (unsigned long long)facts.non_orientable_components);

  // --- topomesh from the arrays.
  Tm tm;
  topomesh_status st = che_mesh_from_triangles(soup.triangles.data(), soup.n_triangles(), soup.n_vertices,
                                               soup.positions.data(), level, &tm.m);
  if (st != TOPOMESH_STATUS_OK) {
    std::printf("FAIL: che_mesh_from_triangles: %s (%s)\n", topomesh_status_str(st), last_error().c_str());
    return 1;
  }
  DIFF_CHECK(chk, che_mesh_level(tm.m) == level, "level", std::to_string(che_mesh_level(tm.m)));
  che_summary sum;
  std::memset(&sum, 0, sizeof sum);
  DIFF_CHECK(chk, che_mesh_summary(tm.m, &sum) == TOPOMESH_STATUS_OK, "summary call", last_error());
  check_summary(sum, facts, chk);
  const size_t nv = che_mesh_num_vertices(tm.m), nt = che_mesh_num_triangles(tm.m),
               ne = che_mesh_num_edges(tm.m);
  std::printf("  topomesh: %zu vertices (%zu added by splits), %zu triangles, %zu edges, %zu curves; "
              "dropped %llu, flipped %llu, split %llu, non-manifold edges %llu\n",
              nv, nv - soup.n_vertices, nt, ne, che_mesh_num_boundary_curves(tm.m),
              (unsigned long long)sum.dropped_degenerate, (unsigned long long)sum.flipped_triangles,
              (unsigned long long)sum.split_vertices, (unsigned long long)sum.non_manifold_edges);

  // Every non-degenerate input triangle kept, in order, as itself or flipped.
  std::vector<uint32_t> tori = view(che_mesh_triangle_origins, tm.m);
  std::vector<uint32_t> vori = view(che_mesh_vertex_origins, tm.m);
  std::vector<uint32_t> V = view(che_mesh_half_edge_vertices, tm.m);
  {
    std::vector<uint32_t> kept;
    for (uint32_t t = 0; t < soup.n_triangles(); ++t)
      if (!soup.is_degenerate(t)) kept.push_back(t);
    DIFF_CHECK(chk, tori == kept, "kept triangles",
              std::to_string(tori.size()) + " kept, " + std::to_string(kept.size()) + " non-degenerate given");
    size_t flipped = 0;
    for (size_t t = 0; t < std::min(tori.size(), nt) && vori.size() == nv && V.size() == 3 * nt; ++t) {
      const uint32_t *in = &soup.triangles[3 * size_t(tori[t])];
      uint32_t out[3] = {vori[V[3 * t]], vori[V[3 * t + 1]], vori[V[3 * t + 2]]};
      bool same = false, rev = false;
      for (int r = 0; r < 3; ++r) {
        same |= out[0] == in[r] && out[1] == in[(r + 1) % 3] && out[2] == in[(r + 2) % 3];
        rev |= out[0] == in[r] && out[1] == in[(r + 2) % 3] && out[2] == in[(r + 1) % 3];
      }
      DIFF_CHECK(chk, same || rev, "triangle corners",
                "t " + std::to_string(t) + " from input " + std::to_string(tori[t]));
      flipped += rev && !same;
    }
    DIFF_CHECK(chk, flipped == sum.flipped_triangles, "flipped count",
              std::to_string(flipped) + " triangles reversed, summary says " +
                  std::to_string(sum.flipped_triangles));
  }

  const Sampling samp = sampling_for(level, nv, ne, nt, sum.boundary_edges);
  if (level < 2)
    std::printf("  level %u: asking every %zu-th vertex, %zu-th edge, %zu-th triangle%s\n", level,
                samp.vertex_stride, samp.edge_stride, samp.face_stride, samp.curves ? "" : ", no curves");

  // --- Input build of the peers.
  PeerInput in{soup.n_vertices, soup.positions.data(), soup.triangles.data(), soup.n_triangles()};
  PeerBuild ob, cb;
  Answers om = openmesh_answers(in, ob), cg = cgal_answers(in, cb);
  print_build("OpenMesh", ob);
  print_build("CGAL", cb);
  DIFF_CHECK(chk, ob.vertices_in_order && cb.vertices_in_order, "peer vertex order", "");
  Checker peers;
  peers.context = chk.context + " OpenMesh vs CGAL";
  bool full_input = ob.refused == 0 && cb.refused == 0 && nv == soup.n_vertices && sum.flipped_triangles == 0;
  if (full_input) {
    std::vector<uint32_t> ident(nv);
    for (uint32_t v = 0; v < nv; ++v) ident[v] = v;
    const std::string ctx = chk.context;
    chk.context = ctx + " input";
    Answers a = topomesh_answers(tm.m, ident, tori, soup.n_triangles(), samp, chk);
    maybe_corrupt(a);
    compare(a, om, chk);
    compare(a, cg, chk);
    compare(om, cg, peers);
    chk.context = ctx;
    std::printf("  input build: every relation compared with both peers\n");
  } else {
    std::printf("  input build: %s; compared the facts only\n",
                ob.refused || cb.refused ? "a peer refused faces"
                : nv != soup.n_vertices  ? "topomesh split non-manifold vertices the peers keep"
                                         : "topomesh flipped triangles");
  }

  // --- Canonical build: the peers from topomesh's own triangles.
  {
    std::vector<double> pos(3 * nv);
    for (size_t v = 0; v < nv && vori.size() == nv; ++v)
      for (int k = 0; k < 3; ++k) pos[3 * v + k] = soup.positions[3 * size_t(vori[v]) + k];
    PeerInput cin{nv, pos.data(), V.data(), nt};
    PeerBuild ob2, cb2;
    Answers om2 = openmesh_answers(cin, ob2), cg2 = cgal_answers(cin, cb2);
    if (ob2.refused || cb2.refused) {
      print_build("OpenMesh", ob2);
      print_build("CGAL", cb2);
    }
    // topomesh keeps every half-edge of a non-manifold edge unpaired (by design): after the
    // split, two of its triangles may still share a vertex pair, a slit the peers would glue.
    size_t slits = 0;
    {
      size_t olen = 0;
      const uint32_t *O = che_mesh_opposites(tm.m, &olen);
      std::vector<Pair> open;
      for (uint32_t h = 0; O && h < olen; ++h)
        if (O[h] == NONE) open.push_back(mkpair(V[h], V[h % 3 == 2 ? h - 2 : h + 1]));
      std::sort(open.begin(), open.end());
      for (size_t i = 1; i < open.size(); ++i) slits += open[i] == open[i - 1];
    }
    bool nm = sum.non_manifold_edges > 0;
    DIFF_CHECK(chk, ob2.refused == 0 || nm, "canonical build refused by OpenMesh", std::to_string(ob2.refused));
    DIFF_CHECK(chk, cb2.refused == 0 || nm, "canonical build refused by CGAL", std::to_string(cb2.refused));
    DIFF_CHECK(chk, slits == 0 || nm, "unpaired half-edges on one vertex pair", std::to_string(slits));
    if (slits > 0) {
      const std::string ctx = chk.context;
      chk.context = ctx + " self";
      std::vector<uint32_t> vid(nv), fid(nt);
      for (uint32_t i = 0; i < nv; ++i) vid[i] = i;
      for (uint32_t i = 0; i < nt; ++i) fid[i] = i;
      topomesh_answers(tm.m, vid, fid, nt, samp, chk);
      chk.context = ctx;
      std::printf("  canonical build: not compared: %zu vertex pairs keep two unpaired half-edges (what is "
                  "left of non-manifold edges; the peers would pair them); topomesh's own answers checked\n",
                  slits);
    } else if (ob2.refused == 0 && cb2.refused == 0) {
      std::vector<uint32_t> ident(std::max(nv, nt));
      for (uint32_t i = 0; i < ident.size(); ++i) ident[i] = i;
      std::vector<uint32_t> vid(ident.begin(), ident.begin() + nv), fid(ident.begin(), ident.begin() + nt);
      const std::string ctx = chk.context;
      chk.context = ctx + " canonical";
      Answers a = topomesh_answers(tm.m, vid, fid, nt, samp, chk);
      maybe_corrupt(a);
      compare(a, om2, chk);
      compare(a, cg2, chk);
      compare(om2, cg2, peers);
      chk.context = ctx;
      std::printf("  canonical build: peers accept all %zu triangles; every relation compared\n", nt);
    }
  }
  if (peers.failures) std::printf("  note: OpenMesh and CGAL disagree %zu times (above)\n", peers.failures);

  // --- Views and level changes.
  check_views(tm.m, chk);
  {
    Tm low;
    if (che_mesh_from_triangles(soup.triangles.data(), soup.n_triangles(), soup.n_vertices, nullptr, 0,
                                &low.m) != TOPOMESH_STATUS_OK ||
        che_mesh_build_level(low.m, level) != TOPOMESH_STATUS_OK) {
      chk.fail("build_level", last_error());
    } else {
      auto same = [&](const char *what, const uint32_t *(*f)(const che_mesh *, size_t *)) {
        size_t la = 0, lb = 0;
        const uint32_t *pa = f(tm.m, &la), *pb = f(low.m, &lb);
        DIFF_CHECK(chk, la == lb && (la == 0 || std::memcmp(pa, pb, 4 * la) == 0), std::string("raised level ") + what,
                  "built at 0 then raised to " + std::to_string(level) + " differs from built at " +
                      std::to_string(level));
      };
      same("V", che_mesh_half_edge_vertices);
      same("O", che_mesh_opposites);
      same("VH", che_mesh_vertex_half_edges);
      same("EH", che_mesh_edge_half_edges);
      same("CH", che_mesh_curve_half_edges);
      DIFF_CHECK(chk, che_mesh_num_edges(low.m) == ne, "raised level edges", "");
    }
  }

  if (chk.failures) {
    std::printf("FAIL: %s: %zu mismatches\n", chk.context.c_str(), chk.failures);
    return 1;
  }
  std::printf("PASS: %s\n", chk.context.c_str());
  return 0;
}
