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

/* The surface of a tetrahedron at level 2. Half-edges: T0 = 0->2, 2->1, 1->0; T1 = 0->1,
   1->3, 3->0; T2 = 0->3, 3->2, 2->0; T3 = 1->2, 2->3, 3->1. Edges are numbered by their
   smaller half-edge: e0 = h0 {0,2}, e1 = h1 {2,1}, e2 = h2 {1,0}, e3 = h4 {1,3},
   e4 = h5 {3,0}, e5 = h7 {3,2}. */
static const answer_row TETRA_ANSWERS[] = {
    ROW(che_vertex_vertices, 0, 2, 1, 3),
    ROW(che_vertex_edges, 0, 0, 2, 4),
    ROW(che_vertex_triangles, 0, 0, 1, 2),
    ROW(che_vertex_vertices, 3, 0, 1, 2),
    ROW(che_edge_vertices, 0, 0, 2),
    ROW(che_edge_vertices, 2, 1, 0),
    ROW(che_edge_triangles, 0, 0, 2),
    ROW(che_edge_edges, 0, 1, 2, 4, 5),
    ROW(che_triangle_vertices, 0, 0, 2, 1),
    ROW(che_triangle_edges, 0, 0, 1, 2),
    ROW(che_triangle_triangles, 0, 2, 3, 1),
    ROW(che_triangle_triangles, 3, 0, 2, 1),
    ROW(che_half_edge_opposite, 0, 8),
    ROW(che_half_edge_edge, 8, 0),
    ROW(che_half_edge_edge, 11, 3),
    ROW(che_edge_half_edge, 5, 7),
    ROW(che_half_edge_curve, 0, N_),
    ROW(che_vertex_is_boundary, 0, 0),
    ROW(che_edge_is_boundary, 0, 0),
    ROW_FAILS(che_boundary_curve_vertices, 0, TOPOMESH_STATUS_OUT_OF_RANGE, "curve 0"),
};

/* The strip at level 3: T0 = 0->1, 1->2, 2->0; T1 = 1->3, 3->2, 2->1; edges e0..e4 =
   h0..h4. */
static const answer_row STRIP_ANSWERS[] = {
    ROW(che_vertex_vertices, 1, 3, 2, 0),
    ROW(che_vertex_edges, 1, 3, 1, 0),
    ROW(che_vertex_triangles, 1, 1, 0),
    ROW(che_vertex_vertices, 0, 1, 2),
    ROW(che_vertex_triangles, 0, 0),
    ROW(che_vertex_vertices, 2, 0, 1, 3),
    ROW(che_vertex_triangles, 2, 0, 1),
    ROW(che_vertex_vertices, 3, 2, 1),
    ROW(che_edge_vertices, 1, 1, 2),
    ROW(che_edge_triangles, 1, 0, 1),
    ROW(che_edge_triangles, 3, 1),
    ROW(che_edge_edges, 1, 2, 0, 3, 4),
    ROW(che_edge_edges, 0, 1, 2),
    ROW(che_triangle_triangles, 0, N_, 1, N_),
    ROW(che_triangle_triangles, 1, N_, N_, 0),
    ROW(che_triangle_edges, 1, 3, 4, 1),
    ROW(che_boundary_curve_vertices, 0, 0, 1, 3, 2),
    ROW_FAILS(che_boundary_curve_vertices, 1, TOPOMESH_STATUS_OUT_OF_RANGE, NULL),
    ROW(che_vertex_half_edge, 1, 3),
    ROW(che_half_edge_opposite, 0, N_),
    ROW(che_half_edge_opposite, 5, 1),
    ROW(che_half_edge_curve, 4, 0),
    ROW(che_half_edge_curve, 1, N_),
    ROW(che_vertex_is_boundary, 0, 1),
    ROW(che_vertex_is_boundary, 1, 1),
    ROW(che_vertex_is_boundary, 2, 1),
    ROW(che_vertex_is_boundary, 3, 1),
    ROW(che_edge_is_boundary, 1, 0),
    ROW(che_edge_is_boundary, 4, 1),
};

static void test_tetrahedron(void) {
    che_mesh *m = make(TETRA, 4, 4, TETRA_POS, 2);
    check_answers("tetrahedron", m, TETRA_ANSWERS, N_ROWS(TETRA_ANSWERS));
    uint32_t x = 0;
    CHECK_OK(che_vertex_half_edge(m, 3, &x));
    CHECK(x != TOPOMESH_NONE);
    che_mesh_free(m);
}

static void test_strip(void) {
    che_mesh *m = make(STRIP, 2, 4, STRIP_POS, 3);
    check_answers("strip", m, STRIP_ANSWERS, N_ROWS(STRIP_ANSWERS));
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

VIEW_QUERY(che_mesh, che_mesh_opposites)
VIEW_QUERY(che_mesh, che_mesh_vertex_half_edges)
static const any_view_fn LEVEL_3_VIEWS[] = {q_che_mesh_opposites, q_che_mesh_vertex_half_edges};
static topomesh_status build_level(void *m, uint32_t level) {
    return che_mesh_build_level(m, level);
}
static void free_mesh(void *m) { che_mesh_free(m); }
static const level_suite SUITE = {QUERIES, N_QUERIES, count_of, HALF_EDGE + 1, LEVEL_3_VIEWS,
                                  2, build_level, free_mesh};

/* Every relation and helper gives the same answer at levels 0, 1, 2 as at level 3. */
static void same_at_every_level(const char *name, const uint32_t *tris, size_t nt, size_t nv) {
    che_mesh *ref = make(tris, nt, nv, NULL, 3);
    void *lower[3];
    for (uint32_t level = 0; level < 3; level++) lower[level] = make(tris, nt, nv, NULL, level);
    same_as_level_3(name, &SUITE, ref, lower);
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
