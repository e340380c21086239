/* The sparse-matrix exports of CHE and CHF, for their export tests (with check.h). */
#ifndef TOPOMESH_EXPORT_MATRIX_H
#define TOPOMESH_EXPORT_MATRIX_H

#include "check.h"

#define MATRIX_CAP 1024

/* A matrix in CSR form: rows + 1 offsets, nnz columns and values. */
typedef struct matrix {
    uint64_t offsets[MATRIX_CAP];
    uint32_t columns[MATRIX_CAP];
    double values[MATRIX_CAP];
    size_t rows, nnz;
} matrix;

/* che_mesh_export_matrix or chf_mesh_export_matrix, adapted by MATRIX_QUERY to a mesh
   given as const void *. */
typedef topomesh_status (*any_matrix_fn)(const void *m, uint32_t kind, uint64_t *offsets,
                                         size_t offsets_cap, uint32_t *columns,
                                         size_t columns_cap, double *values, size_t values_cap,
                                         size_t *n_offsets, size_t *n_values);
#define MATRIX_QUERY(mesh_t, fn)                                                           \
    static UNUSED_ topomesh_status q_##fn(const void *m, uint32_t k, uint64_t *o, size_t oc, \
                                          uint32_t *c, size_t cc, double *v, size_t vc,    \
                                          size_t *no, size_t *nv) {                        \
        return fn((const mesh_t *)m, k, o, oc, c, cc, v, vc, no, nv);                      \
    }

/* The matrix `kind` of m, into a: the size query and the export agree on the sizes, and
   the offsets run from 0 to nnz. */
static inline void get_matrix(any_matrix_fn f, const void *m, uint32_t kind, matrix *a) {
    size_t no = 0, nn = 0;
    CHECK_OK(f(m, kind, NULL, 0, NULL, 0, NULL, 0, &no, &nn));
    CHECK(no >= 1 && no <= MATRIX_CAP && nn <= MATRIX_CAP);
    size_t no2 = 0, nn2 = 0;
    CHECK_OK(f(m, kind, a->offsets, MATRIX_CAP, a->columns, MATRIX_CAP, a->values, MATRIX_CAP,
               &no2, &nn2));
    CHECK(no == no2 && nn == nn2 && a->offsets[0] == 0 && a->offsets[no - 1] == nn);
    a->rows = no - 1;
    a->nnz = nn;
}

/* a * b == 0 (a boundary of a boundary), densely (b has `cols` columns). */
static inline void check_product_zero(const matrix *a, const matrix *b, size_t cols) {
    for (size_t r = 0; r < a->rows; r++)
        for (size_t c = 0; c < cols; c++) {
            double sum = 0;
            for (uint64_t i = a->offsets[r]; i < a->offsets[r + 1]; i++) {
                const uint32_t k = a->columns[i];
                for (uint64_t j = b->offsets[k]; j < b->offsets[k + 1]; j++)
                    if (b->columns[j] == c) sum += a->values[i] * b->values[j];
            }
            CHECK(sum == 0);
        }
}

#endif
