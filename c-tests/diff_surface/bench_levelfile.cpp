// Level-file benchmark: opening a saved CHE against building it from the arrays, and
// against OpenMesh reading its own binary format (.om), in one process, interleaved
// repetitions, medians.
//
//   topomesh_bench_levelfile [--reps N] [--md FILE] MESH.off...
//
// Per mesh, each round runs every step once, starting at a different one each round: the
// level-2 build from the arrays through the C API (every thread, as
// che_build_options_default; and one thread), che_mesh_save to a temporary .che,
// che_mesh_open mapped and trusted (alone, and right after an untimed one: caches warm),
// mapped and verified, loaded and verified, each with the first VV query (vertex 0's
// one-ring), and OpenMesh's read_mesh of a binary .om written once, with the same first
// query. Then rounds of a VV sweep over every vertex through the C++ wrapper
// (topomesh::Surface::vertex_vertices) on the built mesh, on a mapped trusted mesh opened
// just before (its pages touched for the first time) and on one mapped mesh kept open (its
// pages already touched). Wall-clock time, since the build and the verified opens run on
// every thread; the process's CPU time beside it. The files are in the page cache (each was
// just written). The targets compare with the faster of the two builds. Markdown to stdout
// and, with --md, to FILE.
#include "om_mesh.hpp"
#include "off_reader.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <topomesh/topomesh.h>
#include <topomesh/topomesh.hpp>

#include <sys/stat.h>

#include <cstdlib>
#include <functional>
#include <memory>

using namespace diffmesh;

