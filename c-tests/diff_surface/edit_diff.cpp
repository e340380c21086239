// Differential test of surface editing: topomesh (through the C++ wrapper) against
// OpenMesh (TriMesh) and CGAL (Surface_mesh), on one mesh.
//
//   topomesh_edit_diff MESH.off sequence N   N seeded random flips, edge splits, edge
//                                            collapses and triangle removals
//   topomesh_edit_diff MESH.off remove-all   every triangle removed, in a seeded order
//   topomesh_edit_diff MESH.off isolate      the triangles around some vertices removed,
//                                            leaving them isolated
//
// topomesh builds the mesh (level 3) and the peers are built from its oriented triangles,
// so that all three start from the same surface (checked). Each operation is drawn from
// topomesh's live triangles and given to every library as vertex ids (see edit_ops.hpp);
// each library decides with its own check (topomesh's is_flip_ok / is_collapse_ok and a
// split's status, OpenMesh's is_flip_ok / is_collapse_ok, CGAL's does_satisfy_link_condition
// and the flip conditions CGAL leaves to the caller, see edit_cgal.cpp) and applies the
// accepted ones. The same operations must be accepted and refused by all three; after the
// edits, and after garbage collection on all three (halfway through a sequence, and at the
// end), the counts, the Euler characteristic, the boundary and the oriented triangles (in
// shared ids) must be equal, up to the rule differences same_meshes() checks exactly.
// Exit status 1 on any difference, 2 for bad arguments or a mesh the sequences cannot
// compare (see unflagged()); one summary line per run.
#include "../diff_common/splitmix.hpp"
#include "edit_ops.hpp"
#include "off_reader.hpp"

#include <topomesh/topomesh.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <optional>

using namespace diffmesh;
using namespace topomesh;

namespace {

// splitmix64: the same sequence on every platform (std's distributions are not).
struct Rng {
  uint64_t s;
  uint64_t next() { return diffcommon::splitmix64(s); }
  uint32_t below(size_t n) { return uint32_t(next() % n); }
};

const char *kind_name(OpKind k) {
  static const char *names[] = {"flip", "split", "collapse", "remove"};
  return names[int(k)];
}
const char *outcome_name(Outcome o) {
  static const char *names[] = {"refused", "done", "missing"};
  return names[int(o)];
}

// topomesh's side: the surface, and the shared id of each of its vertices (the identity
// until a removal splits a vertex or garbage collection renumbers).
struct TmSide {
  Surface s;
  std::vector<uint32_t> shared;
  uint32_t next_shared = 0; // the shared id of the next split's vertex
  size_t copies = 0;        // vertices split by a removal (OpenMesh and CGAL keep them whole)
  std::vector<uint32_t> isolated_at_build; // every library keeps these

