/* che_mesh_save / che_mesh_open and chf_mesh_save / chf_mesh_open: a built structure saved
   and opened again (loaded or mapped) has the same level, counts and arrays; a damaged file
   (truncated, a byte flipped, a wrong version or endianness, counts that do not match the
   file, ids pointing outside), a file of the other kind, unknown flags and NULL arguments
   give a status in both modes, and queries on a damaged trusted file give a status, never
   a crash. Runs in a scratch folder. */
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
    const uint32_t flags[] = {0,
                              TOPOMESH_OPEN_CHECKSUMS_ONLY,
                              TOPOMESH_OPEN_TRUSTED,
                              TOPOMESH_OPEN_MAPPED,
                              TOPOMESH_OPEN_MAPPED | TOPOMESH_OPEN_CHECKSUMS_ONLY,
                              TOPOMESH_OPEN_MAPPED | TOPOMESH_OPEN_TRUSTED};
    for (size_t i = 0; i < sizeof flags / sizeof flags[0]; ++i) {
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
    CHECK_STATUS(che_mesh_open("s.che", 8, &b), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_DETAIL("unknown bits 0x8");
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
    for (int mapped = 0; mapped < 2; ++mapped) {
        b = NULL;
        CHECK_OK(chf_mesh_open("v.chf", mapped ? TOPOMESH_OPEN_MAPPED : 0, &b));
        if (!b) continue;
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

/* ---- Bad files, byte by byte ---- */

/* CRC-32 (IEEE, reflected), as the level files use it: to re-seal an edited file so that
   the damage reaches the checks behind the checksums. */
static uint32_t crc32_of(const unsigned char *b, size_t n) {
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < n; ++i) {
        c ^= b[i];
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1)));
    }
    return ~c;
}

static uint64_t le64(const unsigned char *b) {
    uint64_t x = 0;
    for (int i = 7; i >= 0; --i) x = x * 256 + b[i];
    return x;
}

static void put32(unsigned char *b, uint32_t x) {
    for (int i = 0; i < 4; ++i) b[i] = (unsigned char)(x >> (8 * i));
}

static void put64(unsigned char *b, uint64_t x) {
    for (int i = 0; i < 8; ++i) b[i] = (unsigned char)(x >> (8 * i));
}

typedef struct {
    unsigned char *b;
    size_t n;
} bytes;

static bytes read_all(const char *path) {
    bytes out = {NULL, 0};
    FILE *f = fopen(path, "rb");
    CHECK(f != NULL);
    if (!f) return out;
    fseek(f, 0, SEEK_END);
    out.n = (size_t)ftell(f);
    fseek(f, 0, SEEK_SET);
    out.b = malloc(out.n);
    CHECK(out.b != NULL && fread(out.b, 1, out.n, f) == out.n);
    fclose(f);
    return out;
}

static void write_all(const char *path, const unsigned char *b, size_t n) {
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return;
    CHECK(fwrite(b, 1, n, f) == n);
    fclose(f);
}

static bytes copy_of(bytes good) {
    bytes out = {malloc(good.n), good.n};
    CHECK(out.b != NULL);
    if (out.b) memcpy(out.b, good.b, good.n);
    return out;
}

/* The table entry of section `name` (its offset in the file), or 0. */
static size_t entry_of(bytes f, const char *name) {
    uint32_t n = (uint32_t)le64(f.b + 28) & 0xffffffffu;
    for (size_t i = 0; i < n; ++i) {
        size_t at = 64 + 64 * i;
        if (strncmp((const char *)f.b + at, name, 32) == 0) return at;
    }
    CHECK(!"section found");
    return 0;
}

/* Recomputes the checksums of the section at table entry `e` and of the table. */
static void reseal(bytes f, size_t e) {
    uint64_t offset = le64(f.b + e + 40), count = le64(f.b + e + 48);
    uint32_t elem = (uint32_t)le64(f.b + e + 32) & 0xffffffffu;
    size_t len = (size_t)count * (elem == 1 ? 4 : 8);
    if (offset + len <= f.n) put32(f.b + e + 36, crc32_of(f.b + offset, len));
    uint32_t n = (uint32_t)le64(f.b + 28) & 0xffffffffu;
    unsigned char *both = malloc(40 + 64 * (size_t)n);
    CHECK(both != NULL);
    if (!both) return;
    memcpy(both, f.b, 40);
    memcpy(both + 40, f.b + 64, 64 * (size_t)n);
    put32(f.b + 40, crc32_of(both, 40 + 64 * (size_t)n));
    free(both);
}

