/*
 * cli/modes_symmetry.c - `qdot modes --symmetry`: prints what libqdot's
 * qd_symmetry_find / qd_symmetry_reduce (or the cyclic fast path,
 * qd_cyclic_solve) give: the group, the character table, the reducible
 * character of the displacements and its decomposition, the symmetry
 * coordinates, K0 by blocks and each mode with its irrep.
 */
#define _POSIX_C_SOURCE 200809L /* clock_gettime */
#include "modes_symmetry.h"

#include <math.h>
#include <string.h>
#include <time.h>

static const char *kind_name(qd_mode_kind k) {
    switch (k) {
    case QD_MODE_TRANSLATION:
        return "translation";
    case QD_MODE_ROTATION:
        return "rotation";
    case QD_MODE_ZERO:
        return "zero mode";
    default:
        return "vibration";
    }
}

static double seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The fast path, timed against the full eigenproblem for the note. */
static int fast_path(cli_lin_run *lr, const qd_linear *lin, size_t cell, cli_sym_run *s) {
    qd_modes_result full;
    double t0 = seconds();
    qd_status st = qd_modes_solve(lr->ctx, lin, &full);
    double t1 = seconds();
    if (st == QD_OK)
        st = qd_cyclic_solve(lr->ctx, lin, cell, &s->cyc);
    double t2 = seconds();
    qd_modes_result_free(&full);
    if (st != QD_OK) {
        cli_diag_error("%s", qd_ctx_message(lr->ctx));
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
    size_t cell = lin->n >= CLI_SYM_FAST_N ? qd_cyclic_cell(lin) : 0;
    if (cell)
        return fast_path(lr, lin, cell, s);
    qd_status st = qd_symmetry_find(lr->ctx, lr->e, lr->mf.model, lr->st.n, lr->st.syms,
                                    lr->st.vals, lin, &s->sym);
    if (st == QD_ERR_NOMEM) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    if (st != QD_OK) {
        fprintf(stderr, "qdot: note: --symmetry: %s; the plain modes follow\n",
                qd_ctx_message(lr->ctx));
        qd_ctx_clear_error(lr->ctx);
        return QD_EXIT_OK;
    }
    if (s->sym.order <= 1) {
        fprintf(stderr, "qdot: note: --symmetry: the equilibrium has no symmetry (no operation "
                "but the identity leaves M0 and K0 invariant); the plain modes follow\n");
        return QD_EXIT_OK;
    }
    if (qd_symmetry_reduce(lr->ctx, lin, &s->sym) != QD_OK) {
        cli_diag_error("%s", qd_ctx_message(lr->ctx));
        return QD_EXIT_FAIL;
    }
    s->active = true;
    return QD_EXIT_OK;
}

void cli_sym_free(cli_sym_run *s) {
    qd_symmetry_free(&s->sym);
    qd_cyclic_modes_free(&s->cyc);
}

/* ---- text ------------------------------------------------------------------ */

/* A character: an integer as such, else 4 significant digits, complex as
 * a+bi. */
static void put_character(qd_buf *b, double re, double im) {
    char t[48];
    if (fabs(im) < 1e-9) {
        if (fabs(re - round(re)) < 1e-9)
            snprintf(t, sizeof t, "%.0f", round(re) == 0 ? 0.0 : round(re));
        else
            snprintf(t, sizeof t, "%.4g", re);
    } else {
        snprintf(t, sizeof t, "%.3g%s%.3gi", fabs(re) < 1e-9 ? 0.0 : re, im < 0 ? "-" : "+",
                 fabs(im));
    }
    qd_buf_printf(b, " %9s", t);
}

static void put_group(const qd_symmetry *y, qd_buf *b) {
    if (y->name[0])
        qd_buf_printf(b, "symmetry group: %s (order %zu, %zu classes)\n", y->name, y->order,
                      y->nclass);
    else
        qd_buf_printf(b, "symmetry group: abstract group of order %zu, %zu classes "
                         "(permutations of the coordinates)\n", y->order, y->nclass);
    qd_buf_printf(b, "character table:\n  %-8s", "");
    for (size_t c = 0; c < y->nclass; c++) {
        char name[24];
        qd_symmetry_class_name(y, c, name, sizeof name);
        qd_buf_printf(b, " %9s", name);
    }
    qd_buf_puts(b, "\n");
    for (size_t i = 0; i < y->nirrep; i++) {
        qd_buf_printf(b, "  %-8s", y->label[i]);
        for (size_t c = 0; c < y->nclass; c++)
            put_character(b, y->chi_re[i * y->nclass + c], y->chi_im[i * y->nclass + c]);
        qd_buf_puts(b, "\n");
    }
    qd_buf_printf(b, "  %-8s", "Gamma");
    for (size_t c = 0; c < y->nclass; c++)
        put_character(b, y->chi[c], 0);
    qd_buf_puts(b, "   (displacements: chi = tr S)\n");
}

static void put_decomposition(const qd_symmetry *y, qd_buf *b) {
    qd_buf_puts(b, "Gamma =");
    for (size_t k = 0; k < y->nblock; k++) {
        char lab[32];
        qd_symmetry_block_label(y, k, lab, sizeof lab);
        size_t m = y->mult[y->block_irrep[k]];
        qd_buf_printf(b, "%s ", k ? " +" : "");
        if (m > 1)
            qd_buf_printf(b, "%zu", m);
        qd_buf_puts(b, lab);
    }
    qd_buf_puts(b, "\n");
}

static void put_coordinates(const qd_symmetry *y, const qd_eom *e, qd_buf *b) {
    size_t n = y->n;
    qd_buf_puts(b, "symmetry coordinates (columns of U, U^T M0 U = I):\n");
    for (size_t k = 0; k < y->nblock; k++) {
        char lab[32];
        qd_symmetry_block_label(y, k, lab, sizeof lab);
        for (size_t c = 0; c < y->block_size[k]; c++) {
            size_t col = y->block_start[k] + c;
            qd_buf_printf(b, "  %s: ", lab);
            for (size_t i = 0; i < n; i++) {
                qd_buf_printf(b, "%s%s = ", i ? ", " : "", qd_expr_name(e->q[i]));
                cli_state_put_result(b, y->U[i * n + col]);
            }
            qd_buf_puts(b, "\n");
        }
    }
}

static void put_blocks(const qd_symmetry *y, qd_buf *b) {
    size_t n = y->n;
    qd_buf_puts(b, "K0 in the symmetry coordinates, by block (zero off the blocks):\n");
    for (size_t k = 0; k < y->nblock; k++) {
        char lab[32];
        size_t s0 = y->block_start[k], m = y->block_size[k];
        qd_symmetry_block_label(y, k, lab, sizeof lab);
        qd_buf_printf(b, "  %s: [", lab);
        for (size_t i = 0; i < m; i++) {
            qd_buf_puts(b, i ? ", [" : "[");
            for (size_t j = 0; j < m; j++) {
                qd_buf_puts(b, j ? ", " : "");
                cli_state_put_result(b, y->Kb[(s0 + i) * n + s0 + j]);
            }
            qd_buf_puts(b, "]");
        }
        qd_buf_puts(b, "]\n");
    }
}

static void put_w2(qd_buf *b, double w2) {
    cli_state_put_result(b, w2);
    if (w2 > 0)
        qd_buf_printf(b, ", w = %.10g rad/s", sqrt(w2));
    else if (w2 < 0)
        qd_buf_printf(b, ", unstable: growth rate %.10g 1/s", sqrt(-w2));
}

static void put_modes(const qd_symmetry *y, const qd_eom *e, qd_buf *b) {
    size_t n = y->n;
    qd_buf_puts(b, "modes by block: K0 a = w^2 M0 a, a^T M0 a = 1\n");
    for (size_t j = 0; j < n; j++) {
        char lab[32];
        qd_symmetry_block_label(y, y->mode_block[j], lab, sizeof lab);
        qd_buf_printf(b, "mode %zu: w^2 = ", j + 1);
        put_w2(b, y->omega2[j]);
        qd_buf_printf(b, ", %s (multiplicity %zu)", lab, y->mode_degeneracy[j]);
        if (y->mode_kind[j] != QD_MODE_VIBRATION)
            qd_buf_printf(b, ", %s", kind_name(y->mode_kind[j]));
        qd_buf_puts(b, "\n  shape: ");
        for (size_t i = 0; i < n; i++) {
            qd_buf_printf(b, "%s%s = ", i ? ", " : "", qd_expr_name(e->q[i]));
            cli_state_put_result(b, y->shapes[i * n + j]);
        }
        qd_buf_puts(b, "\n");
    }
}

static void put_cyclic(const qd_cyclic_modes *c, qd_buf *b) {
    qd_buf_printf(b, "symmetry: the shift of the coordinates by %zu (cyclic group C%zu: %zu "
                     "cells of %zu); fast path, one pencil per harmonic k = 0..%zu\n",
                  c->cell, c->cells, c->cells, c->cell, c->cells / 2);
    for (size_t j = 0; j < c->n; j++) {
        qd_buf_printf(b, "mode %zu: w^2 = ", j + 1);
        put_w2(b, c->omega2[j]);
        qd_buf_printf(b, ", harmonic k = %zu (multiplicity %zu)\n", c->harmonic[j],
                      c->degeneracy[j]);
    }
}

void cli_sym_put_text(const cli_sym_run *s, const qd_eom *e, qd_buf *b) {
    if (s->cyc.n) {
        put_cyclic(&s->cyc, b);
        return;
    }
    put_group(&s->sym, b);
    put_decomposition(&s->sym, b);
    put_coordinates(&s->sym, e, b);
    put_blocks(&s->sym, b);
    put_modes(&s->sym, e, b);
}

/* ---- json ------------------------------------------------------------------ */

static void json_characters(const qd_symmetry *y, qd_json *j) {
    qd_json_key(j, "characters");
    qd_json_begin_array(j);
    for (size_t i = 0; i < y->nirrep; i++) {
        bool cplx = false;
        qd_json_begin_object(j);
        qd_json_key(j, "irrep");
        qd_json_string(j, y->label[i]);
        qd_json_key(j, "dimension");
        qd_json_number(j, (double)y->irrep_dim[i]);
        qd_json_key(j, "chi");
        qd_json_begin_array(j);
        for (size_t c = 0; c < y->nclass; c++) {
            qd_json_number(j, y->chi_re[i * y->nclass + c]);
            cplx = cplx || fabs(y->chi_im[i * y->nclass + c]) > 1e-9;
        }
        qd_json_end_array(j);
        if (cplx) {
            qd_json_key(j, "chi_imag");
            qd_json_begin_array(j);
            for (size_t c = 0; c < y->nclass; c++)
                qd_json_number(j, y->chi_im[i * y->nclass + c]);
            qd_json_end_array(j);
        }
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_classes(const qd_symmetry *y, qd_json *j) {
    qd_json_key(j, "classes");
    qd_json_begin_array(j);
    for (size_t c = 0; c < y->nclass; c++) {
        char name[24];
        qd_symmetry_class_name(y, c, name, sizeof name);
        qd_json_begin_object(j);
        qd_json_key(j, "name");
        qd_json_string(j, name);
        qd_json_key(j, "size");
        qd_json_number(j, (double)y->class_size[c]);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_blocks(const qd_symmetry *y, const qd_eom *e, qd_json *j) {
    size_t n = y->n;
    qd_json_key(j, "blocks");
    qd_json_begin_array(j);
    for (size_t k = 0; k < y->nblock; k++) {
        char lab[32];
        size_t s0 = y->block_start[k], m = y->block_size[k];
        qd_symmetry_block_label(y, k, lab, sizeof lab);
        qd_json_begin_object(j);
        qd_json_key(j, "irrep");
        qd_json_string(j, lab);
        qd_json_key(j, "K");
        qd_json_begin_array(j);
        for (size_t a = 0; a < m; a++) {
            qd_json_begin_array(j);
            for (size_t c = 0; c < m; c++)
                qd_json_number(j, y->Kb[(s0 + a) * n + s0 + c]);
            qd_json_end_array(j);
        }
        qd_json_end_array(j);
        qd_json_key(j, "coordinates");
        qd_json_begin_array(j);
        for (size_t a = 0; a < m; a++) {
            qd_json_begin_object(j);
            for (size_t i = 0; i < n; i++) {
                qd_json_key(j, qd_expr_name(e->q[i]));
                qd_json_number(j, y->U[i * n + s0 + a]);
            }
            qd_json_end_object(j);
        }
        qd_json_end_array(j);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_group(const qd_symmetry *y, const qd_eom *e, qd_json *j) {
    qd_json_key(j, "group");
    if (y->name[0])
        qd_json_string(j, y->name);
    else
        qd_json_null(j);
    qd_json_key(j, "order");
    qd_json_number(j, (double)y->order);
    json_classes(y, j);
    json_characters(y, j);
    qd_json_key(j, "reducible");
    qd_json_begin_array(j);
    for (size_t c = 0; c < y->nclass; c++)
        qd_json_number(j, y->chi[c]);
    qd_json_end_array(j);
    qd_json_key(j, "multiplicities");
    qd_json_begin_object(j);
    for (size_t i = 0; i < y->nirrep; i++) {
        qd_json_key(j, y->label[i]);
        qd_json_number(j, (double)y->mult[i]);
    }
    qd_json_end_object(j);
    json_blocks(y, e, j);
}

void cli_sym_put_json(const cli_sym_run *s, const qd_eom *e, qd_json *j) {
    qd_json_key(j, "symmetry");
    qd_json_begin_object(j);
    if (s->cyc.n) {
        qd_json_key(j, "group");
        qd_json_string(j, "cyclic");
        qd_json_key(j, "order");
        qd_json_number(j, (double)s->cyc.cells);
        qd_json_key(j, "cell");
        qd_json_number(j, (double)s->cyc.cell);
        qd_json_key(j, "fast_path");
        qd_json_bool(j, true);
    } else {
        json_group(&s->sym, e, j);
    }
    qd_json_end_object(j);
}

static void json_sym_mode(const qd_symmetry *y, const qd_eom *e, size_t k, qd_json *j) {
    char lab[32];
    qd_symmetry_block_label(y, y->mode_block[k], lab, sizeof lab);
    qd_json_begin_object(j);
    qd_json_frequency(j, y->omega2[k]);
    qd_json_key(j, "irrep");
    qd_json_string(j, lab);
    qd_json_key(j, "multiplicity");
    qd_json_number(j, (double)y->mode_degeneracy[k]);
    qd_json_key(j, "kind");
    qd_json_string(j, kind_name(y->mode_kind[k]));
    qd_json_key(j, "shape");
    qd_json_begin_object(j);
    for (size_t i = 0; i < y->n; i++) {
        qd_json_key(j, qd_expr_name(e->q[i]));
        qd_json_number(j, y->shapes[i * y->n + k]);
    }
    qd_json_end_object(j);
    qd_json_end_object(j);
}

void cli_sym_json_modes(const cli_sym_run *s, const qd_eom *e, qd_json *j) {
    qd_json_key(j, "modes");
    qd_json_begin_array(j);
    for (size_t k = 0; k < s->cyc.n; k++) {
        char lab[32];
        snprintf(lab, sizeof lab, "k=%zu", s->cyc.harmonic[k]);
        qd_json_begin_object(j);
        qd_json_frequency(j, s->cyc.omega2[k]);
        qd_json_key(j, "irrep");
        qd_json_string(j, lab);
        qd_json_key(j, "harmonic");
        qd_json_number(j, (double)s->cyc.harmonic[k]);
        qd_json_key(j, "multiplicity");
        qd_json_number(j, (double)s->cyc.degeneracy[k]);
        qd_json_end_object(j);
    }
    for (size_t k = 0; !s->cyc.n && k < s->sym.n; k++)
        json_sym_mode(&s->sym, e, k, j);
    qd_json_end_array(j);
}
