// OpenMesh 9 (TriMesh_ArrayKernelT with double points): differential answers and benchmark.
#include "om_mesh.hpp"

#include <OpenMesh/Core/System/omstream.hh>

namespace diffmesh {

void om::build(const PeerInput &in, Mesh &m, PeerBuild &b, std::vector<uint32_t> *face_input) {
  static bool quiet = (::omerr().disable(), true); // "complex edge" etc.
  (void)quiet;
  m.reserve(in.n_vertices, in.n_triangles * 3 / 2 + 16, in.n_triangles);
  for (size_t v = 0; v < in.n_vertices; ++v) {
    const double *p = in.positions + 3 * v;
    auto h = m.add_vertex(Mesh::Point(p[0], p[1], p[2]));
    if ((size_t)h.idx() != v) b.vertices_in_order = false;
  }
  add_triangles(in, b, face_input, [&](const uint32_t *c) {
    return m.add_face(OpenMesh::VertexHandle(int(c[0])), OpenMesh::VertexHandle(int(c[1])),
                      OpenMesh::VertexHandle(int(c[2])))
        .is_valid();
  });
}

namespace {
using om::Mesh;

uint32_t vid(OpenMesh::VertexHandle h) { return uint32_t(h.idx()); }

// The adapter of peers.hpp.
struct Peer {
  using Mesh = om::Mesh;
  static void build(const PeerInput &in, Mesh &m, PeerBuild &b, std::vector<uint32_t> *fin) {
    om::build(in, m, b, fin);
  }
  using H = OpenMesh::HalfedgeHandle;
  static auto halfedges(const Mesh &m) { return m.halfedges(); }
  static size_t index(OpenMesh::HalfedgeHandle h) { return size_t(h.idx()); }
  static bool border(const Mesh &m, OpenMesh::HalfedgeHandle h) { return m.is_boundary(h); }
  static uint32_t source(const Mesh &m, OpenMesh::HalfedgeHandle h) {
    return vid(m.from_vertex_handle(h));
  }
  static OpenMesh::HalfedgeHandle next(const Mesh &m, OpenMesh::HalfedgeHandle h) {
    return m.next_halfedge_handle(h);
  }
  static size_t n_halfedges(const Mesh &m) { return m.n_halfedges(); }
  template <class F> static void each_vv(const Mesh &m, F f) {
    for (auto v : m.vertices())
      for (auto it = m.cvv_iter(v); it.is_valid(); ++it) f(v.idx(), it->idx());
  }
  template <class F> static void each_vf(const Mesh &m, F f) {
    for (auto v : m.vertices())
      for (auto it = m.cvf_iter(v); it.is_valid(); ++it) f(v.idx(), it->idx());
  }
  template <class F> static void each_ff(const Mesh &m, F f) {
    for (auto g : m.faces())
      for (auto it = m.cff_iter(g); it.is_valid(); ++it) f(g.idx(), it->idx());
  }
  template <class F> static void each_ef(const Mesh &m, F f) {
    for (auto e : m.edges()) {
      auto f0 = m.face_handle(m.halfedge_handle(e, 0));
      auto f1 = m.face_handle(m.halfedge_handle(e, 1));
      if (f0.is_valid()) f(f0.idx());
      if (f1.is_valid()) f(f1.idx());
    }
  }
};

} // namespace

Answers openmesh_answers(const PeerInput &in, PeerBuild &b) {
  Mesh m;
  std::vector<uint32_t> fin;
  om::build(in, m, b, &fin);
  Answers a;
  a.lib = "OpenMesh";
  a.resize(m.n_vertices(), m.n_edges(), 0);
  // Faces are stored by submitted index: resize to the submitted count.
  a.resize_faces(m.n_faces(), in.n_triangles);
  auto fid = [&](OpenMesh::FaceHandle f) { return f.is_valid() ? fin[size_t(f.idx())] : NONE; };
  om::element_answers(m, a, fid);
  boundary_loops<Peer>(m, m.n_halfedges(), a);
  return a;
}

namespace {
class OpenMeshSubject : public PeerSubject<Peer> {
public:
  using PeerSubject::PeerSubject;
  void describe(LibBench &r) const override {
    r.refused = b_.refused;
    r.faces = m_->n_faces();
    r.vertices = m_->n_vertices();
    r.connectivity_bytes = m_->n_vertices() * sizeof(Mesh::Vertex) + m_->n_edges() * sizeof(Mesh::Edge) +
                           m_->n_faces() * sizeof(Mesh::Face);
  }
  std::vector<LibBench> rows() override { return {peer_row<Peer>("OpenMesh", m_)}; }

};
} // namespace

std::unique_ptr<Subject> openmesh_subject(const PeerInput &in) { return std::make_unique<OpenMeshSubject>(in); }

} // namespace diffmesh
