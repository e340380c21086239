// The peers' side of the scale run (scripts/bench-scale.sh): one library, one size, one
// process, so that the peak resident set is this run's alone.
//
//   topomesh_bench_scale {openmesh|cgal} N
//
// Generates the torus `topomesh generate torus --triangles N` builds (torus_grid.hpp),
// builds OpenMesh's TriMesh or CGAL's Surface_mesh from the arrays as the head-to-head
// benchmark does (peers.hpp), frees the arrays, sweeps VV once over every vertex, and
// prints one line: the library, the triangles, the build's wall-clock seconds (and the
// thread's CPU seconds), the peak resident set (VmHWM), the connectivity bytes as
// bench.cpp counts them, the sweep's seconds (wall-clock and CPU) and its checksum. When memory runs out
// (std::bad_alloc) the line says `failed: out of memory` and the exit status is 0; a kill
// by the OOM killer is the caller's to see (signal 9).
#include "peers.hpp"
#include "torus_grid.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>

using namespace diffmesh;

namespace {

// The peak resident set of this process in bytes (VmHWM of /proc/self/status), -1 when
// it cannot be read.
long peak_rss_bytes() {
  long kb = -1;
  if (std::FILE *f = std::fopen("/proc/self/status", "r")) {
    char line[256];
    while (std::fgets(line, sizeof line, f))
      if (std::sscanf(line, "VmHWM: %ld kB", &kb) == 1) break;
    std::fclose(f);
  }
  return kb < 0 ? -1 : kb * 1024;
}

// Build, free the input, sweep: the line of a run that did not run out of memory.
void run(const std::string &lib, TorusGrid &t) {
  torus_fill(t);
  PeerInput in{size_t(t.n_vertices()), t.positions.data(), t.triangles.data(), size_t(t.n_triangles())};
  std::unique_ptr<Subject> subject = lib == "openmesh" ? openmesh_subject(in) : cgal_subject(in);
  const double w0 = now_ms(), c0 = cpu_ms();
  subject->build();
  const double build_wall = now_ms() - w0, build_cpu = cpu_ms() - c0;
  std::vector<double>().swap(t.positions);
  std::vector<uint32_t>().swap(t.triangles);
  std::vector<LibBench> rows = subject->rows();
  LibBench &row = rows.at(0);
  subject->describe(row);
  Sweep &vv = row.sweeps.at(0);
  if (vv.name != "VV" || vv.skipped()) throw std::logic_error("no VV sweep");
  uint64_t visited = 0;
  const double s0 = now_ms(), sc0 = cpu_ms();
  const uint64_t checksum = vv.fn(visited);
  const double sweep_wall = now_ms() - s0, sweep_cpu = cpu_ms() - sc0;
  std::printf("%s triangles=%llu faces=%zu build_s=%.6f build_cpu_s=%.6f peak_rss_bytes=%ld "
              "connectivity_bytes=%zu vv_sweep_s=%.6f vv_sweep_cpu_s=%.6f vv_visited=%llu vv_checksum=%llu\n",
              row.lib.c_str(), (unsigned long long)t.n_triangles(), row.faces, build_wall / 1e3, build_cpu / 1e3,
              peak_rss_bytes(), row.connectivity_bytes, sweep_wall / 1e3, sweep_cpu / 1e3,
              (unsigned long long)visited, (unsigned long long)checksum);
}

} // namespace

int main(int argc, char **argv) {
  const std::string lib = argc == 3 ? argv[1] : "";
  char *end = nullptr;
  const unsigned long long n = argc == 3 ? std::strtoull(argv[2], &end, 10) : 0;
  TorusGrid t;
  if ((lib != "openmesh" && lib != "cgal") || !end || *end || !torus_size(n, t)) {
    std::fprintf(stderr, "usage: topomesh_bench_scale {openmesh|cgal} N (1 <= N <= %llu triangles)\n",
                 (unsigned long long)((uint64_t(UINT32_MAX) - 1) / 3));
    return 2;
  }
  try {
    run(lib, t);
  } catch (const std::bad_alloc &) {
    std::printf("%s triangles=%llu failed: out of memory\n", lib == "openmesh" ? "OpenMesh" : "CGAL",
                (unsigned long long)t.n_triangles());
  }
  return 0;
}
