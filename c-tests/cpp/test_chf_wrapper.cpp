// The C++17 wrapper of CHF: Volume (RAII, moves), strong ids, relations, views, CSR,
// the boundary as a Surface, errors.
#include "check.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>
#include <type_traits>
#include <vector>

using namespace topomesh;

static_assert(!std::is_copy_constructible<Volume>::value, "move-only");
static_assert(!std::is_copy_assignable<Volume>::value, "move-only");
static_assert(std::is_nothrow_move_constructible<Volume>::value, "movable");
static_assert(std::is_nothrow_move_assignable<Volume>::value, "movable");
static_assert(!std::is_convertible<FaceId, TriangleId>::value, "strong ids");
static_assert(!std::is_convertible<TetrahedronId, FaceId>::value, "strong ids");
static_assert(!std::is_convertible<HalfFaceId, HalfEdgeId>::value, "strong ids");
static_assert(!std::is_convertible<std::uint32_t, TetrahedronId>::value, "explicit ids");
static_assert(std::is_same<Chf, Volume>::value, "alias");
static_assert(next(HalfFaceId{7}) == HalfFaceId{4} && next(HalfFaceId{4}) == HalfFaceId{5},
              "constexpr arithmetic");
static_assert(tetrahedron_of(HalfFaceId{7}) == TetrahedronId{1}, "constexpr arithmetic");
static_assert(face_corner(HalfFaceId{5}, 1) == HalfFaceId{7}, "face 1 is {0, 3, 2}");

using U = std::vector<std::uint32_t>;

static const U PAIR = {0, 1, 2, 3, 4, 1, 3, 2};
static const std::vector<double> PAIR_POS = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
static const U CUBE = {0, 1, 2, 4, 3, 2, 1, 7, 5, 1, 4, 7, 6, 4, 2, 7, 1, 2, 4, 7};

