/*
 * src/codegen/speeds.c - the equations in generalized speeds (qdot/speeds.h)
 * as a C file and its header: the first-order system y = (q, u),
 *
 *     q' = W u + w        (the kinematics, e->kin)
 *     M_u u' = f_u        (solved in the generated code: Cholesky, LU when
 *                          M_u is not positive definite)
 *
 * with the shape of the coordinates' code (emit.c): the symbols a function
 * uses are bound to local constants read from its arguments, then one
 * qd_print_c_block computes the outputs, sharing every common
 * subexpression.  The kinematics, M_u and f_u are printed in one block in
 * rhs, so what they share (sines of the angles, mostly) is computed once.
 *
 * The Jacobian of y' differentiates M_u u' = f_u as emit.c does M q'' = f:
 * M_u du'/dy_k = df_u/dy_k - (dM_u/dy_k) u', with u' a symbol bound to the
 * solved value, M_u factored once for all columns; the kinematic rows are
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

/* Where a function reads q, u and u': q[qoff + j], u[uoff + r], z[r]; NULL
 * when it has none. */
typedef struct ssrc {
    const char *q, *u;
    size_t qoff, uoff;
    const char *z;
    const sgen *g;
} ssrc;

/* A coordinate, a speed or its rate, a parameter (cg_bind); a velocity
 * left in the equations has no slot. */
static qd_status bind(void *data, const qd_expr *sym, cg_slot *at) {
    const ssrc *s = data;
    const sgen *g = s->g;
    for (size_t j = 0; j < g->n && s->q; j++)
        if (g->e->q[j] == sym)
            *at = (cg_slot){s->q, s->qoff + j};
    for (size_t r = 0; r < g->ns && s->u; r++)
        if (g->e->u[r] == sym)
            *at = (cg_slot){s->u, s->uoff + r};
    for (size_t r = 0; r < g->ns && s->z; r++)
        if (g->e->ud[r] == sym)
            *at = (cg_slot){s->z, r};
    for (size_t i = 0; i < g->np && !at->array; i++)
        if (qd_model_param(g->m, i) == sym)
            *at = (cg_slot){"qd_par", i};
    return QD_OK;
}

/* A block whose outputs go to consecutive entries of one array. */
static qd_status block_to(sgen *g, ssrc *s, size_t nout, const qd_expr *const *out,
                          const char *arr) {
    s->g = g;
    return qd__cg_block_to(g->ctx, g->c, nout, out, arr, 0, bind, s);
}

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

static void unused(sgen *g, const char *names) { qd__cg_unused(g->c, names); }

static qd_status fn_kinematics(sgen *g) {
    qd_buf_printf(g->c, "void %s_kinematics(double t, const double *qd_q, const double *qd_u,\n"
                        "    const double *qd_par, double *qd_qd) {\n", g->P);
    unused(g, "    (void)qd_q;\n    (void)qd_u;\n");
    ssrc s = {"qd_q", "qd_u", 0, 0, NULL, g};
    qd_status st = block_to(g, &s, g->n, kin(g), "qd_qd");
    qd_buf_puts(g->c, "}\n\n");
    return st;
}

static qd_status fn_mass(sgen *g) {
    qd_buf_printf(g->c, "void %s_mass(double t, const double *qd_q, const double *qd_par, "
                        "double *qd_M) {\n", g->P);
    unused(g, "    (void)qd_q;\n");
    ssrc s = {"qd_q", NULL, 0, 0, NULL, g};
    qd_status st = block_to(g, &s, g->ns * g->ns, mass(g), "qd_M");
    qd_buf_puts(g->c, "}\n\n");
    return st;
}

static qd_status fn_forcing(sgen *g) {
    qd_buf_printf(g->c, "void %s_forcing(double t, const double *qd_q, const double *qd_u,\n"
                        "    const double *qd_par, double *qd_f) {\n", g->P);
    unused(g, "    (void)qd_q;\n    (void)qd_u;\n");
    ssrc s = {"qd_q", "qd_u", 0, 0, NULL, g};
    qd_status st = block_to(g, &s, g->ns, forcing(g), "qd_f");
    qd_buf_puts(g->c, "}\n\n");
    return st;
}

/* q' straight into dydt, M_u and f_u into K = [M_u | f_u], in one block. */
static qd_status rhs_block(sgen *g) {
    size_t n = g->n, ns = g->ns, nout = n + ns * ns + ns;
    char(*names)[48] = qd__malloc(g->ctx, (nout + 1) * sizeof *names);
    const char **lhs = qd__malloc(g->ctx, (nout + 1) * sizeof *lhs);
    qd_status st = names && lhs ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        qd__cg_lhs_names(names, lhs, "qd_dydt", 0, n);
        qd__cg_lhs_names(names + n, lhs + n, "qd_K", 0, ns * ns + ns);
        ssrc s = {"qd_y", "qd_y", 0, n, NULL, g};
        st = qd__cg_block(g->ctx, g->c, nout, g->all, lhs, bind, &s);
    }
    qd__free(names);
    qd__free(lhs);
    return st;
}

