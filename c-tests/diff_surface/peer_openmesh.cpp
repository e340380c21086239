// OpenMesh 9 (TriMesh_ArrayKernelT with double points): differential answers and benchmark.
#include "peer_openmesh_mesh.hpp"

namespace diffmesh {
namespace {

using Mesh = OpenMeshMesh;

uint32_t vid(OpenMesh::VertexHandle h) { return uint32_t(h.idx()); }

// The adapter of peers.hpp.
struct Peer {
  using Mesh = diffmesh::Mesh;
  static void build(const PeerInput &in, Mesh &m, PeerBuild &b, std::vector<uint32_t> *fin) {
    build_openmesh(in, m, b, fin);
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
  build_openmesh(in, m, b, &fin);
  Answers a;
  a.lib = "OpenMesh";
  a.resize(m.n_vertices(), m.n_edges(), m.n_faces());
  auto fid = [&](OpenMesh::FaceHandle f) { return f.is_valid() ? fin[size_t(f.idx())] : NONE; };
  for (auto v : m.vertices()) {
    size_t i = size_t(v.idx());
    a.have_v[i] = 1;
    // An isolated vertex has no half-edge; OpenMesh's circulators must not start there
    // (they return neighbours of half-edge -1's vertex).
    if (!m.halfedge_handle(v).is_valid()) continue;
    for (auto it = m.cvv_ccwiter(v); it.is_valid(); ++it) {
      a.vv[i].push_back(vid(*it));
      a.ve[i].push_back(mkpair(uint32_t(i), vid(*it)));
    }
    for (auto it = m.cvf_ccwiter(v); it.is_valid(); ++it) a.vf[i].push_back(fid(*it));
    a.v_boundary[i] = m.halfedge_handle(v).is_valid() && m.is_boundary(v);
  }
  // Faces are stored by submitted index: resize to the submitted count.
  a.n_faces = m.n_faces();
  a.have_f.assign(in.n_triangles, 0);
  a.fv.assign(in.n_triangles, {NONE, NONE, NONE});
  a.ff.assign(in.n_triangles, {NONE, NONE, NONE});
  a.fe.assign(in.n_triangles, {});
  for (auto f : m.faces()) {
    size_t i = fin[size_t(f.idx())];
    a.have_f[i] = 1;
    int k = 0;
    for (auto it = m.cfh_ccwiter(f); it.is_valid() && k < 3; ++it, ++k) {
      auto h = *it;
      auto from = vid(m.from_vertex_handle(h)), to = vid(m.to_vertex_handle(h));
      a.fv[i][k] = from;
      a.fe[i][k] = mkpair(from, to);
      a.ff[i][k] = fid(m.face_handle(m.opposite_halfedge_handle(h)));
    }
  }
  for (auto e : m.edges()) {
    size_t i = size_t(e.idx());
    a.have_e[i] = 1;
    auto h0 = m.halfedge_handle(e, 0), h1 = m.halfedge_handle(e, 1);
    a.ev[i] = mkpair(vid(m.from_vertex_handle(h0)), vid(m.to_vertex_handle(h0)));
    for (auto h : {h0, h1}) {
      auto f = m.face_handle(h);
      if (!f.is_valid()) continue;
      a.ef[i].push_back(fid(f));
      for (auto g : {m.next_halfedge_handle(h), m.prev_halfedge_handle(h)})
        a.ee[i].push_back(mkpair(vid(m.from_vertex_handle(g)), vid(m.to_vertex_handle(g))));
    }
    std::sort(a.ef[i].begin(), a.ef[i].end());
    std::sort(a.ee[i].begin(), a.ee[i].end());
  }
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