static void test_build_and_counts() {
    Volume v = Volume::from_tetrahedra(PAIR, 5, PAIR_POS);
    CHECK(v.level() == 2);
    CHECK(v.num_vertices() == 5 && v.num_input_vertices() == 5 && v.num_tetrahedra() == 2);
    CHECK(v.num_faces() == 7 && v.num_edges() == 9 && v.num_half_faces() == 8);
    CHECK(v.num_boundary_faces() == 6 && v.num_boundary_components() == 1);
    v.build_level(3);
    CHECK(v.level() == 3);
    CHECK_THROWS(v.build_level(9), TOPOMESH_STATUS_OUT_OF_RANGE, "level 9");

    Volume w = Volume::from_tetrahedra(CUBE.data(), 5, 8, nullptr, {0, true});
    CHECK(w.level() == 0 && w.num_edges() == 18 && w.num_faces() == 16);
    // Any number of threads: the same mesh.
    for (std::uint32_t threads : {1u, 2u, 5u}) {
        Volume t = Volume::from_tetrahedra(CUBE.data(), 5, 8, nullptr, {2, false, threads});
        CHECK(t.num_edges() == 18 && t.num_faces() == 16 && t.num_boundary_faces() == 12);
    }

    CHECK_THROWS(Volume::from_tetrahedra(U{0, 1, 2}, 3), TOPOMESH_STATUS_INVALID_INPUT,
                 "multiple of 4");
    CHECK_THROWS(Volume::from_tetrahedra(PAIR, 5, std::vector<double>{0, 0}),
                 TOPOMESH_STATUS_INVALID_INPUT, "coordinates");
    CHECK_THROWS(Volume::from_tetrahedra(PAIR, 4), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex 4");
    CHECK_THROWS(Volume::from_tetrahedra({0, 1, 2, 3, 0, 1, 2, 4, 0, 1, 2, 5}, 6, {}, {2, true}),
                 TOPOMESH_STATUS_NON_MANIFOLD, "(0, 1, 2)");
    CHECK_THROWS(Volume::load("chf-missing-file.mesh"), TOPOMESH_STATUS_IO,
                 "chf-missing-file.mesh");
    {
        std::ofstream f("chf-wrapper.off");
        f << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    }
    CHECK_THROWS(Volume::load("chf-wrapper.off"), TOPOMESH_STATUS_INVALID_INPUT, "no tetrahedra");
    {
        std::ofstream f("chf-wrapper.mesh");
        f << "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n"
             "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n";
    }
    Volume loaded = Volume::load("chf-wrapper.mesh", {3});
    CHECK(loaded.level() == 3 && loaded.num_tetrahedra() == 1 && loaded.positions().size() == 12);
}

static void test_moves() {
    check_moves(Volume::from_tetrahedra(PAIR, 5), Volume::from_tetrahedra(CUBE, 8),
                [](const Volume &m) { return m.num_tetrahedra(); }, 2, 9);
}

static void test_relations() {
    Volume v = Volume::from_tetrahedra(PAIR, 5);
    CHECK((raw(v.vertex_vertices(VertexId{1})) == U{0, 2, 3, 4}));
    CHECK((raw(v.vertex_edges(VertexId{1})) == U{0, 3, 4, 6}));
    CHECK((raw(v.vertex_faces(VertexId{1})) == U{0, 2, 3, 5, 6}));
    CHECK((raw(v.vertex_tetrahedra(VertexId{1})) == U{0, 1}));
    CHECK((raw(v.edge_edges(EdgeId{3})) == U{0, 1, 5, 4, 8, 6}));
    CHECK((raw(v.edge_faces(EdgeId{3})) == U{3, 0, 5}));
    CHECK((raw(v.edge_tetrahedra(EdgeId{3})) == U{0, 1}));
    CHECK((raw(v.edge_vertices(EdgeId{3})) == U{2, 1}));
    CHECK((raw(v.face_vertices(FaceId{4})) == U{4, 2, 3}));
    CHECK((raw(v.face_edges(FaceId{4})) == U{8, 5, 7}));
    CHECK((raw(v.face_faces(FaceId{0})) == U{1, 2, 3, 4, 5, 6}));
    CHECK((raw(v.face_faces(FaceId{1})) == U{2, 3, 0}));
    CHECK((raw(v.face_tetrahedra(FaceId{0})) == U{0, 1}));
    CHECK(v.face_tetrahedra(FaceId{4}).size() == 1);
    CHECK((raw(v.tetrahedron_vertices(TetrahedronId{1})) == U{4, 1, 3, 2}));
    CHECK((raw(v.tetrahedron_edges(TetrahedronId{1})) == U{6, 7, 8, 4, 3, 5}));
    CHECK((raw(v.tetrahedron_faces(TetrahedronId{1})) == U{0, 4, 5, 6}));
    auto tt = v.tetrahedron_tetrahedra(TetrahedronId{0});
    CHECK(tt[0] == TetrahedronId{1} && !tt[1].valid() && !tt[2].valid() && !tt[3].valid());
    CHECK_THROWS(v.tetrahedron_vertices(TetrahedronId{2}), TOPOMESH_STATUS_OUT_OF_RANGE,
                 "tetrahedron 2");
    CHECK_THROWS(v.face_faces(FaceId{7}), TOPOMESH_STATUS_OUT_OF_RANGE, "face 7");
    CHECK_THROWS(v.edge_faces(EdgeId{9}), TOPOMESH_STATUS_OUT_OF_RANGE, "edge 9");
    CHECK_THROWS(v.vertex_tetrahedra(VertexId{}), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex");

    CHECK(v.opposite(HalfFaceId{0}) == HalfFaceId{4} && !v.opposite(HalfFaceId{1}).valid());
    CHECK(v.face(HalfFaceId{4}) == FaceId{0} && v.half_face(FaceId{4}) == HalfFaceId{5});
    CHECK(v.half_face(VertexId{4}) == HalfFaceId{5});
    CHECK(v.is_boundary(VertexId{0}) && v.is_boundary(EdgeId{3}));
    CHECK(!v.is_boundary(FaceId{0}) && v.is_boundary(FaceId{1}));
    CHECK_THROWS(v.opposite(HalfFaceId{8}), TOPOMESH_STATUS_OUT_OF_RANGE, "half-face 8");

    // A star larger than the wrapper's stack buffer: 80 tetrahedra around one vertex (a
    // fan of tetrahedra around the edge 0-1, closed into a ring).
    const std::uint32_t k = 80;
    U ring;
    for (std::uint32_t i = 0; i < k; i++) {
        ring.insert(ring.end(), {0, 1, 2 + i, 2 + (i + 1) % k});
    }
    Volume r = Volume::from_tetrahedra(ring, 2 + k);
    CHECK(r.vertex_tetrahedra(VertexId{0}).size() == k);
    CHECK(r.vertex_vertices(VertexId{0}).size() == k + 1);
    EdgeId axis;
    for (EdgeId e : r.vertex_edges(VertexId{0})) {
        auto ends = r.edge_vertices(e);
        if (ends[0] == VertexId{1} || ends[1] == VertexId{1}) axis = e;
    }
    CHECK(axis.valid());
    CHECK(r.edge_tetrahedra(axis).size() == k && r.edge_faces(axis).size() == k);
    CHECK(r.edge_edges(axis).size() == 2 * k && !r.is_boundary(axis));
}

static void test_views_csr_boundary_summary() {
    Volume v = Volume::from_tetrahedra(PAIR, 5, PAIR_POS, {1});
    CHECK((v.half_face_vertices().to_vector() == PAIR));
    CHECK(v.opposites().size() == 8 && v.opposites()[0] == 4 && v.opposites()[1] == none);
    CHECK(v.vertex_half_faces().empty() && v.face_half_faces().empty());
    CHECK(v.boundary_half_faces().empty() && v.boundary_vertex_components().empty());
    CHECK(v.boundary_vertices().empty());
    CHECK((v.positions().to_vector() == PAIR_POS));
    CHECK((v.vertex_origins().to_vector() == U{0, 1, 2, 3, 4}));
    CHECK((v.tetrahedron_origins().to_vector() == U{0, 1}));
    v.build_level(3);
    CHECK((v.vertex_half_faces().to_vector() == U{1, 2, 1, 1, 5}));
    CHECK((v.face_half_faces().to_vector() == U{0, 1, 2, 3, 5, 6, 7}));
    CHECK((v.boundary_half_faces().to_vector() == U{1, 2, 3, 5, 6, 7}));
    CHECK((v.boundary_vertex_components().to_vector() == U{0, 0, 0, 0, 0}));
    CHECK((v.boundary_vertices().to_vector() == U{0, 1, 2, 3, 4}));
    CHECK(v.num_boundary_vertices() == 5 && v.num_boundary_triangles() == 6);
    CHECK(v.num_non_manifold_half_faces() == 0 && v.num_seam_half_faces() == 0);
    // The outward corners of a half-face, from the views and the arithmetic.
    Span<std::uint32_t> V = v.half_face_vertices();
    U corners;
    for (std::uint32_t j = 0; j < 3; j++) corners.push_back(V[face_corner(HalfFaceId{5}, j).value()]);
    CHECK((corners == raw(v.face_vertices(FaceId{4}))));

    Csr vt = v.vertex_tetrahedra_csr();
    CHECK(vt.rows() == 5 && (vt.offsets == U{0, 1, 3, 5, 7, 8}));
    CHECK((vt.row(1).to_vector() == U{0, 1}));
    CHECK(v.vertex_vertices_csr().indices.size() == 18);
    CHECK(v.vertex_edges_csr().indices.size() == 18);
    CHECK(v.vertex_faces_csr().rows() == 5);
    CHECK(v.edge_faces_csr().rows() == 9);
    CHECK((v.edge_tetrahedra_csr().row(3).to_vector() == U{0, 1}));
    CHECK((v.tetrahedron_tetrahedra_csr().indices == U{1, none, none, none, 0, none, none, none}));

    // The boundary as a Surface that outlives the volume.
    Surface skin = Surface::from_triangles(U{0, 1, 2}, 3);
    {
        Volume cube = Volume::from_tetrahedra(CUBE, 8);
        skin = cube.boundary();
        for (std::uint32_t k = 0; k < 12; k++) {
            TriangleId t{k};
            FaceId f = cube.boundary_face(t);
            CHECK(cube.boundary_triangle(f) == t);
            CHECK(cube.boundary_triangle(cube.boundary_half_face(t)) == t);
            CHECK(cube.half_face(f) == cube.boundary_half_face(t));
            auto a = skin.triangle_vertices(t);
            auto b = cube.face_vertices(f);
            for (int j = 0; j < 3; j++) {
                CHECK(cube.volume_vertex(a[j]) == b[j]);
                CHECK(cube.boundary_vertex(b[j]) == a[j]);
            }
        }
        CHECK(!cube.boundary_triangle(cube.tetrahedron_faces(TetrahedronId{4})[0]).valid());
        CHECK(cube.boundary_component(VertexId{7}) == 0);
        CHECK_THROWS(cube.boundary_face(TriangleId{12}), TOPOMESH_STATUS_OUT_OF_RANGE,
                     "boundary triangle 12");
    }
    Surface::Summary s = skin.summary();
    CHECK(skin.level() == 3 && skin.num_triangles() == 12 && skin.num_boundary_curves() == 0);
    CHECK(s.vertices == 8 && s.edges == 18 && s.euler_characteristic == 2 && s.genus == 0);

    CHECK_NOTHROW(skin.validate());
    CHECK_NOTHROW(v.validate());
    Volume::Summary sum = v.summary();
    CHECK(v.raw_summary().faces == sum.faces && v.raw_summary().boundary_faces == 6);
    CHECK(sum.vertices == 5 && sum.edges == 9 && sum.faces == 7 && sum.tetrahedra == 2);
    CHECK(sum.boundary_faces == 6 && sum.euler_characteristic == 1 && sum.manifold);
    Volume::BuildReport r = v.report();
    CHECK(v.raw_report().input_faces == 7);
    CHECK(r.input_tetrahedra == 2 && r.boundary_faces == 6 && r.input_faces == 7);
    CHECK(v.report_examples(CHF_REPORT_KIND_DEGENERATE).empty());
    chf_memory m = v.memory();
    CHECK(m.half_face_vertices == 32 && m.positions == 120 && m.boundary > 0);

    Volume split = Volume::from_tetrahedra({0, 1, 2, 3, 0, 4, 5, 6}, 7);
    CHECK(split.num_vertices() == 8 && split.vertex_origins()[7] == 0);
    CHECK((split.report_examples(CHF_REPORT_KIND_SPLIT_VERTEX) == U{0}));
    CHECK(split.num_boundary_components() == 2);
}

static void test_write() {
    Volume v = Volume::from_tetrahedra(PAIR, 5, PAIR_POS);
    v.write("chf-wrapper-write.msh");
    Volume back = Volume::load("chf-wrapper-write.msh");
    CHECK(back.num_vertices() == 5 && back.num_tetrahedra() == 2 && back.num_faces() == 7);
    v.write_boundary("chf-wrapper-skin.obj", TOPOMESH_WRITE_NO_ORIGIN);
    Surface skin = Surface::load("chf-wrapper-skin.obj");
    CHECK(skin.num_vertices() == 5 && skin.num_triangles() == 6 && skin.num_boundary_curves() == 0);
    CHECK_THROWS(v.write("chf-wrapper-write.off"), TOPOMESH_STATUS_INVALID_INPUT, "surfaces only");
    CHECK_THROWS(v.write_boundary("chf-wrapper-skin.node"), TOPOMESH_STATUS_INVALID_INPUT,
                 "tetrahedra only");
}

static void test_level_file() {
    Volume v = Volume::from_tetrahedra(PAIR, 5, PAIR_POS);
    v.save("chf-wrapper.chf");
    Volume back = Volume::open("chf-wrapper.chf", TOPOMESH_OPEN_CHECKSUMS_ONLY);
    CHECK(back.level() == v.level() && back.num_faces() == 7 && back.num_edges() == v.num_edges());
    CHECK_THROWS(Volume::open("no-such.chf"), TOPOMESH_STATUS_IO, "no-such.chf");
}

int main() {
    return run_tests("test_chf_wrapper", [] {
        test_build_and_counts();
        test_moves();
        test_relations();
        test_views_csr_boundary_summary();
        test_write();
        test_level_file();
    });
}
