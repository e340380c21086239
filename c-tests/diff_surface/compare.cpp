// Element-by-element comparison of two libraries' answers in common ids.
#include "compare.hpp"

#include <map>
#include <unordered_map>

namespace diffmesh {

namespace {
struct PairHash {
  size_t operator()(const Pair &p) const { return std::hash<uint64_t>()(uint64_t(p.first) << 32 | p.second); }
};
std::string fstr(const std::array<uint32_t, 3> &a) { return str(std::vector<uint32_t>(a.begin(), a.end())); }
std::string fstr(const std::array<Pair, 3> &a) { return str(std::vector<Pair>(a.begin(), a.end())); }
} // namespace

void compare(const Answers &a, const Answers &b, Checker &chk) {
  const std::string vs = " " + a.lib + " vs " + b.lib;
  auto both = [&](const std::string &what, auto x, auto y) {
    return what + ": " + a.lib + " " + x + ", " + b.lib + " " + y;
  };
  DIFF_CHECK(chk, a.n_vertices == b.n_vertices, "vertex count" + vs,
            both("", std::to_string(a.n_vertices), std::to_string(b.n_vertices)));
  DIFF_CHECK(chk, a.n_edges == b.n_edges, "edge count" + vs,
            both("", std::to_string(a.n_edges), std::to_string(b.n_edges)));
  DIFF_CHECK(chk, a.n_faces == b.n_faces, "face count" + vs,
            both("", std::to_string(a.n_faces), std::to_string(b.n_faces)));
  DIFF_CHECK(chk, a.euler() == b.euler(), "Euler characteristic" + vs,
            both("", std::to_string(a.euler()), std::to_string(b.euler())));

  size_t nv = std::min(a.have_v.size(), b.have_v.size());
  for (size_t v = 0; v < nv; ++v) {
    if (!a.have_v[v] || !b.have_v[v]) continue;
    auto at = [&] { return std::string("v " + std::to_string(v)); };
    DIFF_CHECK(chk, same_cycle(a.vv[v], b.vv[v]), "VV" + vs, both(at(), str(a.vv[v]), str(b.vv[v])));
    DIFF_CHECK(chk, same_cycle(a.ve[v], b.ve[v]), "VE" + vs, both(at(), str(a.ve[v]), str(b.ve[v])));
    DIFF_CHECK(chk, same_cycle(a.vf[v], b.vf[v]), "VF" + vs, both(at(), str(a.vf[v]), str(b.vf[v])));
    DIFF_CHECK(chk, a.v_boundary[v] == b.v_boundary[v], "vertex boundary" + vs,
              both(at(), std::to_string(a.v_boundary[v]), std::to_string(b.v_boundary[v])));
  }

  size_t nf = std::min(a.have_f.size(), b.have_f.size());
  for (size_t f = 0; f < nf; ++f) {
    if (!a.have_f[f] || !b.have_f[f]) continue;
    auto at = [&] { return std::string("face " + std::to_string(f)); };
    int r = -1;
    for (int k = 0; k < 3 && r < 0; ++k)
      if (a.fv[f][0] == b.fv[f][k] && a.fv[f][1] == b.fv[f][(k + 1) % 3] && a.fv[f][2] == b.fv[f][(k + 2) % 3])
        r = k;
    if (r < 0) {
      chk.fail("FV" + vs, both(at(), fstr(a.fv[f]), fstr(b.fv[f])));
      continue;
    }
    bool ff = true, fe = true;
    for (int i = 0; i < 3; ++i) {
      ff &= a.ff[f][i] == b.ff[f][(i + r) % 3];
      fe &= a.fe[f][i] == b.fe[f][(i + r) % 3];
    }
    DIFF_CHECK(chk, ff, "FF" + vs, both(at(), fstr(a.ff[f]), fstr(b.ff[f])) + " (FV " + fstr(a.fv[f]) + ")");
    DIFF_CHECK(chk, fe, "FE" + vs, both(at(), fstr(a.fe[f]), fstr(b.fe[f])));
  }
  for (size_t f = nf; f < a.have_f.size(); ++f) DIFF_CHECK(chk, !a.have_f[f], "face range" + vs, std::to_string(f));

  // Edges by vertex pair.
  std::unordered_map<Pair, size_t, PairHash> bi;
  bi.reserve(b.ev.size() * 2);
  for (size_t e = 0; e < b.ev.size(); ++e)
    if (b.have_e[e] && !bi.emplace(b.ev[e], e).second)
      chk.fail("duplicate edge in " + b.lib, str(b.ev[e]));
  std::unordered_map<Pair, size_t, PairHash> seen;
  for (size_t e = 0; e < a.ev.size(); ++e) {
    if (!a.have_e[e]) continue;
    auto at = [&] { return std::string("edge " + std::to_string(e) + " " + str(a.ev[e])); };
    if (!seen.emplace(a.ev[e], e).second) {
      chk.fail("duplicate edge in " + a.lib, at());
      continue;
    }
    auto it = bi.find(a.ev[e]);
    if (it == bi.end()) {
      chk.fail("EV" + vs, at() + " not in " + b.lib);
      continue;
    }
    size_t g = it->second;
    DIFF_CHECK(chk, a.ef[e] == b.ef[g], "EF" + vs, both(at(), str(a.ef[e]), str(b.ef[g])));
    DIFF_CHECK(chk, a.ee[e] == b.ee[g], "EE" + vs, both(at(), str(a.ee[e]), str(b.ee[g])));
  }

  if (a.have_curves && b.have_curves) {
    auto canon = [](const std::vector<std::vector<uint32_t>> &cs) {
      std::vector<std::vector<uint32_t>> out;
      for (auto &c : cs) out.push_back(canonical_cycle(c));
      std::sort(out.begin(), out.end());
      return out;
    };
    auto ca = canon(a.curves), cb = canon(b.curves);
    DIFF_CHECK(chk, ca.size() == cb.size(), "boundary curve count" + vs,
              both("", std::to_string(ca.size()), std::to_string(cb.size())));
    for (size_t i = 0; i < std::min(ca.size(), cb.size()); ++i)
      DIFF_CHECK(chk, ca[i] == cb[i], "boundary curve" + vs,
                both("curve " + std::to_string(i), str(ca[i]).substr(0, 300), str(cb[i]).substr(0, 300)));
  }
}

} // namespace diffmesh
