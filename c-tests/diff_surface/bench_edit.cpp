// Editing benchmark: topomesh (the C++ wrapper, levels 2 and 3) against OpenMesh's TriMesh
// and CGAL's Surface_mesh, in one process, from the same arrays, with the same policy
// (edit_policy.hpp) for each library:
//
//   topomesh_bench_edit [--reps N] [--md FILE] [--flips N] MESH.off...
//
// Per mesh: a flip storm (N random edge ids, flipped when the library's check allows), an
// edge-split refinement (longest-edge bisection of every edge longer than 1.5 x the mean
// edge length, at its midpoint, until none is left), the shortest-edge simplification of `topomesh simplify` to
// 10 % of the triangles, and the garbage collection after removing every other triangle id
// (only the collection timed). Each operation runs on a fresh build (the build untimed);
// CPU time of the benchmark thread, the median of N repetitions. Memory: each library's
// structure size (positions excluded) after the build and after the edits, and the
// resident-set growth over the build and over the build and the flip storm.
#include "bench_edit_peers.hpp"
#include "floor_che.hpp"
#include "off_reader.hpp"

#include <topomesh/topomesh.hpp>

#include <memory>

using namespace diffmesh;

namespace {

// The C++ wrapper, what an editing user holds.
class TmEdit {
public:
  TmEdit(const Soup &s, uint32_t level) : s_(build(s, level)) {}
  uint32_t n_edges() const { return uint32_t(s_.num_edges()); }
  uint32_t n_triangles() const { return uint32_t(s_.num_triangles()); }
  size_t live_triangles() const { return s_.num_live_triangles(); }
  bool edge_removed(uint32_t e) const { return s_.is_removed(topomesh::EdgeId{e}); }
  uint32_t edge_half_edge(uint32_t e) const { return s_.half_edge(topomesh::EdgeId{e}).value(); }
  uint32_t edge_of(uint32_t h) const { return s_.edge(topomesh::HalfEdgeId{h}).value(); }
  bool half_edge_removed(uint32_t h) const { return s_.is_removed(topomesh::TriangleId{h / 3}); }
  uint32_t origin(uint32_t h) const { return s_.origin(topomesh::HalfEdgeId{h}).value(); }
  uint32_t target(uint32_t h) const { return s_.target(topomesh::HalfEdgeId{h}).value(); }
  void apexes(uint32_t h, uint32_t out[2]) const {
    const topomesh::HalfEdgeId hh{h}, g = s_.opposite(hh);
    out[0] = s_.origin(topomesh::prev(hh)).value();
    out[1] = g.valid() ? s_.origin(topomesh::prev(g)).value() : ~0u;
  }
  P3 point(uint32_t v) const {
    const topomesh::Vec3 p = s_.position(topomesh::VertexId{v});
    return {p.x, p.y, p.z};
  }
  void set_point(uint32_t v, const P3 &p) { s_.set_position(topomesh::VertexId{v}, {p[0], p[1], p[2]}); }
  bool flip_ok(uint32_t e) { return s_.is_flip_ok(topomesh::EdgeId{e}); }
  void flip(uint32_t e) { s_.flip(topomesh::EdgeId{e}); }
  void split(uint32_t e, const P3 &p) {
    const topomesh::Vec3 at{p[0], p[1], p[2]};
    s_.split(topomesh::EdgeId{e}, &at);
  }
  bool collapse_ok(uint32_t h) { return s_.is_collapse_ok(topomesh::HalfEdgeId{h}); }
  uint32_t collapse(uint32_t h) { return s_.collapse(topomesh::HalfEdgeId{h}).value(); }
  template <class F> void each_triangle_around(uint32_t v, F f) const {
    for (topomesh::TriangleId t : s_.vertex_triangles(topomesh::VertexId{v})) {
      const auto c = s_.triangle_vertices(t);
      f(c[0].value(), c[1].value(), c[2].value());
    }
  }
  template <class F> void each_out_half_edge(uint32_t v, F f) const {
    for (const topomesh::StarStep &step : s_.star(topomesh::VertexId{v})) f(step.half_edge.value());
  }
  void remove_triangle(uint32_t t) { s_.remove(topomesh::TriangleId{t}); }
  void garbage_collect() { s_.garbage_collect(); }
  size_t structure_bytes() const { return size_t(s_.memory().topology); }
  FloorChe floor() const { return FloorChe(s_); }

private:
  topomesh::Surface s_;
  static topomesh::Surface build(const Soup &s, uint32_t level) {
    topomesh::Options o;
    o.level = level;
    o.threads = 1; // as the peers
    return topomesh::Surface::from_triangles(s.triangles.data(), s.n_triangles(), s.n_vertices, s.positions.data(),
                                             o);
  }
};

std::string fmt_mb(double bytes) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f", bytes / 1048576.0);
  return b;
}

// The peers' rows, then topomesh's, in the order of every table.
std::vector<const EditRow *> all_rows(const std::vector<EditRow> &tm, const EditRow &om, const EditRow &cg) {
  std::vector<const EditRow *> all = {&om, &cg};
  for (const EditRow &r : tm) all.push_back(&r);
  return all;
}

