/* The CHF exports: half-face arrays, the dual graph, the incidence matrices (d1 d2 == 0,
   d2 d3 == 0), Betti numbers, the same at every level, and the buffer rules. */
#include "chf_fixtures.h"
#include "export_matrix.h"

#define CAP 1024

MATRIX_QUERY(chf_mesh, chf_mesh_export_matrix)

static size_t get_ids(const chf_mesh *m, int which, uint32_t *out) {
    size_t need = 0, n = 0;
    if (which < 0) {
        CHECK_OK(chf_mesh_export_dual_graph(m, NULL, 0, &need));
        CHECK_OK(chf_mesh_export_dual_graph(m, out, CAP, &n));
    } else {
        CHECK_OK(chf_mesh_export_half_faces(m, (uint32_t)which, NULL, 0, &need));
        CHECK_OK(chf_mesh_export_half_faces(m, (uint32_t)which, out, CAP, &n));
    }
    CHECK(n == need && n <= CAP);
    return n;
}

static void test_pair_exact(void) {
    chf_mesh *m = make_chf(PAIR, 2, 5, NULL, 2);
    uint32_t b[CAP];
    size_t n = get_ids(m, CHF_HALF_FACE_ARRAY_TWIN, b);
    CHECK_IDS(b, n, 4, N_, N_, N_, 0, N_, N_, N_);
    n = get_ids(m, -1, b);
    CHECK_IDS(b, n, 1, N_, N_, N_, 0, N_, N_, N_);
    n = get_ids(m, CHF_HALF_FACE_ARRAY_VERTICES, b);
    CHECK(n == 24);
    n = get_ids(m, CHF_HALF_FACE_ARRAY_FACE, b);
    CHECK(n == 8 && b[0] == b[4]);
    chf_betti betti;
    CHECK_OK(chf_mesh_betti_numbers(m, &betti));
    CHECK(betti.b0 == 1 && betti.b1 == 0 && betti.b2 == 0 && betti.b3 == 0);
    chf_mesh_free(m);
}

static void test_every_level(void) {
    static const struct {
        const uint32_t *tets;
        size_t n_tets, n_verts;
        uint64_t b0;
    } F[] = {{TET, 1, 4, 1}, {PAIR, 2, 5, 1}, {CUBE, 5, 8, 1}, {STAR, 4, 5, 1}, {SPLIT, 2, 7, 2}};
    static matrix d[3], ref[3];
    for (size_t f = 0; f < sizeof F / sizeof F[0]; f++) {
        chf_mesh *top = make_chf(F[f].tets, F[f].n_tets, F[f].n_verts, NULL, 3);
        for (uint32_t k = 0; k < 3; k++) get_matrix(q_chf_mesh_export_matrix, top, k, &ref[k]);
        for (uint32_t level = 0; level <= 3; level++) {
            chf_mesh *m = make_chf(F[f].tets, F[f].n_tets, F[f].n_verts, NULL, level);
            for (uint32_t k = 0; k < 3; k++) {
                get_matrix(q_chf_mesh_export_matrix, m, k, &d[k]);
                CHECK(d[k].nnz == ref[k].nnz && d[k].rows == ref[k].rows);
                CHECK(memcmp(d[k].columns, ref[k].columns, d[k].nnz * sizeof(uint32_t)) == 0);
                CHECK(memcmp(d[k].values, ref[k].values, d[k].nnz * sizeof(double)) == 0);
            }
            check_product_zero(&d[0], &d[1], chf_mesh_num_faces(m));
            check_product_zero(&d[1], &d[2], chf_mesh_num_tetrahedra(m));
            chf_betti b;
            CHECK_OK(chf_mesh_betti_numbers(m, &b));
            CHECK(b.b0 == F[f].b0 && b.b1 == 0 && b.b2 == 0 && b.b3 == 0);
            chf_mesh_free(m);
        }
        chf_mesh_free(top);
    }
}

static void test_errors(void) {
    chf_mesh *m = make_chf(PAIR, 2, 5, NULL, 1);
    uint32_t b[CAP];
    size_t n = 0, no = 0, nn = 0;
    CHECK_STATUS(chf_mesh_export_half_faces(m, 3, b, CAP, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("chf_half_face_array");
    CHECK_STATUS(chf_mesh_export_dual_graph(m, b, 3, &n), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(n == 8);
    CHECK_STATUS(chf_mesh_export_dual_graph(NULL, b, CAP, &n), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_mesh_betti_numbers(m, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_mesh_export_matrix(m, 4, NULL, 0, NULL, 0, NULL, 0, &no, &nn),
                 TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("chf_matrix_kind");
    static matrix a;
    CHECK_STATUS(chf_mesh_export_matrix(m, CHF_MATRIX_KIND_D3, NULL, 0, a.columns, CAP, a.values,
                                        CAP, &no, &nn),
                 TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("offsets");
    CHECK_STATUS(chf_mesh_export_matrix(m, CHF_MATRIX_KIND_D3, a.offsets, CAP, a.columns, 2,
                                        a.values, CAP, &no, &nn),
                 TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(no == 8 && nn == 8);
    CHECK_DETAIL("columns");
    chf_mesh_free(m);
}

int main(void) {
    test_pair_exact();
    test_every_level();
    test_errors();
    return finish("test_chf_export");
}
