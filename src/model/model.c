/*
 * src/model/model.c - the parsed model: storage and accessors.
 */
#include "parser.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool qd__mdl_push(qd_ctx *ctx, void **arr, size_t *n, size_t size, const void *item) {
    /* grow by doubling; capacity is implied by n (powers of two) */
    size_t cap = 1;
    while (cap < *n)
        cap *= 2;
    if (*n == 0 || *n == cap) {
        void *a = qd__realloc(ctx, *arr, (*n ? 2 * cap : 4) * size);
        if (!a)
            return false;
        *arr = a;
    }
    memcpy((char *)*arr + *n * size, item, size);
    (*n)++;
    return true;
}

const def *qd__mdl_find_def(const qd_model *m, const char *name, size_t n) {
    long i = qd__mdl_names_find(m, QD_MDL_NAME_DEF, name, n);
    return i >= 0 ? &m->defs[i] : NULL;
}

bool qd__mdl_add_def(qd_model *m, const char *name, value v, size_t off, size_t len) {
    char *copy = qd__malloc(m->ctx, strlen(name) + 1);
    if (!copy)
        return false;
    strcpy(copy, name);
    def d = {copy, v, off, len};
    if (!qd__mdl_push(m->ctx, (void **)&m->defs, &m->ndefs, sizeof d, &d)) {
        qd__free(copy);
        return false;
    }
    return qd__mdl_names_add(m, QD_MDL_NAME_DEF, m->ndefs - 1);
}

bool qd__mdl_add_where(qd_model *m, const char *what, size_t off, size_t len) {
    where w;
    snprintf(w.what, sizeof w.what, "%s", what);
    w.src = m->src;
    w.off = off;
    w.len = len;
    return qd__mdl_push(m->ctx, (void **)&m->wheres, &m->nwheres, sizeof w, &w) &&
           qd__mdl_names_add(m, QD_MDL_NAME_WHERE, m->nwheres - 1);
}

int qd__mdl_coord_index(const qd_model *m, const qd_expr *sym) {
    for (size_t i = 0; i < m->ncoords; i++)
        if (m->coords[i] == sym)
            return (int)i;
    return -1;
}

void qd_model_free(qd_model *m) {
    if (!m)
        return;
    qd__mdl_free_field(m);
    for (size_t i = 0; i < m->ndefs; i++)
        qd__free((char *)m->defs[i].name);
    for (size_t i = 0; i < m->nfuncs; i++)
        qd__free((char *)m->funcs[i]);
    for (size_t i = 0; i < m->ncons; i++)
        qd__free((char *)m->con_names[i]);
    for (size_t i = 0; i < m->nbodies; i++)
        qd__free((char *)m->bodies[i].name);
    qd__free(m->bodies);
    for (size_t i = 0; i < m->nreactions; i++)
        qd__free((char *)m->reactions[i].name);
    qd__free(m->reactions);
    for (size_t i = 0; i < m->nsyms; i++) {
        qd__free((char *)m->syms[i].name);
        qd__free(m->syms[i].xi);
    }
    qd__free(m->syms);
    for (size_t i = 0; i < m->nints; i++)
        qd__free((char *)m->ints[i].name);
    qd__free(m->ints);
    qd__mdl_free_blows(m->blows, 0, m->nblows);
    qd__free(m->blows);
    qd__mdl_free_sudden(m->sudden, 0, m->nsudden);
    qd__free(m->sudden);
    qd__mdl_free_sudden(m->impacts, 0, m->nimpacts);
    qd__free(m->impacts);
    qd__mdl_free_sudden(m->prescribed, 0, m->nprescribed);
    qd__free(m->prescribed);
    qd__free(m->speeds);
    qd__mdl_free_io(m);
    qd__mdl_free_friction(m);
    qd__free(m->parts);
    qd__free(m->Qhat);
    qd__free(m->mom);
    qd__free(m->con_names);
    qd__free(m->cons);
    qd__free(m->coords);
    qd__free(m->params);
    qd__free(m->pdefs);
    qd__free(m->pvals);
    qd__free(m->pfixed);
    for (size_t i = 0; i < m->nadded; i++)
        qd__free(m->added[i]);
    qd__free(m->added);
    qd__free(m->funcs);
    qd__free(m->defs);
    qd__free(m->Q);
    qd__free(m->init);
    qd__free(m->init_defs);
    qd__free(m->wheres);
    qd__mdl_names_free(m);
    qd__mdl_free_isoperimetric(m);
    qd__free(m);
}

