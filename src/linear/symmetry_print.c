/*
 * src/linear/symmetry_print.c - the symmetry of small oscillations as text
 * or JSON (qdot/symmetry.h): the group, the character table, the reducible
 * character and its decomposition, the symmetry coordinates, K0 by blocks
 * and the modes labelled by irreps (qd_symmetry_print, qd_symmetry_json,
 * qd_symmetry_json_modes), and the modes of the cyclic fast path by
 * harmonics (qd_cyclic_print, qd_cyclic_json, qd_cyclic_json_modes).  What
 * `qdot modes --symmetry` prints, for any caller.
 */
#include "qdot/symmetry.h"
#include "qdot/json.h"
#include "../base/args.h"

#include <math.h>
#include <stdio.h>

const char *qd_mode_kind_name(qd_mode_kind k) {
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

/* The largest |A[i][col]| of the n*n matrix A: the scale of a column that
 * is one vector (a mode shape, a symmetry coordinate), whose entries are
 * small together when M0 is large. */
static double column_scale(const double *A, size_t n, size_t col) {
    double s = 0;
    for (size_t i = 0; i < n; i++)
        s = fmax(s, fabs(A[i * n + col]));
    return s;
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
            double scale = column_scale(y->U, n, col);
            for (size_t i = 0; i < n; i++) {
                qd_buf_printf(b, "%s%s = ", i ? ", " : "", qd_expr_name(e->q[i]));
                qd_buf_put_result(b, y->U[i * n + col], scale);
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
                qd_buf_put_result(b, y->Kb[(s0 + i) * n + s0 + j], 1);
            }
            qd_buf_puts(b, "]");
        }
        qd_buf_puts(b, "]\n");
    }
}

static void put_w2(qd_buf *b, double w2) {
    qd_buf_put_result(b, w2, 1);
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
            qd_buf_printf(b, ", %s", qd_mode_kind_name(y->mode_kind[j]));
        qd_buf_puts(b, "\n  shape: ");
        double scale = column_scale(y->shapes, n, j);
        for (size_t i = 0; i < n; i++) {
            qd_buf_printf(b, "%s%s = ", i ? ", " : "", qd_expr_name(e->q[i]));
            qd_buf_put_result(b, y->shapes[i * n + j], scale);
        }
        qd_buf_puts(b, "\n");
    }
}

/* A reduced qd_symmetry (qd_symmetry_reduce) on the coordinates of e. */
static bool reduced(const qd_symmetry *y, const qd_eom *e) {
    return y->n && y->n == e->n && y->nclass && y->chi_re && y->chi_im && y->label && y->chi &&
           y->mult && y->block_start && y->block_size && y->block_irrep && y->U && y->Kb &&
           y->omega2 && y->shapes && y->mode_block && y->mode_degeneracy && y->mode_kind;
}

static bool cyclic_ok(const qd_cyclic_modes *c) {
    return c->n && c->omega2 && c->harmonic && c->degeneracy;
}

qd_status qd_symmetry_print(const qd_symmetry *sym, const qd_eom *e, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, sym && e && out);
    if (!reduced(sym, e))
        return QD_ERR_ARG;
    put_group(sym, out);
    put_decomposition(sym, out);
    put_coordinates(sym, e, out);
    put_blocks(sym, out);
    put_modes(sym, e, out);
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

qd_status qd_cyclic_print(const qd_cyclic_modes *c, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, c && out);
    if (!cyclic_ok(c))
        return QD_ERR_ARG;
    qd_buf_printf(out, "symmetry: the shift of the coordinates by %zu (cyclic group C%zu: %zu "
                       "cells of %zu); fast path, one pencil per harmonic k = 0..%zu\n",
                  c->cell, c->cells, c->cells, c->cell, c->cells / 2);
    for (size_t j = 0; j < c->n; j++) {
        qd_buf_printf(out, "mode %zu: w^2 = ", j + 1);
        put_w2(out, c->omega2[j]);
        qd_buf_printf(out, ", harmonic k = %zu (multiplicity %zu)\n", c->harmonic[j],
                      c->degeneracy[j]);
    }
    return out->failed ? QD_ERR_NOMEM : QD_OK;
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

void qd_symmetry_json(qd_json *j, const qd_symmetry *sym, const qd_eom *e) {
    QD_ARGS(, j && sym && e);
    if (!reduced(sym, e))
        return;
    qd_json_key(j, "symmetry");
    qd_json_begin_object(j);
    json_group(sym, e, j);
    qd_json_end_object(j);
}

void qd_cyclic_json(qd_json *j, const qd_cyclic_modes *c) {
    QD_ARGS(, j && c);
    if (!cyclic_ok(c))
        return;
    qd_json_key(j, "symmetry");
    qd_json_begin_object(j);
    qd_json_key(j, "group");
    qd_json_string(j, "cyclic");
    qd_json_key(j, "order");
    qd_json_number(j, (double)c->cells);
    qd_json_key(j, "cell");
    qd_json_number(j, (double)c->cell);
    qd_json_key(j, "fast_path");
    qd_json_bool(j, true);
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
    qd_json_string(j, qd_mode_kind_name(y->mode_kind[k]));
    qd_json_key(j, "shape");
    qd_json_begin_object(j);
    for (size_t i = 0; i < y->n; i++) {
        qd_json_key(j, qd_expr_name(e->q[i]));
        qd_json_number(j, y->shapes[i * y->n + k]);
    }
    qd_json_end_object(j);
    qd_json_end_object(j);
}

void qd_symmetry_json_modes(qd_json *j, const qd_symmetry *sym, const qd_eom *e) {
    QD_ARGS(, j && sym && e);
    if (!reduced(sym, e))
        return;
    qd_json_key(j, "modes");
    qd_json_begin_array(j);
    for (size_t k = 0; k < sym->n; k++)
        json_sym_mode(sym, e, k, j);
    qd_json_end_array(j);
}

void qd_cyclic_json_modes(qd_json *j, const qd_cyclic_modes *c) {
    QD_ARGS(, j && c);
    if (!cyclic_ok(c))
        return;
    qd_json_key(j, "modes");
    qd_json_begin_array(j);
    for (size_t k = 0; k < c->n; k++) {
        char lab[32];
        snprintf(lab, sizeof lab, "k=%zu", c->harmonic[k]);
        qd_json_begin_object(j);
        qd_json_frequency(j, c->omega2[k]);
        qd_json_key(j, "irrep");
        qd_json_string(j, lab);
        qd_json_key(j, "harmonic");
        qd_json_number(j, (double)c->harmonic[k]);
        qd_json_key(j, "multiplicity");
        qd_json_number(j, (double)c->degeneracy[k]);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}
