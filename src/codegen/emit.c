/*
 * src/codegen/emit.c - the equations of motion M q'' = f as a C file and its
 * header: the expressions of the first-order system y = (q, q') (a cg_form,
 * written by system.c) and the header's text.
 *
 * With constraints the system solved is the saddle point K z = r, K = [M
 * -A^T; A 0], z = (q'', lambda), r = (f, b); the Jacobian's right-hand sides
 * dr/dy_k - (dK/dy_k) z are formed here, so only the entries of dM/dy_k,
 * dA/dy_k that are not zero cost anything.
 */
#include "cg.h"
#include "sym/node.h"
#include "../base/args.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct gen {
    qd_ctx *ctx;
    const qd_model *m;
    const qd_eom *e;
    const char *P;
    size_t n, np, nc, nk;
    /* every printed expression, rewritten together (angles.c) */
    const qd_expr **M, **f, **A, **b, *h, **R;
    const qd_expr **all;
    size_t nall;
    const qd_expr **Kr, **z; /* K then r (nk*nk + nk); z = (q'', lambda) */
    bool jacobian;           /* emit P_jacobian */
} gen;

/* ---- the expressions ---------------------------------------------------------- */

/* h = sum_j q'_j dL/dq'_j - L.  When L is T - V with T split by degree and
 * nothing eliminated, h = T2 - T0 + V, which is already compact; otherwise
 * it is formed and simplified (the T2 part of the sum cancels). */
static const qd_expr *energy(gen *g) {
    qd_ctx *ctx = g->ctx;
    const qd_eom *e = g->e;
    if (!qd_model_lagrangian_given(g->m) && !qd_model_gen_potential(g->m) && !e->nelim &&
        e->T2) {
        const qd_expr *V = qd_model_potential(g->m);
        const qd_expr *h = qd_add(ctx, e->T2, V ? V : qd_int(ctx, 0));
        return e->T0 ? qd_sub(ctx, h, e->T0) : h;
    }
    const qd_expr *h = qd_neg(ctx, e->L);
    for (size_t j = 0; j < g->n; j++)
        h = qd_add(ctx, h, qd_mul(ctx, e->qd[j], qd_diff(ctx, e->L, e->qd[j])));
    return qd_simplify(ctx, h);
}

/* Row i of dr/dy - (dK/dy) z for the coordinate or velocity y. */
static const qd_expr *jac_entry(gen *g, size_t i, const qd_expr *y, const qd_expr **terms) {
    qd_ctx *ctx = g->ctx;
    const qd_eom *e = g->e;
    size_t n = g->n, k = 0;
    if (i < n) {
        terms[k++] = qd_diff(ctx, e->f[i], y);
        for (size_t j = 0; j < n; j++)
            terms[k++] = qd_neg(ctx, qd_mul(ctx, qd_diff(ctx, e->M[i * n + j], y), e->qdd[j]));
        for (size_t c = 0; c < g->nc; c++)
            terms[k++] = qd_mul(ctx, qd_diff(ctx, e->A[c * n + i], y), e->con[c].lambda);
    } else {
        size_t c = i - n;
        terms[k++] = qd_diff(ctx, e->b[c], y);
        for (size_t j = 0; j < n; j++)
            terms[k++] = qd_neg(ctx, qd_mul(ctx, qd_diff(ctx, e->A[c * n + j], y), e->qdd[j]));
    }
    return qd_add_n(ctx, k, terms);
}