// topomesh's time over the faster peer's (below 1: topomesh faster; the target is 0.50).
std::string vs_peer(double tm, const EditRow &om, const EditRow &cg, EditResult EditRow::*op) {
  double best = std::min((om.*op).ms, (cg.*op).ms);
  return fmt_ratio2(tm, best);
}

// The simplification split in two: the policy's queue (each library's own sequence of
// queue operations replayed alone), which no library can save, and the rest (the library's
// calls, and the policy's reads of positions through them).
void report_queue_share(Out &out, const std::vector<EditRow> &tm, const EditRow &om, const EditRow &cg) {
  out("\nThe simplification's queue alone: each library's sequence of queue operations (recorded in one more "
      "run) replayed on an empty queue, median of the same repetitions; the rest is the library's calls and "
      "the policy's work through them. Ratio of the rest: topomesh ÷ the faster peer's rest.\n\n");
  out("| library | simplification | queue operations | queue alone | rest | rest ÷ faster peer's |\n"
      "|---|---:|---:|---:|---:|---:|\n");
  auto rest = [](const EditRow &r) { return r.simplify.ms - r.simplify_queue_ms; };
  const double best = std::min(rest(om), rest(cg));
  const std::vector<const EditRow *> all = all_rows(tm, om, cg);
  for (const EditRow *r : all)
    out("| %s | %s | %zu | %s | %s | %s |\n", r->lib.c_str(), fmt_ms(r->simplify.ms).c_str(),
        r->simplify_queue_ops, fmt_ms(r->simplify_queue_ms).c_str(), fmt_ms(rest(*r)).c_str(),
        r == &om || r == &cg ? "" : fmt_ratio2(rest(*r), best).c_str());
}

void report_times(Out &out, const std::vector<EditRow> &tm, const EditRow &om, const EditRow &cg) {
  struct Op {
    const char *name;
    EditResult EditRow::*op;
  };
  const Op ops[] = {{"flip storm", &EditRow::flips},
                    {"edge-split refinement", &EditRow::splits},
                    {"shortest-edge simplification to 10 %", &EditRow::simplify},
                    {"garbage_collect after removing half", &EditRow::gc}};
  out("\n| operation | OpenMesh | CGAL |");
  for (const EditRow &r : tm) out(" %s |", r.lib.c_str());
  for (const EditRow &r : tm) out(" %s ÷ faster peer |", r.lib.c_str());
  out("\n|---|---:|---:|");
  for (size_t i = 0; i < 2 * tm.size(); ++i) out("---:|");
  out("\n");
  for (const Op &o : ops) {
    out("| %s | %s | %s |", o.name, fmt_ms((om.*o.op).ms).c_str(), fmt_ms((cg.*o.op).ms).c_str());
    for (const EditRow &r : tm) out(" %s |", fmt_ms((r.*o.op).ms).c_str());
    for (const EditRow &r : tm) out(" %s |", vs_peer((r.*o.op).ms, om, cg, o.op).c_str());
    out("\n");
  }
  report_queue_share(out, tm, om, cg);
  out("\nWhat each did (attempts: flips tried, edges looked at over the split passes, collapse candidates "
      "checked, triangles removed; accepted: flips, splits, collapses, triangles removed), and the live "
      "triangles after:\n\n");
  out("| operation | library | attempts | accepted | triangles after |\n|---|---|---:|---:|---:|\n");
  const std::vector<const EditRow *> all = all_rows(tm, om, cg);
  for (const Op &o : ops)
    for (const EditRow *r : all) {
      const EditResult &x = r->*o.op;
      out("| %s | %s | %llu | %llu | %zu |\n", o.name, r->lib.c_str(), (unsigned long long)x.attempts,
          (unsigned long long)x.accepted, x.triangles_after);
    }
}

