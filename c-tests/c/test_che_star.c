/* The inline star step of topomesh_inline.h (che_star_next, inline from level 2) against
   the library's step (che_star_advance) and the per-vertex relations (che_vertex_vertices,
   che_vertex_edges, che_vertex_triangles), for every vertex of every surface fixture and
   of generated grids and fans, at every level 0-3: any difference fails. */
#include "check.h"

typedef topomesh_status (*vertex_relation)(const che_mesh *, uint32_t, uint32_t *, size_t,
                                           size_t *);

/* The whole answer of a vertex relation (malloc'ed; *n its length). */
static uint32_t *answer(vertex_relation f, const che_mesh *m, uint32_t v, size_t *n) {
    *n = 0;
    CHECK_OK(f(m, v, NULL, 0, n));
    uint32_t *out = malloc((*n + 1) * sizeof *out);
    if (!out) exit(2);
    CHECK_OK(f(m, v, out, *n + 1, n));
    return out;
}

static int same_step(const che_star_step *a, const che_star_step *b) {
    return a->half_edge == b->half_edge && a->vertex == b->vertex && a->edge == b->edge &&
           a->triangle == b->triangle;
}

/* Walks the star of v with both steps side by side and checks them against the relations. */
static void walk_vertex(const che_mesh *m, uint32_t v) {
    size_t nvv = 0, nve = 0, nvt = 0;
    uint32_t *vv = answer(che_vertex_vertices, m, v, &nvv);
    uint32_t *ve = answer(che_vertex_edges, m, v, &nve);
    uint32_t *vt = answer(che_vertex_triangles, m, v, &nvt);
    CHECK(nvv == nve);
    che_star_iter inl, lib;
    che_star_step a, b;
    CHECK_OK(che_star_begin(m, v, &inl));
    CHECK_OK(che_star_begin(m, v, &lib));
    size_t i = 0, t = 0;
    for (;;) {
        const bool more_a = che_star_next(&inl, &a), more_b = che_star_advance(&lib, &b);
        CHECK(more_a == more_b);
        if (!more_a || !more_b) break;
        CHECK(same_step(&a, &b));
        CHECK(i < nvv && a.vertex == vv[i] && a.edge == ve[i]);
        if (a.triangle != TOPOMESH_NONE) {
            CHECK(t < nvt && a.triangle == vt[t]);
            t++;
        }
        i++;
    }
    CHECK(i == nvv && t == nvt);
    /* Exhausted stays exhausted, in both. */
    CHECK(!che_star_next(&inl, &a) && !che_star_advance(&lib, &b));
    free(vv);
    free(ve);
    free(vt);
}

/* Every vertex of the mesh built from tris at every level. */
static void walk_every_level(const char *name, const uint32_t *tris, size_t nt, size_t nv) {
    for (uint32_t level = 0; level <= 3; level++) {
        const int before = check_failures;
        che_mesh *m = make(tris, nt, nv, NULL, level);
        for (uint32_t v = 0; v < che_mesh_num_vertices(m); v++) walk_vertex(m, v);
        che_mesh_free(m);
        if (check_failures != before)
            fprintf(stderr, "  (fixture %s built at level %u)\n", name, (unsigned)level);
    }
}

int main(void) {
    for (size_t f = 0; f < N_CHE_FIXTURES; f++)
        walk_every_level(CHE_FIXTURES[f].name, CHE_FIXTURES[f].tris, CHE_FIXTURES[f].n_tris,
                         CHE_FIXTURES[f].n_verts);

    /* Grids: several words of the edge-id directory, with and without a hole. */
    enum { G = 8 };
    static uint32_t grid[6 * G * G];
    size_t nt = grid_triangles(G, G, grid);
    walk_every_level("8 x 8 grid", grid, nt, (G + 1) * (G + 1));
    nt = grid_triangles(G, 3, grid);
    walk_every_level("8 x 8 grid with a hole", grid, nt, (G + 1) * (G + 1));

    /* High degrees around vertex 0: an open fan and a closed double cone of k triangles. */
    static uint32_t fan[3 * 2 * 70];
    for (uint32_t k = 31; k <= 70; k += 39) {
        for (uint32_t i = 0; i < k; i++) {
            const uint32_t t[3] = {0, 1 + i, 2 + i};
            memcpy(fan + 3 * i, t, sizeof t);
        }
        walk_every_level("open fan", fan, k, k + 2);
        for (uint32_t i = 0; i < k; i++) {
            const uint32_t a = 1 + i, b = 1 + (i + 1) % k;
            const uint32_t t[6] = {0, a, b, k + 1, b, a};
            memcpy(fan + 6 * i, t, sizeof t);
        }
        walk_every_level("double cone", fan, 2 * k, k + 2);
    }
    return finish("test_che_star");
}
