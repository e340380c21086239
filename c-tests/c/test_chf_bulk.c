/* CHF: the bulk CSR calls, the zero-copy views with the inline half-face arithmetic, the
   boundary surface and its maps, and concurrent queries. */
#include "chf_fixtures.h"
#include "threads.h"

CSR_QUERY(chf_mesh, chf_mesh_vertex_vertices_csr)
CSR_QUERY(chf_mesh, chf_mesh_vertex_edges_csr)
CSR_QUERY(chf_mesh, chf_mesh_vertex_faces_csr)
CSR_QUERY(chf_mesh, chf_mesh_vertex_tetrahedra_csr)
CSR_QUERY(chf_mesh, chf_mesh_edge_faces_csr)
CSR_QUERY(chf_mesh, chf_mesh_edge_tetrahedra_csr)
CSR_QUERY(chf_mesh, chf_mesh_tetrahedron_tetrahedra_csr)
VALUE_QUERY(chf_mesh, chf_boundary_triangle_half_face)
VALUE_QUERY(chf_mesh, chf_boundary_triangle_face)
VALUE_QUERY(chf_mesh, chf_half_face_boundary_triangle)
VALUE_QUERY(chf_mesh, chf_face_boundary_triangle)
VALUE_QUERY(chf_mesh, chf_vertex_boundary_component)
VALUE_QUERY(chf_mesh, chf_vertex_boundary_vertex)
VALUE_QUERY(chf_mesh, chf_boundary_vertex_vertex)

/* The bulk calls with the relation of their rows. */
static const any_csr CSRS[] = {
    {q_chf_mesh_vertex_vertices_csr, q_chf_vertex_vertices, VERTEX},
    {q_chf_mesh_vertex_edges_csr, q_chf_vertex_edges, VERTEX},
    {q_chf_mesh_vertex_faces_csr, q_chf_vertex_faces, VERTEX},
    {q_chf_mesh_vertex_tetrahedra_csr, q_chf_vertex_tetrahedra, VERTEX},
    {q_chf_mesh_edge_faces_csr, q_chf_edge_faces, EDGE},
    {q_chf_mesh_edge_tetrahedra_csr, q_chf_edge_tetrahedra, EDGE},
    {q_chf_mesh_tetrahedron_tetrahedra_csr, q_chf_tetrahedron_tetrahedra, TETRAHEDRON},
};
#define N_CSRS (sizeof CSRS / sizeof CSRS[0])

/* The boundary maps (one id each). */
static const any_query MAPS[] = {
    {"chf_boundary_triangle_half_face", q_chf_boundary_triangle_half_face, BOUNDARY_TRIANGLE},
    {"chf_boundary_triangle_face", q_chf_boundary_triangle_face, BOUNDARY_TRIANGLE},
    {"chf_half_face_boundary_triangle", q_chf_half_face_boundary_triangle, HALF_FACE},
    {"chf_face_boundary_triangle", q_chf_face_boundary_triangle, FACE},
    {"chf_vertex_boundary_component", q_chf_vertex_boundary_component, VERTEX},
    {"chf_vertex_boundary_vertex", q_chf_vertex_boundary_vertex, VERTEX},
    {"chf_boundary_vertex_vertex", q_chf_boundary_vertex_vertex, BOUNDARY_VERTEX},
};
#define N_MAPS (sizeof MAPS / sizeof MAPS[0])

