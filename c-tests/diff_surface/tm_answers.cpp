// topomesh through its C API: answers in common ids, self-consistency and view checks.
#include "tm_answers.hpp"

#include "../diff_common/relation_call.hpp"

#include <algorithm>
#include <set>

namespace diffmesh {

std::string str(const std::vector<uint32_t> &v) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) {
    if (i) s += ' ';
    s += v[i] == NONE ? std::string("NONE") : std::to_string(v[i]);
  }
  return s + "]";
}
std::string str(const Pair &p) {
  return "(" + std::to_string(p.first) + "," + std::to_string(p.second) + ")";
}
std::string str(const std::vector<Pair> &v) {
  std::string s = "[";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? " " : "") + str(v[i]);
  return s + "]";
}

std::string last_error() {
  char buf[512];
  size_t len = 0;
  topomesh_last_error(buf, sizeof buf, &len);
  return std::string(buf, std::min(len, sizeof buf));
}

bool relation(RelationFn f, const che_mesh *m, uint32_t id, std::vector<uint32_t> &out) {
  const topomesh_status s = diffcall::call_relation(f, m, id, out, 16);
  if (s != TOPOMESH_STATUS_OK)
    std::printf("ERROR: relation call on id %u: %s (%s)\n", id, topomesh_status_str(s),
                last_error().c_str());
  return s == TOPOMESH_STATUS_OK;
}

namespace {

inline uint32_t nxt(uint32_t h) { return 3 * (h / 3) + (h + 1) % 3; }

// The triangle's corners hold the directed edge a -> b.
bool has_directed(const uint32_t *fv, uint32_t a, uint32_t b) {
  for (int i = 0; i < 3; ++i)
    if (fv[i] == a && fv[(i + 1) % 3] == b) return true;
  return false;
}

} // namespace

