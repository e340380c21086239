// The element ranges (vertices(), triangles(), edges(), boundary_curves(); faces() and
// tetrahedra() on a Volume), position(v) and the per-element data (VertexData<T>, ...) of
// the C++ wrapper, each compared with the C API's answers; and the weld through
// Options::weld_tolerance.
#include "check.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

using namespace topomesh;

// Two strips of triangles: a square of two triangles (one boundary curve) beside a closed
// tetrahedron surface, over 8 vertices with positions.
static Surface two_parts(std::uint32_t level) {
    std::vector<std::uint32_t> tris{0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 5, 7, 4, 7, 6, 5, 6, 7};
    std::vector<double> pos{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                            5, 0, 0, 6, 0, 0, 5, 1, 0, 5, 0, 1};
    Options o;
    o.level = level;
    return Surface::from_triangles(tris, 8, pos, o);
}

static std::vector<std::uint32_t> c_curve(const che_mesh *m, std::uint32_t c) {
    std::size_t len = 0;
    che_boundary_curve_vertices(m, c, nullptr, 0, &len);
    std::vector<std::uint32_t> out(len);
    CHECK(che_boundary_curve_vertices(m, c, out.data(), len, &len) == TOPOMESH_STATUS_OK);
    return out;
}

static void surface_ranges(std::uint32_t level) {
    Surface s = two_parts(level);
    const che_mesh *m = s.handle();
    CHECK(s.vertices().size() == che_mesh_num_vertices(m));
    CHECK(s.triangles().size() == che_mesh_num_triangles(m));
    CHECK(s.edges().size() == che_mesh_num_edges(m));
    CHECK(s.half_edges().size() == che_mesh_num_half_edges(m));
    CHECK(s.boundary_curves().size() == che_mesh_num_boundary_curves(m));
    CHECK(s.boundary_curves().size() == 1);
    std::uint32_t want = 0;
    for (VertexId v : s.vertices()) CHECK(v.value() == want++);
    CHECK(want == 8);
    // Random access, as std algorithms use it.
    auto r = s.edges();
    CHECK(r.end() - r.begin() == static_cast<std::ptrdiff_t>(r.size()));
    CHECK(*(r.begin() + 3) == EdgeId{3} && r[4] == EdgeId{4});

    std::size_t n_pos = 0;
    const double *p = che_mesh_positions(m, &n_pos);
    CHECK(s.has_positions() && n_pos == 3 * s.vertices().size());
    for (VertexId v : s.vertices()) {
        Vec3 q = s.position(v);
        for (std::size_t k = 0; k < 3; k++) CHECK(q[k] == p[3 * v.value() + k]);
        CHECK(q.x == q[0] && q.y == q[1] && q.z == q[2]);
    }
    CHECK_THROWS(s.position(VertexId{8}), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex 8");
    for (CurveId c : s.boundary_curves())
        CHECK(raw(s.boundary_curve_vertices(c)) == c_curve(m, c.value()));

    // Per-element data: the degree of each vertex and the area of each triangle, by the
    // wrapper's ranges, against the C calls.
    VertexData<int> degree(s, -1);
    CHECK(degree.size() == che_mesh_num_vertices(m));
    for (VertexId v : s.vertices()) degree[v] = static_cast<int>(s.vertex_vertices(v).size());
    for (VertexId v : s.vertices()) {
        std::size_t len = 0;
        che_vertex_vertices(m, v.value(), nullptr, 0, &len);
        CHECK(degree[v] == static_cast<int>(len) && degree.at(v) == degree[v]);
    }
    TriangleData<double> area(s, 0.0);
    CHECK(area.size() == che_mesh_num_triangles(m));
    for (TriangleId t : s.triangles()) {
        auto c = s.triangle_vertices(t);
        Vec3 a = s.position(c[0]), b = s.position(c[1]), d = s.position(c[2]);
        double u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, w[3] = {d.x - a.x, d.y - a.y, d.z - a.z};
        double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2],
               z = u[0] * w[1] - u[1] * w[0];
        area[t] = 0.5 * std::sqrt(x * x + y * y + z * z);
    }
    CHECK(area[TriangleId{0}] == 0.5 && area[TriangleId{1}] == 0.5);
    EdgeData<bool> boundary(s, false);
    CHECK(boundary.size() == che_mesh_num_edges(m));
    std::size_t n_boundary = 0;
    for (EdgeId e : s.edges()) {
        boundary[e] = s.is_boundary(e);
        bool c = false;
        che_edge_is_boundary(m, e.value(), &c);
        CHECK(boundary[e] == c);
        n_boundary += boundary[e] ? 1 : 0;
    }
    CHECK(n_boundary == 4);
    CurveData<std::size_t> length(s);
    CHECK(length.size() == 1);
    bool threw = false;
    try {
        (void)degree.at(VertexId{8});
    } catch (const std::out_of_range &) {
        threw = true;
    }
    CHECK(threw);
    degree.fill(7);
    CHECK(degree.raw() == std::vector<int>(8, 7));
}