static void test_csr(void) {
    const uint32_t *fixtures[] = {TET, PAIR, SPLIT, CUBE, STAR, BOOK, TDEGEN};
    const size_t nt[] = {1, 2, 2, 5, 4, 3, 3}, nv[] = {4, 5, 7, 8, 5, 6, 6};
    for (int f = 0; f < 7; f++) {
        for (uint32_t level = 0; level <= 3; level++) {
            chf_mesh *m = make_chf(fixtures[f], nt[f], nv[f], NULL, level);
            for (size_t c = 0; c < N_CSRS; c++)
                csr_matches(&CSRS[c], m, count_of(m, CSRS[c].kind));
            /* The bulk calls do not change the level. */
            CHECK(chf_mesh_level(m) == level);
            chf_mesh_free(m);
        }
    }

    /* The pair in full, and the buffer rules. */
    chf_mesh *m = make_chf(PAIR, 2, 5, NULL, 0);
    uint32_t off[16], idx[32];
    size_t no = 0, ni = 0;
    CHECK_OK(chf_mesh_vertex_tetrahedra_csr(m, off, 16, idx, 32, &no, &ni));
    CHECK_IDS(off, no, 0, 1, 3, 5, 7, 8);
    CHECK_IDS(idx, ni, 0, 0, 1, 0, 1, 0, 1, 1);
    CHECK_OK(chf_mesh_tetrahedron_tetrahedra_csr(m, off, 16, idx, 32, &no, &ni));
    CHECK_IDS(off, no, 0, 4, 8);
    CHECK_IDS(idx, ni, 1, N_, N_, N_, 0, N_, N_, N_);
    CHECK_OK(chf_mesh_edge_tetrahedra_csr(m, off, 16, idx, 32, &no, &ni));
    CHECK_IDS(off, no, 0, 1, 2, 3, 5, 7, 9, 10, 11, 12);
    CHECK_IDS(idx, ni, 0, 0, 0, 0, 1, 0, 1, 0, 1, 1, 1, 1);
    CHECK_OK(chf_mesh_vertex_vertices_csr(m, off, 16, idx, 32, &no, &ni));
    CHECK_IDS(off, no, 0, 3, 7, 11, 15, 18);
    CHECK_IDS(idx, 4, 1, 2, 3, 0); /* VV(0), then VV(1) starts */
    CHECK(chf_mesh_level(m) == 0);
    /* The buffer rules. */
    for (size_t c = 0; c < N_CSRS; c++) check_csr_errors(CSRS[c].csr, m);
    chf_mesh_free(m);
}

/* The corners of half-face hf in outward order, through the inline arithmetic. */
static void corners(const uint32_t *V, uint32_t hf, uint32_t out[3]) {
    for (uint32_t j = 0; j < 3; j++) out[j] = V[chf_face_corner(hf, j)];
}

VIEW_QUERY(chf_mesh, chf_mesh_half_face_vertices)
VIEW_QUERY(chf_mesh, chf_mesh_opposites)
VIEW_QUERY(chf_mesh, chf_mesh_vertex_origins)
VIEW_QUERY(chf_mesh, chf_mesh_tetrahedron_origins)
VIEW_QUERY(chf_mesh, chf_mesh_vertex_half_faces)
VIEW_QUERY(chf_mesh, chf_mesh_face_half_faces)
VIEW_QUERY(chf_mesh, chf_mesh_boundary_half_faces)
VIEW_QUERY(chf_mesh, chf_mesh_boundary_vertex_components)
VIEW_QUERY(chf_mesh, chf_mesh_boundary_vertices)
static const any_view_fn VIEWS[] = {
    q_chf_mesh_half_face_vertices,
    q_chf_mesh_opposites,
    q_chf_mesh_vertex_origins,
    q_chf_mesh_tetrahedron_origins,
    q_chf_mesh_vertex_half_faces,
    q_chf_mesh_face_half_faces,
    q_chf_mesh_boundary_half_faces,
    q_chf_mesh_boundary_vertex_components,
    q_chf_mesh_boundary_vertices,
};

