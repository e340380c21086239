/* Concurrent stress of the C API: 8 threads sweep every relation, half-edge helper, star,
   CSR call and view of one CHE and one CHF at once (each thread starting at a different
   relation), and compare each sweep with the answers of one thread alone. Run under
   ThreadSanitizer or helgrind by scripts/sanitize.sh.

   Usage: test_stress [GRID [ROUNDS]]   the surface is a GRID x GRID square of triangles and
   the volume a (GRID/2)^3 block of cubes cut into 6 tetrahedra each (defaults 12 and 2). */
#define _POSIX_C_SOURCE 200809L /* pthread_barrier_t in strict C11 */
#include "../c/check.h"

#include <pthread.h>

#define N_STRESS_THREADS 8

typedef topomesh_status (*che_ids_fn)(const che_mesh *, uint32_t, uint32_t *, size_t, size_t *);
typedef topomesh_status (*chf_ids_fn)(const chf_mesh *, uint32_t, uint32_t *, size_t, size_t *);
typedef topomesh_status (*che_csr_fn)(const che_mesh *, uint32_t *, size_t, uint32_t *, size_t,
                                      size_t *, size_t *);
typedef topomesh_status (*chf_csr_fn)(const chf_mesh *, uint32_t *, size_t, uint32_t *, size_t,
                                      size_t *, size_t *);

/* Order-sensitive digest of a sequence of answers. */
static uint64_t mix(uint64_t h, uint64_t x) { return (h ^ x) * 0x100000001b3ULL + 0x9e3779b9; }

static uint64_t digest_ids(uint64_t h, topomesh_status s, const uint32_t *buf, size_t len) {
    h = mix(h, s);
    if (s == TOPOMESH_STATUS_OK)
        for (size_t i = 0; i < len; i++) h = mix(h, buf[i]);
    return h;
}

static const che_ids_fn CHE_IDS[] = {
    che_vertex_vertices, che_vertex_edges,   che_vertex_triangles,   che_edge_vertices,
    che_edge_edges,      che_edge_triangles, che_triangle_vertices,  che_triangle_edges,
    che_triangle_triangles, che_boundary_curve_vertices,
};
static const chf_ids_fn CHF_IDS[] = {
    chf_vertex_vertices,  chf_vertex_edges,  chf_vertex_faces,  chf_vertex_tetrahedra,
    chf_edge_vertices,    chf_edge_edges,    chf_edge_faces,    chf_edge_tetrahedra,
    chf_face_vertices,    chf_face_edges,    chf_face_faces,    chf_face_tetrahedra,
    chf_tetrahedron_vertices, chf_tetrahedron_edges, chf_tetrahedron_faces,
    chf_tetrahedron_tetrahedra,
};
static const che_csr_fn CHE_CSR[] = {che_mesh_vertex_vertices_csr, che_mesh_vertex_edges_csr,
                                     che_mesh_vertex_triangles_csr,
                                     che_mesh_triangle_triangles_csr};
static const chf_csr_fn CHF_CSR[] = {
    chf_mesh_vertex_vertices_csr,  chf_mesh_vertex_edges_csr,      chf_mesh_vertex_faces_csr,
    chf_mesh_vertex_tetrahedra_csr, chf_mesh_edge_faces_csr,       chf_mesh_edge_tetrahedra_csr,
    chf_mesh_tetrahedron_tetrahedra_csr,
};
#define N_CHE_IDS (sizeof CHE_IDS / sizeof *CHE_IDS)
#define N_CHF_IDS (sizeof CHF_IDS / sizeof *CHF_IDS)
#define N_CHE_CSR (sizeof CHE_CSR / sizeof *CHE_CSR)
#define N_CHF_CSR (sizeof CHF_CSR / sizeof *CHF_CSR)
/* One digest per relation, then the helpers, the stars, the CSR calls and the views. */
#define N_DIGESTS (N_CHE_IDS + N_CHF_IDS + N_CHE_CSR + N_CHF_CSR + 4)

static const che_mesh *che;
static const chf_mesh *chf;
static uint64_t reference[N_DIGESTS];
static pthread_barrier_t start;

static size_t che_count(size_t k) {
    size_t n[] = {che_mesh_num_vertices(che), che_mesh_num_edges(che),
                  che_mesh_num_triangles(che), che_mesh_num_boundary_curves(che)};
    return n[k < 3 ? 0 : k < 6 ? 1 : k < 9 ? 2 : 3];
}

