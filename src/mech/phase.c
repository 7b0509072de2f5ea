/*
 * src/mech/phase.c - a model's phase space for brackets and canonical maps
 * (qdot/canonical.h): the coordinates with their momenta named as
 * hamilton.h names them, functions on it read from text, H, dF/dt along
 * the motion, and the new variables of a transformation.
 */
#include <stdio.h>
#include <string.h>
#include "qdot/canonical.h"
#include "qdot/read.h"
#include "base/args.h"
#include "base/mem.h"

qd_status qd_phase_init(qd_ctx *ctx, const qd_model *m, qd_phase *out) {
    QD_ARGS_CTX(ctx, ctx && m && out);
    size_t n = qd_model_ncoords(m);
    *out = (qd_phase){.n = n, .m = m};
    out->q = qd__calloc(ctx, n + 1, sizeof *out->q);
    out->p = qd__calloc(ctx, n + 1, sizeof *out->p);
    if (!out->q || !out->p) {
        qd_phase_free(out);
        return QD_ERR_NOMEM;
    }
    for (size_t j = 0; j < n; j++) {
        char name[256];
        out->q[j] = qd_model_coord(m, j);
        snprintf(name, sizeof name, "p_%s", qd_expr_name(out->q[j]));
        /* the model's own name (`momenta`), else p_<q>; a parameter already
         * named p_x cannot also be the momentum */
        const qd_expr *named = qd_model_momentum(m, j);
        if (!(out->p[j] = named ? named : qd_symbol(ctx, name))) {
            qd_status st = qd_ctx_status(ctx);
            qd_phase_free(out);
            return st;
        }
    }
    return QD_OK;
}

qd_status qd_phase_new_vars(qd_ctx *ctx, qd_phase *ph) {
    QD_ARGS_CTX(ctx, ctx && ph);
    size_t n = ph->n;
    if (!ph->Q)
        ph->Q = qd__calloc(ctx, n + 1, sizeof *ph->Q);
    if (!ph->P)
        ph->P = qd__calloc(ctx, n + 1, sizeof *ph->P);
    if (!ph->Q || !ph->P)
        return QD_ERR_NOMEM;
    for (size_t k = 0; k < 2 * n; k++) {
        char name[32];
        snprintf(name, sizeof name, n == 1 ? "%c" : "%c%zu", k < n ? 'Q' : 'P', k % n + 1);
        const qd_expr *s = qd_symbol(ctx, name);
        if (!s)
            return qd_ctx_status(ctx);
        (k < n ? ph->Q : ph->P)[k % n] = s;
    }
    return QD_OK;
}

/* A parameter the model was read with a fixed value has its number in the
 * model's expressions: the same in what the user writes beside them. */
static const qd_expr *ph_fixed_values(qd_ctx *ctx, const qd_model *m, const qd_expr *x) {
    for (size_t i = 0; x && i < qd_model_nparams(m); i++)
        if (qd_model_param_fixed(m, i)) {
            const qd_expr *p = qd_model_param(m, i), *v = qd_model_param_value(m, i);
            x = qd_subs(ctx, x, 1, &p, &v);
        }
    return x;
}

/* Velocities have no place in a function on phase space: the first one in
 * x refused, located at its name in text when it is written there. */
static bool ph_no_velocity(qd_ctx *ctx, const qd_phase *ph, const char *text, const qd_expr *x,
                           qd_diag *err) {
    for (size_t j = 0; j < ph->n; j++)
        for (unsigned k = 1; k <= 2; k++) {
            const qd_expr *v = qd_jet(ctx, ph->q[j], k);
            if (!v || !qd_has(x, v))
                continue;
            const char *at = strstr(text, qd_expr_name(v));
            *err = (qd_diag){.status = QD_ERR_ARG, .subject = QD_SUBJECT_TEXT, .located = true,
                             .offset = at ? (size_t)(at - text) : 0,
                             .length = at ? strlen(qd_expr_name(v)) : strlen(text) + !*text};
            snprintf(err->message, sizeof err->message,
                     "the velocity %s has no place in a function on phase space",
                     qd_expr_name(v));
            snprintf(err->hint, sizeof err->hint, "write functions of %s and %s",
                     qd_expr_name(ph->q[j]), qd_expr_name(ph->p[j]));
            return false;
        }
    return true;
}

const qd_expr *qd_phase_read(qd_ctx *ctx, const qd_phase *ph, const char *text, qd_diag *err) {
    QD_ARGS(NULL, ctx && ph && text && err);
    qd_read_opts opts = {.new_symbols = false};
    const qd_expr *x = qd_read(ctx, text, &opts, err);
    if (!x)
        return NULL;
    if (!(x = ph_fixed_values(ctx, ph->m, x))) {
        *err = *qd_ctx_diag(ctx);
        return NULL;
    }
    return ph_no_velocity(ctx, ph, text, x, err) ? x : NULL;
}