static void test_views(void) {
    chf_mesh *m = make_chf(PAIR, 2, 5, PAIR_POS, 0);
    size_t len = 99;
    const uint32_t *V = chf_mesh_half_face_vertices(m, &len);
    CHECK(V != NULL && len == 8);
    if (V) CHECK_IDS(V, len, 0, 1, 2, 3, 4, 1, 3, 2);
    /* Containers that do not exist at this level. */
    len = 99;
    CHECK(chf_mesh_opposites(m, &len) == NULL && len == 0);
    CHECK(chf_mesh_vertex_half_faces(m, &len) == NULL && len == 0);
    CHECK(chf_mesh_face_half_faces(m, &len) == NULL && len == 0);
    CHECK(chf_mesh_boundary_half_faces(m, &len) == NULL && len == 0);
    CHECK(chf_mesh_boundary_vertex_components(m, &len) == NULL && len == 0);
    CHECK(chf_mesh_boundary_vertices(m, &len) == NULL && len == 0);
    const double *P = chf_mesh_positions(m, &len);
    CHECK(P != NULL && len == 15);
    if (P) CHECK(memcmp(P, PAIR_POS, sizeof PAIR_POS) == 0);
    /* Identity origins are materialised on demand, once. */
    const uint32_t *vo = chf_mesh_vertex_origins(m, &len);
    CHECK(vo != NULL);
    if (vo) CHECK_IDS(vo, len, 0, 1, 2, 3, 4);
    const uint32_t *to = chf_mesh_tetrahedron_origins(m, &len);
    CHECK(to != NULL);
    if (to) CHECK_IDS(to, len, 0, 1);
    CHECK(chf_mesh_vertex_origins(m, NULL) == vo);
    CHECK(chf_mesh_tetrahedron_origins(m, NULL) == to);

    CHECK_OK(chf_mesh_build_level(m, 1));
    const uint32_t *O = chf_mesh_opposites(m, &len);
    CHECK(O != NULL && len == 8);
    if (O) CHECK_IDS(O, len, 4, N_, N_, N_, 0, N_, N_, N_);
    CHECK(chf_mesh_vertex_half_faces(m, &len) == NULL);

    CHECK_OK(chf_mesh_build_level(m, 2));
    const uint32_t *VH = chf_mesh_vertex_half_faces(m, &len);
    CHECK(VH != NULL && len == 5);
    if (VH) CHECK_IDS(VH, len, 1, 2, 1, 1, 5);
    const uint32_t *FH = chf_mesh_face_half_faces(m, &len);
    CHECK(FH != NULL && len == 7);
    if (FH) CHECK_IDS(FH, len, 0, 1, 2, 3, 5, 6, 7);
    CHECK(chf_mesh_boundary_half_faces(m, &len) == NULL);

    CHECK_OK(chf_mesh_build_level(m, 3));
    const uint32_t *BH = chf_mesh_boundary_half_faces(m, &len);
    CHECK(BH != NULL && len == 6);
    if (BH) CHECK_IDS(BH, len, 1, 2, 3, 5, 6, 7);
    const uint32_t *BC = chf_mesh_boundary_vertex_components(m, &len);
    CHECK(BC != NULL && len == 5);
    if (BC) CHECK_IDS(BC, len, 0, 0, 0, 0, 0);
    const uint32_t *BV = chf_mesh_boundary_vertices(m, &len);
    CHECK(BV != NULL && len == 5);
    if (BV) CHECK_IDS(BV, len, 0, 1, 2, 3, 4);

    /* Going down drops them again. */
    CHECK_OK(chf_mesh_build_level(m, 1));
    CHECK(chf_mesh_vertex_half_faces(m, &len) == NULL && len == 0);
    CHECK(chf_mesh_boundary_half_faces(m, &len) == NULL && len == 0);
    CHECK(chf_mesh_opposites(m, &len) != NULL && len == 8);

    /* NULL handle: NULL and 0; a NULL len is allowed. */
    check_null_views(VIEWS, sizeof VIEWS / sizeof VIEWS[0]);
    len = 99;
    CHECK(chf_mesh_positions(NULL, &len) == NULL && len == 0);
    chf_mesh_free(m);

    /* The O and VH invariants, walked with the inline arithmetic. */
    m = make_chf(CUBE, 5, 8, CUBE_POS, 2);
    size_t n = 0;
    V = chf_mesh_half_face_vertices(m, &n);
    O = chf_mesh_opposites(m, NULL);
    FH = chf_mesh_face_half_faces(m, &len);
    CHECK(n == 20 && len == 16);
    for (uint32_t hf = 0; hf < n; hf++) {
        CHECK(chf_tet(hf) == hf / 4 && chf_local(hf) == hf % 4 && chf_first(chf_tet(hf)) <= hf);
        CHECK(chf_tet(chf_next(hf)) == chf_tet(hf) && chf_next(chf_next(chf_next(chf_next(hf)))) == hf);
        CHECK(chf_local(chf_next(hf)) == (chf_local(hf) + 1) % 4);
        uint32_t a[3], b[3];
        corners(V, hf, a);
        /* The corners are the other three vertices of the tetrahedron. */
        for (uint32_t j = 0; j < 3; j++) CHECK(chf_face_corner(hf, j) != hf && a[j] != V[hf]);
        if (O[hf] == TOPOMESH_NONE) continue;
        CHECK(O[O[hf]] == hf && chf_tet(O[hf]) != chf_tet(hf));
        /* A twin lists the same vertices in the opposite cyclic order. */
        corners(V, O[hf], b);
        int found = 0;
        for (int r = 0; r < 3; r++)
            found |= a[0] == b[r] && a[1] == b[(r + 2) % 3] && a[2] == b[(r + 1) % 3];
        CHECK(found);
    }
    for (uint32_t f = 0; f < len; f++) {
        uint32_t fv[3], c[3];
        size_t k = 0;
        CHECK_OK(chf_face_vertices(m, f, fv, 3, &k));
        corners(V, FH[f], c);
        CHECK(k == 3 && memcmp(fv, c, sizeof c) == 0);
    }
    VH = chf_mesh_vertex_half_faces(m, &n);
    for (uint32_t v = 0; v < n; v++) {
        uint32_t c[3];
        corners(V, VH[v], c);
        CHECK(c[0] == v || c[1] == v || c[2] == v);
        CHECK(O[VH[v]] == TOPOMESH_NONE); /* every cube vertex is on the boundary */
    }
    chf_mesh_free(m);
}

