/* The stack star iterator, the bulk CSR calls and the zero-copy views. */
#include "threads.h"

/* The edge-id directory gives che_half_edge_edge inline, from level 1; NULL at level 0. */
static void edge_ranks_match(const che_mesh *m) {
    size_t nr = 7, no = 0;
    const uint64_t *ranks = che_mesh_edge_ranks(m, &nr);
    const uint32_t *O = che_mesh_opposites(m, &no);
    const size_t nh = che_mesh_num_half_edges(m);
    if (che_mesh_level(m) == 0) {
        CHECK(ranks == NULL && nr == 0);
        return;
    }
    CHECK(ranks != NULL && O != NULL);
    CHECK(nr == (nh + 31) / 32 && no == nh);
    for (uint32_t h = 0; h < nh; h++) {
        uint32_t e = TOPOMESH_NONE;
        CHECK_OK(che_half_edge_edge(m, h, &e));
        CHECK(che_edge_of(O, ranks, h) == e);
    }
    /* The same pointer again (computed once, kept with the mesh). */
    CHECK(che_mesh_edge_ranks(m, NULL) == ranks);
}

static void test_star(void) {
    che_mesh *m = make(STRIP, 2, 4, NULL, 2);
    che_star_iter it;
    che_star_step s;
    CHECK_OK(che_star_begin(m, 1, &it));
    CHECK(che_star_next(&it, &s));
    CHECK(s.half_edge == 3 && s.vertex == 3 && s.edge == 3 && s.triangle == 1);
    CHECK(che_star_next(&it, &s));
    CHECK(s.half_edge == 1 && s.vertex == 2 && s.edge == 1 && s.triangle == 0);
    CHECK(che_star_next(&it, &s));
    CHECK(s.half_edge == 0 && s.vertex == 0 && s.edge == 0 && s.triangle == TOPOMESH_NONE);
    CHECK(!che_star_next(&it, &s));

    CHECK_STATUS(che_star_begin(NULL, 0, &it), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_star_begin(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_star_begin(m, 4, &it), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("vertex 4");
    CHECK(!che_star_next(NULL, &s));
    CHECK(!che_star_advance(NULL, &s));
    CHECK_OK(che_star_begin(m, 0, &it));
    CHECK(!che_star_next(&it, NULL));
    CHECK(!che_star_advance(&it, NULL));
    for (uint32_t level = 0; level <= 3; level++) {
        CHECK_OK(che_mesh_build_level(m, level));
        edge_ranks_match(m);
    }
    /* Down and up again: the directory follows the level. */
    for (uint32_t level = 3; level-- > 0;) {
        CHECK_OK(che_mesh_build_level(m, level));
        edge_ranks_match(m);
    }
    size_t len = 9;
    CHECK(che_mesh_edge_ranks(NULL, &len) == NULL && len == 0);
    che_mesh_free(m);

    /* A 12 x 12 grid (288 triangles, several words of the edge-id directory) and every
       fixture. (test_che_star compares the star steps with the relations.) */
    enum { G = 12 };
    static uint32_t grid[6 * G * G];
    const size_t nt = grid_triangles(G, G, grid);
    for (uint32_t level = 0; level <= 3; level++) {
        m = make(grid, nt, (G + 1) * (G + 1), NULL, level);
        edge_ranks_match(m);
        che_mesh_free(m);
        for (size_t f = 0; f < N_CHE_FIXTURES; f++) {
            m = make(CHE_FIXTURES[f].tris, CHE_FIXTURES[f].n_tris, CHE_FIXTURES[f].n_verts,
                     NULL, level);
            edge_ranks_match(m);
            che_mesh_free(m);
        }
    }
}

IDS_QUERY(che_mesh, che_vertex_vertices)
IDS_QUERY(che_mesh, che_vertex_edges)
IDS_QUERY(che_mesh, che_vertex_triangles)
IDS_QUERY(che_mesh, che_triangle_triangles)
CSR_QUERY(che_mesh, che_mesh_vertex_vertices_csr)
CSR_QUERY(che_mesh, che_mesh_vertex_edges_csr)
CSR_QUERY(che_mesh, che_mesh_vertex_triangles_csr)
CSR_QUERY(che_mesh, che_mesh_triangle_triangles_csr)

/* The bulk calls with the relation of their rows: over vertices (0) or triangles (1). */
static const any_csr CSRS[] = {
    {q_che_mesh_vertex_vertices_csr, q_che_vertex_vertices, 0},
    {q_che_mesh_vertex_edges_csr, q_che_vertex_edges, 0},
    {q_che_mesh_vertex_triangles_csr, q_che_vertex_triangles, 0},
    {q_che_mesh_triangle_triangles_csr, q_che_triangle_triangles, 1},
};
#define N_CSRS (sizeof CSRS / sizeof CSRS[0])

static void test_csr(void) {
    for (size_t f = 0; f < N_CHE_FIXTURES; f++) {
        for (uint32_t level = 0; level <= 3; level++) {
            che_mesh *m = make(CHE_FIXTURES[f].tris, CHE_FIXTURES[f].n_tris,
                               CHE_FIXTURES[f].n_verts, NULL, level);
            for (size_t c = 0; c < N_CSRS; c++)
                csr_matches(&CSRS[c], m,
                            CSRS[c].kind ? che_mesh_num_triangles(m) : che_mesh_num_vertices(m));
            /* The bulk calls do not change the level. */
            CHECK(che_mesh_level(m) == level);
            che_mesh_free(m);
        }
    }

    /* The strip's VV in full, and the buffer rules. */
    che_mesh *m = make(STRIP, 2, 4, NULL, 2);
    uint32_t off[8], idx[16];
    size_t no = 0, ni = 0;
    CHECK_OK(che_mesh_vertex_vertices_csr(m, off, 8, idx, 16, &no, &ni));
    CHECK_IDS(off, no, 0, 2, 5, 8, 10);
    CHECK_IDS(idx, ni, 1, 2, 3, 2, 0, 0, 1, 3, 2, 1);
    CHECK_OK(che_mesh_triangle_triangles_csr(m, off, 8, idx, 16, &no, &ni));
    CHECK_IDS(off, no, 0, 3, 6);
    CHECK_IDS(idx, ni, N_, 1, N_, N_, N_, 0);
    /* The buffer rules. */
    for (size_t c = 0; c < N_CSRS; c++) check_csr_errors(CSRS[c].csr, m);
    che_mesh_free(m);
}

VIEW_QUERY(che_mesh, che_mesh_half_edge_vertices)
VIEW_QUERY(che_mesh, che_mesh_opposites)
VIEW_QUERY(che_mesh, che_mesh_vertex_origins)
VIEW_QUERY(che_mesh, che_mesh_triangle_origins)
VIEW_QUERY(che_mesh, che_mesh_vertex_half_edges)
VIEW_QUERY(che_mesh, che_mesh_edge_half_edges)
VIEW_QUERY(che_mesh, che_mesh_curve_half_edges)
static const any_view_fn VIEWS[] = {
    q_che_mesh_half_edge_vertices, q_che_mesh_opposites,       q_che_mesh_vertex_origins,
    q_che_mesh_triangle_origins,   q_che_mesh_vertex_half_edges, q_che_mesh_edge_half_edges,
    q_che_mesh_curve_half_edges};

/* che_mesh_views gives at once what the single views and counts give. */
static void views_match(const che_mesh *m) {
    che_views all;
    CHECK_OK(che_mesh_views(m, &all));
    CHECK(all.half_edge_vertices == che_mesh_half_edge_vertices(m, NULL));
    CHECK(all.opposites == che_mesh_opposites(m, NULL));
    CHECK(all.vertex_half_edges == che_mesh_vertex_half_edges(m, NULL));
    CHECK(all.edge_half_edges == che_mesh_edge_half_edges(m, NULL));
    CHECK(all.positions == che_mesh_positions(m, NULL));
    CHECK(all.num_vertices == che_mesh_num_vertices(m));
    CHECK(all.num_triangles == che_mesh_num_triangles(m));
    CHECK(all.num_edges == che_mesh_num_edges(m));
}

static void test_views(void) {
    che_mesh *m = make(STRIP, 2, 4, STRIP_POS, 0);
    size_t len = 99;
    const uint32_t *V = che_mesh_half_edge_vertices(m, &len);
    CHECK(V != NULL && len == 6);
    if (V) CHECK_IDS(V, len, 0, 1, 2, 1, 3, 2);
    /* Containers that do not exist at this level. */
    len = 99;
    CHECK(che_mesh_opposites(m, &len) == NULL && len == 0);
    CHECK(che_mesh_vertex_half_edges(m, &len) == NULL && len == 0);
    CHECK(che_mesh_edge_half_edges(m, &len) == NULL && len == 0);
    CHECK(che_mesh_curve_half_edges(m, &len) == NULL && len == 0);
    const double *P = che_mesh_positions(m, &len);
    CHECK(P != NULL && len == 12);
    if (P) CHECK(memcmp(P, STRIP_POS, sizeof STRIP_POS) == 0);
    /* Identity origins are materialised on demand. */
    const uint32_t *vo = che_mesh_vertex_origins(m, &len);
    CHECK(vo != NULL);
    if (vo) CHECK_IDS(vo, len, 0, 1, 2, 3);
    const uint32_t *to = che_mesh_triangle_origins(m, &len);
    CHECK(to != NULL);
    if (to) CHECK_IDS(to, len, 0, 1);
    CHECK(che_mesh_vertex_origins(m, NULL) == vo); /* the same storage on every call */
    views_match(m);

    CHECK_OK(che_mesh_build_level(m, 1));
    const uint32_t *O = che_mesh_opposites(m, &len);
    CHECK(O != NULL && len == 6);
    if (O) CHECK_IDS(O, len, N_, 5, N_, N_, N_, 1);
    CHECK(che_mesh_vertex_half_edges(m, &len) == NULL);

    CHECK_OK(che_mesh_build_level(m, 2));
    const uint32_t *VH = che_mesh_vertex_half_edges(m, &len);
    CHECK(VH != NULL && len == 4);
    if (VH) CHECK_IDS(VH, len, 0, 3, 2, 4);
    const uint32_t *EH = che_mesh_edge_half_edges(m, &len);
    CHECK(EH != NULL && len == 5);
    if (EH) CHECK_IDS(EH, len, 0, 1, 2, 3, 4);
    CHECK(che_mesh_curve_half_edges(m, &len) == NULL);

    CHECK_OK(che_mesh_build_level(m, 3));
    const uint32_t *CH = che_mesh_curve_half_edges(m, &len);
    CHECK(CH != NULL && len == 1);
    if (CH) CHECK_IDS(CH, len, 0);
    views_match(m);

    /* Going down drops them again. */
    CHECK_OK(che_mesh_build_level(m, 1));
    CHECK(che_mesh_vertex_half_edges(m, &len) == NULL && len == 0);
    CHECK(che_mesh_opposites(m, &len) != NULL && len == 6);
    views_match(m);
    che_views none;
    CHECK(che_mesh_views(NULL, &none) == TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK(che_mesh_views(m, NULL) == TOPOMESH_STATUS_NULL_ARGUMENT);

    /* NULL handle: NULL and 0; a NULL len is allowed. */
    check_null_views(VIEWS, sizeof VIEWS / sizeof VIEWS[0]);
    len = 99;
    CHECK(che_mesh_positions(NULL, &len) == NULL && len == 0);
    che_mesh_free(m);

    /* The O invariants, walked with the inline arithmetic, on a closed mesh. */
    m = make(TETRA, 4, 4, NULL, 2);
    size_t n = 0;
    V = che_mesh_half_edge_vertices(m, &n);
    O = che_mesh_opposites(m, NULL);
    for (uint32_t h = 0; h < n; h++) {
        CHECK(O[h] != TOPOMESH_NONE && O[O[h]] == h);
        CHECK(V[O[h]] == V[che_next(h)] && V[che_next(O[h])] == V[h]);
        CHECK(che_prev(che_next(h)) == h && che_tri(h) == h / 3 && che_first(che_tri(h)) <= h);
    }
    VH = che_mesh_vertex_half_edges(m, &n);
    for (uint32_t v = 0; v < n; v++) CHECK(V[VH[v]] == v);
    che_mesh_free(m);
}

/* Any number of threads may query one const mesh at once, including the first request of
   an identity origin map (materialised once). */
static void *query_everything(void *arg) {
    thread_job *j = arg;
    size_t len = 0;
    j->origins = che_mesh_vertex_origins(j->m, &len);
    if (!j->origins || len != che_mesh_num_vertices(j->m)) j->failed = 1;
    for (int round = 0; round < 50; round++) {
        size_t total = 0;
        for (uint32_t v = 0; v < che_mesh_num_vertices(j->m); v++) {
            che_star_iter it;
            che_star_step s;
            if (che_star_begin(j->m, v, &it) != TOPOMESH_STATUS_OK) j->failed = 1;
            while (che_star_next(&it, &s)) total++;
        }
        size_t no = 0, ni = 0;
        if (che_mesh_vertex_vertices_csr(j->m, NULL, 0, NULL, 0, &no, &ni) != TOPOMESH_STATUS_OK ||
            ni != total)
            j->failed = 1;
        j->total = total;
    }
    return NULL;
}

static void test_threads(void) {
    che_mesh *m = make(MOEBIUS, 6, 6, NULL, 1);
    size_t vv = 0, n = 0; /* the answer: the total of VV */
    for (uint32_t v = 0; v < che_mesh_num_vertices(m); v++, vv += n)
        CHECK_OK(che_vertex_vertices(m, v, NULL, 0, &n));
    run_threads(m, query_everything, vv);
    che_mesh_free(m);
}

int main(void) {
    test_threads();
    test_star();
    test_csr();
    test_views();
    return finish("test_che_iter");
}
