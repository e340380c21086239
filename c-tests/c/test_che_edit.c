/* Editing a surface in place through the C API: every call, and every refusal (removed,
   out-of-range and NONE ids, boundary edges, the link condition, non-manifold and
   reversed additions, small map buffers) gives a status and a detail and leaves the
   mesh's arrays unchanged; the mesh validates after each call and after garbage
   collection, at every level. */
#include "check.h"

/* A closed octahedron: vertices 0 (top), 5 (bottom), 1-4 around. */
static const uint32_t OCTA[] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1,
                                5, 2, 1, 5, 3, 2, 5, 4, 3, 5, 1, 4};
static const double OCTA_XYZ[] = {0, 0, 1,  1, 0, 0,  0, 1, 0, -1, 0, 0,
                                  0, -1, 0, 0, 0, -1};

/* A copy of V (malloc'ed), to compare before and after a refusal. */
static uint32_t *copy_v(const che_mesh *m, size_t *len) {
    const uint32_t *v = che_mesh_half_edge_vertices(m, len);
    return copy_ids(v, *len);
}

/* `call` is refused with `want` and a detail containing `needle`, V unchanged. */
#define CHECK_REFUSED(m, call, want, needle)                                               \
    do {                                                                                   \
        size_t n0_, n1_;                                                                   \
        uint32_t *v0_ = copy_v(m, &n0_);                                                   \
        CHECK_STATUS(call, want);                                                          \
        CHECK_DETAIL(needle);                                                              \
        const uint32_t *v1_ = che_mesh_half_edge_vertices(m, &n1_);                        \
        CHECK(n0_ == n1_ && (n0_ == 0 || memcmp(v0_, v1_, n0_ * sizeof *v0_) == 0));       \
        CHECK_OK(che_mesh_validate(m));                                                    \
        free(v0_);                                                                         \
    } while (0)

