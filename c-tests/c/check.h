/* Tiny test harness and mesh fixtures shared by the C tests. */
#ifndef TOPOMESH_CHECK_H
#define TOPOMESH_CHECK_H

#include <topomesh/topomesh.h>

#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__GNUC__)
#define UNUSED_ __attribute__((unused))
#else
#define UNUSED_
#endif

static int check_failures UNUSED_ = 0;
/* How many checks ran: finish() reports it, so a rewrite can show it dropped none. */
static unsigned long check_count UNUSED_ = 0;

static inline const char *last_error(void) {
    static char buf[1024];
    size_t len = 0;
    topomesh_status s = topomesh_last_error(buf, sizeof buf, &len);
    if (s != TOPOMESH_STATUS_OK && s != TOPOMESH_STATUS_BUFFER_TOO_SMALL) buf[0] = 0;
    return buf;
}

#define CHECK(cond)                                                                        \
    do {                                                                                   \
        check_count++;                                                                     \
        if (!(cond)) {                                                                     \
            fprintf(stderr, "%s:%d: CHECK(%s) failed\n", __FILE__, __LINE__, #cond);      \
            check_failures++;                                                              \
        }                                                                                  \
    } while (0)

/* Expects a status; prints the detail on a mismatch. */
#define CHECK_STATUS(expr, want)                                                           \
    do {                                                                                   \
        check_count++;                                                                     \
        topomesh_status got_ = (expr);                                                     \
        topomesh_status want_ = (want);                                                    \
        if (got_ != want_) {                                                               \
            fprintf(stderr, "%s:%d: %s gave %s (%u), expected %s (%u); detail: %s\n",      \
                    __FILE__, __LINE__, #expr, topomesh_status_str(got_), (unsigned)got_,  \
                    topomesh_status_str(want_), (unsigned)want_, last_error());            \
            check_failures++;                                                              \
        }                                                                                  \
    } while (0)

#define CHECK_OK(expr) CHECK_STATUS(expr, TOPOMESH_STATUS_OK)

/* The last error detail contains `needle`. */
#define CHECK_DETAIL(needle)                                                               \
    do {                                                                                   \
        check_count++;                                                                     \
        const char *d_ = last_error();                                                     \
        if (!strstr(d_, (needle))) {                                                       \
            fprintf(stderr, "%s:%d: detail \"%s\" lacks \"%s\"\n", __FILE__, __LINE__, d_, \
                    (needle));                                                             \
            check_failures++;                                                              \
        }                                                                                  \
    } while (0)

/* Compares got[0..n) with the expected list. */
static inline int ids_equal_(const uint32_t *got, size_t n, int count, ...) {
    va_list ap;
    int ok = (size_t)count == n;
    va_start(ap, count);
    for (int i = 0; i < count; i++) {
        uint32_t want = va_arg(ap, uint32_t);
        if (ok && got[i] != want) ok = 0;
    }
    va_end(ap);
    return ok;
}

static inline void print_ids_(const char *what, const uint32_t *got, size_t n) {
    fprintf(stderr, "    %s = [", what);
    for (size_t i = 0; i < n; i++) fprintf(stderr, i ? ", %u" : "%u", (unsigned)got[i]);
    fprintf(stderr, "]\n");
}

#define NARGS_(...) NARGS_IMPL_(__VA_ARGS__, 12, 11, 10, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0)
#define NARGS_IMPL_(_1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, N, ...) N

/* CHECK_IDS(buf, len, a, b, c): buf[0..len) == {a, b, c}. */
#define CHECK_IDS(got, n, ...)                                                             \
    do {                                                                                   \
        check_count++;                                                                     \
        if (!ids_equal_((got), (n), NARGS_(__VA_ARGS__), __VA_ARGS__)) {                   \
            fprintf(stderr, "%s:%d: %s[0..%s) != {%s}\n", __FILE__, __LINE__, #got, #n,    \
                    #__VA_ARGS__);                                                         \
            print_ids_(#got, (got), (n));                                                  \
            check_failures++;                                                              \
        }                                                                                  \
    } while (0)

#define CHECK_EMPTY(n) CHECK((n) == 0)

/* A load (`call`, writing into m) that fails with `want`: no mesh, and a detail that
   contains `needle`. m is first set to a non-NULL garbage value. */
#define CHECK_LOAD_FAILS(m, call, want, needle)                                            \
    do {                                                                                   \
        (m) = (void *)&(m);                                                                \
        CHECK_STATUS(call, want);                                                          \
        CHECK((m) == NULL);                                                                \
        CHECK_DETAIL(needle);                                                              \
    } while (0)

/* A copy of ids[0..n) (malloc'ed, never NULL), to compare with after a call. */
static inline uint32_t *copy_ids(const uint32_t *ids, size_t n) {
    uint32_t *out = malloc((n + 1) * sizeof *out);
    if (!out) exit(2);
    if (n) memcpy(out, ids, n * sizeof *out);
    return out;
}

/* Writes a test input file into the working directory. */
static inline void write_file(const char *path, const char *text) {
    FILE *f = fopen(path, "w");
    if (!f || fputs(text, f) < 0 || fclose(f) != 0) {
        fprintf(stderr, "cannot write %s\n", path);
        exit(2);
    }
}

static inline int finish(const char *name) {
    if (check_failures) {
        fprintf(stderr, "%s: %d check(s) failed\n", name, check_failures);
        return 1;
    }
    printf("%s: all %lu checks passed\n", name, check_count);
    return 0;
}

/* A part of a test program, run by the program's argument `name`. */
typedef struct test_part {
    const char *name;
    void (*run)(void);
} test_part;

/* The main of a test in parts: runs the part its argument names (`fallback` without one);
   prints `usage` ("prog a|b") for any other argument. */
static inline int parts_main(int argc, char **argv, const char *fallback, const char *usage,
                             const test_part *parts, size_t n) {
    const char *what = argc > 1 ? argv[1] : fallback;
    for (size_t i = 0; i < n; i++)
        if (strcmp(what, parts[i].name) == 0) {
            parts[i].run();
            return finish(what);
        }
    fprintf(stderr, "usage: %s\n", usage);
    return 2;
}

/* The main of a load test: `args` (argument errors, independent of the file readers) or
   `readers` (needs them). */
static inline int load_test_main(int argc, char **argv, const char *prog, void (*args)(void),
                                 void (*readers)(void)) {
    const test_part parts[] = {{"args", args}, {"readers", readers}};
    char usage[80];
    snprintf(usage, sizeof usage, "%s args|readers", prog);
    return parts_main(argc, argv, "args", usage, parts, 2);
}

/* ---- Loading files, for either library ---------------------------------------------- */

/* The load calls of CHE or CHF, and the views of what they load, adapted to a mesh given
   as void * (by ANY_LOADER). */
typedef struct any_loader {
    topomesh_status (*load)(const char *path, uint32_t level, void **m);
    topomesh_status (*load_ex)(const char *path, const void *options, void **m);
    const double *(*positions)(const void *m, size_t *len);
    const uint32_t *(*cells)(const void *m, size_t *len); /* the cells' corners */
    const char *ext; /* of a format it reads, with the dot */
} any_loader;

/* Defines the any_loader `name` of a library's mesh_t, its load calls and its views. */
#define ANY_LOADER(name, mesh_t, load_fn, load_ex_fn, positions_fn, cells_fn, ext)         \
    static topomesh_status name##_load_(const char *path, uint32_t level, void **m) {      \
        return load_fn(path, level, (mesh_t **)m);                                         \
    }                                                                                      \
    static topomesh_status name##_load_ex_(const char *path, const void *o, void **m) {    \
        return load_ex_fn(path, o, (mesh_t **)m);                                          \
    }                                                                                      \
    static const double *name##_positions_(const void *m, size_t *len) {                   \
        return positions_fn((const mesh_t *)m, len);                                       \
    }                                                                                      \
    static const uint32_t *name##_cells_(const void *m, size_t *len) {                     \
        return cells_fn((const mesh_t *)m, len);                                           \
    }                                                                                      \
    static const any_loader name = {name##_load_, name##_load_ex_, name##_positions_,      \
                                    name##_cells_, ext}

/* The argument errors of a loader, which need no file reader: a NULL path (named in the
   detail) or out, level 4, and a file whose extension (of `unknown`) is no mesh format. */
static inline void check_load_args(const any_loader *l, const char *unknown) {
    void *m = NULL;
    char path[32];
    snprintf(path, sizeof path, "x%s", l->ext);
    CHECK_LOAD_FAILS(m, l->load(NULL, 2, &m), TOPOMESH_STATUS_NULL_ARGUMENT, "path");
    CHECK_STATUS(l->load(path, 2, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(l->load(path, 4, &m), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK_STATUS(l->load_ex(NULL, NULL, &m), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(l->load_ex(path, NULL, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    write_file(unknown, "hello\n");
    CHECK_LOAD_FAILS(m, l->load(unknown, 2, &m), TOPOMESH_STATUS_INVALID_INPUT, unknown);
}

/* The file errors of a loader: a missing file (IO), a malformed one (PARSE), both named in
   the detail, and one with a vertex index out of range (an error, no mesh). The files are
   written from the texts given. */
typedef struct bad_files {
    const char *missing, *malformed, *malformed_text, *bad_index, *bad_index_text;
} bad_files;
static inline void check_load_file_errors(const any_loader *l, const bad_files *f) {
    void *m = NULL;
    CHECK_LOAD_FAILS(m, l->load(f->missing, 2, &m), TOPOMESH_STATUS_IO, f->missing);
    write_file(f->malformed, f->malformed_text);
    CHECK_LOAD_FAILS(m, l->load(f->malformed, 2, &m), TOPOMESH_STATUS_PARSE, f->malformed);
    write_file(f->bad_index, f->bad_index_text);
    CHECK(l->load(f->bad_index, 2, &m) != TOPOMESH_STATUS_OK);
    CHECK(m == NULL);
}

/* A mesh m loaded by l holds the arrays of its file: positions (3 a vertex) and the
   corners of its cells, the expected arrays want_p and want_v (zero-copy views each). */
#define CHECK_LOADED_ARRAYS(l, m, want_p, want_v)                                          \
    do {                                                                                   \
        size_t lp_ = 0, lv_ = 0;                                                           \
        const double *p_ = (l)->positions((m), &lp_);                                      \
        const uint32_t *v_ = (l)->cells((m), &lv_);                                        \
        const size_t np_ = sizeof(want_p) / sizeof(want_p)[0];                             \
        CHECK(p_ != NULL && lp_ == np_);                                                   \
        if (p_ && lp_ == np_) CHECK(memcmp(p_, (want_p), sizeof(want_p)) == 0);           \
        CHECK(lv_ == sizeof(want_v) / sizeof(want_v)[0] &&                                 \
              memcmp(v_, (want_v), sizeof(want_v)) == 0);                                  \
    } while (0)

/* ---- Queries of either library ------------------------------------------------------ */

/* An id query of CHE or CHF on a mesh given as const void *: a relation (ids into a buffer),
   a value (one id) or a flag (0 or 1), all with the shape of a relation. The adapters
   (q_<function>) come from IDS_QUERY, VALUE_QUERY and FLAG_QUERY. */
typedef topomesh_status (*any_query_fn)(const void *m, uint32_t id, uint32_t *out, size_t cap,
                                        size_t *len);
typedef struct any_query {
    const char *name;
    any_query_fn fn;
    int kind; /* the elements its ids run over: the caller's count_fn tells how many */
} any_query;
typedef size_t (*any_count_fn)(const void *m, int kind);

#define QUERY_HEAD_(fn)                                                                    \
    static UNUSED_ topomesh_status q_##fn(const void *m, uint32_t id, uint32_t *out,       \
                                          size_t cap, size_t *len)
#define IDS_QUERY(mesh_t, fn)                                                              \
    QUERY_HEAD_(fn) {                                                                      \
        return fn((const mesh_t *)m, id, out, cap, len);                                   \
    }
#define VALUE_QUERY(mesh_t, fn)                                                            \
    QUERY_HEAD_(fn) {                                                                      \
        (void)cap;                                                                         \
        if (len) *len = 1;                                                                 \
        return fn((const mesh_t *)m, id, out);                                             \
    }
/* The flag starts as out[0] says, so a table row (which seeds out[0] with the opposite of
   its answer) sees a flag the call did not write. */
#define FLAG_QUERY(mesh_t, fn)                                                             \
    QUERY_HEAD_(fn) {                                                                      \
        bool b = out ? out[0] != 0 : false;                                                \
        const topomesh_status s = fn((const mesh_t *)m, id, out ? &b : NULL);              \
        (void)cap;                                                                         \
        if (out) out[0] = b;                                                               \
        if (len) *len = 1;                                                                 \
        return s;                                                                          \
    }

/* One expected answer: a query (a q_<function> adapter) on one element, with the status it
   gives and, when that is OK, its ids; when it is an error, a text that the detail contains
   (or NULL). check_answers checks a row as the CHECK_OK/CHECK_IDS pairs did: two checks for
   an OK row (status, ids), one or two for an error row (status, detail). */
typedef struct answer_row {
    const char *name;
    any_query_fn fn;
    uint32_t id;
    topomesh_status status;
    const char *detail;
    size_t n;
    uint32_t want[12];
} answer_row;

static inline void check_answers(const char *mesh, const void *m, const answer_row *rows,
                                 size_t n_rows) {
    for (size_t r = 0; r < n_rows; r++) {
        const answer_row *w = &rows[r];
        uint32_t got[16];
        size_t len = 0;
        /* Seeded unlike the answer, so an id the call does not write is a mismatch. */
        for (size_t i = 0; i < 16; i++) got[i] = i < w->n && w->want[i] == 0;
        const topomesh_status s = w->fn(m, w->id, got, 16, &len);
        check_count++;
        if (s != w->status) {
            fprintf(stderr, "%s: %s(%u) gave %s, expected %s; detail: %s\n", mesh, w->name,
                    (unsigned)w->id, topomesh_status_str(s), topomesh_status_str(w->status),
                    last_error());
            check_failures++;
        }
        if (w->status != TOPOMESH_STATUS_OK) {
            if (w->detail) CHECK_DETAIL(w->detail);
            continue;
        }
        check_count++;
        if (len != w->n || memcmp(got, w->want, len * sizeof *got) != 0) {
            fprintf(stderr, "%s: %s(%u) gave other ids\n", mesh, w->name, (unsigned)w->id);
            print_ids_("got", got, len);
            print_ids_("expected", w->want, w->n);
            check_failures++;
        }
    }
}

/* The statuses an answer file names. */
static const struct {
    const char *name;
    topomesh_status status;
} STATUS_NAMES_[] = {
    {"NULL_ARGUMENT", TOPOMESH_STATUS_NULL_ARGUMENT},
    {"OUT_OF_RANGE", TOPOMESH_STATUS_OUT_OF_RANGE},
    {"INVALID_INPUT", TOPOMESH_STATUS_INVALID_INPUT},
    {"NON_MANIFOLD", TOPOMESH_STATUS_NON_MANIFOLD},
    {"BUFFER_TOO_SMALL", TOPOMESH_STATUS_BUFFER_TOO_SMALL},
};

/* Reads one line of an answer file into *row: `<query> <id> = <ids>` (N for TOPOMESH_NONE)
   or `<query> <id> ! <STATUS> [<detail text>]`, the query named in qs. Exits on a line it
   cannot read: a typo in a table must not pass as a test. */
static inline void parse_answer_(const char *line, const any_query *qs, size_t nq,
                                 answer_row *row, char *detail) {
    char query[64], op = 0;
    unsigned id = 0;
    int used = 0;
    memset(row, 0, sizeof *row);
    if (sscanf(line, "%63s %u %c%n", query, &id, &op, &used) != 3 || (op != '=' && op != '!'))
        goto bad;
    for (size_t q = 0; q < nq && !row->fn; q++)
        if (strcmp(qs[q].name, query) == 0) row->name = qs[q].name, row->fn = qs[q].fn;
    if (!row->fn) goto bad;
    row->id = id;
    const char *rest = line + used;
    if (op == '!') {
        char status[32];
        int more = 0;
        if (sscanf(rest, "%31s %n", status, &more) != 1) goto bad;
        row->status = TOPOMESH_STATUS_PANIC;
        for (size_t i = 0; i < sizeof STATUS_NAMES_ / sizeof STATUS_NAMES_[0]; i++)
            if (strcmp(STATUS_NAMES_[i].name, status) == 0) row->status = STATUS_NAMES_[i].status;
        if (row->status == TOPOMESH_STATUS_PANIC) goto bad;
        strcpy(detail, rest + more);
        detail[strcspn(detail, "\r\n")] = 0;
        row->detail = detail[0] ? detail : NULL;
        return;
    }
    char word[16];
    int w = 0;
    while (sscanf(rest, "%15s%n", word, &w) == 1 && word[0] != '#') {
        char *end = word + 1;
        const uint32_t x =
            strcmp(word, "N") == 0 ? TOPOMESH_NONE : (uint32_t)strtoul(word, &end, 10);
        if (*end || row->n == 12) goto bad;
        row->want[row->n++] = x;
        rest += w;
    }
    if (row->n == 0) goto bad;
    return;
bad:
    fprintf(stderr, "cannot read the answer line: %s", line);
    exit(2);
}

/* Checks mesh m against the section `[mesh]` of an answer file (a file of expected answers,
   one a line; `#` starts a comment). The section must hold at least one answer. */
static inline void check_answer_file(const char *path, const char *mesh, const void *m,
                                     const any_query *qs, size_t nq) {
    FILE *f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "cannot open %s\n", path);
        exit(2);
    }
    char line[256], header[80], detail[256];
    snprintf(header, sizeof header, "[%s]", mesh);
    int inside = 0, rows = 0;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '#' || line[strspn(line, " \r\n")] == 0) continue;
        if (line[0] == '[') {
            inside = strncmp(line, header, strlen(header)) == 0;
            continue;
        }
        if (!inside) continue;
        answer_row row;
        parse_answer_(line, qs, nq, &row, detail);
        check_answers(mesh, m, &row, 1);
        rows++;
    }
    fclose(f);
    CHECK(rows > 0);
}

/* A bulk (CSR) call of either library, adapted by CSR_QUERY to a mesh given as const void *,
   with the per-element relation whose rows it holds. */
typedef topomesh_status (*any_csr_fn)(const void *m, uint32_t *offsets, size_t offsets_cap,
                                      uint32_t *indices, size_t indices_cap, size_t *n_offsets,
                                      size_t *n_indices);
typedef struct any_csr {
    any_csr_fn csr;
    any_query_fn rows;
    int kind;
} any_csr;

#define CSR_QUERY(mesh_t, fn)                                                              \
    static UNUSED_ topomesh_status q_##fn(const void *m, uint32_t *o, size_t oc,           \
                                          uint32_t *i, size_t ic, size_t *no, size_t *ni) { \
        return fn((const mesh_t *)m, o, oc, i, ic, no, ni);                                \
    }

/* A zero-copy view of either library, adapted by VIEW_QUERY. */
typedef const uint32_t *(*any_view_fn)(const void *m, size_t *len);
#define VIEW_QUERY(mesh_t, fn)                                                             \
    static UNUSED_ const uint32_t *q_##fn(const void *m, size_t *len) {                    \
        return fn((const mesh_t *)m, len);                                                 \
    }

