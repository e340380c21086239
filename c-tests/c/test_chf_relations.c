/* CHF: the 16 relations and the half-face helpers, one element at a time: answers on small
   meshes, buffer rules, errors, invariants, and the same answers at every level. */
#include "chf_fixtures.h"

VALUE_QUERY(chf_mesh, chf_half_face_opposite)
VALUE_QUERY(chf_mesh, chf_half_face_face)
VALUE_QUERY(chf_mesh, chf_vertex_half_face)
VALUE_QUERY(chf_mesh, chf_face_half_face)
FLAG_QUERY(chf_mesh, chf_vertex_is_boundary)
FLAG_QUERY(chf_mesh, chf_edge_is_boundary)
FLAG_QUERY(chf_mesh, chf_face_is_boundary)

/* The 16 relations, then the single-value helpers. */
static const any_query QUERIES[] = {
    {"chf_vertex_vertices", q_chf_vertex_vertices, VERTEX},
    {"chf_vertex_edges", q_chf_vertex_edges, VERTEX},
    {"chf_vertex_faces", q_chf_vertex_faces, VERTEX},
    {"chf_vertex_tetrahedra", q_chf_vertex_tetrahedra, VERTEX},
    {"chf_edge_vertices", q_chf_edge_vertices, EDGE},
    {"chf_edge_edges", q_chf_edge_edges, EDGE},
    {"chf_edge_faces", q_chf_edge_faces, EDGE},
    {"chf_edge_tetrahedra", q_chf_edge_tetrahedra, EDGE},
    {"chf_face_vertices", q_chf_face_vertices, FACE},
    {"chf_face_edges", q_chf_face_edges, FACE},
    {"chf_face_faces", q_chf_face_faces, FACE},
    {"chf_face_tetrahedra", q_chf_face_tetrahedra, FACE},
    {"chf_tetrahedron_vertices", q_chf_tetrahedron_vertices, TETRAHEDRON},
    {"chf_tetrahedron_edges", q_chf_tetrahedron_edges, TETRAHEDRON},
    {"chf_tetrahedron_faces", q_chf_tetrahedron_faces, TETRAHEDRON},
    {"chf_tetrahedron_tetrahedra", q_chf_tetrahedron_tetrahedra, TETRAHEDRON},
    {"chf_half_face_opposite", q_chf_half_face_opposite, HALF_FACE},
    {"chf_half_face_face", q_chf_half_face_face, HALF_FACE},
    {"chf_vertex_half_face", q_chf_vertex_half_face, VERTEX},
    {"chf_face_half_face", q_chf_face_half_face, FACE},
    {"chf_vertex_is_boundary", q_chf_vertex_is_boundary, VERTEX},
    {"chf_edge_is_boundary", q_chf_edge_is_boundary, EDGE},
    {"chf_face_is_boundary", q_chf_face_is_boundary, FACE},
};
#define N_QUERIES (sizeof QUERIES / sizeof QUERIES[0])

/* The expected answers on the small meshes, one section a mesh. */
#define ANSWERS TOPOMESH_TEST_DATA "/chf_relations.txt"
#define N_RELATIONS 16

static void test_single(void) {
    chf_mesh *m = make_chf(TET, 1, 4, TET_POS, 2);
    check_answer_file(ANSWERS, "single", m, QUERIES, N_QUERIES);
    uint32_t b[16];
    size_t n = 0;
    for (uint32_t e = 0; e < 6; e++) {
        CHECK_OK(chf_edge_faces(m, e, b, 16, &n));
        CHECK(n == 2);
    }
    chf_mesh_free(m);
}

static void test_pair(void) {
    chf_mesh *m = make_chf(PAIR, 2, 5, PAIR_POS, 2);
    check_answer_file(ANSWERS, "pair", m, QUERIES, N_QUERIES);
    chf_mesh_free(m);

    /* The cube has one interior face per corner tetrahedron, and interior edges none. */
    m = make_chf(CUBE, 5, 8, CUBE_POS, 2);
    uint32_t b[16];
    size_t n = 0;
    bool yes = false;
    size_t interior = 0;
    for (uint32_t f = 0; f < chf_mesh_num_faces(m); f++) {
        CHECK_OK(chf_face_is_boundary(m, f, &yes));
        interior += !yes;
    }
    CHECK(interior == 4 && chf_mesh_num_faces(m) == 16);
    CHECK_OK(chf_tetrahedron_tetrahedra(m, 4, b, 16, &n));
    /* The middle tetrahedron (1,2,4,7) meets the corner tetrahedra of 6, 5, 3 and 0 across
       the faces opposite its vertices 1, 2, 4 and 7. */
    CHECK_IDS(b, n, 3, 2, 1, 0);
    chf_mesh_free(m);
}

/* Buffer rules and errors, for every relation. */
static void test_buffer_rules(void) {
    chf_mesh *m = make_chf(CUBE, 5, 8, CUBE_POS, 3);
    for (size_t r = 0; r < N_RELATIONS; r++)
        check_buffer_rules(QUERIES[r].fn, m, count_of(m, QUERIES[r].kind),
                           KIND_NAMES[QUERIES[r].kind]);

    /* The single-value helpers. */
    for (size_t q = N_RELATIONS; q < N_QUERIES; q++)
        check_value_errors(QUERIES[q].fn, m, count_of(m, QUERIES[q].kind),
                           KIND_NAMES[QUERIES[q].kind]);
    chf_mesh_free(m);
}

static int contains(const uint32_t *b, size_t n, uint32_t x) {
    for (size_t i = 0; i < n; i++)
        if (b[i] == x) return 1;
    return 0;
}

