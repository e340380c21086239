/* Repair a surface and save it: the build orients each component, so the file written holds
 * the repaired mesh, and reading it back finds nothing to repair. */
#include <topomesh/topomesh.h>
#include <stdio.h>

static int failed(topomesh_status s) {
    char detail[256];
    size_t len = 0;
    topomesh_last_error(detail, sizeof detail, &len);
    fprintf(stderr, "%s: %s\n", topomesh_status_str(s), detail);
    return 1;
}

int main(void) {
    /* A tetrahedron's surface whose last triangle is reversed. */
    const uint32_t triangles[] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 2, 3};
    const double positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    che_mesh *m = NULL, *back = NULL;
    topomesh_status s = che_mesh_from_triangles(triangles, 4, 4, positions, 2, &m);
    if (s == TOPOMESH_STATUS_OK) s = che_mesh_write(m, "repaired.off", 0);
    if (s == TOPOMESH_STATUS_OK) s = che_mesh_load("repaired.off", 2, &back);
    if (s != TOPOMESH_STATUS_OK) {
        che_mesh_free(m);
        return failed(s);
    }
    che_build_report before, after;
    che_mesh_report(m, &before);
    che_mesh_report(back, &after);
    printf("flipped %llu triangle(s); repaired.off: flipped %llu\n",
           (unsigned long long)before.flipped_triangles,
           (unsigned long long)after.flipped_triangles);
    che_mesh_free(back);
    che_mesh_free(m);
    return 0;
}
