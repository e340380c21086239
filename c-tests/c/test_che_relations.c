/* The relations, one element at a time: answers on small meshes, buffer rules, errors,
   and the same answers at every level. */
#include "check.h"

#include <stdint.h>

typedef topomesh_status (*relation_fn)(const che_mesh *, uint32_t, uint32_t *, size_t, size_t *);

static const struct {
    const char *name;
    relation_fn fn;
    int kind; /* 0 vertex, 1 edge, 2 triangle, 3 curve */
} RELATIONS[] = {
    {"che_vertex_vertices", che_vertex_vertices, 0},
    {"che_vertex_edges", che_vertex_edges, 0},
    {"che_vertex_triangles", che_vertex_triangles, 0},
    {"che_edge_vertices", che_edge_vertices, 1},
    {"che_edge_edges", che_edge_edges, 1},
    {"che_edge_triangles", che_edge_triangles, 1},
    {"che_triangle_vertices", che_triangle_vertices, 2},
    {"che_triangle_edges", che_triangle_edges, 2},
    {"che_triangle_triangles", che_triangle_triangles, 2},
    {"che_boundary_curve_vertices", che_boundary_curve_vertices, 3},
};
#define N_RELATIONS (sizeof RELATIONS / sizeof RELATIONS[0])

static size_t count_of(const che_mesh *m, int kind) {
    switch (kind) {
    case 0: return che_mesh_num_vertices(m);
    case 1: return che_mesh_num_edges(m);
    case 2: return che_mesh_num_triangles(m);
    default: return che_mesh_num_boundary_curves(m);
    }
}

