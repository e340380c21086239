/* Built by the pkg-config test with `cc pkgconfig_check.c $(pkg-config --cflags --libs topomesh)`. */
#include <topomesh/topomesh.h>
#include <stdio.h>

int main(void) {
    const uint32_t tri[] = {0, 1, 2};
    che_mesh *m = NULL;
    if (che_mesh_from_triangles(tri, 1, 3, NULL, 2, &m) != TOPOMESH_STATUS_OK) return 1;
    size_t e = che_mesh_num_edges(m);
    che_mesh_free(m);
    printf("topomesh %s via pkg-config: %zu edges\n", topomesh_version(), e);
    return e == 3 ? 0 : 1;
}
