// OpenMesh's side of the editing differential test: TriMesh's is_flip_ok / flip,
// split (the 2-to-4 edge split), is_collapse_ok / collapse, delete_face and
// garbage_collection, on the operations of edit_ops.hpp.
#include "edit_ops.hpp"
#include "om_mesh.hpp"

#include <algorithm>

namespace diffmesh {
namespace {

using om::Mesh;
using VH = OpenMesh::VertexHandle;
using HH = OpenMesh::HalfedgeHandle;

class OpenMeshEditor : public EditPeer {
public:
  explicit OpenMeshEditor(const PeerInput &in) {
    om::build_editable(in, m_);
    m_.add_property(id_);
    for (auto v : m_.vertices()) {
      m_.property(id_, v) = uint32_t(v.idx());
      handle_.push_back(v);
    }
  }
  const char *name() const override { return "OpenMesh"; }

  Outcome apply(const EditOp &op) override {
    HH h = find(op);
    if (!h.is_valid()) return Outcome::Missing;
    switch (op.kind) {
    case OpKind::Flip:
      if (!m_.is_flip_ok(m_.edge_handle(h))) return Outcome::Refused;
      m_.flip(m_.edge_handle(h));
      return Outcome::Done;
    case OpKind::Split: return split(h, op.fresh);
    case OpKind::Collapse: {
      // OpenMesh removes the origin of the half-edge it collapses: b -> a keeps a.
      HH ba = m_.opposite_halfedge_handle(h);
      if (!m_.is_collapse_ok(ba)) return Outcome::Refused;
      m_.collapse(ba);
      return Outcome::Done;
    }
    case OpKind::Remove:
      // Vertices left without a face stay, as topomesh's.
      m_.delete_face(m_.face_handle(h), false);
      return Outcome::Done;
    }
    return Outcome::Missing;
  }

  // Handles change: each shared id finds its vertex again through the property.
  void collect_garbage() override {
    m_.garbage_collection();
    std::fill(handle_.begin(), handle_.end(), VH());
    for (auto v : m_.vertices()) handle_[m_.property(id_, v)] = v;
  }

  EditCounts counts() const override {
    EditCounts c;
    for (auto v : m_.vertices()) {
      c.vertices++;
      if (!m_.halfedge_handle(v).is_valid()) c.isolated++;
    }
    for (auto e : m_.edges()) (void)e, c.edges++;
    for (auto f : m_.faces()) (void)f, c.faces++;
    std::vector<uint8_t> seen(m_.n_halfedges(), 0);
    for (auto h : m_.halfedges()) {
      if (!m_.is_boundary(h) || seen[size_t(h.idx())]) continue;
      c.boundary_loops++;
      for (HH g = h; !seen[size_t(g.idx())]; g = m_.next_halfedge_handle(g), c.boundary_edges++)
        seen[size_t(g.idx())] = 1;
    }
    return c;
  }

  std::vector<Tri> triangles() const override {
    std::vector<Tri> out;
    for (auto f : m_.faces()) {
      Tri t{};
      int k = 0;
      for (auto it = m_.cfv_ccwiter(f); it.is_valid() && k < 3; ++it)
        t[k++] = m_.property(id_, *it);
      out.push_back(canonical(t));
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  std::vector<uint32_t> vertex_ids(bool isolated) const override {
    std::vector<uint32_t> out;
    for (auto v : m_.vertices())
      if (m_.halfedge_handle(v).is_valid() != isolated) out.push_back(m_.property(id_, v));
    std::sort(out.begin(), out.end());
    return out;
  }

private:
  // The half-edge a -> b of face (a, b, c), or an invalid handle.
  HH find(const EditOp &op) const {
    if (std::max({op.a, op.b, op.c}) >= handle_.size()) return HH();
    if (!handle_[op.a].is_valid() || !handle_[op.b].is_valid()) return HH();
    HH h = m_.find_halfedge(handle_[op.a], handle_[op.b]);
    if (!h.is_valid() || m_.is_boundary(h)) return HH();
    if (m_.to_vertex_handle(m_.next_halfedge_handle(h)) != handle_[op.c]) return HH();
    return h;
  }

  Outcome split(HH h, uint32_t fresh) {
    if (fresh < handle_.size()) return Outcome::Missing;
    auto a = m_.from_vertex_handle(h), b = m_.to_vertex_handle(h);
    VH v = m_.add_vertex((m_.point(a) + m_.point(b)) / 2);
    m_.property(id_, v) = fresh;
    handle_.resize(fresh + 1);
    handle_[fresh] = v;
    m_.split(m_.edge_handle(h), v);
    return Outcome::Done;
  }

  Mesh m_;
  OpenMesh::VPropHandleT<uint32_t> id_;
  std::vector<VH> handle_; // per shared id
};

} // namespace

std::unique_ptr<EditPeer> openmesh_editor(const PeerInput &in) {
  return std::make_unique<OpenMeshEditor>(in);
}

} // namespace diffmesh
