/*
 * src/mech/integrals_out.c - the model's given symmetries and integrals
 * examined, and the whole analysis of qdot/integrals.h written out as text
 * or JSON: the one rendering the program and Python share.
 */
#include <string.h>
#include "base/args.h"
#include "base/mem.h"
#include "qdot/integrals.h"
#include "qdot/json.h"

typedef struct it_out {
    qd_ctx *ctx;
    const qd_integrals *I;
    const qd_integrals_given *g;
    const char *path;
} it_out;

qd_status qd_integrals_given_derive(qd_ctx *ctx, qd_integrals *I, const qd_model *m,
                                    qd_integrals_given *out) {
    QD_ARGS_CTX(ctx, ctx && I && m && out);
    *out = (qd_integrals_given){0};
    size_t ns = qd_model_nsymmetries(m), ni = qd_model_nintegrals(m), n = I->n;
    out->noether = qd__calloc(ctx, ns + 1, sizeof *out->noether);
    out->proposed = qd__calloc(ctx, ni + 1, sizeof *out->proposed);
    const qd_expr **xi = qd__calloc(ctx, n + 1, sizeof *xi);
    qd_status st = out->noether && out->proposed && xi ? QD_OK : QD_ERR_NOMEM;
    for (size_t i = 0; st == QD_OK && i < ns; i++) {
        for (size_t j = 0; j < n; j++)
            xi[j] = qd_model_symmetry_field(m, i, j);
        st = qd_integrals_noether(ctx, I, qd_model_symmetry_name(m, i), xi, &out->noether[i]);
        out->nnoether = i + 1;
    }
    for (size_t i = 0; st == QD_OK && i < ni; i++) {
        st = qd_integrals_check(ctx, I, qd_model_integral_name(m, i), qd_model_integral(m, i),
                                &out->proposed[i]);
        out->nproposed = i + 1;
    }
    qd__free(xi);
    if (st != QD_OK)
        qd_integrals_given_free(out);
    return st;
}

void qd_integrals_given_free(qd_integrals_given *g) {
    if (!g)
        return;
    for (size_t i = 0; g->noether && i < g->nnoether; i++)
        qd_noether_clear(&g->noether[i]);
    qd__free(g->noether);
    qd__free(g->proposed);
    *g = (qd_integrals_given){0};
}

/* ---- text ---------------------------------------------------------------------- */

static void put(const it_out *r, qd_buf *b, const qd_expr *x) {
    qd_print(r->ctx, x, QD_FMT_TEXT, b);
}

static const char *qname(const it_out *r, size_t j) { return qd_expr_name(r->I->q[j]); }

static void put_field(const it_out *r, qd_buf *b, const qd_noether *nt) {
    bool any = false;
    for (size_t j = 0; j < r->I->n; j++) {
        if (qd_is_zero(nt->xi[j]))
            continue;
        qd_buf_printf(b, "%sdelta %s = ", any ? ", " : "", qname(r, j));
        put(r, b, nt->xi[j]);
        any = true;
    }
    if (!any)
        qd_buf_puts(b, "the zero field");
}

static const char *numerically(bool numeric) {
    return numeric ? " (numerically, at random states: the simplifier did not reach 0)" : "";
}

#define UNDECIDED "could not decide (the simplifier did not reach 0, and no state where it " \
                  "certainly differs from 0 was found)"

/* After a "no": its witness line, the state where ball arithmetic
 * excludes 0 (issue 33: a "no" only with a witness). */
static void witness(qd_buf *b, const qd_zero_result *z) {
    qd_buf_puts(b, "  ");
    qd_zero_result_print(b, z);
}

