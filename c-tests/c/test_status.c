/* Status codes, their strings, the version and the thread-local last error. */
#include "check.h"
#include "chf_fixtures.h"

#include <stddef.h>

#include <pthread.h>

#ifndef TOPOMESH_EXPECTED_VERSION
#error "TOPOMESH_EXPECTED_VERSION must be defined by the build"
#endif

static void *fail_on_another_thread(void *arg) {
    char buf[256];
    size_t len = 0;
    (void)arg;
    /* A fresh thread has no detail yet. */
    if (topomesh_last_error(buf, sizeof buf, &len) != TOPOMESH_STATUS_OK || len != 1 || buf[0])
        return (void *)1;
    if (che_mesh_build_level(NULL, 1) != TOPOMESH_STATUS_NULL_ARGUMENT) return (void *)1;
    if (topomesh_last_error(buf, sizeof buf, &len) != TOPOMESH_STATUS_OK) return (void *)1;
    return strstr(buf, "'m'") ? NULL : (void *)1;
}

int main(void) {
    /* The values of the contract, in order. */
    CHECK(TOPOMESH_STATUS_OK == 0);
    CHECK(TOPOMESH_STATUS_NULL_ARGUMENT == 1);
    CHECK(TOPOMESH_STATUS_OUT_OF_RANGE == 2);
    CHECK(TOPOMESH_STATUS_INVALID_INPUT == 3);
    CHECK(TOPOMESH_STATUS_NON_MANIFOLD == 4);
    CHECK(TOPOMESH_STATUS_BUFFER_TOO_SMALL == 5);
    CHECK(TOPOMESH_STATUS_IO == 6);
    CHECK(TOPOMESH_STATUS_PARSE == 7);
    CHECK(TOPOMESH_STATUS_TOO_LARGE == 8);
    CHECK(TOPOMESH_STATUS_PANIC == 9);
    CHECK(TOPOMESH_STATUS_OUT_OF_MEMORY == 10);
    CHECK(sizeof(topomesh_status) == 4);
    CHECK(TOPOMESH_NONE == UINT32_MAX);

    /* Every status has a distinct, non-empty static string. */
    for (uint32_t s = 0; s <= TOPOMESH_STATUS_OUT_OF_MEMORY; s++) {
        const char *a = topomesh_status_str((topomesh_status)s);
        CHECK(a != NULL && a[0] != 0);
        for (uint32_t t = 0; t < s; t++) CHECK(strcmp(a, topomesh_status_str((topomesh_status)t)));
    }
    CHECK(strcmp(topomesh_status_str(TOPOMESH_STATUS_OK), "ok") == 0);
    /* Any other value is defined: "unknown status". */
    CHECK(strcmp(topomesh_status_str(TOPOMESH_STATUS_OUT_OF_MEMORY + 1), "unknown status") == 0);
    CHECK(strcmp(topomesh_status_str(UINT32_MAX), "unknown status") == 0);

    /* The version is the package's. */
    CHECK(strcmp(topomesh_version(), TOPOMESH_EXPECTED_VERSION) == 0);

    /* No failure yet on this thread: an empty detail. */
    char buf[256];
    size_t len = 99;
    CHECK_OK(topomesh_last_error(buf, sizeof buf, &len));
    CHECK(len == 1 && buf[0] == 0);

    /* A failure records its detail. */
    uint32_t ids[4];
    CHECK_STATUS(che_vertex_vertices(NULL, 0, ids, 4, &len), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_OK(topomesh_last_error(buf, sizeof buf, &len));
    CHECK(strstr(buf, "'m'") != NULL);
    CHECK(len == strlen(buf) + 1);
    size_t full = len;

    /* Size query. */
    len = 0;
    CHECK_OK(topomesh_last_error(NULL, 0, &len));
    CHECK(len == full);

    /* Too small: truncated, NUL-terminated, needed length reported. */
    char small[5];
    memset(small, 'x', sizeof small);
    len = 0;
    CHECK_STATUS(topomesh_last_error(small, sizeof small, &len), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(len == full);
    CHECK(small[4] == 0 && strlen(small) == 4 && strncmp(small, buf, 4) == 0);
    char one[1] = {'x'};
    CHECK_STATUS(topomesh_last_error(one, 1, &len), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(one[0] == 0 && len == full);
    CHECK_STATUS(topomesh_last_error(one, 0, &len), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(len == full);

    /* Its own misuse does not overwrite the detail. */
    CHECK_STATUS(topomesh_last_error(buf, sizeof buf, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(topomesh_last_error(NULL, 8, &len), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_OK(topomesh_last_error(buf, sizeof buf, &len));
    CHECK(len == full && strstr(buf, "'m'") != NULL);

    /* Success does not clear it. */
    che_mesh *m = make(TETRA, NTRI(TETRA), 4, NULL, 2);
    CHECK_OK(che_vertex_vertices(m, 0, ids, 4, &len));
    CHECK_OK(topomesh_last_error(buf, sizeof buf, &len));
    CHECK(strstr(buf, "'m'") != NULL);

    /* The detail of an out-of-range id names the id. */
    CHECK_STATUS(che_vertex_vertices(m, 77, ids, 4, &len), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_DETAIL("vertex 77");

    /* Thread-local: another thread's failure leaves this thread's detail alone. */
    pthread_t th;
    void *ret = (void *)1;
    CHECK(pthread_create(&th, NULL, fail_on_another_thread, NULL) == 0);
    CHECK(pthread_join(th, &ret) == 0);
    CHECK(ret == NULL);
    CHECK_DETAIL("vertex 77");

    che_mesh_free(m);

    /* Option flags are bytes where any non-zero value is true: strict = 2 is strict. */
    CHECK(sizeof(che_build_options) == 32 && sizeof(chf_build_options) == 32);
    CHECK(offsetof(che_build_options, strict) == 4 && offsetof(chf_build_options, threads) == 8);
    che_build_options o = che_build_options_default();
    o.strict = 2;
    m = NULL;
    CHECK_STATUS(che_mesh_from_triangles_ex(BOWTIE, 2, 5, NULL, &o, &m),
                 TOPOMESH_STATUS_NON_MANIFOLD);
    CHECK(m == NULL);
    o.strict = 0;
    CHECK_OK(che_mesh_from_triangles_ex(BOWTIE, 2, 5, NULL, &o, &m));
    che_mesh_free(m);
    chf_build_options vo = chf_build_options_default();
    vo.strict = 0xff;
    chf_mesh *v = NULL;
    CHECK_STATUS(chf_mesh_from_tetrahedra_ex(SPLIT, 2, 7, NULL, &vo, &v),
                 TOPOMESH_STATUS_NON_MANIFOLD);
    CHECK(v == NULL);
    return finish("test_status");
}
