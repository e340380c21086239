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

/* The expected answers on the small meshes, one section a mesh. */
#define ANSWERS TOPOMESH_TEST_DATA "/che_relations.txt"
#define N_RELATIONS 10

static void test_tetrahedron(void) {
    che_mesh *m = make(TETRA, 4, 4, TETRA_POS, 2);
    check_answer_file(ANSWERS, "tetrahedron", m, QUERIES, N_QUERIES);
    uint32_t x = 0;
    CHECK_OK(che_vertex_half_edge(m, 3, &x));
    CHECK(x != TOPOMESH_NONE);
    che_mesh_free(m);
}

static void test_strip(void) {
    che_mesh *m = make(STRIP, 2, 4, STRIP_POS, 3);
    check_answer_file(ANSWERS, "strip", m, QUERIES, N_QUERIES);
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