/* Every view of a NULL handle is NULL with a length of 0; a NULL len is allowed. */
static inline void check_null_views(const any_view_fn *views, size_t n) {
    for (size_t i = 0; i < n; i++) {
        size_t len = 99;
        CHECK(views[i](NULL, &len) == NULL && len == 0);
        CHECK(views[i](NULL, NULL) == NULL);
    }
}

/* A CSR call agrees with its per-element relation, row by row, over `rows` rows. */
static inline void csr_matches(const any_csr *c, const void *m, size_t rows) {
    size_t no = 0, ni = 0;
    CHECK_OK(c->csr(m, NULL, 0, NULL, 0, &no, &ni));
    CHECK(no == rows + 1);
    uint32_t *off = malloc((no + 1) * sizeof *off), *idx = malloc((ni + 1) * sizeof *idx);
    if (!off || !idx) exit(2);
    size_t no2 = 0, ni2 = 0;
    CHECK_OK(c->csr(m, off, no, idx, ni, &no2, &ni2));
    CHECK(no2 == no && ni2 == ni);
    CHECK(off[0] == 0 && off[rows] == ni);
    for (uint32_t r = 0; r < rows; r++) {
        uint32_t b[64];
        size_t n = 0;
        CHECK_OK(c->rows(m, r, b, 64, &n));
        CHECK(off[r + 1] - off[r] == n);
        if (off[r + 1] - off[r] == n) CHECK(memcmp(idx + off[r], b, n * sizeof *b) == 0);
    }
    free(off);
    free(idx);
}

