// The floor of a CHE flip storm: the least a checked flip costs in CHE's arrays, whatever
// the library around them. Copies of a level-2 build's V, O and EH, and each half-edge's
// edge id. A flip lays the two triangles out as topomesh's does: two corners rewritten, two
// outer neighbours re-pointed, two outer edges' ids moved (level 2 keeps edge ids stable).
// Its check walks the rotation round one end, both ways at once as topomesh's does: without
// an edge index, the policy's check can do no less. Nothing else: no VH, no removed marks,
// no positions, no refusal details. Only the flip storm runs on it (the policy's
// flip_storm, the same draws, so the same flips: the accepted counts say so).
#pragma once

#include <topomesh/topomesh.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace diffmesh {

class FloorChe {
public:
  explicit FloorChe(const topomesh::Surface &s) {
    const auto V = s.half_edge_vertices(), O = s.opposites(), EH = s.edge_half_edges();
    v_.assign(V.begin(), V.end());
    o_.assign(O.begin(), O.end());
    eh_.assign(EH.begin(), EH.end());
    e_.assign(v_.size(), kNone);
    for (uint32_t e = 0; e < eh_.size(); ++e) {
      const uint32_t h = eh_[e];
      e_[h] = e;
      if (o_[h] != kNone) e_[o_[h]] = e;
    }
  }
  uint32_t n_edges() const { return uint32_t(eh_.size()); }
  bool edge_removed(uint32_t) const { return false; }
  size_t live_triangles() const { return v_.size() / 3; }
  size_t structure_bytes() const { return 4 * (v_.size() + o_.size() + e_.size() + eh_.size()); }

  // Interior, and the flipped edge (c, d) not there yet (c != d).
  bool flip_ok(uint32_t e) const {
    const uint32_t h = eh_[e], g = o_[h];
    if (g == kNone) return false;
    const uint32_t c = v_[prev(h)], d = v_[prev(g)];
    return c != d && !joined(prev(h), d);
  }
  // Triangles (a b c) and (b a d) become (d b c) and (c a d), as topomesh's flip lays them
  // out: two corners change, the outer edges b-c and a-d keep their slots, c-a and d-b move
  // to h's and g's slots, and the new edge c-d takes h2 and g2.
  void flip(uint32_t e) {
    const uint32_t h = eh_[e], g = o_[h], h2 = prev(h), g2 = prev(g);
    const uint32_t c = v_[h2], d = v_[g2], oh2 = o_[h2], og2 = o_[g2];
    const uint32_t e_ca = e_[h2], e_db = e_[g2];
    v_[h] = d, v_[g] = c;
    link(g, oh2), link(h, og2), link(h2, g2);
    e_[g] = e_ca, e_[h] = e_db, e_[h2] = e_[g2] = e;
    if (eh_[e_ca] == h2) eh_[e_ca] = g;
    if (eh_[e_db] == g2) eh_[e_db] = h;
    eh_[e] = h2;
  }
  // The arrays still describe a surface: O pairs opposite half-edges of one edge id, and
  // each edge's half-edge carries its id.
  bool valid() const {
    for (uint32_t h = 0; h < o_.size(); ++h) {
      const uint32_t g = o_[h];
      if (g != kNone && (o_[g] != h || v_[next(h)] != v_[g] || v_[h] != v_[next(g)] || e_[g] != e_[h])) return false;
    }
    for (uint32_t e = 0; e < eh_.size(); ++e)
      if (e_[eh_[e]] != e) return false;
    return true;
  }

private:
  static constexpr uint32_t kNone = ~0u;
  std::vector<uint32_t> v_, o_, e_, eh_;
  // The header's rotation arithmetic (topomesh_inline.h), under the names of the spec.
  static uint32_t next(uint32_t h) { return che_next(h); }
  static uint32_t prev(uint32_t h) { return che_prev(h); }
  void link(uint32_t x, uint32_t y) {
    o_[x] = y;
    if (y != kNone) o_[y] = x;
  }
  // Does an edge join the origin of k to d? The rotation round that origin, both ways at once
  // (a walk reaches d in half the steps), each triangle naming both its other corners (on a
  // boundary the last neighbour is only a prev); the two ways stop where they meet.
  bool joined(uint32_t k, uint32_t d) const {
    auto hit = [&](uint32_t x) { return v_[next(x)] == d || v_[prev(x)] == d; };
    if (hit(k)) return true;
    for (uint32_t ccw = k, cw = k; ccw != kNone || cw != kNone;) {
      if (ccw != kNone) {
        ccw = o_[prev(ccw)];
        if (ccw != kNone && (ccw == cw || hit(ccw))) return ccw != cw;
      }
      if (cw != kNone) {
        cw = o_[cw] == kNone ? kNone : next(o_[cw]);
        if (cw != kNone && (cw == ccw || hit(cw))) return cw != ccw;
      }
    }
    return false;
  }
};

} // namespace diffmesh