/* Opens `f` as a CHE with `flags`: the status, and `*out` (NULL on failure). */
static topomesh_status open_che_bytes(bytes f, uint32_t flags, che_mesh **out) {
    write_all("bad.che", f.b, f.n);
    *out = (che_mesh *)1;
    topomesh_status s = che_mesh_open("bad.che", flags, out);
    if (s != TOPOMESH_STATUS_OK) CHECK(*out == NULL);
    return s;
}

/* Expects `f` refused with `status` and `detail`, checked and trusted. */
static void refused(bytes f, uint32_t mode, topomesh_status status, const char *detail) {
    che_mesh *m = NULL;
    CHECK_STATUS(open_che_bytes(f, mode, &m), status);
    CHECK_DETAIL(detail);
    CHECK_STATUS(open_che_bytes(f, mode | TOPOMESH_OPEN_TRUSTED, &m), status);
    CHECK_DETAIL(detail);
}

/* Every query on `m` (a trusted, damaged file) gives a status: an answer (possibly wrong),
   or TOPOMESH_STATUS_PANIC when an id points outside an array. Never a crash. */
static void queries_give_a_status(const che_mesh *m) {
    uint32_t buf[64];
    size_t len = 0;
    size_t nv = che_mesh_num_vertices(m), nt = che_mesh_num_triangles(m);
    for (uint32_t v = 0; v < nv; ++v) {
        topomesh_status s = che_vertex_vertices(m, v, buf, 64, &len);
        CHECK(s == TOPOMESH_STATUS_OK || s == TOPOMESH_STATUS_PANIC ||
              s == TOPOMESH_STATUS_BUFFER_TOO_SMALL || s == TOPOMESH_STATUS_OUT_OF_RANGE);
    }
    for (uint32_t t = 0; t < nt; ++t) {
        uint32_t tt[3];
        topomesh_status s = che_triangle_triangles(m, t, tt, 3, &len);
        CHECK(s == TOPOMESH_STATUS_OK || s == TOPOMESH_STATUS_PANIC);
    }
    uint32_t offsets[256], indices[1024];
    size_t no = 0, ni = 0;
    topomesh_status s =
        che_mesh_vertex_vertices_csr(m, offsets, 256, indices, 1024, &no, &ni);
    CHECK(s == TOPOMESH_STATUS_OK || s == TOPOMESH_STATUS_PANIC ||
          s == TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(che_mesh_validate(m) != TOPOMESH_STATUS_OK);
}

static void bad_surface_files(uint32_t mode) {
    che_mesh *a = NULL, *m = NULL;
    CHECK_OK(che_mesh_from_triangles(TRIS, 4, 6, POS, 3, &a));
    if (!a) return;
    CHECK_OK(che_mesh_save(a, "good.che"));
    che_mesh_free(a);
    bytes good = read_all("good.che");
    if (!good.b) return;
    /* Truncated anywhere: the header's length, or the header itself, disagrees. */
    const size_t cuts[] = {0, 8, 63, 64, 100, good.n / 2, good.n - 64, good.n - 1};
    for (size_t i = 0; i < sizeof cuts / sizeof cuts[0]; ++i) {
        bytes f = {good.b, cuts[i]};
        refused(f, mode, TOPOMESH_STATUS_PARSE, cuts[i] < 64 ? "truncated" : "the file has");
    }
    /* A byte flipped in a section: its checksum (a trusted open does not look). */
    bytes f = copy_of(good);
    size_t v = entry_of(f, "V"), o = entry_of(f, "O");
    size_t v_at = (size_t)le64(f.b + v + 40), o_at = (size_t)le64(f.b + o + 40);
    f.b[o_at + 1] ^= 0x10;
    CHECK_STATUS(open_che_bytes(f, mode, &m), TOPOMESH_STATUS_PARSE);
    CHECK_DETAIL("section O fails its checksum");
    CHECK_STATUS(open_che_bytes(f, mode | TOPOMESH_OPEN_CHECKSUMS_ONLY, &m),
                 TOPOMESH_STATUS_PARSE);
    /* Wrong version, wrong endianness: refused even when trusted. */
    memcpy(f.b, good.b, good.n);
    put32(f.b + 12, 2);
    refused(f, mode, TOPOMESH_STATUS_PARSE, "version 2");
    memcpy(f.b, good.b, good.n);
    f.b[16] = 1, f.b[17] = 2, f.b[18] = 3, f.b[19] = 4;
    refused(f, mode, TOPOMESH_STATUS_PARSE, "big-endian");
    /* Counts against the file size: the header's length, a section running past the end,
       a section count that disagrees with the counts section. */
    memcpy(f.b, good.b, good.n);
    put64(f.b + 32, good.n + 64);
    refused(f, mode, TOPOMESH_STATUS_PARSE, "the file has");
    memcpy(f.b, good.b, good.n);
    put64(f.b + o + 48, le64(f.b + o + 48) * 1000);
    reseal(f, o);
    refused(f, mode, TOPOMESH_STATUS_PARSE, "past the end");
    memcpy(f.b, good.b, good.n);
    put64(f.b + o + 48, le64(f.b + o + 48) - 1);
    reseal(f, o);
    refused(f, mode, TOPOMESH_STATUS_PARSE, "the counts say");
    /* Ids pointing outside, the checksums redone: the invariants catch them; checksums
       only or trusted, the file opens and every query gives a status. */
    const uint32_t outside[] = {1000, 0xfffffffeu};
    for (int i = 0; i < 2; ++i) {
        for (int which = 0; which < 2; ++which) {
            memcpy(f.b, good.b, good.n);
            put32(f.b + (which ? o_at : v_at), outside[i]);
            reseal(f, which ? o : v);
            CHECK_STATUS(open_che_bytes(f, mode, &m), TOPOMESH_STATUS_INVALID_INPUT);
            CHECK_DETAIL(which ? "O[0]" : "V[0]");
            const uint32_t lax[] = {TOPOMESH_OPEN_CHECKSUMS_ONLY, TOPOMESH_OPEN_TRUSTED};
            for (int k = 0; k < 2; ++k) {
                CHECK_OK(open_che_bytes(f, mode | lax[k], &m));
                if (!m) continue;
                queries_give_a_status(m);
                che_mesh_free(m);
            }
        }
    }
    free(f.b);
    free(good.b);
}

static void bad_volume_files(uint32_t mode) {
    chf_mesh *a = make_chf(CUBE, NTET(CUBE), 8, CUBE_POS, 3), *m = NULL;
    if (!a) return;
    CHECK_OK(chf_mesh_save(a, "good.chf"));
    chf_mesh_free(a);
    bytes good = read_all("good.chf");
    if (!good.b) return;
    bytes f = copy_of(good);
    /* Truncated, a byte flipped, counts past the end, an id outside. */
    for (size_t cut = 0; cut < good.n; cut += good.n / 7 + 1) {
        write_all("bad.chf", good.b, cut);
        m = (chf_mesh *)1;
        CHECK_STATUS(chf_mesh_open("bad.chf", mode | TOPOMESH_OPEN_TRUSTED, &m),
                     TOPOMESH_STATUS_PARSE);
        CHECK(m == NULL);
    }
    size_t v = entry_of(f, "V");
    size_t v_at = (size_t)le64(f.b + v + 40);
    f.b[v_at] ^= 0x01;
    write_all("bad.chf", f.b, f.n);
    CHECK_STATUS(chf_mesh_open("bad.chf", mode, &m), TOPOMESH_STATUS_PARSE);
    CHECK_DETAIL("section V fails its checksum");
    memcpy(f.b, good.b, good.n);
    put64(f.b + v + 48, le64(f.b + v + 48) * 1000);
    reseal(f, v);
    write_all("bad.chf", f.b, f.n);
    CHECK_STATUS(chf_mesh_open("bad.chf", mode | TOPOMESH_OPEN_TRUSTED, &m),
                 TOPOMESH_STATUS_PARSE);
    CHECK_DETAIL("past the end");
    memcpy(f.b, good.b, good.n);
    put32(f.b + v_at, 0xfffffffeu);
    reseal(f, v);
    write_all("bad.chf", f.b, f.n);
    CHECK_STATUS(chf_mesh_open("bad.chf", mode, &m), TOPOMESH_STATUS_INVALID_INPUT);
    CHECK_OK(chf_mesh_open("bad.chf", mode | TOPOMESH_OPEN_TRUSTED, &m));
    if (m) {
        uint32_t buf[64];
        size_t len = 0;
        for (uint32_t x = 0; x < chf_mesh_num_vertices(m); ++x) {
            topomesh_status s = chf_vertex_vertices(m, x, buf, 64, &len);
            CHECK(s == TOPOMESH_STATUS_OK || s == TOPOMESH_STATUS_PANIC ||
                  s == TOPOMESH_STATUS_BUFFER_TOO_SMALL);
        }
        CHECK(chf_mesh_validate(m) != TOPOMESH_STATUS_OK);
        chf_mesh_free(m);
    }
    free(f.b);
    free(good.b);
}

int main(void) {
    test_surface();
    test_volume();
    bad_surface_files(0);
    bad_surface_files(TOPOMESH_OPEN_MAPPED);
    bad_volume_files(0);
    bad_volume_files(TOPOMESH_OPEN_MAPPED);
    return finish("test_levelfile");
}