  EditCounts counts() const {
    EditCounts c;
    c.vertices = s.num_live_vertices();
    c.edges = s.num_live_edges();
    c.faces = s.num_live_triangles();
    for (VertexId v : s.vertices())
      if (!s.is_removed(v) && s.vertex_triangles(v).empty()) c.isolated++;
    // Unpaired half-edges: the summary counts the input's boundary, without the seams.
    for (HalfEdgeId h : s.half_edges())
      if (!s.is_removed(triangle_of(h)) && !s.opposite(h).valid()) c.boundary_edges++;
    c.boundary_loops = s.num_boundary_curves();
    return c;
  }
  std::vector<Tri> triangles() const {
    std::vector<Tri> out;
    for (TriangleId t : s.triangles()) {
      if (s.is_removed(t)) continue;
      auto c = s.triangle_vertices(t);
      out.push_back(canonical({shared[c[0].value()], shared[c[1].value()], shared[c[2].value()]}));
    }
    std::sort(out.begin(), out.end());
    return out;
  }
  void collect_garbage() {
    auto maps = s.garbage_collect();
    std::vector<uint32_t> moved(s.num_vertices(), NONE);
    for (size_t v = 0; v < maps.vertices.size(); ++v)
      if (maps.vertices[v] != none) moved[maps.vertices[v]] = shared[v];
    shared = std::move(moved);
  }
};

// Would removing triangle t split one of its corners into two fans (a boundary corner
// whose two edges in t are both interior)? topomesh then makes the second fan a vertex of
// its own, as its build does with such a vertex; OpenMesh and CGAL keep one non-manifold
// vertex. The random sequences leave these removals out, so that vertex ids stay shared;
// remove-all and isolate make them and map each copy to the corner it comes from.
bool pinches(const Surface &s, TriangleId t) {
  for (uint32_t k = 0; k < 3; ++k) {
    HalfEdgeId h{3 * t.value() + k};
    HalfEdgeId p{3 * t.value() + (k + 2) % 3};
    if (s.is_boundary(s.origin(h)) && !s.is_boundary(s.edge(h)) && !s.is_boundary(s.edge(p)))
      return true;
  }
  return false;
}

// The operations the libraries' rules answer differently, left out of the random
// sequences so that the others can be compared: a removal that pinches() a vertex, and
// the split of an edge whose two triangles have the same third vertex (a two-triangle
// closed component): its four triangles would hold that vertex's edge to the new vertex
// four times, which topomesh refuses and OpenMesh and CGAL do.
bool left_out(const Surface &s, OpKind kind, HalfEdgeId h) {
  if (kind == OpKind::Remove) return pinches(s, triangle_of(h));
  if (kind != OpKind::Split) return false;
  const HalfEdgeId g = s.opposite(h);
  return g.valid() && s.origin(prev(g)) == s.origin(prev(h));
}

// A random live half-edge (none when no triangle is left).
std::optional<HalfEdgeId> random_half_edge(const Surface &s, Rng &rng) {
  if (s.num_live_triangles() == 0) return std::nullopt;
  for (;;) {
    TriangleId t{rng.below(s.num_triangles())};
    if (!s.is_removed(t)) return HalfEdgeId{3 * t.value() + rng.below(3)};
  }
}

EditOp op_at(const TmSide &tm, OpKind kind, HalfEdgeId h) {
  EditOp op;
  op.kind = kind;
  op.a = tm.shared[tm.s.origin(h).value()];
  op.b = tm.shared[tm.s.target(h).value()];
  op.c = tm.shared[tm.s.origin(prev(h)).value()];
  op.fresh = tm.next_shared;
  return op;
}

} // namespace

namespace {

using Peers = std::vector<std::unique_ptr<EditPeer>>;

// The vertices the removal of a triangle with corners `corners` split off take the shared
// id of the corner they come from: the one of the same input vertex (a triangle has no two
// corners from one input vertex: such a triangle is degenerate, dropped at the build).
void note_copies(TmSide &tm, size_t before, const Ids<VertexId, 3> &corners) {
  const auto origins = tm.s.vertex_origins();
  for (size_t v = before; v < tm.s.num_vertices(); ++v) {
    uint32_t from = NONE;
    for (VertexId x : corners)
      if (origins[x.value()] == origins[v]) from = tm.shared[x.value()];
    tm.shared.push_back(from);
    tm.copies++;
  }
}

// topomesh applies op (drawn at its half-edge h) when its own check accepts it.
Outcome apply_tm(TmSide &tm, const EditOp &op, HalfEdgeId h) {
  Surface &s = tm.s;
  switch (op.kind) {
  case OpKind::Flip:
    if (!s.is_flip_ok(s.edge(h))) return Outcome::Refused;
    s.flip(s.edge(h));
    return Outcome::Done;
  case OpKind::Split: {
    // No check to ask: a refusal throws (see left_out()).
    VertexId v;
    try {
      v = s.split(s.edge(h));
    } catch (const Error &) {
      return Outcome::Refused;
    }
    const bool appended = v.value() == tm.shared.size();
    tm.shared.push_back(op.fresh);
    tm.next_shared++;
    return appended ? Outcome::Done : Outcome::Missing;
  }
  case OpKind::Collapse: {
    if (!s.is_collapse_ok(h)) return Outcome::Refused;
    const VertexId a = s.origin(h);
    return s.collapse(h) == a ? Outcome::Done : Outcome::Missing;
  }
  case OpKind::Remove: {
    const size_t before = s.num_vertices();
    const auto corners = s.triangle_vertices(triangle_of(h));
    s.remove(triangle_of(h));
    note_copies(tm, before, corners);
    return Outcome::Done;
  }
  }
  return Outcome::Missing;
}

struct Tally {
  size_t tried[4] = {};
  size_t accepted[4][3] = {}; // per kind: topomesh, OpenMesh, CGAL
  size_t left_out = 0;

