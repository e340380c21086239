/* CHF: the 16 relations and the half-face helpers, one element at a time: answers on small
   meshes, buffer rules, errors, invariants, and the same answers at every level. */
#include "chf_fixtures.h"

static const struct {
    const char *name;
    chf_relation_fn fn;
    int kind; /* 0 vertex, 1 edge, 2 face, 3 tetrahedron */
} RELATIONS[] = {
    {"chf_vertex_vertices", chf_vertex_vertices, 0},
    {"chf_vertex_edges", chf_vertex_edges, 0},
    {"chf_vertex_faces", chf_vertex_faces, 0},
    {"chf_vertex_tetrahedra", chf_vertex_tetrahedra, 0},
    {"chf_edge_vertices", chf_edge_vertices, 1},
    {"chf_edge_edges", chf_edge_edges, 1},
    {"chf_edge_faces", chf_edge_faces, 1},
    {"chf_edge_tetrahedra", chf_edge_tetrahedra, 1},
    {"chf_face_vertices", chf_face_vertices, 2},
    {"chf_face_edges", chf_face_edges, 2},
    {"chf_face_faces", chf_face_faces, 2},
    {"chf_face_tetrahedra", chf_face_tetrahedra, 2},
    {"chf_tetrahedron_vertices", chf_tetrahedron_vertices, 3},
    {"chf_tetrahedron_edges", chf_tetrahedron_edges, 3},
    {"chf_tetrahedron_faces", chf_tetrahedron_faces, 3},
    {"chf_tetrahedron_tetrahedra", chf_tetrahedron_tetrahedra, 3},
};
#define N_RELATIONS (sizeof RELATIONS / sizeof RELATIONS[0])

static size_t count_of(const chf_mesh *m, int kind) {
    switch (kind) {
    case 0: return chf_mesh_num_vertices(m);
    case 1: return chf_mesh_num_edges(m);
    case 2: return chf_mesh_num_faces(m);
    default: return chf_mesh_num_tetrahedra(m);
    }
}