/* The buffer rules and errors of a CSR call on mesh m (whose answer has some indices):
   either buffer too small (both lengths reported, the detail names it), a NULL buffer
   with a capacity of 0, NULL lengths, a NULL handle. */
static inline void check_csr_errors(any_csr_fn f, const void *m) {
    size_t no = 0, ni = 0, a = 0, b = 0;
    CHECK_OK(f(m, NULL, 0, NULL, 0, &no, &ni));
    CHECK(no >= 2 && ni >= 1);
    uint32_t *off = malloc((no + 1) * sizeof *off), *idx = malloc((ni + 1) * sizeof *idx);
    if (!off || !idx) exit(2);
    CHECK_STATUS(f(m, off, no, idx, ni - 1, &a, &b), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(a == no && b == ni);
    CHECK_DETAIL("indices");
    a = b = 0;
    CHECK_STATUS(f(m, off, no - 1, idx, ni, &a, &b), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(a == no && b == ni);
    CHECK_DETAIL("offsets");
    CHECK_STATUS(f(m, NULL, 0, idx, ni, &a, &b), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("offsets");
    CHECK_STATUS(f(m, off, no, NULL, 0, &a, &b), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("indices");
    CHECK_STATUS(f(m, off, no, idx, ni, NULL, &b), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(f(m, off, no, idx, ni, &a, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(f(NULL, NULL, 0, NULL, 0, &a, &b), TOPOMESH_STATUS_NULL_ARGUMENT);
    free(off);
    free(idx);
}

/* Every query gives mesh m the answers it gives ref, for every element of ref. */
static inline void same_answers(const char *name, uint32_t level, const any_query *qs,
                                size_t nq, any_count_fn count, const void *ref, const void *m) {
    for (size_t q = 0; q < nq; q++) {
        const size_t n = count(ref, qs[q].kind);
        for (uint32_t id = 0; id < n; id++) {
            uint32_t a[64] = {0}, b[64] = {0};
            size_t na = 0, nb = 0;
            CHECK_OK(qs[q].fn(ref, id, a, 64, &na));
            CHECK_OK(qs[q].fn(m, id, b, 64, &nb));
            check_count++;
            if (na != nb || memcmp(a, b, na * sizeof *a)) {
                fprintf(stderr, "%s: %s(%u) differs at level %u from level 3\n", name,
                        qs[q].name, (unsigned)id, (unsigned)level);
                print_ids_("level 3", a, na);
                print_ids_("this level", b, nb);
                check_failures++;
            }
        }
    }
}

/* Two zero-copy views (pointer and length) hold the same ids. */
static inline int same_view(const uint32_t *a, size_t la, const uint32_t *b, size_t lb) {
    return a && b && la == lb && (la == 0 || memcmp(a, b, la * sizeof *a) == 0);
}

/* What the level test needs of a library: its queries, the count of each of its `n_kinds`
   element kinds, the views that level 3 adds, raising a mesh's level and freeing it. */
typedef struct level_suite {
    const any_query *queries;
    size_t n_queries;
    any_count_fn count;
    int n_kinds;
    const any_view_fn *views;
    size_t n_views;
    topomesh_status (*build_level)(void *m, uint32_t level);
    void (*free)(void *m);
} level_suite;

/* Meshes lower[0..3) (built from ref's input at levels 0, 1, 2) have ref's counts and give
   every answer ref (level 3) gives; raised to level 3, they have ref's views. Frees them. */
static inline void same_as_level_3(const char *name, const level_suite *s, const void *ref,
                                   void *const lower[3]) {
    for (uint32_t level = 0; level < 3; level++) {
        void *m = lower[level];
        for (int kind = 0; kind < s->n_kinds; kind++)
            CHECK(s->count(m, kind) == s->count(ref, kind));
        same_answers(name, level, s->queries, s->n_queries, s->count, ref, m);
        CHECK_OK(s->build_level(m, 3));
        for (size_t v = 0; v < s->n_views; v++) {
            size_t la = 0, lb = 0;
            const uint32_t *a = s->views[v](ref, &la), *b = s->views[v](m, &lb);
            CHECK(same_view(a, la, b, lb));
        }
        s->free(m);
    }
}

/* The errors of a single-value helper (a VALUE_QUERY or FLAG_QUERY) on mesh m, whose ids
   run over `count` elements: a NULL handle or out, and id `count`, out of range (the
   detail names it as `what` and the id). */
static inline void check_value_errors(any_query_fn f, const void *m, size_t count,
                                      const char *what) {
    uint32_t x = 0;
    size_t n = 0;
    CHECK_STATUS(f(NULL, 0, &x, 1, &n), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(f(m, 0, NULL, 1, &n), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_STATUS(f(m, (uint32_t)count, &x, 1, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
    char detail[64];
    snprintf(detail, sizeof detail, "%s %u", what, (unsigned)count);
    CHECK_DETAIL(detail);
}

/* The buffer rules and errors of a relation on mesh m (whose ids run over `count`
   elements): on the element with the longest answer (at least 2 ids), then on id `count`,
   out of range (the detail names it as `what` and the id). */
static inline void check_buffer_rules(any_query_fn f, const void *m, size_t count,
                                      const char *what) {
    uint32_t id = 0;
    size_t n = 0, need = 0;
    for (uint32_t x = 0; x < count; x++) {
        CHECK_OK(f(m, x, NULL, 0, &need));
        if (need > n) n = need, id = x;
    }
    CHECK(n >= 2);
    uint32_t full[64], b[64];
    CHECK_OK(f(m, id, full, 64, &need));
    CHECK(need == n);
    /* Too small: the needed length, and the prefix written. */
    for (size_t i = 0; i < 64; i++) b[i] = 12345;
    need = 0;
    CHECK_STATUS(f(m, id, b, 1, &need), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(need == n && b[0] == full[0] && b[1] == 12345);
    CHECK_DETAIL("needed");
    /* A buffer of zero entries (not a size query) is too small as well. */
    CHECK_STATUS(f(m, id, b, 0, &need), TOPOMESH_STATUS_BUFFER_TOO_SMALL);
    CHECK(need == n);
    /* Exactly enough, and "unbounded". */
    CHECK_OK(f(m, id, b, n, &need));
    CHECK(need == n && memcmp(b, full, n * sizeof *b) == 0);
    CHECK_OK(f(m, id, b, SIZE_MAX, &need));
    CHECK(need == n && memcmp(b, full, n * sizeof *b) == 0);
    /* NULL handle, NULL buffer with a capacity, NULL out_len. */
    CHECK_STATUS(f(NULL, 0, b, 64, &n), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("'m'");
    CHECK_STATUS(f(m, 0, NULL, 4, &n), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("buf");
    CHECK_STATUS(f(m, 0, b, 64, NULL), TOPOMESH_STATUS_NULL_ARGUMENT);
    CHECK_DETAIL("out_len");
    /* Out of range: the id in the detail, nothing written. */
    const uint32_t bad = (uint32_t)count;
    n = 777;
    CHECK_STATUS(f(m, bad, b, 64, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
    CHECK(n == 777);
    char detail[64];
    snprintf(detail, sizeof detail, "%s %u", what, (unsigned)bad);
    CHECK_DETAIL(detail);
    CHECK_STATUS(f(m, TOPOMESH_NONE, b, 64, &n), TOPOMESH_STATUS_OUT_OF_RANGE);
}

/* ---- Fixtures ----------------------------------------------------------------------- */

#define N_ (TOPOMESH_NONE)

/* The surface of a tetrahedron, outward (counter-clockwise seen from outside). */
static const uint32_t TETRA[] UNUSED_ = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
static const double TETRA_POS[] UNUSED_ = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};

/* An open strip: the unit square split along 1-2, facing +z. */
static const uint32_t STRIP[] UNUSED_ = {0, 1, 2, 1, 3, 2};
static const double STRIP_POS[] UNUSED_ = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};

/* Two triangles touching at vertex 0 only: a non-manifold vertex. */
static const uint32_t BOWTIE[] UNUSED_ = {0, 1, 2, 0, 3, 4};
static const double BOWTIE_POS[] UNUSED_ = {0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0};

/* Three triangles on the edge 0-1: a non-manifold edge. */
static const uint32_t FIN[] UNUSED_ = {0, 1, 2, 1, 0, 3, 0, 1, 4};

/* A Moebius strip: 6 vertices, 6 triangles, one twisted band. */
static const uint32_t MOEBIUS[] UNUSED_ = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4, 2, 3, 0, 2, 0, 5};

/* A degenerate triangle (1, 1, 2) between two good ones, and isolated vertex 4. */
static const uint32_t DEGEN[] UNUSED_ = {0, 1, 2, 1, 1, 2, 2, 1, 3};

#define NTRI(a) (sizeof(a) / sizeof((a)[0]) / 3)

/* A strip whose second triangle is flipped (repaired by the orientation pass). */
static const uint32_t FLIPPED[] UNUSED_ = {0, 1, 2, 1, 2, 3};

/* Two strips sharing nothing: two boundary curves. */
static const uint32_t TWO_STRIPS[] UNUSED_ = {0, 1, 2, 1, 3, 2, 4, 5, 6, 5, 7, 6};

/* Every small surface fixture, for the tests that run on all of them. */
typedef struct che_fixture {
    const char *name;
    const uint32_t *tris;
    size_t n_tris, n_verts;
} che_fixture;
static const che_fixture CHE_FIXTURES[] UNUSED_ = {
    {"tetrahedron", TETRA, NTRI(TETRA), 4}, {"strip", STRIP, NTRI(STRIP), 4},
    {"bowtie", BOWTIE, NTRI(BOWTIE), 5},    {"fin", FIN, NTRI(FIN), 5},
    {"moebius", MOEBIUS, NTRI(MOEBIUS), 6}, {"degenerate", DEGEN, NTRI(DEGEN), 5},
    {"flipped strip", FLIPPED, NTRI(FLIPPED), 4}, {"two strips", TWO_STRIPS, NTRI(TWO_STRIPS), 8},
};
#define N_CHE_FIXTURES (sizeof CHE_FIXTURES / sizeof CHE_FIXTURES[0])

/* A g x g grid of quads, two triangles each, over (g + 1)^2 vertices; without the quad
   (hole, hole) when hole < g (a boundary inside). Writes the triangles into out (room for
   6 g^2 ids) and returns their number. */
static inline size_t grid_triangles(uint32_t g, uint32_t hole, uint32_t *out) {
    size_t k = 0;
    for (uint32_t i = 0; i < g; i++)
        for (uint32_t j = 0; j < g; j++) {
            if (i == hole && j == hole) continue;
            const uint32_t a = i * (g + 1) + j, b = a + 1, c = a + g + 1, d = c + 1;
            const uint32_t quad[6] = {a, b, d, a, d, c};
            for (int q = 0; q < 6; q++) out[k++] = quad[q];
        }
    return k / 3;
}

/* Exits unless a fixture's build succeeded. */
static inline void fixture_built(topomesh_status s, const void *mesh) {
    if (s != TOPOMESH_STATUS_OK || !mesh) {
        fprintf(stderr, "fixture build failed: %s: %s\n", topomesh_status_str(s), last_error());
        exit(2);
    }
}

static inline che_mesh *make(const uint32_t *tris, size_t n_tris, size_t n_verts, const double *pos,
                      uint32_t level) {
    che_mesh *m = NULL;
    const topomesh_status s = che_mesh_from_triangles(tris, n_tris, n_verts, pos, level, &m);
    fixture_built(s, m);
    return m;
}

#endif