/* The boundary surface: a closed CHE whose triangle k is boundary half-face k, outward. */
static void check_boundary(const char *name, const chf_mesh *m, size_t want_triangles,
                           uint64_t want_vertices, uint64_t want_edges, int64_t want_euler,
                           uint64_t want_isolated, uint64_t want_components) {
    int failures_before = check_failures;
    che_mesh *s = (che_mesh *)&s;
    CHECK_OK(chf_mesh_boundary(m, &s));
    CHECK(s != NULL && che_mesh_level(s) == 3);
    CHECK(che_mesh_num_triangles(s) == want_triangles);
    CHECK(chf_mesh_num_boundary_triangles(m) == want_triangles);
    /* Manifold fixtures: every unpaired half-face is a boundary face. */
    CHECK(chf_mesh_num_boundary_faces(m) == want_triangles);
    CHECK(chf_mesh_num_non_manifold_half_faces(m) == 0 && chf_mesh_num_seam_half_faces(m) == 0);
    CHECK(chf_mesh_num_boundary_vertices(m) == want_vertices);
    che_summary sum;
    CHECK_OK(che_mesh_summary(s, &sum));
    CHECK(sum.vertices == want_vertices && sum.edges == want_edges);
    CHECK(sum.triangles == want_triangles && sum.euler_characteristic == want_euler);
    CHECK(sum.isolated_vertices == want_isolated && sum.components == want_components);
    CHECK(sum.boundary_edges == 0 && sum.manifold && sum.orientable);
    CHECK(sum.flipped_triangles == 0 && sum.genus == 0);
    for (uint32_t k = 0; k < want_triangles; k++) {
        uint32_t hf = 0, f = 0, back = 0, tv[3], fv[3];
        size_t n = 0;
        CHECK_OK(chf_boundary_triangle_half_face(m, k, &hf));
        CHECK_OK(chf_half_face_boundary_triangle(m, hf, &back));
        CHECK(back == k);
        CHECK_OK(chf_boundary_triangle_face(m, k, &f));
        CHECK_OK(chf_face_boundary_triangle(m, f, &back));
        CHECK(back == k);
        CHECK_OK(chf_face_half_face(m, f, &back));
        CHECK(back == hf);
        CHECK_OK(che_triangle_vertices(s, k, tv, 3, &n));
        CHECK_OK(chf_face_vertices(m, f, fv, 3, &n));
        /* Compact boundary vertex ids, mapped both ways. */
        for (int j = 0; j < 3; j++) {
            uint32_t v = 0, b = 0;
            CHECK_OK(chf_boundary_vertex_vertex(m, tv[j], &v));
            CHECK(v == fv[j]);
            CHECK_OK(chf_vertex_boundary_vertex(m, fv[j], &b));
            CHECK(b == tv[j]);
        }
        /* Its vertices are boundary vertices, in one boundary component. */
        uint32_t c0 = 0, c = 0;
        CHECK_OK(chf_vertex_boundary_component(m, fv[0], &c0));
        CHECK(c0 < chf_mesh_num_boundary_components(m));
        for (int j = 0; j < 3; j++) {
            bool yes = false;
            CHECK_OK(chf_vertex_is_boundary(m, fv[j], &yes));
            CHECK(yes);
            CHECK_OK(chf_vertex_boundary_component(m, fv[j], &c));
            CHECK(c == c0);
        }
    }
    /* Interior half-faces and faces map to no triangle. */
    for (uint32_t hf = 0; hf < chf_mesh_num_half_faces(m); hf++) {
        uint32_t o = 0, k = 0;
        CHECK_OK(chf_half_face_opposite(m, hf, &o));
        CHECK_OK(chf_half_face_boundary_triangle(m, hf, &k));
        CHECK((o == TOPOMESH_NONE) == (k != TOPOMESH_NONE));
        if (o != TOPOMESH_NONE) {
            uint32_t f = 0;
            CHECK_OK(chf_half_face_face(m, hf, &f));
            CHECK_OK(chf_face_boundary_triangle(m, f, &k));
            CHECK(k == TOPOMESH_NONE);
        }
    }
    che_mesh_free(s);
    if (check_failures != failures_before) fprintf(stderr, "  (boundary of %s)\n", name);
}