namespace {

// The steps, by name.
const char *const kBuildAll = "build level 2 from the arrays (C API, every thread)";
const char *const kBuildOne = "build level 2 from the arrays (C API, one thread)";
const char *const kSave = "che_mesh_save (.che: written, synced, renamed)";
const char *const kTrusted = "open mapped, trusted + first VV";
const char *const kTrustedAgain = "open mapped, trusted + first VV, right after an untimed one";
const char *const kMappedVerified = "open mapped, verified + first VV";
const char *const kLoadedVerified = "open loaded, verified + first VV";
const char *const kOpenMesh = "OpenMesh read_mesh of the .om + first VV";
const char *const kSweepBuilt = "VV sweep, built in memory";
const char *const kSweepFirst = "VV sweep, mapped trusted, just opened (first touch)";
const char *const kSweepAgain = "VV sweep, mapped trusted, pages touched before";

// A timed step: `before` and `after` untimed (opening what it sweeps, freeing what it
// made), `run` timed; its times in ms, one per round.
struct Step {
  using Fn = std::function<void()>;
  Step(std::string n, Fn b, Fn r, Fn a)
      : name(std::move(n)), before(std::move(b)), run(std::move(r)), after(std::move(a)) {}
  std::string name;
  Fn before, run, after;
  std::vector<double> wall, cpu;
  double ms() const { return median(wall); }
};

// The median wall-clock time of the step named `name` in `steps`.
double step_ms(const std::vector<Step> &steps, const char *name) {
  for (const Step &s : steps)
    if (s.name == name) return s.ms();
  return -1;
}

// `reps` rounds of every step, each round starting at a different one.
void run_rounds(std::vector<Step> &steps, int reps) {
  for (int r = 0; r < reps; ++r)
    for (size_t i = 0; i < steps.size(); ++i) {
      Step &s = steps[(i + size_t(r)) % steps.size()];
      if (s.before) s.before();
      const double w0 = now_ms(), c0 = process_cpu_ms();
      s.run();
      s.cpu.push_back(process_cpu_ms() - c0);
      s.wall.push_back(now_ms() - w0);
      if (s.after) s.after();
    }
}

[[noreturn]] void fail(const char *what, topomesh_status s) {
  char detail[512] = "";
  size_t len = 0;
  topomesh_last_error(detail, sizeof detail, &len);
  std::fprintf(stderr, "bench_levelfile: %s: %s (%s)\n", what, topomesh_status_str(s), detail);
  std::exit(1);
}

che_mesh *build(const Soup &s, uint32_t threads) {
  che_build_options o = che_build_options_default();
  o.level = 2;
  o.threads = threads;
  che_mesh *m = nullptr;
  topomesh_status st =
      che_mesh_from_triangles_ex(s.triangles.data(), s.n_triangles(), s.n_vertices, s.positions.data(), &o, &m);
  if (st != TOPOMESH_STATUS_OK) fail("build", st);
  return m;
}

che_mesh *open_che(const std::string &path, uint32_t flags) {
  che_mesh *m = nullptr;
  topomesh_status st = che_mesh_open(path.c_str(), flags, &m);
  if (st != TOPOMESH_STATUS_OK) fail("che_mesh_open", st);
  return m;
}

// The first query after an open: vertex 0's one-ring, summed.
uint64_t first_vv(const che_mesh *m) {
  uint32_t buf[256];
  size_t len = 0;
  topomesh_status st = che_vertex_vertices(m, 0, buf, 256, &len);
  if (st != TOPOMESH_STATUS_OK) fail("che_vertex_vertices", st);
  uint64_t sum = 0;
  for (size_t i = 0; i < len; ++i) sum += buf[i];
  return sum;
}
uint64_t first_vv(const om::Mesh &m) {
  const OpenMesh::VertexHandle v0(0);
  uint64_t sum = 0;
  if (m.n_vertices() == 0 || !m.halfedge_handle(v0).is_valid()) return 0; // no circulator there
  for (auto it = m.cvv_iter(v0); it.is_valid(); ++it) sum += uint64_t(it->idx());
  return sum;
}

// Every vertex's one-ring through the C++ wrapper (inline over the arrays at level 2, as
// bench.cpp's "C++ wrapper" row), folded into a checksum. Borrows `m`.
uint64_t vv_sweep(che_mesh *m) {
  topomesh::Surface s(m);
  struct Release {
    topomesh::Surface &s;
    ~Release() { s.release(); }
  } release{s};
  const topomesh::Surface &cs = s;
  uint64_t sum = 0;
  const uint32_t nv = uint32_t(cs.num_vertices());
  for (uint32_t v = 0; v < nv; ++v)
    for (topomesh::VertexId w : cs.vertex_vertices(topomesh::VertexId{v})) sum += uint64_t(w.value()) * (v + 1);
  return sum;
}

size_t file_bytes(const std::string &path) {
  struct stat st;
  return stat(path.c_str(), &st) == 0 ? size_t(st.st_size) : 0;
}

// What the steps share: the files, the meshes kept across rounds, what a step made (freed
// untimed after it) and the answers, kept from the optimiser.
struct Session {
  const Soup &soup;
  std::string dir, che_path, om_path;
  che_mesh *kept = nullptr;   // built once: saved, and swept in memory
  che_mesh *mapped = nullptr; // opened once for the sweeps of a mesh already paged in
  che_mesh *made = nullptr;
  std::unique_ptr<om::Mesh> om_made;
  uint64_t sink = 0;
  std::vector<uint64_t> sweep_sums;
  size_t che_bytes = 0, om_bytes = 0;

