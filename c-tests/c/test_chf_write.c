/* chf_mesh_write and chf_mesh_write_boundary: the built volume and its boundary surface
   written, loaded back, and the same structures; the flags and the errors, each leaving no
   file. Runs in a scratch folder. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include <unistd.h>

/* Two tetrahedra on the face (1, 2, 3), the second inverted (flipped once built), and a
   degenerate one (dropped). */
static const uint32_t TETS[] = {0, 1, 2, 3, 1, 3, 2, 4, 0, 0, 1, 2};
static const double POS[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1.0 / 3, 1, 0.1};

static int exists(const char *path) { return access(path, F_OK) == 0; }

static void check_same_volume(const chf_mesh *a, const char *path) {
    chf_mesh *b = NULL;
    CHECK_OK(chf_mesh_load(path, 2, &b));
    if (!b) return;
    size_t na = 0, nb = 0, pa = 0, pb = 0;
    const uint32_t *va = chf_mesh_half_face_vertices(a, &na);
    const uint32_t *vb = chf_mesh_half_face_vertices(b, &nb);
    CHECK(na == nb && na == 8 && memcmp(va, vb, na * sizeof *va) == 0);
    const double *xa = chf_mesh_positions(a, &pa);
    const double *xb = chf_mesh_positions(b, &pb);
    CHECK(pa == pb && pa == 15 && memcmp(xa, xb, pa * sizeof *xa) == 0);
    chf_build_report r;
    CHECK_OK(chf_mesh_report(b, &r));
    CHECK(r.flipped_tetrahedra == 0 && r.dropped_degenerate == 0);
    chf_mesh_free(b);
}

/* The boundary written to `path` loads as the surface chf_mesh_boundary gives. */
static void check_same_boundary(const chf_mesh *a, const char *path) {
    che_mesh *want = NULL, *got = NULL;
    CHECK_OK(chf_mesh_boundary(a, &want));
    CHECK_OK(che_mesh_load(path, 3, &got));
    if (want && got) {
        size_t nw = 0, ng = 0;
        const uint32_t *vw = che_mesh_half_edge_vertices(want, &nw);
        const uint32_t *vg = che_mesh_half_edge_vertices(got, &ng);
        CHECK(nw == ng && nw == 18 && memcmp(vw, vg, nw * sizeof *vw) == 0);
        CHECK(che_mesh_num_vertices(got) == 5);
    }
    che_mesh_free(want);
    che_mesh_free(got);
}

static void test_round_trips(const chf_mesh *m) {
    chf_build_report r;
    CHECK_OK(chf_mesh_report(m, &r));
    CHECK(r.flipped_tetrahedra == 1 && r.dropped_degenerate == 1);
    const char *paths[] = {"w.mesh", "w.msh", "w.vtk", "w.node"};
    for (size_t i = 0; i < sizeof paths / sizeof *paths; ++i) {
        CHECK_OK(chf_mesh_write(m, paths[i], 0));
        check_same_volume(m, paths[i]);
    }
    CHECK(exists("w.ele"));
    CHECK_OK(chf_mesh_write(m, "o.mesh", TOPOMESH_WRITE_NO_ORIGIN));
    check_same_volume(m, "o.mesh");
    CHECK_OK(chf_mesh_write_boundary(m, "skin.off", 0));
    check_same_boundary(m, "skin.off");
    CHECK_OK(chf_mesh_write_boundary(m, "skin.ply", TOPOMESH_WRITE_BINARY));
    check_same_boundary(m, "skin.ply");
}

static void test_errors(const chf_mesh *m) {
    CHECK_STATUS(chf_mesh_write(NULL, "n.mesh", 0), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_mesh_write(m, NULL, 0), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_mesh_write_boundary(NULL, "n.off", 0), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_mesh_write_boundary(m, NULL, 0), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(chf_mesh_write(m, "flags.mesh", 8), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("unknown bits 0x8");
    CHECK_STATUS(chf_mesh_write_boundary(m, "flags.off", 1u << 31),
                 TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_STATUS(chf_mesh_write(m, "binary.mesh", TOPOMESH_WRITE_BINARY),
                 TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_STATUS(chf_mesh_write(m, "volume.off", 0), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("surfaces only");
    CHECK_STATUS(chf_mesh_write_boundary(m, "skin.node", 0), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_STATUS(chf_mesh_write(m, "no-such-folder/m.mesh", 0), TOPOMESH_STATUS_IO);
    CHECK_DETAIL("no-such-folder/m.mesh");
    CHECK_STATUS(chf_mesh_write_boundary(m, "no-such-folder/s.off", 0), TOPOMESH_STATUS_IO);
    CHECK_DETAIL("no-such-folder/s.off");
    CHECK(!exists("n.mesh") && !exists("flags.mesh") && !exists("flags.off"));
    CHECK(!exists("binary.mesh") && !exists("volume.off") && !exists("skin.node"));
    chf_mesh *bare = NULL;
    CHECK_OK(chf_mesh_from_tetrahedra(TETS, 3, 5, NULL, 2, &bare));
    CHECK_STATUS(chf_mesh_write(bare, "bare.mesh", 0), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("no positions");
    CHECK_STATUS(chf_mesh_write_boundary(bare, "bare.off", 0), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK(!exists("bare.mesh") && !exists("bare.off"));
    chf_mesh_free(bare);
}

int main(void) {
    chf_mesh *m = NULL;
    CHECK_OK(chf_mesh_from_tetrahedra(TETS, 3, 5, POS, 1, &m));
    if (m) {
        test_round_trips(m);
        test_errors(m);
        chf_mesh_free(m);
    }
    return finish("test_chf_write");
}
