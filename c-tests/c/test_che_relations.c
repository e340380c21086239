/* The relations, one element at a time: answers on small meshes, buffer rules, errors,
   and the same answers at every level. */
#include "check.h"

#include <stdint.h>

IDS_QUERY(che_mesh, che_vertex_vertices)
IDS_QUERY(che_mesh, che_vertex_edges)
IDS_QUERY(che_mesh, che_vertex_triangles)
IDS_QUERY(che_mesh, che_edge_vertices)
IDS_QUERY(che_mesh, che_edge_edges)
IDS_QUERY(che_mesh, che_edge_triangles)
IDS_QUERY(che_mesh, che_triangle_vertices)
IDS_QUERY(che_mesh, che_triangle_edges)
IDS_QUERY(che_mesh, che_triangle_triangles)
IDS_QUERY(che_mesh, che_boundary_curve_vertices)
VALUE_QUERY(che_mesh, che_half_edge_opposite)
VALUE_QUERY(che_mesh, che_half_edge_edge)
VALUE_QUERY(che_mesh, che_half_edge_curve)
VALUE_QUERY(che_mesh, che_vertex_half_edge)
VALUE_QUERY(che_mesh, che_edge_half_edge)
FLAG_QUERY(che_mesh, che_vertex_is_boundary)
FLAG_QUERY(che_mesh, che_edge_is_boundary)

/* The elements a query's ids run over. */
enum { VERTEX, EDGE, TRIANGLE, CURVE, HALF_EDGE };
static const char *const KIND_NAMES[] = {"vertex", "edge", "triangle", "curve", "half-edge"};

static size_t count_of(const void *mesh, int kind) {
    const che_mesh *m = mesh;
    switch (kind) {
    case VERTEX: return che_mesh_num_vertices(m);
    case EDGE: return che_mesh_num_edges(m);
    case TRIANGLE: return che_mesh_num_triangles(m);
    case CURVE: return che_mesh_num_boundary_curves(m);
    default: return che_mesh_num_half_edges(m);
    }
}

/* The relations, then the single-value helpers. */
static const any_query QUERIES[] = {
    {"che_vertex_vertices", q_che_vertex_vertices, VERTEX},
    {"che_vertex_edges", q_che_vertex_edges, VERTEX},
    {"che_vertex_triangles", q_che_vertex_triangles, VERTEX},
    {"che_edge_vertices", q_che_edge_vertices, EDGE},
    {"che_edge_edges", q_che_edge_edges, EDGE},
    {"che_edge_triangles", q_che_edge_triangles, EDGE},
    {"che_triangle_vertices", q_che_triangle_vertices, TRIANGLE},
    {"che_triangle_edges", q_che_triangle_edges, TRIANGLE},
    {"che_triangle_triangles", q_che_triangle_triangles, TRIANGLE},
    {"che_boundary_curve_vertices", q_che_boundary_curve_vertices, CURVE},
    {"che_half_edge_opposite", q_che_half_edge_opposite, HALF_EDGE},
    {"che_half_edge_edge", q_che_half_edge_edge, HALF_EDGE},
    {"che_half_edge_curve", q_che_half_edge_curve, HALF_EDGE},
    {"che_vertex_half_edge", q_che_vertex_half_edge, VERTEX},
    {"che_edge_half_edge", q_che_edge_half_edge, EDGE},
    {"che_vertex_is_boundary", q_che_vertex_is_boundary, VERTEX},
    {"che_edge_is_boundary", q_che_edge_is_boundary, EDGE},
};
#define N_QUERIES (sizeof QUERIES / sizeof QUERIES[0])
#define N_RELATIONS 10

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
        const che_mesh *mm = QUERIES[r].kind == CURVE ? strip : m;
        check_buffer_rules(QUERIES[r].fn, mm, count_of(mm, QUERIES[r].kind),
                           KIND_NAMES[QUERIES[r].kind]);
    }

    /* The single-value helpers. */
    for (size_t q = N_RELATIONS; q < N_QUERIES; q++)
        check_value_errors(QUERIES[q].fn, m, count_of(m, QUERIES[q].kind),
                           KIND_NAMES[QUERIES[q].kind]);
    che_mesh_free(m);
    che_mesh_free(strip);
}

/* Every relation and helper gives the same answer at levels 0, 1, 2 as at level 3. */
static void same_at_every_level(const char *name, const uint32_t *tris, size_t nt, size_t nv) {
    che_mesh *ref = make(tris, nt, nv, NULL, 3);
    for (uint32_t level = 0; level < 3; level++) {
        che_mesh *m = make(tris, nt, nv, NULL, level);
        for (int kind = VERTEX; kind <= HALF_EDGE; kind++)
            CHECK(count_of(m, kind) == count_of(ref, kind));
        same_answers(name, level, QUERIES, N_QUERIES, count_of, ref, m);
        /* Raising this mesh to level 3 gives the reference's views. */
        CHECK_OK(che_mesh_build_level(m, 3));
        size_t la = 0, lb = 0;
        const uint32_t *a = che_mesh_opposites(ref, &la), *b = che_mesh_opposites(m, &lb);
        CHECK(same_view(a, la, b, lb));
        a = che_mesh_vertex_half_edges(ref, &la);
        b = che_mesh_vertex_half_edges(m, &lb);
        CHECK(same_view(a, la, b, lb));
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
