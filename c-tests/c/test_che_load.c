/* che_mesh_load and che_mesh_load_ex.
   `test_che_load args`: argument errors, independent of the file readers.
   `test_che_load readers`: needs the OFF and Medit readers (src/io). */
#include "check.h"

ANY_LOADER(LOADER, che_mesh, che_mesh_load, che_mesh_load_ex, che_mesh_positions,
           che_mesh_half_edge_vertices, ".off");

static void test_args(void) { check_load_args(&LOADER, "not-a-mesh.xyz"); }

static const char *TETRA_OFF = "OFF\n"
                               "# the surface of a tetrahedron\n"
                               "4 4 6\n"
                               "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                               "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

static void test_readers(void) {
    /* Success. */
    write_file("tetra.off", TETRA_OFF);
    che_mesh *m = NULL;
    CHECK_OK(che_mesh_load("tetra.off", 3, &m));
    if (m) {
        CHECK(che_mesh_level(m) == 3);
        CHECK(che_mesh_num_vertices(m) == 4 && che_mesh_num_triangles(m) == 4);
        CHECK(che_mesh_num_edges(m) == 6);
        CHECK_LOADED_ARRAYS(&LOADER, m, TETRA_POS, TETRA);
        che_summary s;
        CHECK_OK(che_mesh_summary(m, &s));
        CHECK(s.genus == 0 && s.euler_characteristic == 2 && s.manifold && s.orientable);
        CHECK(che_mesh_num_warnings(m) == 0);
        che_mesh_free(m);
    }

    /* The reader's warnings: a face line after the declared one. */
    write_file("extra-face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n");
    m = NULL;
    CHECK_OK(che_mesh_load("extra-face.off", 2, &m));
    if (m) {
        const char *want = "extra-face.off:7: 1 face line after the 1 declared (ignored)";
        char w[256];
        size_t wl = 0;
        CHECK(che_mesh_num_warnings(m) == 1 && che_mesh_num_triangles(m) == 1);
        CHECK_OK(che_mesh_warning(m, 0, NULL, 0, &wl));
        CHECK(wl == strlen(want) + 1);
        CHECK_OK(che_mesh_warning(m, 0, w, sizeof w, &wl));
        CHECK(strcmp(w, want) == 0);
        CHECK_STATUS(che_mesh_warning(m, 0, w, 4, &wl), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
        CHECK(strcmp(w, "ext") == 0);
        CHECK_STATUS(che_mesh_warning(m, 1, w, sizeof w, &wl), TOPOMESH_STATUS_OUT_OF_RANGE);
        CHECK_STATUS(che_mesh_warning(NULL, 0, w, sizeof w, &wl), TOPOMESH_STATUS_NULL_ARGUMENT);
        che_mesh_free(m);
    }

    che_build_options o = {1, true, 0, 0, 0.0};
    m = NULL;
    CHECK_OK(che_mesh_load_ex("tetra.off", &o, &m));
    CHECK(m != NULL && che_mesh_level(m) == 1);
    che_mesh_free(m);

    /* A missing file, a malformed one (the detail names the file and the line), an index
       out of range. */
    const bad_files bad = {"does-not-exist.off", "malformed.off",
                           "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1\n3 0 1 2\n", "bad-index.off",
                           "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"};
    check_load_file_errors(&LOADER, &bad);

    /* Strict mode on a file with a non-manifold vertex. */
    write_file("bowtie.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n"
                             "3 0 1 2\n3 0 3 4\n");
    o.strict = true;
    CHECK_STATUS(che_mesh_load_ex("bowtie.off", &o, &m), TOPOMESH_STATUS_NON_MANIFOLD);
    CHECK(m == NULL);
    o.strict = false;
    CHECK_OK(che_mesh_load_ex("bowtie.off", &o, &m));
    CHECK(che_mesh_num_vertices(m) == 6);
    che_mesh_free(m);

    /* A volume file is not a surface. */
    write_file("tet.mesh", "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n"
                           "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                           "Tetrahedra\n1\n1 2 3 4 0\nEnd\n");
    CHECK_LOAD_FAILS(m, che_mesh_load("tet.mesh", 2, &m),
                     TOPOMESH_STATUS_INVALID_INPUT, "tetrahedra");
}

int main(int argc, char **argv) {
    return load_test_main(argc, argv, "test_che_load", test_args, test_readers);
}
