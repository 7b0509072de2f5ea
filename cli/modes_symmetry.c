/*
 * cli/modes_symmetry.c - `qdot modes --symmetry`: runs what libqdot
 * chooses (qd_symmetry_fast_cell): the cyclic fast path (qd_cyclic_solve),
 * timed against the full eigenproblem for a note, or the group
 * (qd_symmetry_find, qd_symmetry_reduce), with a note on stderr when there
 * is none.  The printing is the library's (qd_modes_print with the
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

/* The fast path, timed against the full eigenproblem for the note. */
static int fast_path(cli_lin_run *lr, const qd_linear *lin, size_t cell, cli_sym_run *s) {
    qd_modes_result full;
    double t0 = seconds();
    qd_status st = qd_modes_solve(lr->c.ctx, lin, &full);
    double t1 = seconds();
    if (st == QD_OK)
        st = qd_cyclic_solve(lr->c.ctx, lin, cell, &s->cyc);
    double t2 = seconds();
    qd_modes_result_free(&full);
    if (st != QD_OK) {
        cli_diag_error("%s", qd_ctx_message(lr->c.ctx));
        return QD_EXIT_FAIL;
    }
    s->active = true;
    fprintf(stderr, "qdot: note: cyclic fast path: %zu cells of %zu coordinate%s, %zu harmonics "
            "solved in %.3g s against %.3g s for the full eigenproblem (%.0fx faster)\n",
            s->cyc.cells, cell, cell == 1 ? "" : "s", s->cyc.cells / 2 + 1, t2 - t1, t1 - t0,
            (t1 - t0) / fmax(t2 - t1, 1e-9));
    return QD_EXIT_OK;
}

int cli_sym_compute(cli_lin_run *lr, const qd_linear *lin, cli_sym_run *s) {
    size_t cell = qd_symmetry_fast_cell(lin);
    if (cell)
        return fast_path(lr, lin, cell, s);
    qd_status st = qd_symmetry_find(lr->c.ctx, lr->e, lr->c.mf.model, lr->pt.st.n, lr->pt.st.syms,
                                    lr->pt.st.vals, lin, &s->sym);
    if (st == QD_ERR_NOMEM)
        return cli_out_of_memory();
    if (st != QD_OK) {
        fprintf(stderr, "qdot: note: --symmetry: %s; the plain modes follow\n",
                qd_ctx_message(lr->c.ctx));
        qd_ctx_clear_error(lr->c.ctx);
        return QD_EXIT_OK;
    }
    if (s->sym.order <= 1) {
        fprintf(stderr, "qdot: note: --symmetry: the equilibrium has no symmetry (no operation "
                "but the identity leaves M0 and K0 invariant); the plain modes follow\n");
        return QD_EXIT_OK;
    }
    if (qd_symmetry_reduce(lr->c.ctx, lin, &s->sym) != QD_OK) {
        cli_diag_error("%s", qd_ctx_message(lr->c.ctx));
        return QD_EXIT_FAIL;
    }
    s->active = true;
    return QD_EXIT_OK;
}

void cli_sym_free(cli_sym_run *s) {
    qd_symmetry_free(&s->sym);
    qd_cyclic_modes_free(&s->cyc);
}
