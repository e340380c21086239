// The C++17 wrapper: RAII, moves, strong ids, ranges, spans, CSR, errors.
#include "check.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

using namespace topomesh;

static_assert(!std::is_copy_constructible<Surface>::value, "move-only");
static_assert(!std::is_copy_assignable<Surface>::value, "move-only");
static_assert(std::is_nothrow_move_constructible<Surface>::value, "movable");
static_assert(std::is_nothrow_move_assignable<Surface>::value, "movable");
static_assert(std::is_base_of<std::runtime_error, Error>::value, "Error is a runtime_error");
static_assert(!std::is_convertible<VertexId, EdgeId>::value, "strong ids");
static_assert(!std::is_convertible<std::uint32_t, VertexId>::value, "explicit ids");
static_assert(std::is_same<Che, Surface>::value, "alias");


static const std::vector<std::uint32_t> STRIP = {0, 1, 2, 1, 3, 2};
static const std::vector<double> STRIP_POS = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
static const std::vector<std::uint32_t> TETRA = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

static void test_build_and_counts() {
    Surface s = Surface::from_triangles(STRIP, 4, STRIP_POS);
    CHECK(s.level() == 2);
    CHECK(s.num_vertices() == 4 && s.num_input_vertices() == 4 && s.num_triangles() == 2);
    CHECK(s.num_edges() == 5 && s.num_half_edges() == 6 && s.num_boundary_curves() == 1);
    s.build_level(3);
    CHECK(s.level() == 3);
    CHECK_THROWS(s.build_level(9), TOPOMESH_STATUS_OUT_OF_RANGE, "level 9");

    Surface t = Surface::from_triangles(TETRA.data(), 4, 4, nullptr, {0, true});
    CHECK(t.level() == 0 && t.num_edges() == 6);

    CHECK_THROWS(Surface::from_triangles(std::vector<std::uint32_t>{0, 1}, 3),
                 TOPOMESH_STATUS_INVALID_INPUT, "multiple of 3");
    CHECK_THROWS(Surface::from_triangles(STRIP, 4, std::vector<double>{0, 0}),
                 TOPOMESH_STATUS_INVALID_INPUT, "coordinates");
    CHECK_THROWS(Surface::from_triangles(STRIP, 3), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex 3");
    CHECK_THROWS(Surface::from_triangles({0, 1, 2, 0, 3, 4}, 5, {}, {2, true}),
                 TOPOMESH_STATUS_NON_MANIFOLD, "vertex 0");
    CHECK_THROWS(Surface::load("missing-file.xyz"), TOPOMESH_STATUS_IO, "missing-file.xyz");
}

static void test_moves() {
    check_moves(Surface::from_triangles(STRIP, 4), Surface::from_triangles(TETRA, 4),
                [](const Surface &m) { return m.num_triangles(); }, 2, 5);
}

static void test_relations_and_ranges() {
    Surface s = Surface::from_triangles(STRIP, 4);
    CHECK((raw(s.vertex_vertices(VertexId{1})) == std::vector<std::uint32_t>{3, 2, 0}));
    CHECK((raw(s.vertex_edges(VertexId{1})) == std::vector<std::uint32_t>{3, 1, 0}));
    CHECK((raw(s.vertex_triangles(VertexId{1})) == std::vector<std::uint32_t>{1, 0}));
    CHECK((raw(s.vertex_vertices(VertexId{1}).to_vector()) == std::vector<std::uint32_t>{3, 2, 0}));
    int steps = 0, closing = 0;
    for (const StarStep &st : s.star(VertexId{1})) {
        steps++;
        closing += st.closing();
        CHECK(st.half_edge.valid() && st.edge.valid());
        if (!st.closing()) CHECK(triangle_of(st.half_edge) == st.triangle);
    }
    CHECK(steps == 3 && closing == 1);
    CHECK_THROWS(s.star(VertexId{4}).begin(), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex 4");
    CHECK_THROWS(s.vertex_vertices(VertexId{}), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex");

    auto ev = s.edge_vertices(EdgeId{1});
    CHECK(ev[0] == VertexId{1} && ev[1] == VertexId{2});
    auto ef = s.edge_triangles(EdgeId{1});
    CHECK(ef.size() == 2 && ef[0] == TriangleId{0} && ef[1] == TriangleId{1});
    CHECK(s.edge_triangles(EdgeId{0}).size() == 1);
    CHECK((raw(s.edge_edges(EdgeId{1})) == std::vector<std::uint32_t>{2, 0, 3, 4}));
    auto fv = s.triangle_vertices(TriangleId{1});
    CHECK(fv[0] == VertexId{1} && fv[1] == VertexId{3} && fv[2] == VertexId{2});
    auto fe = s.triangle_edges(TriangleId{1});
    CHECK(fe[0] == EdgeId{3} && fe[1] == EdgeId{4} && fe[2] == EdgeId{1});
    auto ff = s.triangle_triangles(TriangleId{0});
    CHECK(!ff[0].valid() && ff[1] == TriangleId{1} && !ff[2].valid());
    CHECK_THROWS(s.triangle_vertices(TriangleId{2}), TOPOMESH_STATUS_OUT_OF_RANGE, "triangle 2");
    CHECK_THROWS(s.edge_vertices(EdgeId{5}), TOPOMESH_STATUS_OUT_OF_RANGE, "edge 5");
    CHECK((raw(s.boundary_curve_vertices(0)) == std::vector<std::uint32_t>{0, 1, 3, 2}));
    CHECK_THROWS(s.boundary_curve_vertices(1), TOPOMESH_STATUS_OUT_OF_RANGE, "curve 1");

    CHECK(s.opposite(HalfEdgeId{1}) == HalfEdgeId{5});
    CHECK(!s.opposite(HalfEdgeId{0}).valid());
    CHECK(s.edge(HalfEdgeId{5}) == EdgeId{1});
    CHECK(s.half_edge(VertexId{1}) == HalfEdgeId{3});
    CHECK(s.half_edge(EdgeId{4}) == HalfEdgeId{4});
    CHECK(s.curve(HalfEdgeId{0}) == 0 && s.curve(HalfEdgeId{1}) == none);
    CHECK(s.origin(HalfEdgeId{4}) == VertexId{3} && s.target(HalfEdgeId{4}) == VertexId{2});
    CHECK(s.is_boundary(VertexId{0}) && !s.is_boundary(EdgeId{1}) && s.is_boundary(EdgeId{0}));
    CHECK_THROWS(s.opposite(HalfEdgeId{6}), TOPOMESH_STATUS_OUT_OF_RANGE, "half-edge 6");
    CHECK(next(HalfEdgeId{2}) == HalfEdgeId{0} && prev(HalfEdgeId{3}) == HalfEdgeId{5});
    CHECK(first_half_edge(TriangleId{2}) == HalfEdgeId{6});
}

// The C API's answer for one element, as raw ids.
template <class F> static std::vector<std::uint32_t> c_answer(F f, const che_mesh *m, std::uint32_t id) {
    std::size_t len = 0;
    if (f(m, id, nullptr, 0, &len) != TOPOMESH_STATUS_OK) return {none};
    std::vector<std::uint32_t> out(len);
    if (len && f(m, id, out.data(), len, &len) != TOPOMESH_STATUS_OK) return {none};
    return out;
}

// half_edge(id) and is_boundary(id) of the wrapper against the C API's.
template <class Id, class HalfEdgeFn, class BoundaryFn>
static void same_half_edge_and_boundary(const Surface &s, Id id, HalfEdgeFn half_edge,
                                        BoundaryFn is_boundary) {
    std::uint32_t h = 0;
    bool b = false;
    CHECK(half_edge(s.handle(), id.value(), &h) == TOPOMESH_STATUS_OK && s.half_edge(id).value() == h);
    CHECK(is_boundary(s.handle(), id.value(), &b) == TOPOMESH_STATUS_OK && s.is_boundary(id) == b);
}

// Every relation of the wrapper (inline where the level stores the
// arrays) gives the C API's answer, at every level and after level changes.
static void check_against_c_api(const Surface &s) {
    const che_mesh *m = s.handle();
    for (std::uint32_t v = 0; v < s.num_vertices(); v++) {
        CHECK(raw(s.vertex_vertices(VertexId{v})) == c_answer(che_vertex_vertices, m, v));
        CHECK(raw(s.vertex_edges(VertexId{v})) == c_answer(che_vertex_edges, m, v));
        CHECK(raw(s.vertex_triangles(VertexId{v})) == c_answer(che_vertex_triangles, m, v));
        std::vector<std::uint32_t> star;
        for (const StarStep &st : s.star(VertexId{v})) star.push_back(st.vertex.value());
        CHECK(star == c_answer(che_vertex_vertices, m, v));
        same_half_edge_and_boundary(s, VertexId{v}, che_vertex_half_edge, che_vertex_is_boundary);
    }
    for (std::uint32_t e = 0; e < s.num_edges(); e++) {
        CHECK(raw(s.edge_vertices(EdgeId{e})) == c_answer(che_edge_vertices, m, e));
        CHECK(raw(s.edge_triangles(EdgeId{e})) == c_answer(che_edge_triangles, m, e));
        same_half_edge_and_boundary(s, EdgeId{e}, che_edge_half_edge, che_edge_is_boundary);
    }
    for (std::uint32_t t = 0; t < s.num_triangles(); t++) {
        CHECK(raw(s.triangle_vertices(TriangleId{t})) == c_answer(che_triangle_vertices, m, t));
        CHECK(raw(s.triangle_triangles(TriangleId{t})) == c_answer(che_triangle_triangles, m, t));
    }
    for (std::uint32_t h = 0; h < s.num_half_edges(); h++) {
        std::uint32_t o = 0;
        CHECK(che_half_edge_opposite(m, h, &o) == TOPOMESH_STATUS_OK && s.opposite(HalfEdgeId{h}).value() == o);
        CHECK(s.origin(HalfEdgeId{h}) == VertexId{s.half_edge_vertices()[h]});
    }
    // Past the end: the C API's errors, whatever the path.
    const std::uint32_t nv = static_cast<std::uint32_t>(s.num_vertices()),
                        ne = static_cast<std::uint32_t>(s.num_edges()),
                        nt = static_cast<std::uint32_t>(s.num_triangles()),
                        nh = static_cast<std::uint32_t>(s.num_half_edges());
    CHECK_THROWS(s.vertex_vertices(VertexId{nv}), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex");
    CHECK_THROWS(s.vertex_triangles(VertexId{nv}), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex");
    CHECK_THROWS(s.half_edge(VertexId{nv}), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex");
    CHECK_THROWS(s.is_boundary(VertexId{nv}), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex");
    CHECK_THROWS(s.edge_vertices(EdgeId{ne}), TOPOMESH_STATUS_OUT_OF_RANGE, "edge");
    CHECK_THROWS(s.edge_triangles(EdgeId{ne}), TOPOMESH_STATUS_OUT_OF_RANGE, "edge");
    CHECK_THROWS(s.half_edge(EdgeId{ne}), TOPOMESH_STATUS_OUT_OF_RANGE, "edge");
    CHECK_THROWS(s.is_boundary(EdgeId{ne}), TOPOMESH_STATUS_OUT_OF_RANGE, "edge");
    CHECK_THROWS(s.triangle_vertices(TriangleId{nt}), TOPOMESH_STATUS_OUT_OF_RANGE, "triangle");
    CHECK_THROWS(s.triangle_triangles(TriangleId{nt}), TOPOMESH_STATUS_OUT_OF_RANGE, "triangle");
    CHECK_THROWS(s.opposite(HalfEdgeId{nh}), TOPOMESH_STATUS_OUT_OF_RANGE, "half-edge");
    CHECK_THROWS(s.opposite(HalfEdgeId{}), TOPOMESH_STATUS_OUT_OF_RANGE, "half-edge");
}

// The removed flags and positions the wrapper reads inline agree with the C calls after
// every kind of edit (arrays grow, move and gain removed elements).
static void check_edit_views(const Surface &s) {
    const che_mesh *m = s.handle();
    std::size_t len = 0;
    const double *p = che_mesh_positions(m, &len);
    for (std::uint32_t v = 0; v < s.num_vertices(); v++) {
        const Vec3 q = s.position(VertexId{v});
        CHECK(len >= 3 * (v + 1) && q.x == p[3 * v] && q.y == p[3 * v + 1] && q.z == p[3 * v + 2]);
    }
    for (std::uint32_t t = 0; t < s.num_triangles(); t++) {
        bool c = false;
        CHECK(che_triangle_is_removed(m, t, &c) == TOPOMESH_STATUS_OK);
        CHECK(s.is_removed(TriangleId{t}) == c);
    }
    for (std::uint32_t e = 0; e < s.num_edges(); e++) {
        bool c = false;
        CHECK(che_edge_is_removed(m, e, &c) == TOPOMESH_STATUS_OK);
        CHECK(s.is_removed(EdgeId{e}) == c);
    }
    check_live(s, s.vertices(), &Surface::live_vertices);
    check_live(s, s.triangles(), &Surface::live_triangles);
    check_live(s, s.edges(), &Surface::live_edges);
    CHECK_THROWS(s.position(VertexId{static_cast<std::uint32_t>(s.num_vertices())}),
                 TOPOMESH_STATUS_OUT_OF_RANGE, "vertex");
    CHECK_THROWS(s.is_removed(EdgeId{static_cast<std::uint32_t>(s.num_edges())}),
                 TOPOMESH_STATUS_OUT_OF_RANGE, "edge");
}

static void test_edit_views() {
    // A 4 x 4 grid with positions, at levels 2 and 3.
    std::vector<std::uint32_t> tris;
    std::vector<double> pos;
    const std::uint32_t g = 4;
    for (std::uint32_t i = 0; i <= g; i++)
        for (std::uint32_t j = 0; j <= g; j++) pos.insert(pos.end(), {double(j), double(i), 0.0});
    for (std::uint32_t i = 0; i < g; i++)
        for (std::uint32_t j = 0; j < g; j++) {
            std::uint32_t a = i * (g + 1) + j, b = a + 1, c = a + g + 1, d = c + 1;
            tris.insert(tris.end(), {a, b, d, a, d, c});
        }
    for (std::uint32_t level : {2u, 3u}) {
        Surface s = Surface::from_triangles(tris, (g + 1) * (g + 1), pos, Options{level, false});
        check_edit_views(s);
        s.flip(s.edge(HalfEdgeId{2}));
        check_edit_views(s);
        const Vec3 mid{0.5, 0.25, 0.0};
        s.split(s.edge(HalfEdgeId{7}), &mid);
        check_edit_views(s);
        s.set_position(VertexId{12}, Vec3{2.0, 2.0, 1.0});
        check_edit_views(s);
        std::uint32_t h = 3 * 10;
        while (!s.is_collapse_ok(HalfEdgeId{h})) h++;
        s.collapse(HalfEdgeId{h});
        check_edit_views(s);
        std::uint32_t t = 5;
        while (s.is_removed(TriangleId{t})) t++;
        s.remove(TriangleId{t});
        check_edit_views(s);
        s.garbage_collect();
        check_edit_views(s);
    }
}

static void test_inline_paths() {
    // A 6 x 6 grid with its middle quad missing (a boundary inside), plus a tetrahedron.
    std::vector<std::uint32_t> tris;
    const std::uint32_t g = 6;
    for (std::uint32_t i = 0; i < g; i++)
        for (std::uint32_t j = 0; j < g; j++) {
            if (i == 2 && j == 2) continue;
            std::uint32_t a = i * (g + 1) + j, b = a + 1, c = a + g + 1, d = c + 1;
            tris.insert(tris.end(), {a, b, d, a, d, c});
        }
    const std::uint32_t nv = (g + 1) * (g + 1);
    for (std::uint32_t x : TETRA) tris.push_back(nv + x);
    for (std::uint32_t level = 0; level <= 3; level++) {
        Surface s = Surface::from_triangles(tris, nv + 4, {}, Options{level, false});
        check_against_c_api(s);
        // Level changes through the wrapper refetch the arrays.
        for (std::uint32_t other : {3u, 1u, 0u, 2u}) {
            s.build_level(other);
            check_against_c_api(s);
        }
        // Through the C handle, then refresh().
        CHECK(che_mesh_build_level(s.handle(), level) == TOPOMESH_STATUS_OK);
        s.refresh();
        check_against_c_api(s);
        // A moved Surface keeps its arrays; the moved-from one has none and no handle.
        Surface t = std::move(s);
        check_against_c_api(t);
    }
    // High degrees, around the inline capacity of Ids (32): open fans and closed ones
    // (double cones) around vertex 0.
    for (std::uint32_t k : {15u, 16u, 17u, 31u, 32u, 33u, 40u}) {
        std::vector<std::uint32_t> fan;
        for (std::uint32_t i = 0; i < k; i++) fan.insert(fan.end(), {0, 1 + i, 2 + i});
        std::vector<std::uint32_t> cone;
        for (std::uint32_t i = 0; i < k; i++) {
            const std::uint32_t a = 1 + i, b = 1 + (i + 1) % k;
            cone.insert(cone.end(), {0, a, b, k + 1, b, a});
        }
        for (std::uint32_t level = 1; level <= 3; level++) {
            Surface f = Surface::from_triangles(fan, k + 2, {}, Options{level, false});
            check_against_c_api(f);
            CHECK(raw(f.vertex_vertices(VertexId{0})).size() == k + 1);
            Surface c = Surface::from_triangles(cone, k + 2, {}, Options{level, false});
            check_against_c_api(c);
            CHECK(raw(c.vertex_triangles(VertexId{0})).size() == k);
        }
    }
    // Relations of a Surface without a handle fail as the C API does.
    Surface empty(nullptr);
    CHECK_THROWS(empty.vertex_vertices(VertexId{0}), TOPOMESH_STATUS_NULL_ARGUMENT, "m");
    CHECK_THROWS(empty.triangle_triangles(TriangleId{0}), TOPOMESH_STATUS_NULL_ARGUMENT, "m");
}

// The star of every vertex, one step as four raw ids, walked by one iterator.
static std::vector<std::uint32_t> star_steps(const StarRange &range) {
    std::vector<std::uint32_t> out;
    for (const StarStep &st : range)
        out.insert(out.end(), {st.half_edge.value(), st.vertex.value(), st.edge.value(),
                               st.triangle.value()});
    return out;
}

// Every iterator of a StarRange has its own state: two iterators of one range interleaved,
// and one const range shared by threads, each give the single-threaded walk.
static void test_star_range_iterators() {
    std::vector<std::uint32_t> tris; // an 8 x 8 grid: vertices of degree 2 to 6
    const std::uint32_t g = 8;
    for (std::uint32_t i = 0; i < g; i++)
        for (std::uint32_t j = 0; j < g; j++) {
            std::uint32_t a = i * (g + 1) + j, b = a + 1, c = a + g + 1, d = c + 1;
            tris.insert(tris.end(), {a, b, d, a, d, c});
        }
    const std::uint32_t nv = (g + 1) * (g + 1);
    for (std::uint32_t level = 0; level <= 3; level++) {
        const Surface s = Surface::from_triangles(tris, nv, {}, Options{level, false});
        std::vector<StarRange> ranges;
        std::vector<std::vector<std::uint32_t>> expected;
        for (std::uint32_t v = 0; v < nv; v++) {
            ranges.push_back(s.star(VertexId{v}));
            expected.push_back(star_steps(ranges.back()));
            CHECK(expected.back().size() == 4 * s.vertex_vertices(VertexId{v}).size());
        }

        // Two iterators of one range, stepped in turn: the second starts when the first is
        // one step in, and both see every step.
        for (std::uint32_t v = 0; v < nv; v++) {
            const StarRange &r = ranges[v];
            auto a = r.begin();
            std::vector<std::uint32_t> seen_a, seen_b;
            if (a != r.end()) {
                seen_a.push_back(a->vertex.value());
                ++a;
            }
            auto b = r.begin();
            while (a != r.end() || b != r.end()) {
                if (b != r.end()) {
                    seen_b.push_back(b->vertex.value());
                    ++b;
                }
                if (a != r.end()) {
                    seen_a.push_back(a->vertex.value());
                    ++a;
                }
            }
            const std::vector<std::uint32_t> want = raw(s.vertex_vertices(VertexId{v}));
            CHECK(seen_a == want && seen_b == want);
        }

        // Threads walking the same const ranges many times at once.
        const std::vector<StarRange> &shared = ranges;
        std::vector<int> mismatches(4, 0);
        std::vector<std::thread> threads;
        for (std::size_t t = 0; t < mismatches.size(); t++)
            threads.emplace_back([&shared, &expected, &mismatches, t] {
                for (int round = 0; round < 50; round++)
                    for (std::size_t v = 0; v < shared.size(); v++)
                        if (star_steps(shared[v]) != expected[v]) mismatches[t]++;
            });
        for (std::thread &t : threads) t.join();
        for (int m : mismatches) CHECK(m == 0);
    }
}

// The old names stay for one release and answer as the new ones.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#endif
static void test_deprecated_names() {
    Surface s = Surface::from_triangles(STRIP, 4);
    CHECK(s.vertices_around(VertexId{1}) == s.vertex_vertices(VertexId{1}));
    CHECK(s.edges_around(VertexId{1}) == s.vertex_edges(VertexId{1}));
    CHECK(s.triangles_around(VertexId{1}) == s.vertex_triangles(VertexId{1}));
    static_assert(std::is_same<VerticesAround, Ids<VertexId>>::value, "old range name");
    static_assert(std::is_same<IdList<FaceId>, Ids<FaceId>>::value, "old list name");
}
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

// Ids: inline up to its capacity, on the heap past it (when it grows), a value type.
static void test_ids() {
    Ids<VertexId, 32> a;
    for (std::uint32_t i = 0; i < 40; i++) a.push_back(VertexId{i});
    CHECK(a.size() == 40 && a[31] == VertexId{31} && a[39] == VertexId{39} && a.back() == VertexId{39});
    Ids<VertexId, 32> b = a;
    CHECK(b == a && b.raw().size() == 40 && b.raw()[35] == 35);
    Ids<VertexId, 32> c = std::move(b);
    CHECK(c == a);
    Ids<EdgeId, 3> small;
    for (std::uint32_t i = 0; i < 3; i++) small.push_back(EdgeId{i});
    Ids<EdgeId, 3> small2;
    small2 = small;
    CHECK(small2 == small && small2.front() == EdgeId{0} && *(small2.end() - 1) == EdgeId{2});
    bool length = false;
    try {
        small.push_back(EdgeId{3});
    } catch (const std::length_error &) {
        length = true;
    }
    CHECK(length);
    static_assert(Ids<VertexId>::grows && !Ids<VertexId, 3>::grows, "bounded Ids do not grow");
}

static void test_views_csr_summary() {
    Surface s = Surface::from_triangles(STRIP, 4, STRIP_POS, {1});
    CHECK((s.half_edge_vertices().to_vector() == STRIP));
    CHECK(s.opposites().size() == 6 && s.opposites()[1] == 5);
    CHECK(s.vertex_half_edges().empty() && s.edge_half_edges().empty());
    CHECK(s.curve_half_edges().empty());
    CHECK((s.positions().to_vector() == STRIP_POS));
    CHECK((s.vertex_origins().to_vector() == std::vector<std::uint32_t>{0, 1, 2, 3}));
    CHECK((s.triangle_origins().to_vector() == std::vector<std::uint32_t>{0, 1}));
    std::uint32_t sum = 0;
    for (std::uint32_t v : s.half_edge_vertices()) sum += v;
    CHECK(sum == 9);
    s.build_level(3);
    CHECK((s.vertex_half_edges().to_vector() == std::vector<std::uint32_t>{0, 3, 2, 4}));
    CHECK(s.edge_half_edges().size() == 5 && s.curve_half_edges().size() == 1);
    bool out_of_range = false;
    try {
        (void)s.half_edge_vertices().at(6);
    } catch (const std::out_of_range &) {
        out_of_range = true;
    }
    CHECK(out_of_range);

    Csr vv = s.vertex_vertices_csr();
    CHECK(vv.rows() == 4);
    CHECK((vv.offsets == std::vector<std::uint32_t>{0, 2, 5, 8, 10}));
    CHECK((vv.row(1).to_vector() == std::vector<std::uint32_t>{3, 2, 0}));
    CHECK(s.vertex_edges_csr().indices.size() == 10);
    CHECK(s.vertex_triangles_csr().indices.size() == 6);
    Csr ff = s.triangle_triangles_csr();
    CHECK((ff.indices == std::vector<std::uint32_t>{none, 1, none, none, none, 0}));

    CHECK_NOTHROW(s.validate());
    Surface::Summary sum2 = s.summary();
    static_assert(std::is_same<decltype(sum2.vertices), std::size_t>::value, "C++ counts");
    CHECK(sum2.vertices == 4 && sum2.edges == 5 && sum2.euler_characteristic == 1);
    CHECK(sum2.genus == 0 && sum2.boundary_curves == 1 && sum2.manifold && sum2.orientable);
    const che_summary raw_sum = s.raw_summary();
    CHECK(raw_sum.vertices == 4 && raw_sum.triangles == sum2.triangles && raw_sum.genus == 0);
    Surface::BuildReport r = s.report();
    CHECK(r.input_triangles == 2 && r.boundary_edges == 4);
    CHECK(s.raw_report().input_triangles == 2);
    CHECK(s.report_examples(CHE_REPORT_KIND_DEGENERATE).empty());
    che_memory m = s.memory();
    CHECK(m.half_edge_vertices == 24 && m.positions == 96);

    Surface bow = Surface::from_triangles({0, 1, 2, 0, 3, 4}, 5);
    CHECK(bow.num_vertices() == 6 && bow.vertex_origins()[5] == 0);
    CHECK((bow.report_examples(CHE_REPORT_KIND_SPLIT_VERTEX) == std::vector<std::uint32_t>{0}));
    CHECK(version() == topomesh_version());
}

static void test_write() {
    Surface s = Surface::from_triangles(STRIP, 4, STRIP_POS);
    s.write("che-wrapper-write.ply", TOPOMESH_WRITE_BINARY);
    Surface back = Surface::load("che-wrapper-write.ply");
    CHECK(back.num_vertices() == 4 && back.num_triangles() == 2);
    CHECK(std::equal(back.half_edge_vertices().begin(), back.half_edge_vertices().end(),
                     s.half_edge_vertices().begin()));
    CHECK_THROWS(s.write("che-wrapper-write.off", 64), TOPOMESH_STATUS_INVALID_INPUT,
                 "unknown bits");
    CHECK_THROWS(s.write("no-such-folder/s.off"), TOPOMESH_STATUS_IO, "no-such-folder/s.off");
    CHECK(!std::ifstream("che-wrapper-write.off").good());
}

static void test_level_file() {
    Surface s = Surface::from_triangles(STRIP, 4, STRIP_POS);
    s.save("che-wrapper.che");
    Surface back = Surface::open("che-wrapper.che");
    CHECK(back.level() == s.level() && back.num_edges() == s.num_edges());
    CHECK(std::equal(back.half_edge_vertices().begin(), back.half_edge_vertices().end(),
                     s.half_edge_vertices().begin()));
    CHECK_THROWS(Surface::open("che-wrapper-write.ply"), TOPOMESH_STATUS_PARSE, "magic");
    CHECK_THROWS(Surface::open("che-wrapper.che", 8), TOPOMESH_STATUS_INVALID_INPUT,
                 "unknown bits");
}

int main() {
    return run_tests("test_che_wrapper", [] {
        test_build_and_counts();
        test_moves();
        test_relations_and_ranges();
        test_inline_paths();
        test_edit_views();
        test_views_csr_summary();
        test_star_range_iterators();
        test_deprecated_names();
        test_ids();
        test_write();
        test_level_file();
    });
}
