// Timing, memory and result records for the head-to-head benchmark.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <malloc.h>
#include <string>
#include <unistd.h>
#include <vector>

namespace diffmesh {

inline double now_ms() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

inline double median(std::vector<double> v) {
  if (v.empty()) return -1;
  std::sort(v.begin(), v.end());
  size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Resident set size in bytes, from /proc/self/statm, after giving freed memory back.
inline long rss_bytes() {
  malloc_trim(0);
  long pages_total = 0, pages_res = 0;
  if (std::FILE *f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%ld %ld", &pages_total, &pages_res) != 2) pages_res = 0;
    std::fclose(f);
  }
  return pages_res * sysconf(_SC_PAGESIZE);
}

// One timed full sweep of a relation over the mesh.
struct Sweep {
  std::string name;            // VV, VF, FF, EF, curves
  std::vector<double> ms;      // one per repetition
  uint64_t checksum = 0;       // the same for every library on a fully accepted mesh
  uint64_t count = 0;          // entries visited
  std::string note;            // why skipped, when skipped
  bool skipped() const { return ms.empty(); }
};

// One library (or one topomesh level and access path) on one mesh.
struct LibBench {
  std::string lib;                  // "OpenMesh", "CGAL", "topomesh L2", ...
  std::string path;                 // access path for topomesh: "C API", "C++", "zero-copy"
  std::vector<double> build_ms;     // empty for rows that share a build
  size_t connectivity_bytes = 0;    // from container sizes
  long rss_delta = -1;              // resident-set growth over one build
  size_t faces = 0, refused = 0, vertices = 0;
  std::string note;                 // what the build did (topomesh)
  std::vector<Sweep> sweeps;
  Sweep *find(const std::string &n) {
    for (auto &s : sweeps)
      if (s.name == n) return &s;
    return nullptr;
  }
};

// Runs `f` (which returns a checksum and adds its count) `reps` times, timing each.
template <class F> Sweep time_sweep(const std::string &name, int reps, F &&f) {
  Sweep s;
  s.name = name;
  for (int r = 0; r < reps; ++r) {
    uint64_t count = 0;
    double t0 = now_ms();
    uint64_t cs = f(count);
    double t1 = now_ms();
    s.ms.push_back(t1 - t0);
    s.checksum = cs;
    s.count = count;
  }
  return s;
}

inline Sweep skipped_sweep(const std::string &name, const std::string &why) {
  Sweep s;
  s.name = name;
  s.note = why;
  return s;
}

} // namespace diffmesh
