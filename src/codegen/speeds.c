/*
 * src/codegen/speeds.c - the equations in generalized speeds (qdot/speeds.h)
 * as a C file and its header: the first-order system y = (q, u),
 *
 *     q' = W u + w        (the kinematics, e->kin)
 *     M_u u' = f_u        (solved in the generated code: Cholesky, LU when
 *                          M_u is not positive definite)
 *
 * the expressions of a cg_form (written by system.c, as the coordinates'
 * M q'' = f of emit.c) and the header's text.  The Jacobian's right-hand
 * sides are df_u/dy_k - (dM_u/dy_k) u'; the kinematic rows are
 * differentiated directly.
 */
#include "cg.h"
#include "base/mem.h"
#include "sym/node.h"
#include "qdot/speeds.h"
#include "../base/args.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct sgen {
    qd_ctx *ctx;
    const qd_model *m;
    const qd_speeds_eom *e;
    const char *P;
    size_t n, ns, np;   /* coordinates, speeds, parameters */
    qd_buf *c;
    /* kin (n), M (ns*ns), f (ns), energy (1), d kin/dy (n*d), the right-hand
       sides of the Jacobian's dynamic rows (d*ns, column k at k*ns): every
       printed expression, rewritten together (angles.c) */
    const qd_expr **all;
    size_t nall;
    bool has_energy;
} sgen;

static size_t dim(const sgen *g) { return g->n + g->ns; }

/* ---- the expressions ---------------------------------------------------------- */

/* T + V when the derivation kept T (a model given by L has no T*), else
 * NULL; V may be written with velocities only through the speeds' names,
 * which stand for their definitions: q' is replaced by the kinematics. */
static const qd_expr *energy(sgen *g) {
    const qd_speeds_eom *e = g->e;
    if (!e->T || qd_model_gen_potential(g->m))
        return NULL;
    const qd_expr *V = qd_model_potential(g->m);
    const qd_expr *h = V ? qd_add(g->ctx, e->T, V) : e->T;
    return qd_simplify(g->ctx, qd_subs(g->ctx, h, g->n, e->qd, e->kin));
}

/* Column k of the Jacobian's dynamic rows, before the solve with M_u:
 * df_u/dy_k - (dM_u/dy_k) u'. */
static void jac_column(sgen *g, const qd_expr *y, const qd_expr **out, const qd_expr **terms) {
    qd_ctx *ctx = g->ctx;
    const qd_speeds_eom *e = g->e;
    size_t ns = g->ns;
    for (size_t r = 0; r < ns; r++) {
        size_t k = 0;
        terms[k++] = qd_diff(ctx, e->f[r], y);
        for (size_t c = 0; c < ns; c++)
            terms[k++] = qd_neg(ctx, qd_mul(ctx, qd_diff(ctx, e->M[r * ns + c], y), e->ud[c]));
        out[r] = qd_add_n(ctx, k, terms);
    }
}

static qd_status build(sgen *g) {
    const qd_speeds_eom *e = g->e;
    size_t n = g->n, ns = g->ns, d = dim(g);
    g->nall = n + ns * ns + ns + 1 + n * d + d * ns;
    g->all = qd__malloc(g->ctx, g->nall * sizeof *g->all);
    const qd_expr **terms = qd__malloc(g->ctx, (ns + 2) * sizeof *terms);
    if (!g->all || !terms) {
        qd__free(terms);
        return QD_ERR_NOMEM;
    }
    memcpy(g->all, e->kin, n * sizeof *g->all);
    memcpy(g->all + n, e->M, ns * ns * sizeof *g->all);
    memcpy(g->all + n + ns * ns, e->f, ns * sizeof *g->all);
    const qd_expr *h = energy(g);
    g->has_energy = h != NULL;
    g->all[n + ns * ns + ns] = h ? h : qd_int(g->ctx, 0);
    const qd_expr **dk = g->all + n + ns * ns + ns + 1, **R = dk + n * d;
    for (size_t k = 0; k < d; k++) {
        const qd_expr *y = k < n ? e->q[k] : e->u[k - n];
        for (size_t i = 0; i < n; i++)
            dk[i * d + k] = qd_diff(g->ctx, e->kin[i], y);
        jac_column(g, y, R + k * ns, terms);
    }
    qd__free(terms);
    if (qd_ctx_status(g->ctx) != QD_OK)
        return qd_ctx_status(g->ctx);
    /* M_u = W^T M W is a function of q and t: rhs factors it before u is
       read, and mass() has no u to read */
    for (size_t i = 0; i < ns * ns; i++)
        for (size_t r = 0; r < ns; r++)
            if (qd_has(e->M[i], e->u[r])) {
                qd_ctx_error(g->ctx, QD_ERR_ARG,
                             "cannot generate C: the mass matrix depends on the speed %s",
                             qd_expr_name(e->u[r]));
                return QD_ERR_ARG;
            }
    bool applied;
    return qd__cg_angle_sums(g->ctx, g->nall, g->all, &applied);
}