qd_status qd_phase_read_list(qd_ctx *ctx, const qd_phase *ph, const char *text,
                             const qd_expr **out, qd_diag *err) {
    QD_ARGS_CTX(ctx, ctx && ph && text && out && err);
    size_t k = 0, start = 0, len = strlen(text);
    char *item = qd__malloc(ctx, len + 1);
    if (!item)
        return QD_ERR_NOMEM;
    qd_status st = QD_OK;
    for (size_t i = 0, depth = 0; st == QD_OK; i++) {
        depth += text[i] == '(' ? 1 : text[i] == ')' && depth ? (size_t)-1 : 0;
        if (text[i] && (text[i] != ',' || depth))
            continue;
        if (k++ < ph->n) {
            memcpy(item, text + start, i - start);
            item[i - start] = '\0';
            if (!(out[k - 1] = qd_phase_read(ctx, ph, item, err))) {
                err->offset += start; /* into the whole list */
                st = err->status ? err->status : QD_ERR_PARSE;
            }
        }
        if (!text[i])
            break;
        start = i + 1;
    }
    qd__free(item);
    if (st == QD_OK && k != ph->n) {
        *err = (qd_diag){.status = QD_ERR_ARG, .subject = QD_SUBJECT_TEXT, .located = true,
                         .length = len + !len};
        snprintf(err->message, sizeof err->message, "%zu expression%s for %zu coordinate%s",
                 k, k == 1 ? "" : "s", ph->n, ph->n == 1 ? "" : "s");
        snprintf(err->hint, sizeof err->hint, "the list needs %zu, one per coordinate, "
                 "separated by commas", ph->n);
        st = QD_ERR_ARG;
    }
    return st;
}

qd_status qd_phase_ham(qd_ctx *ctx, qd_phase *ph, bool closed) {
    QD_ARGS_CTX(ctx, ctx && ph);
    /* a model given by H needs no equations of motion for its brackets */
    if (!ph->e && !qd_model_hamiltonian_given(ph->m) && !(ph->e = qd_eom_derive(ctx, ph->m)))
        return qd_ctx_status(ctx);
    if (!ph->h && !(ph->h = qd_ham_derive(ctx, ph->m, ph->e)))
        return qd_ctx_status(ctx);
    if (closed && ph->h->implicit) { /* K = H + dF/dt in new variables needs H itself */
        qd_ctx_error(ctx, QD_ERR_NONLINEAR,
                     "a generating function's new Hamiltonian needs H in closed form, but L is "
                     "not quadratic in the velocities and p = dL/dq' has no closed-form "
                     "solution for q' here (H is defined implicitly)");
        return QD_ERR_NONLINEAR;
    }
    for (size_t j = 0; j < ph->n; j++)
        if (ph->h->p[j] != ph->p[j]) {
            qd_ctx_error(ctx, QD_ERR_ARG, "the Hamiltonian names its momentum %s, not %s",
                         qd_expr_name(ph->h->p[j]), qd_expr_name(ph->p[j]));
            return QD_ERR_ARG;
        }
    return QD_OK;
}

/* dF/dt from Hamilton's equations as qd_ham_derive gives them,
 * dq_j/dt = dH/dp_j and dp_j/dt = -dH/dq_j + extra_j:
 *
 *     dF/dt = dF/dt|explicit + sum_j (dF/dq_j dq_j/dt + dF/dp_j dp_j/dt),
 *
 * i.e. [F, H] plus the forces' part.  Taking the equations rather than
 * differentiating H serves an implicit H too (there dq_j/dt = q'_j and
 * dp_j/dt = dL/dq_j + extra_j, exact, q' the solution of p = dL/dq'). */
const qd_expr *qd_phase_dt(qd_ctx *ctx, qd_phase *ph, const qd_expr *F) {
    QD_ARGS(NULL, ctx && ph && F);
    if (qd_phase_ham(ctx, ph, false) != QD_OK)
        return NULL;
    const qd_ham *h = ph->h;
    const qd_expr *d = qd_diff(ctx, F, qd_time(ctx));
    for (size_t j = 0; j < ph->n; j++)
        d = qd_add(ctx, d, qd_add(ctx, qd_mul(ctx, qd_diff(ctx, F, ph->q[j]), h->dq[j]),
                                  qd_mul(ctx, qd_diff(ctx, F, ph->p[j]), h->dp[j])));
    return d ? qd_simplify(ctx, d) : NULL;
}

void qd_phase_free(qd_phase *ph) {
    if (!ph)
        return;
    qd_ham_free(ph->h);
    if (ph->e)
        qd_eom_free(ph->e);
    qd__free(ph->q);
    qd__free(ph->p);
    qd__free(ph->Q);
    qd__free(ph->P);
    *ph = (qd_phase){0};
}
