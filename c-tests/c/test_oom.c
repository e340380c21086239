/* Running out of memory is a status, never an abort of the host.
 *
 *   test_oom rlimit   a child process caps its address space (RLIMIT_AS) below what large
 *                     generated meshes need, builds them through the C API and must get
 *                     TOPOMESH_STATUS_OUT_OF_MEMORY, then build a small mesh fine; the
 *                     parent checks the child's exit. Not under valgrind (its own
 *                     allocations and a capped address space do not mix).
 *   test_oom budget   small meshes refused by memory_limit_bytes, before allocating and
 *                     after the volume of a level-3 build was allocated (its boundary
 *                     surface then refused), then built fine: run under valgrind too, so
 *                     that a leak on the failure path fails the test. */
/* fork, setrlimit and sysconf under -std=c11. */
#define _POSIX_C_SOURCE 200809L

#include "check.h"

#if defined(__unix__)
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#define HAVE_FORK_ 1
#endif

/* An n by n grid of quads, two triangles each, over (n + 1)^2 vertices, on the heap (the
   caller frees). */
static uint32_t *new_grid(uint32_t n, size_t *n_triangles) {
    uint32_t *t = malloc(2 * (size_t)n * n * 3 * sizeof *t);
    *n_triangles = t ? grid_triangles(n, UINT32_MAX, t) : 0;
    return t;
}

/* An n^3 grid of cubes, six tetrahedra each (Kuhn), over (n + 1)^3 vertices. */
static uint32_t *cube_tetrahedra(uint32_t n, size_t *n_tets) {
    *n_tets = 6 * (size_t)n * n * n;
    uint32_t *t = malloc(*n_tets * 4 * sizeof *t);
    if (!t) return NULL;
    static const uint32_t paths[6][2] = {{1, 2}, {2, 1}, {1, 4}, {4, 1}, {2, 4}, {4, 2}};
    size_t k = 0;
    for (uint32_t z = 0; z < n; z++) {
        for (uint32_t y = 0; y < n; y++) {
            for (uint32_t x = 0; x < n; x++) {
                uint32_t c[8];
                for (uint32_t b = 0; b < 8; b++) {
                    c[b] = ((z + (b >> 2)) * (n + 1) + y + (b >> 1 & 1)) * (n + 1) + x + (b & 1);
                }
                for (int p = 0; p < 6; p++) {
                    uint32_t tet[4] = {c[0], c[paths[p][0]], c[paths[p][0] | paths[p][1]], c[7]};
                    memcpy(t + k, tet, sizeof tet);
                    k += 4;
                }
            }
        }
    }
    return t;
}

/* A small grid still builds, at every level, after a failure. */
static void small_builds_fine(const che_build_options *o) {
    size_t nt = 0;
    uint32_t *tris = new_grid(4, &nt);
    CHECK(tris != NULL);
    if (!tris) return;
    for (uint32_t level = 0; level <= 3; level++) {
        che_build_options ol = *o;
        ol.level = level;
        che_mesh *m = NULL;
        CHECK_OK(che_mesh_from_triangles_ex(tris, nt, 25, NULL, &ol, &m));
        CHECK(m != NULL && che_mesh_num_triangles(m) == nt);
        che_mesh_free(m);
    }
    free(tris);
}

