/* Build a surface from arrays, ask for relations three ways, read its topology. */
#include <topomesh/topomesh.h>
#include <stdio.h>

int main(void) {
    /* The unit square cut along its diagonal 1-2: two triangles, counter-clockwise. */
    const uint32_t triangles[] = {0, 1, 2, 1, 3, 2};
    const double positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    che_mesh *m = NULL;
    topomesh_status s = che_mesh_from_triangles(triangles, 2, 4, positions, 2, &m);
    if (s != TOPOMESH_STATUS_OK) {
        char detail[256];
        size_t len = 0;
        topomesh_last_error(detail, sizeof detail, &len);
        fprintf(stderr, "%s: %s\n", topomesh_status_str(s), detail);
        return 1;
    }

    /* 1. Into a caller buffer (a NULL buffer with cap 0 asks for the size). */
    uint32_t ring[16];
    size_t n = 0;
    if (che_vertex_vertices(m, 1, ring, 16, &n) == TOPOMESH_STATUS_OK) {
        printf("around vertex 1:");
        for (size_t i = 0; i < n; i++) printf(" %u", ring[i]);
        printf("\n");
    }

    /* 2. With the star iterator, on the stack: no allocation. */
    che_star_iter it;
    che_star_step step;
    if (che_star_begin(m, 2, &it) == TOPOMESH_STATUS_OK)
        while (che_star_next(&it, &step))
            printf("vertex 2 -> %u (edge %u)%s\n", step.vertex, step.edge,
                   step.triangle == TOPOMESH_NONE ? " closes the boundary fan" : "");

    /* 3. Straight from the arrays, with the inline half-edge arithmetic. */
    size_t n_half_edges = 0;
    const uint32_t *V = che_mesh_half_edge_vertices(m, &n_half_edges);
    const uint32_t *O = che_mesh_opposites(m, NULL);
    for (uint32_t h = 0; h < n_half_edges; h++)
        if (O[h] == TOPOMESH_NONE) printf("boundary %u -> %u\n", V[h], V[che_next(h)]);

    che_summary sum;
    che_mesh_summary(m, &sum);
    printf("V=%llu E=%llu F=%llu euler=%lld genus=%lld boundary curves=%llu\n",
           (unsigned long long)sum.vertices, (unsigned long long)sum.edges,
           (unsigned long long)sum.triangles, (long long)sum.euler_characteristic,
           (long long)sum.genus, (unsigned long long)sum.boundary_curves);
    che_mesh_free(m);
    return 0;
}
