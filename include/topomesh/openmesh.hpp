// <topomesh/openmesh.hpp>: a topomesh::Surface to and from an OpenMesh TriMesh
// (header-only; include it only where OpenMesh is found, e.g. through the CMake package's
// OpenMesh component).
//
//   topomesh::Surface s = topomesh::Surface::load("bunny.off");
//   auto om = topomesh::openmesh::to_openmesh(s);         // OpenMesh::TriMesh
//   topomesh::Surface back = topomesh::openmesh::from_openmesh(om);
//
// to_openmesh() loads the half-edge export (explicit boundary) straight into OpenMesh's
// connectivity, without add_face(): vertex v is VertexHandle(v), triangle t FaceHandle(t),
// edge e EdgeHandle(e), whose halfedge 0 is the lower of its two half-edges in the export
// (CHE half-edge h is halfedge 2 edge[h] + (h > twin[h])). The surface is the built one:
// split vertices are vertices of their own, so OpenMesh gets a manifold mesh whatever the
// input was.
#ifndef TOPOMESH_OPENMESH_HPP
#define TOPOMESH_OPENMESH_HPP

#include "topomesh.hpp"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace topomesh {
namespace openmesh {

/// OpenMesh's default triangle mesh (float points).
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<>;

/// The OpenMesh halfedge of CHE half-edge `h` of the export `he` (explicit boundary).
inline OpenMesh::HalfedgeHandle halfedge_of(const HalfEdges &he, std::uint32_t h) {
    return OpenMesh::HalfedgeHandle(int(2 * he.edge[h] + (h > he.twin[h] ? 1 : 0)));
}

/// The surface as an OpenMesh mesh of type Mesh (a TriMesh_ArrayKernelT), with the
/// surface's positions (the origin for every vertex when it has none).
template <class Mesh = TriMesh> Mesh to_openmesh(const Surface &s) {
    const HalfEdges he = s.halfedge(HalfEdgeOptions{true});
    const std::size_t nv = s.num_vertices(), ne = s.num_edges(), nt = s.num_triangles();
    const Span<double> pos = s.positions();
    Mesh m;
    m.reserve(nv, ne, nt);
    using Scalar = typename Mesh::Point::value_type;
    for (std::size_t v = 0; v < nv; v++) {
        typename Mesh::Point p(0, 0, 0);
        if (!pos.empty())
            p = typename Mesh::Point(Scalar(pos[3 * v]), Scalar(pos[3 * v + 1]),
                                     Scalar(pos[3 * v + 2]));
        m.new_vertex(p);
    }
    // Each edge from its lower half-edge, so that OpenMesh's halfedge 2e is that one.
    std::vector<std::uint32_t> lower(ne, none);
    for (std::uint32_t h = 0; h < he.twin.size(); h++)
        if (h < he.twin[h]) lower[he.edge[h]] = h;
    for (std::size_t e = 0; e < ne; e++) {
        const std::uint32_t h = lower[e];
        m.new_edge(OpenMesh::VertexHandle(int(he.vertex[h])),
                   OpenMesh::VertexHandle(int(he.vertex[he.next[h]])));
    }
    for (std::size_t t = 0; t < nt; t++)
        m.set_halfedge_handle(m.new_face(), halfedge_of(he, std::uint32_t(3 * t)));
    for (std::uint32_t h = 0; h < he.next.size(); h++) {
        const OpenMesh::HalfedgeHandle oh = halfedge_of(he, h);
        m.set_next_halfedge_handle(oh, halfedge_of(he, he.next[h]));
        m.set_face_handle(oh, he.face[h] == none ? OpenMesh::FaceHandle()
                                                 : OpenMesh::FaceHandle(int(he.face[h])));
    }
    for (std::size_t v = 0; v < nv; v++)
        if (he.vertex_half_edge[v] != none)
            m.set_halfedge_handle(OpenMesh::VertexHandle(int(v)),
                                  halfedge_of(he, he.vertex_half_edge[v]));
    return m;
}

/// The triangles and positions of an OpenMesh triangle mesh (without deleted elements:
/// call garbage_collection() first) as a Surface built with `options`: triangle t is face
/// t, from the source of its halfedge_handle(), vertex v is VertexHandle(v).
template <class Mesh> Surface from_openmesh(const Mesh &m, Options options = {}) {
    std::vector<std::uint32_t> tris;
    tris.reserve(3 * m.n_faces());
    for (auto f : m.faces()) {
        const auto h = m.halfedge_handle(f);
        tris.push_back(std::uint32_t(m.from_vertex_handle(h).idx()));
        tris.push_back(std::uint32_t(m.to_vertex_handle(h).idx()));
        tris.push_back(std::uint32_t(m.to_vertex_handle(m.next_halfedge_handle(h)).idx()));
    }
    std::vector<double> pos;
    pos.reserve(3 * m.n_vertices());
    for (auto v : m.vertices()) {
        const auto p = m.point(v);
        pos.insert(pos.end(), {double(p[0]), double(p[1]), double(p[2])});
    }
    return Surface::from_triangles(tris, m.n_vertices(), pos, options);
}

} // namespace openmesh
} // namespace topomesh

#endif // TOPOMESH_OPENMESH_HPP
