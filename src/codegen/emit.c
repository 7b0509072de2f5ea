/*
 * src/codegen/emit.c - the equations of motion as a C file and its header.
 *
 * Each function binds the symbols its expressions use to local constants
 * named as qdot prints them (theta1, theta1_d, m1), read from the argument
 * arrays, then runs one qd_print_c_block, so every subexpression shared
 * among its outputs is computed once.  The mass matrix and the forcing are
 * printed in one block wherever both are needed (rhs, jacobian).
 *
 * The Jacobian of q'' = M^-1 f differentiates K z = r (K = M, or the
 * saddle-point matrix [M -A^T; A 0], z = (q'', lambda), r = (f, b)):
 * K dz/dy_k = dr/dy_k - (dK/dy_k) z.  The right-hand sides are written
 * symbolically with q'' and lambda as symbols (bound to the solved values
 * at run time), so only the entries of dM/dy_k, dA/dy_k that are not
 * zero cost anything, and K is factored once for all 2n columns.
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
    qd_buf *c;
    /* every printed expression, rewritten together (angles.c) */
    const qd_expr **M, **f, **A, **b, *h, **R;
    const qd_expr **all;
    size_t nall;
} gen;

/* Where a function finds its values: q[j] at q[qoff + j] and so on; NULL
 * when the function has none. */
typedef struct src {
    const gen *g;
    const char *q, *qd, *z;
    size_t qoff, qdoff;
} src;

/* A coordinate or its rates from q, qd and z (q'' then lambda), a
 * parameter from qd_par (cg_bind). */
static qd_status bind(void *data, const qd_expr *sym, cg_slot *at) {
    const src *s = data;
    const gen *g = s->g;
    const qd_eom *e = g->e;
    switch (qd_symbol_role(sym)) {
    case QD_ROLE_COORD: {
        unsigned order = qd_symbol_order(sym);
        const qd_expr *c = qd_symbol_coord(sym);
        for (size_t j = 0; j < g->n; j++)
            if (e->q[j] == c) {
                if (order == 0 && s->q)
                    *at = (cg_slot){s->q, s->qoff + j};
                else if (order == 1 && s->qd)
                    *at = (cg_slot){s->qd, s->qdoff + j};
                else if (order == 2 && s->z)
                    *at = (cg_slot){s->z, j};
            }
        break;
    }
    case QD_ROLE_PARAM:
        for (size_t i = 0; i < g->np; i++)
            if (qd_model_param(g->m, i) == sym)
                *at = (cg_slot){"qd_par", i};
        break;
    case QD_ROLE_PLAIN:
        for (size_t k = 0; k < g->nc && s->z; k++)
            if (e->con[k].lambda == sym)
                *at = (cg_slot){s->z, g->n + k};
        break;
    default:
        break;
    }
    return QD_OK;
}

/* The bindings and the block for outputs out[0..nout) to array[i]. */
static qd_status block(gen *g, src *s, size_t nout, const qd_expr *const *out,
                       const char *array) {
    s->g = g;
    return qd__cg_block_to(g->ctx, g->c, nout, out, array, 0, bind, s);
}

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
    for (size_t i = 0; i < n * n; i++)
        for (size_t j = 0; j < n; j++)
            if (qd_has(g->M[i], e->qd[j])) {
                qd_ctx_error(ctx, QD_ERR_ARG,
                             "cannot generate C: the mass matrix depends on the velocity %s'",
                             qd_expr_name(e->q[j]));
                return QD_ERR_ARG;
            }
    bool applied;
    qd_status st = qd__cg_angle_sums(ctx, g->nall, g->all, &applied);
    g->h = g->b[nc];
    return st;
}

/* K (nk*nk) and r (nk) for the system solve. */
static qd_status system_outputs(gen *g, const qd_expr **out) {
    qd_ctx *ctx = g->ctx;
    size_t n = g->n, nk = g->nk;
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
            out[i * nk + j] = x;
        }
    for (size_t i = 0; i < nk; i++)
        out[nk * nk + i] = i < n ? g->f[i] : g->b[i - n];
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

static qd_status tables(gen *g) {
    qd__cg_name_list(g->c, g->P, "coord", g->n, g->e->q);
    return qd__cg_param_tables(g->ctx, g->m, g->P, g->c);
}

static void unused(gen *g, const char *names) { qd__cg_unused(g->c, names); }

static qd_status fn_mass(gen *g) {
    qd_buf_printf(g->c, "void %s_mass(double t, const double *qd_q, const double *qd_par, "
                        "double *qd_M) {\n", g->P);
    unused(g, "    (void)qd_q;\n");
    src s = {.q = "qd_q"};
    qd_status st = block(g, &s, g->n * g->n, g->M, "qd_M");
    qd_buf_puts(g->c, "}\n\n");
    return st;
}

static qd_status fn_forcing(gen *g) {
    qd_buf_printf(g->c, "void %s_forcing(double t, const double *qd_q, const double *qd_qd,\n"
                        "    const double *qd_par, double *qd_f) {\n", g->P);
    unused(g, "    (void)qd_q;\n    (void)qd_qd;\n");
    src s = {.q = "qd_q", .qd = "qd_qd"};
    qd_status st = block(g, &s, g->n, g->f, "qd_f");
    qd_buf_puts(g->c, "}\n\n");
    return st;
}

/* K and r in one block (r is stored right after K), so what r shares with
 * K is computed once. */
