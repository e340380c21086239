// CGAL 5.5 Surface_mesh (Epick points): differential answers and benchmark. The only CGAL
// translation unit (its headers are slow to compile).
#include "cgal_mesh.hpp"

#include <CGAL/boost/graph/iterator.h>

namespace diffmesh {
namespace {
using cg::K;
using cg::Mesh;
using VI = Mesh::Vertex_index;
using FI = Mesh::Face_index;
using HI = Mesh::Halfedge_index;
} // namespace

void cg::build(const PeerInput &in, Mesh &m, PeerBuild &b, std::vector<uint32_t> *face_input) {
  m.reserve(Mesh::size_type(in.n_vertices), Mesh::size_type(in.n_triangles * 3 / 2 + 16),
            Mesh::size_type(in.n_triangles));
  for (size_t v = 0; v < in.n_vertices; ++v) {
    const double *p = in.positions + 3 * v;
    VI h = m.add_vertex(K::Point_3(p[0], p[1], p[2]));
    if (size_t(h) != v) b.vertices_in_order = false;
  }
  add_triangles(in, b, face_input, [&](const uint32_t *c) {
    return m.add_face(VI(c[0]), VI(c[1]), VI(c[2])) != Mesh::null_face();
  });
}

namespace {

uint32_t id(VI v) { return uint32_t(size_t(v)); }

// The adapter of peers.hpp.
struct Peer {
  using Mesh = cg::Mesh;
  static void build(const PeerInput &in, Mesh &m, PeerBuild &b, std::vector<uint32_t> *fin) {
    cg::build(in, m, b, fin);
  }
  using H = HI;
  static auto halfedges(const Mesh &m) { return m.halfedges(); }
  static size_t index(HI h) { return size_t(h); }
  static bool border(const Mesh &m, HI h) { return m.is_border(h); }
  static uint32_t source(const Mesh &m, HI h) { return id(m.source(h)); }
  static HI next(const Mesh &m, HI h) { return m.next(h); }
  static size_t n_halfedges(const Mesh &m) { return m.number_of_halfedges(); }
  template <class F> static void each_vv(const Mesh &m, F f) {
    for (VI v : m.vertices())
      for (VI w : CGAL::vertices_around_target(m.halfedge(v), m)) f(size_t(v), size_t(w));
  }
  template <class F> static void each_vf(const Mesh &m, F f) {
    for (VI v : m.vertices())
      for (FI g : CGAL::faces_around_target(m.halfedge(v), m))
        if (g != Mesh::null_face()) f(size_t(v), size_t(g));
  }
  template <class F> static void each_ff(const Mesh &m, F f) {
    for (FI e : m.faces())
      for (FI g : CGAL::faces_around_face(m.halfedge(e), m))
        if (g != Mesh::null_face()) f(size_t(e), size_t(g));
  }
  template <class F> static void each_ef(const Mesh &m, F f) {
    for (auto e : m.edges()) {
      HI h = m.halfedge(e);
      FI f0 = m.face(h), f1 = m.face(m.opposite(h));
      if (f0 != Mesh::null_face()) f(size_t(f0));
      if (f1 != Mesh::null_face()) f(size_t(f1));
    }
  }
};

} // namespace

Answers cgal_answers(const PeerInput &in, PeerBuild &b) {
  Mesh m;
  std::vector<uint32_t> fin;
  cg::build(in, m, b, &fin);
  Answers a;
  a.lib = "CGAL";
  a.resize(m.number_of_vertices(), m.number_of_edges(), 0);
  // Faces are stored by submitted index: resize to the submitted count.
  a.resize_faces(m.number_of_faces(), in.n_triangles);
  auto fid = [&](FI f) { return f == Mesh::null_face() ? NONE : fin[size_t(f)]; };
  cg::element_answers(m, a, fid);
  boundary_loops<Peer>(m, m.number_of_halfedges(), a);
  return a;
}

namespace {
class CgalSubject : public PeerSubject<Peer> {
public:
  using PeerSubject::PeerSubject;
  void describe(LibBench &r) const override {
    const Mesh &m = *m_;
    r.refused = b_.refused;
    r.faces = m.number_of_faces();
    r.vertices = m.number_of_vertices();
    // vconn (a halfedge index), hconn (face, vertex, next, prev), fconn (a halfedge index),
    // and one "removed" bit per vertex, edge and face (std::vector<bool>).
    size_t idx = sizeof(HI);
    r.connectivity_bytes = m.number_of_vertices() * idx + m.number_of_halfedges() * 4 * idx +
                           m.number_of_faces() * idx +
                           (m.number_of_vertices() + m.number_of_edges() + m.number_of_faces()) / 8;
  }
  std::vector<LibBench> rows() override { return {peer_row<Peer>("CGAL", m_)}; }

};
} // namespace

std::unique_ptr<Subject> cgal_subject(const PeerInput &in) { return std::make_unique<CgalSubject>(in); }

} // namespace diffmesh
