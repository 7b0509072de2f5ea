/*
 * cli/modes_symmetry.c - `qdot modes --symmetry`: what libqdot chooses
 * and computes (qd_modes_symmetry: the cyclic fast path, or the group), its
 * note on stderr when there is none, and the fast path timed against the
 * full eigenproblem for a note.  The printing is the library's (qd_modes_print with the
 * symmetry, qdot/symmetry.h).
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include "modes_symmetry.h"

#include <math.h>
#include <time.h>

static double seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The full eigenproblem's time, for the fast path's note. */
static void fast_note(const cli_lin_run *lr, const qd_linear *lin, const qd_cyclic_modes *c,
                      double fast) {
    qd_modes_result full;
    double t0 = seconds();
    qd_status st = qd_modes_solve(lr->c.ctx, lin, &full);
    double t1 = seconds();
    qd_modes_result_free(&full);
    if (st != QD_OK) {
        qd_ctx_clear_error(lr->c.ctx);
        return;
    }
    fprintf(stderr, "qdot: note: cyclic fast path: %zu cells of %zu coordinate%s, %zu harmonics "
            "solved in %.3g s against %.3g s for the full eigenproblem (%.0fx faster)\n",
            c->cells, c->cell, c->cell == 1 ? "" : "s", c->cells / 2 + 1, fast, t1 - t0,
            (t1 - t0) / fmax(fast, 1e-9));
}

/* The library's choice and computation (qd_modes_symmetry); its note. */
int cli_sym_compute(cli_lin_run *lr, const qd_linear *lin, cli_sym_run *s) {
    qd_buf note = QD_BUF_INIT;
    const qd_state *st = &lr->pt.st;
    double t0 = seconds();
    qd_status rc = qd_modes_symmetry(lr->c.ctx, lr->e, lr->c.mf.model, st->n, st->syms,
                                     st->vals, lin, &s->sym, &s->cyc, &note);
    double t1 = seconds();
    if (rc == QD_OK && qd_buf_str(&note)[0])
        fprintf(stderr, "qdot: note: --symmetry: %s\n", qd_buf_str(&note));
    qd_buf_free(&note);
    if (rc != QD_OK)
        return cli_diag_ctx(lr->c.ctx);
    s->active = s->cyc.n > 0 || s->sym.order > 1;
    if (s->cyc.n)
        fast_note(lr, lin, &s->cyc, t1 - t0);
    return QD_EXIT_OK;
}

void cli_sym_free(cli_sym_run *s) {
    qd_symmetry_free(&s->sym);
    qd_cyclic_modes_free(&s->cyc);
}
