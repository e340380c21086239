/* Building, levels, counts, summary, report, memory, origins, strict mode. */
#include "check.h"

/* The counts of a mesh, in the order the tests give their expected values. */
static const struct {
    const char *name;
    size_t (*fn)(const che_mesh *);
} COUNTS[] = {
    {"vertices", che_mesh_num_vertices},   {"input vertices", che_mesh_num_input_vertices},
    {"triangles", che_mesh_num_triangles}, {"edges", che_mesh_num_edges},
    {"half-edges", che_mesh_num_half_edges}, {"boundary curves", che_mesh_num_boundary_curves},
};
#define N_COUNTS (sizeof COUNTS / sizeof COUNTS[0])

/* Every count of m (of mesh `name`) is the one expected. */
static void check_counts(const char *name, const che_mesh *m, const size_t want[N_COUNTS]) {
    for (size_t i = 0; i < N_COUNTS; i++) {
        const size_t got = COUNTS[i].fn(m);
        CHECK(got == want[i]);
        if (got != want[i])
            fprintf(stderr, "  %s of %s: %zu, expected %zu\n", COUNTS[i].name, name, got, want[i]);
    }
}

static void test_argument_errors(void) {
    che_mesh *m = (che_mesh *)&m; /* must be reset to NULL on failure */
    CHECK_STATUS(che_mesh_from_triangles(NULL, 2, 4, NULL, 2, &m), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK(m == NULL);
    CHECK_DETAIL("triangles");
    CHECK_STATUS(che_mesh_from_triangles(STRIP, 2, 4, NULL, 2, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("out");
    m = (che_mesh *)&m;
    CHECK_STATUS(che_mesh_from_triangles(STRIP, 2, 4, NULL, 4, &m), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK(m == NULL);
    CHECK_DETAIL("level 4");
    CHECK_STATUS(che_mesh_from_triangles(STRIP, 2, 4, NULL, 0xFFFFFFFFu, &m),
                 TOPOMESH_STATUS_OUT_OF_RANGE);
    /* A vertex id >= n_vertices. */
    CHECK_STATUS(che_mesh_from_triangles(STRIP, 2, 3, NULL, 2, &m), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK(m == NULL);
    CHECK_DETAIL("vertex 3");
    /* Sizes beyond 32-bit ids fail before the arrays are read. */
    CHECK_STATUS(che_mesh_from_triangles(STRIP, (size_t)1 << 31, 4, NULL, 2, &m),
                 TOPOMESH_STATUS_TOO_LARGE);
    CHECK_STATUS(che_mesh_from_triangles(STRIP, 2, (size_t)UINT32_MAX, NULL, 2, &m),
                 TOPOMESH_STATUS_TOO_LARGE);
    CHECK(m == NULL);
    /* Empty input: NULL triangles are fine when there are none. */
    CHECK_OK(che_mesh_from_triangles(NULL, 0, 3, NULL, 3, &m));
    CHECK(m != NULL);
    CHECK(che_mesh_num_vertices(m) == 3 && che_mesh_num_triangles(m) == 0);
    CHECK(che_mesh_num_edges(m) == 0 && che_mesh_num_boundary_curves(m) == 0);
    che_summary s;
    CHECK_OK(che_mesh_summary(m, &s));
    CHECK(s.vertices == 3 && s.isolated_vertices == 3 && s.components == 0);
    che_mesh_free(m);

    /* Options. */
    che_build_options o = che_build_options_default();
    CHECK(o.level == 2 && !o.strict && o.threads == 0 && o.weld_tolerance == 0.0);
    CHECK_OK(che_mesh_from_triangles_ex(STRIP, 2, 4, NULL, NULL, &m));
    CHECK(che_mesh_level(m) == 2);
    che_mesh_free(m);
    for (uint32_t threads = 1; threads <= 3; ++threads) {
        o.threads = threads;
        CHECK_OK(che_mesh_from_triangles_ex(STRIP, 2, 4, NULL, &o, &m));
        CHECK(che_mesh_num_triangles(m) == 2 && che_mesh_num_edges(m) == 5);
        che_mesh_free(m);
    }
    o.threads = 0;
    o.level = 7;
    CHECK_STATUS(che_mesh_from_triangles_ex(STRIP, 2, 4, NULL, &o, &m), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(che_mesh_from_triangles_ex(STRIP, 2, 4, NULL, &o, NULL),
                 TOPOMESH_STATUS_NULL_ARGUMENT);

    /* NULL handles: counts are 0, free is a no-op, calls that fail say so. */
    che_mesh_free(NULL);
    CHECK(che_mesh_level(NULL) == 0);
    check_counts("NULL", NULL, (const size_t[N_COUNTS]){0});
    CHECK_STATUS(che_mesh_build_level(NULL, 2), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_mesh_summary(NULL, &s), TOPOMESH_STATUS_NULL_ARGUMENT);
    che_build_report r;
    CHECK_STATUS(che_mesh_report(NULL, &r), TOPOMESH_STATUS_NULL_ARGUMENT);
    che_memory mem;
    CHECK_STATUS(che_mesh_memory(NULL, &mem), TOPOMESH_STATUS_NULL_ARGUMENT);
}

static void test_tetrahedron(void) {
    che_mesh *m = make(TETRA, 4, 4, TETRA_POS, 2);
    CHECK(che_mesh_level(m) == 2);
    check_counts("tetrahedron", m, (const size_t[N_COUNTS]){4, 4, 4, 6, 12, 0});
    che_summary s;
    CHECK_STATUS(che_mesh_summary(m, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_OK(che_mesh_summary(m, &s));
    CHECK(s.vertices == 4 && s.edges == 6 && s.triangles == 4);
    CHECK(s.boundary_edges == 0 && s.boundary_curves == 0 && s.components == 1);
    CHECK(s.isolated_vertices == 0 && s.euler_characteristic == 2 && s.genus == 0);
    CHECK(s.orientable && s.manifold);
    CHECK(s.dropped_degenerate == 0 && s.non_manifold_edges == 0 && s.split_vertices == 0);
    CHECK(s.flipped_triangles == 0 && s.non_orientable_components == 0);

    /* Memory per level: V is 3T ints, O doubles it; positions apart. */
    che_memory mem;
    CHECK_STATUS(che_mesh_memory(m, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_OK(che_mesh_build_level(m, 0));
    CHECK_OK(che_mesh_memory(m, &mem));
    CHECK(mem.half_edge_vertices == 48 && mem.opposites == 0 && mem.topology == 48);
    CHECK(mem.positions == 4 * 3 * sizeof(double));
    CHECK_OK(che_mesh_build_level(m, 1));
    CHECK_OK(che_mesh_memory(m, &mem));
    CHECK(mem.opposites == 48 && mem.topology == 96);
    CHECK_OK(che_mesh_build_level(m, 2));
    CHECK_OK(che_mesh_memory(m, &mem));
    CHECK(mem.vertex_half_edges == 16 && mem.edges >= 24 && mem.curves == 0);
    uint64_t l2 = mem.topology;
    CHECK(l2 == mem.half_edge_vertices + mem.opposites + mem.vertex_half_edges + mem.edges);
    CHECK_OK(che_mesh_build_level(m, 3));
    CHECK_OK(che_mesh_memory(m, &mem));
    CHECK(mem.topology >= l2);
    CHECK(che_mesh_level(m) == 3);
    CHECK_STATUS(che_mesh_build_level(m, 4), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK(che_mesh_level(m) == 3);
    /* Counts do not depend on the level. */
    for (uint32_t level = 0; level <= 3; level++) {
        CHECK_OK(che_mesh_build_level(m, level));
        CHECK(che_mesh_level(m) == level);
        CHECK(che_mesh_num_edges(m) == 6 && che_mesh_num_boundary_curves(m) == 0);
    }
    che_mesh_free(m);
}

static void test_strip(void) {
    che_mesh *m = make(STRIP, 2, 4, NULL, 3);
    CHECK(che_mesh_num_edges(m) == 5);
    CHECK(che_mesh_num_boundary_curves(m) == 1);
    che_summary s;
    CHECK_OK(che_mesh_summary(m, &s));
    CHECK(s.vertices == 4 && s.edges == 5 && s.triangles == 2 && s.boundary_edges == 4);
    CHECK(s.boundary_curves == 1 && s.components == 1 && s.euler_characteristic == 1);
    CHECK(s.genus == 0 && s.orientable && s.manifold);
    che_memory mem;
    CHECK_OK(che_mesh_memory(m, &mem));
    CHECK(mem.positions == 0 && mem.curves > 0);
    che_mesh_free(m);
}

static void test_non_manifold_vertex(void) {
    /* Repaired: vertex 0 is split, the copy appended with an origin back to 0. */
    che_mesh *m = make(BOWTIE, 2, 5, BOWTIE_POS, 2);
    CHECK(che_mesh_num_input_vertices(m) == 5);
    CHECK(che_mesh_num_vertices(m) == 6);
    size_t len = 0;
    const uint32_t *vo = che_mesh_vertex_origins(m, &len);
    CHECK(vo != NULL && len == 6);
    if (vo && len == 6) CHECK_IDS(vo, len, 0, 1, 2, 3, 4, 0);
    const double *pos = che_mesh_positions(m, &len);
    CHECK(pos != NULL && len == 18);
    if (pos && len == 18) CHECK(pos[15] == 0 && pos[16] == 0 && pos[17] == 0);
    /* One triangle keeps vertex 0, the other uses the copy 5. */
    uint32_t a[3], b[3];
    CHECK_OK(che_triangle_vertices(m, 0, a, 3, &len));
    CHECK_OK(che_triangle_vertices(m, 1, b, 3, &len));
    uint32_t c0 = a[0] == 0 || a[0] == 5 ? a[0] : (a[1] == 0 || a[1] == 5 ? a[1] : a[2]);
    uint32_t c1 = b[0] == 0 || b[0] == 5 ? b[0] : (b[1] == 0 || b[1] == 5 ? b[1] : b[2]);
    CHECK((c0 == 0 && c1 == 5) || (c0 == 5 && c1 == 0));
    uint32_t vv[8];
    CHECK_OK(che_vertex_vertices(m, 0, vv, 8, &len));
    CHECK(len == 2);
    CHECK_OK(che_vertex_vertices(m, 5, vv, 8, &len));
    CHECK(len == 2);

    che_summary s;
    CHECK_OK(che_mesh_summary(m, &s));
    CHECK(s.vertices == 5 && s.edges == 6 && s.triangles == 2 && s.components == 1);
    CHECK(!s.manifold && s.split_vertices == 1 && s.genus == -1);
    CHECK(s.euler_characteristic == 1);
    che_build_report r;
    CHECK_STATUS(che_mesh_report(m, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_OK(che_mesh_report(m, &r));
    CHECK(r.input_triangles == 2 && r.input_vertices == 5 && r.split_vertices == 1);
    CHECK(r.added_vertices == 1 && r.dropped_degenerate == 0 && r.non_manifold_edges == 0);
    uint32_t ex[32];
    CHECK_OK(che_mesh_report_examples(m, CHE_REPORT_KIND_SPLIT_VERTEX, ex, 32, &len));
    CHECK_IDS(ex, len, 0);
    CHECK_OK(che_mesh_report_examples(m, CHE_REPORT_KIND_DEGENERATE, ex, 32, &len));
    CHECK_EMPTY(len);
    CHECK_OK(che_mesh_report_examples(m, CHE_REPORT_KIND_NON_FINITE_VERTEX, ex, 32, &len));
    CHECK_EMPTY(len);
    CHECK(r.non_finite_vertices == 0);
    CHECK_STATUS(che_mesh_report_examples(m, 6, ex, 32, &len), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("6");
    CHECK_STATUS(che_mesh_report_examples(NULL, 0, ex, 32, &len), TOPOMESH_STATUS_NULL_ARGUMENT);
    che_mesh_free(m);

    /* Strict: rejected, the detail names the vertex. */
    che_build_options o = che_build_options_default();
    o.strict = true;
    m = (che_mesh *)&o;
    CHECK_STATUS(che_mesh_from_triangles_ex(BOWTIE, 2, 5, NULL, &o, &m),
                 TOPOMESH_STATUS_NON_MANIFOLD);
    CHECK(m == NULL);
    CHECK_DETAIL("vertex 0");
}

static void test_non_manifold_edge(void) {
    che_mesh *m = make(FIN, 3, 5, NULL, 3);
    che_summary s;
    CHECK_OK(che_mesh_summary(m, &s));
    CHECK(s.non_manifold_edges == 1 && !s.manifold && s.edges == 7 && s.triangles == 3);
    /* The three half-edges of 0-1 stay unpaired: three structure edges. */
    CHECK(che_mesh_num_edges(m) == 9);
    uint32_t ex[8];
    size_t len = 0;
    CHECK_OK(che_mesh_report_examples(m, CHE_REPORT_KIND_NON_MANIFOLD_EDGE, ex, 8, &len));
    CHECK_IDS(ex, len, 0, 1);
    uint32_t ff[3];
    CHECK_OK(che_triangle_triangles(m, 0, ff, 3, &len));
    CHECK_IDS(ff, len, N_, N_, N_);
    che_mesh_free(m);

    che_build_options o = {2, true, 0, 0, 0.0};
    m = NULL;
    CHECK_STATUS(che_mesh_from_triangles_ex(FIN, 3, 5, NULL, &o, &m), TOPOMESH_STATUS_NON_MANIFOLD);
    CHECK(m == NULL);
    CHECK_DETAIL("(0, 1)");
    /* Strict accepts a manifold. */
    CHECK_OK(che_mesh_from_triangles_ex(TETRA, 4, 4, NULL, &o, &m));
    CHECK(m != NULL);
    che_mesh_free(m);
    /* Exact duplicates are refused in strict mode too. */
    const uint32_t dup[] = {0, 1, 2, 0, 1, 2};
    CHECK_STATUS(che_mesh_from_triangles_ex(dup, 2, 3, NULL, &o, &m), TOPOMESH_STATUS_NON_MANIFOLD);
    o.strict = false;
    CHECK_OK(che_mesh_from_triangles_ex(dup, 2, 3, NULL, &o, &m));
    che_build_report r;
    CHECK_OK(che_mesh_report(m, &r));
    CHECK(r.duplicate_triangles == 1);
    CHECK_OK(che_mesh_report_examples(m, CHE_REPORT_KIND_DUPLICATE, ex, 8, &len));
    CHECK_IDS(ex, len, 0, 1);
    che_mesh_free(m);
}

static void test_degenerate_and_isolated(void) {
    che_mesh *m = make(DEGEN, 3, 5, NULL, 2);
    CHECK(che_mesh_num_triangles(m) == 2);
    size_t len = 0;
    const uint32_t *to = che_mesh_triangle_origins(m, &len);
    CHECK(to != NULL);
    if (to) CHECK_IDS(to, len, 0, 2);
    const uint32_t *vo = che_mesh_vertex_origins(m, &len);
    CHECK(vo != NULL);
    if (vo) CHECK_IDS(vo, len, 0, 1, 2, 3, 4);
    CHECK(che_mesh_positions(m, &len) == NULL && len == 0);
    che_build_report r;
    CHECK_OK(che_mesh_report(m, &r));
    CHECK(r.dropped_degenerate == 1 && r.input_triangles == 3);
    uint32_t ex[4];
    CHECK_OK(che_mesh_report_examples(m, CHE_REPORT_KIND_DEGENERATE, ex, 4, &len));
    CHECK_IDS(ex, len, 1);
    che_summary s;
    CHECK_OK(che_mesh_summary(m, &s));
    CHECK(s.dropped_degenerate == 1 && s.isolated_vertices == 1 && s.triangles == 2);
    CHECK(s.components == 1 && s.euler_characteristic == 5 - 5 + 2);
    /* The isolated vertex: no star, not boundary, no half-edge. */
    uint32_t h = 0;
    bool b = true;
    CHECK_OK(che_vertex_half_edge(m, 4, &h));
    CHECK(h == TOPOMESH_NONE);
    CHECK_OK(che_vertex_is_boundary(m, 4, &b));
    CHECK(!b);
    uint32_t buf[4];
    CHECK_OK(che_vertex_vertices(m, 4, buf, 4, &len));
    CHECK_EMPTY(len);
    CHECK_OK(che_vertex_triangles(m, 4, NULL, 0, &len));
    CHECK_EMPTY(len);
    che_mesh_free(m);
}

static void test_moebius(void) {
    che_mesh *m = make(MOEBIUS, 6, 6, NULL, 3);
    che_summary s;
    CHECK_OK(che_mesh_summary(m, &s));
    CHECK(!s.orientable && s.non_orientable_components == 1 && s.genus == -1);
    CHECK(s.vertices == 6 && s.edges == 12 && s.triangles == 6 && s.euler_characteristic == 0);
    CHECK(s.boundary_curves == 1);
    che_build_report r;
    CHECK_OK(che_mesh_report(m, &r));
    CHECK(r.non_orientable_components == 1 && r.seam_edges >= 1);
    uint32_t ex[4];
    size_t len = 0;
    CHECK_OK(che_mesh_report_examples(m, CHE_REPORT_KIND_NON_ORIENTABLE, ex, 4, &len));
    CHECK(len == 1 && ex[0] < 6);
    che_mesh_free(m);
}

static void test_orientation_repair(void) {
    /* The strip with its second triangle reversed: flipped back, same answers. */
    const uint32_t flipped[] = {0, 1, 2, 1, 2, 3};
    che_mesh *m = make(flipped, 2, 4, NULL, 2);
    che_summary s;
    CHECK_OK(che_mesh_summary(m, &s));
    CHECK(s.flipped_triangles == 1 && s.orientable && s.boundary_edges == 4);
    uint32_t t[3];
    size_t len = 0;
    CHECK_OK(che_triangle_triangles(m, 0, t, 3, &len));
    CHECK(len == 3);
    int across = 0, none = 0;
    for (int i = 0; i < 3; i++) across += t[i] == 1, none += t[i] == TOPOMESH_NONE;
    CHECK(across == 1 && none == 2);
    che_mesh_free(m);
}

/* Every fixture is a valid structure at every level; NULL is refused by name. */
static void test_validate(void) {
    for (size_t f = 0; f < N_CHE_FIXTURES; f++)
        for (uint32_t level = 0; level <= 3; level++) {
            che_mesh *m = make(CHE_FIXTURES[f].tris, CHE_FIXTURES[f].n_tris,
                               CHE_FIXTURES[f].n_verts, NULL, level);
            CHECK_OK(che_mesh_validate(m));
            che_mesh_free(m);
        }
    CHECK_STATUS(che_mesh_validate(NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("m");
}

/* The weld: a square's two triangles, each with its own corners, the shared ones a unit in
 * the last place apart, build as one patch with it and as two triangles without. */
static void test_weld(void) {
    const uint32_t tris[] = {0, 1, 2, 3, 4, 5};
    const double e = 2.220446049250313e-16;
    const double pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1 + e, 0, 0, 1, 1, 0, 0, 1, e};
    che_build_options o = che_build_options_default();
    o.weld_tolerance = 1e-9;
    che_mesh *m = NULL;
    CHECK_OK(che_mesh_from_triangles_ex(tris, 2, 6, pos, &o, &m));
    CHECK(che_mesh_num_vertices(m) == 6 && che_mesh_num_edges(m) == 5);
    CHECK(che_mesh_num_boundary_curves(m) == 1);
    che_build_report r;
    CHECK_OK(che_mesh_report(m, &r));
    CHECK(r.welded_vertices == 2);
    che_summary s;
    CHECK_OK(che_mesh_summary(m, &s));
    CHECK(s.vertices == 4 && s.isolated_vertices == 0 && s.euler_characteristic == 1);
    uint32_t tv[3];
    size_t len = 0;
    CHECK_OK(che_triangle_vertices(m, 1, tv, 3, &len));
    CHECK_IDS(tv, len, 1, 4, 2);
    che_mesh_free(m);
    /* The weld alone: each vertex's representative, the map the build applied. */
    uint32_t rep[6];
    CHECK_OK(topomesh_weld_representatives(pos, 6, 1e-9, NULL, 0, &len));
    CHECK(len == 6);
    CHECK_OK(topomesh_weld_representatives(pos, 6, 1e-9, rep, 6, &len));
    CHECK_IDS(rep, len, 0, 1, 2, 1, 4, 2);
    CHECK_STATUS(topomesh_weld_representatives(pos, 6, 1e-9, rep, 5, &len),
                 TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(len == 6);
    CHECK_STATUS(topomesh_weld_representatives(NULL, 6, 1e-9, rep, 6, &len),
                 TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("positions");
    CHECK_STATUS(topomesh_weld_representatives(pos, 6, 0.0, rep, 6, &len),
                 TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("weld_tolerance 0");
    o.weld_tolerance = 0.0;
    CHECK_OK(che_mesh_from_triangles_ex(tris, 2, 6, pos, &o, &m));
    CHECK(che_mesh_num_edges(m) == 6 && che_mesh_num_boundary_curves(m) == 2);
    che_mesh_free(m);
    /* Without positions, or with a negative tolerance: INVALID_INPUT naming the option. */
    o.weld_tolerance = 1e-9;
    m = NULL;
    CHECK_STATUS(che_mesh_from_triangles_ex(tris, 2, 6, NULL, &o, &m), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK(m == NULL);
    CHECK_DETAIL("without vertex positions");
    o.weld_tolerance = -1.0;
    CHECK_STATUS(che_mesh_from_triangles_ex(tris, 2, 6, pos, &o, &m), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("weld_tolerance");
}

int main(void) {
    test_argument_errors();
    test_validate();
    test_tetrahedron();
    test_strip();
    test_non_manifold_vertex();
    test_non_manifold_edge();
    test_degenerate_and_isolated();
    test_moebius();
    test_orientation_repair();
    test_weld();
    return finish("test_che_build");
}