size_t qd_model_ncoords(const qd_model *m) { QD_ARGS(0, m); return m->ncoords; }
const qd_expr *qd_model_coord(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->ncoords ? m->coords[i] : NULL;
}
size_t qd_model_nparams(const qd_model *m) { QD_ARGS(0, m); return m->nparams; }
size_t qd_model_nfunctions(const qd_model *m) { QD_ARGS(0, m); return m->nfuncs; }
const char *qd_model_function_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nfuncs ? m->funcs[i] : NULL;
}
const qd_expr *qd_model_param(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nparams ? m->params[i] : NULL;
}
const qd_expr *qd_model_param_value(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nparams ? m->pvals[i] : NULL;
}

const qd_expr *qd_model_param_definition(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nparams ? m->pdefs[i] : NULL;
}

qd_status qd_model_param_number(const qd_model *m, size_t i, double *x) {
    QD_ARGS(QD_ERR_ARG, m && x);
    long p, q;
    const qd_expr *v = i < m->nparams ? m->pvals[i] : NULL;
    *x = NAN;
    if (v && qd_rational_get(v, &p, &q) && fabs((double)p) <= 0x1p53 && (double)q <= 0x1p53)
        *x = (double)p / (double)q; /* both exact in a double: one rounding */
    else if (v && qd_eval(m->ctx, v, 0, NULL, NULL, x) != QD_OK) {
        *x = NAN;
        if (!qd__ctx_recover(m->ctx)) /* out of memory stays recorded */
            return QD_ERR_NOMEM;
    }
    return isfinite(*x) ? QD_OK : QD_ERR_ARG;
}

bool qd_model_param_fixed(const qd_model *m, size_t i) { QD_ARGS(false, m); return i < m->nparams && m->pfixed[i]; }

const qd_expr *qd__mdl_subs_params(const qd_model *m, const qd_expr *x, size_t n) {
    if (!x)
        return NULL;
    enum { FEW = 16 };
    const qd_expr *few[3 * FEW], **sym = few;
    size_t ns = qd_free_symbols(m->ctx, x, few, FEW);
    if (ns == 0)
        return qd__ctx_nomem(m->ctx) ? NULL : x;
    if (ns > FEW) {
        if (!(sym = qd__malloc(m->ctx, 3 * ns * sizeof *sym)))
            return NULL;
        qd_free_symbols(m->ctx, x, sym, ns);
    }
    const qd_expr **from = sym + ns, **to = sym + 2 * ns;
    size_t k = 0;
    for (size_t i = 0; i < ns; i++) {
        const char *name = qd_expr_name(sym[i]);
        long j = name ? qd__mdl_names_find(m, QD_MDL_NAME_PARAM, name, strlen(name)) : -1;
        if (j >= 0 && (size_t)j < n && m->params[j] == sym[i]) {
            from[k] = sym[i];
            to[k++] = m->pvals[j];
        }
    }
    const qd_expr *r = k ? qd_subs(m->ctx, x, k, from, to) : x;
    if (sym != few)
        qd__free(sym);
    return r;
}

/* x with the values of the first n parameters put in. */
static const qd_expr *valued(const qd_model *m, const qd_expr *x, size_t n) {
    return qd__mdl_subs_params(m, x, n);
}

bool qd__mdl_eval_params(qd_model *m) {
    for (size_t i = 0; i < m->nparams; i++)
        if (!(m->pvals[i] = valued(m, m->pdefs[i], i)))
            return false;
    for (size_t j = 0; j < 2 * m->ncoords; j++)
        if (m->init_defs[j] && !(m->init[j] = valued(m, m->init_defs[j], m->nparams)))
            return false;
    for (size_t k = 0; k < m->nspeeds; k++) {
        speed *s = &m->speeds[k];
        if (s->init_def && !(s->init = valued(m, s->init_def, m->nparams)))
            return false;
    }
    return true;
}

qd_status qd__mdl_unknown_param(qd_ctx *ctx, const qd_model *m, const char *name) {
    const char **names = qd__malloc(ctx, (m->nparams + 1) * sizeof *names);
    if (!names) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    for (size_t i = 0; i < m->nparams; i++)
        names[i] = qd_expr_name(m->params[i]);
    const char *near = qd__diag_nearest(name, strlen(name), names, m->nparams);
    if (near)
        qd_ctx_error(ctx, QD_ERR_ARG, "unknown parameter '%s'; did you mean '%s'?", name, near);
    else
        qd_ctx_error(ctx, QD_ERR_ARG, "unknown parameter '%s'", name);
    qd__free(names);
    return QD_ERR_ARG;
}

