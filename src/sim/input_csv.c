/*
 * src/sim/input_csv.c - a sampled input read from the text of a CSV table
 * of rows "t,value" (qd_sim_input_table_read, qdot/sim.h): what `qdot
 * simulate --input F=FILE.csv` hands to the run, and Python could too.
 */
#include "simint.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "../base/args.h"

/* The line text[a, b): "t,value" -> 1, blank -> 0, anything else -> -1. */
static int parse_row(const char *text, size_t a, size_t b, double *t, double *v) {
    char buf[512];
    size_t n = b - a < sizeof buf - 1 ? b - a : sizeof buf - 1;
    memcpy(buf, text + a, n);
    buf[n] = '\0';
    const char *line = buf;
    char *end;
    while (*line == ' ' || *line == '\t')
        line++;
    if (!*line || *line == '\r')
        return 0;
    if (b - a >= sizeof buf - 1)
        return -1; /* longer than any row of two numbers */
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
    while (*end == ' ' || *end == '\t' || *end == '\r')
        end++;
    return *end ? -1 : 1;
}

qd_status qd_sim_input_table_read(qd_sim *s, const char *name, const char *text, size_t len,
                                  size_t *bad_line) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, name && text && bad_line);
    *bad_line = 0;
    size_t cap = 64, n = 0;
    double *t = malloc(2 * cap * sizeof *t);
    if (!t) {
        qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    size_t lineno = 0;
    for (size_t a = 0; a < len;) {
        const char *nl = memchr(text + a, '\n', len - a);
        size_t b = nl ? (size_t)(nl - text) : len;
        double ti, vi;
        int r = parse_row(text, a, b, &ti, &vi);
        lineno++;
        a = nl ? b + 1 : len;
        if (r < 0 && lineno == 1)
            continue; /* a header */
        if (r < 0) {
            free(t);
            *bad_line = lineno;
            qd_ctx_error(s->ctx, QD_ERR_ARG, "line %zu: expected \"t,value\"", lineno);
            return QD_ERR_ARG;
        }
        if (r == 0)
            continue;
        if (n == cap) { /* t[0, cap) then v[cap, 2 cap): moved apart as it grows */
            double *g = realloc(t, 4 * cap * sizeof *t);
            if (!g) {
                free(t);
                qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory");
                return QD_ERR_NOMEM;
            }
            t = g;
            memmove(t + 2 * cap, t + cap, n * sizeof *t);
            cap *= 2;
        }
        t[n] = ti;
        t[cap + n++] = vi;
    }
    qd_status st = qd_sim_input_table(s, name, n, t, t + cap);
    free(t);
    return st;
}