  size_t total_tried() const { return tried[0] + tried[1] + tried[2] + tried[3]; }
  size_t total_accepted(int lib) const {
    return accepted[0][lib] + accepted[1][lib] + accepted[2][lib] + accepted[3][lib];
  }
};

// The comparison is itself tested (TOPOMESH_EDIT_SELFTEST, see CMakeLists.txt): with
// "skip", topomesh leaves out the first operation from the 100th on that OpenMesh accepts
// and answers as OpenMesh did (only the final meshes can tell); with "refuse", it answers
// refused to it. Either must fail the run.
Outcome selftest(Outcome openmesh, size_t step) {
  static const char *mode = std::getenv("TOPOMESH_EDIT_SELFTEST");
  static bool spent = false;
  if (mode == nullptr || spent || step < 100 || openmesh != Outcome::Done) return Outcome::Missing;
  spent = true;
  return std::strcmp(mode, "skip") == 0 ? Outcome::Done : Outcome::Refused;
}

// Applies op everywhere; false (with a message) when the libraries do not all answer alike.
bool apply_all(TmSide &tm, Peers &peers, const EditOp &op, HalfEdgeId h, size_t step,
               Tally &tally) {
  Outcome out[3] = {Outcome::Missing, peers[0]->apply(op), peers[1]->apply(op)};
  const Outcome forced = selftest(out[1], step);
  out[0] = forced != Outcome::Missing ? forced : apply_tm(tm, op, h);
  tally.tried[int(op.kind)]++;
  for (int lib = 0; lib < 3; ++lib)
    if (out[lib] == Outcome::Done) tally.accepted[int(op.kind)][lib]++;
  if (out[0] == out[1] && out[1] == out[2] && out[0] != Outcome::Missing) return true;
  std::printf("MISMATCH at operation %zu: %s of %u-%u (triangle %u %u %u): topomesh %s, "
              "OpenMesh %s, CGAL %s\n",
              step, kind_name(op.kind), op.a, op.b, op.a, op.b, op.c, outcome_name(out[0]),
              outcome_name(out[1]), outcome_name(out[2]));
  return false;
}

bool same_meshes(const TmSide &tm, const Peers &peers, const char *when);

// Garbage collection on all three, then the meshes compared.
bool collect_all(TmSide &tm, Peers &peers, const char *when) {
  tm.collect_garbage();
  for (auto &p : peers) p->collect_garbage();
  return same_meshes(tm, peers, when);
}

// The random sequence: flips 40%, splits 20%, collapses 30%, removals 10% (drawn again
// when left_out()), with a garbage collection halfway,
// after which the edits go on over the new ids.
bool run_sequence(TmSide &tm, Peers &peers, size_t n_ops, Rng &rng, Tally &tally) {
  for (size_t i = 0; i < n_ops; ++i) {
    if (i == n_ops / 2 && !collect_all(tm, peers, "after garbage collection halfway"))
      return false;
    auto h = random_half_edge(tm.s, rng);
    if (!h) break;
    const uint32_t roll = rng.below(10);
    OpKind kind = roll < 4 ? OpKind::Flip : roll < 6 ? OpKind::Split : roll < 9 ? OpKind::Collapse
                                                                             : OpKind::Remove;
    if (left_out(tm.s, kind, *h)) {
      tally.left_out++;
      --i;
      continue;
    }
    if (!apply_all(tm, peers, op_at(tm, kind, *h), *h, i, tally)) return false;
    if (tm.copies != 0) {
      std::printf("MISMATCH at operation %zu: topomesh split a vertex\n", i);
      return false;
    }
  }
  return true;
}

// Every triangle removed, in a seeded order (vertices split on the way: see pinches()).
bool run_remove_all(TmSide &tm, Peers &peers, Rng &rng, Tally &tally) {
  for (size_t i = 0; auto h = random_half_edge(tm.s, rng); ++i)
    if (!apply_all(tm, peers, op_at(tm, OpKind::Remove, *h), *h, i, tally)) return false;
  return true;
}

// The triangles around every 16th vertex (in a seeded choice) removed: those vertices are
// left isolated, and many of their neighbours split.
bool run_isolate(TmSide &tm, Peers &peers, Rng &rng, Tally &tally) {
  size_t step = 0;
  const size_t n = tm.s.num_vertices();
  for (size_t v = rng.below(16); v < n; v += 16) {
    for (;;) {
      auto star = tm.s.vertex_triangles(VertexId{uint32_t(v)});
      if (star.empty()) break;
      HalfEdgeId h{3 * star[0].value()};
      if (!apply_all(tm, peers, op_at(tm, OpKind::Remove, h), h, step++, tally)) return false;
    }
  }
  return true;
}

} // namespace