static const qd_expr *const *kin(const sgen *g) { return g->all; }
static const qd_expr *const *mass(const sgen *g) { return g->all + g->n; }
static const qd_expr *const *forcing(const sgen *g) { return g->all + g->n + g->ns * g->ns; }
static const qd_expr *const *hamilton(const sgen *g) { return forcing(g) + g->ns; }
static const qd_expr *const *dkin(const sgen *g) { return hamilton(g) + 1; }
static const qd_expr *const *jac_rhs(const sgen *g) { return dkin(g) + g->n * dim(g); }

/* ---- the text -------------------------------------------------------------------- */

static void names_line(qd_buf *h, const char *what, size_t n, const qd_expr *const *syms) {
    qd_buf_printf(h, " * %s:", what);
    for (size_t j = 0; j < n; j++)
        qd_buf_printf(h, " %s", qd_expr_name(syms[j]));
    qd_buf_puts(h, n ? ".\n" : " none.\n");
}

static void header(sgen *g, qd_buf *h) {
    const char *P = g->P;
    const qd_expr **par = qd__malloc(g->ctx, (g->np + 1) * sizeof *par);
    qd_buf_printf(h,
                  "/*\n * %s.h - generated by qdot codegen: the equations of motion of a model\n"
                  " * in generalized speeds (Kane's form), %zu coordinate%s, %zu speed%s and\n"
                  " * %zu parameter%s.  Needs only <math.h> (link with -lm).\n *\n"
                  " * State y = (q[0..%zu), u[0..%zu)).\n",
                  P, g->n, g->n == 1 ? "" : "s", g->ns, g->ns == 1 ? "" : "s", g->np,
                  g->np == 1 ? "" : "s", g->n, g->ns);
    names_line(h, "Coordinates", g->n, g->e->q);
    names_line(h, "Speeds", g->ns, g->e->u);
    for (size_t i = 0; par && i < g->np; i++)
        par[i] = qd_model_param(g->m, i);
    names_line(h, "Parameters par[0..NPAR), in model order", par ? g->np : 0, par);
    qd__free(par);
    qd_buf_puts(h, " * Matrices are row-major.\n */\n");
    qd__cg_guard(h, P, true);
    qd_buf_printf(h,
                  "#define %s_N %zu    /* coordinates */\n"
                  "#define %s_M %zu    /* speeds */\n"
                  "#define %s_NPAR %zu /* parameters */\n\n",
                  P, g->n, P, g->ns, P, g->np);
    qd_buf_printf(h,
                  "extern const char *const %s_coord_names[]; /* N names, then NULL */\n"
                  "extern const char *const %s_speed_names[]; /* M names, then NULL */\n"
                  "extern const char *const %s_param_names[]; /* NPAR names, then NULL */\n"
                  "extern const double %s_par_default[];      /* the model's values */\n\n",
                  P, P, P, P);
    qd_buf_printf(h,
                  "/* The kinematics q' = W u + w (N) at time t, coordinates q, speeds u. */\n"
                  "void %s_kinematics(double t, const double *q, const double *u,\n"
                  "                   const double *par, double *qd);\n\n"
                  "/* The mass matrix M_u = W^T M W (M*M) at time t, coordinates q. */\n"
                  "void %s_mass(double t, const double *q, const double *par, double *M);\n\n"
                  "/* The forcing f_u (M): the dynamic equations are M_u u' = f_u. */\n"
                  "void %s_forcing(double t, const double *q, const double *u, const double *par,\n"
                  "                double *f);\n\n",
                  P, P, P);
    qd_buf_printf(h,
                  "/* dydt = (q', u'), with u' from M_u u' = f_u (Cholesky, LU when M_u is\n"
                  "   not positive definite).  Returns 0, or 1 when M_u is singular (then u'\n"
                  "   is NaN). */\n"
                  "int %s_rhs(double t, const double *y, const double *par, double *dydt);\n\n",
                  P);
    qd_buf_printf(h,
                  "/* %s */\n"
                  "double %s_energy(double t, const double *y, const double *par);\n\n"
                  "/* J ((N+M)*(N+M)) = d(dydt)/dy, analytic; the rows of u' NaN when M_u is\n"
                  "   singular. */\n"
                  "void %s_jacobian(double t, const double *y, const double *par, double *J);\n",
                  g->has_energy ? "The energy T + V in q and u (conserved when the model is "
                                  "scleronomic and conservative)."
                                : "NAN: the model gives L (or U), so no energy T + V is known.",
                  P, P);
    qd__cg_guard(h, P, false);
}