qd_status qd_model_set_param(qd_ctx *ctx, qd_model *m, const char *name, const qd_expr *value) {
    QD_ARGS_CTX(ctx, ctx && m && name && value);
    size_t i = 0;
    while (i < m->nparams && strcmp(qd_expr_name(m->params[i]), name) != 0)
        i++;
    if (i == m->nparams)
        return qd__mdl_unknown_param(ctx, m, name);
    if (!value || !qd_is_number(value)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "the value of '%s' must be a number", name);
        return QD_ERR_ARG;
    }
    if (m->pfixed[i]) {
        qd_ctx_error(ctx, QD_ERR_ARG, "'%s' is fixed in this model: it was given when the model "
                     "was read", name);
        return QD_ERR_ARG;
    }
    const qd_expr *old = m->pdefs[i];
    m->pdefs[i] = value;
    const char *bad = NULL;
    qd_status st = qd__mdl_eval_params(m) ? QD_OK : QD_ERR_NOMEM;
    bool sign = false; /* a parameter assumed positive would become <= 0 */
    for (size_t j = i; st == QD_OK && j < m->nparams && !bad; j++) {
        double x;
        if (qd_eval(ctx, m->pvals[j], 0, NULL, NULL, &x) != QD_OK || !isfinite(x))
            bad = qd_expr_name(m->params[j]);
        else if (x <= 0 && qd_symbol_is_positive(m->params[j]))
            bad = qd_expr_name(m->params[j]), sign = true;
    }
    if (st == QD_OK && !bad)
        return QD_OK;
    m->pdefs[i] = old; /* back to the values before */
    qd__mdl_eval_params(m);
    if (bad) {
        qd__ctx_recover(ctx);
        if (sign)
            qd_ctx_error(ctx, QD_ERR_ARG, "with this value of '%s', '%s' would be zero or "
                         "negative, but it was positive when the model was read and the "
                         "equations assume so; give the value when reading the model "
                         "(--set)", name, bad);
        else
            qd_ctx_error(ctx, QD_ERR_ARG, "with this value of '%s', '%s' is not a finite number",
                         name, bad);
        return QD_ERR_ARG;
    }
    return qd_ctx_status(ctx) != QD_OK ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
}

const qd_expr *qd_model_kinetic(const qd_model *m) { QD_ARGS(NULL, m); return m->T; }
const qd_expr *qd_model_potential(const qd_model *m) { QD_ARGS(NULL, m); return m->V; }
const qd_expr *qd_model_gen_potential(const qd_model *m) { QD_ARGS(NULL, m); return m->U; }
const qd_expr *qd_model_lagrangian(const qd_model *m) { QD_ARGS(NULL, m); return m->L; }
const qd_expr *qd_model_dissipation(const qd_model *m) { QD_ARGS(NULL, m); return m->D; }

bool qd_model_lagrangian_given(const qd_model *m) { QD_ARGS(false, m); return qd_model_where(m, "L", NULL); }

const qd_expr *qd_model_force(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->ncoords ? m->Q[i] : NULL;
}

size_t qd_model_nconstraints(const qd_model *m) { QD_ARGS(0, m); return m->ncons; }
const char *qd_model_constraint_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->ncons ? m->con_names[i] : NULL;
}
const qd_expr *qd_model_constraint(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->ncons ? m->cons[i] : NULL;
}

size_t qd_model_nbodies(const qd_model *m) { QD_ARGS(0, m); return m->nbodies; }

static const body *body_at(const qd_model *m, size_t i) {
    return i < m->nbodies ? &m->bodies[i] : NULL;
}

const char *qd_model_body_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const body *b = body_at(m, i);
    return b ? b->name : NULL;
}

const qd_expr *qd_model_body_mass(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    const body *b = body_at(m, i);
    return b ? b->mass : NULL;
}

const qd_expr *qd_model_body_inertia(const qd_model *m, size_t i, unsigned row, unsigned col) {
    QD_ARGS(NULL, m);
    const body *b = body_at(m, i);
    return b && row < 3 && col < 3 ? b->I[3 * row + col] : NULL;
}

qd_body_shape qd_model_body_shape(const qd_model *m, size_t i, const qd_expr *size[3],
                                  int *axis) {
    QD_ARGS(QD_SHAPE_NONE, m);
    const body *b = body_at(m, i);
    for (int k = 0; size && k < 3; k++)
        size[k] = b ? b->size[k] : NULL;
    if (axis)
        *axis = b && b->shape ? b->axis : 2;
    return b ? (qd_body_shape)b->shape : QD_SHAPE_NONE;
}

bool qd_model_body_ground(const qd_model *m, size_t i, const qd_expr *n[3],
                          const qd_expr *r0[3]) {
    QD_ARGS(false, m && n && r0);
    const body *b = body_at(m, i);
    if (!b || !b->ground[0])
        return false;
    memcpy(n, b->ground, 3 * sizeof *n);
    memcpy(r0, b->ground + 3, 3 * sizeof *r0);
    return true;
}