void report_memory(Out &out, const std::vector<EditRow> &tm, const EditRow &om, const EditRow &cg,
                   const std::vector<size_t> &never_edited) {
  out("\nMemory, MiB: the structure as each library counts it (positions excluded: topomesh "
      "`che_mesh_memory().topology`, which includes the edit state once edited; OpenMesh its connectivity and "
      "the four status properties deletion needs; CGAL its connectivity and removed bits), right after the "
      "build, after the flip storm (same size of mesh) and after the split refinement (a larger mesh); the "
      "resident-set growth over the build, and over the build and the flip storm (positions and allocator "
      "slack included). Ratio: over OpenMesh's (the target is 0.60).\n\n");
  out("| library | built | after flips | ÷ OpenMesh | after splits | ÷ OpenMesh | RSS: build | RSS: build + flips | ÷ "
      "OpenMesh |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  const std::vector<const EditRow *> all = all_rows(tm, om, cg);
  for (const EditRow *r : all)
    out("| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r->lib.c_str(), fmt_mb(double(r->bytes_built)).c_str(),
        fmt_mb(double(r->flips.bytes_after)).c_str(),
        fmt_ratio2(double(r->flips.bytes_after), double(om.flips.bytes_after)).c_str(),
        fmt_mb(double(r->splits.bytes_after)).c_str(),
        fmt_ratio2(double(r->splits.bytes_after), double(om.splits.bytes_after)).c_str(),
        fmt_mb(double(r->rss_build)).c_str(), fmt_mb(double(r->rss_edited)).c_str(),
        fmt_ratio2(double(r->rss_edited), double(om.rss_edited)).c_str());
  out("\nA never-edited CHE: `che_mesh_memory().topology` ");
  for (size_t i = 0; i < tm.size(); ++i)
    out("%s%s %zu bytes", i ? ", " : "", tm[i].lib.c_str(), never_edited[i]);
  out(" (the edit state exists only from the first edit).\n");
}

// The flip storm on CHE's arrays alone (floor_che.hpp), the same draws: the least any
// library built on CHE can take, against the faster peer and the target.
EditResult floor_flips(const Soup &s, const EditParams &p, int reps) {
  std::vector<double> ms;
  EditResult r;
  for (int i = 0; i < reps; ++i) {
    FloorChe f = TmEdit(s, 2).floor();
    r = flip_storm(f, p);
    ms.push_back(r.ms);
    if (!f.valid()) {
      std::fprintf(stderr, "bench_edit: the CHE floor broke its arrays\n");
      std::exit(1);
    }
  }
  r.ms = median(ms);
  return r;
}

void report_floor(Out &out, const EditResult &floor, const EditRow &tm, const EditRow &om, const EditRow &cg) {
  // The same draws and the same rule: the same flips, or the floor is not doing the work.
  if (floor.accepted != tm.flips.accepted) {
    std::fprintf(stderr, "bench_edit: the CHE floor flipped %llu edges, %s %llu\n", (unsigned long long)floor.accepted,
                 tm.lib.c_str(), (unsigned long long)tm.flips.accepted);
    std::exit(1);
  }
  const EditResult &fast = om.flips.ms < cg.flips.ms ? om.flips : cg.flips;
  out("\nThe floor of the flip storm: the same draws on copies of CHE's V, O and edge ids alone "
      "(`floor_che.hpp`: the check walks round one end, the flip rewrites two corners, re-points two "
      "neighbours and moves two edge ids, as topomesh's does; no VH, no marks, no details): what a library built on these arrays "
      "cannot beat. The target over it: below 1, the target cannot be met on them.\n\n");
  out("| | ms | accepted | ÷ faster peer | target ÷ this |\n|---|---:|---:|---:|---:|\n");
  out("| CHE floor | %s | %llu | %s | %s |\n", fmt_ms(floor.ms).c_str(), (unsigned long long)floor.accepted,
      fmt_ratio2(floor.ms, fast.ms).c_str(), fmt_ratio2(0.5 * fast.ms, floor.ms).c_str());
}

} // namespace

int main(int argc, char **argv) {
  EditParams params;
  // --flips N is ours; the rest goes to the common parser.
  std::vector<char *> rest = {argv[0]};
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--flips" && i + 1 < argc) params.flips = size_t(std::atoll(argv[++i]));
    else rest.push_back(argv[i]);
  }
  const char *usage = "topomesh_bench_edit [--reps N] [--md FILE] [--flips N] MESH.off...";
  return bench_main(int(rest.size()), rest.data(), "bench_edit", usage, [&params](const Soup &s, int reps, Out &out) {
    const PeerInput in{s.n_vertices, s.positions.data(), s.triangles.data(), s.n_triangles()};
    double mean = 0;
    std::vector<EditRow> tm;
    std::vector<size_t> never_edited;
    for (uint32_t level : {2u, 3u}) {
      auto make = [&s, level] { return std::make_unique<TmEdit>(s, level); };
      if (level == 2) mean = mean_edge_length(*make());
      never_edited.push_back(make()->structure_bytes());
      tm.push_back(run_edits("topomesh L" + std::to_string(level), make, params, params.split_factor * mean,
                             reps));
    }
    const double threshold = params.split_factor * mean;
    const EditRow om = openmesh_edits(in, params, threshold, reps);
    const EditRow cg = cgal_edits(in, params, threshold, reps);
    out("\n### Editing: %s\n\n%zu vertices, %zu triangles. CPU milliseconds of the benchmark thread, median of %d "
        "run(s), each on a fresh build; %zu flip attempts (seed %llu); splits of the edges longer than %.2f x the "
        "mean edge length (%.6g); simplification to %.0f %% of the triangles. Ratio: topomesh ÷ the faster peer "
        "(the target is 0.50×).\n",
        s.name.c_str(), s.n_vertices, s.n_triangles(), reps, params.flips, (unsigned long long)params.seed,
        params.split_factor, mean, params.simplify_ratio * 100);
    report_times(out, tm, om, cg);
    report_floor(out, floor_flips(s, params, reps), tm[0], om, cg);
    report_memory(out, tm, om, cg, never_edited);
  });
}
