/*
 * src/model/circuit.c - electrical networks: circuit elements as statements.
 *
 *   inductance L on BRANCH             T += L/2 b'^2
 *   inductance M between B1, B2        T += M b1' b2'   (mutual)
 *   capacitance C on BRANCH            V += b^2/(2 C)
 *   resistance R on BRANCH             D += R/2 b'^2    (Rayleigh's dissipation)
 *   source E on BRANCH                 Q_j += E db/dq_j (virtual work E db)
 *
 * A branch's charge b is a linear combination of the charge coordinates with
 * constant coefficients: `q`, or `q1 - q2` for an element shared by two
 * loops.  Each statement adds exactly what the hand-written energies would,
 * so every command downstream sees an ordinary Lagrangian: the inductance
 * matrix is the mass matrix, and an inductance that depends on a mechanical
 * coordinate gives the ponderomotive force (1/2) sum dL_ij/dx i_i i_j by
 * itself (Byerly, Generalized Coordinates, ch. V Arts. 52-53).  The usual
 * SI self-inductance: Byerly's `L y1'^2` is (2L)/2 y1'^2 here.
 */
#include "parser.h"
#include "../base/mem.h"

#include <stdio.h>
#include <string.h>

#define BRANCH_HINT "a branch is a sum of charge coordinates times constants: q, q1 - q2"

static qd_ctx *C(parser *p) { return p->ctx; }

typedef struct branch {
    const qd_expr *b;       /* the branch charge */
    const qd_expr **a;      /* db/dq_j, one per coordinate (owned) */
    size_t off, len;
} branch;

/* An element's value: what the statement calls it, its usage (for hints),
 * the sign it must have when it is a number (1: > 0, 0: >= 0, -1: any), and
 * whether it may depend on the currents (only a source's may: a back-EMF). */
typedef struct element {
    const char *what;       /* "an inductance" */
    const char *usage;
    int sign;
    bool rates_ok;
} element;

/* The next token is the word; else an error showing the statement. */
static bool expect_word(parser *p, const char *word, const char *usage) {
    if (qd__mdl_lex_is(&p->lx, word)) {
        qd__mdl_lex_next(&p->lx);
        return true;
    }
    char hint[128];
    snprintf(hint, sizeof hint, "write: %s", usage);
    return qd__mdl_perr_tok(p, hint, "expected '%s', found %s", word,
                            qd__mdl_lex_tk_name(p->lx.tok.kind));
}

static bool is_coordinate(const parser *p, size_t off, size_t len) {
    for (size_t i = 0; i < p->m->ncoords; i++)
        if (qd__mdl_name_is(p->lx.src, off, len, qd_expr_name(p->m->coords[i])))
            return true;
    return false;
}

/* A lone name in the branch's place that is no coordinate (a typo, a
 * parameter): say so with the nearest coordinate, before the expression
 * parser calls it an unknown name.  A definition may be a branch (b = q1 - q2). */
static bool lone_name_not_coordinate(parser *p) {
    token at = p->lx.tok;
    if (at.kind != TK_IDENT || is_coordinate(p, at.off, at.len) ||
        qd__mdl_find_def(p->m, p->lx.src + at.off, at.len))
        return false;
    lexer save = p->lx;
    qd__mdl_lex_next(&p->lx);
    tk_kind next = p->lx.tok.kind;
    p->lx = save;
    if (next != TK_NEWLINE && next != TK_EOF && next != TK_COMMA)
        return false;
    const qd_model *m = p->m;
    const char **names = qd__malloc(p->ctx, (m->ncoords + 1) * sizeof *names);
    for (size_t i = 0; names && i < m->ncoords; i++)
        names[i] = qd_expr_name(m->coords[i]);
    const char *near = names ? qd__diag_nearest(p->lx.src + at.off, at.len, names, m->ncoords) : NULL;
    char hint[160];
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    else
        snprintf(hint, sizeof hint, "%s", BRANCH_HINT);
    qd__free(names);
    qd__mdl_perr(p, at.off, at.len, hint, "'%.*s' is not a coordinate",
                 (int)(at.len < 100 ? at.len : 100), p->lx.src + at.off);
    return true;
}

/* The first coordinate or rate of order from..4 (four primes at most) in x,
 * or NULL. */
static const qd_expr *jet_in(parser *p, const qd_expr *x, unsigned from) {
    for (size_t j = 0; j < p->m->ncoords; j++)
        for (unsigned order = from; order <= 4; order++) {
            const qd_expr *v = qd_jet(C(p), p->m->coords[j], order);
            if (v && qd_has(x, v))
                return v;
        }
    return NULL;
}

static const qd_expr *rate_in(parser *p, const qd_expr *x) { return jet_in(p, x, 1); }

/* Is x a constant: free of the coordinates, their rates and t? */
static bool is_constant(parser *p, const qd_expr *x) {
    return !jet_in(p, x, 0) && !qd_has(x, qd_time(C(p)));
}

/* Which way b fails to be a branch: 0 it is one, 1 not linear (or not
 * constant coefficients, or a term with no charge), 2 no charge at all. */