static void test_tetrahedron(void) {
    che_mesh *m = make(TETRA, 4, 4, TETRA_POS, 2);
    uint32_t b[8];
    size_t n = 0;
    /* Half-edges: T0 = 0->2, 2->1, 1->0; T1 = 0->1, 1->3, 3->0; T2 = 0->3, 3->2, 2->0;
       T3 = 1->2, 2->3, 3->1. Edges are numbered by their smaller half-edge:
       e0 = h0 {0,2}, e1 = h1 {2,1}, e2 = h2 {1,0}, e3 = h4 {1,3}, e4 = h5 {3,0}, e5 = h7 {3,2}. */
    CHECK_OK(che_vertex_vertices(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 2, 1, 3);
    CHECK_OK(che_vertex_edges(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 0, 2, 4);
    CHECK_OK(che_vertex_triangles(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 0, 1, 2);
    CHECK_OK(che_vertex_vertices(m, 3, b, 8, &n));
    CHECK_IDS(b, n, 0, 1, 2);
    CHECK_OK(che_edge_vertices(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 0, 2);
    CHECK_OK(che_edge_vertices(m, 2, b, 8, &n));
    CHECK_IDS(b, n, 1, 0);
    CHECK_OK(che_edge_triangles(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 0, 2);
    CHECK_OK(che_edge_edges(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 1, 2, 4, 5);
    CHECK_OK(che_triangle_vertices(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 0, 2, 1);
    CHECK_OK(che_triangle_edges(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 0, 1, 2);
    CHECK_OK(che_triangle_triangles(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 2, 3, 1);
    CHECK_OK(che_triangle_triangles(m, 3, b, 8, &n));
    CHECK_IDS(b, n, 0, 2, 1);

    uint32_t x = 0;
    bool yes = true;
    CHECK_OK(che_half_edge_opposite(m, 0, &x));
    CHECK(x == 8);
    CHECK_OK(che_half_edge_edge(m, 8, &x));
    CHECK(x == 0);
    CHECK_OK(che_half_edge_edge(m, 11, &x));
    CHECK(x == 3);
    CHECK_OK(che_edge_half_edge(m, 5, &x));
    CHECK(x == 7);
    CHECK_OK(che_vertex_half_edge(m, 3, &x));
    CHECK(x != TOPOMESH_NONE);
    CHECK_OK(che_half_edge_curve(m, 0, &x));
    CHECK(x == TOPOMESH_NONE);
    CHECK_OK(che_vertex_is_boundary(m, 0, &yes));
    CHECK(!yes);
    yes = true;
    CHECK_OK(che_edge_is_boundary(m, 0, &yes));
    CHECK(!yes);
    CHECK_STATUS(che_boundary_curve_vertices(m, 0, b, 8, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("curve 0");
    che_mesh_free(m);
}

static void test_strip(void) {
    che_mesh *m = make(STRIP, 2, 4, STRIP_POS, 3);
    uint32_t b[8];
    size_t n = 0;
    /* T0 = 0->1, 1->2, 2->0; T1 = 1->3, 3->2, 2->1; edges e0..e4 = h0..h4. */
    CHECK_OK(che_vertex_vertices(m, 1, b, 8, &n));
    CHECK_IDS(b, n, 3, 2, 0);
    CHECK_OK(che_vertex_edges(m, 1, b, 8, &n));
    CHECK_IDS(b, n, 3, 1, 0);
    CHECK_OK(che_vertex_triangles(m, 1, b, 8, &n));
    CHECK_IDS(b, n, 1, 0);
    CHECK_OK(che_vertex_vertices(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 1, 2);
    CHECK_OK(che_vertex_triangles(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 0);
    CHECK_OK(che_vertex_vertices(m, 2, b, 8, &n));
    CHECK_IDS(b, n, 0, 1, 3);
    CHECK_OK(che_vertex_triangles(m, 2, b, 8, &n));
    CHECK_IDS(b, n, 0, 1);
    CHECK_OK(che_vertex_vertices(m, 3, b, 8, &n));
    CHECK_IDS(b, n, 2, 1);
    CHECK_OK(che_edge_vertices(m, 1, b, 8, &n));
    CHECK_IDS(b, n, 1, 2);
    CHECK_OK(che_edge_triangles(m, 1, b, 8, &n));
    CHECK_IDS(b, n, 0, 1);
    CHECK_OK(che_edge_triangles(m, 3, b, 8, &n));
    CHECK_IDS(b, n, 1);
    CHECK_OK(che_edge_edges(m, 1, b, 8, &n));
    CHECK_IDS(b, n, 2, 0, 3, 4);
    CHECK_OK(che_edge_edges(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 1, 2);
    CHECK_OK(che_triangle_triangles(m, 0, b, 8, &n));
    CHECK_IDS(b, n, N_, 1, N_);
    CHECK_OK(che_triangle_triangles(m, 1, b, 8, &n));
    CHECK_IDS(b, n, N_, N_, 0);
    CHECK_OK(che_triangle_edges(m, 1, b, 8, &n));
    CHECK_IDS(b, n, 3, 4, 1);
    CHECK_OK(che_boundary_curve_vertices(m, 0, b, 8, &n));
    CHECK_IDS(b, n, 0, 1, 3, 2);
    CHECK_STATUS(che_boundary_curve_vertices(m, 1, b, 8, &n), TOPOMESH_STATUS_OUT_OF_RANGE);

    uint32_t x = 0;
    bool yes = false;
    CHECK_OK(che_vertex_half_edge(m, 1, &x));
    CHECK(x == 3);
    CHECK_OK(che_half_edge_opposite(m, 0, &x));
    CHECK(x == TOPOMESH_NONE);
    CHECK_OK(che_half_edge_opposite(m, 5, &x));
    CHECK(x == 1);
    CHECK_OK(che_half_edge_curve(m, 4, &x));
    CHECK(x == 0);
    CHECK_OK(che_half_edge_curve(m, 1, &x));
    CHECK(x == TOPOMESH_NONE);
    for (uint32_t v = 0; v < 4; v++) {
        CHECK_OK(che_vertex_is_boundary(m, v, &yes));
        CHECK(yes);
    }
    CHECK_OK(che_edge_is_boundary(m, 1, &yes));
    CHECK(!yes);
    CHECK_OK(che_edge_is_boundary(m, 4, &yes));
    CHECK(yes);
    che_mesh_free(m);
}

/* Buffer rules and errors, for every relation. */
static void test_buffer_rules(void) {
    che_mesh *m = make(TETRA, 4, 4, NULL, 3);
    che_mesh *strip = make(STRIP, 2, 4, NULL, 3);
    for (size_t r = 0; r < N_RELATIONS; r++) {
        const che_mesh *mm = RELATIONS[r].kind == 3 ? strip : m;
        relation_fn f = RELATIONS[r].fn;
        uint32_t full[16], b[16];
        size_t n = 0, need = 0;
        CHECK_OK(f(mm, 0, full, 16, &n));
        CHECK(n >= 2);
        /* Size query. */
        CHECK_OK(f(mm, 0, NULL, 0, &need));
        CHECK(need == n);
        /* Too small: the needed length, and the prefix written. */
        for (size_t i = 0; i < 16; i++) b[i] = 12345;
        need = 0;
        CHECK_STATUS(f(mm, 0, b, 1, &need), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
        CHECK(need == n && b[0] == full[0] && b[1] == 12345);
        CHECK_DETAIL("needed");
        /* Exactly enough. */
        CHECK_OK(f(mm, 0, b, n, &need));
        CHECK(need == n && memcmp(b, full, n * sizeof *b) == 0);
        /* A capacity larger than any buffer (SIZE_MAX as "enough"). */
        CHECK_OK(f(mm, 0, b, SIZE_MAX, &need));
        CHECK(need == n && memcmp(b, full, n * sizeof *b) == 0);
        /* NULL handle, NULL buffer with a capacity, NULL out_len. */
        CHECK_STATUS(f(NULL, 0, b, 16, &n), TOPOMESH_STATUS_NULL_ARGUMENT);
        CHECK_STATUS(f(mm, 0, NULL, 4, &n), TOPOMESH_STATUS_NULL_ARGUMENT);
        CHECK_DETAIL("buf");
        CHECK_STATUS(f(mm, 0, b, 16, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
        CHECK_DETAIL("out_len");
        /* Out of range: the id in the detail, nothing written. */
        uint32_t bad = (uint32_t)count_of(mm, RELATIONS[r].kind);
        n = 777;
        CHECK_STATUS(f(mm, bad, b, 16, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
        CHECK(n == 777);
        char id[32];
        snprintf(id, sizeof id, "%u", (unsigned)bad);
        CHECK_DETAIL(id);
        CHECK_STATUS(f(mm, TOPOMESH_NONE, b, 16, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
    }

    /* The single-value helpers. */
    uint32_t x;
    bool yes;
    CHECK_STATUS(che_half_edge_opposite(NULL, 0, &x), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_half_edge_opposite(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_half_edge_opposite(m, 12, &x), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("half-edge 12");
    CHECK_STATUS(che_half_edge_edge(m, 12, &x), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(che_half_edge_edge(NULL, 0, &x), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_half_edge_curve(m, 12, &x), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(che_half_edge_curve(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_vertex_half_edge(m, 4, &x), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("vertex 4");
    CHECK_STATUS(che_vertex_half_edge(NULL, 0, &x), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_edge_half_edge(m, 6, &x), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("edge 6");
    CHECK_STATUS(che_edge_half_edge(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_vertex_is_boundary(m, 4, &yes), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(che_vertex_is_boundary(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_edge_is_boundary(m, 6, &yes), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(che_edge_is_boundary(NULL, 0, &yes), TOPOMESH_STATUS_NULL_ARGUMENT);
    che_mesh_free(m);
    che_mesh_free(strip);
}

/* Every relation and helper gives the same answer at levels 0, 1, 2 as at level 3. */
static void same_at_every_level(const char *name, const uint32_t *tris, size_t nt, size_t nv) {
    che_mesh *ref = make(tris, nt, nv, NULL, 3);
    for (uint32_t level = 0; level < 3; level++) {
        che_mesh *m = make(tris, nt, nv, NULL, level);
        CHECK(che_mesh_num_vertices(m) == che_mesh_num_vertices(ref));
        CHECK(che_mesh_num_edges(m) == che_mesh_num_edges(ref));
        CHECK(che_mesh_num_boundary_curves(m) == che_mesh_num_boundary_curves(ref));
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
        for (uint32_t h = 0; h < che_mesh_num_half_edges(ref); h++) {
            uint32_t a = 0, b = 1;
            CHECK_OK(che_half_edge_opposite(ref, h, &a));
            CHECK_OK(che_half_edge_opposite(m, h, &b));
            CHECK(a == b);
            CHECK_OK(che_half_edge_edge(ref, h, &a));
            CHECK_OK(che_half_edge_edge(m, h, &b));
            CHECK(a == b);
            CHECK_OK(che_half_edge_curve(ref, h, &a));
            CHECK_OK(che_half_edge_curve(m, h, &b));
            CHECK(a == b);
        }
        for (uint32_t v = 0; v < che_mesh_num_vertices(ref); v++) {
            uint32_t a = 0, b = 1;
            bool x = false, y = true;
            CHECK_OK(che_vertex_half_edge(ref, v, &a));
            CHECK_OK(che_vertex_half_edge(m, v, &b));
            CHECK(a == b);
            CHECK_OK(che_vertex_is_boundary(ref, v, &x));
            CHECK_OK(che_vertex_is_boundary(m, v, &y));
            CHECK(x == y);
        }
        for (uint32_t e = 0; e < che_mesh_num_edges(ref); e++) {
            uint32_t a = 0, b = 1;
            bool x = false, y = true;
            CHECK_OK(che_edge_half_edge(ref, e, &a));
            CHECK_OK(che_edge_half_edge(m, e, &b));
            CHECK(a == b);
            CHECK_OK(che_edge_is_boundary(ref, e, &x));
            CHECK_OK(che_edge_is_boundary(m, e, &y));
            CHECK(x == y);
        }
        /* Raising this mesh to level 3 gives the reference's views. */
        CHECK_OK(che_mesh_build_level(m, 3));
        size_t la = 0, lb = 0;
        const uint32_t *oa = che_mesh_opposites(ref, &la), *ob = che_mesh_opposites(m, &lb);
        CHECK(oa && ob && la == lb && memcmp(oa, ob, la * sizeof *oa) == 0);
        oa = che_mesh_vertex_half_edges(ref, &la);
        ob = che_mesh_vertex_half_edges(m, &lb);
        CHECK(oa && ob && la == lb && memcmp(oa, ob, la * sizeof *oa) == 0);
        che_mesh_free(m);
    }
    che_mesh_free(ref);
}

int main(void) {
    test_tetrahedron();
    test_strip();
    test_buffer_rules();
    for (size_t f = 0; f < N_CHE_FIXTURES; f++)
        same_at_every_level(CHE_FIXTURES[f].name, CHE_FIXTURES[f].tris, CHE_FIXTURES[f].n_tris,
                            CHE_FIXTURES[f].n_verts);
    return finish("test_che_relations");
}
