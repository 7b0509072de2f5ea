/*
 * cli/sim_input_cli.c - `qdot simulate --input F=FILE.csv`: the file read
 * and its text handed to the library (qd_sim_input_table_read: rows
 * "t,value", linear interpolation, the run's span covered).
 */
#include "cli.h"
#include "out.h"
#include "sim_cli.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The whole of path into *text (*len bytes); an exit status. */
static int read_file(const char *path, char **text, size_t *len) {
    int rc = QD_EXIT_OK;
    FILE *f = cli_in_open(path, &rc);
    if (!f)
        return rc;
    size_t cap = 4096, n = 0;
    char *s = malloc(cap);
    errno = 0;
    while (s) {
        n += fread(s + n, 1, cap - n, f);
        if (n < cap)
            break;
        char *g = realloc(s, 2 * cap);
        if (!g)
            free(s);
        s = g;
        cap *= 2;
    }
    if (!s) {
        cli_diag_error("out of memory");
        rc = QD_EXIT_FAIL;
    } else if (ferror(f)) {
        cli_diag_error("cannot read %s: %s", path, strerror(errno ? errno : EIO));
        rc = QD_EXIT_USAGE;
    }
    fclose(f);
    if (rc != QD_EXIT_OK) {
        free(s);
        return rc;
    }
    *text = s;
    *len = n;
    return rc;
}

int cli_sim_input_csv(cli_sim *c, const char *name, const char *path, size_t len) {
    char *file = malloc(len + 1), *text = NULL;
    size_t n = 0, bad = 0;
    if (!file) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    memcpy(file, path, len);
    file[len] = '\0';
    int rc = read_file(file, &text, &n);
    if (rc == QD_EXIT_OK && qd_sim_input_table_read(c->s, name, text, n, &bad) != QD_OK) {
        if (bad)
            cli_diag_error("--input: %s:%zu: expected \"t,value\"", file, bad);
        else
            cli_diag_error("--input: %s: %s", file, qd_ctx_message(c->ctx));
        rc = qd_ctx_status(c->ctx) == QD_ERR_NOMEM ? QD_EXIT_FAIL : QD_EXIT_USAGE;
    }
    free(text);
    free(file);
    return rc;
}
