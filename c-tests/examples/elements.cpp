// Loops as with OpenMesh, per-element data as with geometry-central, and the weld.
#include <topomesh/topomesh.hpp>
#include <iostream>
#include <vector>

int main() {
    using namespace topomesh;
    // The unit square's two triangles, each with its own three corners, as STL stores
    // them: the weld joins corners at most 1e-9 apart, so the triangles share the diagonal.
    std::vector<std::uint32_t> triangles{0, 1, 2, 3, 4, 5};
    std::vector<double> positions{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    Options options;
    options.weld_tolerance = 1e-9;
    Surface s = Surface::from_triangles(triangles, 6, positions, options);
    std::cout << "welded " << s.report().welded_vertices << " vertices, " << s.edges().size()
              << " edges\n";

    // One double per vertex, indexed by VertexId: a third of each triangle's area.
    VertexData<double> area(s, 0.0);
    for (TriangleId t : s.triangles()) {
        Ids<VertexId, 3> c = s.triangle_vertices(t);
        Vec3 a = s.position(c[0]), b = s.position(c[1]), d = s.position(c[2]);
        double twice = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x); // in z = 0
        for (VertexId v : c) area[v] += twice / 6;
    }
    for (VertexId v : s.vertices())
        if (!s.vertex_triangles(v).empty()) // the welded vertices 3 and 5 have none
            std::cout << "vertex " << v.value() << " at (" << s.position(v).x << ", "
                      << s.position(v)[1] << "): area " << area[v] << '\n';
    for (CurveId c : s.boundary_curves())
        std::cout << "boundary curve " << c.value() << ": "
                  << s.boundary_curve_vertices(c).size() << " vertices\n";
    return 0;
}
