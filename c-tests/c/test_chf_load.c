/* chf_mesh_load and chf_mesh_load_ex.
   `test_chf_load args`: argument errors, independent of the file readers.
   `test_chf_load readers`: needs the Medit, TetGen and OFF readers (src/io). */
#include "chf_fixtures.h"

ANY_LOADER(LOADER, chf_mesh, chf_mesh_load, chf_mesh_load_ex, chf_mesh_positions,
           chf_mesh_half_face_vertices, ".mesh");

static void test_args(void) {
    check_load_args(&LOADER, "chf-not-a-volume.xyz");
    chf_mesh *m = NULL;
    chf_build_options o = {9, false, 0, 0, 0.0};
    CHECK_STATUS(chf_mesh_load_ex("x.mesh", &o, &m), TOPOMESH_STATUS_OUT_OF_RANGE);
}

/* PAIR in Medit (1-based), with its boundary triangles too (ignored by chf_mesh_load). */
static const char *PAIR_MESH = "MeshVersionFormatted 1\nDimension 3\nVertices\n5\n"
                               "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n"
                               "Triangles\n2\n1 2 3 0\n1 3 4 0\n"
                               "Tetrahedra\n2\n1 2 3 4 0\n5 2 4 3 0\nEnd\n";

/* BOOK: three tetrahedra on one face. */
static const char *BOOK_MESH = "MeshVersionFormatted 1\nDimension 3\nVertices\n6\n"
                               "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 -1 0\n1 1 1 0\n"
                               "Tetrahedra\n3\n1 2 3 4 0\n1 2 3 5 0\n1 2 3 6 0\nEnd\n";

static void test_readers(void) {
    /* Success, at every level; triangles in the file are not tetrahedra. */
    write_file("chf-pair.mesh", PAIR_MESH);
    for (uint32_t level = 0; level <= 3; level++) {
        chf_mesh *m = NULL;
        CHECK_OK(chf_mesh_load("chf-pair.mesh", level, &m));
        if (!m) continue;
        CHECK(chf_mesh_level(m) == level);
        CHECK(chf_mesh_num_vertices(m) == 5 && chf_mesh_num_tetrahedra(m) == 2);
        CHECK(chf_mesh_num_faces(m) == 7 && chf_mesh_num_edges(m) == 9);
        CHECK_LOADED_ARRAYS(&LOADER, m, PAIR_POS, PAIR);
        chf_summary s;
        CHECK_OK(chf_mesh_summary(m, &s));
        CHECK(s.euler_characteristic == 1 && s.boundary_faces == 6 && s.manifold);
        CHECK(s.flipped_tetrahedra == 0 && s.inverted_tetrahedra == 0);
        /* The reader's warning: the triangles are ignored. */
        char w[256];
        size_t wl = 0;
        CHECK(chf_mesh_num_warnings(m) == 1);
        CHECK_OK(chf_mesh_warning(m, 0, w, sizeof w, &wl));
        CHECK(strcmp(w, "chf-pair.mesh: 2 triangles beside the 2 tetrahedra ignored "
                        "(a volume is built from its tetrahedra)") == 0);
        CHECK(wl == strlen(w) + 1);
        CHECK_STATUS(chf_mesh_warning(m, 1, w, sizeof w, &wl), TOPOMESH_STATUS_OUT_OF_RANGE);
        chf_mesh_free(m);
    }
    chf_build_options o = {1, true, 0, 0, 0.0};
    chf_mesh *m = NULL;
    CHECK_OK(chf_mesh_load_ex("chf-pair.mesh", &o, &m));
    CHECK(m != NULL && chf_mesh_level(m) == 1);
    chf_mesh_free(m);
    m = NULL;
    CHECK_OK(chf_mesh_load_ex("chf-pair.mesh", NULL, &m));
    CHECK(m != NULL && chf_mesh_level(m) == 2);
    chf_mesh_free(m);

    /* TetGen .node + .ele (0-based here), by either path. */
    write_file("chf-pair.node", "5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 1 1 1\n");
    write_file("chf-pair.ele", "2 4 0\n0 0 1 2 3\n1 4 1 3 2\n");
    m = NULL;
    CHECK_OK(chf_mesh_load("chf-pair.ele", 2, &m));
    CHECK(m != NULL && chf_mesh_num_tetrahedra(m) == 2 && chf_mesh_num_faces(m) == 7);
    chf_mesh_free(m);
    m = NULL;
    CHECK_OK(chf_mesh_load("chf-pair.node", 3, &m));
    CHECK(m != NULL && chf_mesh_num_boundary_faces(m) == 6);
    chf_mesh_free(m);

    /* A missing file, a malformed one (the detail names the file), an index out of range. */
    const bad_files bad = {"chf-does-not-exist.mesh", "chf-malformed.mesh",
                           "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n"
                           "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                           "Tetrahedra\n1\n1 2 x 4 0\nEnd\n",
                           "chf-bad-index.mesh",
                           "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n"
                           "0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
                           "Tetrahedra\n1\n1 2 3 9 0\nEnd\n"};
    check_load_file_errors(&LOADER, &bad);

    /* A surface file is not a volume. */
    write_file("chf-tetra.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                            "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    CHECK_LOAD_FAILS(m, chf_mesh_load("chf-tetra.off", 2, &m),
                     TOPOMESH_STATUS_INVALID_INPUT, "chf-tetra.off");
    CHECK_DETAIL("no tetrahedra");
    /* ... nor is a Medit file with triangles only. */
    write_file("chf-surface.mesh", "MeshVersionFormatted 1\nDimension 3\nVertices\n3\n"
                               "0 0 0 0\n1 0 0 0\n0 1 0 0\nTriangles\n1\n1 2 3 0\nEnd\n");
    CHECK_STATUS(chf_mesh_load("chf-surface.mesh", 2, &m), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("1 triangles");

    /* Strict mode on a file with a non-manifold face. */
    write_file("chf-book.mesh", BOOK_MESH);
    o.strict = true;
    CHECK_LOAD_FAILS(m, chf_mesh_load_ex("chf-book.mesh", &o, &m),
                     TOPOMESH_STATUS_NON_MANIFOLD, "(0, 1, 2)");
    o.strict = false;
    CHECK_OK(chf_mesh_load_ex("chf-book.mesh", &o, &m));
    chf_summary s;
    CHECK_OK(chf_mesh_summary(m, &s));
    CHECK(s.non_manifold_faces == 1 && !s.manifold);
    chf_mesh_free(m);
}

int main(int argc, char **argv) {
    return load_test_main(argc, argv, "test_chf_load", test_args, test_readers);
}