static void test_boundary(void) {
    for (uint32_t level = 0; level <= 3; level++) {
        chf_mesh *m = make_chf(CUBE, 5, 8, CUBE_POS, level);
        check_boundary("cube", m, 12, 8, 18, 2, 0, 1);
        CHECK(chf_mesh_num_boundary_components(m) == 1);
        CHECK(chf_mesh_level(m) == level);
        chf_mesh_free(m);

        m = make_chf(PAIR, 2, 5, NULL, level);
        check_boundary("pair", m, 6, 5, 9, 2, 0, 1);
        chf_mesh_free(m);

        /* The interior vertex 4 is not a vertex of the surface. */
        m = make_chf(STAR, 4, 5, STAR_POS, level);
        check_boundary("star", m, 4, 4, 6, 2, 0, 1);
        uint32_t c = 0;
        CHECK_OK(chf_vertex_boundary_vertex(m, 4, &c));
        CHECK(c == TOPOMESH_NONE);
        bool yes = true;
        CHECK_OK(chf_vertex_boundary_component(m, 4, &c));
        CHECK(c == TOPOMESH_NONE);
        CHECK_OK(chf_vertex_is_boundary(m, 4, &yes));
        CHECK(!yes);
        chf_mesh_free(m);

        /* Two surfaces after the split: components 0 and 1. */
        m = make_chf(SPLIT, 2, 7, SPLIT_POS, level);
        check_boundary("split", m, 8, 8, 12, 4, 0, 2);
        CHECK(chf_mesh_num_boundary_components(m) == 2);
        uint32_t c7 = 0;
        CHECK_OK(chf_vertex_boundary_component(m, 0, &c));
        CHECK_OK(chf_vertex_boundary_component(m, 7, &c7));
        CHECK(c != c7 && c < 2 && c7 < 2);
        chf_mesh_free(m);
    }
    /* A mesh without tetrahedra has an empty boundary. */
    chf_mesh *m = make_chf(NULL, 0, 3, NULL, 2);
    che_mesh *s = NULL;
    CHECK_OK(chf_mesh_boundary(m, &s));
    CHECK(s != NULL && che_mesh_num_triangles(s) == 0);
    che_mesh_free(s);
    chf_mesh_free(m);

    /* Errors. */
    m = make_chf(CUBE, 5, 8, NULL, 3);
    s = (che_mesh *)&s;
    CHECK_STATUS(chf_mesh_boundary(NULL, &s), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK(s == NULL);
    CHECK_STATUS(chf_mesh_boundary(m, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("out");
    for (size_t q = 0; q < N_MAPS; q++)
        check_value_errors(MAPS[q].fn, m, count_of(m, MAPS[q].kind), KIND_NAMES[MAPS[q].kind]);
    CHECK(chf_mesh_num_boundary_triangles(NULL) == 0 && chf_mesh_num_boundary_vertices(NULL) == 0);
    CHECK(chf_mesh_num_non_manifold_half_faces(NULL) == 0 && chf_mesh_num_seam_half_faces(NULL) == 0);
    chf_mesh_free(m);
}

/* Any number of threads may query one const mesh at once, including the first request of
   an identity origin map (materialised once). */
static void *query_everything(void *arg) {
    thread_job *j = arg;
    size_t len = 0;
    j->origins = chf_mesh_vertex_origins(j->m, &len);
    if (!j->origins || len != chf_mesh_num_vertices(j->m)) j->failed = 1;
    if (!chf_mesh_tetrahedron_origins(j->m, &len) || len != chf_mesh_num_tetrahedra(j->m))
        j->failed = 1;
    for (int round = 0; round < 20; round++) {
        size_t total = 0;
        for (uint32_t v = 0; v < chf_mesh_num_vertices(j->m); v++) {
            size_t n = 0;
            if (chf_vertex_tetrahedra(j->m, v, NULL, 0, &n) != TOPOMESH_STATUS_OK) j->failed = 1;
            total += n;
        }
        size_t no = 0, ni = 0;
        if (chf_mesh_vertex_tetrahedra_csr(j->m, NULL, 0, NULL, 0, &no, &ni) !=
                TOPOMESH_STATUS_OK ||
            ni != total || total != 4 * chf_mesh_num_tetrahedra(j->m))
            j->failed = 1;
        j->total = total;
    }
    return NULL;
}

static void test_threads(void) {
    chf_mesh *m = make_chf(CUBE, 5, 8, NULL, 1);
    run_threads(m, query_everything, 20);
    chf_mesh_free(m);
}

int main(void) {
    test_threads();
    test_csr();
    test_views();
    test_boundary();
    return finish("test_chf_bulk");
}