static qd_status tables(sgen *g) {
    qd_buf *c = g->c;
    qd__cg_name_list(c, g->P, "coord", g->n, g->e->q);
    qd__cg_name_list(c, g->P, "speed", g->ns, g->e->u);
    return qd__cg_param_tables(g->ctx, g->m, g->P, c);
}

/* The form system.c writes: y = (q, u), K = M_u, z = u'. */
static cg_form form(const sgen *g) {
    const qd_speeds_eom *e = g->e;
    return (cg_form){.ctx = g->ctx, .m = g->m, .P = g->P, .c = g->c, .n = g->n, .nv = g->ns,
                     .nk = g->ns, .np = g->np, .q = e->q, .v = e->u, .z = e->ud,
                     .vname = "qd_u", .kin = kin(g), .dkin = dkin(g), .M = mass(g),
                     .f = forcing(g), .Kr = mass(g), .R = jac_rhs(g),
                     .h = g->has_energy ? *hamilton(g) : NULL, .h_decl_late = true,
                     .cholesky = true};
}

static qd_status check_args(qd_ctx *ctx, const qd_speeds_eom *e, const char *prefix) {
    if (qd__cg_prefix(ctx, prefix) != QD_OK)
        return QD_ERR_ARG;
    if (!e->n || !e->m) {
        qd_ctx_error(ctx, QD_ERR_ARG, "cannot generate C: the model has no %s",
                     e->n ? "speeds" : "coordinates");
        return QD_ERR_ARG;
    }
    return QD_OK;
}

qd_status qd_codegen_speeds_c(qd_ctx *ctx, const qd_model *m, const qd_speeds_eom *e,
                              const char *prefix, qd_buf *c_text, qd_buf *h_text) {
    QD_ARGS_CTX(ctx, ctx && m && e && prefix && c_text);
    qd_status st = check_args(ctx, e, prefix);
    if (st != QD_OK)
        return st;
    qd_buf scratch = QD_BUF_WITH(qd__ctx_allocator(ctx));
    sgen g = {.ctx = ctx, .m = m, .e = e, .P = prefix, .n = e->n, .ns = e->m,
              .np = qd_model_nparams(m), .c = c_text};
    st = build(&g);
    if (st == QD_OK) {
        header(&g, h_text ? h_text : &scratch);
        qd__cg_preamble(c_text, prefix);
        st = tables(&g);
    }
    if (st == QD_OK) {
        cg_form f = form(&g);
        st = qd__cg_system(&f);
    }
    qd__free(g.all);
    qd_buf_free(&scratch);
    if (st == QD_OK && (c_text->failed || (h_text && h_text->failed)))
        st = QD_ERR_NOMEM;
    if (st == QD_ERR_NOMEM)
        qd__oom(ctx);
    return st;
}