static void no_positions() {
    Surface s = Surface::from_triangles(std::vector<std::uint32_t>{0, 1, 2}, 3);
    CHECK(!s.has_positions());
    CHECK_THROWS(s.position(VertexId{0}), TOPOMESH_STATUS_INVALID_INPUT, "without positions");
    CHECK(s.boundary_curves().size() == 1);
}

static void volume_ranges() {
    // Two tetrahedra sharing face 1 2 3.
    std::vector<std::uint32_t> tets{0, 1, 2, 3, 1, 3, 2, 4};
    std::vector<double> pos{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
    Volume v = Volume::from_tetrahedra(tets, 5, pos);
    const chf_mesh *m = v.handle();
    CHECK(v.vertices().size() == chf_mesh_num_vertices(m));
    CHECK(v.edges().size() == chf_mesh_num_edges(m));
    CHECK(v.faces().size() == chf_mesh_num_faces(m) && v.faces().size() == 7);
    CHECK(v.tetrahedra().size() == chf_mesh_num_tetrahedra(m));
    CHECK(v.half_faces().size() == chf_mesh_num_half_faces(m));
    std::size_t n_pos = 0;
    const double *p = chf_mesh_positions(m, &n_pos);
    for (VertexId x : v.vertices()) {
        Vec3 q = v.position(x);
        CHECK(q.x == p[3 * x.value()] && q.y == p[3 * x.value() + 1] && q.z == p[3 * x.value() + 2]);
    }
    CHECK_THROWS(v.position(VertexId{5}), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex 5");
    TetData<std::size_t> neighbours(v, 0);
    for (TetrahedronId t : v.tetrahedra()) {
        for (TetrahedronId u : v.tetrahedron_tetrahedra(t)) neighbours[t] += u.valid() ? 1 : 0;
    }
    CHECK(neighbours[TetrahedronId{0}] == 1 && neighbours[TetrahedronId{1}] == 1);
    FaceData<bool> boundary(v, false);
    std::size_t n_boundary = 0;
    for (FaceId f : v.faces()) {
        boundary[f] = v.is_boundary(f);
        n_boundary += boundary[f] ? 1 : 0;
    }
    CHECK(n_boundary == chf_mesh_num_boundary_faces(m));
    VertexData<int> per_vertex(v, 1);
    EdgeData<int> per_edge(v, 2);
    HalfFaceData<int> per_half_face(v, 3);
    CHECK(per_vertex.size() == 5 && per_edge.size() == chf_mesh_num_edges(m));
    CHECK(per_half_face.size() == 8);
}

// An STL-like square: two triangles written with their own three corners each, the shared
// ones off by one unit in the last place. Welded it is one patch with one boundary curve.
static void weld_option() {
    const double e = 2.220446049250313e-16;
    std::vector<std::uint32_t> tris{0, 1, 2, 3, 4, 5};
    std::vector<double> pos{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, e, 1, 1 + e, 0, 0, 1, 0};
    Options o;
    o.weld_tolerance = 1e-9;
    Surface welded = Surface::from_triangles(tris, 6, pos, o);
    CHECK(welded.num_edges() == 5 && welded.boundary_curves().size() == 1);
    CHECK(welded.report().welded_vertices == 2 && welded.raw_report().welded_vertices == 2);
    CHECK(welded.summary().vertices == 4 && welded.summary().euler_characteristic == 1);
    Surface loose = Surface::from_triangles(tris, 6, pos);
    CHECK(loose.num_edges() == 6 && loose.boundary_curves().size() == 2);
    o.weld_tolerance = -1;
    CHECK_THROWS(Surface::from_triangles(tris, 6, pos, o), TOPOMESH_STATUS_INVALID_INPUT,
                 "weld_tolerance");
    // The map the build applied: corners 3 and 4 went to 0 and 2.
    std::vector<VertexId> rep = weld_representatives(pos, 1e-9);
    std::vector<VertexId> want{VertexId{0}, VertexId{1}, VertexId{2},
                               VertexId{0}, VertexId{2}, VertexId{5}};
    CHECK(rep == want);
    CHECK_THROWS(weld_representatives(pos, 0.0), TOPOMESH_STATUS_INVALID_INPUT, "weld_tolerance");
}

int main() {
    return run_tests("test_elements", [] {
        for (std::uint32_t level = 0; level <= 3; level++) surface_ranges(level);
        no_positions();
        volume_ranges();
        weld_option();
    });
}
