// Differential test of topomesh's CHF editing (C API, level 2) against CGAL's
// Triangulation_3: the same seeded sequence of 1-4 splits, 2-3 flips and 3-2 flips applied to
// both, each accepted by both or refused by both, then the same final mesh.
//
//   edit_diffvol cases                               the manifold pathological cases
//   edit_diffvol mesh <dir/name> [--ops N] [--seed S] a tetgen mesh <dir/name>.node/.ele
//
// Both start from the SAME tetrahedra: CGAL's triangulation is built from the soup by
// CGAL::build_triangulation (CgalVol), not as the Delaunay triangulation of the points. The
// tetgen meshes are constrained (-p) meshes of non-convex solids, so the Delaunay
// triangulation of their points has other tetrahedra and fills the convex hull; CGAL's
// insert_in_cell and flip are local and only use the orientation predicate, so they behave
// on the soup's triangulation (infinite cells glued to a non-convex boundary) exactly as on a
// Delaunay one. What CGAL holds is checked against the mesh before the first operation.
//
// Operations are chosen on topomesh's side (a random live tetrahedron; a random face of it;
// preferably an edge of it with three tetrahedra) and addressed to CGAL by vertex tuples
// through a vertex map (topomesh id -> CGAL id, from chf_mesh_vertex_origins; each split's
// new vertex is appended on both sides, in the same order). A split puts the new vertex at
// the centroid, computed here and given to both.
//
// The rules compared, per operation (both sides, same answer):
// - 1-4: accepted iff the point is strictly inside (CGAL: insert_in_cell's precondition,
//   side_of_cell == ON_BOUNDED_SIDE, checked by the peer);
// - 2-3: CGAL's flip(Facet) refuses a facet with an infinite cell, which is exactly a
//   boundary face of the mesh (refused by topomesh), and a union not strictly convex;
// - 3-2: CGAL's flip(Edge) refuses an edge with an infinite cell around it (a boundary
//   edge of the mesh), a degree other than 3, and new cells not positive.
// Both orientation tests are exact (topomesh's src/chf/geometry.rs, CGAL's Epick), so there
// is no tolerated difference: any disagreement, a tuple CGAL lacks, or a new tetrahedron of
// topomesh missing in CGAL fails the test. (This test found topomesh's rounded determinant
// accepting a 2-3 flip into an inverted tetrahedron before the orientation was made exact.)
//
// At the end topomesh is garbage-collected and compared with CGAL: live vertices,
// tetrahedra, faces, edges, V - E + F - T (also chf_mesh_summary's), the set of tetrahedra
// after mapping the ids, chf_mesh_validate, CGAL's Tds::is_valid per cell and vertex, and
// its finite cells exactly positive.
// With TOPOMESH_EDITDIFF_SELFTEST set, CGAL skips some 2-3 flips on purpose: the run must fail.
#include "peer_cgal_edit.hpp"
#include "tet_soup.hpp"
#include "tm_vol.hpp"

#include "../diff_common/relation_call.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

using namespace diffvol;