  explicit Session(const Soup &s) : soup(s) {
    char tmpl[4096];
    const char *tmp = std::getenv("TMPDIR");
    std::snprintf(tmpl, sizeof tmpl, "%s/topomesh-levelfile.XXXXXX", tmp && *tmp ? tmp : "/tmp");
    if (!mkdtemp(tmpl)) {
      std::perror(tmpl);
      std::exit(1);
    }
    dir = tmpl;
    che_path = dir + "/" + s.name + ".che";
    om_path = dir + "/" + s.name + ".om";
  }
  ~Session() {
    free_made();
    che_mesh_free(kept);
    che_mesh_free(mapped);
    std::remove(che_path.c_str());
    std::remove(om_path.c_str());
    rmdir(dir.c_str());
  }
  void free_made() {
    che_mesh_free(made);
    made = nullptr;
    om_made.reset();
  }
};

// The .om file OpenMesh reads: the same arrays built into its TriMesh, written binary once.
void write_om(Session &x) {
  const Soup &s = x.soup;
  PeerInput in{s.n_vertices, s.positions.data(), s.triangles.data(), s.n_triangles()};
  om::Mesh m;
  PeerBuild b;
  om::build(in, m, b, nullptr);
  ::omlog().disable(); // "#bytes written"
  if (!OpenMesh::IO::write_mesh(m, x.om_path, OpenMesh::IO::Options::Binary)) {
    std::fprintf(stderr, "bench_levelfile: OpenMesh cannot write %s\n", x.om_path.c_str());
    std::exit(1);
  }
  x.om_bytes = file_bytes(x.om_path);
}

std::vector<Step> open_steps(Session &x) {
  auto after = [&x] { x.free_made(); };
  auto built = [&x](uint32_t threads) { return [&x, threads] { x.made = build(x.soup, threads); }; };
  auto opened = [&x](uint32_t flags) {
    return [&x, flags] {
      x.made = open_che(x.che_path, flags);
      x.sink += first_vv(x.made);
    };
  };
  auto save = [&x] {
    topomesh_status st = che_mesh_save(x.kept, x.che_path.c_str());
    if (st != TOPOMESH_STATUS_OK) fail("che_mesh_save", st);
  };
  auto om_read = [&x] {
    x.om_made = std::make_unique<om::Mesh>();
    if (!OpenMesh::IO::read_mesh(*x.om_made, x.om_path)) {
      std::fprintf(stderr, "bench_levelfile: OpenMesh cannot read %s\n", x.om_path.c_str());
      std::exit(1);
    }
    x.sink += first_vv(*x.om_made);
  };
  const uint32_t mapped = TOPOMESH_OPEN_MAPPED, trusted = TOPOMESH_OPEN_TRUSTED;
  auto warm_up = [opened, after, mapped, trusted] {
    opened(mapped | trusted)();
    after();
  };
  return {{kBuildAll, {}, built(0), after},          {kBuildOne, {}, built(1), after},
          {kSave, {}, save, {}},                      {kTrusted, {}, opened(mapped | trusted), after},
          {kTrustedAgain, warm_up, opened(mapped | trusted), after},
          {kMappedVerified, {}, opened(mapped), after}, {kLoadedVerified, {}, opened(0), after},
          {kOpenMesh, {}, om_read, after}};
}

std::vector<Step> sweep_steps(Session &x) {
  auto swept = [&x](che_mesh *const &m) {
    return [&x, &m] {
      x.sweep_sums.push_back(vv_sweep(m));
      x.sink += x.sweep_sums.back();
    };
  };
  auto open_mapped = [&x] { x.made = open_che(x.che_path, TOPOMESH_OPEN_MAPPED | TOPOMESH_OPEN_TRUSTED); };
  return {{kSweepBuilt, {}, swept(x.kept), {}},
          {kSweepFirst, open_mapped, swept(x.made), [&x] { x.free_made(); }},
          {kSweepAgain, {}, swept(x.mapped), {}}};
}

std::string fmt_time(double ms) {
  char b[32];
  if (ms < 0) return "–";
  if (ms < 0.01) std::snprintf(b, sizeof b, "%.2f µs", ms * 1e3);
  else if (ms < 1) std::snprintf(b, sizeof b, "%.1f µs", ms * 1e3);
  else return fmt_ms(ms) + " ms";
  return b;
}

std::string fmt_times(double num, double den) {
  char b[32];
  if (num <= 0 || den <= 0) return "–";
  const double r = num / den;
  std::snprintf(b, sizeof b, r >= 100 ? "%.0f×" : "%.1f×", r);
  return b;
}

void report_table(Out &out, const Session &x, const std::vector<Step> &steps, int reps) {
  const Soup &s = x.soup;
  out("\n### %s\n\n", s.name.c_str());
  out("%zu vertices, %zu triangles; the .che file (level 2) %.1f MiB, the .om file %.1f MiB. Medians of %d rounds: "
      "wall-clock time, and the CPU time of the process (every thread) beside it.\n\n",
      s.n_vertices, s.n_triangles(), double(x.che_bytes) / 1048576.0, double(x.om_bytes) / 1048576.0, reps);
  out("| step | wall | CPU |\n|---|---:|---:|\n");
  for (const Step &st : steps)
    out("| %s | %s | %s |\n", st.name.c_str(), fmt_time(st.ms()).c_str(), fmt_time(median(st.cpu)).c_str());
}

// The targets: `faster` is how many times less time the level file takes than `slower`.
struct Target {
  const char *what;
  double slower, faster, at_least;
};

// The targets against the faster of the two builds; the sweeps' ratios at most 1.20.
void report_targets(Out &out, const std::vector<Step> &st, bool sums_agree) {
  auto ms = [&st](const char *name) { return step_ms(st, name); };
  const double build = std::min(ms(kBuildAll), ms(kBuildOne)), trusted = ms(kTrusted);
  const Target targets[] = {
      {"mapped trusted open + first VV against the build", build, trusted, 1000},
      {"against OpenMesh reading its .om", ms(kOpenMesh), trusted, 100},
      {"mapped verified open + first VV against the build", build, ms(kMappedVerified), 5},
      {"loaded verified open + first VV against the build", build, ms(kLoadedVerified), 5},
  };
  out("\nTargets (times faster; the build: the faster of the two):");
  for (const Target &t : targets)
    out(" %s %s (target ≥ %.0f×: %s);", t.what, fmt_times(t.slower, t.faster).c_str(), t.at_least,
        t.faster > 0 && t.slower >= t.at_least * t.faster ? "met" : "missed");
  out(" right after an untimed open, the mapped trusted open + first VV is %s faster than the build, %s than "
      "OpenMesh;",
      fmt_times(build, ms(kTrustedAgain)).c_str(), fmt_times(ms(kOpenMesh), ms(kTrustedAgain)).c_str());
  const double in_memory = ms(kSweepBuilt), first = ms(kSweepFirst), again = ms(kSweepAgain);
  out(" the mapped VV sweep over the in-memory one: just opened %s (target ≤ 1.20×: %s), pages touched before %s "
      "(target ≤ 1.20×: %s).",
      fmt_ratio2(first, in_memory).c_str(), first <= 1.2 * in_memory ? "met" : "missed",
      fmt_ratio2(again, in_memory).c_str(), again <= 1.2 * in_memory ? "met" : "missed");
  out(" VV sweep checksums: %s.\n", sums_agree ? "all agree" : "DIFFER");
}

// One mesh: false when the sweeps' checksums differ (the report says so).
bool bench_one(const Soup &s, int reps, Out &out) {
  Session x(s);
  x.kept = build(s, 0);
  write_om(x);
  std::vector<Step> opens = open_steps(x);
  run_rounds(opens, reps);
  x.che_bytes = file_bytes(x.che_path);
  x.mapped = open_che(x.che_path, TOPOMESH_OPEN_MAPPED | TOPOMESH_OPEN_TRUSTED);
  x.sink += vv_sweep(x.mapped); // touches its pages, untimed
  std::vector<Step> sweeps = sweep_steps(x);
  run_rounds(sweeps, reps);
  bool agree = true;
  for (uint64_t sum : x.sweep_sums) agree = agree && sum == x.sweep_sums.front();
  std::vector<Step> all = std::move(opens);
  for (Step &st : sweeps) all.push_back(std::move(st));
  report_table(out, x, all, reps);
  report_targets(out, all, agree);
  std::fprintf(stderr, "bench_levelfile: %s done (sink %llu)\n", s.name.c_str(), (unsigned long long)x.sink);
  return agree;
}

void bench_mesh(const Soup &s, int reps, Out &out) {
  if (!bench_one(s, reps, out)) std::exit(1);
}

} // namespace

int main(int argc, char **argv) {
  const char *usage = "topomesh_bench_levelfile [--reps N] [--md FILE] MESH.off...";
  return bench_main(argc, argv, "bench_levelfile", usage, bench_mesh);
}
