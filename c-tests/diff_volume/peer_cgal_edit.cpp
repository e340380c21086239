// The second translation unit that includes CGAL. See peer_cgal_edit.hpp.
#include "peer_cgal_edit.hpp"

#include "cgal_tr.hpp"

#include <unordered_map>

namespace diffvol {

using namespace cgal;

CgalEdit::CgalEdit() = default;
CgalEdit::~CgalEdit() = default;

std::unique_ptr<CgalEdit> CgalEdit::build(const TetSoup &s, std::string &err) {
  CgalStats st;
  std::unique_ptr<CgalEdit> out(new CgalEdit);
  out->vol_ = CgalVol::build(s, st);
  if (!out->vol_) {
    err = st.refusal;
    return nullptr;
  }
  return out;
}

namespace {

// CGAL vertex id -> handle (soup vertex i is handles[i + 1]; handles[0] is the infinite one).
Vh handle(const std::vector<Vh> &handles, uint32_t v) {
  return size_t(v) + 1 < handles.size() ? handles[size_t(v) + 1] : Vh();
}

bool all_handles(const std::vector<Vh> &handles, const uint32_t *ids, int n, Vh *out) {
  for (int k = 0; k < n; ++k)
    if ((out[k] = handle(handles, ids[k])) == Vh()) return false;
  return true;
}

} // namespace

CgalOutcome CgalEdit::split(const Quad &q, const std::array<double, 3> &p, uint32_t &new_v) {
  Tr &tr = vol_->p_->tr;
  Vh v[4];
  Ch c;
  if (!all_handles(vol_->p_->handles, q.data(), 4, v) || !tr.is_cell(v[0], v[1], v[2], v[3], c))
    return CgalOutcome::Missing;
  const Tr::Point pt(p[0], p[1], p[2]);
  Tr::Locate_type lt;
  int li = 0, lj = 0;
  if (tr.side_of_cell(pt, c, lt, li, lj) != CGAL::ON_BOUNDED_SIDE) return CgalOutcome::Refused;
  vol_->p_->handles.push_back(tr.insert_in_cell(pt, c));
  new_v = uint32_t(vol_->p_->handles.size() - 2);
  return CgalOutcome::Done;
}

CgalOutcome CgalEdit::flip_23(const std::array<uint32_t, 3> &f) {
  Tr &tr = vol_->p_->tr;
  Vh v[3];
  Ch c;
  int i = 0, j = 0, k = 0;
  if (!all_handles(vol_->p_->handles, f.data(), 3, v) || !tr.is_facet(v[0], v[1], v[2], c, i, j, k))
    return CgalOutcome::Missing;
  return tr.flip(c, 6 - i - j - k) ? CgalOutcome::Done : CgalOutcome::Refused;
}

CgalOutcome CgalEdit::flip_32(const std::array<uint32_t, 2> &e) {
  Tr &tr = vol_->p_->tr;
  Vh v[2];
  Ch c;
  int i = 0, j = 0;
  if (!all_handles(vol_->p_->handles, e.data(), 2, v) || !tr.is_edge(v[0], v[1], c, i, j))
    return CgalOutcome::Missing;
  return tr.flip(c, i, j) ? CgalOutcome::Done : CgalOutcome::Refused;
}

bool CgalEdit::has_cell(const Quad &q) const {
  Vh v[4];
  Ch c;
  return all_handles(vol_->p_->handles, q.data(), 4, v) && vol_->p_->tr.is_cell(v[0], v[1], v[2], v[3], c);
}

size_t CgalEdit::num_vertices() const { return vol_->p_->tr.number_of_vertices(); }

CgalEdit::Counts CgalEdit::counts() const {
  const Tr &tr = vol_->p_->tr;
  Counts n;
  n.V = long(tr.number_of_vertices());
  n.E = long(tr.number_of_finite_edges());
  n.F = long(tr.number_of_finite_facets());
  n.T = long(tr.number_of_finite_cells());
  return n;
}

std::vector<Quad> CgalEdit::cells() const {
  const Tr &tr = vol_->p_->tr;
  const std::vector<Vh> &h = vol_->p_->handles;
  std::unordered_map<const void *, uint32_t> id;
  id.reserve(2 * h.size());
  for (size_t i = 1; i < h.size(); ++i) id[&*h[i]] = uint32_t(i - 1);
  std::vector<Quad> out;
  out.reserve(tr.number_of_cells());
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    out.push_back({id.at(&*c->vertex(0)), id.at(&*c->vertex(1)), id.at(&*c->vertex(2)), id.at(&*c->vertex(3))});
  return out;
}

std::string CgalEdit::check(size_t &negative) const {
  const Tr &tr = vol_->p_->tr;
  size_t bad_cells = 0, bad_vertices = 0;
  negative = 0;
  for (auto c = tr.tds().cells_begin(); c != tr.tds().cells_end(); ++c) bad_cells += !tr.tds().is_valid(c);
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    bad_vertices += v->cell() != Ch() && !tr.tds().is_valid(v);
  for (auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    negative += tr.orientation(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point(),
                               c->vertex(3)->point()) != CGAL::POSITIVE;
  if (bad_cells + bad_vertices == 0) return std::string();
  return "CGAL: " + std::to_string(bad_cells) + " cells and " + std::to_string(bad_vertices) +
         " vertices fail Tds::is_valid";
}

} // namespace diffvol