namespace {

std::vector<uint32_t> unique_sorted(std::vector<uint32_t> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

// topomesh's live vertices by shared id: {isolated ones, others}, each once.
std::pair<std::vector<uint32_t>, std::vector<uint32_t>> tm_vertex_ids(const TmSide &tm) {
  std::vector<uint32_t> isolated, used;
  for (VertexId v : tm.s.vertices()) {
    if (tm.s.is_removed(v)) continue;
    (tm.s.vertex_triangles(v).empty() ? isolated : used).push_back(tm.shared[v.value()]);
  }
  return {unique_sorted(isolated), unique_sorted(used)};
}

// The meshes after the edits (before or after garbage collection). The differences that
// are the libraries' rules, each checked exactly:
// - topomesh's copies (see pinches()) are vertices of their own: topomesh has `copies` more
//   vertices than OpenMesh, and the same shared ids;
// - CGAL's Euler::remove_face removes a vertex left without a face, which topomesh and
//   OpenMesh (delete_face(f, false)) keep: CGAL's isolated vertices are those of the input,
//   and OpenMesh's are those of topomesh whose shared id has no face there.
bool same_meshes(const TmSide &tm, const Peers &peers, const char *when) {
  const EditCounts c[3] = {tm.counts(), peers[0]->counts(), peers[1]->counts()};
  const auto [tm_isolated, tm_used] = tm_vertex_ids(tm);
  std::vector<uint32_t> om_isolated;
  std::set_difference(tm_isolated.begin(), tm_isolated.end(), tm_used.begin(), tm_used.end(),
                      std::back_inserter(om_isolated));
  const auto tris = tm.triangles();
  bool ok = true;
  auto check = [&](bool good, const char *what) {
    if (!good) std::printf("MISMATCH %s: %s\n", when, what);
    ok = ok && good;
  };
  check(c[0].edges == c[1].edges && c[1].edges == c[2].edges, "edge counts");
  check(c[0].faces == c[1].faces && c[1].faces == c[2].faces, "face counts");
  check(c[0].vertices == c[1].vertices + tm.copies, "vertex counts (topomesh, OpenMesh)");
  const long long dropped = (long long)c[1].isolated - (long long)tm.isolated_at_build.size();
  check(peers[1]->vertex_ids(true) == tm.isolated_at_build &&
            (long long)c[2].vertices + dropped == (long long)c[1].vertices,
        "vertex counts (OpenMesh, CGAL)");
  check(c[0].euler() - (long long)tm.copies == c[1].euler() &&
            c[2].euler() + dropped == c[1].euler(),
        "Euler characteristic");
  for (size_t p = 0; p < peers.size(); ++p) {
    check(peers[p]->vertex_ids(false) == tm_used, "vertices with faces");
    check(peers[p]->triangles() == tris, "triangles");
  }
  check(peers[0]->vertex_ids(true) == om_isolated, "isolated vertices (OpenMesh)");
  check(c[0].boundary_edges == c[1].boundary_edges && c[1].boundary_edges == c[2].boundary_edges,
        "boundary edges");
  // topomesh's curves (level 3, recomputed after edits) against the border loops; at a
  // split vertex, OpenMesh and CGAL may run one loop through both fans.
  check(tm.copies != 0 || (c[0].boundary_loops == c[1].boundary_loops &&
                           c[1].boundary_loops == c[2].boundary_loops),
        "boundary curves");
  if (!ok)
    for (int lib = 0; lib < 3; ++lib)
      std::printf("  %-8s V %zu E %zu F %zu isolated %zu boundary %zu edges, %zu curves\n",
                  lib == 0 ? "topomesh" : peers[lib - 1]->name(), c[lib].vertices, c[lib].edges,
                  c[lib].faces, c[lib].isolated, c[lib].boundary_edges, c[lib].boundary_loops);
  return ok;
}

// Builds topomesh from the file, then the peers from its oriented triangles.
bool build_all(const std::string &path, std::optional<TmSide> &side, Peers &peers) {
  Soup soup;
  std::string err;
  if (!read_off(path, soup, err)) {
    std::fprintf(stderr, "%s\n", err.c_str());
    return false;
  }
  Options opt;
  opt.level = 3;
  TmSide &tm = side.emplace(
      TmSide{Surface::from_triangles(soup.triangles, soup.n_vertices, soup.positions, opt), {}, 0});
  std::vector<uint32_t> tris;
  for (TriangleId t : tm.s.triangles())
    for (VertexId v : tm.s.triangle_vertices(t)) tris.push_back(v.value());
  const auto pos = tm.s.positions();
  PeerInput in;
  in.n_vertices = tm.s.num_vertices();
  in.positions = pos.data();
  in.triangles = tris.data();
  in.n_triangles = tris.size() / 3;
  for (uint32_t v = 0; v < in.n_vertices; ++v) tm.shared.push_back(v);
  tm.next_shared = uint32_t(in.n_vertices);
  peers.push_back(openmesh_editor(in));
  peers.push_back(cgal_editor(in));
  tm.isolated_at_build = peers[1]->vertex_ids(true);
  return true;
}

// The build cuts a non-manifold edge, and an orientation seam, into boundary half-edges it
// keeps flagged: topomesh refuses to collapse a triangle or split an edge there (the input
// glued them), while OpenMesh and CGAL, built from the cut triangles, see a plain boundary
// and accept. The random sequences run on meshes without such edges only; remove-all and
// isolate (removals are never refused) run on any.
bool unflagged(const Surface &s) {
  const auto r = s.report();
  if (r.non_manifold_edges == 0 && r.seam_edges == 0) return true;
  std::fprintf(stderr, "sequence: the build flagged %zu non-manifold and %zu seam edges, where "
                       "topomesh refuses collapses and splits the peers make: not compared\n",
               r.non_manifold_edges, r.seam_edges);
  return false;
}

// One line: the operations tried and left out, those each library accepted (topomesh's
// per kind), and the final counts.
void print_summary(const char *mesh, const char *mode, const Tally &t, const TmSide &tm,
                   const Peers &peers) {
  const EditCounts c = tm.counts();
  std::printf("%s %s: %zu ops (flip %zu, split %zu, collapse %zu, remove %zu; %zu left out); "
              "accepted topomesh %zu OpenMesh %zu CGAL %zu (flip %zu, split %zu, collapse %zu, "
              "remove %zu); final V %zu E %zu F %zu chi %lld, isolated %zu, boundary curves %zu, "
              "split vertices %zu (OpenMesh V %zu, CGAL V %zu)\n",
              mesh, mode, t.total_tried(), t.tried[0], t.tried[1], t.tried[2], t.tried[3],
              t.left_out, t.total_accepted(0), t.total_accepted(1), t.total_accepted(2),
              t.accepted[0][0], t.accepted[1][0], t.accepted[2][0], t.accepted[3][0], c.vertices,
              c.edges, c.faces, c.euler(), c.isolated, c.boundary_loops, tm.copies,
              peers[0]->counts().vertices,
              peers[1]->counts().vertices);
}

bool run_mode(const std::string &mode, const char *n_ops, TmSide &tm, Peers &peers, Tally &tally) {
  Rng rng{0x5eed0000ULL + tm.s.num_triangles()};
  if (mode == "sequence" && n_ops)
    return run_sequence(tm, peers, std::strtoull(n_ops, nullptr, 10), rng, tally);
  if (mode == "remove-all") return run_remove_all(tm, peers, rng, tally);
  if (mode == "isolate") return run_isolate(tm, peers, rng, tally);
  std::fprintf(stderr, "unknown mode %s\n", mode.c_str());
  return false;
}

} // namespace

int main(int argc, char **argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s MESH.off (sequence N | remove-all | isolate)\n", argv[0]);
    return 2;
  }
  const std::string mode = argv[2];
  std::optional<TmSide> side;
  Peers peers;
  try {
    if (!build_all(argv[1], side, peers)) return 2;
    TmSide &tm = *side;
    if (mode == "sequence" && !unflagged(tm.s)) return 2;
    if (!same_meshes(tm, peers, "after the build")) return 1;
    Tally tally;
    bool ok = run_mode(mode, argc > 3 ? argv[3] : nullptr, tm, peers, tally);
    ok = ok && same_meshes(tm, peers, "after the edits");
    ok = collect_all(tm, peers, "after garbage collection") && ok;
    tm.s.validate();
    const std::string path = argv[1];
    print_summary(path.substr(path.find_last_of('/') + 1).c_str(), mode.c_str(), tally, tm, peers);
    return ok ? 0 : 1;
  } catch (const std::exception &e) {
    std::printf("FAILED: %s\n", e.what());
    return 1;
  }
}