static size_t chf_count(size_t k) {
    size_t n[] = {chf_mesh_num_vertices(chf), chf_mesh_num_edges(chf), chf_mesh_num_faces(chf),
                  chf_mesh_num_tetrahedra(chf)};
    return n[k / 4];
}

/* Digest d of the sweep: every id of one relation (and one past the end), or the rest. */
static uint64_t sweep(size_t d) {
    uint32_t buf[256];
    size_t len = 0;
    uint64_t h = 1;
    if (d < N_CHE_IDS) {
        for (uint32_t i = 0; i <= che_count(d); i++)
            h = digest_ids(h, CHE_IDS[d](che, i, buf, 256, &len), buf, len);
        return h;
    }
    d -= N_CHE_IDS;
    if (d < N_CHF_IDS) {
        for (uint32_t i = 0; i <= chf_count(d); i++)
            h = digest_ids(h, CHF_IDS[d](chf, i, buf, 256, &len), buf, len);
        return h;
    }
    d -= N_CHF_IDS;
    if (d < N_CHE_CSR + N_CHF_CSR) {
        size_t no = 0, ni = 0;
        topomesh_status s = d < N_CHE_CSR ? CHE_CSR[d](che, NULL, 0, NULL, 0, &no, &ni)
                                          : CHF_CSR[d - N_CHE_CSR](chf, NULL, 0, NULL, 0, &no, &ni);
        uint32_t *o = malloc((no + 1) * sizeof *o), *ix = malloc((ni + 1) * sizeof *ix);
        s = d < N_CHE_CSR ? CHE_CSR[d](che, o, no, ix, ni, &no, &ni)
                          : CHF_CSR[d - N_CHE_CSR](chf, o, no, ix, ni, &no, &ni);
        h = digest_ids(digest_ids(h, s, o, no), s, ix, ni);
        free(o);
        free(ix);
        return h;
    }
    d -= N_CHE_CSR + N_CHF_CSR;
    if (d == 0) { /* half-edge and half-face helpers, boundary tests */
        uint32_t out = 0;
        bool b = false;
        for (uint32_t i = 0; i < che_mesh_num_half_edges(che); i++) {
            h = mix(mix(h, che_half_edge_opposite(che, i, &out)), out);
            h = mix(mix(h, che_half_edge_edge(che, i, &out)), out);
            h = mix(mix(h, che_half_edge_curve(che, i, &out)), out);
        }
        for (uint32_t i = 0; i < che_mesh_num_vertices(che); i++)
            h = mix(mix(h, che_vertex_is_boundary(che, i, &b)), b);
        for (uint32_t i = 0; i < chf_mesh_num_half_faces(chf); i++) {
            h = mix(mix(h, chf_half_face_opposite(chf, i, &out)), out);
            h = mix(mix(h, chf_half_face_face(chf, i, &out)), out);
            h = mix(mix(h, chf_half_face_boundary_triangle(chf, i, &out)), out);
        }
        for (uint32_t i = 0; i < chf_mesh_num_vertices(chf); i++) {
            h = mix(mix(h, chf_vertex_is_boundary(chf, i, &b)), b);
            h = mix(mix(h, chf_vertex_boundary_component(chf, i, &out)), out);
        }
        return h;
    }
    if (d == 1) { /* every star, stepped inline and past its end */
        for (uint32_t v = 0; v < che_mesh_num_vertices(che); v++) {
            che_star_iter it;
            che_star_step s;
            h = mix(h, che_star_begin(che, v, &it));
            while (che_star_next(&it, &s)) h = mix(mix(mix(h, s.vertex), s.edge), s.triangle);
            h = mix(h, che_star_next(&it, &s));
        }
        return h;
    }
    if (d == 2) { /* views, the origin maps materialised on first use */
        size_t n = 0;
        const uint32_t *p = che_mesh_vertex_origins(che, &n);
        for (size_t i = 0; i < n; i++) h = mix(h, p[i]);
        p = che_mesh_triangle_origins(che, &n);
        for (size_t i = 0; i < n; i++) h = mix(h, p[i]);
        p = chf_mesh_vertex_origins(chf, &n);
        for (size_t i = 0; i < n; i++) h = mix(h, p[i]);
        p = chf_mesh_tetrahedron_origins(chf, &n);
        for (size_t i = 0; i < n; i++) h = mix(h, p[i]);
        return h;
    }
    /* summaries and validation */
    che_summary cs;
    chf_summary fs;
    h = mix(h, che_mesh_summary(che, &cs));
    h = mix(mix(h, cs.euler_characteristic), chf_mesh_summary(chf, &fs));
    h = mix(mix(h, che_mesh_validate(che)), chf_mesh_validate(chf));
    return mix(h, (uint64_t)fs.euler_characteristic);
}

