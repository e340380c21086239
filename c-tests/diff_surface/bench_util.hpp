// Timing, memory and result records for the head-to-head benchmark.
//
// Every library (OpenMesh, CGAL, topomesh at each level) is a Subject: something built from
// the arrays. The driver (bench.cpp) interleaves the repetitions: round r builds every
// subject in turn (starting with a different one each round), then runs each sweep of every
// row in turn, so that load from other jobs on the machine spreads over all of them.
#pragma once

#include "off_reader.hpp"

#include <algorithm>
#include <cstdarg>
#include <cstdlib>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <malloc.h>
#include <time.h>
#include <string>
#include <unistd.h>
#include <vector>

namespace diffmesh {

inline double now_ms() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

// CPU time of the calling thread (user + system), in milliseconds: on a machine shared with
// other jobs it leaves out the time the benchmark waits for a core.
inline double cpu_ms() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// CPU time of the whole process (user + system, every thread), in milliseconds: for what
// runs on several threads, where the calling thread's time leaves the others out.
inline double process_cpu_ms() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
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

// A full sweep of a relation over the current build: returns a checksum, adds the number of
// entries visited to `count`.
using SweepFn = std::function<uint64_t(uint64_t &count)>;

// One sweep of one row: the function (empty when skipped, with the reason in `note`) and its
// results.
struct Sweep {
  std::string name;        // VV, VF, FF, EF, curves
  SweepFn fn;
  std::string note;        // why skipped
  std::vector<double> ms;  // CPU time, one per repetition
  std::vector<double> wall_ms;
  uint64_t checksum = 0;   // the same for every library on a fully accepted mesh
  uint64_t count = 0;      // entries visited
  bool skipped() const { return !fn; }
};

inline Sweep sweep(const std::string &name, SweepFn fn) { return Sweep{name, std::move(fn), {}, {}, {}, 0, 0}; }
inline Sweep skipped_sweep(const std::string &name, const std::string &why) {
  return Sweep{name, nullptr, why, {}, {}, 0, 0};
}

// One line of the tables: a library, or a topomesh level with one access path.
struct LibBench {
  std::string lib;                  // "OpenMesh", "CGAL", "topomesh L2", ...
  std::string path;                 // access path for topomesh: "C API", "zero-copy", ...
  bool owns_build = false;          // the first row of its subject: build and memory columns
  std::vector<double> build_ms;      // CPU time
  std::vector<double> build_wall_ms;
  size_t connectivity_bytes = 0;    // from container sizes
  long rss_delta = -1;              // resident-set growth over one build
  size_t faces = 0, refused = 0, vertices = 0;
  std::string note;                 // what the build did (topomesh)
  std::vector<Sweep> sweeps;
};

// Something built from the arrays, with the rows of sweeps that run on its current build.
class Subject {
public:
  virtual ~Subject() = default;
  // Frees the current build (if any); not timed.
  virtual void release() = 0;
  // Builds from the arrays (the previous build released); timed.
  virtual void build() = 0;
  // Fills the build columns of the first row from the current build.
  virtual void describe(LibBench &row) const = 0;
  // The rows; their sweep functions act on whatever is built when they run.
  virtual std::vector<LibBench> rows() = 0;
};

// Prints to stdout and, when `file` is open, into the Markdown page too.
struct Out {
  FILE *file = nullptr;
  void operator()(const char *fmt, ...) __attribute__((format(printf, 2, 3))) {
    char buf[4096];
    va_list ap;
    va_start(ap, fmt);
    std::vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    std::fputs(buf, stdout);
    std::fflush(stdout);
    if (file) std::fputs(buf, file);
  }
};

// The benchmark programs' arguments: [--reps N] [--md FILE] MESH.off...; `--md` opens
// FILE into `out`. Gives the exit status to leave with, 0 to go on: 1 (the reason
// printed) when FILE cannot be opened, 2 (`usage: USAGE` printed) without a mesh or with
// fewer than one repetition.
struct BenchArgs {
  int reps = 5;
  std::vector<std::string> files;
};
inline int parse_bench_args(int argc, char **argv, const char *usage, BenchArgs &args, Out &out) {
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--reps" && i + 1 < argc) args.reps = std::atoi(argv[++i]);
    else if (a == "--md" && i + 1 < argc) {
      out.file = std::fopen(argv[++i], "w");
      if (!out.file) { std::perror(argv[i]); return 1; }
    } else args.files.push_back(a);
  }
  if (args.files.empty() || args.reps < 1) {
    std::fprintf(stderr, "usage: %s\n", usage);
    return 2;
  }
  return 0;
}

// The main of a benchmark program (`tool`, `usage` as for parse_bench_args): each mesh
// of its arguments read by read_bench_mesh, then given to `each(soup, reps, out)`. The
// exit status: parse_bench_args's, or 1 when a mesh cannot be read.
template <class Each>
int bench_main(int argc, char **argv, const char *tool, const char *usage, Each each) {
  BenchArgs args;
  Out out;
  if (int status = parse_bench_args(argc, argv, usage, args, out)) return status;
  for (const std::string &f : args.files) {
    Soup s;
    if (!read_bench_mesh(tool, f, s)) return 1;
    each(s, args.reps, out);
  }
  if (out.file) std::fclose(out.file);
  return 0;
}

inline std::string fmt_ms(double ms) {
  char b[32];
  if (ms < 0) return "–";
  if (ms < 10) std::snprintf(b, sizeof b, "%.2f", ms);
  else if (ms < 100) std::snprintf(b, sizeof b, "%.1f", ms);
  else std::snprintf(b, sizeof b, "%.0f", ms);
  return b;
}
inline std::string fmt_ratio2(double num, double den) {
  char b[32];
  if (num <= 0 || den <= 0) return "–";
  std::snprintf(b, sizeof b, "%.2f×", num / den);
  return b;
}

} // namespace diffmesh
