/* The C consumer of the packaging tests: the version and one build through the C API. */
#include <topomesh/topomesh.h>

#include <stdio.h>

#if !defined(__STDC_VERSION__) || __STDC_VERSION__ < 199901L
#error "the topomesh targets must bring C99 (c_std_99)"
#endif

int main(void) {
    const uint32_t tris[] = {0, 1, 2, 0, 2, 3};
    che_mesh *m = NULL;
    if (che_mesh_from_triangles(tris, 2, 4, NULL, 2, &m) != TOPOMESH_STATUS_OK) return 1;
    printf("consumer_c: %s, %zu edges\n", topomesh_version(), che_mesh_num_edges(m));
    che_mesh_free(m);
    return 0;
}
