/* The exports: half-edge and winged-edge arrays, the corner table, edge and face lists,
   sparse matrices, Betti numbers and strips: exact answers on a strip of two triangles,
   the same answers at every level on every fixture, d1 * d2 == 0, Betti numbers against
   the Euler characteristic, and the buffer rules. */
#include "export_matrix.h"

#define CAP 512

/* The ids export f gives for `which` (options NULL), into out (CAP entries); its length. */
typedef topomesh_status (*kind_fn)(const che_mesh *, uint32_t, uint32_t *, size_t, size_t *);
typedef topomesh_status (*list_fn)(const che_mesh *, uint32_t *, size_t, size_t *);

static topomesh_status half_edges_marked(const che_mesh *m, uint32_t which, uint32_t *b, size_t cap,
                                         size_t *n) {
    return che_mesh_export_half_edges(m, NULL, which, b, cap, n);
}
static topomesh_status half_edges_explicit(const che_mesh *m, uint32_t which, uint32_t *b,
                                           size_t cap, size_t *n) {
    const che_half_edge_options o = {true};
    return che_mesh_export_half_edges(m, &o, which, b, cap, n);
}

static size_t get_kind(kind_fn f, const che_mesh *m, uint32_t which, uint32_t *out) {
    size_t n = 0, need = 0;
    CHECK_OK(f(m, which, NULL, 0, &need));
    CHECK_OK(f(m, which, out, CAP, &n));
    CHECK(n == need && n <= CAP);
    return n;
}
static size_t get_list(list_fn f, const che_mesh *m, uint32_t *out) {
    size_t n = 0, need = 0;
    CHECK_OK(f(m, NULL, 0, &need));
    CHECK_OK(f(m, out, CAP, &n));
    CHECK(n == need && n <= CAP);
    return n;
}

MATRIX_QUERY(che_mesh, che_mesh_export_matrix)

static void test_strip_exact(void) {
    che_mesh *m = make(STRIP, 2, 4, NULL, 2);
    uint32_t b[CAP];
    size_t n = get_kind(half_edges_marked, m, CHE_HALF_EDGE_ARRAY_TWIN, b);
    CHECK_IDS(b, n, N_, 5, N_, N_, N_, 1);
    n = get_kind(half_edges_marked, m, CHE_HALF_EDGE_ARRAY_VERTEX, b);
    CHECK_IDS(b, n, 0, 1, 2, 1, 3, 2);
    n = get_kind(half_edges_marked, m, CHE_HALF_EDGE_ARRAY_NEXT, b);
    CHECK_IDS(b, n, 1, 2, 0, 4, 5, 3);
    n = get_kind(half_edges_marked, m, CHE_HALF_EDGE_ARRAY_EDGE, b);
    CHECK_IDS(b, n, 0, 1, 2, 3, 4, 1);
    n = get_kind(half_edges_marked, m, CHE_HALF_EDGE_ARRAY_FACE_HALF_EDGE, b);
    CHECK_IDS(b, n, 0, 3);
    /* Explicit boundary: the twins of h0, h2, h3, h4 are 6..9, round the hole. */
    n = get_kind(half_edges_explicit, m, CHE_HALF_EDGE_ARRAY_TWIN, b);
    CHECK_IDS(b, n, 6, 5, 7, 8, 9, 1, 0, 2, 3, 4);
    n = get_kind(half_edges_explicit, m, CHE_HALF_EDGE_ARRAY_VERTEX, b);
    CHECK_IDS(b, n, 0, 1, 2, 1, 3, 2, 1, 0, 3, 2);
    n = get_kind(half_edges_explicit, m, CHE_HALF_EDGE_ARRAY_NEXT, b);
    CHECK_IDS(b, n, 1, 2, 0, 4, 5, 3, 7, 9, 6, 8);
    n = get_kind(half_edges_explicit, m, CHE_HALF_EDGE_ARRAY_FACE, b);
    CHECK_IDS(b, n, 0, 0, 0, 1, 1, 1, N_, N_, N_, N_);
    n = get_kind(half_edges_explicit, m, CHE_HALF_EDGE_ARRAY_VERTEX_HALF_EDGE, b);
    CHECK_IDS(b, n, 7, 6, 9, 8);

    n = get_kind(che_mesh_export_winged_edges, m, CHE_WINGED_ARRAY_WINGS, b);
    static const uint32_t WINGS[] = {2, 1, N_, N_, 0, 2, 4, 3, 1, 0,
                                     N_, N_, 1, 4, N_, N_, 3, 1, N_, N_};
    CHECK(n == 20 && memcmp(b, WINGS, sizeof WINGS) == 0);
    n = get_kind(che_mesh_export_winged_edges, m, CHE_WINGED_ARRAY_FACES, b);
    CHECK_IDS(b, n, 0, N_, 0, 1, 0, N_, 1, N_, 1, N_);
    n = get_list(che_mesh_export_corner_opposites, m, b);
    CHECK_IDS(b, n, 4, N_, N_, N_, 0, N_);
    n = get_list(che_mesh_export_edge_list, m, b);
    CHECK_IDS(b, n, 0, 1, 1, 2, 2, 0, 1, 3, 3, 2);
    n = get_list(che_mesh_export_triangle_edges, m, b);
    CHECK_IDS(b, n, 0, 1, 2, 3, 4, 1);
    n = get_kind(che_mesh_export_strips, m, CHE_STRIP_LIST_RESTARTS, b);
    CHECK_IDS(b, n, 0, 1, 2, 3);

    matrix a;
    get_matrix(q_che_mesh_export_matrix, m, CHE_MATRIX_KIND_LAPLACIAN, &a);
    CHECK(a.rows == 4 && a.nnz == 14);
    CHECK(a.offsets[1] == 3 && a.columns[0] == 0 && a.values[0] == 2 && a.values[1] == -1);
    get_matrix(q_che_mesh_export_matrix, m, CHE_MATRIX_KIND_D1, &a);
    CHECK(a.rows == 4 && a.nnz == 10);
    /* Vertex 0: edge 0 (0 -> 1) leaves it, edge 2 (2 -> 0) enters it. */
    CHECK(a.offsets[1] == 2 && a.columns[0] == 0 && a.values[0] == -1);
    CHECK(a.columns[1] == 2 && a.values[1] == 1);

    che_betti betti;
    CHECK_OK(che_mesh_betti_numbers(m, &betti));
    CHECK(betti.b0 == 1 && betti.b1 == 0 && betti.b2 == 0);
    che_mesh_free(m);
}

