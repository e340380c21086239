// The random numbers of the editing runs (diff_surface and diff_volume): splitmix64, small,
// fast and the same sequence on every platform (std's distributions are not).
#pragma once

#include <cstdint>

namespace diffcommon {

// The next number of the sequence whose state is `s`.
inline uint64_t splitmix64(uint64_t &s) {
  uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

} // namespace diffcommon
