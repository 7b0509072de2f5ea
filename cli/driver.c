/*
 * cli/driver.c - the shared entry point of the commands (driver.h), so each
 * cmd_*.c keeps only what is its own: its options, checks, run and frees.
 */
#include "driver.h"
#include "progress.h"

int cli_drive(const cli_driver *d, cli_run *r, int argc, char **argv) {
    char *base = (char *)r;
    const char **pos = d->pos ? (const char **)(void *)(base + d->pos) : &r->file;
    int rc = cli_parse(d->spec, argc, argv, base + d->args, pos);
    if (rc == QD_EXIT_OK && d->check)
        rc = d->check(r);
    if (rc != QD_EXIT_OK)
        return rc;
    if (!(r->ctx = qd_ctx_new()))
        return cli_out_of_memory();
    cli_progress bar; /* the library's long searches (qd_ctx_set_progress), on a terminal */
    cli_progress_start(&bar, d->spec->name);
    qd_ctx_set_progress(r->ctx, cli_progress_steps, &bar);
    rc = d->run(r);
    cli_progress_end(&bar);
    if (d->free)
        d->free(r);
    cli_model_file_free(&r->mf);
    qd_ctx_free(r->ctx);
    return rc;
}

int cli_emit_status(const qd_ctx *ctx, qd_status st, qd_buf *b, const char *what) {
    if (st != QD_OK) {
        qd_buf_free(b);
        return cli_diag_ctx(ctx);
    }
    return cli_emit(b, what);
}