/* d1 * d2 == 0. */
static void check_boundary_of_boundary(const che_mesh *m) {
    static matrix d1, d2;
    get_matrix(q_che_mesh_export_matrix, m, CHE_MATRIX_KIND_D1, &d1);
    get_matrix(q_che_mesh_export_matrix, m, CHE_MATRIX_KIND_D2, &d2);
    check_product_zero(&d1, &d2, che_mesh_num_triangles(m));
}

/* Every export of m equals that of ref (the same mesh at level 3). */
static void check_same(const che_mesh *m, const che_mesh *ref) {
    uint32_t a[CAP], b[CAP];
    const kind_fn kinds[] = {half_edges_marked, half_edges_explicit, che_mesh_export_winged_edges,
                             che_mesh_export_strips};
    const uint32_t n_kinds[] = {8, 8, 5, 2};
    for (size_t k = 0; k < 4; k++)
        for (uint32_t w = 0; w < n_kinds[k]; w++) {
            const size_t na = get_kind(kinds[k], m, w, a), nb = get_kind(kinds[k], ref, w, b);
            CHECK(na == nb && memcmp(a, b, na * sizeof *a) == 0);
        }
    const list_fn lists[] = {che_mesh_export_corner_opposites, che_mesh_export_edge_list,
                             che_mesh_export_triangle_edges};
    for (size_t k = 0; k < 3; k++) {
        const size_t na = get_list(lists[k], m, a), nb = get_list(lists[k], ref, b);
        CHECK(na == nb && memcmp(a, b, na * sizeof *a) == 0);
    }
    static matrix x, y;
    for (uint32_t kind = 0; kind <= CHE_MATRIX_KIND_DUAL_ADJACENCY; kind++) {
        get_matrix(q_che_mesh_export_matrix, m, kind, &x);
        get_matrix(q_che_mesh_export_matrix, ref, kind, &y);
        CHECK(x.rows == y.rows && x.nnz == y.nnz);
        CHECK(memcmp(x.offsets, y.offsets, (x.rows + 1) * sizeof *x.offsets) == 0);
        CHECK(memcmp(x.columns, y.columns, x.nnz * sizeof *x.columns) == 0);
        CHECK(memcmp(x.values, y.values, x.nnz * sizeof *x.values) == 0);
    }
}