static int rounds = 2;

static void *worker(void *arg) {
    size_t first = (size_t)(uintptr_t)arg;
    int *failed = calloc(1, sizeof *failed);
    pthread_barrier_wait(&start);
    for (int r = 0; r < rounds; r++)
        for (size_t i = 0; i < N_DIGESTS; i++) {
            size_t d = (first * 5 + i) % N_DIGESTS;
            if (sweep(d) != reference[d]) {
                fprintf(stderr, "thread %zu: sweep %zu differs from one thread's\n", first, d);
                *failed = 1;
            }
        }
    return failed;
}

/* The surface: a g x g square of quads, each cut in two; the volume: a k^3 block of cubes
   (k = g / 2), each cut into 6 tetrahedra around its diagonal. Both at level 3. */
static void build(uint32_t g, che_mesh **surface, chf_mesh **volume) {
    uint32_t *tris = malloc((size_t)g * g * 6 * sizeof *tris), nq = 0;
    for (uint32_t y = 0; y < g; y++)
        for (uint32_t x = 0; x < g; x++) {
            uint32_t a = y * (g + 1) + x, b = a + 1, c = a + g + 1, d = c + 1;
            uint32_t t[6] = {a, b, d, a, d, c};
            memcpy(tris + 6 * (size_t)nq++, t, sizeof t);
        }
    uint32_t k = g / 2 > 0 ? g / 2 : 1, m = k + 1, ntet = 0;
    uint32_t *tets = malloc((size_t)k * k * k * 24 * sizeof *tets);
    static const int path[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
    for (uint32_t z = 0; z < k; z++)
        for (uint32_t y = 0; y < k; y++)
            for (uint32_t x = 0; x < k; x++) {
                uint32_t c[8];
                for (int i = 0; i < 8; i++)
                    c[i] = ((z + (i >> 2 & 1)) * m + y + (i >> 1 & 1)) * m + x + (i & 1);
                for (int i = 0; i < 6; i++) {
                    uint32_t t[4] = {c[0], c[path[i][0]], c[path[i][1]], c[7]};
                    memcpy(tets + 4 * (size_t)ntet++, t, sizeof t);
                }
            }
    CHECK_OK(che_mesh_from_triangles(tris, 2 * (size_t)nq, (size_t)(g + 1) * (g + 1), NULL, 3,
                                     surface));
    CHECK_OK(chf_mesh_from_tetrahedra(tets, ntet, (size_t)m * m * m, NULL, 3, volume));
    free(tris);
    free(tets);
}

int main(int argc, char **argv) {
    uint32_t g = argc > 1 ? (uint32_t)atoi(argv[1]) : 12;
    rounds = argc > 2 ? atoi(argv[2]) : 2;
    che_mesh *surface = NULL;
    chf_mesh *volume = NULL;
    /* One thread's answers, on a first pair of meshes, so that the lazily materialised
       views of the second (shared) pair are first touched by all the threads at once. */
    build(g, &surface, &volume);
    if (!surface || !volume) return finish("test_stress");
    che = surface;
    chf = volume;
    for (size_t d = 0; d < N_DIGESTS; d++) reference[d] = sweep(d);
    che_mesh_free(surface);
    chf_mesh_free(volume);
    build(g, &surface, &volume);
    if (!surface || !volume) return finish("test_stress");
    che = surface;
    chf = volume;
    pthread_t th[N_STRESS_THREADS];
    pthread_barrier_init(&start, NULL, N_STRESS_THREADS);
    for (size_t i = 0; i < N_STRESS_THREADS; i++)
        CHECK(pthread_create(&th[i], NULL, worker, (void *)(uintptr_t)i) == 0);
    for (size_t i = 0; i < N_STRESS_THREADS; i++) {
        void *failed = NULL;
        CHECK(pthread_join(th[i], &failed) == 0);
        CHECK(failed && !*(int *)failed);
        free(failed);
    }
    pthread_barrier_destroy(&start);
    che_mesh_free(surface);
    chf_mesh_free(volume);
    printf("test_stress: %d threads x %d rounds x %zu sweeps (grid %u)\n", N_STRESS_THREADS,
           rounds, (size_t)N_DIGESTS, g);
    return finish("test_stress");
}