Answers topomesh_answers(const che_mesh *m, const std::vector<uint32_t> &vmap,
                         const std::vector<uint32_t> &fmap, size_t n_common_faces,
                         const Sampling &s, Checker &chk) {
  const size_t nv = che_mesh_num_vertices(m), nt = che_mesh_num_triangles(m),
               ne = che_mesh_num_edges(m);
  size_t vlen = 0;
  const uint32_t *V = che_mesh_half_edge_vertices(m, &vlen);
  Answers a;
  a.lib = "topomesh";
  a.resize(vmap.empty() ? nv : *std::max_element(vmap.begin(), vmap.end()) + 1, ne, n_common_faces);
  a.n_vertices = nv;
  a.n_faces = nt;
  if (!V || vlen != 3 * nt) {
    chk.fail("view V", "missing or wrong length");
    return a;
  }
  auto vm = [&](uint32_t v) { return v == NONE ? NONE : vmap[v]; };
  auto fm = [&](uint32_t t) { return t == NONE ? NONE : fmap[t]; };

  // EV (structure ids, canonical direction), fetched once per edge.
  std::vector<std::array<uint32_t, 2>> evc(ne, {NONE, NONE});
  std::vector<uint32_t> buf;
  auto ev = [&](uint32_t e) -> std::array<uint32_t, 2> {
    if (e >= ne) return {NONE, NONE};
    if (evc[e][0] == NONE && relation(che_edge_vertices, m, e, buf)) {
      DIFF_CHECK(chk, buf.size() == 2, "EV size", "edge " + std::to_string(e) + ": " + str(buf));
      if (buf.size() == 2) evc[e] = {buf[0], buf[1]};
    }
    return evc[e];
  };
  auto evpair = [&](uint32_t e) {
    auto x = ev(e);
    return mkpair(vm(x[0]), vm(x[1]));
  };
  auto edge_boundary = [&](uint32_t e) {
    bool b = false;
    if (che_edge_is_boundary(m, e, &b) != TOPOMESH_STATUS_OK) chk.fail("edge_is_boundary", "error");
    return b;
  };

  std::vector<uint32_t> vv, ve, vf;
  for (uint32_t v = 0; v < nv; v += uint32_t(s.vertex_stride)) {
    auto at = [&] { return std::string("v " + std::to_string(v)); };
    if (!relation(che_vertex_vertices, m, v, vv) || !relation(che_vertex_edges, m, v, ve) ||
        !relation(che_vertex_triangles, m, v, vf)) {
      chk.fail("vertex relation", at() + ": " + last_error());
      continue;
    }
    bool bnd = false;
    che_vertex_is_boundary(m, v, &bnd);
    DIFF_CHECK(chk, ve.size() == vv.size(), "VE/VV size", at());
    if (vv.empty()) {
      DIFF_CHECK(chk, vf.empty() && !bnd, "isolated vertex", at() + " VF " + str(vf));
    } else {
      DIFF_CHECK(chk, vv.size() == vf.size() + (bnd ? 1 : 0), "VV/VF size",
                at() + (bnd ? " boundary" : " interior") + " VV " + str(vv) + " VF " + str(vf));
    }
    for (size_t i = 0; i < ve.size() && i < vv.size(); ++i) {
      auto x = ev(ve[i]);
      DIFF_CHECK(chk, mkpair(x[0], x[1]) == mkpair(v, vv[i]), "VE endpoints",
                at() + " edge " + std::to_string(ve[i]) + " is (" + std::to_string(x[0]) + "," +
                    std::to_string(x[1]) + ") not (v," + std::to_string(vv[i]) + ")");
      bool eb = edge_boundary(ve[i]);
      bool end = bnd && (i == 0 || i + 1 == ve.size());
      DIFF_CHECK(chk, eb == end, "VE boundary",
                at() + " edge " + std::to_string(ve[i]) + (eb ? " is" : " is not") + " boundary");
    }
    for (size_t i = 0; i < vf.size() && vv.size() >= 2; ++i) {
      uint32_t t = vf[i];
      if (t >= nt) { chk.fail("VF range", at()); continue; }
      uint32_t w = vv[i], x = vv[(i + 1) % vv.size()];
      DIFF_CHECK(chk, has_directed(V + 3 * t, v, w) && has_directed(V + 3 * t, w, x), "VF order",
                at() + " triangle " + std::to_string(t) + " is not (v," + std::to_string(w) + "," +
                    std::to_string(x) + ")");
    }
    uint32_t c = vm(v);
    a.have_v[c] = 1;
    a.v_boundary[c] = bnd;
    for (size_t i = 0; i < vv.size(); ++i) {
      a.vv[c].push_back(vm(vv[i]));
      a.ve[c].push_back(evpair(ve[i]));
    }
    for (uint32_t t : vf) a.vf[c].push_back(fm(t));
  }

  std::vector<uint32_t> fv, fe, ff;
  for (uint32_t t = 0; t < nt; t += uint32_t(s.face_stride)) {
    auto at = [&] { return std::string("t " + std::to_string(t)); };
    if (!relation(che_triangle_vertices, m, t, fv) || !relation(che_triangle_edges, m, t, fe) ||
        !relation(che_triangle_triangles, m, t, ff) || fv.size() != 3 || fe.size() != 3 ||
        ff.size() != 3) {
      chk.fail("face relation", at());
      continue;
    }
    uint32_t c = fm(t);
    a.have_f[c] = 1;
    for (int i = 0; i < 3; ++i) {
      uint32_t p = fv[i], q = fv[(i + 1) % 3];
      auto x = ev(fe[i]);
      DIFF_CHECK(chk, mkpair(x[0], x[1]) == mkpair(p, q), "FE endpoints", at() + " corner " + std::to_string(i));
      bool eb = edge_boundary(fe[i]);
      DIFF_CHECK(chk, eb == (ff[i] == NONE), "FF boundary", at() + " corner " + std::to_string(i));
      if (ff[i] != NONE)
        DIFF_CHECK(chk, ff[i] < nt && has_directed(V + 3 * ff[i], q, p), "FF edge",
                  at() + " neighbour " + std::to_string(ff[i]) + " lacks " + std::to_string(q) +
                      "->" + std::to_string(p));
      a.fv[c][i] = vm(p);
      a.fe[c][i] = mkpair(vm(p), vm(q));
      a.ff[c][i] = fm(ff[i]);
    }
  }

  std::vector<uint32_t> ef, ee;
  for (uint32_t e = 0; e < ne; e += uint32_t(s.edge_stride)) {
    auto at = [&] { return std::string("e " + std::to_string(e)); };
    auto x = ev(e);
    if (!relation(che_edge_triangles, m, e, ef) || !relation(che_edge_edges, m, e, ee)) {
      chk.fail("edge relation", at());
      continue;
    }
    bool eb = edge_boundary(e);
    DIFF_CHECK(chk, ef.size() == (eb ? 1u : 2u), "EF size", at() + " " + str(ef));
    DIFF_CHECK(chk, ee.size() == 2 * ef.size(), "EE size", at() + " " + str(ee));
    if (ef.empty() || ee.size() != 2 * ef.size()) continue;
    // EF[0] holds the canonical direction a -> b, EF[1] the other; EE: next and previous
    // in EF[0], then in EF[1].
    for (size_t k = 0; k < ef.size(); ++k) {
      uint32_t p = k ? x[1] : x[0], q = k ? x[0] : x[1], t = ef[k];
      if (t >= nt || !has_directed(V + 3 * t, p, q)) {
        chk.fail("EF direction", at() + " triangle " + std::to_string(t));
        continue;
      }
      uint32_t r = V[3 * t] ^ V[3 * t + 1] ^ V[3 * t + 2] ^ p ^ q; // the third corner
      auto n = ev(ee[2 * k]), pv = ev(ee[2 * k + 1]);
      DIFF_CHECK(chk, mkpair(n[0], n[1]) == mkpair(q, r) && mkpair(pv[0], pv[1]) == mkpair(r, p),
                "EE wings", at() + " in triangle " + std::to_string(t) + ": " + str(ee));
    }
    a.have_e[e] = 1;
    a.ev[e] = mkpair(vm(x[0]), vm(x[1]));
    for (uint32_t t : ef) a.ef[e].push_back(fm(t));
    for (uint32_t g : ee) a.ee[e].push_back(evpair(g));
    std::sort(a.ef[e].begin(), a.ef[e].end());
    std::sort(a.ee[e].begin(), a.ee[e].end());
  }

  if (s.curves) {
    a.have_curves = true;
    // Directed boundary half-edges from the views (O exists from level 1).
    size_t olen = 0;
    const uint32_t *O = che_mesh_opposites(m, &olen);
    std::multiset<std::pair<uint32_t, uint32_t>> open;
    if (O)
      for (uint32_t h = 0; h < vlen; ++h)
        if (O[h] == NONE) open.insert({V[h], V[nxt(h)]});
    size_t nc = che_mesh_num_boundary_curves(m), total = 0;
    std::vector<uint32_t> cv;
    for (uint32_t c = 0; c < nc; ++c) {
      if (!relation(che_boundary_curve_vertices, m, c, cv)) {
        chk.fail("curve relation", "curve " + std::to_string(c));
        continue;
      }
      total += cv.size();
      for (size_t i = 0; O && i < cv.size(); ++i) {
        auto it = open.find({cv[i], cv[(i + 1) % cv.size()]});
        if (it == open.end())
          chk.fail("curve step", "curve " + std::to_string(c) + " step " + std::to_string(i) + " " +
                                     std::to_string(cv[i]) + "->" +
                                     std::to_string(cv[(i + 1) % cv.size()]) +
                                     " is not a boundary half-edge (or used twice)");
        else
          open.erase(it);
      }
      std::vector<uint32_t> mapped;
      for (uint32_t v : cv) mapped.push_back(vm(v));
      a.curves.push_back(mapped);
    }
    if (O)
      DIFF_CHECK(chk, open.empty(), "curves cover",
                std::to_string(open.size()) + " boundary half-edges in no curve (" +
                    std::to_string(total) + " visited)");
  }
  return a;
}