static void text_noether(const it_out *r, qd_buf *b, const qd_noether *nt, bool found) {
    qd_buf_printf(b, "  %s: ", nt->name);
    put_field(r, b, nt);
    qd_buf_puts(b, "\n");
    if (!nt->invariant) {
        qd_buf_puts(b, "    not a symmetry: dL/deps = ");
        put(r, b, nt->dL);
        qd_buf_puts(b, found ? "\n" : " (not 0, nor found as dF/dt of some F(q, t))\n");
        return;
    }
    if (nt->F) {
        qd_buf_puts(b, "    dL/deps = dF/dt with F = ");
        put(r, b, nt->F);
        qd_buf_puts(b, " (a symmetry up to a total derivative)\n");
    } else {
        qd_buf_puts(b, "    dL/deps = 0: a symmetry of L\n");
    }
    qd_buf_puts(b, "    I = ");
    put(r, b, nt->integral);
    if (nt->conserved) {
        qd_buf_printf(b, " is conserved%s\n", numerically(nt->numeric));
    } else if (nt->cert.kind != QD_ZERO_NONZERO) {
        qd_buf_puts(b, ": conserved? " UNDECIDED ": dI/dt = ");
        put(r, b, nt->remainder);
        qd_buf_puts(b, "\n");
    } else {
        qd_buf_puts(b, " is not conserved: the forces work along the field, dI/dt = ");
        put(r, b, nt->remainder);
        qd_buf_puts(b, "\n");
        witness(b, &nt->cert);
    }
}

static void text_cyclic(const it_out *r, qd_buf *b) {
    const qd_integrals *I = r->I;
    qd_buf_puts(b, "cyclic coordinates");
    qd_buf_puts(b, I->ncyclic ? "\n" : ": none\n");
    for (size_t i = 0; i < I->ncyclic; i++) {
        const qd_int_cyclic *c = &I->cyclic[i];
        qd_buf_printf(b, "  %s: p_%s = ", qname(r, c->coord), qname(r, c->coord));
        put(r, b, c->momentum);
        if (c->conserved)
            qd_buf_puts(b, " is conserved\n");
        else
            qd_buf_printf(b, " is not conserved: %s\n", c->obstruction);
    }
}

static void text_jacobi(const it_out *r, qd_buf *b) {
    const qd_int_jacobi *J = &r->I->jacobi;
    qd_buf_puts(b, "Jacobi's integral h = sum_j q'_j dL/dq'_j - L\n  h = ");
    put(r, b, J->h);
    if (J->conserved)
        qd_buf_printf(b, "\n  conserved: yes%s\n", numerically(J->numeric));
    else if (J->cert.kind != QD_ZERO_NONZERO)
        qd_buf_puts(b, "\n  conserved: " UNDECIDED "\n");
    else {
        qd_buf_printf(b, "\n  conserved: no (%s)\n", J->not_conserved);
        witness(b, &J->cert);
    }
    if (J->energy) {
        qd_buf_puts(b, "  energy E = T + V + U0 = ");
        put(r, b, J->energy);
        qd_buf_puts(b, "\n");
    }
    if (J->equals_energy == 1) {
        qd_buf_printf(b, "  h = E: yes (%s)\n", J->reason);
    } else if (J->equals_energy == 0) {
        qd_buf_puts(b, "  h = E: no, h - E = ");
        put(r, b, J->h_minus_E);
        qd_buf_printf(b, " (%s)\n", J->reason);
    } else {
        qd_buf_printf(b, "  h = E: unknown (%s)\n", J->reason);
    }
}

static void text_balance(const it_out *r, qd_buf *b) {
    const qd_int_balance *B = &r->I->balance;
    const char *t = qd_print_time_name(r->ctx); /* x for `independent x` */
    qd_buf_printf(b, "energy balance along the motion\n  dh/d%s = ", t);
    put(r, b, B->dhdt);
    qd_buf_printf(b, "\n  expected %s = ", B->formula);
    put(r, b, B->expected);
    if (B->verified) {
        qd_buf_printf(b, ": verified%s\n", numerically(B->numeric));
    } else {
        qd_buf_printf(b, ": NOT verified, dh/d%s - expected = ", t);
        put(r, b, B->remainder);
        qd_buf_puts(b, "\n");
    }
    if (r->I->balance.D_quadratic)
        qd_buf_puts(b, "  D is homogeneous quadratic in the velocities: it dissipates at the "
                       "rate 2D\n");
}

