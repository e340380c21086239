// <topomesh/cgal.hpp>: a topomesh::Surface to and from a CGAL::Surface_mesh, and a
// topomesh::Volume to a CGAL 3D triangulation of Mesh_3 (header-only; include it only
// where CGAL is found, e.g. through the CMake package's CGAL component).
//
//   using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
//   Mesh sm = topomesh::cgal::to_surface_mesh<Mesh>(surface);
//   topomesh::Surface back = topomesh::cgal::from_surface_mesh(sm);
//   topomesh::cgal::to_triangulation(volume, tr);   // tr: a Mesh_3 triangulation
//
// to_surface_mesh() loads the half-edge export (explicit boundary) straight into the
// Surface_mesh's connectivity, without add_face(): vertex v is Vertex_index(v), triangle t
// Face_index(t), edge e Edge_index(e), whose halfedge 2e is the lower of its two
// half-edges in the export (CHE half-edge h is Halfedge_index(2 edge[h] + (h > twin[h]))).
#ifndef TOPOMESH_CGAL_HPP
#define TOPOMESH_CGAL_HPP

#include "topomesh.hpp"

#include <CGAL/Mesh_3/tet_soup_to_c3t3.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace topomesh {
namespace cgal {

/// The Surface_mesh halfedge of CHE half-edge `h` of the export `he` (explicit boundary).
template <class Mesh>
typename Mesh::Halfedge_index halfedge_of(const HalfEdges &he, std::uint32_t h) {
    return typename Mesh::Halfedge_index(
        typename Mesh::size_type(2 * he.edge[h] + (h > he.twin[h] ? 1 : 0)));
}

/// The surface as a Surface_mesh<Point> (a CGAL::Surface_mesh), with the surface's
/// positions (the origin for every vertex when it has none).
template <class Mesh> Mesh to_surface_mesh(const Surface &s) {
    using Size = typename Mesh::size_type;
    using Point = typename Mesh::Point;
    const HalfEdges he = s.halfedge(HalfEdgeOptions{true});
    const std::size_t nv = s.num_vertices(), ne = s.num_edges(), nt = s.num_triangles();
    const Span<double> pos = s.positions();
    Mesh m;
    m.reserve(Size(nv), Size(ne), Size(nt));
    for (std::size_t v = 0; v < nv; v++)
        m.add_vertex(pos.empty() ? Point(0, 0, 0)
                                 : Point(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]));
    std::vector<std::uint32_t> lower(ne, none);
    for (std::uint32_t h = 0; h < he.twin.size(); h++)
        if (h < he.twin[h]) lower[he.edge[h]] = h;
    for (std::size_t e = 0; e < ne; e++) {
        const std::uint32_t h = lower[e];
        // add_edge(a, b) gives the halfedge with target b, 2e: CHE's h (from a to b).
        m.add_edge(typename Mesh::Vertex_index(Size(he.vertex[h])),
                   typename Mesh::Vertex_index(Size(he.vertex[he.next[h]])));
    }
    for (std::size_t t = 0; t < nt; t++)
        m.set_halfedge(m.add_face(), halfedge_of<Mesh>(he, std::uint32_t(3 * t)));
    for (std::uint32_t h = 0; h < he.next.size(); h++) {
        const auto ch = halfedge_of<Mesh>(he, h);
        m.set_next(ch, halfedge_of<Mesh>(he, he.next[h]));
        m.set_face(ch, he.face[h] == none ? Mesh::null_face()
                                          : typename Mesh::Face_index(Size(he.face[h])));
    }
    // A Surface_mesh vertex keeps an incoming halfedge, a border one on the border: the
    // one before CHE's outgoing half-edge (which is the hole's on the boundary).
    for (std::size_t v = 0; v < nv; v++)
        if (he.vertex_half_edge[v] != none)
            m.set_halfedge(typename Mesh::Vertex_index(Size(v)),
                           halfedge_of<Mesh>(he, he.prev[he.vertex_half_edge[v]]));
    return m;
}

/// The triangles and positions of a Surface_mesh (without removed elements: call
/// collect_garbage() first) as a Surface built with `options`: triangle t is face t, from
/// the source of its halfedge(), vertex v is Vertex_index(v).
template <class Mesh> Surface from_surface_mesh(const Mesh &m, Options options = {}) {
    std::vector<std::uint32_t> tris;
    tris.reserve(3 * m.number_of_faces());
    for (auto f : m.faces()) {
        const auto h = m.halfedge(f);
        tris.push_back(std::uint32_t(std::size_t(m.source(h))));
        tris.push_back(std::uint32_t(std::size_t(m.target(h))));
        tris.push_back(std::uint32_t(std::size_t(m.target(m.next(h)))));
    }
    std::vector<double> pos;
    pos.reserve(3 * m.number_of_vertices());
    for (auto v : m.vertices()) {
        const auto &p = m.point(v);
        pos.insert(pos.end(), {CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                               CGAL::to_double(p.z())});
    }
    return Surface::from_triangles(tris, m.number_of_vertices(), pos, options);
}

/// Fills `tr`, a 3D triangulation of Mesh_3 (Mesh_triangulation_3<...>::type), with the
/// volume's vertices (its positions are required) and tetrahedra, through CGAL's
/// build_triangulation, every cell in `subdomain`; tetrahedron t is the t-th finite cell
/// created, its vertices ordered to be positively oriented. Returns build_triangulation's
/// answer: false when the tetrahedra do not form a valid triangulation (a face in more than two
/// tetrahedra, a boundary that is not a closed surface), and throws Error without
/// positions.
template <class Tr> bool to_triangulation(const Volume &vol, Tr &tr, int subdomain = 1) {
    using Point = typename Tr::Point;
    const Span<double> pos = vol.positions();
    if (pos.empty() && vol.num_vertices() != 0)
        detail::throw_error(TOPOMESH_STATUS_INVALID_INPUT,
                            "to_triangulation: the volume has no positions");
    std::vector<Point> points;
    points.reserve(vol.num_vertices());
    for (std::size_t v = 0; v < vol.num_vertices(); v++)
        points.push_back(Point(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]));
    std::vector<std::array<int, 5>> cells;
    cells.reserve(vol.num_tetrahedra());
    for (TetrahedronId t : vol.tetrahedra()) {
        auto c = vol.tetrahedron_vertices(t);
        std::array<int, 5> cell{int(c[0].value()), int(c[1].value()), int(c[2].value()),
                                int(c[3].value()), subdomain};
        const double *p[4];
        for (int j = 0; j < 4; j++) p[j] = &pos[3 * std::size_t(cell[j])];
        double a[3], b[3], d[3];
        for (int k = 0; k < 3; k++)
            a[k] = p[1][k] - p[0][k], b[k] = p[2][k] - p[0][k], d[k] = p[3][k] - p[0][k];
        const double det = a[0] * (b[1] * d[2] - b[2] * d[1]) -
                           a[1] * (b[0] * d[2] - b[2] * d[0]) +
                           a[2] * (b[0] * d[1] - b[1] * d[0]);
        if (det < 0) std::swap(cell[0], cell[1]);
        cells.push_back(cell);
    }
    std::map<std::array<int, 3>, typename Tr::Cell::Surface_patch_index> no_patches;
    std::vector<typename Tr::Vertex_handle> handles;
    return CGAL::build_triangulation<Tr, false>(tr, points, cells, no_patches, handles);
}

} // namespace cgal
} // namespace topomesh

#endif // TOPOMESH_CGAL_HPP
