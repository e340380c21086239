/* che_mesh_save / che_mesh_open and chf_mesh_save / chf_mesh_open: a built structure saved
   and opened again has the same level, counts and arrays; a damaged file, a file of the
   other kind, unknown flags and NULL arguments give a status. Runs in a scratch folder. */
#define _POSIX_C_SOURCE 200809L
#include "check.h"
#include "chf_fixtures.h"
#include <unistd.h>

/* A square of two triangles, the second flipped; a triangle pinched at vertex 0 (split
   once built); a degenerate triangle (dropped). */
static const uint32_t TRIS[] = {0, 1, 2, 1, 2, 3, 0, 4, 5, 1, 1, 2};
static const double POS[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, -1, 0, 0, -1, -0.1, 1.0 / 3};

/* View `f` of meshes `a` and `b` holds the same `size`-byte elements. */
#define SAME_ARRAY(f, size)                                                                \
    do {                                                                                   \
        size_t na_ = 0, nb_ = 0;                                                           \
        const void *xa_ = f(a, &na_);                                                      \
        const void *xb_ = f(b, &nb_);                                                      \
        CHECK(na_ == nb_ && na_ > 0 && xa_ != NULL && xb_ != NULL);                        \
        if (xa_ && xb_ && na_ == nb_) CHECK(memcmp(xa_, xb_, na_ * (size)) == 0);          \
    } while (0)

/* The offset of the first section: the offset field of the first table entry. */
static long first_section(const char *path) {
    unsigned char b[8] = {0};
    FILE *f = fopen(path, "rb");
    CHECK(f != NULL);
    if (!f) return 0;
    CHECK(fseek(f, 64 + 40, SEEK_SET) == 0 && fread(b, 1, 8, f) == 8);
    fclose(f);
    long at = 0;
    for (int i = 7; i >= 0; --i) at = at * 256 + b[i];
    return at;
}

/* Flips one byte at `offset` of `path`. */
static void flip_byte(const char *path, long offset) {
    FILE *f = fopen(path, "r+b");
    CHECK(f != NULL);
    if (!f) return;
    CHECK(fseek(f, offset, SEEK_SET) == 0);
    int c = fgetc(f);
    CHECK(c != EOF);
    CHECK(fseek(f, offset, SEEK_SET) == 0);
    fputc(c ^ 0xff, f);
    fclose(f);
}

static void test_surface(void) {
    che_mesh *a = NULL, *b = NULL;
    CHECK_OK(che_mesh_from_triangles(TRIS, 4, 6, POS, 3, &a));
    if (!a) return;
    CHECK_OK(che_mesh_save(a, "s.che"));
    const uint32_t flags[] = {0, TOPOMESH_OPEN_CHECKSUMS_ONLY, TOPOMESH_OPEN_TRUSTED};
    for (size_t i = 0; i < 3; ++i) {
        b = NULL;
        CHECK_OK(che_mesh_open("s.che", flags[i], &b));
        if (!b) continue;
        CHECK(che_mesh_level(b) == 3);
        CHECK(che_mesh_num_vertices(b) == che_mesh_num_vertices(a));
        CHECK(che_mesh_num_edges(b) == che_mesh_num_edges(a));
        SAME_ARRAY(che_mesh_half_edge_vertices, 4);
        SAME_ARRAY(che_mesh_opposites, 4);
        SAME_ARRAY(che_mesh_positions, 8);
        SAME_ARRAY(che_mesh_edge_half_edges, 4);
        che_build_report ra, rb;
        CHECK_OK(che_mesh_report(a, &ra));
        CHECK_OK(che_mesh_report(b, &rb));
        CHECK(memcmp(&ra, &rb, sizeof ra) == 0);
        CHECK_OK(che_mesh_validate(b));
        che_mesh_free(b);
    }
    /* The errors. */
    CHECK_STATUS(che_mesh_save(NULL, "n.che"), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_mesh_save(a, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_mesh_save(a, "no-such-folder/s.che"), TOPOMESH_STATUS_IO);
    CHECK_DETAIL("no-such-folder/s.che");
    b = (che_mesh *)1;
    CHECK_STATUS(che_mesh_open("missing.che", 0, &b), TOPOMESH_STATUS_IO);
    CHECK(b == NULL);
    CHECK_STATUS(che_mesh_open(NULL, 0, &b), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_mesh_open("s.che", 0, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(che_mesh_open("s.che", 4, &b), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("unknown bits 0x4");
    chf_mesh *v = (chf_mesh *)1;
    CHECK_STATUS(chf_mesh_open("s.che", 0, &v), TOPOMESH_STATUS_PARSE);
    CHECK(v == NULL);
    CHECK_DETAIL("expected a CHF file");
    /* A flipped byte in the first section (after the header and table): its checksum. */
    flip_byte("s.che", first_section("s.che"));
    CHECK_STATUS(che_mesh_open("s.che", 0, &b), TOPOMESH_STATUS_PARSE);
    CHECK_DETAIL("checksum");
    CHECK(b == NULL);
    /* A flipped magic byte, even when trusted. */
    CHECK_OK(che_mesh_save(a, "s.che"));
    flip_byte("s.che", 0);
    CHECK_STATUS(che_mesh_open("s.che", TOPOMESH_OPEN_TRUSTED, &b), TOPOMESH_STATUS_PARSE);
    CHECK_DETAIL("byte 0");
    che_mesh_free(a);
}

static void test_volume(void) {
    chf_mesh *a = make_chf(CUBE, NTET(CUBE), 8, CUBE_POS, 3), *b = NULL;
    if (!a) return;
    CHECK_OK(chf_mesh_save(a, "v.chf"));
    CHECK_OK(chf_mesh_open("v.chf", 0, &b));
    if (b) {
        CHECK(chf_mesh_level(b) == 3);
        CHECK(chf_mesh_num_faces(b) == chf_mesh_num_faces(a));
        SAME_ARRAY(chf_mesh_half_face_vertices, 4);
        SAME_ARRAY(chf_mesh_opposites, 4);
        SAME_ARRAY(chf_mesh_face_half_faces, 4);
        SAME_ARRAY(chf_mesh_positions, 8);
        CHECK_OK(chf_mesh_validate(b));
        chf_mesh_free(b);
    }
    CHECK_STATUS(chf_mesh_save(NULL, "n.chf"), TOPOMESH_STATUS_NULL_ARGUMENT);
    che_mesh *s = NULL;
    CHECK_STATUS(che_mesh_open("v.chf", 0, &s), TOPOMESH_STATUS_PARSE);
    CHECK_DETAIL("expected a CHE file");
    /* A truncated file. */
    FILE *f = fopen("v.chf", "r+b");
    CHECK(f != NULL);
    if (f) {
        CHECK(ftruncate(fileno(f), 100) == 0);
        fclose(f);
    }
    CHECK_STATUS(chf_mesh_open("v.chf", 0, &b), TOPOMESH_STATUS_PARSE);
    CHECK(b == NULL);
    chf_mesh_free(a);
}

int main(void) {
    test_surface();
    test_volume();
    return finish("test_levelfile");
}
