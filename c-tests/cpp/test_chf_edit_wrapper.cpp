// The Volume editing methods of the C++ wrapper, against the C API they call: each edit
// and each refusal (an Error carrying the status, the volume unchanged) at every level.
#include "check.hpp"

#include <topomesh/topomesh.hpp>

#include <vector>

using namespace topomesh;

// Two positive tetrahedra sharing the face (1, 2, 3).
static const std::vector<std::uint32_t> PAIR = {0, 1, 2, 3, 4, 1, 3, 2};
static const std::vector<double> PAIR_POS = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};

// The live ranges skip exactly the removed elements.
static void check_live_ranges(const Volume &m) {
    check_live(m, m.vertices(), &Volume::live_vertices);
    check_live(m, m.edges(), &Volume::live_edges);
    check_live(m, m.faces(), &Volume::live_faces);
    check_live(m, m.tetrahedra(), &Volume::live_tetrahedra);
}

template <class F> static topomesh_status refused(Volume &m, F &&edit) {
    const std::size_t t0 = m.num_live_tetrahedra(), v0 = m.num_live_vertices();
    topomesh_status s = TOPOMESH_STATUS_OK;
    try {
        edit();
    } catch (const Error &e) {
        s = e.status();
    }
    CHECK(m.num_live_tetrahedra() == t0 && m.num_live_vertices() == v0);
    m.validate();
    return s;
}

static void at_level(std::uint32_t level) {
    Options o;
    o.level = level;
    Volume m = Volume::from_tetrahedra(PAIR, 5, PAIR_POS, o);
    const Vec3 p{2, 2, 2};
    const VertexId x = m.add_vertex(&p);
    CHECK(x.value() == 5 && m.num_live_vertices() == 6);
    CHECK(refused(m, [&] { m.add_vertex(); }) == TOPOMESH_STATUS_INVALID_INPUT);
    const TetrahedronId t = m.add_tetrahedron(VertexId{1}, VertexId{2}, VertexId{4}, x);
    CHECK(t.value() == 2 && m.num_live_tetrahedra() == 3);
    CHECK(refused(m, [&] { m.add_tetrahedron(VertexId{0}, VertexId{1}, VertexId{2},
                                              VertexId{3}); }) == TOPOMESH_STATUS_NON_MANIFOLD);
    m.remove(t);
    CHECK(m.is_removed(t) && !m.is_removed(TetrahedronId{0}));
    CHECK(refused(m, [&] { m.remove(t); }) == TOPOMESH_STATUS_OUT_OF_RANGE);

    const FaceId shared = m.face(HalfFaceId{0}), outer = m.face(HalfFaceId{1});
    CHECK(m.can_flip_23(shared) && !m.can_flip_23(outer));
    CHECK(m.is_flip_23_ok(shared) && !m.is_flip_23_ok(outer));
    CHECK_THROWS(m.is_flip_23_ok(FaceId{none}), TOPOMESH_STATUS_OUT_OF_RANGE, "face");
    CHECK(!m.can_flip_23(FaceId{none}));
    CHECK(refused(m, [&] { m.flip_23(outer); }) == TOPOMESH_STATUS_INVALID_INPUT);
    const auto three = m.flip_23(shared);
    CHECK(m.num_live_tetrahedra() == 3 && m.is_removed(shared));
    EdgeId inner{none};
    for (EdgeId e : m.tetrahedron_edges(three[0]))
        if (m.can_flip_32(e)) inner = e;
    CHECK(inner.value() != none);
    const auto two = m.flip_32(inner);
    CHECK(m.num_live_tetrahedra() == 2 && m.is_removed(inner) && !m.is_removed(two[0]));

    const Vec3 outside{5, 5, 5};
    CHECK(!m.can_split(two[0], &outside) && m.can_split(two[0]));
    CHECK(refused(m, [&] { m.split(two[0], &outside); }) == TOPOMESH_STATUS_INVALID_INPUT);
    const VertexId c = m.split(two[0]);
    CHECK(m.num_live_tetrahedra() == 5);
    const VertexId d = m.split(m.vertex_faces(c)[0]);
    const VertexId e = m.split(m.vertex_edges(d)[0]);
    CHECK(e.value() == d.value() + 1);
    m.validate();
    std::uint64_t good = ~0ull;
    for (TetrahedronId s : m.vertex_tetrahedra(e))
        for (std::uint64_t he = 12ull * s.value(); he < 12ull * s.value() + 12; he++)
            if (good == ~0ull && m.can_collapse(he)) good = he;
    CHECK(good != ~0ull);
    const std::size_t live = m.num_live_vertices();
    const VertexId kept = m.collapse(good);
    CHECK(!m.is_removed(kept) && m.num_live_vertices() == live - 1);
    CHECK(refused(m, [&] { m.collapse(~0ull); }) == TOPOMESH_STATUS_OUT_OF_RANGE);
    m.remove(VertexId{5});
    CHECK(m.is_removed(VertexId{5}));
    CHECK(m.num_live_faces() < m.num_faces() && m.num_live_edges() < m.num_edges());
    check_live_ranges(m);

    const std::size_t lv = m.num_live_vertices(), lt = m.num_live_tetrahedra();
    const auto maps = m.garbage_collect();
    CHECK(maps.vertices.size() > lv && maps.vertices[5] == none && maps.tetrahedra[2] == none);
    CHECK(maps.faces.size() > m.num_faces() && maps.edges.size() > m.num_edges());
    CHECK(m.num_vertices() == lv && m.num_tetrahedra() == lt);
    CHECK(m.summary().tetrahedra == lt);
    check_live_ranges(m);
    m.validate();
}

int main() {
    return run_tests("test_chf_edit_wrapper", [] {
        for (std::uint32_t level = 0; level <= 3; level++) at_level(level);
    });
}
