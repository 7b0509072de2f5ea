/*
 * src/model/io.c - a model's inputs and outputs, for control:
 *
 *   inputs F, tau                 signals supplied at run time (u)
 *   outputs y1 = EXPR, ...        measured quantities (y = C x + D u)
 *
 * An input is a plain symbol: the derivation keeps it by name (Q[x] = F
 * gives the equation ... = F), and the numbers need its value (qd_sim's
 * input sources, qd_linearize's operating point).  Being plain, it has no
 * time derivative, so it may stand where Lagrange's equations never
 * differentiate it in time: forces, torques, Q[q], V, the dissipation
 * function, and the velocity-free part of L.  Where d/dt(dL/dq') would
 * reach it (T, U, L in the velocities) or in a constraint it is refused
 * after the last line (qd__mdl_check_inputs), not silently differentiated
 * as a constant.
 */
#include "parser.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <stdio.h>
#include <string.h>

static qd_ctx *C(parser *p) { return p->ctx; }

#define OUTPUT_USAGE "outputs y1 = EXPR, y2 = EXPR"

const qd_expr *qd__mdl_find_input(const qd_model *m, const char *name, size_t n) {
    for (size_t i = 0; i < m->ninputs; i++)
        if (qd__mdl_name_is(name, 0, n, qd_expr_name(m->inputs[i])))
            return m->inputs[i];
    return NULL;
}

static bool one_input(parser *p) {
    qd__mdl_lex_next(&p->lx);
    token at = p->lx.tok;
    if (at.kind != TK_IDENT)
        return qd__mdl_perr_tok(p, "inputs F, tau", "expected an input's name, found %s",
                                qd__mdl_lex_tk_name(at.kind));
    char name[128];
    snprintf(name, sizeof name, "%.*s", (int)(at.len < 127 ? at.len : 127), p->lx.src + at.off);
    if (!qd__mdl_fresh_name(p, "input"))
        return false;
    const qd_expr *sym = qd_symbol(C(p), name);
    if (!sym)
        return qd__mdl_perr(p, at.off, at.len, "choose another name for the input", "%s",
                            qd_ctx_message(C(p)));
    qd_model *m = p->m;
    size_t n = m->ninputs;
    if (!qd__mdl_push(m->ctx, (void **)&m->inputs, &n, sizeof sym, &sym))
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    m->ninputs = n;
    char what[160];
    snprintf(what, sizeof what, "input:%s", name);
    if (!qd__mdl_add_where(m, what, at.off, at.len))
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    qd__mdl_lex_next(&p->lx);
    return true;
}

/* inputs NAME (',' NAME)* */
bool qd__mdl_stmt_inputs(parser *p) {
    do
        if (!one_input(p))
            return false;
    while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

static bool output_name_fresh(parser *p, const char *name, token at) {
    for (size_t i = 0; i < p->m->nouts; i++)
        if (!strcmp(p->m->out_names[i], name))
            return qd__mdl_perr(p, at.off, at.len, "choose another name for the output",
                                "output '%s' is given twice", name);
    return qd__mdl_fresh_name(p, "output");
}

static bool add_output(parser *p, const char *name, token at, const qd_expr *x) {
    qd_model *m = p->m;
    char *copy = qd__malloc(m->ctx, strlen(name) + 1);
    size_t n = m->nouts, k = m->nouts;
    if (copy)
        strcpy(copy, name);
    if (!copy || !qd__mdl_push(m->ctx, (void **)&m->out_names, &n, sizeof copy, &copy)) {
        qd__free(copy);
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    }
    if (!qd__mdl_push(m->ctx, (void **)&m->outs, &k, sizeof x, &x)) {
        qd__free(copy);
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    }
    m->nouts = n;
    char what[160];
    snprintf(what, sizeof what, "output:%s", name);
    return qd__mdl_add_where(m, what, at.off, at.len) ||
           qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
}

/* NAME '=' EXPR */
static bool one_output(parser *p) {
    char name[QD_MDL_NAME_MAX];
    token at;
    value v;
    if (!qd__mdl_named_definition(p, "output", OUTPUT_USAGE, output_name_fresh, name, &at, &v))
        return false;
    if (v.kind != VK_SCALAR)
        return qd__mdl_perr_why(p, QD_REASON_WRONG_KIND, v.off, v.len, "give one output per component",
                            "a %s where a scalar is needed: an output is a scalar",
                            qd__mdl_vkind_name(v.kind));
    return add_output(p, name, at, v.c[0]);
}

/* outputs NAME '=' EXPR (',' NAME '=' EXPR)* */
bool qd__mdl_stmt_outputs(parser *p) {
    do
        if (!one_output(p))
            return false;
    while (p->lx.tok.kind == TK_COMMA);
    return qd__mdl_end_of_statement(p);
}

static bool refuse_input(parser *p, const qd_expr *u, const char *where, const char *hint) {
    char key[160];
    qd_diag at = {0};
    snprintf(key, sizeof key, "input:%.120s", qd_expr_name(u));
    qd_model_where(p->m, key, &at);
    return qd__mdl_perr(p, at.offset, at.length, hint, "input '%s' %s", qd_expr_name(u), where);
}

/* Lagrange's equations differentiate dL/dq' in time; an input there would
 * need its own rate, which no source gives. */
bool qd__mdl_check_inputs(parser *p) {
    qd_model *m = p->m;
    for (size_t i = 0; i < m->ninputs; i++) {
        const qd_expr *u = m->inputs[i];
        for (size_t j = 0; j < m->ncoords; j++) {
            const qd_expr *dL = qd_diff(C(p), m->L, qd_jet(C(p), m->coords[j], 1));
            if (!dL)
                return qd__mdl_perr(p, 0, 1, NULL, "%s", qd_ctx_message(C(p)));
            if (qd_has(dL, u))
                return refuse_input(p, u, "is in the velocity-dependent part of the Lagrangian, "
                                    "where Lagrange's equations would need its time derivative",
                                    "use it in a force, a torque, Q[q] or V");
        }
        for (size_t k = 0; k < m->ncons; k++)
            if (qd_has(m->cons[k], u))
                return refuse_input(p, u, "is in a constraint", "inputs drive forces, not constraints");
    }
    return true;
}

void qd__mdl_free_io(qd_model *m) {
    for (size_t i = 0; i < m->nouts; i++)
        qd__free((char *)m->out_names[i]);
    qd__free(m->out_names);
    qd__free(m->outs);
    qd__free(m->inputs);
}

/* ---- accessors ----------------------------------------------------------- */

size_t qd_model_ninputs(const qd_model *m) { QD_ARGS(0, m); return m->ninputs; }

const qd_expr *qd_model_input(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->ninputs ? m->inputs[i] : NULL;
}

size_t qd_model_noutputs(const qd_model *m) { QD_ARGS(0, m); return m->nouts; }

const char *qd_model_output_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nouts ? m->out_names[i] : NULL;
}

const qd_expr *qd_model_output(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nouts ? m->outs[i] : NULL;
}
