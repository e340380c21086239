/* che_mesh_write: the built surface written, loaded back, and the same structure; the
   flags; the errors (arguments, a mesh without positions, a format that holds no surface,
   a missing folder, a full device), each leaving no file. Runs in a scratch folder. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include <unistd.h>

/* A square of two triangles, the second flipped; a triangle pinched at vertex 0 (split
   once built); a degenerate triangle (dropped). */
static const uint32_t TRIS[] = {0, 1, 2, 1, 2, 3, 0, 4, 5, 1, 1, 2};
static const double POS[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, -1, 0, 0, -1, -0.1, 1.0 / 3};

static int exists(const char *path) { return access(path, F_OK) == 0; }

/* `a` and the mesh loaded from `path` have the same positions, V and pairing, and the
   loaded one needed no repair. */
static void check_same(const che_mesh *a, const char *path) {
    che_mesh *b = NULL;
    CHECK_OK(che_mesh_load(path, 2, &b));
    if (!b) return;
    size_t na = 0, nb = 0, pa = 0, pb = 0, oa = 0, ob = 0;
    const uint32_t *va = che_mesh_half_edge_vertices(a, &na);
    const uint32_t *vb = che_mesh_half_edge_vertices(b, &nb);
    CHECK(na == nb && na > 0 && memcmp(va, vb, na * sizeof *va) == 0);
    const double *xa = che_mesh_positions(a, &pa);
    const double *xb = che_mesh_positions(b, &pb);
    CHECK(pa == pb && pa > 0 && memcmp(xa, xb, pa * sizeof *xa) == 0);
    const uint32_t *ya = che_mesh_opposites(a, &oa);
    const uint32_t *yb = che_mesh_opposites(b, &ob);
    CHECK(oa == ob && oa > 0 && memcmp(ya, yb, oa * sizeof *ya) == 0);
    che_build_report r;
    CHECK_OK(che_mesh_report(b, &r));
    CHECK(r.flipped_triangles == 0 && r.split_vertices == 0 && r.dropped_degenerate == 0);
    che_mesh_free(b);
}

static void test_round_trips(const che_mesh *m) {
    che_build_report r;
    CHECK_OK(che_mesh_report(m, &r));
    CHECK(r.flipped_triangles == 1 && r.split_vertices == 1 && r.dropped_degenerate == 1);
    CHECK(che_mesh_num_vertices(m) == 7);
    const char *paths[] = {"w.off", "w.obj", "w.ply", "w.vtk", "w.mesh", "w.msh"};
    for (size_t i = 0; i < sizeof paths / sizeof *paths; ++i) {
        CHECK_OK(che_mesh_write(m, paths[i], 0));
        check_same(m, paths[i]);
    }
    CHECK_OK(che_mesh_write(m, "b.ply", TOPOMESH_WRITE_BINARY | TOPOMESH_WRITE_NO_ORIGIN));
    check_same(m, "b.ply");
    /* STL: binary, f32 corners, 84 + 50 bytes per triangle. */
    CHECK_OK(che_mesh_write(m, "w.stl", 0));
    FILE *f = fopen("w.stl", "rb");
    CHECK(f != NULL);
    if (f) {
        CHECK(fseek(f, 0, SEEK_END) == 0 && ftell(f) == 84 + 50 * 3);
        fclose(f);
    }
}

static void test_errors(const che_mesh *m) {
    CHECK_STATUS(che_mesh_write(NULL, "n.off", 0), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_mesh_write(m, NULL, 0), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("path");
    CHECK_STATUS(che_mesh_write(m, "flags.off", 4), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("unknown bits 0x4");
    CHECK_STATUS(che_mesh_write(m, "text.off", TOPOMESH_WRITE_BINARY),
                 TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("text only");
    CHECK_STATUS(che_mesh_write(m, "surface.node", 0), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("tetrahedra only");
    CHECK_STATUS(che_mesh_write(m, "unknown.xyz", 0), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_STATUS(che_mesh_write(m, "no-such-folder/m.off", 0), TOPOMESH_STATUS_IO);
    CHECK_DETAIL("no-such-folder/m.off");
    /* A link named .off to the full device: written in place, ENOSPC, nothing left. */
    unlink("full.off");
    if (symlink("/dev/full", "full.off") == 0) {
        CHECK_STATUS(che_mesh_write(m, "full.off", 0), TOPOMESH_STATUS_IO);
        CHECK_DETAIL("full.off");
        unlink("full.off");
    }
    CHECK(!exists("flags.off") && !exists("text.off") && !exists("surface.node"));
    CHECK(!exists("unknown.xyz") && !exists("n.off"));
    /* No positions: nothing to write. */
    che_mesh *bare = NULL;
    CHECK_OK(che_mesh_from_triangles(TRIS, 4, 6, NULL, 2, &bare));
    CHECK_STATUS(che_mesh_write(bare, "bare.off", 0), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("no positions");
    CHECK(!exists("bare.off"));
    che_mesh_free(bare);
}

int main(void) {
    che_mesh *m = NULL;
    CHECK_OK(che_mesh_from_triangles(TRIS, 4, 6, POS, 2, &m));
    if (m) {
        test_round_trips(m);
        test_errors(m);
        che_mesh_free(m);
    }
    return finish("test_che_write");
}
