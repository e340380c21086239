// topomesh's answers through the C API (see tm_vol.hpp).
#include "tm_vol.hpp"

#include "../diff_common/relation_call.hpp"

#include <algorithm>

namespace diffvol {

namespace {

std::string last_error(topomesh_status st) {
  char buf[512];
  size_t len = 0;
  std::string detail;
  if (topomesh_last_error(buf, sizeof buf, &len) == TOPOMESH_STATUS_OK) detail.assign(buf, std::min(len, sizeof buf));
  return std::string(topomesh_status_str(st)) + (detail.empty() ? "" : ": " + detail);
}

using Relation = topomesh_status (*)(const chf_mesh *, uint32_t, uint32_t *, size_t, size_t *);

// One per-element call into `out`, growing the buffer on BUFFER_TOO_SMALL.
bool call(Relation f, const chf_mesh *m, uint32_t id, std::vector<uint32_t> &out, Diff &d, const char *name) {
  const topomesh_status st = diffcall::call_relation(f, m, id, out, 64);
  if (st != TOPOMESH_STATUS_OK)
    d.add(std::string(name) + "(" + std::to_string(id) + ") failed: " + last_error(st));
  return st == TOPOMESH_STATUS_OK;
}

using CsrCall = topomesh_status (*)(const chf_mesh *, uint32_t *, size_t, uint32_t *, size_t, size_t *, size_t *);

// A bulk call (size query, then the fill).
bool csr(CsrCall f, const chf_mesh *m, Rows &r, Diff &d, const char *name) {
  size_t no = 0, ni = 0;
  topomesh_status st = f(m, nullptr, 0, nullptr, 0, &no, &ni);
  if (st != TOPOMESH_STATUS_OK) {
    d.add(std::string(name) + " size query failed: " + last_error(st));
    return false;
  }
  r.offsets.assign(no, 0);
  r.ids.assign(ni, 0);
  st = f(m, r.offsets.data(), no, r.ids.data(), ni, &no, &ni);
  if (st != TOPOMESH_STATUS_OK) {
    d.add(std::string(name) + " failed: " + last_error(st));
    return false;
  }
  return true;
}

void same_row(const Rows &bulk, size_t i, const std::vector<uint32_t> &one, Diff &d, const char *name) {
  if (i + 1 >= bulk.offsets.size() || !std::equal(bulk.begin(i), bulk.end(i), one.begin(), one.end()))
    d.add(std::string(name) + " row " + std::to_string(i) + " differs from the per-element call");
}

} // namespace

std::string tm_error(topomesh_status st) { return last_error(st); }

bool tm_build(const TetSoup &s, uint32_t level, TmMesh &out, std::string &err) {
  chf_mesh_free(out.m);
  out.m = nullptr;
  topomesh_status st = chf_mesh_from_tetrahedra(s.tets.data(), s.n_tets(), s.n_vertices,
                                                s.positions.empty() ? nullptr : s.positions.data(), level, &out.m);
  if (st != TOPOMESH_STATUS_OK) {
    err = last_error(st);
    return false;
  }
  return true;
}

namespace {
// Per-element calls below level 2 cost O(T) each (the core recomputes the missing tables):
// there they are made for a sample (the first 8 ids and about 16 spread out) and checked
// against the bulk rows, which are O(T) at every level.
bool sampled(uint32_t id, size_t n, uint32_t level) {
  if (level >= 2 || id < 8) return true;
  size_t stride = n / 16 + 1;
  return id % stride == 0;
}
} // namespace

Answers tm_answers(const TetSoup &s, chf_mesh *m, const std::string &side, Diff &in) {
  Answers a;
  a.side = side;
  a.et_ordered = true;
  const uint32_t level = chf_mesh_level(m);
  const size_t nv = chf_mesh_num_vertices(m), nt = chf_mesh_num_tetrahedra(m);
  const size_t ne = chf_mesh_num_edges(m), nf = chf_mesh_num_faces(m);
  size_t len = 0;
  const uint32_t *vo = chf_mesh_vertex_origins(m, &len);
  if (!vo || len != nv) { in.add("chf_mesh_vertex_origins: NULL or wrong length"); return a; }
  const uint32_t *to = chf_mesh_tetrahedron_origins(m, &len);
  if (!to || len != nt) { in.add("chf_mesh_tetrahedron_origins: NULL or wrong length"); return a; }
  auto in_t = [&](uint32_t t) { return t == NONE ? NONE : (t < nt ? to[t] : NONE - 1); };
  auto in_v = [&](uint32_t v) { return v < nv ? vo[v] : NONE - 1; };

  chf_summary sum{};
  topomesh_status st = chf_mesh_summary(m, &sum);
  if (st != TOPOMESH_STATUS_OK) in.add("chf_mesh_summary failed: " + last_error(st));
  a.V = long(sum.vertices), a.E = long(sum.edges), a.F = long(sum.faces), a.T = long(sum.tetrahedra);
  if (sum.euler_characteristic != a.euler())
    in.add("summary: euler_characteristic " + std::to_string(sum.euler_characteristic) + " != V - E + F - T = " +
           std::to_string(a.euler()));

  std::vector<uint32_t> buf, tv;

  // TV, TT (O(1) from level 1: every tetrahedron); the zero-copy V and O views; the TT bulk
  // call. Boundary faces from TT's NONE slots (below level 2; from level 2 the face calls
  // below must agree with them).
  const uint32_t *V = chf_mesh_half_face_vertices(m, &len);
  if (!V || len != 4 * nt) in.add("chf_mesh_half_face_vertices: NULL or wrong length"), V = nullptr;
  size_t olen = 0;
  const uint32_t *O = chf_mesh_opposites(m, &olen);
  if (level >= 1 && (!O || olen != 4 * nt)) in.add("chf_mesh_opposites: NULL or wrong length at level >= 1"), O = nullptr;
  Rows tt_bulk;
  csr(chf_mesh_tetrahedron_tetrahedra_csr, m, tt_bulk, in, "chf_mesh_tetrahedron_tetrahedra_csr");
  a.tt.assign(s.tets.size(), NONE);
  std::vector<std::array<uint32_t, 3>> tt_boundary;
  for (uint32_t t = 0; t < nt; ++t) {
    if (!call(chf_tetrahedron_vertices, m, t, tv, in, "chf_tetrahedron_vertices")) continue;
    if (!call(chf_tetrahedron_tetrahedra, m, t, buf, in, "chf_tetrahedron_tetrahedra")) continue;
    if (tv.size() != 4 || buf.size() != 4) { in.add("TV or TT of " + std::to_string(t) + " not 4 entries"); continue; }
    same_row(tt_bulk, t, buf, in, "chf_mesh_tetrahedron_tetrahedra_csr");
    uint32_t T = to[t];
    std::array<uint32_t, 4> mapped, input;
    for (int i = 0; i < 4; ++i) {
      if (V && V[4 * t + i] != tv[i]) in.add("V view differs from TV at tetrahedron " + std::to_string(t));
      if (O) {
        uint32_t o = O[4 * t + i];
        uint32_t want = o == NONE ? NONE : o / 4;
        if (want != buf[i]) in.add("O view differs from TT at half-face " + std::to_string(4 * t + i));
        if (o != NONE && (o >= 4 * nt || O[o] != 4 * t + i)) in.add("O is not an involution at half-face " + std::to_string(4 * t + i));
      }
      mapped[i] = in_v(tv[i]);
      input[i] = s.tets[4 * T + i];
    }
    auto ms = mapped, is = input;
    std::sort(ms.begin(), ms.end()), std::sort(is.begin(), is.end());
    if (ms != is) { in.add("TV of " + std::to_string(t) + " is not input tetrahedron " + std::to_string(T)); continue; }
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j)
        if (input[j] == mapped[i]) a.tt[4 * T + j] = in_t(buf[i]);
      if (buf[i] == NONE) {
        std::array<uint32_t, 3> f;
        for (int k = 1; k < 4; ++k) f[k - 1] = mapped[(i + k) % 4];
        std::sort(f.begin(), f.end());
        tt_boundary.push_back(f);
      }
    }
  }
  std::sort(tt_boundary.begin(), tt_boundary.end());

  // VT and VV: the bulk rows (per structure vertex) merged into input vertices; the
  // per-element calls must give the same rows.
  const size_t ninput = s.n_vertices;
  std::vector<std::vector<uint32_t>> vt(ninput), vv(ninput);
  Rows vt_bulk, vv_bulk;
  bool vt_ok = csr(chf_mesh_vertex_tetrahedra_csr, m, vt_bulk, in, "chf_mesh_vertex_tetrahedra_csr");
  bool vv_ok = csr(chf_mesh_vertex_vertices_csr, m, vv_bulk, in, "chf_mesh_vertex_vertices_csr");
  if ((vt_ok && vt_bulk.size() != nv) || (vv_ok && vv_bulk.size() != nv)) {
    in.add("vertex CSR: wrong number of rows");
    vt_ok = vv_ok = false;
  }
  for (uint32_t v = 0; v < nv; ++v) {
    uint32_t x = vo[v];
    if (x >= ninput) { in.add("vertex origin out of range at " + std::to_string(v)); continue; }
    if (sampled(v, nv, level)) {
      if (call(chf_vertex_tetrahedra, m, v, buf, in, "chf_vertex_tetrahedra") && vt_ok)
        same_row(vt_bulk, v, buf, in, "chf_mesh_vertex_tetrahedra_csr");
      if (call(chf_vertex_vertices, m, v, buf, in, "chf_vertex_vertices") && vv_ok)
        same_row(vv_bulk, v, buf, in, "chf_mesh_vertex_vertices_csr");
    }
    if (vt_ok)
      for (const uint32_t *p = vt_bulk.begin(v); p != vt_bulk.end(v); ++p) vt[x].push_back(in_t(*p));
    if (vv_ok) {
      std::vector<uint32_t> sorted(vv_bulk.begin(v), vv_bulk.end(v));
      std::sort(sorted.begin(), sorted.end());
      if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end() ||
          std::binary_search(sorted.begin(), sorted.end(), v))
        in.add("VV of structure vertex " + std::to_string(v) + " repeats a vertex or holds itself");
      for (uint32_t w : sorted) vv[x].push_back(in_v(w));
    }
  }
  for (size_t x = 0; x < ninput; ++x) {
    std::sort(vt[x].begin(), vt[x].end()); // repeats stay: compare() then reports them
    a.vt.ids.insert(a.vt.ids.end(), vt[x].begin(), vt[x].end());
    a.vt.push_row();
    std::sort(vv[x].begin(), vv[x].end());
    vv[x].erase(std::unique(vv[x].begin(), vv[x].end()), vv[x].end());
    a.vv.ids.insert(a.vv.ids.end(), vv[x].begin(), vv[x].end());
    a.vv.push_row();
  }

  // ET: the bulk rows in rotation order (one entry per edge id); the per-element calls must
  // agree. EV (O(T) per call below level 2) for a sample; then, below level 2, the level is
  // raised in place to 2 (ids do not change) for the EV of every edge.
  Rows et_bulk;
  bool et_ok = csr(chf_mesh_edge_tetrahedra_csr, m, et_bulk, in, "chf_mesh_edge_tetrahedra_csr");
  if (et_ok && et_bulk.size() != ne) { in.add("chf_mesh_edge_tetrahedra_csr: wrong number of rows"); et_ok = false; }
  std::vector<uint64_t> keys(ne, ~uint64_t(0));
  std::vector<uint32_t> ev;
  for (uint32_t e = 0; e < ne; ++e) {
    if (!sampled(e, ne, level)) continue;
    if (call(chf_edge_tetrahedra, m, e, buf, in, "chf_edge_tetrahedra") && et_ok)
      same_row(et_bulk, e, buf, in, "chf_mesh_edge_tetrahedra_csr");
    if (call(chf_edge_vertices, m, e, ev, in, "chf_edge_vertices") && ev.size() == 2)
      keys[e] = edge_key(in_v(ev[0]), in_v(ev[1]));
  }
  if (level < 2) {
    st = chf_mesh_build_level(m, 2);
    if (st != TOPOMESH_STATUS_OK) in.add("chf_mesh_build_level(2) failed: " + last_error(st));
    for (uint32_t e = 0; e < ne && st == TOPOMESH_STATUS_OK; ++e)
      if (call(chf_edge_vertices, m, e, ev, in, "chf_edge_vertices (after build_level 2)") && ev.size() == 2) {
        uint64_t k = edge_key(in_v(ev[0]), in_v(ev[1]));
        if (keys[e] != ~uint64_t(0) && keys[e] != k) in.add("EV of edge " + std::to_string(e) + " changed with the level");
        keys[e] = k;
      }
  }
  for (uint32_t e = 0; e < ne && et_ok; ++e) {
    std::vector<uint32_t> fan;
    for (const uint32_t *p = et_bulk.begin(e); p != et_bulk.end(e); ++p) fan.push_back(in_t(*p));
    a.et.push_back({keys[e], std::move(fan)});
  }
  std::stable_sort(a.et.begin(), a.et.end(), [](auto &x, auto &y) { return x.first < y.first; });

  // Boundary faces: from TT's NONE slots; from level 2 also the faces chf_face_is_boundary
  // names (one per unpaired half-face), which must be the same.
  a.boundary_faces = tt_boundary;
  if (chf_mesh_level(m) >= 2 && level >= 2) {
    std::vector<std::array<uint32_t, 3>> by_face;
    for (uint32_t f = 0; f < nf; ++f) {
      bool b = false;
      st = chf_face_is_boundary(m, f, &b);
      if (st != TOPOMESH_STATUS_OK) { in.add("chf_face_is_boundary failed: " + last_error(st)); continue; }
      if (!b) continue;
      if (!call(chf_face_vertices, m, f, buf, in, "chf_face_vertices") || buf.size() != 3) continue;
      std::array<uint32_t, 3> tri{in_v(buf[0]), in_v(buf[1]), in_v(buf[2])};
      std::sort(tri.begin(), tri.end());
      by_face.push_back(tri);
    }
    std::sort(by_face.begin(), by_face.end());
    if (by_face != tt_boundary)
      in.add("boundary faces from chf_face_is_boundary/chf_face_vertices (" + std::to_string(by_face.size()) +
             ") differ from TT's NONE slots (" + std::to_string(tt_boundary.size()) + ")");
  }
  // Unpaired half-faces are the boundary surface's triangles; the faces with one
  // tetrahedron leave out the non-manifold and seam half-faces.
  if (a.boundary_faces.size() != chf_mesh_num_boundary_triangles(m))
    in.add("chf_mesh_num_boundary_triangles = " + std::to_string(chf_mesh_num_boundary_triangles(m)) + ", but " +
           std::to_string(a.boundary_faces.size()) + " unpaired half-faces");
  if (chf_mesh_num_boundary_faces(m) + chf_mesh_num_non_manifold_half_faces(m) + chf_mesh_num_seam_half_faces(m) !=
      a.boundary_faces.size())
    in.add("chf_mesh_num_boundary_faces + non-manifold + seam half-faces = " +
           std::to_string(chf_mesh_num_boundary_faces(m) + chf_mesh_num_non_manifold_half_faces(m) +
                          chf_mesh_num_seam_half_faces(m)) +
           ", but " + std::to_string(a.boundary_faces.size()) + " unpaired half-faces");
  return a;
}

void corrupt_for_selftest(Answers &a) {
  if (!a.tt.empty()) a.tt[a.tt.size() / 2] ^= 1;
  if (a.vt.ids.size() > 1) a.vt.ids[a.vt.ids.size() / 3] += 1;
  if (!a.et.empty() && a.et[a.et.size() / 2].second.size() >= 4)
    std::swap(a.et[a.et.size() / 2].second[0], a.et[a.et.size() / 2].second[1]);
  if (!a.boundary_faces.empty()) a.boundary_faces.pop_back();
}

} // namespace diffvol
