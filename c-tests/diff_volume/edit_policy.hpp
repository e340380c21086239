// The seeded random policy of the editing benchmark, shared by both sides (peer_cgal.cpp and
// bench_vol_edit.cpp) so that CGAL and topomesh draw the same kind of operation on the same
// distribution of tetrahedra: a live tetrahedron chosen uniformly (an index into a list of
// the live ones), then the operation and its local face or edge.
#pragma once

#include "../diff_common/splitmix.hpp"

#include <cstddef>
#include <cstdint>
#include <ctime>

namespace diffvol {

// The clock of the editing runs: the CPU time of the process, in ms (every timed run is on
// one thread; on a shared machine the wall clock also counts the other processes' turns).
inline double cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
}

// splitmix64: small, fast and the same on every platform (std:: distributions are not).
struct EditRng {
  uint64_t s;
  explicit EditRng(uint64_t seed) : s(seed) {}
  uint64_t next() { return diffcommon::splitmix64(s); }
  // Uniform enough in [0, n) for n far below 2^64.
  size_t below(size_t n) { return size_t(next() % n); }
};

// One attempt of the flip storm: the live tetrahedron (index into the live list), then a
// 2-3 flip of its face `local` (0..3, the face opposite its vertex `local`) or a 3-2 flip of
// its edge `local` (0..5, the pairs (0,1) (0,2) (0,3) (1,2) (1,3) (2,3) of its vertices).
struct FlipPick {
  size_t k;
  bool flip23;
  int local;
};
inline FlipPick pick_flip(EditRng &rng, size_t live) {
  size_t k = rng.below(live);
  uint64_t r = rng.next();
  bool f23 = (r & 1) == 0;
  return FlipPick{k, f23, int((r >> 1) % (f23 ? 4 : 6))};
}
constexpr int kEdgeEnds[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

// What a storm did: attempts and accepted, by kind (splits count as 2-3 slots unused).
struct EditRun {
  double ms = 0;
  uint64_t attempts = 0, accepted = 0;         // all operations
  uint64_t attempts23 = 0, accepted23 = 0;     // flip storm: 2-3 flips
  uint64_t attempts32 = 0, accepted32 = 0;     // flip storm: 3-2 flips
  double first_ms = -1;                        // the first operation alone (topomesh: makes the edit state)
};

} // namespace diffvol
