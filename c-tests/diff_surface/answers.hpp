// The answers of one library to every relation, in "common" ids, so that OpenMesh, CGAL and
// topomesh can be compared element by element.
//
// Common ids: vertices are the ids the mesh was built with (all three libraries add the
// vertices in order; the adaptors check it); faces are indices into the submitted triangle
// list (a peer's face ids skip the faces it refused; the adaptor maps them back; topomesh's
// through its triangle origins); edges are unordered vertex pairs (ids differ everywhere).
//
// Orders: VV, VE, VF counter-clockwise seen from outside (cyclic; CGAL's clockwise
// circulators are reversed by its adaptor); FV counter-clockwise, cyclic; FF[f][i] and
// FE[f][i] are across / on the edge FV[f][i] -> FV[f][i+1]; EF, EE as sets; boundary curves
// as cyclic vertex sequences with the interior on the left.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace diffmesh {

constexpr uint32_t NONE = UINT32_MAX;
using Pair = std::pair<uint32_t, uint32_t>; // always (min, max)

inline Pair mkpair(uint32_t a, uint32_t b) { return a < b ? Pair{a, b} : Pair{b, a}; }

struct Answers {
  std::string lib;
  size_t n_vertices = 0, n_edges = 0, n_faces = 0;
  // Per vertex (have_v says which were asked; all of them for the peers).
  std::vector<uint8_t> have_v;
  std::vector<std::vector<uint32_t>> vv, vf;
  std::vector<std::vector<Pair>> ve;
  std::vector<uint8_t> v_boundary;
  // Per face.
  std::vector<uint8_t> have_f;
  std::vector<std::array<uint32_t, 3>> fv, ff;
  std::vector<std::array<Pair, 3>> fe;
  // Per edge, in the library's own edge order.
  std::vector<uint8_t> have_e;
  std::vector<Pair> ev;
  std::vector<std::vector<uint32_t>> ef; // sorted
  std::vector<std::vector<Pair>> ee;     // sorted
  bool have_curves = false;
  std::vector<std::vector<uint32_t>> curves;

  void resize(size_t nv, size_t ne, size_t nf) {
    n_vertices = nv;
    n_edges = ne;
    n_faces = nf;
    have_v.assign(nv, 0);
    vv.assign(nv, {});
    vf.assign(nv, {});
    ve.assign(nv, {});
    v_boundary.assign(nv, 0);
    resize_faces(nf, nf);
    have_e.assign(ne, 0);
    ev.assign(ne, {NONE, NONE});
    ef.assign(ne, {});
    ee.assign(ne, {});
  }
  // `nf` faces, stored in `slots` places (a peer's: by submitted index).
  void resize_faces(size_t nf, size_t slots) {
    n_faces = nf;
    have_f.assign(slots, 0);
    fv.assign(slots, {NONE, NONE, NONE});
    ff.assign(slots, {NONE, NONE, NONE});
    fe.assign(slots, {});
  }
  long long euler() const { return (long long)n_vertices - (long long)n_edges + (long long)n_faces; }
};

// The answers (fv, fe, ff) of triangle i of any library, from its half-edge h on (`next`
// the next one): `ends` gives a half-edge's (source, target) as they are (not a Pair),
// `across` the face id across it or NONE.
template <class H, class Next, class Ends, class Across>
void face_answers(Answers &a, size_t i, H h, Next next, Ends ends, Across across) {
  a.have_f[i] = 1;
  for (int k = 0; k < 3; ++k, h = next(h)) {
    const auto [from, to] = ends(h);
    a.fv[i][k] = from;
    a.fe[i][k] = mkpair(from, to);
    a.ff[i][k] = across(h);
  }
}

// Per-edge answers (ev, ef, ee) from a half-edge pair h0, h1 of any library: `face`
// gives a face id or NONE, `ends` a half-edge's (source, target), `around` its next and
// previous half-edges.
template <class H, class Face, class Ends, class Around>
void edge_answers(Answers &a, size_t i, H h0, H h1, Face face, Ends ends, Around around) {
  a.have_e[i] = 1;
  a.ev[i] = ends(h0);
  for (H h : {h0, h1}) {
    const uint32_t f = face(h);
    if (f == NONE) continue;
    a.ef[i].push_back(f);
    for (H g : around(h)) a.ee[i].push_back(ends(g));
  }
  std::sort(a.ef[i].begin(), a.ef[i].end());
  std::sort(a.ee[i].begin(), a.ee[i].end());
}

// What the peer did with the submitted triangles.
struct PeerBuild {
  size_t submitted = 0;  // triangles offered (degenerate ones are not offered)
  size_t skipped_degenerate = 0;
  size_t refused = 0;    // add_face gave an invalid / null face
  std::vector<uint32_t> refused_examples;
  bool vertices_in_order = true; // vertex i got handle i
};

// A cyclic sequence rotated to its lexicographically smallest rotation.
template <class T> std::vector<T> canonical_cycle(const std::vector<T> &s) {
  if (s.empty()) return s;
  size_t best = 0, n = s.size();
  for (size_t r = 1; r < n; ++r) {
    for (size_t k = 0; k < n; ++k) {
      const T &a = s[(r + k) % n], &b = s[(best + k) % n];
      if (a < b) { best = r; break; }
      if (b < a) break;
    }
  }
  std::vector<T> out(n);
  for (size_t k = 0; k < n; ++k) out[k] = s[(best + k) % n];
  return out;
}

template <class T> bool same_cycle(const std::vector<T> &a, const std::vector<T> &b) {
  if (a.size() != b.size()) return false;
  size_t n = a.size();
  if (n == 0) return true;
  for (size_t r = 0; r < n; ++r) {
    if (!(b[r] == a[0])) continue;
    size_t k = 1;
    while (k < n && a[k] == b[(r + k) % n]) ++k;
    if (k == n) return true;
  }
  return false;
}

} // namespace diffmesh
