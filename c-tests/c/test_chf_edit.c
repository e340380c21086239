/* Editing a tetrahedral mesh in place through the C API: every call, and every refusal
   (removed, out-of-range and NONE ids, boundary flips, repeated or existing tetrahedra,
   inverted splits, the link condition, NULL pointers, small map buffers) gives a status
   and a detail and leaves the mesh's arrays and counts unchanged; the mesh validates after
   each call and after garbage collection, at every level, with and without positions. */
#include "chf_fixtures.h"

/* A copy of the half-face vertices (malloc'ed), to compare before and after a refusal. */
static uint32_t *copy_hf(const chf_mesh *m, size_t *len) {
    const uint32_t *v = chf_mesh_half_face_vertices(m, len);
    return copy_ids(v, *len);
}

/* `call` is refused with `want` and a detail containing `needle`; the tetrahedra, the
   counts and the live counts unchanged, the mesh still valid. */
#define CHECK_REFUSED(m, call, want, needle)                                               \
    do {                                                                                   \
        size_t n0_, n1_;                                                                   \
        uint32_t *v0_ = copy_hf(m, &n0_);                                                  \
        const size_t t0_ = chf_mesh_num_live_tetrahedra(m),                                \
                     x0_ = chf_mesh_num_live_vertices(m), f0_ = chf_mesh_num_faces(m),     \
                     e0_ = chf_mesh_num_edges(m);                                          \
        CHECK_STATUS(call, want);                                                          \
        CHECK_DETAIL(needle);                                                              \
        const uint32_t *v1_ = chf_mesh_half_face_vertices(m, &n1_);                        \
        CHECK(n0_ == n1_ && (n0_ == 0 || memcmp(v0_, v1_, n0_ * sizeof *v0_) == 0));       \
        CHECK(t0_ == chf_mesh_num_live_tetrahedra(m));                                     \
        CHECK(x0_ == chf_mesh_num_live_vertices(m));                                       \
        CHECK(f0_ == chf_mesh_num_faces(m) && e0_ == chf_mesh_num_edges(m));               \
        CHECK_OK(chf_mesh_validate(m));                                                    \
        free(v0_);                                                                         \
    } while (0)

static const uint32_t NONE_ = TOPOMESH_NONE;

/* Adding and removing vertices and tetrahedra. */
/* Splitting a face or an edge: its call, its check, and the elements around a vertex. */
typedef struct split_op {
    topomesh_status (*split)(chf_mesh *m, uint32_t id, const double *position, uint32_t *v);
    topomesh_status (*check)(const chf_mesh *m, uint32_t id, const double *position);
    topomesh_status (*around)(const chf_mesh *m, uint32_t v, uint32_t *buf, size_t cap,
                              size_t *len);
    const char *what; /* in the detail of an out-of-range id */
} split_op;
static const split_op SPLIT_FACE = {chf_mesh_split_face, chf_mesh_check_split_face,
                                    chf_vertex_faces, "face"};
static const split_op SPLIT_EDGE = {chf_mesh_split_edge, chf_mesh_check_split_edge,
                                    chf_vertex_edges, "edge"};

/* Splits the first element around vertex x (the check accepts it first) at a new vertex,
   which must be `want`; then that element is refused as removed, and NONE as out of range.
   Returns the new vertex. */
static uint32_t split_around(chf_mesh *m, uint32_t x, const split_op *op, uint32_t want) {
    uint32_t ids[16];
    size_t n = 0;
    CHECK_OK(op->around(m, x, ids, 16, &n));
    CHECK(n >= 1);
    CHECK_OK(op->check(m, ids[0], NULL));
    CHECK_OK(op->split(m, ids[0], NULL, &x));
    CHECK(x == want);
    CHECK_REFUSED(m, op->split(m, ids[0], NULL, &x), TOPOMESH_STATUS_OUT_OF_RANGE, "removed");
    CHECK_REFUSED(m, op->check(m, NONE_, NULL), TOPOMESH_STATUS_OUT_OF_RANGE, op->what);
    CHECK_OK(chf_mesh_validate(m));
    return x;
}