static void test_every_fixture_at_every_level(void) {
    for (size_t f = 0; f < N_CHE_FIXTURES; f++) {
        const che_fixture *fx = &CHE_FIXTURES[f];
        che_mesh *ref = make(fx->tris, fx->n_tris, fx->n_verts, NULL, 3);
        for (uint32_t level = 0; level <= 3; level++) {
            che_mesh *m = make(fx->tris, fx->n_tris, fx->n_verts, NULL, level);
            check_same(m, ref);
            check_boundary_of_boundary(m);
            che_betti b;
            che_summary s;
            CHECK_OK(che_mesh_betti_numbers(m, &b));
            CHECK_OK(che_mesh_summary(m, &s));
            CHECK((int64_t)b.b0 - (int64_t)b.b1 + (int64_t)b.b2 == s.euler_characteristic);
            che_mesh_free(m);
        }
        che_mesh_free(ref);
    }
}

static void test_errors(void) {
    che_mesh *m = make(STRIP, 2, 4, NULL, 1);
    uint32_t b[CAP];
    size_t n = 0;
    /* Too small: the needed length, and the prefix written. */
    b[1] = 12345;
    CHECK_STATUS(che_mesh_export_edge_list(m, b, 1, &n), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(n == 10 && b[0] == 0 && b[1] == 12345);
    CHECK_DETAIL("needed");
    CHECK_STATUS(che_mesh_export_half_edges(m, NULL, CHE_HALF_EDGE_ARRAY_TWIN, b, 5, &n),
                 TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(n == 6);
    /* An unknown array or kind names its enum. */
    CHECK_STATUS(che_mesh_export_half_edges(m, NULL, 8, b, CAP, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("che_half_edge_array");
    CHECK_STATUS(che_mesh_export_winged_edges(m, 5, b, CAP, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("che_winged_array");
    CHECK_STATUS(che_mesh_export_strips(m, 2, b, CAP, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("che_strip_list");
    size_t no = 0, nn = 0;
    CHECK_STATUS(che_mesh_export_matrix(m, 6, NULL, 0, NULL, 0, NULL, 0, &no, &nn),
                 TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("che_matrix_kind");
    /* NULL handle, buffer with a capacity, out-parameters. */
    CHECK_STATUS(che_mesh_export_corner_opposites(NULL, b, CAP, &n), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_mesh_export_triangle_edges(m, NULL, 4, &n), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_mesh_export_edge_list(m, b, CAP, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("out_len");
    CHECK_STATUS(che_mesh_betti_numbers(m, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_mesh_betti_numbers(NULL, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    /* Matrices: some buffers NULL and not all; each buffer too small. */
    static matrix a;
    CHECK_STATUS(che_mesh_export_matrix(m, CHE_MATRIX_KIND_D2, a.offsets, CAP, NULL, 0, a.values,
                                        CAP, &no, &nn),
                 TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("columns");
    CHECK_STATUS(che_mesh_export_matrix(m, CHE_MATRIX_KIND_D2, a.offsets, 2, a.columns, CAP,
                                        a.values, CAP, &no, &nn),
                 TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(no == 6 && nn == 6);
    CHECK_STATUS(che_mesh_export_matrix(m, CHE_MATRIX_KIND_D2, a.offsets, CAP, a.columns, CAP,
                                        a.values, 3, &no, &nn),
                 TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK_DETAIL("values");
    CHECK_STATUS(che_mesh_export_matrix(m, CHE_MATRIX_KIND_D2, a.offsets, CAP, a.columns, CAP,
                                        a.values, CAP, NULL, &nn),
                 TOPOMESH_STATUS_NULL_ARGUMENT);
    che_mesh_free(m);
}

int main(void) {
    test_strip_exact();
    test_every_fixture_at_every_level();
    test_errors();
    return finish("test_che_export");
}
