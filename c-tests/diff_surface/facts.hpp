// Brute-force topology of a triangle soup, independent of every library: what che_summary
// must say about the input complex.
#pragma once

#include "../diff_common/dsu.hpp"

#include "off_reader.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace diffmesh {

struct Facts {
  uint64_t vertices = 0, edges = 0, triangles = 0, boundary_edges = 0, boundary_curves = 0,
           components = 0, isolated_vertices = 0, non_manifold_edges = 0,
           non_manifold_vertices = 0, degenerate = 0, non_orientable_components = 0;
  int64_t euler = 0, genus = -1;
};

namespace detail {
using diffcommon::Dsu;
// Union-find with parity (for orientation): parity(x) relative to its root.
struct ParityDsu {
  std::vector<uint32_t> p;
  std::vector<uint8_t> par;
  explicit ParityDsu(size_t n) : p(n), par(n, 0) { std::iota(p.begin(), p.end(), 0u); }
  std::pair<uint32_t, uint8_t> find(uint32_t x) {
    uint8_t acc = 0;
    uint32_t r = x;
    while (p[r] != r) acc ^= par[r], r = p[r];
    // Compress: point x's path straight at r with its parity.
    uint8_t a2 = acc;
    while (p[x] != x) {
      uint32_t up = p[x];
      uint8_t pu = par[x];
      p[x] = r, par[x] = a2;
      a2 ^= pu;
      x = up;
    }
    return {r, acc};
  }
  // Returns false when the constraint contradicts the ones before.
  bool join(uint32_t a, uint32_t b, uint8_t differ) {
    auto [ra, pa] = find(a);
    auto [rb, pb] = find(b);
    if (ra == rb) return (pa ^ pb) == differ;
    p[rb] = ra, par[rb] = pa ^ pb ^ differ;
    return true;
  }
};
} // namespace detail

inline Facts brute_force_facts(const Soup &s) {
  Facts f;
  const size_t nv = s.n_vertices, nt = s.n_triangles();
  f.vertices = nv;
  // Half-edge records (min, max, corner) of the non-degenerate triangles, sorted by pair.
  struct Rec { uint32_t a, b, h; bool fwd; };
  std::vector<Rec> r;
  r.reserve(3 * nt);
  std::vector<uint8_t> used(nv, 0);
  detail::Dsu comp(nv);
  for (uint32_t t = 0; t < nt; ++t) {
    if (s.is_degenerate(t)) { f.degenerate++; continue; }
    f.triangles++;
    const uint32_t *c = &s.triangles[3 * t];
    for (int i = 0; i < 3; ++i) {
      uint32_t p = c[i], q = c[(i + 1) % 3];
      r.push_back({std::min(p, q), std::max(p, q), 3 * t + uint32_t(i), p < q});
      used[p] = 1;
    }
    comp.join(c[0], c[1]);
    comp.join(c[0], c[2]);
  }
  for (size_t v = 0; v < nv; ++v) {
    if (!used[v]) f.isolated_vertices++;
    else if (comp.find(uint32_t(v)) == v) f.components++;
  }
  std::sort(r.begin(), r.end(), [](const Rec &x, const Rec &y) {
    return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.h < y.h;
  });
  detail::Dsu corners(3 * nt), bcurves(nv);
  detail::ParityDsu orient(nt);
  std::vector<uint8_t> on_boundary(nv, 0), conflict(nt, 0);
  for (size_t i = 0; i < r.size();) {
    size_t j = i;
    while (j < r.size() && r[j].a == r[i].a && r[j].b == r[i].b) ++j;
    size_t k = j - i;
    f.edges++;
    if (k == 1) {
      f.boundary_edges++;
      on_boundary[r[i].a] = on_boundary[r[i].b] = 1;
      bcurves.join(r[i].a, r[i].b);
    } else if (k >= 3) {
      f.non_manifold_edges++;
    } else {
      // Two triangles: their corners at each end are in one fan.
      auto corner_at = [&](uint32_t h, uint32_t v) {
        uint32_t t = h / 3;
        for (uint32_t c = 0; c < 3; ++c)
          if (s.triangles[3 * t + c] == v) return 3 * t + c;
        return h;
      };
      for (uint32_t v : {r[i].a, r[i].b}) corners.join(corner_at(r[i].h, v), corner_at(r[i + 1].h, v));
      // Same direction: exactly one of the two must flip.
      uint8_t differ = r[i].fwd == r[i + 1].fwd;
      if (!orient.join(r[i].h / 3, r[i + 1].h / 3, differ)) conflict[r[i].h / 3] = 1;
    }
    i = j;
  }
  for (size_t v = 0; v < nv; ++v)
    if (on_boundary[v] && bcurves.find(uint32_t(v)) == v) f.boundary_curves++;
  // Fans per vertex: distinct corner roots.
  std::vector<std::pair<uint32_t, uint32_t>> vr; // (vertex, root)
  for (uint32_t t = 0; t < nt; ++t) {
    if (s.is_degenerate(t)) continue;
    for (uint32_t c = 0; c < 3; ++c) vr.push_back({s.triangles[3 * t + c], corners.find(3 * t + c)});
  }
  std::sort(vr.begin(), vr.end());
  vr.erase(std::unique(vr.begin(), vr.end()), vr.end());
  for (size_t i = 0; i + 1 < vr.size(); ++i)
    if (vr[i].first == vr[i + 1].first && (i == 0 || vr[i - 1].first != vr[i].first))
      f.non_manifold_vertices++;
  std::vector<uint8_t> bad_root(nt, 0);
  for (uint32_t t = 0; t < nt; ++t)
    if (conflict[t]) bad_root[orient.find(t).first] = 1;
  for (uint32_t t = 0; t < nt; ++t) f.non_orientable_components += bad_root[t];
  f.euler = int64_t(nv) - int64_t(f.edges) + int64_t(f.triangles);
  if (f.non_manifold_edges == 0 && f.non_manifold_vertices == 0 && f.non_orientable_components == 0) {
    int64_t twice = 2 * int64_t(f.components) - (f.euler - int64_t(f.isolated_vertices)) -
                    int64_t(f.boundary_curves);
    f.genus = (twice >= 0 && twice % 2 == 0) ? twice / 2 : -1;
  }
  return f;
}

} // namespace diffmesh
