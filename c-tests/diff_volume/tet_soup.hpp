// Tetrahedron soups for the CHF differential tests and the volume benchmark: a reader for
// tetgen's .node/.ele pair, and the small pathological cases the tests write themselves.
// CGAL and topomesh are always built from the SAME arrays held here.
#pragma once

#include "../diff_common/text.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace diffvol {

struct TetSoup : difftext::Points {
  std::vector<uint32_t> tets;    // 4 per tetrahedron, input vertex ids
  size_t n_tets() const { return tets.size() / 4; }
};

namespace detail {
using difftext::Lines;
using difftext::num;
using difftext::slurp;
} // namespace detail

// Reads tetgen's `<base>.node` and `<base>.ele` (numbered from 0 or 1: the first node's
// index decides; attributes and boundary markers ignored; 10-node tetrahedra keep their
// 4 corners). On failure returns false with a message in `err`.
inline bool read_tetgen(const std::string &base, TetSoup &s, std::string &err) {
  s = TetSoup();
  s.name = difftext::file_name(base);
  std::string text;
  const char *b, *e;
  if (!detail::slurp(base + ".node", text)) { err = "cannot read " + base + ".node"; return false; }
  {
    detail::Lines lines{text.data(), text.data() + text.size()};
    size_t nv = 0;
    int dim = 0;
    if (!lines.next(b, e) || !detail::num(b, e, nv) || !detail::num(b, e, dim) || dim != 3) {
      err = base + ".node: bad header";
      return false;
    }
    s.n_vertices = nv;
    s.positions.resize(3 * nv);
    long first = -1;
    for (size_t v = 0; v < nv; ++v) {
      long id = 0;
      if (!lines.next(b, e) || !detail::num(b, e, id)) {
        err = base + ".node: bad line for node " + std::to_string(v);
        return false;
      }
      if (first < 0) first = id;
      if (size_t(id - first) != v) { err = base + ".node: nodes not numbered in order"; return false; }
      for (int k = 0; k < 3; ++k)
        if (!detail::num(b, e, s.positions[3 * v + k])) {
          err = base + ".node: bad coordinate in node " + std::to_string(v);
          return false;
        }
    }
    if (!detail::slurp(base + ".ele", text)) { err = "cannot read " + base + ".ele"; return false; }
    lines = detail::Lines{text.data(), text.data() + text.size()};
    size_t nt = 0;
    int per = 0;
    if (!lines.next(b, e) || !detail::num(b, e, nt) || !detail::num(b, e, per) ||
        (per != 4 && per != 10)) {
      err = base + ".ele: bad header";
      return false;
    }
    s.tets.resize(4 * nt);
    for (size_t t = 0; t < nt; ++t) {
      long id = 0;
      if (!lines.next(b, e) || !detail::num(b, e, id)) {
        err = base + ".ele: bad line for tetrahedron " + std::to_string(t);
        return false;
      }
      for (int k = 0; k < 4; ++k) {
        long x = 0;
        if (!detail::num(b, e, x) || x < first || size_t(x - first) >= nv) {
          err = base + ".ele: bad node id in tetrahedron " + std::to_string(t);
          return false;
        }
        s.tets[4 * t + k] = uint32_t(x - first);
      }
    }
  }
  return true;
}

// ---- The pathological cases, with what a careful reader counts by hand. ----

// Hand-computed topology of a case (-1: not asserted).
struct Expect {
  long vertices = -1, edges = -1, faces = -1, tetrahedra = -1;
  long boundary_faces = -1, boundary_components = -1, components = -1;
  long euler = -1;
  int manifold = -1;          // 1 / 0
  long split_vertices = -1;   // non-manifold input vertices
  long non_manifold_faces = -1;
  long non_manifold_edges = -1;
  long structure_vertices = -1; // after the split: input vertices + copies
  long boundary_euler = -1;   // V - E + F of the boundary surface
};

// What CGAL's build_triangulation should do with a case.
enum class CgalExpect { Accept, Refuse, AcceptButWrong };

struct Case {
  TetSoup soup;
  Expect expect;
  CgalExpect cgal = CgalExpect::Accept;
  std::string why; // for Refuse / AcceptButWrong
};

namespace detail {
inline void add_point(TetSoup &s, double x, double y, double z) {
  s.positions.insert(s.positions.end(), {x, y, z});
  s.n_vertices++;
}
inline void add_tet(TetSoup &s, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  s.tets.insert(s.tets.end(), {a, b, c, d});
}
// Cubes of a grid, cut into 6 tetrahedra around the main diagonal (Kuhn/Freudenthal): the
// cut agrees on shared cube faces, so any set of cubes gives a conforming mesh. Vertex
// (i, j, k) of an (n+1)^3 grid has id i + (n+1) (j + (n+1) k); unused ones are dropped.
inline TetSoup kuhn_cubes(const std::string &name, int n,
                          const std::vector<std::array<int, 3>> &cubes) {
  TetSoup s;
  s.name = name;
  int m = n + 1;
  std::vector<long> id(size_t(m) * m * m, -1);
  auto vid = [&](int i, int j, int k) {
    long &x = id[size_t(i + m * (j + m * k))];
    if (x < 0) {
      x = long(s.n_vertices);
      add_point(s, i, j, k);
    }
    return uint32_t(x);
  };
  // The 6 monotone paths from (0,0,0) to (1,1,1).
  static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2},
                                  {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (auto c : cubes)
    for (auto &p : perms) {
      int cur[3] = {c[0], c[1], c[2]};
      uint32_t v[4];
      v[0] = vid(cur[0], cur[1], cur[2]);
      for (int step = 0; step < 3; ++step) {
        cur[p[step]]++;
        v[step + 1] = vid(cur[0], cur[1], cur[2]);
      }
      add_tet(s, v[0], v[1], v[2], v[3]);
    }
  return s;
}
} // namespace detail

