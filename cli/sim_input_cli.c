/*
 * cli/sim_input_cli.c - `qdot simulate --input F=FILE.csv`: a sampled input
 * signal read from a file of rows "t,value" and handed to the library as a
 * table (qd_sim_input_table: linear interpolation, the run's span covered).
 */
#include "cli.h"
#include "model_file.h" /* cli_open_input */
#include "sim_cli.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct table {
    double *t, *v;
    size_t n, cap;
} table;

static bool push_row(table *tb, double t, double v) {
    if (tb->n == tb->cap) {
        size_t cap = tb->cap ? 2 * tb->cap : 64;
        double *nt = realloc(tb->t, cap * sizeof *nt);
        if (!nt)
            return false;
        tb->t = nt;
        double *nv = realloc(tb->v, cap * sizeof *nv);
        if (!nv)
            return false;
        tb->v = nv;
        tb->cap = cap;
    }
    tb->t[tb->n] = t;
    tb->v[tb->n++] = v;
    return true;
}

/* One line: "t,value" -> 1, blank -> 0, anything else -> -1. */
static int parse_row(const char *line, double *t, double *v) {
    char *end;
    while (*line == ' ' || *line == '\t')
        line++;
    if (!*line || *line == '\n' || *line == '\r')
        return 0;
    errno = 0;
    *t = strtod(line, &end);
    if (end == line || errno)
        return -1;
    while (*end == ' ' || *end == '\t')
        end++;
    if (*end++ != ',')
        return -1;
    const char *p = end;
    *v = strtod(p, &end);
    if (end == p || errno)
        return -1;
    while (*end == ' ' || *end == '\t' || *end == '\r' || *end == '\n')
        end++;
    return *end ? -1 : 1;
}

static int read_table(const char *path, table *tb) {
    FILE *f = cli_open_input(path, "--input: ");
    if (!f)
        return QD_EXIT_USAGE;
    char line[512];
    size_t lineno = 0;
    int rc = QD_EXIT_OK;
    while (rc == QD_EXIT_OK && fgets(line, sizeof line, f)) {
        double t, v;
        int r = parse_row(line, &t, &v);
        lineno++;
        if (r < 0 && lineno == 1)
            continue; /* a header */
        if (r < 0) {
            cli_diag_error("--input: %s:%zu: expected \"t,value\"", path, lineno);
            rc = QD_EXIT_USAGE;
        } else if (r > 0 && !push_row(tb, t, v)) {
            cli_diag_error("out of memory");
            rc = QD_EXIT_FAIL;
        }
    }
    fclose(f);
    return rc;
}

int cli_sim_input_csv(cli_sim *c, const char *name, const char *path, size_t len) {
    char *file = malloc(len + 1);
    table tb = {0};
    if (!file) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    memcpy(file, path, len);
    file[len] = '\0';
    int rc = read_table(file, &tb);
    if (rc == QD_EXIT_OK && qd_sim_input_table(c->s, name, tb.n, tb.t, tb.v) != QD_OK) {
        cli_diag_error("--input: %s: %s", file, qd_ctx_message(c->ctx));
        rc = QD_EXIT_USAGE;
    }
    free(tb.t);
    free(tb.v);
    free(file);
    return rc;
}