#ifdef HAVE_FORK_
/* The child: everything past the cap must come back as a status. */
static int capped_child(void) {
    /* Generated before the cap: 4.5 million triangles (54 MB of ids), 3 million
       tetrahedra (48 MB); each build needs several times its input. */
    size_t nt = 0, ntets = 0;
    uint32_t *tris = new_grid(1500, &nt);
    uint32_t *tets = cube_tetrahedra(80, &ntets);
    if (!tris || !tets) return 3;
    FILE *f = fopen("/proc/self/statm", "r");
    unsigned long pages = 0;
    if (!f || fscanf(f, "%lu", &pages) != 1) return 3;
    fclose(f);
    /* The address space in use plus 160 MiB: the builds need more, the small one less. */
    rlim_t cap = (rlim_t)pages * (rlim_t)sysconf(_SC_PAGESIZE) + ((rlim_t)160 << 20);
    struct rlimit rl = {cap, cap};
    if (setrlimit(RLIMIT_AS, &rl) != 0) return 3;

    che_build_options o = che_build_options_default();
    for (uint32_t threads = 0; threads <= 1; threads++) {
        o.threads = threads;
        che_mesh *m = (che_mesh *)&o;
        CHECK_STATUS(che_mesh_from_triangles_ex(tris, nt, 1501 * 1501, NULL, &o, &m),
                     TOPOMESH_STATUS_OUT_OF_MEMORY);
        CHECK(m == NULL);
        CHECK_DETAIL("out of memory: ");
    }
    chf_build_options v = chf_build_options_default();
    chf_mesh *c = (chf_mesh *)&v;
    CHECK_STATUS(chf_mesh_from_tetrahedra_ex(tets, ntets, 81 * 81 * 81, NULL, &v, &c),
                 TOPOMESH_STATUS_OUT_OF_MEMORY);
    CHECK(c == NULL);
    CHECK_DETAIL("out of memory: ");
    free(tris);
    free(tets);
    small_builds_fine(&o);
    return finish("test_oom rlimit (child)");
}

static void rlimit_test(void) {
    fflush(NULL);
    pid_t pid = fork();
    CHECK(pid >= 0);
    if (pid == 0) _exit(capped_child());
    int status = 0;
    CHECK(waitpid(pid, &status, 0) == pid);
    CHECK(WIFEXITED(status));
    if (WIFSIGNALED(status)) fprintf(stderr, "child killed by signal %d\n", WTERMSIG(status));
    CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}
#else
static void rlimit_test(void) { printf("test_oom rlimit: no fork here, skipped\n"); }
#endif

/* The budget: refused before allocating, and after the volume of a level-3 build. */
static void budget_test(void) {
    size_t nt = 0;
    uint32_t *tris = new_grid(30, &nt);
    CHECK(tris != NULL);
    if (!tris) return;
    che_build_options o = che_build_options_default();
    o.memory_limit_bytes = 1000;
    che_mesh *m = NULL;
    CHECK_STATUS(che_mesh_from_triangles_ex(tris, nt, 31 * 31, NULL, &o, &m),
                 TOPOMESH_STATUS_OUT_OF_MEMORY);
    CHECK(m == NULL);
    CHECK_DETAIL("1800 triangles at level 2 needs an estimated");
    CHECK_DETAIL("over the limit of 1000 B");
    o.memory_limit_bytes = 64u << 20;
    CHECK_OK(che_mesh_from_triangles_ex(tris, nt, 31 * 31, NULL, &o, &m));
    che_mesh_free(m);
    free(tris);

    /* A limit the volume fits in but not its boundary surface as well: the level-3
       build fails after allocating the volume, which it must free. */
    size_t ntets = 0;
    uint32_t *tets = cube_tetrahedra(3, &ntets);
    CHECK(tets != NULL);
    if (!tets) return;
    chf_build_options v = chf_build_options_default();
    int found = 0;
    for (uint64_t limit = 1024; limit < (64u << 20) && !found; limit += limit / 8) {
        v.memory_limit_bytes = limit;
        chf_mesh *c = NULL;
        v.level = 2;
        if (chf_mesh_from_tetrahedra_ex(tets, ntets, 64, NULL, &v, &c) != TOPOMESH_STATUS_OK) {
            continue;
        }
        chf_mesh_free(c);
        v.level = 3;
        topomesh_status s = chf_mesh_from_tetrahedra_ex(tets, ntets, 64, NULL, &v, &c);
        if (s == TOPOMESH_STATUS_OUT_OF_MEMORY) {
            found = 1;
            CHECK(c == NULL);
            CHECK_DETAIL("a CHE build of 108 triangles at level 3");
        }
        chf_mesh_free(c);
    }
    CHECK(found);
    v.memory_limit_bytes = 0;
    chf_mesh *c = NULL;
    CHECK_OK(chf_mesh_from_tetrahedra_ex(tets, ntets, 64, NULL, &v, &c));
    chf_mesh_free(c);
    free(tets);
    small_builds_fine(&o);
}

int main(int argc, char **argv) {
    const test_part parts[] = {{"rlimit", rlimit_test}, {"budget", budget_test}};
    return parts_main(argc, argv, "", "test_oom rlimit|budget", parts, 2);
}