static void test_single(void) {
    chf_mesh *m = make_chf(TET, 1, 4, TET_POS, 2);
    uint32_t b[16];
    size_t n = 0;
    /* Half-face i is opposite vertex i: faces f0 = (1,2,3), f1 = (0,3,2), f2 = (0,1,3),
       f3 = (0,2,1), outward. Edge k is the local pair k: (0,1) (0,2) (0,3) (1,2) (1,3) (2,3),
       directed by its smallest boundary half-edge. */
    CHECK_OK(chf_vertex_vertices(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 1, 2, 3);
    CHECK_OK(chf_vertex_edges(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 0, 1, 2);
    CHECK_OK(chf_vertex_faces(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 1, 2, 3);
    CHECK_OK(chf_vertex_tetrahedra(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 0);
    CHECK_OK(chf_vertex_vertices(m, 3, b, 16, &n));
    CHECK_IDS(b, n, 0, 1, 2);
    CHECK_OK(chf_vertex_edges(m, 3, b, 16, &n));
    CHECK_IDS(b, n, 2, 4, 5);
    CHECK_OK(chf_vertex_faces(m, 3, b, 16, &n));
    CHECK_IDS(b, n, 0, 1, 2);
    const uint32_t ev[6][2] = {{0, 1}, {2, 0}, {0, 3}, {1, 2}, {3, 1}, {2, 3}};
    for (uint32_t e = 0; e < 6; e++) {
        CHECK_OK(chf_edge_vertices(m, e, b, 16, &n));
        CHECK_IDS(b, n, ev[e][0], ev[e][1]);
        CHECK_OK(chf_edge_tetrahedra(m, e, b, 16, &n));
        CHECK_IDS(b, n, 0);
        CHECK_OK(chf_edge_faces(m, e, b, 16, &n));
        CHECK(n == 2);
    }
    CHECK_OK(chf_edge_faces(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 2, 3);
    CHECK_OK(chf_edge_edges(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 4, 2, 1, 3);
    CHECK_OK(chf_face_vertices(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 1, 2, 3);
    CHECK_OK(chf_face_vertices(m, 1, b, 16, &n));
    CHECK_IDS(b, n, 0, 3, 2);
    CHECK_OK(chf_face_vertices(m, 3, b, 16, &n));
    CHECK_IDS(b, n, 0, 2, 1);
    CHECK_OK(chf_face_edges(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 3, 5, 4);
    CHECK_OK(chf_face_edges(m, 1, b, 16, &n));
    CHECK_IDS(b, n, 2, 5, 1);
    CHECK_OK(chf_face_faces(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 1, 2, 3);
    CHECK_OK(chf_face_faces(m, 2, b, 16, &n));
    CHECK_IDS(b, n, 3, 0, 1);
    CHECK_OK(chf_face_tetrahedra(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 0);
    CHECK_OK(chf_tetrahedron_vertices(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 0, 1, 2, 3);
    CHECK_OK(chf_tetrahedron_edges(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 0, 1, 2, 3, 4, 5);
    CHECK_OK(chf_tetrahedron_faces(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 0, 1, 2, 3);
    CHECK_OK(chf_tetrahedron_tetrahedra(m, 0, b, 16, &n));
    CHECK_IDS(b, n, N_, N_, N_, N_);
    bool yes = false;
    for (uint32_t x = 0; x < 4; x++) {
        CHECK_OK(chf_vertex_is_boundary(m, x, &yes));
        CHECK(yes);
        CHECK_OK(chf_face_is_boundary(m, x, &yes));
        CHECK(yes);
    }
    chf_mesh_free(m);
}

static void test_pair(void) {
    chf_mesh *m = make_chf(PAIR, 2, 5, PAIR_POS, 2);
    uint32_t b[16];
    size_t n = 0;
    /* Faces: half-faces 0 1 2 3 5 6 7 (4 is the twin of 0): f4 = (4,2,3), f5 = (4,1,2),
       f6 = (4,3,1). Edges: the six of tetrahedron 0, then (4,1) (4,3) (4,2). */
    CHECK_OK(chf_vertex_vertices(m, 1, b, 16, &n));
    CHECK_IDS(b, n, 0, 2, 3, 4);
    CHECK_OK(chf_vertex_edges(m, 1, b, 16, &n));
    CHECK_IDS(b, n, 0, 3, 4, 6);
    CHECK_OK(chf_vertex_faces(m, 1, b, 16, &n));
    CHECK_IDS(b, n, 0, 2, 3, 5, 6);
    CHECK_OK(chf_vertex_tetrahedra(m, 1, b, 16, &n));
    CHECK_IDS(b, n, 0, 1);
    /* Around a vertex: increasing order. */
    CHECK_OK(chf_vertex_vertices(m, 4, b, 16, &n));
    CHECK_IDS(b, n, 1, 2, 3);
    CHECK_OK(chf_vertex_edges(m, 4, b, 16, &n));
    CHECK_IDS(b, n, 6, 7, 8);
    CHECK_OK(chf_vertex_faces(m, 4, b, 16, &n));
    CHECK_IDS(b, n, 4, 5, 6);
    CHECK_OK(chf_vertex_tetrahedra(m, 4, b, 16, &n));
    CHECK_IDS(b, n, 1);
    const uint32_t ev[9][2] = {{0, 1}, {2, 0}, {0, 3}, {2, 1}, {1, 3},
                               {3, 2}, {4, 1}, {3, 4}, {4, 2}};
    for (uint32_t e = 0; e < 9; e++) {
        CHECK_OK(chf_edge_vertices(m, e, b, 16, &n));
        CHECK_IDS(b, n, ev[e][0], ev[e][1]);
    }
    /* Around the shared edge (1,2): from the boundary face f3 through f0 to f5. */
    CHECK_OK(chf_edge_tetrahedra(m, 3, b, 16, &n));
    CHECK_IDS(b, n, 0, 1);
    CHECK_OK(chf_edge_faces(m, 3, b, 16, &n));
    CHECK_IDS(b, n, 3, 0, 5);
    CHECK_OK(chf_edge_edges(m, 3, b, 16, &n));
    CHECK_IDS(b, n, 0, 1, 5, 4, 8, 6);
    CHECK_OK(chf_edge_tetrahedra(m, 6, b, 16, &n));
    CHECK_IDS(b, n, 1);
    CHECK_OK(chf_face_vertices(m, 4, b, 16, &n));
    CHECK_IDS(b, n, 4, 2, 3);
    CHECK_OK(chf_face_vertices(m, 6, b, 16, &n));
    CHECK_IDS(b, n, 4, 3, 1);
    CHECK_OK(chf_face_edges(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 3, 5, 4);
    CHECK_OK(chf_face_edges(m, 4, b, 16, &n));
    CHECK_IDS(b, n, 8, 5, 7);
    CHECK_OK(chf_face_faces(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 1, 2, 3, 4, 5, 6);
    CHECK_OK(chf_face_faces(m, 1, b, 16, &n));
    CHECK_IDS(b, n, 2, 3, 0);
    CHECK_OK(chf_face_tetrahedra(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 0, 1);
    CHECK_OK(chf_face_tetrahedra(m, 4, b, 16, &n));
    CHECK_IDS(b, n, 1);
    CHECK_OK(chf_tetrahedron_vertices(m, 1, b, 16, &n));
    CHECK_IDS(b, n, 4, 1, 3, 2);
    CHECK_OK(chf_tetrahedron_edges(m, 1, b, 16, &n));
    CHECK_IDS(b, n, 6, 7, 8, 4, 3, 5);
    CHECK_OK(chf_tetrahedron_faces(m, 1, b, 16, &n));
    CHECK_IDS(b, n, 0, 4, 5, 6);
    CHECK_OK(chf_tetrahedron_tetrahedra(m, 0, b, 16, &n));
    CHECK_IDS(b, n, 1, N_, N_, N_);
    CHECK_OK(chf_tetrahedron_tetrahedra(m, 1, b, 16, &n));
    CHECK_IDS(b, n, 0, N_, N_, N_);

    /* Half-face helpers and boundary tests. */
    uint32_t x = 0;
    bool yes = false;
    CHECK_OK(chf_half_face_opposite(m, 0, &x));
    CHECK(x == 4);
    CHECK_OK(chf_half_face_opposite(m, 4, &x));
    CHECK(x == 0);
    CHECK_OK(chf_half_face_opposite(m, 1, &x));
    CHECK(x == TOPOMESH_NONE);
    CHECK_OK(chf_half_face_face(m, 4, &x));
    CHECK(x == 0);
    CHECK_OK(chf_half_face_face(m, 7, &x));
    CHECK(x == 6);
    CHECK_OK(chf_face_half_face(m, 4, &x));
    CHECK(x == 5);
    CHECK_OK(chf_vertex_half_face(m, 1, &x));
    CHECK(x == 2); /* the first boundary half-face holding vertex 1 */
    CHECK_OK(chf_vertex_half_face(m, 4, &x));
    CHECK(x == 5);
    CHECK_OK(chf_face_is_boundary(m, 0, &yes));
    CHECK(!yes);
    CHECK_OK(chf_face_is_boundary(m, 1, &yes));
    CHECK(yes);
    for (uint32_t e = 0; e < 9; e++) {
        CHECK_OK(chf_edge_is_boundary(m, e, &yes));
        CHECK(yes);
    }
    for (uint32_t v = 0; v < 5; v++) {
        CHECK_OK(chf_vertex_is_boundary(m, v, &yes));
        CHECK(yes);
    }
    chf_mesh_free(m);

    /* The cube has one interior face per corner tetrahedron, and interior edges none. */
    m = make_chf(CUBE, 5, 8, CUBE_POS, 2);
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
    for (size_t r = 0; r < N_RELATIONS; r++) {
        chf_relation_fn f = RELATIONS[r].fn;
        /* The element with the longest answer. */
        uint32_t id = 0;
        size_t n = 0, need = 0;
        for (uint32_t x = 0; x < count_of(m, RELATIONS[r].kind); x++) {
            CHECK_OK(f(m, x, NULL, 0, &need));
            if (need > n) n = need, id = x;
        }
        CHECK(n >= 2);
        uint32_t full[64], b[64];
        CHECK_OK(f(m, id, full, 64, &need));
        CHECK(need == n);
        /* Too small: the needed length, and the prefix written. */
        for (size_t i = 0; i < 64; i++) b[i] = 12345;
        need = 0;
        CHECK_STATUS(f(m, id, b, 1, &need), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
        CHECK(need == n && b[0] == full[0] && b[1] == 12345);
        CHECK_DETAIL("needed");
        /* A buffer of zero entries (not a size query) is too small as well. */
        CHECK_STATUS(f(m, id, b, 0, &need), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
        CHECK(need == n);
        /* Exactly enough, and "unbounded". */
        CHECK_OK(f(m, id, b, n, &need));
        CHECK(need == n && memcmp(b, full, n * sizeof *b) == 0);
        CHECK_OK(f(m, id, b, SIZE_MAX, &need));
        CHECK(need == n && memcmp(b, full, n * sizeof *b) == 0);
        /* NULL handle, NULL buffer with a capacity, NULL out_len. */
        CHECK_STATUS(f(NULL, 0, b, 64, &n), TOPOMESH_STATUS_NULL_ARGUMENT);
        CHECK_DETAIL("'m'");
        CHECK_STATUS(f(m, 0, NULL, 4, &n), TOPOMESH_STATUS_NULL_ARGUMENT);
        CHECK_DETAIL("buf");
        CHECK_STATUS(f(m, 0, b, 64, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
        CHECK_DETAIL("out_len");
        /* Out of range: the id in the detail, nothing written. */
        uint32_t bad = (uint32_t)count_of(m, RELATIONS[r].kind);
        n = 777;
        CHECK_STATUS(f(m, bad, b, 64, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
        CHECK(n == 777);
        char detail[64];
        static const char *const what[] = {"vertex", "edge", "face", "tetrahedron"};
        snprintf(detail, sizeof detail, "%s %u", what[RELATIONS[r].kind], (unsigned)bad);
        CHECK_DETAIL(detail);
        CHECK_STATUS(f(m, TOPOMESH_NONE, b, 64, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
    }

    /* The single-value helpers. */
    uint32_t x;
    bool yes;
    CHECK_STATUS(chf_half_face_opposite(NULL, 0, &x), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_half_face_opposite(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("out");
    CHECK_STATUS(chf_half_face_opposite(m, 20, &x), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("half-face 20");
    CHECK_STATUS(chf_half_face_face(m, 20, &x), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(chf_half_face_face(NULL, 0, &x), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_face_half_face(m, 16, &x), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("face 16");
    CHECK_STATUS(chf_face_half_face(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_vertex_half_face(m, 8, &x), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("vertex 8");
    CHECK_STATUS(chf_vertex_half_face(NULL, 0, &x), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_vertex_is_boundary(m, 8, &yes), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(chf_vertex_is_boundary(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_edge_is_boundary(m, 18, &yes), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("edge 18");
    CHECK_STATUS(chf_edge_is_boundary(NULL, 0, &yes), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_face_is_boundary(m, 16, &yes), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(chf_face_is_boundary(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
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

/* Every relation and helper gives the same answer at levels 0, 1, 2 as at level 3. */
static void same_at_every_level(const char *name, const uint32_t *tets, size_t nt, size_t nv,
                                const double *pos) {
    chf_mesh *ref = make_chf(tets, nt, nv, pos, 3);
    invariants(name, ref);
    for (uint32_t level = 0; level < 3; level++) {
        chf_mesh *m = make_chf(tets, nt, nv, pos, level);
        CHECK(chf_mesh_num_vertices(m) == chf_mesh_num_vertices(ref));
        CHECK(chf_mesh_num_edges(m) == chf_mesh_num_edges(ref));
        CHECK(chf_mesh_num_faces(m) == chf_mesh_num_faces(ref));
        for (size_t r = 0; r < N_RELATIONS; r++) {
            size_t count = count_of(ref, RELATIONS[r].kind);
            for (uint32_t id = 0; id < count; id++) {
                uint32_t a[64], b[64];
                size_t na = 0, nb = 0;
                CHECK_OK(RELATIONS[r].fn(ref, id, a, 64, &na));
                CHECK_OK(RELATIONS[r].fn(m, id, b, 64, &nb));
                if (na != nb || memcmp(a, b, na * sizeof *a)) {
                    fprintf(stderr, "%s: %s(%u) differs at level %u from level 3\n", name,
                            RELATIONS[r].name, (unsigned)id, (unsigned)level);
                    print_ids_("level 3", a, na);
                    print_ids_("this level", b, nb);
                    check_failures++;
                }
            }
        }
        for (uint32_t hf = 0; hf < chf_mesh_num_half_faces(ref); hf++) {
            uint32_t a = 0, b = 1;
            CHECK_OK(chf_half_face_opposite(ref, hf, &a));
            CHECK_OK(chf_half_face_opposite(m, hf, &b));
            CHECK(a == b);
            CHECK_OK(chf_half_face_face(ref, hf, &a));
            CHECK_OK(chf_half_face_face(m, hf, &b));
            CHECK(a == b);
        }
        for (uint32_t v = 0; v < chf_mesh_num_vertices(ref); v++) {
            uint32_t a = 0, b = 1;
            bool x = false, y = true;
            CHECK_OK(chf_vertex_half_face(ref, v, &a));
            CHECK_OK(chf_vertex_half_face(m, v, &b));
            CHECK(a == b);
            CHECK_OK(chf_vertex_is_boundary(ref, v, &x));
            CHECK_OK(chf_vertex_is_boundary(m, v, &y));
            CHECK(x == y);
        }
        for (uint32_t e = 0; e < chf_mesh_num_edges(ref); e++) {
            bool x = false, y = true;
            CHECK_OK(chf_edge_is_boundary(ref, e, &x));
            CHECK_OK(chf_edge_is_boundary(m, e, &y));
            CHECK(x == y);
        }
        for (uint32_t f = 0; f < chf_mesh_num_faces(ref); f++) {
            uint32_t a = 0, b = 1;
            bool x = false, y = true;
            CHECK_OK(chf_face_half_face(ref, f, &a));
            CHECK_OK(chf_face_half_face(m, f, &b));
            CHECK(a == b);
            CHECK_OK(chf_face_is_boundary(ref, f, &x));
            CHECK_OK(chf_face_is_boundary(m, f, &y));
            CHECK(x == y);
        }
        /* Raising this mesh to level 3 gives the reference's views. */
        CHECK_OK(chf_mesh_build_level(m, 3));
        size_t la = 0, lb = 0;
        const uint32_t *oa = chf_mesh_opposites(ref, &la), *ob = chf_mesh_opposites(m, &lb);
        CHECK(oa && ob && la == lb && memcmp(oa, ob, la * sizeof *oa) == 0);
        oa = chf_mesh_vertex_half_faces(ref, &la);
        ob = chf_mesh_vertex_half_faces(m, &lb);
        CHECK(oa && ob && la == lb && memcmp(oa, ob, la * sizeof *oa) == 0);
        oa = chf_mesh_face_half_faces(ref, &la);
        ob = chf_mesh_face_half_faces(m, &lb);
        CHECK(oa && ob && la == lb && (la == 0 || memcmp(oa, ob, la * sizeof *oa) == 0));
        chf_mesh_free(m);
    }
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