static int branch_fault(parser *p, branch *br) {
    size_t n = p->m->ncoords;
    const qd_expr *rest;
    qd_status st = qd_linear_coeffs(C(p), br->b, n, p->m->coords, br->a, &rest);
    if (st != QD_OK) {
        qd__ctx_recover(C(p)); /* keeps an out of memory */
        return 1;
    }
    bool any = false, constant = true;
    for (size_t j = 0; j < n; j++) {
        br->a[j] = qd_simplify(C(p), br->a[j]);
        constant = constant && br->a[j] && is_constant(p, br->a[j]);
        any = any || (br->a[j] && !qd_is_zero(br->a[j]));
    }
    const qd_expr *r = qd_simplify(C(p), rest);
    if (!any)
        return 2;
    return constant && r && qd_is_zero(r) ? 0 : 1;
}

/* b = sum a_j q_j with constant a_j, not all zero, and nothing else. */
static bool check_linear(parser *p, branch *br) {
    int fault = branch_fault(p, br);
    if (qd__ctx_nomem(C(p))) /* a NULL above may be only that */
        return qd__mdl_perr(p, br->off, br->len, NULL, "out of memory");
    const qd_expr *rate = fault ? rate_in(p, br->b) : NULL;
    if (rate)
        return qd__mdl_perr(p, br->off, br->len, "write the charge: q for the current q'",
                            "a branch is a charge, not a current (%s)", qd_expr_name(rate));
    if (fault == 1)
        return qd__mdl_perr(p, br->off, br->len, BRANCH_HINT,
                            "a branch must be linear in the charges, with constant coefficients");
    if (fault == 2)
        return qd__mdl_perr(p, br->off, br->len, BRANCH_HINT, "the branch has no charge coordinate");
    return true;
}

/* BRANCH: a scalar linear in the coordinates.  br->a is freed by the caller. */
static bool parse_branch(parser *p, branch *br) {
    br->a = qd__calloc(p->ctx, p->m->ncoords + 1, sizeof *br->a);
    if (!br->a)
        return qd__mdl_perr_tok(p, NULL, "out of memory");
    if (lone_name_not_coordinate(p))
        return false;
    value v;
    if (!qd__mdl_parse_expr(p, &v) || !qd__mdl_need_kind(p, &v, VK_SCALAR, "for a branch"))
        return false;
    br->b = v.c[0];
    br->off = v.off;
    br->len = v.len;
    return check_linear(p, br);
}

/* An element's value is in the coordinates, parameters and t (an
 * inductance that depends on a current would not be one), and of the
 * element's sign when it is a number once the parameters' values are put in. */
static bool check_value(parser *p, const element *e, const qd_expr *x, size_t off, size_t len) {
    const qd_expr *rate = rate_in(p, x);
    if (rate && !e->rates_ok)
        return qd__mdl_perr(p, off, len,
                            "an element's value depends on the coordinates, the parameters and t",
                            "%s cannot depend on the rate %s", e->what, qd_expr_name(rate));
    const qd_model *m = p->m;
    const qd_expr *num = qd_subs(C(p), x, m->nparams, m->params, m->pvals);
    if (!num)
        return qd__mdl_perr(p, off, len, NULL, "%s", qd_ctx_message(C(p)));
    if (e->sign >= 0 && qd_is_number(num) && qd_number_sign(num) < e->sign) {
        char hint[160];
        snprintf(hint, sizeof hint, "give a %s value: %s", e->sign ? "positive" : "non-negative",
                 e->usage);
        return qd__mdl_perr(p, off, len, hint, "%s must be %s, but it is %g", e->what,
                            e->sign ? "positive" : "zero or positive", qd_number_value(num));
    }
    return true;
}

/* A scalar value and its span. */
static bool parse_value(parser *p, value *v) {
    return qd__mdl_parse_expr(p, v) && qd__mdl_need_kind(p, v, VK_SCALAR, "for a circuit element");
}

static const qd_expr *add_to(qd_ctx *ctx, const qd_expr *slot, const qd_expr *term) {
    return slot ? qd_add(ctx, slot, term) : term;
}

/* value on BRANCH, after the keyword */
static bool parse_on(parser *p, const element *e, const qd_expr **val, branch *br) {
    qd__mdl_lex_next(&p->lx);
    value v;
    if (!parse_value(p, &v) || !check_value(p, e, v.c[0], v.off, v.len))
        return false;
    *val = v.c[0];
    return expect_word(p, "on", e->usage) && parse_branch(p, br);
}

static bool added(parser *p, const qd_expr *x, const branch *br) {
    if (!x)
        return qd__mdl_perr(p, br->off, br->len, NULL, "%s", qd_ctx_message(C(p)));
    return qd__mdl_end_of_statement(p);
}

