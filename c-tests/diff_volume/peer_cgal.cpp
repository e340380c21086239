// One of the two translation units that include CGAL (slow to compile). See peer_cgal.hpp.
#include "peer_cgal.hpp"

#include "cgal_tr.hpp"

#include <algorithm>
#include <chrono>
#include <unordered_map>

namespace diffvol {

using namespace cgal;

namespace {

double now_ms() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

} // namespace

CgalVol::CgalVol() : p_(new Impl) {}
CgalVol::~CgalVol() = default;

std::unique_ptr<CgalVol> CgalVol::build(const TetSoup &s, CgalStats &st) {
  st = CgalStats();
  st.sizeof_vertex = sizeof(Tr::Vertex);
  st.sizeof_point = sizeof(Tr::Point);
  st.sizeof_cell = sizeof(Tr::Cell);
  std::unique_ptr<CgalVol> out(new CgalVol);
  double t0 = now_ms();
  std::vector<Tr::Point> points;
  points.reserve(s.n_vertices);
  for (size_t v = 0; v < s.n_vertices; ++v)
    points.emplace_back(s.positions[3 * v], s.positions[3 * v + 1], s.positions[3 * v + 2]);
  std::vector<std::array<int, 5>> cells(s.n_tets());
  for (size_t t = 0; t < s.n_tets(); ++t) {
    const uint32_t *q = &s.tets[4 * t];
    std::array<int, 5> c{int(q[0]), int(q[1]), int(q[2]), int(q[3]), 1};
    // The builder wants positively oriented cells.
    if (CGAL::orientation(points[q[0]], points[q[1]], points[q[2]], points[q[3]]) == CGAL::NEGATIVE)
      std::swap(c[1], c[2]);
    cells[t] = c;
  }
  std::map<std::array<int, 3>, int> border_facets;
  double t1 = now_ms();
  bool ok = CGAL::build_triangulation<Tr, true>(out->p_->tr, points, cells, border_facets,
                                                 out->p_->handles, false, false);
  double t2 = now_ms();
  if (!ok) {
    st.refusal = "build_triangulation returned false (a facet or an infinite facet with more than two cells)";
    return nullptr;
  }
  st = out->stats();
  st.convert_ms = t1 - t0;
  st.build_ms = t2 - t0;
  return out;
}

CgalStats CgalVol::stats() const {
  CgalStats st;
  st.ok = true;
  st.sizeof_vertex = sizeof(Tr::Vertex);
  st.sizeof_point = sizeof(Tr::Point);
  st.sizeof_cell = sizeof(Tr::Cell);
  const Tds &tds = p_->tr.tds();
  st.vertices = tds.number_of_vertices();
  st.cells = tds.number_of_cells();
  st.vertex_capacity = tds.vertices().capacity();
  st.cell_capacity = tds.cells().capacity();
  st.finite_cells = p_->tr.number_of_finite_cells();
  return st;
}

namespace {
std::vector<Ch> finite_cell_list(const Tr &tr) {
  std::vector<Ch> live;
  live.reserve(tr.number_of_finite_cells());
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) live.push_back(c);
  return live;
}
} // namespace

EditRun CgalVol::split_storm(uint64_t n, uint64_t seed) {
  Tr &tr = p_->tr;
  std::vector<Ch> live = finite_cell_list(tr);
  live.reserve(live.size() + 3 * n);
  EditRng rng(seed);
  EditRun run;
  double t0 = cpu_ms();
  for (uint64_t i = 0; i < n; ++i) {
    Ch c = live[rng.below(live.size())];
    const auto &a = c->vertex(0)->point(), &b = c->vertex(1)->point(), &d = c->vertex(2)->point(),
               &e = c->vertex(3)->point();
    Tr::Point p(0.25 * (a.x() + b.x() + d.x() + e.x()), 0.25 * (a.y() + b.y() + d.y() + e.y()),
                0.25 * (a.z() + b.z() + d.z() + e.z()));
    tr.insert_in_cell(p, c);
    // The TDS keeps `c` (now holding the new vertex) and puts the three new cells across
    // its faces 1, 2, 3.
    live.push_back(c->neighbor(1));
    live.push_back(c->neighbor(2));
    live.push_back(c->neighbor(3));
    if (i == 0) run.first_ms = cpu_ms() - t0;
  }
  run.ms = cpu_ms() - t0;
  run.attempts = run.accepted = n;
  return run;
}