static void text_found(const it_out *r, qd_buf *b) {
    const qd_integrals *I = r->I;
    if (!r->I->searched)
        return;
    qd_buf_puts(b, "symmetries found by coordinate names (x*, y*, z*)");
    if (r->I->constrained) {
        qd_buf_puts(b, ": not searched (the model has constraints)\n");
        return;
    }
    if (!I->ntested) {
        qd_buf_puts(b, ": no candidates (no coordinate is named x, y or z, with or "
                       "without a numeric suffix)\n");
        return;
    }
    qd_buf_puts(b, I->nfound ? "\n" : ": none\n");
    for (size_t i = 0; i < I->nfound; i++)
        text_noether(r, b, &I->found[i], true);
    bool any = false;
    for (size_t i = 0; i < I->ntested; i++) {
        bool hit = false;
        for (size_t k = 0; k < I->nfound; k++)
            hit |= !strcmp(I->found[k].name, I->tested[i]);
        if (!hit)
            qd_buf_printf(b, "%s%s", any ? ", " : "  not symmetries: ", I->tested[i]);
        any |= !hit;
    }
    if (any)
        qd_buf_puts(b, "\n");
}

static void text_proposed(const it_out *r, qd_buf *b) {
    if (!r->g->nproposed)
        return;
    qd_buf_puts(b, "proposed integrals\n");
    for (size_t i = 0; i < r->g->nproposed; i++) {
        const qd_int_proposed *p = &r->g->proposed[i];
        qd_buf_printf(b, "  %s = ", p->name);
        put(r, b, p->expr);
        if (p->conserved) {
            qd_buf_printf(b, "\n    conserved: dI/dt = 0 along the motion%s\n",
                          numerically(p->numeric));
        } else if (p->cert.kind != QD_ZERO_NONZERO) {
            qd_buf_puts(b, "\n    conserved? " UNDECIDED ": dI/dt = ");
            put(r, b, p->remainder);
            qd_buf_puts(b, " along the motion\n");
        } else {
            qd_buf_puts(b, "\n    not conserved: dI/dt = ");
            put(r, b, p->remainder);
            qd_buf_puts(b, " along the motion\n");
            witness(b, &p->cert);
        }
    }
}

static void write_text(const it_out *r, qd_buf *b) {
    qd_buf_printf(b, "qdot integrals %s\n", r->path);
    text_cyclic(r, b);
    text_jacobi(r, b);
    text_balance(r, b);
    text_found(r, b);
    if (r->g->nnoether) {
        qd_buf_puts(b, "Noether's integrals of the given symmetries\n");
        for (size_t i = 0; i < r->g->nnoether; i++)
            text_noether(r, b, &r->g->noether[i], false);
    }
    text_proposed(r, b);
}

/* ---- JSON ---------------------------------------------------------------------- */

static void jexpr(const it_out *r, qd_json *j, const char *key, const qd_expr *x) {
    qd_json_key(j, key);
    qd_json_expr(j, r->ctx, x);
}

static void jbool(qd_json *j, const char *key, bool v) {
    qd_json_key(j, key);
    qd_json_bool(j, v);
}

static void jstr(qd_json *j, const char *key, const char *v) {
    qd_json_key(j, key);
    if (v)
        qd_json_string(j, v);
    else
        qd_json_null(j);
}

static void json_noether(const it_out *r, qd_json *j, const qd_noether *nt) {
    qd_json_begin_object(j);
    jstr(j, "name", nt->name);
    qd_json_key(j, "field");
    qd_json_begin_object(j);
    for (size_t k = 0; k < r->I->n; k++)
        if (!qd_is_zero(nt->xi[k]))
            jexpr(r, j, qname(r, k), nt->xi[k]);
    qd_json_end_object(j);
    jbool(j, "invariant", nt->invariant);
    jexpr(r, j, "dL_deps", nt->dL);
    jexpr(r, j, "F", nt->F);
    jexpr(r, j, "remainder", nt->invariant ? qd_int(r->ctx, 0) : nt->dL);
    jexpr(r, j, "integral", nt->integral);
    jbool(j, "conserved", nt->conserved);
    jexpr(r, j, "dIdt", nt->remainder);
    jbool(j, "numeric", nt->numeric);
    qd_zero_result_json(j, &nt->cert);
    qd_json_end_object(j);
}

