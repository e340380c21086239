/* topomesh: hand-written part of the C API, included by the generated topomesh.h.
 *
 * The half-edge arithmetic of CHE as static inline functions, so that C hosts can walk
 * the zero-copy arrays (che_mesh_half_edge_vertices, che_mesh_opposites, ...) at native
 * speed: triangle t owns half-edges 3t, 3t+1, 3t+2; half-edge h runs from V[h] to
 * V[che_next(h)]; the vertex opposite h in its triangle is V[che_prev(h)].
 *
 * The half-face arithmetic of CHF likewise (chf_mesh_half_face_vertices,
 * chf_mesh_opposites, ...): tetrahedron t owns half-faces 4t .. 4t+3; half-face
 * hf = 4t + i is the face opposite local vertex i, V[hf] is that vertex, and the face's
 * vertices in outward order are V[chf_face_corner(hf, 0)], V[chf_face_corner(hf, 1)],
 * V[chf_face_corner(hf, 2)]; the twin half-face across it is O[hf].
 *
 * Also here, because the inline star step needs their layout before the generated
 * declarations: the star iterator (che_star_iter, che_star_step) and che_star_next, which
 * steps inline from level 2 (che_star_begin leaves V, O and the edge-id directory in the
 * iterator) and calls the library's che_star_advance otherwise.
 */
#ifndef TOPOMESH_INLINE_H
#define TOPOMESH_INLINE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* No element: boundary, none, invalid. */
#ifndef TOPOMESH_NONE
#define TOPOMESH_NONE UINT32_MAX
#endif

/* The triangle of half-edge h. */
static inline uint32_t che_tri(uint32_t h) { return h / 3u; }

/* The next half-edge in the same triangle (counter-clockwise). */
static inline uint32_t che_next(uint32_t h) { return h % 3u == 2u ? h - 2u : h + 1u; }

/* The previous half-edge in the same triangle. */
static inline uint32_t che_prev(uint32_t h) { return h % 3u == 0u ? h + 2u : h - 1u; }

/* The first half-edge of triangle t (its corner 0). */
static inline uint32_t che_first(uint32_t t) { return 3u * t; }

/* The tetrahedron of half-face hf. */
static inline uint32_t chf_tet(uint32_t hf) { return hf >> 2; }

/* The local index of half-face hf in its tetrahedron (the local vertex it is opposite). */
static inline uint32_t chf_local(uint32_t hf) { return hf & 3u; }

/* The first half-face of tetrahedron t (the face opposite its vertex 0). */
static inline uint32_t chf_first(uint32_t t) { return 4u * t; }

/* The next half-face of the same tetrahedron (4t+3 -> 4t). */
static inline uint32_t chf_next(uint32_t hf) { return (hf & ~3u) | ((hf + 1u) & 3u); }

/* The half-face (of the same tetrahedron) whose V entry is corner j (0..2) of half-face
   hf in its outward order. Face i lists local vertices {1,2,3}, {0,3,2}, {0,1,3},
   {0,2,1} for i = 0..3, packed two bits each. */
static inline uint32_t chf_face_corner(uint32_t hf, uint32_t j) {
    return (hf & ~3u) | ((0x634B39u >> (2u * (3u * (hf & 3u) + j))) & 3u);
}

/* The number of set bits of x: the instruction when the target has it, else a few
   inline operations (cheaper than the compiler's library call for __builtin_popcount on
   baseline x86-64). */
static inline uint32_t topomesh_popcount32(uint32_t x) {
#if (defined(__GNUC__) || defined(__clang__)) && (defined(__POPCNT__) || !defined(__x86_64__))
    return (uint32_t)__builtin_popcount(x);
#else
    x = x - ((x >> 1) & 0x55555555u);
    x = (x & 0x33333333u) + ((x >> 2) & 0x33333333u);
    x = (x + (x >> 4)) & 0x0F0F0F0Fu;
    return (x * 0x01010101u) >> 24;
#endif
}

/* The edge of half-edge h (< 3 * num_triangles), from O (che_mesh_opposites) and the
   edge-id directory (che_mesh_edge_ranks): the rank of its canonical half-edge (h, or O[h]
   when that is smaller) among the canonical ones. */
static inline uint32_t che_edge_of(const uint32_t *O, const uint64_t *ranks, uint32_t h) {
    const uint32_t g = O[h], c = (g != TOPOMESH_NONE && g < h) ? g : h;
    const uint64_t d = ranks[c >> 5];
    return (uint32_t)(d >> 32) + topomesh_popcount32((uint32_t)d & ((1u << (c & 31u)) - 1u));
}

struct che_mesh;

/* The state of a rotation around a vertex. Its fields are private: set them only with
   che_star_begin. It borrows the mesh: do not free the mesh or change its level while
   iterating. (Mirrors CheStarIter in src/ffi/che_star.rs.) */
typedef struct che_star_iter {
    const struct che_mesh *mesh;
    const uint32_t *v;           /* V, O and the edge-id directory from level 2, else NULL */
    const uint32_t *o;
    const uint64_t *edge_ranks;
    uint32_t start;
    uint32_t cur;
    uint32_t tail;
    uint32_t cur_opposite;       /* O[cur]: the previous step's prev(h) */
} che_star_iter;