EditRun CgalVol::flip_storm(uint64_t attempts, uint64_t seed) {
  Tr &tr = p_->tr;
  std::vector<Ch> live = finite_cell_list(tr);
  live.reserve(live.size() + attempts);
  EditRng rng(seed);
  EditRun run;
  double t0 = cpu_ms();
  for (uint64_t i = 0; i < attempts; ++i) {
    FlipPick pk = pick_flip(rng, live.size());
    Ch c = live[pk.k];
    if (pk.flip23) {
      ++run.attempts23;
      if (tr.flip(c, pk.local)) {
        ++run.accepted23;
        // The TDS keeps `c` and its neighbour and links the new cell across c's face
        // (i + 2) mod 4.
        live.push_back(c->neighbor((pk.local + 2) & 3));
      }
    } else {
      ++run.attempts32;
      if (tr.flip(c, kEdgeEnds[pk.local][0], kEdgeEnds[pk.local][1])) {
        ++run.accepted32;
        // The TDS deletes `c` and keeps the other two.
        live[pk.k] = live.back();
        live.pop_back();
      }
    }
    if (i == 0) run.first_ms = cpu_ms() - t0;
  }
  run.ms = cpu_ms() - t0;
  run.attempts = attempts;
  run.accepted = run.accepted23 + run.accepted32;
  return run;
}

Answers CgalVol::answers(const TetSoup &s) const {
  const Tr &tr = p_->tr;
  Answers a;
  a.side = "CGAL";
  a.et_ordered = true;
  // Vertex handle -> input id; cell -> input tetrahedron (by sorted vertex quadruple).
  std::unordered_map<const void *, uint32_t> vid;
  vid.reserve(2 * s.n_vertices);
  for (size_t i = 0; i < s.n_vertices; ++i) vid[&*p_->handles[i + 1]] = uint32_t(i);
  auto id = [&](Vh v) { return vid.at(&*v); };
  std::vector<std::pair<std::array<uint32_t, 4>, uint32_t>> quads(s.n_tets());
  for (size_t t = 0; t < s.n_tets(); ++t) {
    std::array<uint32_t, 4> q{s.tets[4 * t], s.tets[4 * t + 1], s.tets[4 * t + 2], s.tets[4 * t + 3]};
    std::sort(q.begin(), q.end());
    quads[t] = {q, uint32_t(t)};
  }
  std::sort(quads.begin(), quads.end());
  std::unordered_map<const void *, uint32_t> cid;
  cid.reserve(2 * s.n_tets());
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    std::array<uint32_t, 4> q{id(c->vertex(0)), id(c->vertex(1)), id(c->vertex(2)), id(c->vertex(3))};
    std::sort(q.begin(), q.end());
    auto it = std::lower_bound(quads.begin(), quads.end(), std::make_pair(q, uint32_t(0)));
    cid[&*c] = (it != quads.end() && it->first == q) ? it->second : NONE;
  }
  auto cell_id = [&](Ch c) { return tr.is_infinite(c) ? NONE : cid.at(&*c); };

  a.V = long(tr.number_of_vertices());
  a.E = long(tr.number_of_finite_edges());
  a.F = long(tr.number_of_finite_facets());
  a.T = long(tr.number_of_finite_cells());

  // TT per input slot, and boundary faces.
  a.tt.assign(s.tets.size(), NONE);
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    uint32_t t = cid.at(&*c);
    if (t == NONE) continue;
    for (int i = 0; i < 4; ++i) {
      uint32_t x = id(c->vertex(i));
      Ch n = c->neighbor(i);
      for (int j = 0; j < 4; ++j)
        if (s.tets[4 * t + j] == x) a.tt[4 * t + j] = cell_id(n);
      if (tr.is_infinite(n)) {
        std::array<uint32_t, 3> f;
        for (int k = 1; k < 4; ++k) f[k - 1] = id(c->vertex((i + k) % 4));
        std::sort(f.begin(), f.end());
        a.boundary_faces.push_back(f);
      }
    }
  }
  std::sort(a.boundary_faces.begin(), a.boundary_faces.end());

  // VT and VV.
  std::vector<Ch> cs;
  std::vector<Vh> vs;
  std::vector<uint32_t> row;
  for (size_t v = 0; v < s.n_vertices; ++v) {
    Vh h = p_->handles[v + 1];
    cs.clear(), vs.clear();
    if (h->cell() != Ch()) {
      tr.finite_incident_cells(h, std::back_inserter(cs));
      tr.finite_adjacent_vertices(h, std::back_inserter(vs));
    }
    row.clear();
    for (Ch c : cs) row.push_back(cell_id(c));
    std::sort(row.begin(), row.end());
    a.vt.ids.insert(a.vt.ids.end(), row.begin(), row.end());
    a.vt.push_row();
    row.clear();
    for (Vh w : vs) row.push_back(id(w));
    std::sort(row.begin(), row.end());
    a.vv.ids.insert(a.vv.ids.end(), row.begin(), row.end());
    a.vv.push_row();
  }

  // ET: the circulator's order, started just after the infinite cells of a boundary edge.
  std::vector<Ch> ring;
  for (auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    ring.clear();
    auto cc = tr.incident_cells(*e), done = cc;
    do ring.push_back(cc); while (++cc != done);
    size_t k = ring.size(), start = 0;
    for (size_t i = 0; i < k; ++i)
      if (tr.is_infinite(ring[i]) && !tr.is_infinite(ring[(i + 1) % k])) { start = (i + 1) % k; break; }
    std::vector<uint32_t> fan;
    for (size_t i = 0; i < k; ++i) {
      Ch c = ring[(start + i) % k];
      if (!tr.is_infinite(c)) fan.push_back(cell_id(c));
    }
    a.et.push_back({edge_key(id(e->first->vertex(e->second)), id(e->first->vertex(e->third))), std::move(fan)});
  }
  std::sort(a.et.begin(), a.et.end());
  return a;
}

