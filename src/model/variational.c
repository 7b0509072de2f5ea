/*
 * src/model/variational.c - the calculus of variations in the model
 * language: functionals of curves other than the action.
 *
 *   independent x                               x names the time symbol
 *   constraint NAME: integral(EXPR) = VALUE     isoperimetric condition
 *
 * Euler-Lagrange equations do not care what the independent variable means:
 * with `independent x`, `coordinates y` and L = F(y, y', x), the equations
 * qdot derives for the action are those of the functional integral F dx
 * (Byerly ch. IV; Desloge ch. 82).  So `independent` is a renaming only: x
 * reads as the kernel's time symbol and everything downstream is unchanged.
 *
 * An isoperimetric condition integral G dx = l makes integral (F - lambda G) dx
 * stationary with lambda a constant (Lagrange's rule for isoperimetric
 * problems), so -lambda_NAME*G joins L and lambda_NAME is a plain symbol that
 * the boundary data fix together with the constants of integration.
 */
#include "parser.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <stdio.h>
#include <string.h>

static qd_ctx *C(parser *p) { return p->ctx; }

/* Both statements shape every equation: an added statement may not bring them. */
static bool in_model_text(parser *p, const char *what) {
    if (p->m->src == p->m->text)
        return true;
    return qd__mdl_perr_tok(p, "declare it in the model's text",
                            "%s cannot be added to a model already read", what);
}

/* independent NAME */
bool qd__mdl_stmt_independent(parser *p) {
    qd_model *m = p->m;
    size_t kw = p->lx.tok.off;
    if (!in_model_text(p, "the independent variable"))
        return false;
    qd__mdl_lex_next(&p->lx);
    if (p->lx.tok.kind != TK_IDENT)
        return qd__mdl_perr_tok(p, "write: independent x", "expected a variable name, found %s",
                                qd__mdl_lex_tk_name(p->lx.tok.kind));
    if (m->indep) {
        qd_diag first;
        qd_model_where(m, "independent", &first);
        char hint[96];
        snprintf(hint, sizeof hint, "a model has one independent variable (declared on line %zu)",
                 first.line);
        return qd__mdl_perr(p, kw, p->lx.tok.off + p->lx.tok.len - kw, hint,
                            "the independent variable is declared twice");
    }
    if (m->ncoords)
        return qd__mdl_perr(p, kw, p->lx.tok.off + p->lx.tok.len - kw,
                            "move it above the coordinates",
                            "the independent variable must be declared before the coordinates");
    if (!qd__mdl_fresh_name(p, "independent variable"))
        return false;
    char *copy = qd__malloc(C(p), p->lx.tok.len + 1);
    if (!copy)
        return qd__mdl_perr_tok(p, NULL, "out of memory");
    memcpy(copy, p->lx.src + p->lx.tok.off, p->lx.tok.len);
    copy[p->lx.tok.len] = '\0';
    m->indep = copy;
    if (!qd__mdl_add_where(m, "independent", p->lx.tok.off, p->lx.tok.len))
        return qd__mdl_perr_tok(p, NULL, "out of memory");
    qd__mdl_lex_next(&p->lx);
    return qd__mdl_end_of_statement(p);
}

bool qd__mdl_integral_ahead(const parser *p) {
    if (!qd__mdl_lex_is(&p->lx, "integral"))
        return false;
    lexer look = p->lx;
    qd__mdl_lex_next(&look);
    return look.tok.kind == TK_LPAREN;
}

bool qd__mdl_isoperimetric_named(const qd_model *m, const char *name) {
    for (size_t i = 0; i < m->nisos; i++)
        if (!strcmp(m->isos[i].name, name))
            return true;
    return false;
}