// A case from its points and tetrahedra.
inline Case soup_case(const std::string &name, const std::vector<std::array<double, 3>> &points,
                      const std::vector<std::array<uint32_t, 4>> &tets, const Expect &expect,
                      CgalExpect cgal = CgalExpect::Accept, const std::string &why = "") {
  Case c;
  c.soup.name = name;
  for (const auto &p : points) detail::add_point(c.soup, p[0], p[1], p[2]);
  for (const auto &t : tets) detail::add_tet(c.soup, t[0], t[1], t[2], t[3]);
  c.expect = expect;
  c.cgal = cgal;
  c.why = why;
  return c;
}

// A case of Kuhn cubes: the cubes (i, j, k) of an n^3 grid that `keep` accepts.
template <class Keep>
inline Case cubes_case(const std::string &name, int n, Keep keep, const Expect &expect) {
  std::vector<std::array<int, 3>> cubes;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        if (keep(i, j, k)) cubes.push_back({i, j, k});
  Case c;
  c.soup = detail::kuhn_cubes(name, n, cubes);
  c.expect = expect;
  return c;
}

inline std::vector<Case> pathological_cases() {
  // The corners of the unit tetrahedron at x = 0, and of its copy moved to x = 5.
  const std::array<double, 3> o{0, 0, 0}, x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  const std::array<double, 3> o5{5, 0, 0}, x5{6, 0, 0}, y5{5, 1, 0}, z5{5, 0, 1};
  std::vector<Case> out;
  out.push_back(soup_case("one-tet", {o, x, y, z}, {{0, 1, 2, 3}},
                          {4, 6, 4, 1, 4, 1, 1, 1, 1, 0, 0, 0, 4, 2}));
  // 0,1,2 shared; 3 above, 4 below.
  out.push_back(soup_case("two-share-face", {o, x, y, {0.3, 0.3, 1}, {0.3, 0.3, -1}},
                          {{0, 1, 2, 3}, {0, 2, 1, 4}},
                          {5, 9, 7, 2, 6, 1, 1, 1, 1, 0, 0, 0, 5, 2}));
  // Edge 0-1 shared by two tetrahedra that share nothing else. Both ends of the edge have
  // two face-disconnected stars: split, 2 copies added.
  out.push_back(soup_case("two-share-edge",
                          {o, x, {0, 1, 0.2}, {0, 0.2, 1}, {0, -1, -0.2}, {0, -0.2, -1}},
                          {{0, 1, 2, 3}, {0, 1, 4, 5}},
                          {6, 11, 8, 2, 8, 1, 1, 1, 0, 2, 0, 1, 8, -1},
                          CgalExpect::Refuse,
                          "four boundary facets on one edge: the infinite cells cannot be glued"));
  // Vertex 0 shared.
  out.push_back(soup_case(
      "two-share-vertex", {o, x, y, z, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
      {{0, 1, 2, 3}, {0, 4, 5, 6}}, {7, 12, 8, 2, 8, 1, 1, 1, 0, 1, 0, 0, 8, -1},
      CgalExpect::AcceptButWrong,
      "one cell per vertex: the star of vertex 0 reaches one of its two tetrahedra"));
  // Face 0,1,2 in three tetrahedra. The face is non-manifold (never paired); its three
  // edges then carry three fans and its three vertices three face-disconnected pieces
  // each: 6 copies added.
  out.push_back(soup_case("three-on-face",
                          {o, x, y, {0.3, 0.3, 1}, {0.3, 0.3, -1}, {0.3, 0.3, 2}},
                          {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 5}},
                          {6, 12, 10, 3, 9, 1, 1, 1, 0, 3, 1, 3, 12, -1}, CgalExpect::Refuse,
                          "a facet with three cells"));
  // A ball minus a ball: chi = 2; boundary: two spheres (outer 6x9x2 + inner 6x2
  // triangles), boundary chi = 4. V = 64, T = 26 x 6.
  const auto all_but_middle = [](int i, int j, int k) { return !(i == 1 && j == 1 && k == 1); };
  out.push_back(cubes_case("cavity", 3, all_but_middle,
                           {64, -1, -1, 156, 120, 2, 1, 2, 1, 0, 0, 0, 64, 4}));
  // A solid torus: chi = 0; boundary: one torus (chi 0). V = 32, T = 8 x 6,
  // boundary triangles: 2 x 8 x 2 (top, bottom) + (12 outer + 4 inner squares) x 2.
  const auto ring = [](int i, int j, int k) { return k == 0 && !(i == 1 && j == 1); };
  out.push_back(
      cubes_case("solid-torus", 3, ring, {32, -1, -1, 48, 64, 1, 1, 0, 1, 0, 0, 0, 32, 0}));
  // Two tetrahedra apart and an isolated vertex.
  out.push_back(soup_case("two-apart-isolated", {o, x, y, z, o5, x5, y5, z5, {9, 9, 9}},
                          {{0, 1, 2, 3}, {4, 5, 6, 7}},
                          {9, 12, 8, 2, 8, 2, 2, 3, 1, 0, 0, 0, 9, 4}));
  return out;
}

} // namespace diffvol
