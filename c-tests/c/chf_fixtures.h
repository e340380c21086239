/* Tetrahedral fixtures shared by the CHF C tests (with check.h). */
#ifndef TOPOMESH_CHF_FIXTURES_H
#define TOPOMESH_CHF_FIXTURES_H

#include "check.h"

/* One positive tetrahedron. */
static const uint32_t TET[] UNUSED_ = {0, 1, 2, 3};
static const double TET_POS[] UNUSED_ = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};

/* Two positive tetrahedra sharing the face (1, 2, 3): V=5 E=9 F=7 T=2, chi = 1. */
static const uint32_t PAIR[] UNUSED_ = {0, 1, 2, 3, 4, 1, 3, 2};
static const double PAIR_POS[] UNUSED_ = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};

/* Two tetrahedra sharing only vertex 0: a non-manifold vertex, split into 0 and 7. */
static const uint32_t SPLIT[] UNUSED_ = {0, 1, 2, 3, 0, 4, 6, 5};
static const double SPLIT_POS[] UNUSED_ = {0, 0, 0, 1, 0,  0, 0, 1,  0, 0, 0, 1,
                                           -1, 0, 0, 0, -1, 0, 0, 0, -1};

/* The unit cube (vertex x + 2y + 4z) in 5 positive tetrahedra: 4 corners and the middle
   one (1, 2, 4, 7). V=8 E=18 F=16 T=5, chi = 1; its boundary is a sphere of 12 triangles. */
static const uint32_t CUBE[] UNUSED_ = {0, 1, 2, 4, 3, 2, 1, 7, 5, 1, 4, 7,
                                        6, 4, 2, 7, 1, 2, 4, 7};
static const double CUBE_POS[] UNUSED_ = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                                          0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};

/* The single tetrahedron split into 4 around an interior vertex 4: its boundary has 4
   triangles, vertex 4 is off the boundary, and the edges (4, i) have closed fans. */
static const uint32_t STAR[] UNUSED_ = {4, 1, 2, 3, 0, 4, 2, 3, 0, 1, 4, 3, 0, 1, 2, 4};
static const double STAR_POS[] UNUSED_ = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.2, 0.2, 0.2};

/* Three tetrahedra on the face (0, 1, 2): a non-manifold face. */
static const uint32_t BOOK[] UNUSED_ = {0, 1, 2, 3, 0, 1, 2, 4, 0, 1, 2, 5};

/* A degenerate tetrahedron (1 repeated) between the two of PAIR; vertex 5 is isolated. */
static const uint32_t TDEGEN[] UNUSED_ = {0, 1, 2, 3, 0, 1, 1, 2, 4, 1, 3, 2};

#define NTET(a) (sizeof(a) / sizeof((a)[0]) / 4)

static inline chf_mesh *make_chf(const uint32_t *tets, size_t n_tets, size_t n_verts,
                                 const double *pos, uint32_t level) {
    chf_mesh *m = NULL;
    const topomesh_status s = chf_mesh_from_tetrahedra(tets, n_tets, n_verts, pos, level, &m);
    fixture_built(s, m);
    return m;
}

/* The 16 relations as queries of check.h. */
IDS_QUERY(chf_mesh, chf_vertex_vertices)
IDS_QUERY(chf_mesh, chf_vertex_edges)
IDS_QUERY(chf_mesh, chf_vertex_faces)
IDS_QUERY(chf_mesh, chf_vertex_tetrahedra)
IDS_QUERY(chf_mesh, chf_edge_vertices)
IDS_QUERY(chf_mesh, chf_edge_edges)
IDS_QUERY(chf_mesh, chf_edge_faces)
IDS_QUERY(chf_mesh, chf_edge_tetrahedra)
IDS_QUERY(chf_mesh, chf_face_vertices)
IDS_QUERY(chf_mesh, chf_face_edges)
IDS_QUERY(chf_mesh, chf_face_faces)
IDS_QUERY(chf_mesh, chf_face_tetrahedra)
IDS_QUERY(chf_mesh, chf_tetrahedron_vertices)
IDS_QUERY(chf_mesh, chf_tetrahedron_edges)
IDS_QUERY(chf_mesh, chf_tetrahedron_faces)
IDS_QUERY(chf_mesh, chf_tetrahedron_tetrahedra)

/* The elements a query's ids run over. */
enum { VERTEX, EDGE, FACE, TETRAHEDRON, HALF_FACE, BOUNDARY_TRIANGLE, BOUNDARY_VERTEX };
static const char *const KIND_NAMES[] UNUSED_ = {
    "vertex", "edge", "face", "tetrahedron", "half-face", "boundary triangle", "boundary vertex"};

static inline size_t count_of(const void *mesh, int kind) {
    const chf_mesh *m = mesh;
    switch (kind) {
    case VERTEX: return chf_mesh_num_vertices(m);
    case EDGE: return chf_mesh_num_edges(m);
    case FACE: return chf_mesh_num_faces(m);
    case TETRAHEDRON: return chf_mesh_num_tetrahedra(m);
    case HALF_FACE: return chf_mesh_num_half_faces(m);
    case BOUNDARY_TRIANGLE: return chf_mesh_num_boundary_triangles(m);
    default: return chf_mesh_num_boundary_vertices(m);
    }
}

#endif