/* M between B1, B2: T += M b1' b2' */
static bool mutual(parser *p, const qd_expr *M, branch *b1, branch *b2) {
    if (!parse_branch(p, b1))
        return false;
    if (p->lx.tok.kind != TK_COMMA)
        return qd__mdl_perr_tok(p, "write: inductance M between q1, q2",
                                "expected ',' between the two branches, found %s",
                                qd__mdl_lex_tk_name(p->lx.tok.kind));
    qd__mdl_lex_next(&p->lx);
    if (!parse_branch(p, b2))
        return false;
    /* M b' b' would be a self-inductance of 2M: say it as one */
    if (qd_expr_cmp(b1->b, b2->b) == 0)
        return qd__mdl_perr(p, b2->off, b2->len, "a self-inductance is: inductance L on q",
                            "a mutual inductance is between two different branches");
    qd_ctx *ctx = C(p);
    const qd_expr *t = qd_mul_n(ctx, 3, (const qd_expr *[]){M, qd_dt(ctx, b1->b), qd_dt(ctx, b2->b)});
    p->m->T = add_to(ctx, p->m->T, t);
    return added(p, p->m->T, b2);
}

/* L on BRANCH: T += L/2 b'^2 */
static bool self(parser *p, const qd_expr *L, branch *br) {
    if (!expect_word(p, "on", "inductance L on q (or inductance M between q1, q2)") ||
        !parse_branch(p, br))
        return false;
    qd_ctx *ctx = C(p);
    const qd_expr *i = qd_dt(ctx, br->b);
    const qd_expr *t = qd_mul_n(ctx, 3, (const qd_expr *[]){qd_rat(ctx, 1, 2), L, qd_powi(ctx, i, 2)});
    p->m->T = add_to(ctx, p->m->T, t);
    return added(p, p->m->T, br);
}

/* inductance L on BRANCH | inductance M between B1, B2.  The word after
 * the value tells which, and a mutual inductance may have either sign. */
bool qd__mdl_stmt_inductance(parser *p) {
    token kw = p->lx.tok;
    if (!qd__mdl_no_hamiltonian_yet(p, "an inductance", kw.off, kw.len))
        return false;
    static const element own = {"an inductance", "inductance L on q", 1, false};
    static const element mut = {"a mutual inductance", "inductance M between q1, q2", -1, false};
    branch b1 = {0}, b2 = {0};
    value v;
    qd__mdl_lex_next(&p->lx);
    if (!parse_value(p, &v))
        return false;
    bool between = qd__mdl_lex_is(&p->lx, "between");
    const element *e = between ? &mut : &own;
    bool ok = check_value(p, e, v.c[0], v.off, v.len);
    if (ok && between) {
        qd__mdl_lex_next(&p->lx);
        ok = mutual(p, v.c[0], &b1, &b2);
    } else if (ok) {
        ok = self(p, v.c[0], &b1);
    }
    qd__free(b1.a);
    qd__free(b2.a);
    return ok;
}

/* capacitance C on BRANCH: V += b^2/(2 C) */
bool qd__mdl_stmt_capacitance(parser *p) {
    token kw = p->lx.tok;
    if (!qd__mdl_no_hamiltonian_yet(p, "a capacitance", kw.off, kw.len))
        return false;
    static const element e = {"a capacitance", "capacitance C on q", 1, false};
    branch br = {0};
    const qd_expr *Cap = NULL;
    bool ok = parse_on(p, &e, &Cap, &br);
    if (ok) {
        qd_ctx *ctx = C(p);
        const qd_expr *v = qd_div(ctx, qd_powi(ctx, br.b, 2), qd_mul(ctx, qd_int(ctx, 2), Cap));
        p->m->V = add_to(ctx, p->m->V, v);
        ok = added(p, p->m->V, &br);
    }
    qd__free(br.a);
    return ok;
}

/* resistance R on BRANCH: D += R/2 b'^2 */
bool qd__mdl_stmt_resistance(parser *p) {
    static const element e = {"a resistance", "resistance R on q", 0, false};
    branch br = {0};
    const qd_expr *R;
    bool ok = parse_on(p, &e, &R, &br);
    if (ok) {
        qd_ctx *ctx = C(p);
        const qd_expr *i = qd_dt(ctx, br.b);
        const qd_expr *d = qd_mul_n(ctx, 3, (const qd_expr *[]){qd_rat(ctx, 1, 2), R, qd_powi(ctx, i, 2)});
        p->m->D = add_to(ctx, p->m->D, d);
        ok = added(p, p->m->D, &br);
    }
    qd__free(br.a);
    return ok;
}

/* source E on BRANCH: the EMF E does virtual work E db = sum E a_j dq_j */
bool qd__mdl_stmt_source(parser *p) {
    static const element e = {"a source", "source E on q", -1, true};
    branch br = {0};
    const qd_expr *E;
    bool ok = parse_on(p, &e, &E, &br);
    for (size_t j = 0; ok && j < p->m->ncoords; j++) {
        p->m->Q[j] = qd_add(C(p), p->m->Q[j], qd_mul(C(p), E, br.a[j]));
        if (!p->m->Q[j])
            ok = qd__mdl_perr(p, br.off, br.len, NULL, "%s", qd_ctx_message(C(p)));
    }
    if (ok)
        ok = qd__mdl_end_of_statement(p);
    qd__free(br.a);
    return ok;
}
