/* The bad-input table (tests/fixtures/bad/expected.tsv) through the C API: each file loaded
   with che_mesh_load or chf_mesh_load, each .arrays description made into a call of the
   build and load functions; the status and the words of the detail must be the table's.
   Rows marked xfail must still fail (they say how the input SHOULD be handled); one that
   passes fails the test, so that its mark is removed with the fix. The columns and the
   .arrays keys are described in tests/bad_inputs.rs, which runs the same table in Rust.

   Usage: test_bad_inputs FIXTURES_DIR */
#include "check.h"

static const char *const STATUS_NAMES[] = {
    "OK", "NULL_ARGUMENT", "OUT_OF_RANGE", "INVALID_INPUT", "NON_MANIFOLD",
    "BUFFER_TOO_SMALL", "IO", "PARSE", "TOO_LARGE", "PANIC",
};

static const char *status_name(topomesh_status s) {
    return (size_t)s < sizeof STATUS_NAMES / sizeof *STATUS_NAMES ? STATUS_NAMES[s] : "OTHER";
}

/* The detail after a failure, or the facts of the mesh built ("triangles=N"). */
static char message[4096];

static void facts(che_mesh *che, chf_mesh *chf) {
    if (che) snprintf(message, sizeof message, "triangles=%zu", che_mesh_num_triangles(che));
    if (chf) snprintf(message, sizeof message, "tetrahedra=%zu", chf_mesh_num_tetrahedra(chf));
    che_mesh_free(che);
    chf_mesh_free(chf);
}

static topomesh_status load_file(const char *path, const char *as) {
    che_mesh *che = NULL;
    chf_mesh *chf = NULL;
    topomesh_status s = strcmp(as, "che") == 0 ? che_mesh_load(path, 2, &che)
                                                : chf_mesh_load(path, 2, &chf);
    message[0] = 0;
    if (s != TOPOMESH_STATUS_OK) snprintf(message, sizeof message, "%s", last_error());
    facts(che, chf);
    return s;
}

/* A .arrays description (see tests/bad_inputs.rs). */
typedef struct call {
    char kind[16];
    unsigned long long vertices;
    uint32_t level, threads;
    bool strict, out_null, path_null, elements_null;
    char path[1024];
    uint32_t *elements;
    size_t n_ids;      /* ids in `elements` */
    size_t n_elements; /* elements said to be there (`null N`) */
} call;

static void read_elements(call *c, char *rest) {
    char *word = strtok(rest, " \t\n");
    if (word && strcmp(word, "null") == 0) {
        c->elements_null = true;
        c->n_elements = (size_t)strtoull(strtok(NULL, " \t\n"), NULL, 10);
        return;
    }
    if (word && strcmp(word, "strip") == 0) {
        size_t n = (size_t)strtoull(strtok(NULL, " \t\n"), NULL, 10);
        size_t k = strcmp(c->kind, "chf") == 0 ? 4 : 3;
        c->elements = malloc(n * k * sizeof *c->elements);
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < k; j++) c->elements[i * k + j] = (uint32_t)(i + j);
        c->n_ids = n * k;
        return;
    }
    c->elements = malloc(64 * sizeof *c->elements);
    for (; word && c->n_ids < 64; word = strtok(NULL, " \t\n"))
        c->elements[c->n_ids++] = (uint32_t)strtoul(word, NULL, 10);
}

static bool parse_call(const char *file, call *c) {
    FILE *f = fopen(file, "r");
    if (!f) return false;
    *c = (call){.level = 2};
    char line[4096];
    while (fgets(line, sizeof line, f)) {
        char key[32] = {0};
        int used = 0;
        if (sscanf(line, "%31s %n", key, &used) < 1) continue;
        char *rest = line + used;
        if (!strcmp(key, "kind")) sscanf(rest, "%15s", c->kind);
        else if (!strcmp(key, "vertices")) c->vertices = strtoull(rest, NULL, 10);
        else if (!strcmp(key, "level")) c->level = (uint32_t)strtoul(rest, NULL, 10);
        else if (!strcmp(key, "strict")) c->strict = strtoul(rest, NULL, 10) != 0;
        else if (!strcmp(key, "threads")) c->threads = (uint32_t)strtoul(rest, NULL, 10);
        else if (!strcmp(key, "out")) c->out_null = true;
        else if (!strcmp(key, "elements")) read_elements(c, rest);
        else if (!strcmp(key, "path")) {
            char p[512] = {0};
            sscanf(rest, "%511s", p);
            c->path_null = strcmp(p, "null") == 0;
            /* Relative to the .arrays file's folder. */
            const char *slash = strrchr(file, '/');
            snprintf(c->path, sizeof c->path, "%.*s/%s", (int)(slash ? slash - file : 1),
                     slash ? file : ".", p);
        }
    }
    fclose(f);
    return true;
}