const qd_expr *qd_model_body_position(const qd_model *m, size_t i, unsigned k) {
    QD_ARGS(NULL, m);
    const body *b = body_at(m, i);
    return b && k < 3 ? b->r[k] : NULL;
}

const qd_expr *qd_model_body_rotation(const qd_model *m, size_t i, unsigned row, unsigned col) {
    QD_ARGS(NULL, m);
    const body *b = body_at(m, i);
    return b && row < 3 && col < 3 ? b->R[3 * row + col] : NULL;
}

const qd_expr *qd_model_body_omega(const qd_model *m, size_t i, unsigned k) {
    QD_ARGS(NULL, m);
    const body *b = body_at(m, i);
    return b && k < 3 ? b->w[k] : NULL;
}

const qd_expr *qd_model_body_omega_space(const qd_model *m, size_t i, unsigned k) {
    QD_ARGS(NULL, m);
    const body *b = body_at(m, i);
    return b && k < 3 ? b->ws[k] : NULL;
}

bool qd_model_hamiltonian_given(const qd_model *m) { QD_ARGS(false, m); return m->H != NULL; }
const qd_expr *qd_model_hamiltonian(const qd_model *m) { QD_ARGS(NULL, m); return m->H; }
const qd_expr *qd_model_momentum(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return m->mom && i < m->ncoords ? m->mom[i] : NULL;
}

size_t qd_model_nsymmetries(const qd_model *m) { QD_ARGS(0, m); return m->nsyms; }
const char *qd_model_symmetry_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nsyms ? m->syms[i].name : NULL;
}
const qd_expr *qd_model_symmetry_field(const qd_model *m, size_t i, size_t coord) {
    QD_ARGS(NULL, m);
    return i < m->nsyms && coord < m->ncoords ? m->syms[i].xi[coord] : NULL;
}

size_t qd_model_nintegrals(const qd_model *m) { QD_ARGS(0, m); return m->nints; }
const char *qd_model_integral_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nints ? m->ints[i].name : NULL;
}
const qd_expr *qd_model_integral(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nints ? m->ints[i].expr : NULL;
}

const qd_expr *qd__mdl_find_momentum(const qd_model *m, const char *name, size_t n) {
    for (size_t i = 0; m->mom && i < m->ncoords; i++)
        if (m->mom[i] && qd__mdl_name_is(name, 0, n, qd_expr_name(m->mom[i])))
            return m->mom[i];
    return NULL;
}

const qd_expr *qd_model_initial(const qd_model *m, size_t coord, unsigned order) {
    QD_ARGS(NULL, m);
    return coord < m->ncoords && order < 2 ? m->init[2 * coord + order] : NULL;
}

const qd_expr *qd_model_initial_definition(const qd_model *m, size_t coord, unsigned order) {
    QD_ARGS(NULL, m);
    return coord < m->ncoords && order < 2 ? m->init_defs[2 * coord + order] : NULL;
}

const qd_expr *qd_model_definition(const qd_model *m, const char *name) {
    QD_ARGS(NULL, m && name);
    const def *d = qd__mdl_find_def(m, name, strlen(name));
    return d && d->v.kind == VK_SCALAR ? d->v.c[0] : NULL;
}

qd_ctx *qd_model_ctx(const qd_model *m) {
    QD_ARGS(NULL, m);
    return m->ctx;
}

size_t qd_model_ndefinitions(const qd_model *m) {
    QD_ARGS(0, m);
    return m->ndefs;
}

const char *qd_model_definition_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->ndefs ? m->defs[i].name : NULL;
}

size_t qd_model_definition_size(const qd_model *m, size_t i) {
    QD_ARGS(0, m);
    if (i >= m->ndefs)
        return 0;
    vkind k = m->defs[i].v.kind;
    return k == VK_SCALAR ? 1 : k == VK_VECTOR ? 3 : 9;
}

const qd_expr *qd_model_definition_component(const qd_model *m, size_t i, size_t k) {
    QD_ARGS(NULL, m);
    return k < qd_model_definition_size(m, i) ? m->defs[i].v.c[k] : NULL;
}

bool qd_model_where(const qd_model *m, const char *what, qd_diag *out) {
    QD_ARGS(false, m && what);
    long i = qd__mdl_names_find(m, QD_MDL_NAME_WHERE, what, strlen(what));
    if (i >= 0) {
        const where *w = &m->wheres[i];
        if (out) {
            memset(out, 0, sizeof *out);
            out->located = true;
            out->offset = w->off;
            out->length = w->len;
            qd__diag_line_col(w->src, w->off, &out->line, &out->col, NULL);
        }
        return true;
    }
    return false;
}