static qd_status fn_rhs(sgen *g) {
    qd_buf *c = g->c;
    size_t n = g->n, ns = g->ns;
    qd_buf_printf(c, "int %s_rhs(double t, const double *qd_y, const double *qd_par, "
                     "double *qd_dydt) {\n", g->P);
    qd_buf_puts(c, "    double qd_K[qd_NK * qd_NK + qd_NK];\n    double *qd_r = qd_K + qd_NK * "
                   "qd_NK;\n    qd_fac qd_fa;\n");
    unused(g, "");
    qd_status st = rhs_block(g);
    qd_buf_printf(c,
                  "    if (qd_factor(qd_K, &qd_fa)) {\n"
                  "        for (int i = 0; i < %zu; i++)\n            qd_dydt[%zu + i] = NAN;\n"
                  "        return 1;\n    }\n"
                  "    qd_solve(qd_K, &qd_fa, qd_r);\n"
                  "    for (int i = 0; i < %zu; i++)\n        qd_dydt[%zu + i] = qd_r[i];\n"
                  "    return 0;\n}\n",
                  ns, n, ns, n);
    return st;
}

static qd_status fn_energy(sgen *g) {
    qd_buf *c = g->c;
    qd_buf_printf(c, "\ndouble %s_energy(double t, const double *qd_y, const double *qd_par) {\n",
                  g->P);
    unused(g, "    (void)qd_y;\n");
    if (!g->has_energy) {
        qd_buf_puts(c, "    return NAN;\n}\n");
        return QD_OK;
    }
    qd_buf_puts(c, "    double qd_h[1];\n");
    ssrc s = {"qd_y", "qd_y", 0, g->n, NULL, g};
    qd_status st = block_to(g, &s, 1, hamilton(g), "qd_h");
    qd_buf_puts(c, "    return qd_h[0];\n}\n");
    return st;
}

static qd_status fn_jacobian(sgen *g) {
    qd_buf *c = g->c;
    size_t n = g->n, ns = g->ns, d = dim(g);
    qd_buf_printf(c, "\nvoid %s_jacobian(double t, const double *qd_y, const double *qd_par, "
                     "double *qd_J) {\n", g->P);
    qd_buf_printf(c, "    double qd_K[qd_NK * qd_NK + qd_NK], qd_R[%zu];\n"
                     "    double *qd_z = qd_K + qd_NK * qd_NK;\n    qd_fac qd_fa;\n", d * ns);
    unused(g, "    (void)qd_y;\n");
    qd_buf_printf(c, "    for (int i = 0; i < %zu; i++)\n        qd_J[i] = 0.0;\n    {\n", d * d);
    ssrc s = {"qd_y", "qd_y", 0, n, NULL, g};
    qd_status st = block_to(g, &s, n * d, dkin(g), "qd_J");
    qd_buf_puts(c, "    }\n    {\n");
    if (st == QD_OK)
        st = block_to(g, &s, ns * ns + ns, mass(g), "qd_K");
    qd_buf_printf(c,
                  "    }\n    if (qd_factor(qd_K, &qd_fa)) {\n"
                  "        for (int i = %zu; i < %zu; i++)\n            qd_J[i] = NAN;\n"
                  "        return;\n    }\n    qd_solve(qd_K, &qd_fa, qd_z);\n    {\n",
                  n * d, d * d);
    s.z = "qd_z";
    if (st == QD_OK)
        st = block_to(g, &s, d * ns, jac_rhs(g), "qd_R");
    qd_buf_printf(c,
                  "    }\n    for (int k = 0; k < %zu; k++)\n"
                  "        qd_solve(qd_K, &qd_fa, qd_R + k * qd_NK);\n"
                  "    for (int i = 0; i < %zu; i++)\n        for (int k = 0; k < %zu; k++)\n"
                  "            qd_J[(%zu + i) * %zu + k] = qd_R[k * qd_NK + i];\n}\n",
                  d, ns, d, n, d);
    return st;
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
        qd_buf_printf(c_text, "/* %s.c - generated by qdot codegen (see %s.h). */\n"
                              "#include <math.h>\n\n#include \"%s.h\"\n\n", prefix, prefix, prefix);
        st = tables(&g);
    }
    if (st == QD_OK) {
        qd__cg_solvers(c_text, g.ns, true);
        st = fn_kinematics(&g);
    }
    if (st == QD_OK)
        st = fn_mass(&g);
    if (st == QD_OK)
        st = fn_forcing(&g);
    if (st == QD_OK)
        st = fn_rhs(&g);
    if (st == QD_OK)
        st = fn_energy(&g);
    if (st == QD_OK)
        st = fn_jacobian(&g);
    qd__free(g.all);
    qd_buf_free(&scratch);
    if (st == QD_OK && (c_text->failed || (h_text && h_text->failed)))
        st = QD_ERR_NOMEM;
    if (st == QD_ERR_NOMEM)
        qd__oom(ctx);
    return st;
}