/* Built strict: additions that would need a repair are refused. */
static void edit_at_level(uint32_t level) {
    che_mesh *m = NULL;
    che_build_options strict = che_build_options_default();
    strict.level = level;
    strict.strict = 1;
    CHECK_OK(che_mesh_from_triangles_ex(OCTA, 8, 6, OCTA_XYZ, &strict, &m));
    const uint32_t NONE = TOPOMESH_NONE;
    uint32_t x = NONE, t = NONE;
    bool flag = true;

    /* Vertices and triangles. */
    const double p[3] = {2, 2, 2};
    CHECK_OK(che_mesh_add_vertex(m, p, &x));
    CHECK(x == 6);
    CHECK_REFUSED(m, che_mesh_add_vertex(m, NULL, &x), TOPOMESH_STATUS_INVALID_INPUT,
                  "positions");
    CHECK_REFUSED(m, che_mesh_add_triangle(m, 0, 1, 2, &t), TOPOMESH_STATUS_INVALID_INPUT,
                  "duplicates");
    CHECK_REFUSED(m, che_mesh_add_triangle(m, 0, 1, 6, &t), TOPOMESH_STATUS_INVALID_INPUT,
                  "orientation");
    CHECK_REFUSED(m, che_mesh_add_triangle(m, 0, 6, 6, &t), TOPOMESH_STATUS_INVALID_INPUT,
                  "degenerate");
    CHECK_REFUSED(m, che_mesh_add_triangle(m, 0, 99, 6, &t), TOPOMESH_STATUS_OUT_OF_RANGE,
                  "99");
    CHECK_REFUSED(m, che_mesh_add_triangle(m, NONE, 1, 6, &t), TOPOMESH_STATUS_OUT_OF_RANGE,
                  "vertex");

    /* Remove a triangle, then put it back. */
    CHECK_OK(che_mesh_remove_triangle(m, 0));
    CHECK_OK(che_triangle_is_removed(m, 0, &flag));
    CHECK(flag);
    CHECK(che_mesh_num_live_triangles(m) == 7 && che_mesh_num_triangles(m) == 8);
    CHECK_REFUSED(m, che_mesh_remove_triangle(m, 0), TOPOMESH_STATUS_INVALID_INPUT,
                  "removed");
    CHECK_REFUSED(m, che_mesh_remove_triangle(m, 8), TOPOMESH_STATUS_OUT_OF_RANGE, "8");
    CHECK_OK(che_mesh_add_triangle(m, 0, 1, 2, &t));
    CHECK(t == 8);
    CHECK_OK(che_mesh_validate(m));

    /* Flip, split, collapse. */
    uint32_t e = NONE;
    CHECK_OK(che_half_edge_edge(m, 3 * 1, &e)); /* the edge 0-2 of triangle 1 */
    CHECK_OK(che_mesh_is_flip_ok(m, e, &flag));
    CHECK(flag);
    CHECK_OK(che_mesh_flip_edge(m, e));
    CHECK_OK(che_mesh_is_flip_ok(m, e, &flag));
    CHECK_OK(che_mesh_validate(m));
    CHECK_REFUSED(m, che_mesh_flip_edge(m, NONE), TOPOMESH_STATUS_OUT_OF_RANGE, "edge");
    CHECK_OK(che_mesh_split_edge(m, e, NULL, &x));
    CHECK(x == 7);
    CHECK_OK(che_mesh_split_triangle(m, 2, NULL, &x));
    CHECK(x == 8);
    CHECK_OK(che_mesh_validate(m));
    uint32_t h = 3 * 2; /* a half-edge of triangle 2, now around vertex 8 */
    CHECK_OK(che_mesh_is_collapse_ok(m, h, &flag));
    const bool collapsed = flag;
    if (flag) {
        CHECK_OK(che_mesh_collapse_edge(m, h, &x));
    } else {
        CHECK_REFUSED(m, che_mesh_collapse_edge(m, h, &x), TOPOMESH_STATUS_INVALID_INPUT,
                      "collapse_edge");
    }
    CHECK_OK(che_mesh_validate(m));
    const double q[3] = {0.5, 0.5, 0.5};
    CHECK_OK(che_mesh_set_position(m, 0, q));
    CHECK_REFUSED(m, che_mesh_set_position(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT,
                  "position_xyz");
    CHECK_REFUSED(m, che_mesh_set_position(m, 999, q), TOPOMESH_STATUS_OUT_OF_RANGE, "999");

    /* Remove the added vertex; the removed-element queries. */
    CHECK_OK(che_mesh_remove_vertex(m, 6));
    CHECK_OK(che_vertex_is_removed(m, 6, &flag));
    CHECK(flag);
    CHECK_REFUSED(m, che_mesh_remove_vertex(m, 6), TOPOMESH_STATUS_INVALID_INPUT, "removed");
    CHECK_STATUS(che_vertex_is_removed(m, 999, &flag), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(che_triangle_is_removed(m, 999, &flag), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(che_edge_is_removed(m, NONE, &flag), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_OK(che_edge_is_removed(m, 0, &flag));
    CHECK(che_mesh_num_live_vertices(m) == (collapsed ? 7u : 8u));
    CHECK(che_mesh_num_live_edges(m) > 0);
    CHECK_STATUS(che_mesh_flip_edge(NULL, 0), TOPOMESH_STATUS_NULL_ARGUMENT);

    /* Garbage collection: maps sized by the counts before it. */
    const size_t nv = che_mesh_num_vertices(m), nt = che_mesh_num_triangles(m),
                 ne = che_mesh_num_edges(m);
    uint32_t *vm = malloc(nv * sizeof *vm), *tm = malloc(nt * sizeof *tm),
             *em = malloc(ne * sizeof *em);
    if (!vm || !tm || !em) exit(2);
    CHECK_REFUSED(m, che_mesh_garbage_collect(m, vm, nv - 1, tm, nt, em, ne),
                  TOPOMESH_STATUS_BUFFER_TOO_SMALL, "vertex_map");
    /* One buffer lent for two maps: refused, before anything changes. */
    CHECK_REFUSED(m, che_mesh_garbage_collect(m, vm, nv, vm, nt, em, ne),
                  TOPOMESH_STATUS_INVALID_INPUT, "overlap");
    CHECK(che_mesh_num_live_vertices(m) < che_mesh_num_vertices(m));
    CHECK_OK(che_mesh_garbage_collect(m, vm, nv, tm, nt, em, ne));
    CHECK(vm[6] == NONE && vm[0] == 0);
    CHECK(tm[0] != NONE || nt > 0);
    CHECK(che_mesh_num_vertices(m) == che_mesh_num_live_vertices(m));
    CHECK(che_mesh_num_triangles(m) == che_mesh_num_live_triangles(m));
    CHECK_OK(che_mesh_validate(m));
    CHECK_OK(che_mesh_garbage_collect(m, NULL, 0, NULL, 0, NULL, 0));

    /* Collapse refused on the boundary fold: a lone triangle. */
    che_mesh *lone = NULL;
    const uint32_t one[] = {0, 1, 2};
    CHECK_OK(che_mesh_from_triangles(one, 1, 3, NULL, level, &lone));
    CHECK_OK(che_mesh_is_collapse_ok(lone, 0, &flag));
    CHECK(!flag);
    CHECK_REFUSED(lone, che_mesh_collapse_edge(lone, 0, &x), TOPOMESH_STATUS_INVALID_INPUT,
                  "fold");
    CHECK_REFUSED(lone, che_mesh_flip_edge(lone, 0), TOPOMESH_STATUS_INVALID_INPUT,
                  "boundary");
    CHECK_OK(che_mesh_add_vertex(lone, NULL, &x));
    CHECK_REFUSED(lone, che_mesh_add_vertex(lone, p, &x), TOPOMESH_STATUS_INVALID_INPUT,
                  "no positions");
    CHECK_REFUSED(lone, che_mesh_set_position(lone, 0, p), TOPOMESH_STATUS_INVALID_INPUT,
                  "no positions");
    CHECK_OK(che_mesh_remove_triangle(lone, 0));
    CHECK_OK(che_mesh_garbage_collect(lone, NULL, 0, NULL, 0, NULL, 0));
    CHECK(che_mesh_num_triangles(lone) == 0 && che_mesh_num_vertices(lone) == 4);
    CHECK_OK(che_mesh_validate(lone));
    che_mesh_free(lone);

    free(vm);
    free(tm);
    free(em);
    che_mesh_free(m);
}

/* Built non-strict (the default): the same additions are repaired as the build repairs
   its input, and the report counts them. */
static void repair_at_level(uint32_t level) {
    che_mesh *m = NULL;
    CHECK_OK(che_mesh_from_triangles(OCTA, 8, 6, OCTA_XYZ, level, &m));
    che_build_report r0, r1;
    CHECK_OK(che_mesh_report(m, &r0));
    uint32_t t = TOPOMESH_NONE, tv[3] = {0, 0, 0};
    size_t len = 0;

    /* A hole filled the wrong way round: the triangle is flipped to agree. */
    CHECK_OK(che_mesh_remove_triangle(m, 0));
    CHECK_OK(che_mesh_add_triangle(m, 0, 2, 1, &t));
    CHECK(t == 8);
    CHECK_OK(che_triangle_vertices(m, t, tv, 3, &len));
    CHECK(len == 3 && tv[0] == 0 && tv[1] == 1 && tv[2] == 2);
    CHECK_OK(che_mesh_report(m, &r1));
    CHECK(r1.flipped_triangles == r0.flipped_triangles + 1);
    CHECK_OK(che_mesh_validate(m));

    /* A duplicate: its three edges would carry three triangles each (non-manifold), so
       its corners are split off as the build splits them; the report lists the edges. */
    CHECK_OK(che_mesh_add_triangle(m, 0, 1, 2, &t));
    CHECK(t == 9);
    CHECK_OK(che_mesh_report(m, &r1));
    CHECK(r1.duplicate_triangles == r0.duplicate_triangles + 1);
    CHECK(r1.non_manifold_edges == r0.non_manifold_edges + 3);
    CHECK(r1.split_vertices == r0.split_vertices + 3);
    uint32_t pairs[32];
    CHECK_OK(che_mesh_report_examples(m, CHE_REPORT_KIND_NON_MANIFOLD_EDGE, pairs, 32, &len));
    CHECK(len == 6);
    CHECK_OK(che_mesh_validate(m));
    che_summary s;
    CHECK_OK(che_mesh_summary(m, &s));
    CHECK(s.triangles == 9);
    CHECK_OK(che_mesh_garbage_collect(m, NULL, 0, NULL, 0, NULL, 0));
    CHECK_OK(che_mesh_validate(m));
    che_mesh_free(m);
}

/* The checks never modify: every view taken before them (the origin maps included) is
   the same after them, and the mesh saves as one never edited. */
static void checks_at_level(uint32_t level) {
    che_mesh *m = NULL;
    che_build_options options = che_build_options_default();
    options.level = level;
    CHECK_OK(che_mesh_from_triangles_ex(OCTA, 8, 6, OCTA_XYZ, &options, &m));
    if (!m) return;
    size_t n_v = 0, n_origins = 0;
    const uint32_t *v = che_mesh_half_edge_vertices(m, &n_v);
    const uint32_t *origins = che_mesh_vertex_origins(m, &n_origins);
    uint32_t *before = copy_v(m, &n_v);
    size_t passed = 0;
    bool ok = false;
    for (uint32_t e = 0; e < che_mesh_num_edges(m); e++) {
        CHECK_OK(che_mesh_is_flip_ok(m, e, &ok));
        passed += ok;
    }
    for (uint32_t h = 0; h < che_mesh_num_half_edges(m); h++) {
        CHECK_OK(che_mesh_is_collapse_ok(m, h, &ok));
        passed += ok;
    }
    CHECK(passed > 0);
    /* A check needs its answer's place and the mesh. */
    CHECK_STATUS(che_mesh_is_flip_ok(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_mesh_is_collapse_ok(NULL, 0, &ok), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_mesh_is_flip_ok(m, TOPOMESH_NONE, &ok), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK(che_mesh_half_edge_vertices(m, NULL) == v && memcmp(v, before, n_v * sizeof *v) == 0);
    CHECK(che_mesh_vertex_origins(m, NULL) == origins && origins[5] == 5);
    CHECK_OK(che_mesh_save(m, "checks.che"));
    remove("checks.che");
    free(before);
    che_mesh_free(m);
}

int main(void) {
    for (uint32_t level = 0; level <= 3; level++) {
        checks_at_level(level);
        edit_at_level(level);
        repair_at_level(level);
    }
    return finish("test_che_edit");
}