static void add_and_remove(chf_mesh *m) {
    uint32_t x = NONE_, t = NONE_;
    bool flag = false;
    const double p[3] = {2, 2, 2};
    CHECK_OK(chf_mesh_add_vertex(m, p, &x));
    CHECK(x == 5 && chf_mesh_num_live_vertices(m) == 6);
    CHECK_REFUSED(m, chf_mesh_add_vertex(m, NULL, &x), TOPOMESH_STATUS_INVALID_INPUT,
                  "needs one");
    const double inf[3] = {1.0 / 0.0, 0, 0};
    CHECK_REFUSED(m, chf_mesh_add_vertex(m, inf, &x), TOPOMESH_STATUS_INVALID_INPUT,
                  "not finite");
    const uint32_t again[4] = {0, 1, 2, 3}, far[4] = {0, 1, 2, 99},
                   none[4] = {NONE_, 1, 2, 3}, rep[4] = {0, 1, 1, 2}, ok[4] = {1, 2, 4, 5};
    CHECK_REFUSED(m, chf_mesh_add_tetrahedron(m, again, &t), TOPOMESH_STATUS_NON_MANIFOLD,
                  "face [1, 2, 3] would have three tetrahedra");
    CHECK_REFUSED(m, chf_mesh_check_add_tetrahedron(m, again), TOPOMESH_STATUS_NON_MANIFOLD,
                  "three tetrahedra");
    CHECK_REFUSED(m, chf_mesh_add_tetrahedron(m, far, &t), TOPOMESH_STATUS_OUT_OF_RANGE, "99");
    CHECK_REFUSED(m, chf_mesh_add_tetrahedron(m, none, &t), TOPOMESH_STATUS_OUT_OF_RANGE,
                  "vert");
    CHECK_REFUSED(m, chf_mesh_add_tetrahedron(m, rep, &t), TOPOMESH_STATUS_INVALID_INPUT,
                  "repeats vertex 1");
    CHECK_REFUSED(m, chf_mesh_add_tetrahedron(m, NULL, &t), TOPOMESH_STATUS_NULL_ARGUMENT,
                  "vertices");
    CHECK_OK(chf_mesh_check_add_tetrahedron(m, ok));
    CHECK_OK(chf_mesh_add_tetrahedron(m, ok, &t));
    CHECK(t == 2 && chf_mesh_num_live_tetrahedra(m) == 3);
    CHECK_OK(chf_mesh_validate(m));
    CHECK_OK(chf_mesh_check_remove_tetrahedron(m, t));
    CHECK_OK(chf_mesh_remove_tetrahedron(m, t));
    CHECK_OK(chf_tetrahedron_is_removed(m, t, &flag));
    CHECK(flag && chf_mesh_num_live_tetrahedra(m) == 2 && chf_mesh_num_tetrahedra(m) == 3);
    CHECK_REFUSED(m, chf_mesh_remove_tetrahedron(m, t), TOPOMESH_STATUS_OUT_OF_RANGE,
                  "removed");
    CHECK_REFUSED(m, chf_mesh_check_remove_tetrahedron(m, t), TOPOMESH_STATUS_OUT_OF_RANGE,
                  "removed");
    CHECK_REFUSED(m, chf_mesh_remove_tetrahedron(m, 99), TOPOMESH_STATUS_OUT_OF_RANGE, "99");
    CHECK_REFUSED(m, chf_mesh_remove_tetrahedron(m, NONE_), TOPOMESH_STATUS_OUT_OF_RANGE,
                  "tetrahedron");
    CHECK_STATUS(chf_mesh_remove_tetrahedron(NULL, 0), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("m");
    CHECK_OK(chf_tetrahedron_is_removed(m, 0, &flag));
    CHECK(!flag);
}

/* The 2-3 flip of the shared face and the 3-2 flip back; refusals on the boundary. */
static void flips(chf_mesh *m) {
    uint32_t f = NONE_, fb = NONE_, news[3] = {NONE_, NONE_, NONE_}, back[2] = {NONE_, NONE_};
    CHECK_OK(chf_half_face_face(m, 0, &f)); /* (1, 2, 3), shared by the pair */
    CHECK_OK(chf_half_face_face(m, 1, &fb)); /* a boundary face of tetrahedron 0 */
    CHECK_REFUSED(m, chf_mesh_flip_23(m, fb, news), TOPOMESH_STATUS_INVALID_INPUT,
                  "boundary");
    CHECK_REFUSED(m, chf_mesh_check_flip_23(m, fb), TOPOMESH_STATUS_INVALID_INPUT,
                  "boundary");
    CHECK_REFUSED(m, chf_mesh_flip_23(m, NONE_, news), TOPOMESH_STATUS_OUT_OF_RANGE, "face");
    CHECK_STATUS(chf_mesh_flip_23(NULL, f, news), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_OK(chf_mesh_check_flip_23(m, f));
    /* The yes-or-no question: true, false for a refusal, an error for a bad id. */
    bool ok = false;
    CHECK_OK(chf_mesh_is_flip_23_ok(m, f, &ok));
    CHECK(ok);
    CHECK_OK(chf_mesh_is_flip_23_ok(m, fb, &ok));
    CHECK(!ok);
    CHECK_STATUS(chf_mesh_is_flip_23_ok(m, NONE_, &ok), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("face");
    CHECK_STATUS(chf_mesh_is_flip_23_ok(m, f, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_mesh_is_flip_23_ok(NULL, f, &ok), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_OK(chf_mesh_flip_23(m, f, news));
    CHECK(chf_mesh_num_live_tetrahedra(m) == 3);
    CHECK(news[0] != NONE_ && news[1] != NONE_ && news[2] != NONE_);
    CHECK_OK(chf_mesh_validate(m));
    bool flag = false;
    CHECK_OK(chf_face_is_removed(m, f, &flag));
    CHECK(flag);
    CHECK_REFUSED(m, chf_mesh_flip_23(m, f, NULL), TOPOMESH_STATUS_OUT_OF_RANGE, "removed");
    /* The new edge (0, 4) is the one edge of news[0] with three tetrahedra around it. */
    uint32_t edges[6];
    size_t n = 0;
    CHECK_OK(chf_tetrahedron_edges(m, news[0], edges, 6, &n));
    uint32_t e = NONE_, eb = NONE_;
    for (size_t i = 0; i < n; i++) {
        if (chf_mesh_check_flip_32(m, edges[i]) == TOPOMESH_STATUS_OK) e = edges[i];
        bool b = false;
        if (chf_edge_is_boundary(m, edges[i], &b) == TOPOMESH_STATUS_OK && b) eb = edges[i];
    }
    CHECK(e != NONE_ && eb != NONE_);
    CHECK_REFUSED(m, chf_mesh_flip_32(m, eb, back), TOPOMESH_STATUS_INVALID_INPUT, "boundary");
    CHECK_REFUSED(m, chf_mesh_check_flip_32(m, eb), TOPOMESH_STATUS_INVALID_INPUT, "boundary");
    CHECK_OK(chf_mesh_is_flip_32_ok(m, e, &ok));
    CHECK(ok);
    CHECK_OK(chf_mesh_is_flip_32_ok(m, eb, &ok));
    CHECK(!ok);
    CHECK_STATUS(chf_mesh_is_flip_32_ok(m, NONE_, &ok), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_REFUSED(m, chf_mesh_flip_32(m, NONE_, back), TOPOMESH_STATUS_OUT_OF_RANGE, "edge");
    CHECK_OK(chf_mesh_flip_32(m, e, back));
    CHECK(back[0] != NONE_ && back[1] != NONE_ && chf_mesh_num_live_tetrahedra(m) == 2);
    CHECK_OK(chf_edge_is_removed(m, e, &flag));
    CHECK(flag);
    CHECK_OK(chf_mesh_validate(m));
}

/* 1-4, 2-6 and edge splits; a refused position; a collapse, accepted and refused. */
static void splits_and_collapse(chf_mesh *m, bool positions) {
    uint32_t x = NONE_, t = NONE_;
    const size_t nv = chf_mesh_num_vertices(m);
    for (t = 0; t < chf_mesh_num_tetrahedra(m); t++) {
        bool removed = true;
        CHECK_OK(chf_tetrahedron_is_removed(m, t, &removed));
        if (!removed) break;
    }
    if (positions) {
        const double out[3] = {5, 5, 5};
        CHECK_REFUSED(m, chf_mesh_split_tetrahedron(m, t, out, &x),
                      TOPOMESH_STATUS_INVALID_INPUT, "inverted");
        CHECK_REFUSED(m, chf_mesh_check_split_tetrahedron(m, t, out),
                      TOPOMESH_STATUS_INVALID_INPUT, "inverted");
    } else {
        const double p[3] = {0.1, 0.1, 0.1};
        CHECK_REFUSED(m, chf_mesh_split_tetrahedron(m, t, p, &x),
                      TOPOMESH_STATUS_INVALID_INPUT, "no positions");
    }
    CHECK_REFUSED(m, chf_mesh_split_tetrahedron(m, NONE_, NULL, &x),
                  TOPOMESH_STATUS_OUT_OF_RANGE, "tetrahedron");
    CHECK_OK(chf_mesh_check_split_tetrahedron(m, t, NULL));
    CHECK_OK(chf_mesh_split_tetrahedron(m, t, NULL, &x));
    CHECK(x == nv && chf_mesh_num_vertices(m) == nv + 1);
    CHECK_OK(chf_mesh_validate(m));
    x = split_around(m, x, &SPLIT_FACE, nv + 1);
    x = split_around(m, x, &SPLIT_EDGE, nv + 2);

    /* Every half-edge of the live tetrahedra: the check and the call agree; collapse the
       first accepted one, refuse the first refused one. */
    uint64_t good = UINT64_MAX, bad = UINT64_MAX;
    topomesh_status why = TOPOMESH_STATUS_OK;
    for (uint32_t s = 0; s < chf_mesh_num_tetrahedra(m); s++) {
        bool removed = true;
        CHECK_OK(chf_tetrahedron_is_removed(m, s, &removed));
        for (uint64_t he = 12ull * s; !removed && he < 12ull * s + 12; he++) {
            const topomesh_status c = chf_mesh_check_collapse_edge(m, he);
            bool ok = false;
            CHECK_OK(chf_mesh_is_collapse_ok(m, he, &ok));
            CHECK(ok == (c == TOPOMESH_STATUS_OK));
            if (c == TOPOMESH_STATUS_OK && good == UINT64_MAX) good = he;
            if (c != TOPOMESH_STATUS_OK && bad == UINT64_MAX) {
                bad = he;
                why = c;
            }
        }
    }
    CHECK(good != UINT64_MAX && bad != UINT64_MAX);
    CHECK(why == TOPOMESH_STATUS_INVALID_INPUT || why == TOPOMESH_STATUS_NON_MANIFOLD);
    CHECK_REFUSED(m, chf_mesh_collapse_edge(m, bad, &x), why, "collapse_edge");
    CHECK_REFUSED(m, chf_mesh_collapse_edge(m, UINT64_MAX, &x), TOPOMESH_STATUS_OUT_OF_RANGE,
                  "half-edge");
    bool asked = true;
    CHECK_STATUS(chf_mesh_is_collapse_ok(m, UINT64_MAX, &asked), TOPOMESH_STATUS_OUT_OF_RANGE);
    const size_t live = chf_mesh_num_live_vertices(m);
    CHECK_OK(chf_mesh_collapse_edge(m, good, &x));
    CHECK(chf_mesh_num_live_vertices(m) == live - 1);
    bool flag = true;
    CHECK_OK(chf_vertex_is_removed(m, x, &flag));
    CHECK(!flag);
    CHECK_OK(chf_mesh_validate(m));
}

/* Removing a vertex with its star; the removed marks and live counts. */
static void remove_and_marks(chf_mesh *m) {
    bool flag = false;
    const uint32_t v = (uint32_t)chf_mesh_num_vertices(m) - 1; /* the edge split's vertex */
    CHECK_OK(chf_mesh_check_remove_vertex(m, v));
    CHECK_OK(chf_mesh_remove_vertex(m, v));
    CHECK_OK(chf_vertex_is_removed(m, v, &flag));
    CHECK(flag);
    CHECK_REFUSED(m, chf_mesh_remove_vertex(m, v), TOPOMESH_STATUS_OUT_OF_RANGE, "removed");
    CHECK_REFUSED(m, chf_mesh_check_remove_vertex(m, v), TOPOMESH_STATUS_OUT_OF_RANGE,
                  "is removed");
    /* A new tetrahedron over a removed vertex, in every position, beside live ones. */
    uint32_t t = 0, q[4];
    size_t len = 0;
    for (bool gone = true; gone; t++) CHECK_OK(chf_tetrahedron_is_removed(m, t, &gone));
    CHECK_OK(chf_tetrahedron_vertices(m, t - 1, q, 4, &len));
    for (int i = 0; i < 4; i++) {
        uint32_t r[4] = {q[0], q[1], q[2], q[3]}, out = NONE_;
        r[i] = v;
        CHECK_REFUSED(m, chf_mesh_add_tetrahedron(m, r, &out), TOPOMESH_STATUS_OUT_OF_RANGE,
                      "is removed");
        CHECK_REFUSED(m, chf_mesh_check_add_tetrahedron(m, r), TOPOMESH_STATUS_OUT_OF_RANGE,
                      "is removed");
        CHECK(out == NONE_);
    }
    CHECK_REFUSED(m, chf_mesh_check_remove_vertex(m, 999), TOPOMESH_STATUS_OUT_OF_RANGE,
                  "999");
    CHECK_REFUSED(m, chf_mesh_remove_vertex(m, NONE_), TOPOMESH_STATUS_OUT_OF_RANGE, "vertex");
    CHECK_STATUS(chf_vertex_is_removed(m, 999, &flag), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("999");
    CHECK_STATUS(chf_tetrahedron_is_removed(m, NONE_, &flag), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(chf_face_is_removed(m, NONE_, &flag), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(chf_edge_is_removed(m, NONE_, &flag), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(chf_edge_is_removed(m, 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_face_is_removed(NULL, 0, &flag), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK(chf_mesh_num_live_vertices(m) < chf_mesh_num_vertices(m));
    CHECK(chf_mesh_num_live_tetrahedra(m) < chf_mesh_num_tetrahedra(m));
    CHECK(chf_mesh_num_live_faces(m) < chf_mesh_num_faces(m));
    CHECK(chf_mesh_num_live_edges(m) < chf_mesh_num_edges(m));
    CHECK(chf_mesh_num_live_tetrahedra(NULL) == 0);
}

/* Fills `map` (n ids) for `count` live elements: each live id to a distinct new id below
   `count`, each removed one to NONE. */
static void check_map(const uint32_t *map, size_t n, size_t count) {
    uint8_t *seen = calloc(count + 1, 1);
    if (!seen) exit(2);
    size_t live = 0;
    for (size_t i = 0; i < n; i++) {
        if (map[i] == NONE_) continue;
        CHECK(map[i] < count && !seen[map[i]]);
        if (map[i] < count) seen[map[i]] = 1;
        live++;
    }
    CHECK(live == count);
    free(seen);
}

static void garbage_collect(chf_mesh *m) {
    const size_t nv = chf_mesh_num_vertices(m), nt = chf_mesh_num_tetrahedra(m),
                 nf = chf_mesh_num_faces(m), ne = chf_mesh_num_edges(m);
    const size_t lv = chf_mesh_num_live_vertices(m), lt = chf_mesh_num_live_tetrahedra(m),
                 lf = chf_mesh_num_live_faces(m), le = chf_mesh_num_live_edges(m);
    uint32_t *vm = malloc(nv * sizeof *vm), *tm = malloc(nt * sizeof *tm),
             *fm = malloc(nf * sizeof *fm), *em = malloc(ne * sizeof *em);
    if (!vm || !tm || !fm || !em) exit(2);
    CHECK_REFUSED(m, chf_mesh_garbage_collect(m, vm, nv - 1, tm, nt, fm, nf, em, ne),
                  TOPOMESH_STATUS_BUFFER_TOO_SMALL, "vertex_map");
    CHECK_REFUSED(m, chf_mesh_garbage_collect(m, vm, nv, tm, nt, fm, nf, em, ne - 1),
                  TOPOMESH_STATUS_BUFFER_TOO_SMALL, "edge_map");
    CHECK_STATUS(chf_mesh_garbage_collect(NULL, NULL, 0, NULL, 0, NULL, 0, NULL, 0),
                 TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_REFUSED(m, chf_mesh_garbage_collect(m, vm, nv, tm, nt, fm, nf, fm + 1, ne),
                  TOPOMESH_STATUS_INVALID_INPUT, "overlap");
    CHECK_OK(chf_mesh_garbage_collect(m, vm, nv, tm, nt, fm, nf, em, ne));
    CHECK(chf_mesh_num_vertices(m) == lv && chf_mesh_num_tetrahedra(m) == lt);
    CHECK(chf_mesh_num_faces(m) == lf && chf_mesh_num_edges(m) == le);
    CHECK(chf_mesh_num_live_vertices(m) == lv && chf_mesh_num_live_tetrahedra(m) == lt);
    check_map(vm, nv, lv);
    check_map(tm, nt, lt);
    check_map(fm, nf, lf);
    check_map(em, ne, le);
    CHECK(vm[nv - 1] == NONE_); /* the removed vertex */
    CHECK(tm[2] == NONE_);      /* the added and removed tetrahedron */
    CHECK_OK(chf_mesh_validate(m));
    CHECK_OK(chf_mesh_garbage_collect(m, NULL, 0, NULL, 0, NULL, 0, NULL, 0));
    CHECK(chf_mesh_num_tetrahedra(m) == lt);
    free(vm);
    free(tm);
    free(fm);
    free(em);
}

static void edit_at_level(uint32_t level, bool positions) {
    chf_mesh *m = make_chf(PAIR, NTET(PAIR), 5, positions ? PAIR_POS : NULL, level);
    if (positions) {
        add_and_remove(m);
    } else {
        uint32_t x = NONE_;
        const double p[3] = {2, 2, 2};
        CHECK_REFUSED(m, chf_mesh_add_vertex(m, p, &x), TOPOMESH_STATUS_INVALID_INPUT,
                      "no positions");
        CHECK_OK(chf_mesh_add_vertex(m, NULL, &x));
        CHECK(x == 5);
        const uint32_t q[4] = {1, 2, 4, 5};
        uint32_t t = NONE_;
        CHECK_OK(chf_mesh_add_tetrahedron(m, q, &t));
        CHECK(t == 2);
        CHECK_OK(chf_mesh_remove_tetrahedron(m, t));
    }
    flips(m);
    splits_and_collapse(m, positions);
    remove_and_marks(m);
    garbage_collect(m);
    chf_mesh_free(m);
}

/* Refusals the pair cannot show: a tetrahedron that exists, and the 3-2 flip of an edge
   of the star whose result would repeat its outer tetrahedron. */
static void more_refusals(uint32_t level) {
    chf_mesh *one = make_chf(TET, 1, 4, TET_POS, level);
    uint32_t t = NONE_;
    CHECK_REFUSED(one, chf_mesh_add_tetrahedron(one, TET, &t), TOPOMESH_STATUS_INVALID_INPUT,
                  "already exists");
    chf_mesh_free(one);
    chf_mesh *star = make_chf(STAR, NTET(STAR), 5, STAR_POS, level);
    uint32_t edges[16];
    size_t n = 0;
    CHECK_OK(chf_vertex_edges(star, 4, edges, 16, &n));
    CHECK(n == 4);
    for (size_t i = 0; i < n; i++) {
        uint32_t two[2];
        CHECK_REFUSED(star, chf_mesh_flip_32(star, edges[i], two),
                      TOPOMESH_STATUS_INVALID_INPUT, "refused");
    }
    chf_mesh_free(star);
}

int main(void) {
    for (uint32_t level = 0; level <= 3; level++) {
        edit_at_level(level, true);
        edit_at_level(level, false);
        more_refusals(level);
    }
    return finish("test_chf_edit");
}
