/*
 * cli/sim_input_cli.c - `qdot simulate --input F=FILE.csv`: the file read
 * and its text handed to the library (qd_sim_input_table_read: rows
 * "t,value", linear interpolation, the run's span covered).
 */
#include "cli.h"
#include "model_file.h"
#include "sim_cli.h"

#include <stdlib.h>
#include <string.h>

int cli_sim_input_csv(cli_sim *c, const char *name, const char *path, size_t len) {
    char *file = malloc(len + 1), *text = NULL;
    size_t n = 0, bad = 0;
    if (!file) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    memcpy(file, path, len);
    file[len] = '\0';
    int rc = cli_read_text(file, "an input table", &text, &n);
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