static topomesh_status run_call(const char *file) {
    call c;
    message[0] = 0;
    if (!parse_call(file, &c)) {
        snprintf(message, sizeof message, "cannot open %s", file);
        return TOPOMESH_STATUS_IO;
    }
    che_mesh *che = NULL;
    chf_mesh *chf = NULL;
    che_build_options co = che_build_options_default();
    chf_build_options fo = chf_build_options_default();
    co.level = fo.level = c.level;
    co.strict = fo.strict = c.strict;
    co.threads = fo.threads = c.threads;
    const uint32_t *ids = c.elements_null ? NULL : c.elements;
    size_t n3 = c.elements_null ? c.n_elements : c.n_ids / 3;
    size_t n4 = c.elements_null ? c.n_elements : c.n_ids / 4;
    const char *path = c.path_null ? NULL : c.path;
    topomesh_status s;
    if (!strcmp(c.kind, "che"))
        s = che_mesh_from_triangles_ex(ids, n3, (size_t)c.vertices, NULL, &co,
                                       c.out_null ? NULL : &che);
    else if (!strcmp(c.kind, "chf"))
        s = chf_mesh_from_tetrahedra_ex(ids, n4, (size_t)c.vertices, NULL, &fo,
                                        c.out_null ? NULL : &chf);
    else if (!strcmp(c.kind, "che_load"))
        s = che_mesh_load_ex(path, &co, c.out_null ? NULL : &che);
    else
        s = chf_mesh_load_ex(path, &fo, c.out_null ? NULL : &chf);
    if (s != TOPOMESH_STATUS_OK) snprintf(message, sizeof message, "%s", last_error());
    facts(che, chf);
    free(c.elements);
    return s;
}

/* Every space-separated word of `words` ("-" for none) is in `message`. */
static bool has_words(const char *words) {
    if (!strcmp(words, "-")) return true;
    char copy[1024];
    snprintf(copy, sizeof copy, "%s", words);
    for (char *w = strtok(copy, " "); w; w = strtok(NULL, " "))
        if (!strstr(message, w)) return false;
    return true;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s FIXTURES_DIR\n", argv[0]);
        return 2;
    }
    char table[1024];
    snprintf(table, sizeof table, "%s/expected.tsv", argv[1]);
    FILE *f = fopen(table, "r");
    if (!f) {
        fprintf(stderr, "cannot open %s\n", table);
        return 1;
    }
    char line[2048];
    int rows = 0, xfails = 0, n = 0;
    while (fgets(line, sizeof line, f)) {
        n++;
        line[strcspn(line, "\r\n")] = 0;
        if (!line[0] || line[0] == '#') continue;
        char *cols[5] = {0};
        int k = 0;
        for (char *p = line; p && k < 5; k++) {
            cols[k] = p;
            p = strchr(p, '\t');
            if (p) *p++ = 0;
        }
        CHECK(k >= 4);
        if (k < 4) continue;
        rows++;
        char path[2048];
        snprintf(path, sizeof path, "%s/%s", argv[1], cols[0]);
        topomesh_status s = strcmp(cols[1], "-") == 0 ? run_call(path) : load_file(path, cols[1]);
        bool passed = !strcmp(status_name(s), cols[2]) && has_words(cols[3]);
        bool xfail = k == 5 && !strcmp(cols[4], "xfail");
        check_count++;
        if (passed == xfail) {
            check_failures++;
            fprintf(stderr, "expected.tsv:%d %s: got %s \"%s\", expected %s with \"%s\"%s\n", n,
                    cols[0], status_name(s), message, cols[2], cols[3],
                    xfail ? ": passes now, remove its xfail mark" : "");
        } else if (xfail) {
            xfails++;
            printf("xfail (still wrong today) expected.tsv:%d %s: got %s \"%s\"\n", n, cols[0],
                   status_name(s), message);
        }
    }
    fclose(f);
    printf("%d rows, %d expected failures\n", rows, xfails);
    CHECK(rows >= 100);
    return finish("test_bad_inputs");
}
