/* topomesh: hand-written part of the C API, included by the generated topomesh.h.
 *
 * The half-edge arithmetic of CHE as static inline functions, so that C hosts can walk
 * the zero-copy arrays (che_mesh_half_edge_vertices, che_mesh_opposites, ...) at native
 * speed: triangle t owns half-edges 3t, 3t+1, 3t+2; half-edge h runs from V[h] to
 * V[che_next(h)]; the vertex opposite h in its triangle is V[che_prev(h)].
 */
#ifndef TOPOMESH_INLINE_H
#define TOPOMESH_INLINE_H

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

#endif /* TOPOMESH_INLINE_H */