static qd_status system_block(gen *g, src *s) {
    size_t nk = g->nk;
    const qd_expr **out = qd__malloc(g->ctx, (nk * nk + nk) * sizeof *out);
    if (!out) {
        qd__oom(g->ctx);
        return QD_ERR_NOMEM;
    }
    qd_status st = system_outputs(g, out);
    if (st == QD_OK)
        st = block(g, s, nk * nk + nk, out, "qd_K");
    qd__free(out);
    return st;
}

static qd_status fn_rhs(gen *g) {
    qd_buf *c = g->c;
    qd_buf_printf(c, "int %s_rhs(double t, const double *qd_y, const double *qd_par, "
                     "double *qd_dydt) {\n", g->P);
    qd_buf_puts(c, "    double qd_K[qd_NK * qd_NK + qd_NK];\n    double *qd_r = qd_K + qd_NK * "
                   "qd_NK;\n    qd_fac qd_fa;\n");
    unused(g, "");
    src s = {.q = "qd_y", .qd = "qd_y", .qdoff = g->n};
    qd_status st = system_block(g, &s);
    qd_buf_printf(c,
                  "    for (int i = 0; i < %zu; i++)\n        qd_dydt[i] = qd_y[%zu + i];\n"
                  "    if (qd_factor(qd_K, &qd_fa)) {\n"
                  "        for (int i = 0; i < %zu; i++)\n            qd_dydt[%zu + i] = NAN;\n"
                  "        return 1;\n    }\n"
                  "    qd_solve(qd_K, &qd_fa, qd_r);\n"
                  "    for (int i = 0; i < %zu; i++)\n        qd_dydt[%zu + i] = qd_r[i];\n"
                  "    return 0;\n}\n\n",
                  g->n, g->n, g->n, g->n, g->n, g->n);
    return st;
}

static qd_status fn_energy(gen *g) {
    qd_buf *c = g->c;
    qd_buf_printf(c, "double %s_energy(double t, const double *qd_y, const double *qd_par) {\n"
                     "    double qd_h[1];\n", g->P);
    unused(g, "    (void)qd_y;\n");
    src s = {.q = "qd_y", .qd = "qd_y", .qdoff = g->n};
    qd_status st = block(g, &s, 1, &g->h, "qd_h");
    qd_buf_puts(c, "    return qd_h[0];\n}\n\n");
    return st;
}

static qd_status fn_jacobian(gen *g) {
    qd_buf *c = g->c;
    size_t n = g->n, nk = g->nk, w = 2 * n;
    qd_buf_printf(c, "void %s_jacobian(double t, const double *qd_y, const double *qd_par, "
                     "double *qd_J) {\n", g->P);
    qd_buf_printf(c, "    double qd_K[qd_NK * qd_NK + qd_NK], qd_R[%zu];\n"
                     "    double *qd_z = qd_K + qd_NK * qd_NK;\n    qd_fac qd_fa;\n", w * nk);
    unused(g, "    (void)qd_y;\n");
    qd_buf_puts(c, "    {\n");
    src s = {.q = "qd_y", .qd = "qd_y", .qdoff = n};
    qd_status st = system_block(g, &s);
    qd_buf_printf(c,
                  "    }\n    for (int i = 0; i < %zu; i++)\n        qd_J[i] = 0.0;\n"
                  "    for (int i = 0; i < %zu; i++)\n        qd_J[i * %zu + %zu + i] = 1.0;\n"
                  "    if (qd_factor(qd_K, &qd_fa)) {\n"
                  "        for (int i = %zu; i < %zu; i++)\n            qd_J[i] = NAN;\n"
                  "        return;\n    }\n    qd_solve(qd_K, &qd_fa, qd_z);\n    {\n",
                  w * w, n, w, n, n * w, w * w);
    s.z = "qd_z";
    if (st == QD_OK)
        st = block(g, &s, w * nk, g->R, "qd_R");
    qd_buf_printf(c,
                  "    }\n    for (int k = 0; k < %zu; k++)\n"
                  "        qd_solve(qd_K, &qd_fa, qd_R + k * qd_NK);\n"
                  "    for (int i = 0; i < %zu; i++)\n        for (int k = 0; k < %zu; k++)\n"
                  "            qd_J[(%zu + i) * %zu + k] = qd_R[k * qd_NK + i];\n}\n",
                  w, n, w, n, w);
    return st;
}

qd_status qd__codegen(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *prefix,
                      bool embed, qd_buf *c, qd_buf *h) {
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
             .np = qd_model_nparams(m), .nc = e->ncon, .c = c};
    g.nk = g.n + g.nc;
    qd_status st = build(&g);
    if (st == QD_OK) {
        if (embed) {
            header(&g, c, false);
            qd_buf_puts(c, "\n#include <math.h>\n\n");
        } else {
            header(&g, h, true);
            qd_buf_printf(c, "/* %s.c - generated by qdot codegen (see %s.h). */\n"
                             "#include <math.h>\n\n#include \"%s.h\"\n\n", prefix, prefix, prefix);
        }
        st = tables(&g);
    }
    if (st == QD_OK) {
        qd__cg_solvers(c, g.nk, g.nc == 0);
        st = fn_mass(&g);
    }
    if (st == QD_OK)
        st = fn_forcing(&g);
    if (st == QD_OK)
        st = fn_rhs(&g);
    if (st == QD_OK)
        st = fn_energy(&g);
    if (st == QD_OK)
        st = fn_jacobian(&g);
    qd__free(g.all);
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
    qd_status st = qd__codegen(ctx, m, e, prefix, false, c_text, h_text ? h_text : &scratch);
    qd_buf_free(&scratch);
    return st;
}
