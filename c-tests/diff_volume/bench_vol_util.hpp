// What the volume benchmarks share (bench_vol.cpp, bench_vol_edit.cpp): the clock, the
// median, the resident-set probes and the number formats of their tables.
#pragma once

#include "tet_soup.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <malloc.h>
#include <string>
#include <vector>

namespace diffvol {

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

// /proc/self/status fields in bytes (VmRSS, VmHWM).
inline long status_bytes(const char *field) {
  long kb = -1;
  if (std::FILE *f = std::fopen("/proc/self/status", "r")) {
    char line[256];
    size_t n = std::strlen(field);
    while (std::fgets(line, sizeof line, f))
      if (std::strncmp(line, field, n) == 0 && line[n] == ':') {
        kb = std::atol(line + n + 1);
        break;
      }
    std::fclose(f);
  }
  return kb < 0 ? -1 : kb * 1024;
}
// Resets VmHWM to the current RSS (Linux: "5" to /proc/self/clear_refs).
inline bool reset_peak() {
  std::FILE *f = std::fopen("/proc/self/clear_refs", "w");
  if (!f) return false;
  bool ok = std::fputs("5", f) >= 0;
  return std::fclose(f) == 0 && ok;
}

struct MemProbe {
  long base = -1, peak = -1, after = -1;
  bool peak_ok = false;
  void begin() {
    malloc_trim(0);
    peak_ok = reset_peak();
    base = status_bytes("VmRSS");
  }
  // The peak first; then freed memory goes back (the build's temporaries would otherwise
  // stay in malloc's free lists and count as retained).
  void end() {
    peak = status_bytes("VmHWM");
    malloc_trim(0);
    after = status_bytes("VmRSS");
  }
  long retained() const { return after - base; }
  long peak_delta() const { return peak_ok ? peak - base : -1; }
};

inline std::string mib(double bytes) {
  char b[64];
  std::snprintf(b, sizeof b, "%.1f", bytes / (1024.0 * 1024.0));
  return b;
}
inline std::string ms(double x) {
  char b[64];
  std::snprintf(b, sizeof b, x < 10 ? "%.2f" : "%.1f", x);
  return b;
}
inline std::string ratio(double a, double b) {
  if (a <= 0 || b <= 0) return "-";
  char buf[64];
  // Two significant digits below 0.1 (a ratio far under 1 would print as 0.00).
  std::snprintf(buf, sizeof buf, a / b < 0.1 ? "%.2g" : "%.2f", a / b);
  return buf;
}

// A benchmark's tetrahedra, tetgen's `<base>.node` and `<base>.ele`; exits with status 1
// when they cannot be read.
inline TetSoup read_bench_tets(const std::string &base) {
  TetSoup s;
  std::string err;
  if (!read_tetgen(base, s, err)) {
    std::fprintf(stderr, "%s\n(run scripts/fetch-tets.sh first)\n", err.c_str());
    std::exit(1);
  }
  return s;
}

} // namespace diffvol
