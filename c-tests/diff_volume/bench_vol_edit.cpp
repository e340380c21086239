// Volume editing head-to-head: topomesh's CHF (the C++ wrapper, levels 2 and 1) against
// CGAL's Triangulation_3 (built by CGAL::build_triangulation from the same tetrahedra, as in
// bench_vol.cpp), in one process, with the same seeded policy (edit_policy.hpp).
//
//   topomesh_bench_vol_edit [--ops N] [--reps R] [--seed S] [--level1] <dir/name> ...
//
// Prints, per tetgen mesh <dir/name>.node/.ele, Markdown tables:
//  - N random 1-4 splits (a live tetrahedron drawn uniformly, split at its centroid), and
//    the memory of each structure after them (container sizes and resident set); with
//    --level1 the level-1 CHF runs them too (after its first edit it edits as level 2
//    does, so by default only its first split is timed);
//  - a flip storm of N attempts (a live tetrahedron drawn uniformly, then a 2-3 flip of one
//    of its faces or a 3-2 flip of one of its edges, checked, then done when allowed);
//  - garbage_collect after removing half the tetrahedra, against CGAL's build of the same
//    remaining tetrahedra (median of R);
//  - a never-edited CHF's memory before and after checks and refused edits;
// then the targets. Times are CPU time (cpu_ms, edit_policy.hpp). Compile with -O2 (no
// -march=native).
#include "bench_vol_util.hpp"
#include "edit_policy.hpp"
#include "floor_chf.hpp"
#include "peer_cgal.hpp"
#include "tet_soup.hpp"

#include <CGAL/version.h>
#include <topomesh/topomesh.hpp>

#include <numeric>

using namespace diffvol;
using topomesh::EdgeId;
using topomesh::FaceId;
using topomesh::HalfFaceId;
using topomesh::TetrahedronId;
using topomesh::Volume;