size_t CgalVol::vertex_star_size(uint32_t v) const {
  Vh h = p_->handles[v + 1];
  if (h->cell() == Ch()) return 0;
  std::vector<Ch> cs;
  p_->tr.finite_incident_cells(h, std::back_inserter(cs));
  return cs.size();
}

// Over every finite vertex in a cell: the number of handles `collect(v, out)` writes.
template <class Handle, class Collect>
uint64_t count_around_vertices(const Tr &tr, Collect collect) {
  uint64_t n = 0;
  std::vector<Handle> buf;
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    if (v->cell() == Ch()) continue;
    buf.clear();
    collect(v, std::back_inserter(buf));
    n += buf.size();
  }
  return n;
}

uint64_t CgalVol::sweep_tt() const {
  const Tr &tr = p_->tr;
  uint64_t n = 0;
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    for (int i = 0; i < 4; ++i) n += !tr.is_infinite(c->neighbor(i));
  return n;
}

uint64_t CgalVol::sweep_vt() const {
  const Tr &tr = p_->tr;
  return count_around_vertices<Ch>(tr, [&](Vh v, auto out) { tr.finite_incident_cells(v, out); });
}

uint64_t CgalVol::sweep_et() const {
  const Tr &tr = p_->tr;
  uint64_t n = 0;
  for (auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    auto cc = tr.incident_cells(*e), done = cc;
    do n += !tr.is_infinite(cc); while (++cc != done);
  }
  return n;
}

uint64_t CgalVol::sweep_vv() const {
  const Tr &tr = p_->tr;
  return count_around_vertices<Vh>(tr,
                                   [&](Vh v, auto out) { tr.finite_adjacent_vertices(v, out); });
}

} // namespace diffvol
