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

#endif /* TOPOMESH_INLINE_H */