/* Incidence invariants that hold on any mesh. */
static void invariants(const char *name, const chf_mesh *m) {
    size_t T = chf_mesh_num_tetrahedra(m), sum_vt = 0, sum_ft = 0, sum_et = 0;
    int failures_before = check_failures;
    for (uint32_t t = 0; t < T; t++) {
        uint32_t tv[4], te[6], tf[4], tt[4], b[64];
        size_t n = 0, nb = 0;
        CHECK_OK(chf_tetrahedron_vertices(m, t, tv, 4, &n));
        CHECK_OK(chf_tetrahedron_edges(m, t, te, 6, &n));
        CHECK_OK(chf_tetrahedron_faces(m, t, tf, 4, &n));
        CHECK_OK(chf_tetrahedron_tetrahedra(m, t, tt, 4, &n));
        for (uint32_t i = 0; i < 4; i++) {
            uint32_t f = 0;
            CHECK_OK(chf_half_face_face(m, chf_first(t) + i, &f));
            CHECK(f == tf[i]);
            CHECK_OK(chf_face_tetrahedra(m, tf[i], b, 64, &nb));
            CHECK(contains(b, nb, t) && nb == (tt[i] == TOPOMESH_NONE ? 1u : 2u));
            if (tt[i] != TOPOMESH_NONE) CHECK(contains(b, nb, tt[i]));
            CHECK_OK(chf_face_vertices(m, tf[i], b, 64, &nb));
            CHECK(nb == 3 && !contains(b, nb, tv[i]));
            CHECK_OK(chf_vertex_tetrahedra(m, tv[i], b, 64, &nb));
            CHECK(contains(b, nb, t));
        }
        static const int pair[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
        for (int k = 0; k < 6; k++) {
            CHECK_OK(chf_edge_vertices(m, te[k], b, 64, &nb));
            CHECK(nb == 2 && contains(b, 2, tv[pair[k][0]]) && contains(b, 2, tv[pair[k][1]]));
            CHECK_OK(chf_edge_tetrahedra(m, te[k], b, 64, &nb));
            CHECK(contains(b, nb, t));
        }
    }
    for (uint32_t v = 0; v < chf_mesh_num_vertices(m); v++) {
        size_t n = 0;
        CHECK_OK(chf_vertex_tetrahedra(m, v, NULL, 0, &n));
        sum_vt += n;
    }
    for (uint32_t f = 0; f < chf_mesh_num_faces(m); f++) {
        size_t n = 0;
        CHECK_OK(chf_face_tetrahedra(m, f, NULL, 0, &n));
        sum_ft += n;
    }
    for (uint32_t e = 0; e < chf_mesh_num_edges(m); e++) {
        size_t nt = 0, nf = 0;
        bool boundary = false;
        CHECK_OK(chf_edge_tetrahedra(m, e, NULL, 0, &nt));
        CHECK_OK(chf_edge_faces(m, e, NULL, 0, &nf));
        CHECK_OK(chf_edge_is_boundary(m, e, &boundary));
        CHECK(nf == nt + (boundary ? 1 : 0));
        sum_et += nt;
    }
    CHECK(sum_vt == 4 * T && sum_ft == 4 * T && sum_et == 6 * T);
    if (check_failures != failures_before) fprintf(stderr, "  (invariants of %s)\n", name);
}

VIEW_QUERY(chf_mesh, chf_mesh_opposites)
VIEW_QUERY(chf_mesh, chf_mesh_vertex_half_faces)
VIEW_QUERY(chf_mesh, chf_mesh_face_half_faces)
static const any_view_fn LEVEL_3_VIEWS[] = {q_chf_mesh_opposites, q_chf_mesh_vertex_half_faces,
                                            q_chf_mesh_face_half_faces};
static topomesh_status build_level(void *m, uint32_t level) {
    return chf_mesh_build_level(m, level);
}
static void free_mesh(void *m) { chf_mesh_free(m); }
static const level_suite SUITE = {QUERIES, N_QUERIES, count_of, HALF_FACE + 1, LEVEL_3_VIEWS,
                                  3, build_level, free_mesh};

/* Every relation and helper gives the same answer at levels 0, 1, 2 as at level 3, and the
   level-3 mesh keeps the invariants. */
static void same_at_every_level(const char *name, const uint32_t *tets, size_t nt, size_t nv,
                                const double *pos) {
    chf_mesh *ref = make_chf(tets, nt, nv, pos, 3);
    invariants(name, ref);
    void *lower[3];
    for (uint32_t level = 0; level < 3; level++) lower[level] = make_chf(tets, nt, nv, pos, level);
    same_as_level_3(name, &SUITE, ref, lower);
    chf_mesh_free(ref);
}

int main(void) {
    test_single();
    test_pair();
    test_buffer_rules();
    same_at_every_level("single", TET, 1, 4, TET_POS);
    same_at_every_level("pair", PAIR, 2, 5, NULL);
    same_at_every_level("split vertex", SPLIT, 2, 7, SPLIT_POS);
    same_at_every_level("cube", CUBE, 5, 8, CUBE_POS);
    same_at_every_level("star", STAR, 4, 5, STAR_POS);
    same_at_every_level("book", BOOK, 3, 6, NULL);
    same_at_every_level("degenerate", TDEGEN, 3, 6, NULL);
    const uint32_t hinge[] = {0, 1, 2, 3, 0, 1, 4, 5};
    same_at_every_level("hinge", hinge, 2, 6, NULL);
    const uint32_t flipped[] = {0, 1, 2, 3, 4, 1, 2, 3};
    same_at_every_level("flipped pair", flipped, 2, 5, NULL);
    return finish("test_chf_relations");
}