namespace {

struct EditOptions {
  size_t ops = 2000;
  uint64_t seed = 1;
};

enum Kind { SPLIT, FLIP23, FLIP32, KINDS };
const char *const kind_name[KINDS] = {"1-4", "2-3", "3-2"};

// One operation as both sides see it.
struct Op {
  explicit Op(Kind k) : kind(k) {}
  Kind kind;
  uint32_t target = NONE;             // topomesh tetrahedron, face or edge
  std::vector<uint32_t> tuple;        // its topomesh vertices (4, 3 or 2)
  std::array<double, 3> point{};      // a split's new vertex
  std::vector<Quad> planned;          // what topomesh's plan makes (a split's vertex: the next id)
};

// One mesh's run.
struct Run {
  std::string name;
  TmMesh tm;
  std::vector<double> pos;       // per topomesh vertex
  std::vector<uint32_t> to_cgal; // topomesh vertex -> CGAL vertex
  std::unique_ptr<CgalEdit> cg;
  std::mt19937_64 rng;
  size_t tried[KINDS] = {}, accepted[KINDS] = {};
  bool selftest = false;
  Diff fails;
};

std::vector<uint32_t> rel(Run &r, topomesh_status (*f)(const chf_mesh *, uint32_t, uint32_t *, size_t, size_t *),
                          uint32_t id, const char *what) {
  std::vector<uint32_t> out;
  topomesh_status st = diffcall::call_relation(f, r.tm.m, id, out, 16);
  if (st != TOPOMESH_STATUS_OK) r.fails.add(std::string(what) + "(" + std::to_string(id) + "): " + tm_error(st));
  return out;
}

// rel() on f, named in a failure by its own name.
#define REL(r, f, id) rel(r, f, id, #f)

Quad tv(Run &r, uint32_t t) {
  std::vector<uint32_t> v = REL(r, chf_tetrahedron_vertices, t);
  Quad q{NONE, NONE, NONE, NONE};
  std::copy_n(v.begin(), std::min<size_t>(4, v.size()), q.begin());
  return q;
}

// q with vertex `c` replaced by `x` (src/chf/edit/plan.rs: replaced).
Quad replaced(Quad q, uint32_t c, uint32_t x) {
  for (uint32_t &y : q)
    if (y == c) y = x;
  return q;
}

uint32_t random_live_tet(Run &r) {
  const size_t n = chf_mesh_num_tetrahedra(r.tm.m);
  for (;;) {
    uint32_t t = uint32_t(r.rng() % n);
    bool removed = true;
    chf_tetrahedron_is_removed(r.tm.m, t, &removed);
    if (!removed) return t;
  }
}

Op pick_split(Run &r) {
  Op op(SPLIT);
  op.target = random_live_tet(r);
  Quad q = tv(r, op.target);
  op.tuple.assign(q.begin(), q.end());
  for (int k = 0; k < 3; ++k) {
    double sum = 0;
    for (uint32_t v : q) sum += r.pos[3 * v + k];
    op.point[k] = sum * 0.25;
  }
  const uint32_t x = uint32_t(r.pos.size() / 3);
  for (uint32_t c : q) op.planned.push_back(replaced(q, c, x));
  return op;
}

// A random face of a random tetrahedron; the plan of src/chf/edit/flip_23.rs.
Op pick_flip23(Run &r) {
  Op op(FLIP23);
  std::vector<uint32_t> faces = REL(r, chf_tetrahedron_faces, random_live_tet(r));
  if (faces.size() != 4) return op;
  op.target = faces[r.rng() % 4];
  op.tuple = REL(r, chf_face_vertices, op.target);
  uint32_t hf = NONE, g = NONE;
  chf_face_half_face(r.tm.m, op.target, &hf);
  if (chf_half_face_opposite(r.tm.m, hf, &g) != TOPOMESH_STATUS_OK || g == NONE) return op;
  const Quad q = tv(r, hf / 4);
  const uint32_t apex = tv(r, g / 4)[g % 4];
  for (uint32_t k = 0; k < 4; ++k)
    if (k != hf % 4) op.planned.push_back(replaced(q, q[k], apex));
  return op;
}

// An edge of a random tetrahedron, one with three tetrahedra around it when there is one;
// the plan of src/chf/edit/flip_32.rs.
Op pick_flip32(Run &r) {
  Op op(FLIP32);
  std::vector<uint32_t> edges = REL(r, chf_tetrahedron_edges, random_live_tet(r));
  if (edges.size() != 6) return op;
  std::vector<uint32_t> three;
  for (uint32_t e : edges)
    if (REL(r, chf_edge_tetrahedra, e).size() == 3) three.push_back(e);
  op.target = three.empty() ? edges[r.rng() % 6] : three[r.rng() % three.size()];
  op.tuple = REL(r, chf_edge_vertices, op.target);
  std::vector<uint32_t> ring = REL(r, chf_edge_tetrahedra, op.target);
  if (ring.size() != 3 || op.tuple.size() != 2) return op;
  const Quad q = tv(r, ring[0]);
  uint32_t far = NONE;
  for (uint32_t x : tv(r, ring[1]))
    if (std::find(q.begin(), q.end(), x) == q.end()) far = x;
  op.planned = {replaced(q, op.tuple[1], far), replaced(q, op.tuple[0], far)};
  return op;
}

// Applies `op` to topomesh: the status, the new tetrahedra and a split's new vertex.
topomesh_status tm_apply(Run &r, const Op &op, std::vector<uint32_t> &made, uint32_t &new_v) {
  made.assign(op.kind == SPLIT ? 0 : op.kind == FLIP23 ? 3 : 2, NONE);
  switch (op.kind) {
  case SPLIT: {
    const size_t before = chf_mesh_num_tetrahedra(r.tm.m);
    topomesh_status st = chf_mesh_split_tetrahedron(r.tm.m, op.target, op.point.data(), &new_v);
    if (st == TOPOMESH_STATUS_OK) {
      made.push_back(op.target); // the split tetrahedron keeps its id as one piece
      for (size_t t = before; t < chf_mesh_num_tetrahedra(r.tm.m); ++t) made.push_back(uint32_t(t));
    }
    return st;
  }
  case FLIP23: return chf_mesh_flip_23(r.tm.m, op.target, made.data());
  default: return chf_mesh_flip_32(r.tm.m, op.target, made.data());
  }
}

std::vector<uint32_t> to_cgal(const Run &r, const std::vector<uint32_t> &ids) {
  std::vector<uint32_t> out;
  for (uint32_t v : ids) out.push_back(v < r.to_cgal.size() ? r.to_cgal[v] : NONE);
  return out;
}

// Applies `op` to CGAL (a split's new vertex into `new_v`).
CgalOutcome cg_apply(Run &r, const Op &op, uint32_t &new_v) {
  const std::vector<uint32_t> c = to_cgal(r, op.tuple);
  switch (op.kind) {
  case SPLIT: return c.size() == 4 ? r.cg->split({c[0], c[1], c[2], c[3]}, op.point, new_v) : CgalOutcome::Missing;
  case FLIP23: return c.size() == 3 ? r.cg->flip_23({c[0], c[1], c[2]}) : CgalOutcome::Missing;
  default: return c.size() == 2 ? r.cg->flip_32({c[0], c[1]}) : CgalOutcome::Missing;
  }
}

// Live topomesh tetrahedra as sorted quadruples (topomesh ids).
std::vector<Quad> tm_tets(Run &r) {
  std::vector<Quad> out;
  for (uint32_t t = 0; t < chf_mesh_num_tetrahedra(r.tm.m); ++t) {
    bool removed = true;
    chf_tetrahedron_is_removed(r.tm.m, t, &removed);
    if (removed) continue;
    Quad q = tv(r, t);
    std::sort(q.begin(), q.end());
    out.push_back(q);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string describe(const Op &op) {
  std::string s = std::string(kind_name[op.kind]) + " on topomesh " +
                  (op.kind == SPLIT ? "tetrahedron " : op.kind == FLIP23 ? "face " : "edge ") +
                  std::to_string(op.target) + " (vertices";
  for (uint32_t v : op.tuple) s += " " + std::to_string(v);
  return s + ")";
}

// Both accepted: the split's new vertex joins the map, and every new tetrahedron of
// topomesh is a cell of CGAL.
void after_both(Run &r, const Op &op, const std::vector<uint32_t> &made, uint32_t tm_v, uint32_t cg_v) {
  r.accepted[op.kind]++;
  if (op.kind == SPLIT) {
    if (tm_v != r.to_cgal.size())
      r.fails.add(describe(op) + ": new vertex " + std::to_string(tm_v) + " not the next id");
    r.to_cgal.push_back(cg_v);
    r.pos.insert(r.pos.end(), op.point.begin(), op.point.end());
  }
  for (uint32_t t : made) {
    const Quad q = tv(r, t);
    std::vector<uint32_t> c = to_cgal(r, std::vector<uint32_t>(q.begin(), q.end()));
    if (!r.cg->has_cell({c[0], c[1], c[2], c[3]}))
      r.fails.add(describe(op) + ": new tetrahedron " + std::to_string(t) + " is not a CGAL cell");
  }
}

// One operation on both sides, compared.
void step(Run &r, size_t i) {
  const Kind kind = Kind(r.rng() % KINDS);
  const Op op = kind == SPLIT ? pick_split(r) : kind == FLIP23 ? pick_flip23(r) : pick_flip32(r);
  if (op.target == NONE) return;
  r.tried[kind]++;
  std::vector<uint32_t> made;
  uint32_t tm_v = NONE, cg_v = NONE;
  const topomesh_status st = tm_apply(r, op, made, tm_v);
  const std::string detail = st == TOPOMESH_STATUS_OK ? "" : tm_error(st);
  CgalOutcome co = CgalOutcome::Refused;
  // The self-test: CGAL "refuses" some 2-3 flips without trying them.
  if (!(r.selftest && kind == FLIP23 && i % 7 == 0)) co = cg_apply(r, op, cg_v);
  if (co == CgalOutcome::Missing) {
    r.fails.add(describe(op) + ": CGAL has no such element");
    return;
  }
  const bool tm_ok = st == TOPOMESH_STATUS_OK, cg_ok = co == CgalOutcome::Done;
  if (tm_ok && cg_ok) return after_both(r, op, made, tm_v, cg_v);
  if (tm_ok == cg_ok) return;
  r.fails.add(describe(op) + ": topomesh " + (tm_ok ? "accepted" : "refused (" + detail + ")") + ", CGAL " +
              (cg_ok ? "accepted" : "refused"));
}

// Builds both sides and checks that CGAL holds the mesh's tetrahedra.
bool start(Run &r, const TetSoup &s) {
  std::string err;
  if (!tm_build(s, 2, r.tm, err)) {
    r.fails.add("topomesh build: " + err);
    return false;
  }
  size_t len = 0;
  const uint32_t *origin = chf_mesh_vertex_origins(r.tm.m, &len);
  r.cg = CgalEdit::build(s, err);
  if (!origin || len != s.n_vertices || !r.cg) {
    r.fails.add(!r.cg ? "CGAL refused the soup: " + err : "split vertices: no one-to-one vertex map");
    return false;
  }
  r.to_cgal.assign(origin, origin + len);
  r.pos.resize(3 * len);
  for (size_t v = 0; v < len; ++v) std::copy_n(&s.positions[3 * origin[v]], 3, &r.pos[3 * v]);
  return true;
}

// CGAL's cells in topomesh ids (through the inverse of the vertex map, then `gc`),
// sorted quadruples.
std::vector<Quad> cg_tets(const Run &r, const std::vector<uint32_t> &gc) {
  std::vector<uint32_t> back(r.cg->num_vertices() + r.to_cgal.size(), NONE);
  for (uint32_t v = 0; v < r.to_cgal.size(); ++v)
    if (r.to_cgal[v] < back.size()) back[r.to_cgal[v]] = gc.empty() ? v : gc[v];
  std::vector<Quad> out = r.cg->cells();
  for (Quad &q : out) {
    for (uint32_t &v : q) v = v < back.size() ? back[v] : NONE;
    std::sort(q.begin(), q.end());
  }
  std::sort(out.begin(), out.end());
  return out;
}

void same_tets(Run &r, const std::vector<Quad> &tm, const std::vector<Quad> &cg, const char *when) {
  if (tm == cg) return;
  std::vector<Quad> only_tm, only_cg;
  std::set_difference(tm.begin(), tm.end(), cg.begin(), cg.end(), std::back_inserter(only_tm));
  std::set_difference(cg.begin(), cg.end(), tm.begin(), tm.end(), std::back_inserter(only_cg));
  r.fails.add(std::string(when) + ": tetrahedra differ: " + std::to_string(only_tm.size()) + " only in topomesh, " +
              std::to_string(only_cg.size()) + " only in CGAL");
}

void expect_eq(Run &r, const char *what, long tm, long cg) {
  if (tm != cg) r.fails.add(std::string(what) + ": topomesh " + std::to_string(tm) + ", CGAL " + std::to_string(cg));
}

// Garbage collection, then the final comparison; returns topomesh's counts.
CgalEdit::Counts finish(Run &r) {
  std::vector<uint32_t> vmap(chf_mesh_num_vertices(r.tm.m));
  topomesh_status st = chf_mesh_garbage_collect(r.tm.m, vmap.data(), vmap.size(), nullptr, 0, nullptr, 0, nullptr, 0);
  if (st != TOPOMESH_STATUS_OK) r.fails.add("chf_mesh_garbage_collect: " + tm_error(st));
  if ((st = chf_mesh_validate(r.tm.m)) != TOPOMESH_STATUS_OK) r.fails.add("chf_mesh_validate: " + tm_error(st));
  CgalEdit::Counts tm;
  tm.V = long(chf_mesh_num_live_vertices(r.tm.m));
  tm.E = long(chf_mesh_num_live_edges(r.tm.m));
  tm.F = long(chf_mesh_num_live_faces(r.tm.m));
  tm.T = long(chf_mesh_num_live_tetrahedra(r.tm.m));
  const CgalEdit::Counts cg = r.cg->counts();
  expect_eq(r, "live vertices", tm.V, cg.V);
  expect_eq(r, "edges", tm.E, cg.E);
  expect_eq(r, "faces", tm.F, cg.F);
  expect_eq(r, "tetrahedra", tm.T, cg.T);
  expect_eq(r, "V - E + F - T", tm.euler(), cg.euler());
  chf_summary sum{};
  chf_mesh_summary(r.tm.m, &sum);
  expect_eq(r, "chf_mesh_summary euler_characteristic", long(sum.euler_characteristic), cg.euler());
  expect_eq(r, "chf_mesh_summary tetrahedra", long(sum.tetrahedra), cg.T);
  same_tets(r, tm_tets(r), cg_tets(r, vmap), "after garbage_collect");
  size_t negative = 0;
  const std::string bad = r.cg->check(negative);
  if (!bad.empty()) r.fails.add(bad);
  if (negative) r.fails.add(std::to_string(negative) + " tetrahedra not positive by CGAL's exact predicate");
  return tm;
}

bool edit_run(const TetSoup &s, const EditOptions &opt) {
  Run r;
  r.name = s.name;
  r.rng.seed(opt.seed);
  r.selftest = std::getenv("TOPOMESH_EDITDIFF_SELFTEST") != nullptr;
  CgalEdit::Counts fin;
  if (start(r, s)) {
    same_tets(r, tm_tets(r), cg_tets(r, {}), "before the first operation");
    for (size_t i = 0; i < opt.ops && r.fails.count == 0; ++i) step(r, i);
    fin = finish(r);
  }
  std::printf("%s: %zu ops (1-4 %zu/%zu, 2-3 %zu/%zu, 3-2 %zu/%zu accepted by both/tried); final V=%ld E=%ld F=%ld T=%ld chi=%ld: %s\n",
              s.name.c_str(), r.tried[0] + r.tried[1] + r.tried[2], r.accepted[0], r.tried[0], r.accepted[1],
              r.tried[1], r.accepted[2], r.tried[2], fin.V, fin.E,
              fin.F, fin.T, fin.euler(),
              r.fails.count ? "FAIL" : "same as CGAL");
  for (const std::string &l : r.fails.lines) std::printf("  FAIL %s\n", l.c_str());
  return r.fails.count == 0;
}

int run_cases() {
  int failures = 0;
  for (const Case &c : pathological_cases()) {
    if (c.cgal != CgalExpect::Accept) continue; // non-manifold: CGAL cannot hold them
    failures += !edit_run(c.soup, EditOptions{600, 7}) ? 1 : 0;
  }
  return failures;
}

} // namespace

int main(int argc, char **argv) {
  int failures = 0;
  if (argc >= 2 && std::strcmp(argv[1], "cases") == 0) {
    failures = run_cases();
  } else if (argc >= 3 && std::strcmp(argv[1], "mesh") == 0) {
    EditOptions opt;
    for (int i = 3; i + 1 < argc; i += 2) {
      if (std::strcmp(argv[i], "--ops") == 0) opt.ops = std::strtoul(argv[i + 1], nullptr, 10);
      else if (std::strcmp(argv[i], "--seed") == 0) opt.seed = std::strtoull(argv[i + 1], nullptr, 10);
    }
    TetSoup s;
    std::string err;
    if (!read_tetgen(argv[2], s, err)) {
      std::printf("FAIL: %s\n  The tetrahedral meshes are made by scripts/fetch-tets.sh: run it first.\n",
                  err.c_str());
      return 1;
    }
    failures = !edit_run(s, opt) ? 1 : 0;
  } else {
    std::fprintf(stderr, "usage: edit_diffvol cases | mesh <dir/name> [--ops N] [--seed S]\n");
    return 2;
  }
  std::printf(failures ? "edit_diffvol: FAILED\n" : "edit_diffvol: all checks passed\n");
  return failures ? 1 : 0;
}