static qd_status build(gen *g) {
    qd_ctx *ctx = g->ctx;
    const qd_eom *e = g->e;
    size_t n = g->n, nc = g->nc, nk = g->nk;
    g->nall = n * n + n + nc * n + nc + 1 + 2 * n * nk;
    g->all = qd__malloc(ctx, g->nall * sizeof *g->all);
    const qd_expr **terms = qd__malloc(ctx, (1 + n + nc) * sizeof *terms);
    if (!g->all || !terms) {
        qd__free(terms);
        qd__oom(ctx);
        return QD_ERR_NOMEM;
    }
    g->M = g->all;
    g->f = g->M + n * n;
    g->A = g->f + n;
    g->b = g->A + nc * n;
    g->R = g->b + nc + 1;
    memcpy(g->M, e->M, n * n * sizeof *g->M);
    memcpy(g->f, e->f, n * sizeof *g->f);
    if (nc) {
        memcpy(g->A, e->A, nc * n * sizeof *g->A);
        memcpy(g->b, e->b, nc * sizeof *g->b);
    }
    g->b[nc] = energy(g);
    for (size_t k = 0; k < 2 * n; k++) {
        const qd_expr *y = k < n ? e->q[k] : e->qd[k - n];
        for (size_t i = 0; i < nk; i++)
            g->R[k * nk + i] = jac_entry(g, i, y, terms);
    }
    qd__free(terms);
    if (qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    if (qd__cg_mass_free_of(ctx, n * n, e->M, n, e->qd, "velocity") != QD_OK)
        return QD_ERR_ARG;
    bool applied;
    qd_status st = qd__cg_angle_sums(ctx, g->nall, g->all, &applied);
    g->h = g->b[nc];
    return st;
}

/* K (nk*nk) then r (nk) for the system solve, from the rewritten M, f, A,
 * b; z = (q'', lambda), their symbols. */
static qd_status system_outputs(gen *g) {
    qd_ctx *ctx = g->ctx;
    size_t n = g->n, nk = g->nk;
    g->Kr = qd__malloc(ctx, (nk * nk + nk) * sizeof *g->Kr);
    g->z = qd__malloc(ctx, nk * sizeof *g->z);
    if (!g->Kr || !g->z) {
        qd__oom(ctx);
        return QD_ERR_NOMEM;
    }
    for (size_t i = 0; i < nk; i++)
        for (size_t j = 0; j < nk; j++) {
            const qd_expr *x;
            if (i < n && j < n)
                x = g->M[i * n + j];
            else if (i < n)
                x = qd_neg(ctx, g->A[(j - n) * n + i]);
            else if (j < n)
                x = g->A[(i - n) * n + j];
            else
                x = qd_int(ctx, 0);
            g->Kr[i * nk + j] = x;
        }
    for (size_t i = 0; i < nk; i++) {
        g->Kr[nk * nk + i] = i < n ? g->f[i] : g->b[i - n];
        g->z[i] = i < n ? g->e->qdd[i] : g->e->con[i - n].lambda;
    }
    return qd_ctx_status(ctx);
}

/* ---- the text -------------------------------------------------------------------- */

static void header(gen *g, qd_buf *h, bool guard) {
    const char *P = g->P;
    const qd_eom *e = g->e;
    qd_buf_printf(h,
                  "/*\n * %s.h - generated by qdot codegen: the equations of motion of a model\n"
                  " * with %zu coordinate%s, %zu parameter%s and %zu constraint%s.  Needs only\n"
                  " * <math.h> (link with -lm).\n *\n * State y = (q[0..%zu), q'[0..%zu)):",
                  P, g->n, g->n == 1 ? "" : "s", g->np, g->np == 1 ? "" : "s", g->nc,
                  g->nc == 1 ? "" : "s", g->n, g->n);
    for (size_t j = 0; j < g->n; j++)
        qd_buf_printf(h, " %s", qd_expr_name(e->q[j]));
    qd_buf_puts(h, ".\n * Parameters par[0..NPAR), in model order:");
    for (size_t i = 0; i < g->np; i++)
        qd_buf_printf(h, " %s", qd_expr_name(qd_model_param(g->m, i)));
    qd_buf_puts(h, g->np ? ".\n" : " none.\n");
    if (qd_model_independent(g->m)) /* the argument keeps the name t in every program */
        qd_buf_printf(h, " * The argument t is the independent variable %s: q' is dq/d%s.\n",
                      qd_model_independent(g->m), qd_model_independent(g->m));
    qd_buf_puts(h, " * Matrices are row-major.\n */\n");
    if (guard)
        qd__cg_guard(h, P, true);
    bool rheo = (e->T1 && !qd_is_zero(e->T1)) || (e->T0 && !qd_is_zero(e->T0));
    qd_buf_printf(h,
                  "#define %s_N %zu    /* coordinates */\n"
                  "#define %s_NPAR %zu /* parameters */\n"
                  "#define %s_NCON %zu /* constraints (Lagrange multipliers) */\n\n",
                  P, g->n, P, g->np, P, g->nc);
    qd_buf_printf(h,
                  "extern const char *const %s_coord_names[]; /* N names, then NULL */\n"
                  "extern const char *const %s_param_names[]; /* NPAR names, then NULL */\n"
                  "extern const double %s_par_default[];      /* the model's values */\n\n",
                  P, P, P);
    qd_buf_printf(
        h,
        "/* The mass matrix M (N*N) at time t, coordinates q. */\n"
        "void %s_mass(double t, const double *q, const double *par, double *M);\n\n"
        "/* The forcing f (N): the equations are M q'' = f%s. */\n"
        "void %s_forcing(double t, const double *q, const double *qd, const double *par,\n"
        "                double *f);\n\n",
        P, g->nc ? " + A^T lambda, A q'' = b" : "", P);
    qd_buf_printf(
        h,
        "/* dydt = (q', q''), with q'' from\n   %s.\n"
        "   Returns 0, or 1 when that matrix is singular (then q'' is NaN). */\n"
        "int %s_rhs(double t, const double *y, const double *par, double *dydt);\n\n",
        g->nc ? "[M -A^T; A 0] [q''; lambda] = [f; b] (LU, partial pivoting)"
              : "M q'' = f (Cholesky, LU when M is not positive definite)",
        P);
    qd_buf_printf(h,
                  "/* %s: h = sum_j q'_j dL/dq'_j - L%s. */\n"
                  "double %s_energy(double t, const double *y, const double *par);\n\n",
                  rheo ? "The Jacobi integral (the system is rheonomic, so not T + V)"
                       : "The energy T + V",
                  rheo ? " = T2 - T0 + V" : "", P);
    qd_buf_printf(h,
                  "/* J (2N*2N) = d(dydt)/dy, analytic; the lower half NaN when the matrix\n"
                  "   is singular. */\n"
                  "void %s_jacobian(double t, const double *y, const double *par, double *J);\n",
                  P);
    if (guard)
        qd__cg_guard(h, P, false);
}

qd_status qd__cg_param_tables(qd_ctx *ctx, const qd_model *m, const char *P, qd_buf *c) {
    size_t np = qd_model_nparams(m);
    qd_buf_printf(c, "const char *const %s_param_names[] = {", P);
    for (size_t i = 0; i < np; i++)
        qd_buf_printf(c, "\"%s\", ", qd_expr_name(qd_model_param(m, i)));
    qd_buf_puts(c, "0};\n");
    qd_buf_printf(c, "const double %s_par_default[] = {", P);
    for (size_t i = 0; i < np; i++) {
        const qd_expr *v = qd_model_param_value(m, i);
        qd_status st = v ? qd_print(ctx, v, QD_FMT_C, c) : QD_ERR_ARG;
        if (st != QD_OK) {
            qd_ctx_error(ctx, st, "cannot generate C: parameter %s has no value",
                         qd_expr_name(qd_model_param(m, i)));
            return st;
        }
        qd_buf_puts(c, ", ");
    }
    qd_buf_puts(c, np ? "};\n\n" : "0.0};\n\n");
    return QD_OK;
}

static qd_status tables(gen *g, qd_buf *c) {
    qd__cg_name_list(c, g->P, "coord", g->n, g->e->q);
    return qd__cg_param_tables(g->ctx, g->m, g->P, c);
}

/* The form system.c writes: y = (q, q'), K z = r. */
static cg_form form(const gen *g, qd_buf *c) {
    const qd_eom *e = g->e;
    return (cg_form){.ctx = g->ctx, .m = g->m, .P = g->P, .c = c, .n = g->n, .nv = g->n,
                     .nk = g->nk, .np = g->np, .q = e->q, .v = e->qd, .z = g->z,
                     .vname = "qd_qd", .M = g->M, .f = g->f, .Kr = g->Kr, .R = g->R,
                     .h = g->h, .cholesky = g->nc == 0, .no_jacobian = !g->jacobian};
}

qd_status qd__cg_emit(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *prefix,
                      bool embed, bool jacobian, qd_buf *c, qd_buf *h) {
    if (!ctx || !m || !e || !c || (!embed && !h))
        return QD_ERR_ARG;
    prefix = prefix ? prefix : "qdot_model";
    if (qd__cg_prefix(ctx, prefix) != QD_OK)
        return QD_ERR_ARG;
    if (!e->n) {
        qd_ctx_error(ctx, QD_ERR_ARG, "cannot generate C: the model has no coordinates");
        return QD_ERR_ARG;
    }
    gen g = {.ctx = ctx, .m = m, .e = e, .P = prefix, .n = e->n,
             .np = qd_model_nparams(m), .nc = e->ncon, .jacobian = jacobian};
    g.nk = g.n + g.nc;
    qd_status st = build(&g);
    if (st == QD_OK)
        st = system_outputs(&g);
    if (st == QD_OK) {
        header(&g, embed ? c : h, !embed);
        if (embed)
            qd_buf_puts(c, "\n#include <math.h>\n\n");
        else
            qd__cg_preamble(c, prefix);
        st = tables(&g, c);
    }
    if (st == QD_OK) {
        cg_form f = form(&g, c);
        st = qd__cg_system(&f);
    }
    qd__free(g.all);
    qd__free(g.Kr);
    qd__free(g.z);
    if (st == QD_OK && (c->failed || (h && h->failed))) {
        qd__oom(ctx);
        st = QD_ERR_NOMEM;
    }
    return st;
}

qd_status qd_codegen_c(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *prefix,
                       qd_buf *c_text, qd_buf *h_text) {
    QD_ARGS_CTX(ctx, ctx && m && e && prefix && c_text);
    qd_buf scratch = QD_BUF_WITH(qd__ctx_allocator(ctx));
    qd_status st = qd__cg_emit(ctx, m, e, prefix, false, true, c_text, h_text ? h_text : &scratch);
    qd_buf_free(&scratch);
    return st;
}
