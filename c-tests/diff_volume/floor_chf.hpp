// The floor of a 1-4 split storm: the least a split costs in CHF's arrays, whatever the
// library around them. Copies of a build's V and O; a split reads the drawn tetrahedron's
// corners and twins, appends three tetrahedra on a new vertex, and re-points the three
// neighbours whose faces move to the new ones. Nothing else: no check (CGAL's
// insert_in_cell makes none either), no position for the new vertex (a centroid costs four
// more loads, which a faster layout of the positions might save), no VH, no face or edge
// ids, no removed marks. The same draws as the storms of bench_vol_edit.cpp (the live list,
// the split one kept in its slot).
#pragma once

#include "edit_policy.hpp"

#include <topomesh/topomesh.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace diffvol {

class FloorChf {
public:
  explicit FloorChf(const topomesh::Volume &vol) {
    const auto V = vol.half_face_vertices(), O = vol.opposites();
    v_.assign(V.begin(), V.end());
    o_.assign(O.begin(), O.end());
    nv_ = uint32_t(vol.num_vertices());
  }

  // V and O.
  size_t structure_bytes() const { return 4 * (v_.size() + o_.size()); }

  EditRun split_storm(uint64_t n, uint64_t seed) {
    std::vector<uint32_t> live(v_.size() / 4);
    std::iota(live.begin(), live.end(), 0u);
    live.reserve(live.size() + 3 * n);
    v_.reserve(v_.size() + 12 * n), o_.reserve(o_.size() + 12 * n);
    EditRng rng(seed);
    EditRun run;
    double t0 = cpu_ms();
    for (uint64_t i = 0; i < n; ++i) {
      const uint32_t t = live[rng.below(live.size())], bound = uint32_t(v_.size() / 4);
      split(t);
      live.insert(live.end(), {bound, bound + 1, bound + 2});
    }
    run.ms = cpu_ms() - t0;
    run.attempts = run.accepted = n;
    return run;
  }

  // The arrays still describe a tetrahedral mesh: O pairs half-faces on the same three
  // vertices.
  bool valid() const {
    for (size_t h = 0; h < o_.size(); ++h) {
      const uint32_t g = o_[h];
      if (g != kNone && (o_[g] != h || face(h) != face(g))) return false;
    }
    return true;
  }

private:
  static constexpr uint32_t kNone = ~0u;
  // The sorted vertices of half-face h.
  std::array<uint32_t, 3> face(size_t h) const {
    std::array<uint32_t, 3> f;
    for (size_t i = 0, k = 0; i < 4; ++i)
      if (i != h % 4) f[k++] = v_[h / 4 * 4 + i];
    std::sort(f.begin(), f.end());
    return f;
  }
  std::vector<uint32_t> v_, o_;
  uint32_t nv_ = 0;

  // t keeps its face 3 with the new vertex x for corner 3; tetrahedron b + i (i < 3) takes
  // face i of t, with x for corner i.
  void split(uint32_t t) {
    const size_t f = 4 * size_t(t), b = v_.size() / 4;
    uint32_t q[4], nb[4];
    for (int i = 0; i < 4; ++i) q[i] = v_[f + i], nb[i] = o_[f + i];
    const uint32_t x = nv_++;
    v_[f + 3] = x;
    v_.resize(v_.size() + 12), o_.resize(o_.size() + 12);
    for (uint32_t i = 0; i < 3; ++i) {
      const size_t n = 4 * (b + i);
      for (uint32_t j = 0; j < 4; ++j) v_[n + j] = j == i ? x : q[j];
      o_[n + i] = nb[i];
      if (nb[i] != kNone) o_[nb[i]] = uint32_t(n + i);
      o_[f + i] = uint32_t(n + 3), o_[n + 3] = uint32_t(f + i);
      for (uint32_t j = 0; j < 3; ++j)
        if (j != i) o_[n + j] = uint32_t(4 * (b + j) + i);
    }
  }
};

} // namespace diffvol