static void json_cyclic(const it_out *r, qd_json *j) {
    qd_json_key(j, "cyclic");
    qd_json_begin_array(j);
    for (size_t i = 0; i < r->I->ncyclic; i++) {
        const qd_int_cyclic *c = &r->I->cyclic[i];
        qd_json_begin_object(j);
        jstr(j, "coordinate", qname(r, c->coord));
        jexpr(r, j, "momentum", c->momentum);
        jbool(j, "conserved", c->conserved);
        jstr(j, "obstruction", c->obstruction);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void json_jacobi(const it_out *r, qd_json *j) {
    const qd_int_jacobi *J = &r->I->jacobi;
    qd_json_key(j, "jacobi");
    qd_json_begin_object(j);
    jexpr(r, j, "h", J->h);
    jbool(j, "explicit_t", J->explicit_t);
    jbool(j, "conserved", J->conserved);
    jstr(j, "not_conserved", J->not_conserved);
    jexpr(r, j, "energy", J->energy);
    qd_json_key(j, "equals_energy");
    if (J->equals_energy < 0)
        qd_json_null(j);
    else
        qd_json_bool(j, J->equals_energy == 1);
    jexpr(r, j, "h_minus_energy", J->h_minus_E);
    jstr(j, "reason", J->reason);
    jbool(j, "numeric", J->numeric);
    qd_zero_result_json(j, &J->cert);
    qd_json_end_object(j);
}

static void json_balance(const it_out *r, qd_json *j) {
    const qd_int_balance *B = &r->I->balance;
    qd_json_key(j, "energy_balance");
    qd_json_begin_object(j);
    jexpr(r, j, "dhdt", B->dhdt);
    jstr(j, "formula", B->formula);
    jexpr(r, j, "expected", B->expected);
    jbool(j, "D_quadratic", B->D_quadratic);
    jbool(j, "verified", B->verified);
    jbool(j, "numeric", B->numeric);
    jexpr(r, j, "remainder", B->remainder);
    qd_json_end_object(j);
}

static void json_lists(const it_out *r, qd_json *j) {
    qd_json_key(j, "found");
    qd_json_begin_array(j);
    for (size_t i = 0; i < r->I->nfound; i++)
        json_noether(r, j, &r->I->found[i]);
    qd_json_end_array(j);
    qd_json_key(j, "tested");
    qd_json_begin_array(j);
    for (size_t i = 0; i < r->I->ntested; i++)
        qd_json_string(j, r->I->tested[i]);
    qd_json_end_array(j);
    qd_json_key(j, "noether");
    qd_json_begin_array(j);
    for (size_t i = 0; i < r->g->nnoether; i++)
        json_noether(r, j, &r->g->noether[i]);
    qd_json_end_array(j);
    qd_json_key(j, "proposed");
    qd_json_begin_array(j);
    for (size_t i = 0; i < r->g->nproposed; i++) {
        const qd_int_proposed *p = &r->g->proposed[i];
        qd_json_begin_object(j);
        jstr(j, "name", p->name);
        jexpr(r, j, "expr", p->expr);
        jbool(j, "conserved", p->conserved);
        jexpr(r, j, "remainder", p->remainder);
        jbool(j, "numeric", p->numeric);
        qd_zero_result_json(j, &p->cert);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

static void write_json(const it_out *r, qd_buf *b) {
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    jstr(&j, "model", r->path);
    qd_json_key(&j, "coordinates");
    qd_json_begin_array(&j);
    for (size_t k = 0; k < r->I->n; k++)
        qd_json_string(&j, qname(r, k));
    qd_json_end_array(&j);
    jexpr(r, &j, "L", r->I->L);
    json_cyclic(r, &j);
    json_jacobi(r, &j);
    json_balance(r, &j);
    json_lists(r, &j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    b->failed = b->failed || !qd_json_ok(&j);
}

/* ---- LaTeX ------------------------------------------------------------------- */

static void lx(const it_out *r, qd_buf *b, const qd_expr *x) {
    qd_print(r->ctx, x, QD_FMT_LATEX, b);
}

/* A name given by the model (a symmetry's, an integral's) inside \text{}. */
static void ltext(qd_buf *b, const char *s) {
    qd_buf_puts(b, "\\text{");
    for (; *s; s++)
        if (strchr("_&%$#{}", *s))
            qd_buf_printf(b, "\\%c", *s);
        else if (*s == '\\' || *s == '^' || *s == '~')
            qd_buf_puts(b, " ");
        else
            qd_buf_printf(b, "%c", *s);
    qd_buf_puts(b, "}");
}

/* The verdict column of a row. */
static void lverdict(qd_buf *b, bool conserved, bool numeric, const qd_zero_result *z) {
    qd_buf_puts(b, " && \\text{");
    qd_buf_puts(b, conserved ? (numeric ? "conserved (numerically)" : "conserved")
                   : !z || z->kind == QD_ZERO_NONZERO ? "not conserved"
                                                      : "could not decide");
    qd_buf_puts(b, "} \\\\\n");
}

static void lnoether(const it_out *r, qd_buf *b, const qd_noether *nt) {
    ltext(b, nt->name);
    qd_buf_puts(b, " &= ");
    lx(r, b, nt->integral);
    lverdict(b, nt->conserved, nt->numeric, &nt->cert);
}

static void write_latex(const it_out *r, qd_buf *b) {
    const qd_integrals *I = r->I;
    qd_buf_puts(b, "\\begin{aligned}\n");
    for (size_t i = 0; i < I->ncyclic; i++) {
        const qd_int_cyclic *c = &I->cyclic[i];
        qd_buf_puts(b, "p_{");
        lx(r, b, I->q[c->coord]);
        qd_buf_puts(b, "} &= ");
        lx(r, b, c->momentum);
        lverdict(b, c->conserved, false, NULL);
    }
    qd_buf_puts(b, "h &= ");
    lx(r, b, I->jacobi.h);
    lverdict(b, I->jacobi.conserved, I->jacobi.numeric, &I->jacobi.cert);
    for (size_t i = 0; i < I->nfound; i++)
        lnoether(r, b, &I->found[i]);
    for (size_t i = 0; i < r->g->nnoether; i++)
        lnoether(r, b, &r->g->noether[i]);
    for (size_t i = 0; i < r->g->nproposed; i++) {
        const qd_int_proposed *p = &r->g->proposed[i];
        ltext(b, p->name);
        qd_buf_puts(b, " &= ");
        lx(r, b, p->expr);
        lverdict(b, p->conserved, p->numeric, &p->cert);
    }
    qd_buf_puts(b, "\\end{aligned}\n");
}

static qd_status it_done(qd_ctx *ctx, const qd_buf *b) {
    if (!b->failed)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory writing the integrals");
    return QD_ERR_NOMEM;
}

qd_status qd_integrals_latex(qd_ctx *ctx, const qd_integrals *I, const qd_integrals_given *g,
                             qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && I && out);
    const qd_integrals_given none = {0};
    it_out o = {ctx, I, g ? g : &none, NULL};
    write_latex(&o, out);
    return it_done(ctx, out);
}

qd_status qd_integrals_print(qd_ctx *ctx, const qd_integrals *I, const qd_integrals_given *g,
                             const char *model_name, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && I && out);
    const qd_integrals_given none = {0};
    it_out o = {ctx, I, g ? g : &none, model_name ? model_name : "model"};
    write_text(&o, out);
    return it_done(ctx, out);
}

qd_status qd_integrals_json(qd_ctx *ctx, const qd_integrals *I, const qd_integrals_given *g,
                            const char *model_name, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && I && out);
    const qd_integrals_given none = {0};
    it_out o = {ctx, I, g ? g : &none, model_name};
    write_json(&o, out);
    return it_done(ctx, out);
}
