// CGAL's side of the editing differential test: Surface_mesh with CGAL::Euler's
// flip_edge, split_edge (then split_face on each side, giving topomesh's four triangles),
// collapse_edge after does_satisfy_link_condition, remove_face, and collect_garbage.
#include "cgal_mesh.hpp"
#include "edit_ops.hpp"

#include <CGAL/boost/graph/Euler_operations.h>

#include <algorithm>

namespace diffmesh {
namespace {

using cg::Mesh;
using VI = Mesh::Vertex_index;
using HI = Mesh::Halfedge_index;

class CgalEditor : public EditPeer {
public:
  explicit CgalEditor(const PeerInput &in) {
    PeerBuild b;
    cg::build(in, m_, b, nullptr);
    id_ = m_.add_property_map<VI, uint32_t>("v:shared_id", 0).first;
    for (VI v : m_.vertices()) {
      id_[v] = uint32_t(size_t(v));
      handle_.push_back(v);
    }
  }
  const char *name() const override { return "CGAL"; }

  Outcome apply(const EditOp &op) override {
    HI h = find(op);
    if (h == Mesh::null_halfedge()) return Outcome::Missing;
    switch (op.kind) {
    case OpKind::Flip:
      if (!flip_ok(h)) return Outcome::Refused;
      CGAL::Euler::flip_edge(h, m_);
      return Outcome::Done;
    case OpKind::Split: return split(h, op.fresh);
    case OpKind::Collapse: {
      if (!CGAL::Euler::does_satisfy_link_condition(m_.edge(h), m_)) return Outcome::Refused;
      // CGAL chooses which end stays (usually the target of the edge's half-edge): the one
      // it returns takes a's shared id.
      VI kept = CGAL::Euler::collapse_edge(m_.edge(h), m_);
      id_[kept] = op.a;
      handle_[op.a] = kept;
      return Outcome::Done;
    }
    case OpKind::Remove:
      // Euler::remove_face also removes a vertex left without a face (see counts()).
      CGAL::Euler::remove_face(h, m_);
      return Outcome::Done;
    }
    return Outcome::Missing;
  }

  // Indices change: each shared id finds its vertex again through the property.
  void collect_garbage() override {
    m_.collect_garbage();
    std::fill(handle_.begin(), handle_.end(), Mesh::null_vertex());
    for (VI v : m_.vertices()) handle_[id_[v]] = v;
  }

  EditCounts counts() const override {
    EditCounts c;
    c.vertices = m_.number_of_vertices();
    c.edges = m_.number_of_edges();
    c.faces = m_.number_of_faces();
    for (VI v : m_.vertices())
      if (m_.halfedge(v) == Mesh::null_halfedge()) c.isolated++;
    std::vector<uint8_t> seen(m_.num_halfedges(), 0);
    for (HI h : m_.halfedges()) {
      if (!m_.is_border(h) || seen[size_t(h)]) continue;
      c.boundary_loops++;
      for (HI g = h; !seen[size_t(g)]; g = m_.next(g), c.boundary_edges++) seen[size_t(g)] = 1;
    }
    return c;
  }

  std::vector<Tri> triangles() const override {
    std::vector<Tri> out;
    for (auto f : m_.faces()) {
      HI h = m_.halfedge(f);
      out.push_back(canonical({id_[m_.source(h)], id_[m_.target(h)], id_[m_.target(m_.next(h))]}));
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  std::vector<uint32_t> vertex_ids(bool isolated) const override {
    std::vector<uint32_t> out;
    for (VI v : m_.vertices())
      if ((m_.halfedge(v) == Mesh::null_halfedge()) == isolated) out.push_back(id_[v]);
    std::sort(out.begin(), out.end());
    return out;
  }

private:
  // The half-edge a -> b of face (a, b, c), or the null half-edge.
  HI find(const EditOp &op) const {
    if (std::max({op.a, op.b, op.c}) >= handle_.size()) return Mesh::null_halfedge();
    if (handle_[op.a] == Mesh::null_vertex() || handle_[op.b] == Mesh::null_vertex())
      return Mesh::null_halfedge();
    auto [h, found] = CGAL::halfedge(handle_[op.a], handle_[op.b], m_);
    if (!found || m_.is_border(h) || m_.target(m_.next(h)) != handle_[op.c])
      return Mesh::null_halfedge();
    return h;
  }

  // CGAL leaves the flip's conditions to the caller (flip_edge only asserts that both
  // faces exist): the edge is not on the border, and the new edge c-d is neither a loop
  // nor there already, which are is_flip_ok's rules in OpenMesh and topomesh.
  bool flip_ok(HI h) const {
    HI o = m_.opposite(h);
    if (m_.is_border(o)) return false;
    VI c = m_.target(m_.next(h)), d = m_.target(m_.next(o));
    return c != d && !CGAL::halfedge(c, d, m_).second;
  }

  // split_edge leaves a quadrangle on each side: split_face joins the new vertex to each
  // third vertex, so that a-m-c, m-b-c, m-a-d, b-m-d are the triangles, as topomesh's.
  Outcome split(HI h, uint32_t fresh) {
    if (fresh < handle_.size()) return Outcome::Missing;
    auto mid = CGAL::midpoint(m_.point(m_.source(h)), m_.point(m_.target(h)));
    HI hnew = CGAL::Euler::split_edge(h, m_); // a -> m, followed by h: m -> b
    VI v = m_.target(hnew);
    m_.point(v) = mid;
    id_[v] = fresh;
    handle_.resize(fresh + 1, Mesh::null_vertex());
    handle_[fresh] = v;
    CGAL::Euler::split_face(hnew, m_.next(h), m_);
    HI o = m_.opposite(h), onew = m_.opposite(hnew); // b -> m, m -> a
    if (!m_.is_border(o)) CGAL::Euler::split_face(o, m_.next(onew), m_);
    return Outcome::Done;
  }

  Mesh m_;
  Mesh::Property_map<VI, uint32_t> id_;
  std::vector<VI> handle_; // per shared id
};

} // namespace

std::unique_ptr<EditPeer> cgal_editor(const PeerInput &in) {
  return std::make_unique<CgalEditor>(in);
}

} // namespace diffmesh
