// The brute-force oracle and the comparisons (see answers.hpp).
#include "answers.hpp"

#include "../diff_common/dsu.hpp"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <tuple>

namespace diffvol {

namespace {

using diffcommon::Dsu;

std::array<uint32_t, 3> face_opposite(const TetSoup &s, size_t t, int j) {
  std::array<uint32_t, 3> f;
  int k = 0;
  for (int i = 0; i < 4; ++i)
    if (i != j) f[k++] = s.tets[4 * t + i];
  std::sort(f.begin(), f.end());
  return f;
}

// Every (face triple, tetrahedron, slot), sorted by triple.
struct FaceRec {
  std::array<uint32_t, 3> f;
  uint32_t t;
  uint32_t j;
  bool operator<(const FaceRec &o) const { return std::tie(f, t, j) < std::tie(o.f, o.t, o.j); }
};
std::vector<FaceRec> face_records(const TetSoup &s) {
  std::vector<FaceRec> r;
  r.reserve(s.tets.size());
  for (size_t t = 0; t < s.n_tets(); ++t)
    for (int j = 0; j < 4; ++j) r.push_back({face_opposite(s, t, j), uint32_t(t), uint32_t(j)});
  std::sort(r.begin(), r.end());
  return r;
}

std::string fmt_ids(const uint32_t *b, const uint32_t *e, size_t max = 16) {
  std::ostringstream o;
  o << "[";
  size_t n = 0;
  for (const uint32_t *p = b; p != e; ++p, ++n) {
    if (n == max) { o << " ... (" << (e - b) << ")"; break; }
    o << (n ? " " : "") << (*p == NONE ? std::string("NONE") : std::to_string(*p));
  }
  return o.str() + "]";
}
std::string fmt_ids(const std::vector<uint32_t> &v) { return fmt_ids(v.data(), v.data() + v.size()); }
std::string fmt_edge(uint64_t k) {
  return "(" + std::to_string(k >> 32) + "," + std::to_string(k & 0xffffffffu) + ")";
}
std::string fmt_face(const std::array<uint32_t, 3> &f) {
  return "(" + std::to_string(f[0]) + "," + std::to_string(f[1]) + "," + std::to_string(f[2]) + ")";
}

} // namespace

Answers oracle_answers(const TetSoup &s) {
  Answers a;
  a.side = "oracle";
  size_t nt = s.n_tets(), nv = s.n_vertices;
  a.V = long(nv);
  a.T = long(nt);

  // Faces: paired iff exactly two tetrahedra hold the triple.
  a.tt.assign(4 * nt, NONE);
  auto recs = face_records(s);
  for (size_t i = 0; i < recs.size();) {
    size_t j = i;
    while (j < recs.size() && recs[j].f == recs[i].f) ++j;
    a.F++;
    if (j - i == 2) {
      a.tt[4 * recs[i].t + recs[i].j] = recs[i + 1].t;
      a.tt[4 * recs[i + 1].t + recs[i + 1].j] = recs[i].t;
    } else {
      for (size_t k = i; k < j; ++k) a.boundary_faces.push_back(recs[i].f);
    }
    i = j;
  }

  // VT by counting sort (tetrahedra come in increasing order: rows are sorted).
  a.vt.offsets.assign(nv + 1, 0);
  for (uint32_t v : s.tets) a.vt.offsets[v + 1]++;
  for (size_t v = 0; v < nv; ++v) a.vt.offsets[v + 1] += a.vt.offsets[v];
  a.vt.ids.resize(s.tets.size());
  {
    std::vector<uint32_t> fill(a.vt.offsets.begin(), a.vt.offsets.end() - 1);
    for (size_t t = 0; t < nt; ++t)
      for (int k = 0; k < 4; ++k) {
        uint32_t v = s.tets[4 * t + k];
        // A tetrahedron with a repeated vertex appears once.
        if (fill[v] > a.vt.offsets[v] && a.vt.ids[fill[v] - 1] == t) continue;
        a.vt.ids[fill[v]++] = uint32_t(t);
      }
    // Compact (only matters for degenerate input).
    Rows c;
    for (size_t v = 0; v < nv; ++v) {
      c.ids.insert(c.ids.end(), a.vt.ids.begin() + a.vt.offsets[v], a.vt.ids.begin() + fill[v]);
      c.push_row();
    }
    a.vt = std::move(c);
  }

  // VV from the tetrahedra around each vertex.
  std::vector<uint32_t> tmp;
  for (size_t v = 0; v < nv; ++v) {
    tmp.clear();
    for (const uint32_t *p = a.vt.begin(v); p != a.vt.end(v); ++p)
      for (int k = 0; k < 4; ++k)
        if (s.tets[4 * *p + k] != v) tmp.push_back(s.tets[4 * *p + k]);
    std::sort(tmp.begin(), tmp.end());
    tmp.erase(std::unique(tmp.begin(), tmp.end()), tmp.end());
    a.vv.ids.insert(a.vv.ids.end(), tmp.begin(), tmp.end());
    a.vv.push_row();
  }

  // ET per vertex pair.
  std::vector<std::pair<uint64_t, uint32_t>> pairs;
  pairs.reserve(6 * nt);
  static const int E6[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  for (size_t t = 0; t < nt; ++t)
    for (auto &e : E6) pairs.push_back({edge_key(s.tets[4 * t + e[0]], s.tets[4 * t + e[1]]), uint32_t(t)});
  std::sort(pairs.begin(), pairs.end());
  for (size_t i = 0; i < pairs.size();) {
    size_t j = i;
    std::vector<uint32_t> ts;
    while (j < pairs.size() && pairs[j].first == pairs[i].first) ts.push_back(pairs[j++].second);
    a.et.push_back({pairs[i].first, std::move(ts)});
    i = j;
  }
  a.E = long(a.et.size());
  return a;
}

OracleSummary oracle_summary(const TetSoup &s, const Answers &o) {
  OracleSummary r;
  size_t nv = s.n_vertices;
  Dsu all(nv), bnd(nv);
  std::vector<char> used(nv, 0), onb(nv, 0);
  for (size_t t = 0; t < s.n_tets(); ++t) {
    const uint32_t *q = &s.tets[4 * t];
    for (int k = 0; k < 4; ++k) used[q[k]] = 1;
    all.join(q[0], q[1]), all.join(q[0], q[2]), all.join(q[0], q[3]);
  }
  // Faces with exactly one tetrahedron (o.boundary_faces also lists non-manifold ones
  // once per tetrahedron).
  std::vector<std::array<uint32_t, 3>> bf;
  for (size_t i = 0; i < o.boundary_faces.size();) {
    size_t j = i;
    while (j < o.boundary_faces.size() && o.boundary_faces[j] == o.boundary_faces[i]) ++j;
    if (j - i == 1) bf.push_back(o.boundary_faces[i]);
    else r.non_manifold_faces++;
    i = j;
  }
  std::vector<uint64_t> be;
  for (auto &f : bf) {
    for (int k = 0; k < 3; ++k) onb[f[k]] = 1;
    bnd.join(f[0], f[1]), bnd.join(f[0], f[2]);
    be.push_back(edge_key(f[0], f[1])), be.push_back(edge_key(f[1], f[2])), be.push_back(edge_key(f[0], f[2]));
  }
  std::sort(be.begin(), be.end());
  be.erase(std::unique(be.begin(), be.end()), be.end());
  r.boundary_faces = long(bf.size());
  r.boundary_edges = long(be.size());
  for (size_t v = 0; v < nv; ++v) {
    r.isolated += !used[v];
    r.boundary_vertices += onb[v];
    r.components += used[v] && all.find(uint32_t(v)) == v;
    r.boundary_components += onb[v] && bnd.find(uint32_t(v)) == v;
  }
  r.boundary_euler = r.boundary_vertices - r.boundary_edges + r.boundary_faces;
  return r;
}

void compare(const TetSoup &s, const Answers &want, const Answers &got, Diff &d) {
  const std::string tag = got.side + " vs " + want.side + ": ";
  auto count = [&](const char *what, long w, long g) {
    if (w != g) d.add(tag + what + " count: expected " + std::to_string(w) + ", got " + std::to_string(g));
  };
  count("V", want.V, got.V);
  count("E", want.E, got.E);
  count("F", want.F, got.F);
  count("T", want.T, got.T);

  // TT per slot.
  if (got.tt.size() != want.tt.size()) {
    d.add(tag + "TT has " + std::to_string(got.tt.size()) + " slots, expected " + std::to_string(want.tt.size()));
  } else {
    for (size_t i = 0; i < want.tt.size(); ++i)
      if (want.tt[i] != got.tt[i])
        d.add(tag + "TT of tetrahedron " + std::to_string(i / 4) + " across the face opposite vertex " +
              std::to_string(s.tets[i]) + ": expected " +
              (want.tt[i] == NONE ? "NONE" : std::to_string(want.tt[i])) + ", got " +
              (got.tt[i] == NONE ? "NONE" : std::to_string(got.tt[i])));
  }

  auto rows = [&](const char *what, const Rows &w, const Rows &g) {
    if (w.size() != g.size()) {
      d.add(tag + what + " has " + std::to_string(g.size()) + " rows, expected " + std::to_string(w.size()));
      return;
    }
    for (size_t v = 0; v < w.size(); ++v)
      if (!std::equal(w.begin(v), w.end(v), g.begin(v), g.end(v)))
        d.add(tag + what + " of vertex " + std::to_string(v) + ": expected " + fmt_ids(w.begin(v), w.end(v)) +
              ", got " + fmt_ids(g.begin(v), g.end(v)));
  };
  rows("VT", want.vt, got.vt);
  rows("VV", want.vv, got.vv);

  // ET grouped by key: union of fans, fans disjoint.
  auto grouped = [&](const Answers &a, bool check_disjoint) {
    std::vector<std::pair<uint64_t, std::vector<uint32_t>>> g;
    for (size_t i = 0; i < a.et.size();) {
      size_t j = i;
      std::vector<uint32_t> u;
      size_t total = 0;
      while (j < a.et.size() && a.et[j].first == a.et[i].first) {
        u.insert(u.end(), a.et[j].second.begin(), a.et[j].second.end());
        total += a.et[j].second.size();
        ++j;
      }
      std::sort(u.begin(), u.end());
      u.erase(std::unique(u.begin(), u.end()), u.end());
      if (check_disjoint && u.size() != total)
        d.add(tag + "ET of edge " + fmt_edge(a.et[i].first) + ": a tetrahedron repeated (within or across fans)");
      g.push_back({a.et[i].first, std::move(u)});
      i = j;
    }
    return g;
  };
  auto we = grouped(want, false), ge = grouped(got, true);
  size_t i = 0, j = 0;
  while (i < we.size() || j < ge.size()) {
    if (j == ge.size() || (i < we.size() && we[i].first < ge[j].first)) {
      d.add(tag + "ET: edge " + fmt_edge(we[i].first) + " missing (expected " + fmt_ids(we[i].second) + ")");
      ++i;
    } else if (i == we.size() || ge[j].first < we[i].first) {
      d.add(tag + "ET: unexpected edge " + fmt_edge(ge[j].first) + " " + fmt_ids(ge[j].second));
      ++j;
    } else {
      if (we[i].second != ge[j].second)
        d.add(tag + "ET of edge " + fmt_edge(we[i].first) + ": expected " + fmt_ids(we[i].second) + ", got " +
              fmt_ids(ge[j].second));
      ++i, ++j;
    }
  }

  // Boundary faces (multisets).
  if (want.boundary_faces != got.boundary_faces) {
    std::vector<std::array<uint32_t, 3>> miss, extra;
    std::set_difference(want.boundary_faces.begin(), want.boundary_faces.end(), got.boundary_faces.begin(),
                        got.boundary_faces.end(), std::back_inserter(miss));
    std::set_difference(got.boundary_faces.begin(), got.boundary_faces.end(), want.boundary_faces.begin(),
                        want.boundary_faces.end(), std::back_inserter(extra));
    std::string m = tag + "boundary faces: expected " + std::to_string(want.boundary_faces.size()) + ", got " +
                    std::to_string(got.boundary_faces.size());
    if (!miss.empty()) m += "; missing " + fmt_face(miss[0]) + (miss.size() > 1 ? " and " + std::to_string(miss.size() - 1) + " more" : "");
    if (!extra.empty()) m += "; unexpected " + fmt_face(extra[0]) + (extra.size() > 1 ? " and " + std::to_string(extra.size() - 1) + " more" : "");
    d.add(m);
  }
}

namespace {
// The two tetrahedra across the faces of `t` holding edge (u, w) (per the truth's TT): the
// faces opposite the two vertices of `t` other than u and w.
std::array<uint32_t, 2> around_edge(const TetSoup &s, const Answers &truth, uint32_t t, uint32_t u, uint32_t w) {
  std::array<uint32_t, 2> r{NONE, NONE};
  int k = 0;
  for (int j = 0; j < 4; ++j) {
    uint32_t x = s.tets[4 * t + j];
    if (x != u && x != w) r[k++ & 1] = truth.tt[4 * t + j];
  }
  return r;
}
} // namespace

void check_rotations(const TetSoup &s, const Answers &truth, const Answers &a, Diff &d) {
  if (!a.et_ordered) return;
  const std::string tag = a.side + " rotation: ";
  for (auto &[key, fan] : a.et) {
    uint32_t u = uint32_t(key >> 32), w = uint32_t(key & 0xffffffffu);
    size_t k = fan.size();
    auto bad = [&](const std::string &why) {
      d.add(tag + "edge " + fmt_edge(key) + " " + fmt_ids(fan) + ": " + why);
    };
    if (k == 0) { bad("empty"); continue; }
    std::vector<uint32_t> sorted = fan;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) { bad("a tetrahedron repeated"); continue; }
    bool ok = true;
    for (size_t i = 0; i + 1 < k && ok; ++i) {
      auto nb = around_edge(s, truth, fan[i], u, w);
      if (nb[0] != fan[i + 1] && nb[1] != fan[i + 1]) {
        bad("tetrahedra " + std::to_string(fan[i]) + " and " + std::to_string(fan[i + 1]) +
            " are consecutive but share no face holding the edge");
        ok = false;
      }
    }
    if (!ok) continue;
    auto first = around_edge(s, truth, fan[0], u, w);
    auto last = around_edge(s, truth, fan[k - 1], u, w);
    bool cycle = k >= 3 && (last[0] == fan[0] || last[1] == fan[0]);
    if (cycle) continue;
    int open_first = (first[0] == NONE) + (first[1] == NONE);
    int open_last = (last[0] == NONE) + (last[1] == NONE);
    if (k == 1 ? open_first != 2 : (open_first < 1 || open_last < 1))
      bad("neither a closed cycle nor a chain from boundary to boundary");
  }
}

void compare_rotations(const Answers &a, const Answers &b, Diff &d) {
  if (!a.et_ordered || !b.et_ordered) return;
  const std::string tag = a.side + " vs " + b.side + " rotation: ";
  size_t i = 0, j = 0;
  auto single = [](const std::vector<std::pair<uint64_t, std::vector<uint32_t>>> &v, size_t x) {
    return (x == 0 || v[x - 1].first != v[x].first) && (x + 1 == v.size() || v[x + 1].first != v[x].first);
  };
  while (i < a.et.size() && j < b.et.size()) {
    if (a.et[i].first < b.et[j].first) { ++i; continue; }
    if (b.et[j].first < a.et[i].first) { ++j; continue; }
    if (single(a.et, i) && single(b.et, j)) {
      auto &x = a.et[i].second, &y = b.et[j].second;
      size_t k = x.size();
      bool ok = y.size() == k;
      if (ok && k > 0) {
        size_t p = size_t(std::find(y.begin(), y.end(), x[0]) - y.begin());
        bool fwd = p < k, bwd = p < k;
        for (size_t t = 0; t < k && (fwd || bwd); ++t) {
          if (fwd && x[t] != y[(p + t) % k]) fwd = false;
          if (bwd && x[t] != y[(p + k - t) % k]) bwd = false;
        }
        ok = fwd || bwd;
      }
      if (!ok)
        d.add(tag + "edge " + fmt_edge(a.et[i].first) + ": " + fmt_ids(x) + " vs " + fmt_ids(y) +
              " (not the same cycle up to start and direction)");
    }
    ++i, ++j;
  }
}

} // namespace diffvol