/* One step of a rotation around a vertex v, counter-clockwise seen from outside.
   For each triangle around v: half_edge is its outgoing half-edge v -> w, vertex is w,
   edge the edge of v -> w, triangle the triangle of half_edge. On a boundary vertex the
   rotation starts at the outgoing boundary half-edge and ends with one more step for the
   incoming boundary half-edge u -> v: half_edge is that half-edge, vertex is u, edge its
   edge, and triangle is TOPOMESH_NONE. So the steps give exactly che_vertex_vertices and
   che_vertex_edges, and the steps with a triangle give che_vertex_triangles. */
typedef struct che_star_step {
    uint32_t half_edge;
    uint32_t vertex;
    uint32_t edge;
    uint32_t triangle;
} che_star_step;

/* The layout of the two structs above is mirrored by hand from src/ffi (which asserts the
   same numbers): with P = sizeof(void *), che_star_iter is four pointers then four u32,
   4P + 16 bytes (48 on LP64), and che_star_step four u32, 16 bytes. A drift would be
   silent undefined behaviour, so it fails to compile instead. */
#if defined(__cplusplus)
#define TOPOMESH_STATIC_ASSERT(cond, msg) static_assert(cond, msg)
#elif defined(__STDC_VERSION__) && __STDC_VERSION__ >= 201112L
#define TOPOMESH_STATIC_ASSERT(cond, msg) _Static_assert(cond, msg)
#else
#define TOPOMESH_STATIC_ASSERT_CAT2(a, b) a##b
#define TOPOMESH_STATIC_ASSERT_CAT(a, b) TOPOMESH_STATIC_ASSERT_CAT2(a, b)
#define TOPOMESH_STATIC_ASSERT(cond, msg) \
    typedef char TOPOMESH_STATIC_ASSERT_CAT(topomesh_static_assert_, __LINE__)[(cond) ? 1 : -1]
#endif
#define TOPOMESH_P sizeof(void *)
TOPOMESH_STATIC_ASSERT(sizeof(che_star_iter) == 4 * TOPOMESH_P + 16, "che_star_iter size");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_iter, mesh) == 0, "che_star_iter.mesh");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_iter, v) == TOPOMESH_P, "che_star_iter.v");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_iter, o) == 2 * TOPOMESH_P, "che_star_iter.o");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_iter, edge_ranks) == 3 * TOPOMESH_P,
                       "che_star_iter.edge_ranks");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_iter, start) == 4 * TOPOMESH_P, "che_star_iter.start");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_iter, cur) == 4 * TOPOMESH_P + 4, "che_star_iter.cur");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_iter, tail) == 4 * TOPOMESH_P + 8, "che_star_iter.tail");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_iter, cur_opposite) == 4 * TOPOMESH_P + 12,
                       "che_star_iter.cur_opposite");
TOPOMESH_STATIC_ASSERT(sizeof(che_star_step) == 16, "che_star_step size");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_step, half_edge) == 0, "che_star_step.half_edge");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_step, vertex) == 4, "che_star_step.vertex");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_step, edge) == 8, "che_star_step.edge");
TOPOMESH_STATIC_ASSERT(offsetof(che_star_step, triangle) == 12, "che_star_step.triangle");
#undef TOPOMESH_P

#ifdef __cplusplus
extern "C" {
#endif
/* The library's step (declared again, with its documentation, in topomesh.h). */
bool che_star_advance(struct che_star_iter *it, struct che_star_step *step);
#ifdef __cplusplus
}
#endif

/* Writes the next step of the rotation begun by che_star_begin into *step and returns
   true, or returns false at the end (also when it or step is NULL). O(1) per step from
   level 2, without a call into the library; below, each step is che_star_advance. */
static inline bool che_star_next(che_star_iter *it, che_star_step *step) {
    if (it == NULL || step == NULL || it->o == NULL) return che_star_advance(it, step);
    /* Everything is read before anything is written (the compiler cannot know that step
       aliases nothing). */
    const uint32_t *const O = it->o;
    const uint32_t cur = it->cur, tail = it->tail;
    uint32_t h, vertex, triangle, canonical;
    if (cur != TOPOMESH_NONE) {
        const uint32_t p = che_prev(cur), g = O[p], o = it->cur_opposite;
        h = cur;
        vertex = it->v[che_next(cur)];
        triangle = che_tri(cur);
        canonical = (o != TOPOMESH_NONE && o < cur) ? o : cur;
        it->cur = (g == TOPOMESH_NONE || g == it->start) ? TOPOMESH_NONE : g;
        it->cur_opposite = p; /* O[g] == p */
        if (g == TOPOMESH_NONE) it->tail = p;
    } else if (tail != TOPOMESH_NONE) {
        h = canonical = tail; /* a boundary half-edge is its edge's canonical one */
        vertex = it->v[tail];
        triangle = TOPOMESH_NONE;
        it->tail = TOPOMESH_NONE;
    } else {
        return false;
    }
    /* The edge of h: the rank of its canonical half-edge (see che_edge_of). */
    const uint64_t d = it->edge_ranks[canonical >> 5];
    step->half_edge = h;
    step->vertex = vertex;
    step->edge = (uint32_t)(d >> 32) +
                 topomesh_popcount32((uint32_t)d & ((1u << (canonical & 31u)) - 1u));
    step->triangle = triangle;
    return true;
}

#endif /* TOPOMESH_INLINE_H */