namespace {

Volume tm_volume(const TetSoup &s, uint32_t level, uint32_t threads = 0) {
  topomesh::Options o;
  o.level = level;
  o.threads = threads;
  return Volume::from_tetrahedra(s.tets.data(), s.n_tets(), s.n_vertices, s.positions.data(), o);
}

// One structure after the split storm.
struct MemRow {
  std::string lib;
  double structure = 0, geometry = 0; // connectivity bytes; with positions (and maps)
  long retained = -1;                 // RSS growth over build + edits
  std::string note;
};

struct Row {
  std::string op, lib, path;
  EditRun run;
  uint64_t refused = 0;
};

std::string us_per(double ms, uint64_t n) {
  return n ? ratio(1000.0 * ms, double(n)) : "-";
}

// A split storm with its memory: `storm(done)` runs it, fills the row and `mem`, and calls
// done() while its structure is still alive; the resident set is read then, and its growth
// kept once the structure is gone.
template <class Storm> Row probed(MemRow &mem, Storm storm) {
  MemProbe p;
  p.begin();
  Row row = storm([&p] { p.end(); });
  mem.retained = p.retained();
  malloc_trim(0);
  return row;
}

// N splits through the wrapper; the live list is updated as CGAL's is (the split
// tetrahedron keeps its slot, the three new ones go to the back).
Row tm_splits(const TetSoup &s, uint32_t level, uint64_t n, uint64_t seed, MemRow &mem) {
  return probed(mem, [&](auto done) {
    Row row{"1-4 split", "topomesh L" + std::to_string(level), "Volume::split(TetrahedronId)", {}, 0};
    Volume vol = tm_volume(s, level);
    std::vector<uint32_t> live(vol.num_tetrahedra());
    std::iota(live.begin(), live.end(), 0u);
    live.reserve(live.size() + 3 * n);
    EditRng rng(seed);
    double t0 = cpu_ms();
    for (uint64_t i = 0; i < n; ++i) {
      size_t k = rng.below(live.size());
      uint32_t bound = uint32_t(vol.num_tetrahedra());
      try {
        vol.split(TetrahedronId{live[k]});
      } catch (const topomesh::Error &) {
        ++row.refused;
        continue;
      }
      live.insert(live.end(), {bound, bound + 1, bound + 2});
      if (i == 0) row.run.first_ms = cpu_ms() - t0;
    }
    row.run.ms = cpu_ms() - t0;
    row.run.attempts = n;
    row.run.accepted = n - row.refused;
    std::vector<uint32_t>().swap(live);
    chf_memory m = vol.memory();
    mem.lib = row.lib;
    mem.structure = double(m.topology);
    mem.geometry = mem.structure + double(m.positions + m.maps);
    mem.note = "edit state included: faces " + mib(double(m.faces)) + ", edges " + mib(double(m.edges));
    done();
    return row;
  });
}

// The same storm on CHF's arrays alone (floor_chf.hpp): the least a split costs there, and
// the least memory it needs.
Row floor_splits(const TetSoup &s, uint64_t n, uint64_t seed, MemRow &mem) {
  return probed(mem, [&](auto done) {
    Row row{"1-4 split", "CHF floor", "V and O only (floor_chf.hpp)", {}, 0};
    FloorChf floor(tm_volume(s, 1));
    row.run = floor.split_storm(n, seed);
    if (!floor.valid()) {
      std::fprintf(stderr, "bench_vol_edit: the CHF floor broke its arrays\n");
      std::exit(1);
    }
    mem = {row.lib, double(floor.structure_bytes()), double(floor.structure_bytes()), -1, "V and O only, no positions"};
    done();
    return row;
  });
}

Row cgal_splits(const TetSoup &s, uint64_t n, uint64_t seed, MemRow &mem) {
  return probed(mem, [&](auto done) {
    Row row{"1-4 split", "CGAL", "Triangulation_3::insert_in_cell", {}, 0};
    CgalStats st;
    auto c = CgalVol::build(s, st);
    row.run = c->split_storm(n, seed);
    st = c->stats();
    mem.lib = "CGAL Triangulation_3";
    mem.structure = double(st.cells * st.sizeof_cell + st.vertices * (st.sizeof_vertex - st.sizeof_point));
    mem.geometry = double(st.cells * st.sizeof_cell + st.vertices * st.sizeof_vertex);
    mem.note = std::to_string(st.cells) + " cells, " + std::to_string(st.vertices) + " vertices";
    done();
    return row;
  });
}

// A live tetrahedron for the flip storm: the live list keeps removed ids until they are
// drawn (then dropped and the draw repeated), so each draw is uniform over the live ones.
FlipPick draw_live(Volume &vol, std::vector<uint32_t> &live, EditRng &rng) {
  for (;;) {
    FlipPick pk = pick_flip(rng, live.size());
    if (!vol.is_removed(TetrahedronId{live[pk.k]})) return pk;
    live[pk.k] = live.back();
    live.pop_back();
  }
}

// One flip of the storm, of face or edge `x`: `checked`, the wrapper's `can` then `flip`;
// else the C call `raw` alone. The N new tetrahedra join `live`.
template <size_t N, class X, class New>
void storm_flip(Volume &vol, bool checked, X x, bool (Volume::*can)(X) const,
                std::array<New, N> (Volume::*flip)(X),
                topomesh_status (*raw)(chf_mesh *, uint32_t, uint32_t *), std::vector<uint32_t> &live) {
  if (checked) {
    if ((vol.*can)(x))
      for (New t : (vol.*flip)(x)) live.push_back(t.value());
  } else {
    uint32_t out[N];
    if (raw(vol.handle(), x.value(), out) == TOPOMESH_STATUS_OK) live.insert(live.end(), out, out + N);
  }
}

// `checked`: can_flip_* then flip_* through the wrapper (the check-then-act pattern); else
// one C call per attempt whose status says whether it was done (one verification).
Row tm_flips(const TetSoup &s, uint64_t attempts, uint64_t seed, bool checked) {
  Row row{"2-3/3-2 flip storm", "topomesh L2",
          checked ? "can_flip_23/32, then flip_23/32 (wrapper)" : "chf_mesh_flip_23/32, status", {}, 0};
  Volume vol = tm_volume(s, 2);
  std::vector<uint32_t> live(vol.num_tetrahedra());
  std::iota(live.begin(), live.end(), 0u);
  EditRng rng(seed);
  EditRun &r = row.run;
  double t0 = cpu_ms();
  for (uint64_t i = 0; i < attempts; ++i) {
    FlipPick pk = draw_live(vol, live, rng);
    uint32_t t = live[pk.k];
    size_t before = live.size();
    if (pk.flip23) {
      ++r.attempts23;
      FaceId f = vol.face(HalfFaceId{4 * t + uint32_t(pk.local)});
      storm_flip<3>(vol, checked, f, &Volume::can_flip_23, &Volume::flip_23, chf_mesh_flip_23,
                    live);
      r.accepted23 += live.size() != before;
    } else {
      ++r.attempts32;
      EdgeId e = vol.tetrahedron_edges(TetrahedronId{t})[size_t(pk.local)];
      storm_flip<2>(vol, checked, e, &Volume::can_flip_32, &Volume::flip_32, chf_mesh_flip_32,
                    live);
      r.accepted32 += live.size() != before;
    }
    if (i == 0) r.first_ms = cpu_ms() - t0;
  }
  r.ms = cpu_ms() - t0;
  r.attempts = attempts;
  r.accepted = r.accepted23 + r.accepted32;
  return row;
}

struct Collect {
  Row remove, gc, cgal, fresh;
  size_t remaining = 0;
};

// Removes half the tetrahedra (in decreasing x of their centroids, the ones whose removal
// would pinch a vertex or an edge refused and skipped), then garbage_collect; CGAL and a
// fresh topomesh build get the remaining tetrahedra, with every vertex.
Collect tm_collect(const TetSoup &s, int reps) {
  Collect c;
  c.remove = {"remove half", "topomesh L2", "chf_mesh_remove_tetrahedron, status", {}, 0};
  c.gc = {"compaction", "topomesh L2", "Volume::garbage_collect", {}, 0};
  c.cgal = {"compaction", "CGAL", "build_triangulation of the remaining", {}, 0};
  c.fresh = {"compaction", "topomesh L2", "a fresh build of the remaining, 1 thread", {}, 0};
  Volume vol = tm_volume(s, 2);
  size_t nt = s.n_tets(), goal = nt / 2;
  std::vector<std::pair<double, uint32_t>> order(nt);
  for (uint32_t t = 0; t < nt; ++t) {
    double x = 0;
    for (int k = 0; k < 4; ++k) x += s.positions[3 * s.tets[4 * t + k]];
    order[t] = {-x, t};
  }
  std::sort(order.begin(), order.end());
  double t0 = cpu_ms();
  for (auto &o : order) {
    if (c.remove.run.accepted == goal) break;
    ++c.remove.run.attempts;
    if (chf_mesh_remove_tetrahedron(vol.handle(), o.second) == TOPOMESH_STATUS_OK) ++c.remove.run.accepted;
    else ++c.remove.refused;
  }
  c.remove.run.ms = cpu_ms() - t0;
  TetSoup rest;
  rest.name = s.name + " (remaining half)";
  rest.n_vertices = vol.num_vertices();
  rest.positions.assign(vol.positions().begin(), vol.positions().end());
  for (uint32_t t = 0; t < vol.num_tetrahedra(); ++t)
    if (!vol.is_removed(TetrahedronId{t}))
      for (auto x : vol.tetrahedron_vertices(TetrahedronId{t})) rest.tets.push_back(x.value());
  c.remaining = rest.n_tets();
  t0 = cpu_ms();
  vol.garbage_collect();
  c.gc.run.ms = cpu_ms() - t0;
  c.gc.run.attempts = c.gc.run.accepted = 1;
  if (vol.num_tetrahedra() != c.remaining) {
    std::fprintf(stderr, "garbage_collect kept %zu tetrahedra, not %zu\n", vol.num_tetrahedra(), c.remaining);
    std::exit(1);
  }
  std::vector<double> tc, tf;
  for (int r = 0; r < reps; ++r) {
    CgalStats st;
    double c0 = cpu_ms();
    auto cg = CgalVol::build(rest, st);
    tc.push_back(cpu_ms() - c0);
    if (!cg) {
      std::fprintf(stderr, "CGAL refused the remaining half: %s\n", st.refusal.c_str());
      std::exit(1);
    }
    double f0 = cpu_ms();
    Volume fresh = tm_volume(rest, 2, 1);
    tf.push_back(cpu_ms() - f0);
  }
  c.cgal.run.ms = median(tc);
  c.fresh.run.ms = median(tf);
  c.cgal.run.attempts = c.cgal.run.accepted = c.fresh.run.attempts = c.fresh.run.accepted = 1;
  return c;
}

// A never-edited CHF: its memory (every container) and resident set before and after
// `n` checks of random operations and refused edits (boundary faces flipped).
struct Untouched {
  chf_memory before{}, after{};
  long rss_growth = -1;
  uint64_t checks = 0, refused = 0;
  bool same() const { return std::memcmp(&before, &after, sizeof before) == 0; }
};
Untouched untouched(const TetSoup &s, uint64_t n, uint64_t seed) {
  Untouched u;
  Volume vol = tm_volume(s, 2);
  u.before = vol.memory();
  malloc_trim(0);
  long rss0 = status_bytes("VmRSS");
  EditRng rng(seed);
  uint32_t nt = uint32_t(vol.num_tetrahedra()), out[3];
  for (uint64_t i = 0; i < n; ++i) {
    TetrahedronId t{uint32_t(rng.below(nt))};
    FaceId f = vol.face(HalfFaceId{4 * t.value() + uint32_t(rng.below(4))});
    u.checks += 3;
    vol.can_split(t);
    vol.can_flip_23(f);
    vol.can_flip_32(vol.tetrahedron_edges(t)[rng.below(6)]);
    if (vol.is_boundary(f)) u.refused += chf_mesh_flip_23(vol.handle(), f.value(), out) != TOPOMESH_STATUS_OK;
  }
  malloc_trim(0);
  u.rss_growth = status_bytes("VmRSS") - rss0;
  u.after = vol.memory();
  return u;
}

void print_rows(const std::vector<Row> &rows, bool flips) {
  if (flips)
    std::printf("| operation | library | call | attempts | accepted (2-3 + 3-2) | ms | us / attempt | CGAL / this |\n"
                "|---|---|---|---:|---:|---:|---:|---:|\n");
  else
    std::printf("| operation | library | call | operations | refused | ms | us / op | CGAL / this |\n"
                "|---|---|---|---:|---:|---:|---:|---:|\n");
  double cg = -1;
  for (auto &r : rows)
    if (r.lib == "CGAL") cg = r.run.ms;
  for (auto &r : rows) {
    std::string acc = flips ? std::to_string(r.run.accepted) + " (" + std::to_string(r.run.accepted23) + " + " +
                                  std::to_string(r.run.accepted32) + ")"
                            : std::to_string(r.refused);
    std::printf("| %s | %s | %s | %llu | %s | %s | %s | %s |\n", r.op.c_str(), r.lib.c_str(), r.path.c_str(),
                (unsigned long long)r.run.attempts, acc.c_str(), ms(r.run.ms).c_str(),
                us_per(r.run.ms, r.run.attempts).c_str(), ratio(cg, r.run.ms).c_str());
  }
}

void line(const std::string &what, bool ok, const std::string &got) {
  std::printf("- %s: %s (%s)\n", what.c_str(), got.c_str(), ok ? "met" : "MISSED");
}

// The first split of a never-edited CHF at `level` (it makes the edit state), ms.
double first_split_ms(const TetSoup &s, uint32_t level) {
  Volume vol = tm_volume(s, level);
  double t0 = cpu_ms();
  vol.split(TetrahedronId{0});
  return cpu_ms() - t0;
}

void bench(const std::string &base, uint64_t ops, int reps, uint64_t seed, bool level1) {
  const TetSoup s = read_bench_tets(base);
  std::printf("\n### Editing %s: %zu vertices, %zu tetrahedra\n\n", s.name.c_str(), s.n_vertices, s.n_tets());
  std::fflush(stdout);

  std::vector<MemRow> mem(level1 ? 4 : 3);
  std::vector<Row> splits;
  splits.push_back(cgal_splits(s, ops, seed, mem[0]));
  splits.push_back(tm_splits(s, 2, ops, seed, mem[1]));
  if (level1) splits.push_back(tm_splits(s, 1, ops, seed, mem[2]));
  splits.push_back(floor_splits(s, ops, seed, mem.back()));
  double l1_first = level1 ? splits[2].run.first_ms : first_split_ms(s, 1);
  std::printf("%llu random 1-4 splits at the centroid (one run; the first operation alone, which makes "
              "topomesh's edit state: CGAL %s ms, topomesh L2 %s ms, L1 %s ms). The CHF floor: the same draws "
              "on copies of V and O alone (`floor_chf.hpp`: no check, no position for the new vertex, no VH, no face or "
              "edge ids), what a library built on these arrays cannot beat:\n\n",
              (unsigned long long)ops, ms(splits[0].run.first_ms).c_str(), ms(splits[1].run.first_ms).c_str(),
              ms(l1_first).c_str());
  print_rows(splits, false);

  std::printf("\nMemory after the splits (MiB). Structure: CGAL = cells x sizeof(Cell) + vertices x "
              "(sizeof(Vertex) - sizeof(Point)) as in the build table; topomesh = chf_mesh_memory().topology "
              "(the edit state included: explicit face and edge ids, removed marks). \"+ geometry\": with points / "
              "positions and origin maps. RSS retained: growth of the resident set over build + edits:\n\n");
  std::printf("| after the splits | structure | / CGAL | + geometry | RSS retained | RSS / CGAL's | |\n"
              "|---|---:|---:|---:|---:|---:|---|\n");
  for (auto &m : mem)
    std::printf("| %s | %s | %s | %s | %s | %s | %s |\n", m.lib.c_str(), mib(m.structure).c_str(),
                ratio(m.structure, mem[0].structure).c_str(), mib(m.geometry).c_str(), mib(double(m.retained)).c_str(),
                ratio(double(m.retained), double(mem[0].retained)).c_str(), m.note.c_str());

  std::vector<Row> flips;
  {
    CgalStats st;
    auto c = CgalVol::build(s, st);
    flips.push_back({"2-3/3-2 flip storm", "CGAL", "Triangulation_3::flip (checks, then flips)", c->flip_storm(ops, seed), 0});
  }
  flips.push_back(tm_flips(s, ops, seed, true));
  flips.push_back(tm_flips(s, ops, seed, false));
  std::printf("\nFlip storm: %llu attempts, each a 2-3 flip of a random face or a 3-2 flip of a random edge "
              "of a random live tetrahedron (one run):\n\n", (unsigned long long)ops);
  print_rows(flips, true);

  Collect c = tm_collect(s, reps);
  std::printf("\nCompaction after removing half the tetrahedra (%llu removed in decreasing x of the centroid, "
              "%llu removals refused as pinches, in %s ms; %zu remain). CGAL has no removal that keeps a "
              "triangulation, so its row is build_triangulation of the remaining tetrahedra (median of %d), "
              "which is what topomesh's garbage_collect does too:\n\n",
              (unsigned long long)c.remove.run.accepted, (unsigned long long)c.remove.refused,
              ms(c.remove.run.ms).c_str(), c.remaining, reps);
  std::vector<Row> gc{c.cgal, c.gc, c.fresh};
  std::printf("| operation | library | call | ms | CGAL / this |\n|---|---|---|---:|---:|\n");
  for (auto &r : gc)
    std::printf("| %s | %s | %s | %s | %s |\n", r.op.c_str(), r.lib.c_str(), r.path.c_str(), ms(r.run.ms).c_str(),
                ratio(c.cgal.run.ms, r.run.ms).c_str());

  Untouched u = untouched(s, std::max<uint64_t>(100, ops / 100), seed);
  std::printf("\nA never-edited CHF (level 2): chf_mesh_memory before and after %llu checks (can_split, "
              "can_flip_23, can_flip_32) and %llu refused flips: %s (topology %s MiB); resident set "
              "growth %s MiB.\n",
              (unsigned long long)u.checks, (unsigned long long)u.refused, u.same() ? "identical" : "DIFFERENT",
              mib(double(u.after.topology)).c_str(), mib(double(u.rss_growth)).c_str());

  std::printf("\nTargets on %s:\n\n", s.name.c_str());
  line("1-4 splits >= 3x faster than CGAL (L2)", splits[0].run.ms / splits[1].run.ms >= 3,
       ratio(splits[0].run.ms, splits[1].run.ms) + "x; the CHF floor " + ratio(splits[0].run.ms, splits.back().run.ms) +
           "x");
  line("flip storm >= 3x faster than CGAL (L2, check then flip; one call)", flips[0].run.ms / flips[1].run.ms >= 3,
       ratio(flips[0].run.ms, flips[1].run.ms) + "x; " + ratio(flips[0].run.ms, flips[2].run.ms) + "x");
  line("garbage_collect >= 3x faster than CGAL's rebuild", c.cgal.run.ms / c.gc.run.ms >= 3,
       ratio(c.cgal.run.ms, c.gc.run.ms) + "x");
  line("memory while editing <= 0.5x CGAL's (L2, structure; RSS)", mem[1].structure <= 0.5 * mem[0].structure,
       ratio(mem[1].structure, mem[0].structure) + "; " + ratio(double(mem[1].retained), double(mem[0].retained)) +
           "; the CHF floor " + ratio(mem.back().structure, mem[0].structure));
  line("a never-edited CHF keeps its memory", u.same(), u.same() ? "identical" : "different");
  std::fflush(stdout);
}

} // namespace

int main(int argc, char **argv) {
  uint64_t ops = 1000000, seed = 42;
  int reps = 3;
  bool level1 = false;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--ops") == 0 && i + 1 < argc) ops = std::strtoull(argv[++i], nullptr, 10);
    else if (std::strcmp(argv[i], "--reps") == 0 && i + 1 < argc) reps = std::max(1, std::atoi(argv[++i]));
    else if (std::strcmp(argv[i], "--seed") == 0 && i + 1 < argc) seed = std::strtoull(argv[++i], nullptr, 10);
    else if (std::strcmp(argv[i], "--level1") == 0) level1 = true;
    else meshes.push_back(argv[i]);
  }
  if (meshes.empty() || ops == 0) {
    std::fprintf(stderr, "usage: topomesh_bench_vol_edit [--ops N] [--reps R] [--seed S] [--level1] <dir/name> ...\n");
    return 2;
  }
  std::printf("topomesh %s; CGAL %s\n", topomesh_version(), CGAL_VERSION_STR);
  try {
    for (auto &m : meshes) bench(m, ops, reps, seed, level1);
  } catch (const topomesh::Error &e) {
    std::fprintf(stderr, "topomesh: %s\n", e.what());
    return 1;
  }
  return 0;
}