void check_views(const che_mesh *m, Checker &chk) {
  const uint32_t level = che_mesh_level(m);
  const size_t nv = che_mesh_num_vertices(m), nt = che_mesh_num_triangles(m),
               ne = che_mesh_num_edges(m), nin = che_mesh_num_input_vertices(m);
  size_t len = 0;
  const uint32_t *V = che_mesh_half_edge_vertices(m, &len);
  if (!V || len != 3 * nt) return chk.fail("view V", "missing or wrong length");
  DIFF_CHECK(chk, che_mesh_num_half_edges(m) == 3 * nt, "num_half_edges", "");
  std::vector<uint32_t> buf;
  for (uint32_t t = 0; t < nt; ++t) {
    relation(che_triangle_vertices, m, t, buf);
    DIFF_CHECK(chk, buf.size() == 3 && buf[0] == V[3 * t] && buf[1] == V[3 * t + 1] && buf[2] == V[3 * t + 2],
              "view V vs FV", "t " + std::to_string(t));
  }
  const uint32_t *O = che_mesh_opposites(m, &len);
  DIFF_CHECK(chk, (O != nullptr) == (level >= 1), "view O presence", "level " + std::to_string(level));
  if (O) {
    DIFF_CHECK(chk, len == 3 * nt, "view O length", std::to_string(len));
    for (uint32_t h = 0; h < 3 * nt; ++h) {
      uint32_t g = O[h];
      if (g == NONE) continue;
      DIFF_CHECK(chk, g < 3 * nt && O[g] == h && V[g] == V[nxt(h)] && V[nxt(g)] == V[h] && g / 3 != h / 3,
                "view O invariant", "h " + std::to_string(h) + " O " + std::to_string(g));
    }
    for (uint32_t t = 0; t < nt; ++t) {
      relation(che_triangle_triangles, m, t, buf);
      for (uint32_t i = 0; i < 3 && buf.size() == 3; ++i) {
        uint32_t g = O[3 * t + i];
        DIFF_CHECK(chk, buf[i] == (g == NONE ? NONE : g / 3), "view O vs FF",
                  "t " + std::to_string(t) + " " + str(buf));
      }
    }
  }
  const uint32_t *VH = che_mesh_vertex_half_edges(m, &len);
  DIFF_CHECK(chk, (VH != nullptr) == (level >= 2), "view VH presence", "level " + std::to_string(level));
  if (VH && O) {
    DIFF_CHECK(chk, len == nv, "view VH length", std::to_string(len));
    std::vector<uint8_t> used(nv, 0), out_boundary(nv, 0);
    for (uint32_t h = 0; h < 3 * nt; ++h) {
      used[V[h]] = 1;
      if (O[h] == NONE) out_boundary[V[h]] = 1;
    }
    for (uint32_t v = 0; v < nv && len == nv; ++v) {
      uint32_t h = VH[v];
      bool bnd = false;
      che_vertex_is_boundary(m, v, &bnd);
      auto at = [&] { return std::string("v " + std::to_string(v)); };
      if (h == NONE) {
        DIFF_CHECK(chk, !used[v] && !bnd, "view VH isolated", at());
        continue;
      }
      DIFF_CHECK(chk, h < 3 * nt && V[h] == v, "view VH origin", at());
      DIFF_CHECK(chk, (O[h] == NONE) == bool(out_boundary[v]), "view VH boundary rule", at());
      DIFF_CHECK(chk, bnd == (O[h] == NONE), "vertex_is_boundary vs VH", at());
    }
  }
  const uint32_t *EH = che_mesh_edge_half_edges(m, &len);
  DIFF_CHECK(chk, (EH != nullptr) == (level >= 2), "view EH presence", "level " + std::to_string(level));
  if (EH && O) {
    DIFF_CHECK(chk, len == ne, "view EH length", std::to_string(len));
    uint32_t prev = 0;
    for (uint32_t e = 0; e < ne && len == ne; ++e) {
      uint32_t h = EH[e];
      auto at = [&] { return std::string("e " + std::to_string(e)); };
      DIFF_CHECK(chk, h < 3 * nt && (O[h] == NONE || h < O[h]) && (e == 0 || h > prev), "view EH canonical", at());
      prev = h;
      relation(che_edge_vertices, m, e, buf);
      DIFF_CHECK(chk, buf.size() == 2 && buf[0] == V[h] && buf[1] == V[nxt(h)], "view EH vs EV", at());
    }
    size_t canonical = 0;
    for (uint32_t h = 0; h < 3 * nt; ++h) canonical += (O[h] == NONE || h < O[h]);
    DIFF_CHECK(chk, canonical == ne, "edge count", std::to_string(canonical) + " canonical half-edges, " +
                                                 std::to_string(ne) + " edges");
  }
  const uint32_t *CH = che_mesh_curve_half_edges(m, &len);
  DIFF_CHECK(chk, (CH != nullptr) == (level >= 3), "view CH presence", "level " + std::to_string(level));
  if (CH && O) {
    DIFF_CHECK(chk, len == che_mesh_num_boundary_curves(m), "view CH length", std::to_string(len));
    for (size_t c = 0; c < len; ++c) DIFF_CHECK(chk, O[CH[c]] == NONE, "view CH boundary", std::to_string(c));
  }
  const uint32_t *VO = che_mesh_vertex_origins(m, &len);
  DIFF_CHECK(chk, VO && len == nv, "view vertex origins", std::to_string(len));
  for (uint32_t v = 0; VO && v < len; ++v)
    DIFF_CHECK(chk, v < nin ? VO[v] == v : VO[v] < nin, "vertex origin", "v " + std::to_string(v));
  const uint32_t *TO = che_mesh_triangle_origins(m, &len);
  DIFF_CHECK(chk, TO && len == nt, "view triangle origins", std::to_string(len));
  for (uint32_t t = 1; TO && t < len; ++t)
    DIFF_CHECK(chk, TO[t] > TO[t - 1], "triangle origins increasing", "t " + std::to_string(t));
}

} // namespace diffmesh
