// Tiny test harness shared by the C++ wrapper tests.
#ifndef TOPOMESH_TEST_CHECK_HPP
#define TOPOMESH_TEST_CHECK_HPP

#include <topomesh/topomesh.hpp>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

static int failures = 0;
// How many checks ran: run_tests() reports it, so a rewrite can show it dropped none.
static unsigned long check_count = 0;
#define CHECK(cond)                                                                        \
    do {                                                                                   \
        check_count++;                                                                     \
        if (!(cond)) {                                                                     \
            std::fprintf(stderr, "%s:%d: CHECK(%s) failed\n", __FILE__, __LINE__, #cond); \
            failures++;                                                                    \
        }                                                                                  \
    } while (0)

// Expects `expr` to throw topomesh::Error with `status` and a detail containing `needle`
// (which what() repeats).
#define CHECK_THROWS(expr, want, needle)                                                   \
    do {                                                                                   \
        bool thrown_ = false;                                                              \
        try {                                                                              \
            (void)(expr);                                                                  \
        } catch (const topomesh::Error &e) {                                               \
            thrown_ = true;                                                                \
            CHECK(e.status() == (want));                                                   \
            CHECK(e.detail().find(needle) != std::string::npos);                           \
            CHECK(std::string(e.what()).find(e.detail()) != std::string::npos);           \
        }                                                                                  \
        CHECK(thrown_);                                                                    \
    } while (0)

// Expects `expr` to return without throwing topomesh::Error (a throw names its detail).
#define CHECK_NOTHROW(expr)                                                                \
    do {                                                                                   \
        check_count++;                                                                     \
        try {                                                                              \
            (void)(expr);                                                                  \
        } catch (const topomesh::Error &e) {                                               \
            std::fprintf(stderr, "%s:%d: %s threw: %s\n", __FILE__, __LINE__, #expr,      \
                         e.what());                                                        \
            failures++;                                                                    \
        }                                                                                  \
    } while (0)

// The ids of a range as raw integers.
template <class T> static std::vector<std::uint32_t> raw(const T &range) {
    std::vector<std::uint32_t> out;
    for (auto id : range) out.push_back(id.value());
    return out;
}

// A live range (`live`) of mesh `m` lists the ids of `all` that are not removed, in order,
// as many as its size(); an iterator taken from a range that is gone still reads.
template <class Mesh, class All, class Live>
static void check_live(const Mesh &m, const All &all, Live (Mesh::*live)() const) {
    std::vector<std::uint32_t> want;
    for (auto id : all)
        if (!m.is_removed(id)) want.push_back(id.value());
    CHECK(raw((m.*live)()) == want && (m.*live)().size() == want.size());
    auto first = (m.*live)().begin();
    CHECK(want.empty() || (*first).value() == want[0]);
}

// The ownership rules of a wrapper mesh type (Surface, Volume), on two built meshes `a` and
// `other`: a move hands the handle over and leaves an empty mesh whose calls throw, a move
// assignment frees the target's own mesh, release() hands the handle out and the
// constructor adopts it again. `cells(m)` counts a's triangles or tetrahedra.
template <class Mesh, class Cells>
static void check_moves(Mesh a, Mesh other, Cells cells, std::size_t want_cells,
                        std::size_t want_edges) {
    const auto *h = a.handle();
    Mesh b = std::move(a);
    CHECK(b.handle() == h && a.handle() == nullptr);
    CHECK(a.num_vertices() == 0); // a moved-from mesh is empty
    CHECK_THROWS(a.summary(), TOPOMESH_STATUS_NULL_ARGUMENT, "'m'");
    CHECK_THROWS(a.vertex_vertices(topomesh::VertexId{0}), TOPOMESH_STATUS_NULL_ARGUMENT, "'m'");
    Mesh c = std::move(other);
    c = std::move(b); // frees other's mesh
    CHECK(c.handle() == h && cells(c) == want_cells);
    auto *released = c.release();
    CHECK(released == h && c.handle() == nullptr);
    Mesh d(released); // adopt again
    CHECK(d.num_edges() == want_edges);
}

// The end of a test's main: runs `body`, reports an unexpected exception or the failures.
template <class F> static int run_tests(const char *name, F body) {
    try {
        body();
    } catch (const std::exception &e) {
        std::fprintf(stderr, "unexpected exception: %s\n", e.what());
        return 1;
    }
    if (failures) {
        std::fprintf(stderr, "%s: %d check(s) failed\n", name, failures);
        return 1;
    }
    std::printf("%s: all %lu checks passed\n", name, check_count);
    return 0;
}

#endif