/* integral '(' EXPR ')' '=' VALUE, EXPR a function of the coordinates. */
static bool read_isoperimetric(parser *p, isoper *c) {
    qd__mdl_lex_next(&p->lx); /* integral */
    size_t open = p->lx.tok.off;
    qd__mdl_lex_next(&p->lx);
    size_t off = p->lx.tok.off;
    if (!qd__mdl_parse_scalar(p, &c->expr, "an integrand"))
        return false;
    size_t len = p->lx.tok.off > off ? p->lx.tok.off - off : 1;
    if (!qd__mdl_expect_close(p, open))
        return false;
    if (qd_is_number(c->expr))
        return qd__mdl_perr(p, off, len,
                            "the integrand is a function of the coordinates, e.g. sqrt(1 + y'^2)",
                            "this integral does not depend on the path");
    if (p->lx.tok.kind != TK_EQ)
        return qd__mdl_perr_tok(p, "write: constraint length: integral(sqrt(1 + y'^2)) = l",
                                "expected '=' and the integral's value");
    qd__mdl_lex_next(&p->lx);
    return qd__mdl_parse_constant(p, &c->value_def, &c->value, "an isoperimetric value");
}

/* The multiplier lambda_NAME: a plain constant symbol, or the parameter of
 * that name when the model declares one (so that numeric work can give it a
 * value and --set can vary it, as a shooting method does). */
static const qd_expr *multiplier(parser *p, const char *name) {
    char sym[96];
    snprintf(sym, sizeof sym, "lambda_%s", name);
    const qd_model *m = p->m;
    for (size_t i = 0; i < m->nparams; i++)
        if (!strcmp(qd_expr_name(m->params[i]), sym))
            return m->pfixed[i] ? m->pvals[i] : m->params[i];
    return qd_symbol(C(p), sym);
}

bool qd__mdl_isoperimetric(parser *p, const char *name, size_t at_off, size_t at_len) {
    qd_model *m = p->m;
    if (!in_model_text(p, "an isoperimetric constraint"))
        return false;
    if (m->H)
        return qd__mdl_perr_tok(p, "write the integrand as L = ... in the velocities",
                                "an isoperimetric constraint needs a Lagrangian, not H");
    isoper c = {0};
    if (!read_isoperimetric(p, &c))
        return false;
    c.lambda = multiplier(p, name);
    if (!c.lambda)
        return qd__mdl_perr(p, at_off, at_len, "rename the constraint", "%s", qd_ctx_message(C(p)));
    char *copy = qd__malloc(C(p), strlen(name) + 1);
    if (copy)
        strcpy(copy, name);
    if (!copy) {
        qd__free(copy);
        return qd__mdl_perr(p, at_off, at_len, NULL, "out of memory");
    }
    c.name = copy;
    if (!qd__mdl_push(C(p), (void **)&m->isos, &m->nisos, sizeof c, &c)) {
        qd__free(copy);
        return qd__mdl_perr(p, at_off, at_len, NULL, "out of memory");
    }
    char what[80];
    snprintf(what, sizeof what, "constraint:%s", name);
    if (!qd__mdl_add_where(m, what, at_off, at_len))
        return qd__mdl_perr(p, at_off, at_len, NULL, "out of memory");
    return qd__mdl_end_of_statement(p);
}

bool qd__mdl_apply_isoperimetric(parser *p) {
    qd_model *m = p->m;
    for (; m->nisos_applied < m->nisos; m->nisos_applied++) {
        const isoper *c = &m->isos[m->nisos_applied];
        m->L = qd_sub(C(p), m->L, qd_mul(C(p), c->lambda, c->expr));
        if (!m->L)
            return qd__mdl_perr(p, 0, 1, NULL, "%s", qd_ctx_message(C(p)));
    }
    return true;
}

/* ---- public accessors ------------------------------------------------------ */

const char *qd_model_independent(const qd_model *m) { QD_ARGS(NULL, m); return m->indep; }

size_t qd_model_nisoperimetric(const qd_model *m) { QD_ARGS(0, m); return m->nisos; }

const char *qd_model_isoperimetric_name(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nisos ? m->isos[i].name : NULL;
}

const qd_expr *qd_model_isoperimetric(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nisos ? m->isos[i].expr : NULL;
}

const qd_expr *qd_model_isoperimetric_value(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nisos ? m->isos[i].value : NULL;
}

const qd_expr *qd_model_isoperimetric_multiplier(const qd_model *m, size_t i) {
    QD_ARGS(NULL, m);
    return i < m->nisos ? m->isos[i].lambda : NULL;
}

void qd__mdl_free_isoperimetric(qd_model *m) {
    for (size_t i = 0; i < m->nisos; i++)
        qd__free((char *)m->isos[i].name);
    qd__free(m->isos);
    qd__free(m->indep);
}
