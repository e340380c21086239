/* CHF: building, levels, counts, summary, report, memory, origins, strict mode. */
#include "chf_fixtures.h"

static void test_argument_errors(void) {
    chf_mesh *m = (chf_mesh *)&m; /* must be reset to NULL on failure */
    CHECK_STATUS(chf_mesh_from_tetrahedra(NULL, 2, 5, NULL, 2, &m), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK(m == NULL);
    CHECK_DETAIL("tetrahedra");
    CHECK_STATUS(chf_mesh_from_tetrahedra(PAIR, 2, 5, NULL, 2, NULL),
                 TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("out");
    m = (chf_mesh *)&m;
    CHECK_STATUS(chf_mesh_from_tetrahedra(PAIR, 2, 5, NULL, 4, &m), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK(m == NULL);
    CHECK_DETAIL("level 4");
    /* A vertex id >= n_vertices. */
    CHECK_STATUS(chf_mesh_from_tetrahedra(PAIR, 2, 4, NULL, 2, &m), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK(m == NULL);
    CHECK_DETAIL("vertex 4");
    /* Sizes beyond 32-bit ids fail before the arrays are read. */
    CHECK_STATUS(chf_mesh_from_tetrahedra(PAIR, (size_t)1 << 30, 5, NULL, 2, &m),
                 TOPOMESH_STATUS_TOO_LARGE);
    CHECK_STATUS(chf_mesh_from_tetrahedra(PAIR, 2, (size_t)UINT32_MAX, NULL, 2, &m),
                 TOPOMESH_STATUS_TOO_LARGE);
    CHECK(m == NULL);
    /* Empty input: NULL tetrahedra are fine when there are none. */
    CHECK_OK(chf_mesh_from_tetrahedra(NULL, 0, 3, NULL, 3, &m));
    CHECK(m != NULL);
    CHECK(chf_mesh_num_vertices(m) == 3 && chf_mesh_num_tetrahedra(m) == 0);
    CHECK(chf_mesh_num_edges(m) == 0 && chf_mesh_num_faces(m) == 0);
    CHECK(chf_mesh_num_boundary_faces(m) == 0 && chf_mesh_num_boundary_components(m) == 0);
    chf_summary s;
    CHECK_OK(chf_mesh_summary(m, &s));
    CHECK(s.vertices == 3 && s.isolated_vertices == 3 && s.components == 0);
    CHECK(s.euler_characteristic == 3);
    chf_mesh_free(m);

    /* Options. */
    chf_build_options o = chf_build_options_default();
    CHECK(o.level == 2 && !o.strict && o.threads == 0 && o.weld_tolerance == 0.0);
    m = NULL;
    CHECK_OK(chf_mesh_from_tetrahedra_ex(PAIR, 2, 5, NULL, NULL, &m));
    CHECK(chf_mesh_level(m) == 2);
    chf_mesh_free(m);
    for (uint32_t threads = 1; threads <= 3; ++threads) {
        o.threads = threads;
        CHECK_OK(chf_mesh_from_tetrahedra_ex(PAIR, 2, 5, NULL, &o, &m));
        CHECK(chf_mesh_num_tetrahedra(m) == 2 && chf_mesh_num_faces(m) == 7);
        chf_mesh_free(m);
    }
    o.threads = 0;
    o.level = 7;
    CHECK_STATUS(chf_mesh_from_tetrahedra_ex(PAIR, 2, 5, NULL, &o, &m),
                 TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(chf_mesh_from_tetrahedra_ex(PAIR, 2, 5, NULL, &o, NULL),
                 TOPOMESH_STATUS_NULL_ARGUMENT);

    /* NULL handles: counts are 0, free is a no-op, calls that fail say so. */
    chf_mesh_free(NULL);
    CHECK(chf_mesh_level(NULL) == 0);
    CHECK(chf_mesh_num_vertices(NULL) == 0);
    CHECK(chf_mesh_num_input_vertices(NULL) == 0);
    CHECK(chf_mesh_num_tetrahedra(NULL) == 0);
    CHECK(chf_mesh_num_faces(NULL) == 0);
    CHECK(chf_mesh_num_edges(NULL) == 0);
    CHECK(chf_mesh_num_half_faces(NULL) == 0);
    CHECK(chf_mesh_num_boundary_faces(NULL) == 0);
    CHECK(chf_mesh_num_boundary_components(NULL) == 0);
    CHECK_STATUS(chf_mesh_build_level(NULL, 2), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_mesh_summary(NULL, &s), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("'m'");
    chf_build_report r;
    CHECK_STATUS(chf_mesh_report(NULL, &r), TOPOMESH_STATUS_NULL_ARGUMENT);
    chf_memory mem;
    CHECK_STATUS(chf_mesh_memory(NULL, &mem), TOPOMESH_STATUS_NULL_ARGUMENT);
}

static void test_single(void) {
    chf_mesh *m = make_chf(TET, 1, 4, TET_POS, 2);
    CHECK(chf_mesh_level(m) == 2);
    CHECK(chf_mesh_num_vertices(m) == 4 && chf_mesh_num_input_vertices(m) == 4);
    CHECK(chf_mesh_num_tetrahedra(m) == 1 && chf_mesh_num_half_faces(m) == 4);
    CHECK(chf_mesh_num_faces(m) == 4 && chf_mesh_num_edges(m) == 6);
    CHECK(chf_mesh_num_boundary_faces(m) == 4 && chf_mesh_num_boundary_components(m) == 1);
    chf_summary s;
    CHECK_STATUS(chf_mesh_summary(m, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_OK(chf_mesh_summary(m, &s));
    CHECK(s.vertices == 4 && s.edges == 6 && s.faces == 4 && s.tetrahedra == 1);
    CHECK(s.boundary_faces == 4 && s.boundary_edges == 6 && s.boundary_vertices == 4);
    CHECK(s.boundary_components == 1 && s.components == 1 && s.isolated_vertices == 0);
    CHECK(s.euler_characteristic == 1 && s.manifold && s.orientable);
    CHECK(s.dropped_degenerate == 0 && s.zero_volume == 0 && s.inverted_tetrahedra == 0);
    CHECK(s.non_manifold_faces == 0 && s.non_manifold_edges == 0 && s.split_vertices == 0);
    CHECK(s.flipped_tetrahedra == 0 && s.non_orientable_components == 0);

    /* Memory per level: V is 4T ints, O as much again; positions apart. */
    chf_memory mem;
    CHECK_STATUS(chf_mesh_memory(m, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_OK(chf_mesh_build_level(m, 0));
    CHECK_OK(chf_mesh_memory(m, &mem));
    CHECK(mem.half_face_vertices == 16 && mem.opposites == 0 && mem.topology == 16);
    CHECK(mem.positions == 4 * 3 * sizeof(double) && mem.maps == 0);
    CHECK_OK(chf_mesh_build_level(m, 1));
    CHECK_OK(chf_mesh_memory(m, &mem));
    CHECK(mem.opposites == 16 && mem.topology == 32);
    CHECK_OK(chf_mesh_build_level(m, 2));
    CHECK_OK(chf_mesh_memory(m, &mem));
    CHECK(mem.vertex_half_faces == 16 && mem.edges >= 24 && mem.faces >= 16 && mem.boundary == 0);
    uint64_t l2 = mem.topology;
    CHECK(l2 == mem.half_face_vertices + mem.opposites + mem.vertex_half_faces + mem.edges +
                    mem.faces);
    CHECK_OK(chf_mesh_build_level(m, 3));
    CHECK_OK(chf_mesh_memory(m, &mem));
    CHECK(mem.boundary > 0 && mem.topology == l2 + mem.boundary);
    CHECK(chf_mesh_level(m) == 3);
    CHECK_STATUS(chf_mesh_build_level(m, 4), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("level 4");
    CHECK(chf_mesh_level(m) == 3);
    /* Counts do not depend on the level, going down or up. */
    for (int i = 0; i < 8; i++) {
        uint32_t level = (uint32_t)(i < 4 ? 3 - i : i - 4);
        CHECK_OK(chf_mesh_build_level(m, level));
        CHECK(chf_mesh_level(m) == level);
        CHECK(chf_mesh_num_edges(m) == 6 && chf_mesh_num_faces(m) == 4);
        CHECK(chf_mesh_num_boundary_faces(m) == 4 && chf_mesh_num_boundary_components(m) == 1);
    }
    chf_build_report r;
    CHECK_STATUS(chf_mesh_report(m, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_OK(chf_mesh_report(m, &r));
    CHECK(r.input_tetrahedra == 1 && r.input_vertices == 4 && r.input_faces == 4);
    CHECK(r.boundary_faces == 4 && r.input_edges == 6 && r.added_vertices == 0);
    chf_mesh_free(m);

    /* The reversed tetrahedron is oriented by its positions: local vertices 1 and 2 swapped. */
    const uint32_t reversed[] = {0, 2, 1, 3};
    m = make_chf(reversed, 1, 4, TET_POS, 2);
    CHECK_OK(chf_mesh_report(m, &r));
    CHECK(r.flipped_tetrahedra == 1);
    uint32_t tv[4];
    size_t len = 0;
    CHECK_OK(chf_tetrahedron_vertices(m, 0, tv, 4, &len));
    CHECK_IDS(tv, len, 0, 1, 2, 3);
    chf_mesh_free(m);
}

static void test_pair(void) {
    for (uint32_t level = 0; level <= 3; level++) {
        chf_mesh *m = make_chf(PAIR, 2, 5, level % 2 ? PAIR_POS : NULL, level);
        CHECK(chf_mesh_level(m) == level);
        CHECK(chf_mesh_num_vertices(m) == 5 && chf_mesh_num_tetrahedra(m) == 2);
        CHECK(chf_mesh_num_faces(m) == 7 && chf_mesh_num_edges(m) == 9);
        CHECK(chf_mesh_num_half_faces(m) == 8 && chf_mesh_num_boundary_faces(m) == 6);
        chf_summary s;
        CHECK_OK(chf_mesh_summary(m, &s));
        CHECK(s.vertices == 5 && s.edges == 9 && s.faces == 7 && s.tetrahedra == 2);
        CHECK(s.boundary_faces == 6 && s.boundary_edges == 9 && s.boundary_vertices == 5);
        CHECK(s.boundary_components == 1 && s.components == 1);
        CHECK(s.euler_characteristic == 1 && s.manifold && s.orientable);
        CHECK(s.flipped_tetrahedra == 0 && s.inverted_tetrahedra == 0);
        chf_mesh_free(m);
    }
}

static void test_split_vertex(void) {
    /* Repaired: vertex 0 is split, the copy appended with an origin back to 0. */
    chf_mesh *m = make_chf(SPLIT, 2, 7, SPLIT_POS, 3);
    CHECK(chf_mesh_num_input_vertices(m) == 7 && chf_mesh_num_vertices(m) == 8);
    size_t len = 0;
    const uint32_t *vo = chf_mesh_vertex_origins(m, &len);
    CHECK(vo != NULL && len == 8);
    if (vo && len == 8) CHECK_IDS(vo, len, 0, 1, 2, 3, 4, 5, 6, 0);
    const double *pos = chf_mesh_positions(m, &len);
    CHECK(pos != NULL && len == 24);
    if (pos && len == 24) CHECK(pos[21] == 0 && pos[22] == 0 && pos[23] == 0);
    /* One tetrahedron keeps vertex 0, the other uses the copy 7. */
    uint32_t a[4], b[4];
    CHECK_OK(chf_tetrahedron_vertices(m, 0, a, 4, &len));
    CHECK_OK(chf_tetrahedron_vertices(m, 1, b, 4, &len));
    CHECK((a[0] == 0 && b[0] == 7) || (a[0] == 7 && b[0] == 0));
    uint32_t vt[4];
    CHECK_OK(chf_vertex_tetrahedra(m, 0, vt, 4, &len));
    CHECK(len == 1);
    CHECK_OK(chf_vertex_tetrahedra(m, 7, vt, 4, &len));
    CHECK(len == 1);
    const uint32_t *to = chf_mesh_tetrahedron_origins(m, &len);
    CHECK(to != NULL);
    if (to) CHECK_IDS(to, len, 0, 1);
    /* Two boundary components in the structure, one in the input (joined at vertex 0). */
    CHECK(chf_mesh_num_boundary_components(m) == 2);

    chf_summary s;
    CHECK_OK(chf_mesh_summary(m, &s));
    CHECK(s.vertices == 7 && s.edges == 12 && s.faces == 8 && s.tetrahedra == 2);
    CHECK(!s.manifold && s.split_vertices == 1 && s.components == 1);
    CHECK(s.boundary_components == 1 && s.euler_characteristic == 1);
    chf_build_report r;
    CHECK_OK(chf_mesh_report(m, &r));
    CHECK(r.input_tetrahedra == 2 && r.input_vertices == 7 && r.split_vertices == 1);
    CHECK(r.added_vertices == 1 && r.dropped_degenerate == 0 && r.non_manifold_faces == 0);
    uint32_t ex[64];
    CHECK_OK(chf_mesh_report_examples(m, CHF_REPORT_KIND_SPLIT_VERTEX, ex, 64, &len));
    CHECK_IDS(ex, len, 0);
    CHECK_OK(chf_mesh_report_examples(m, CHF_REPORT_KIND_DEGENERATE, ex, 64, &len));
    CHECK_EMPTY(len);
    CHECK_OK(chf_mesh_report_examples(m, CHF_REPORT_KIND_NON_FINITE_VERTEX, ex, 64, &len));
    CHECK_EMPTY(len);
    CHECK(r.non_finite_vertices == 0);
    CHECK_STATUS(chf_mesh_report_examples(m, 10, ex, 64, &len), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("10");
    CHECK_STATUS(chf_mesh_report_examples(NULL, 0, ex, 64, &len), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_mesh_report_examples(m, 0, NULL, 4, &len), TOPOMESH_STATUS_NULL_ARGUMENT);
    chf_mesh_free(m);

    /* Strict: rejected, the detail names the vertex. */
    chf_build_options o = chf_build_options_default();
    o.strict = true;
    m = (chf_mesh *)&o;
    CHECK_STATUS(chf_mesh_from_tetrahedra_ex(SPLIT, 2, 7, NULL, &o, &m),
                 TOPOMESH_STATUS_NON_MANIFOLD);
    CHECK(m == NULL);
    CHECK_DETAIL("vertex 0");
}

static void test_non_manifold_face(void) {
    /* Three tetrahedra on the face (0, 1, 2): its three half-faces stay unpaired. */
    chf_mesh *m = make_chf(BOOK, 3, 6, NULL, 3);
    chf_summary s;
    CHECK_OK(chf_mesh_summary(m, &s));
    CHECK(s.non_manifold_faces == 1 && !s.manifold && s.tetrahedra == 3);
    /* 9 faces with one tetrahedron; the three unpaired half-faces of the shared face are
       no boundary faces, but they are triangles of the boundary surface. */
    CHECK(chf_mesh_num_faces(m) == 12 && chf_mesh_num_boundary_faces(m) == 9);
    CHECK(s.boundary_faces == 9);
    CHECK(chf_mesh_num_non_manifold_half_faces(m) == 3 && chf_mesh_num_seam_half_faces(m) == 0);
    CHECK(chf_mesh_num_boundary_triangles(m) == 12);
    for (uint32_t level = 0; level < 3; level++) {
        CHECK_OK(chf_mesh_build_level(m, level));
        CHECK(chf_mesh_num_boundary_faces(m) == 9 && chf_mesh_num_boundary_triangles(m) == 12);
    }
    CHECK_OK(chf_mesh_build_level(m, 3));
    che_mesh *b = NULL;
    CHECK_OK(chf_mesh_boundary(m, &b));
    che_summary cs;
    CHECK_OK(che_mesh_summary(b, &cs));
    /* Three closed tetrahedra after the split: three spheres, 12 vertices. */
    CHECK(cs.triangles == 12 && cs.vertices == 12 && cs.isolated_vertices == 0);
    CHECK(cs.components == 3 && cs.euler_characteristic == 6);
    che_mesh_free(b);
    uint32_t ex[8];
    size_t len = 0;
    CHECK_OK(chf_mesh_report_examples(m, CHF_REPORT_KIND_NON_MANIFOLD_FACE, ex, 8, &len));
    CHECK_IDS(ex, len, 0, 1, 2);
    uint32_t tt[4];
    for (uint32_t t = 0; t < 3; t++) {
        CHECK_OK(chf_tetrahedron_tetrahedra(m, t, tt, 4, &len));
        CHECK_IDS(tt, len, N_, N_, N_, N_);
    }
    chf_mesh_free(m);

    /* Strict: NON_MANIFOLD, the detail names the face and its tetrahedra. */
    chf_build_options o = {2, true, 0, 0, 0.0};
    m = (chf_mesh *)&o;
    CHECK_STATUS(chf_mesh_from_tetrahedra_ex(BOOK, 3, 6, NULL, &o, &m),
                 TOPOMESH_STATUS_NON_MANIFOLD);
    CHECK(m == NULL);
    CHECK_DETAIL("(0, 1, 2)");
    CHECK_DETAIL("tetrahedra 0, 1, 2");
    /* Strict accepts a manifold. */
    CHECK_OK(chf_mesh_from_tetrahedra_ex(CUBE, 5, 8, CUBE_POS, &o, &m));
    CHECK(m != NULL);
    chf_mesh_free(m);
    /* Exact duplicates are refused in strict mode too, counted otherwise. */
    const uint32_t dup[] = {0, 1, 2, 3, 0, 1, 2, 3};
    CHECK_STATUS(chf_mesh_from_tetrahedra_ex(dup, 2, 4, NULL, &o, &m),
                 TOPOMESH_STATUS_NON_MANIFOLD);
    CHECK_DETAIL("same vertices");
    o.strict = false;
    CHECK_OK(chf_mesh_from_tetrahedra_ex(dup, 2, 4, NULL, &o, &m));
    chf_build_report r;
    CHECK_OK(chf_mesh_report(m, &r));
    CHECK(r.duplicate_tetrahedra == 1);
    CHECK_OK(chf_mesh_report_examples(m, CHF_REPORT_KIND_DUPLICATE, ex, 8, &len));
    CHECK_IDS(ex, len, 0, 1);
    chf_mesh_free(m);

    /* Two tetrahedra sharing only an edge: a non-manifold edge, with its examples. */
    const uint32_t hinge[] = {0, 1, 2, 3, 0, 1, 4, 5};
    m = make_chf(hinge, 2, 6, NULL, 2);
    CHECK_OK(chf_mesh_report(m, &r));
    CHECK(r.non_manifold_edges == 1);
    CHECK_OK(chf_mesh_report_examples(m, CHF_REPORT_KIND_NON_MANIFOLD_EDGE, ex, 8, &len));
    CHECK_IDS(ex, len, 0, 1);
    CHECK_OK(chf_mesh_report_examples(m, CHF_REPORT_KIND_KEPT_NON_MANIFOLD_EDGE, ex, 8, &len));
    CHECK(len == 2 * r.kept_non_manifold_edges);
    chf_mesh_free(m);
    o.strict = true;
    CHECK_STATUS(chf_mesh_from_tetrahedra_ex(hinge, 2, 6, NULL, &o, &m),
                 TOPOMESH_STATUS_NON_MANIFOLD);
    CHECK_DETAIL("(0, 1)");
}

static void test_degenerate_and_isolated(void) {
    chf_mesh *m = make_chf(TDEGEN, 3, 6, NULL, 2);
    CHECK(chf_mesh_num_tetrahedra(m) == 2);
    size_t len = 0;
    const uint32_t *to = chf_mesh_tetrahedron_origins(m, &len);
    CHECK(to != NULL);
    if (to) CHECK_IDS(to, len, 0, 2);
    const uint32_t *vo = chf_mesh_vertex_origins(m, &len);
    CHECK(vo != NULL);
    if (vo) CHECK_IDS(vo, len, 0, 1, 2, 3, 4, 5);
    /* Built without positions. */
    CHECK(chf_mesh_positions(m, &len) == NULL && len == 0);
    chf_build_report r;
    CHECK_OK(chf_mesh_report(m, &r));
    CHECK(r.dropped_degenerate == 1 && r.input_tetrahedra == 3);
    uint32_t ex[4];
    CHECK_OK(chf_mesh_report_examples(m, CHF_REPORT_KIND_DEGENERATE, ex, 4, &len));
    CHECK_IDS(ex, len, 1);
    chf_summary s;
    CHECK_OK(chf_mesh_summary(m, &s));
    CHECK(s.dropped_degenerate == 1 && s.isolated_vertices == 1 && s.tetrahedra == 2);
    CHECK(s.components == 1 && s.euler_characteristic == 6 - 9 + 7 - 2);
    /* The isolated vertex: no star, not on the boundary, no half-face. */
    uint32_t hf = 0;
    bool b = true;
    CHECK_OK(chf_vertex_half_face(m, 5, &hf));
    CHECK(hf == TOPOMESH_NONE);
    CHECK_OK(chf_vertex_is_boundary(m, 5, &b));
    CHECK(!b);
    uint32_t buf[4];
    CHECK_OK(chf_vertex_vertices(m, 5, buf, 4, &len));
    CHECK_EMPTY(len);
    CHECK_OK(chf_vertex_tetrahedra(m, 5, NULL, 0, &len));
    CHECK_EMPTY(len);
    chf_mesh_free(m);

    /* Only degenerate tetrahedra: an empty structure. */
    const uint32_t flat[] = {0, 0, 1, 2};
    m = make_chf(flat, 1, 3, NULL, 3);
    CHECK(chf_mesh_num_tetrahedra(m) == 0 && chf_mesh_num_faces(m) == 0);
    CHECK_OK(chf_mesh_report(m, &r));
    CHECK(r.dropped_degenerate == 1);
    chf_mesh_free(m);
}

static void test_geometry(void) {
    /* A flat tetrahedron (all four points in z = 0) has zero volume: kept, counted. */
    const double flat_pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    chf_mesh *m = make_chf(TET, 1, 4, flat_pos, 2);
    chf_build_report r;
    CHECK_OK(chf_mesh_report(m, &r));
    CHECK(r.zero_volume == 1 && r.dropped_degenerate == 0);
    uint32_t ex[4];
    size_t len = 0;
    CHECK_OK(chf_mesh_report_examples(m, CHF_REPORT_KIND_ZERO_VOLUME, ex, 4, &len));
    CHECK_IDS(ex, len, 0);
    chf_mesh_free(m);

    /* A folded pair: the second apex on the same side of the shared face as the first, so
       one of the two, consistently oriented, has negative volume. */
    const double folded[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.1, 0.1, 0.1};
    m = make_chf(PAIR, 2, 5, folded, 2);
    CHECK_OK(chf_mesh_report(m, &r));
    CHECK(r.inverted_tetrahedra == 1);
    CHECK_OK(chf_mesh_report_examples(m, CHF_REPORT_KIND_INVERTED, ex, 4, &len));
    CHECK(len == 1 && ex[0] < 2);
    CHECK_OK(chf_mesh_report_examples(m, CHF_REPORT_KIND_NON_ORIENTABLE, ex, 4, &len));
    CHECK_EMPTY(len);
    chf_mesh_free(m);
}

/* Every fixture is a valid structure at every level; NULL is refused by name. */
static void test_validate(void) {
    static const struct {
        const uint32_t *tets;
        size_t n_tets, n_verts;
        const double *pos;
    } fixtures[] = {
        {TET, NTET(TET), 4, TET_POS},     {PAIR, NTET(PAIR), 5, PAIR_POS},
        {SPLIT, NTET(SPLIT), 7, SPLIT_POS}, {CUBE, NTET(CUBE), 8, CUBE_POS},
        {STAR, NTET(STAR), 5, STAR_POS},  {BOOK, NTET(BOOK), 6, NULL},
        {TDEGEN, NTET(TDEGEN), 6, NULL},
    };
    for (size_t f = 0; f < sizeof fixtures / sizeof fixtures[0]; f++)
        for (uint32_t level = 0; level <= 3; level++) {
            chf_mesh *m = make_chf(fixtures[f].tets, fixtures[f].n_tets, fixtures[f].n_verts,
                                   fixtures[f].pos, level);
            CHECK_OK(chf_mesh_validate(m));
            chf_mesh_free(m);
        }
    CHECK_STATUS(chf_mesh_validate(NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("m");
}

/* The weld: two tetrahedra on a shared face, each with its own corners, the shared ones a
 * unit in the last place apart, share the face with it and none without. */
static void test_weld(void) {
    const uint32_t tets[] = {0, 1, 2, 3, 4, 6, 5, 7};
    const double e = 2.220446049250313e-16;
    const double pos[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1,
                          1 + e, 0, 0, 0, 1 + e, 0, 0, 0, 1, 1, 1, 1};
    chf_build_options o = chf_build_options_default();
    o.weld_tolerance = 1e-9;
    chf_mesh *m = NULL;
    CHECK_OK(chf_mesh_from_tetrahedra_ex(tets, 2, 8, pos, &o, &m));
    CHECK(chf_mesh_num_faces(m) == 7 && chf_mesh_num_boundary_faces(m) == 6);
    chf_build_report r;
    CHECK_OK(chf_mesh_report(m, &r));
    CHECK(r.welded_vertices == 3);
    chf_summary s;
    CHECK_OK(chf_mesh_summary(m, &s));
    CHECK(s.vertices == 5 && s.isolated_vertices == 0 && s.components == 1);
    chf_mesh_free(m);
    o.weld_tolerance = 0.0;
    CHECK_OK(chf_mesh_from_tetrahedra_ex(tets, 2, 8, pos, &o, &m));
    CHECK(chf_mesh_num_faces(m) == 8 && chf_mesh_num_boundary_faces(m) == 8);
    chf_mesh_free(m);
    o.weld_tolerance = 1e-9;
    m = NULL;
    CHECK_STATUS(chf_mesh_from_tetrahedra_ex(tets, 2, 8, NULL, &o, &m), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK(m == NULL);
    CHECK_DETAIL("without vertex positions");
}

int main(void) {
    test_argument_errors();
    test_validate();
    test_single();
    test_pair();
    test_split_vertex();
    test_non_manifold_face();
    test_degenerate_and_isolated();
    test_geometry();
    test_weld();
    return finish("test_chf_build");
}
