/*
 * src/codegen/system.c - the functions of a generated first-order system
 * y = (q, v), whichever equations it holds (a cg_form, cg.h): v = q' and
 * K z = r the mass matrix or the saddle-point system (emit.c), or v the
 * generalized speeds and K = M_u (speeds.c).
 *
 * rhs prints K and r in one block, with the kinematics q' = kin(q, v) when
 * they are not the state's second half, so what they share is computed once.
 * The Jacobian differentiates K z = r: K dz/dy_k = dr/dy_k - (dK/dy_k) z,
 * the right-hand sides R written with z as symbols bound at run time to the
 * solved values, K factored once for all columns; the rows of q' are the
 * identity on v, or d kin/dy.
 */
#include "cg.h"
#include "base/ctx.h"
#include "base/mem.h"

#include <stdio.h>
#include <string.h>

/* Where a function reads q, v and z: q[j], v[voff + r], z[k]; NULL when it
 * has none. */
typedef struct src {
    const cg_form *f;
    const char *q, *v, *z;
    size_t voff;
} src;

static qd_status bind(void *data, const qd_expr *sym, cg_slot *at) {
    const src *s = data;
    const cg_form *f = s->f;
    for (size_t j = 0; j < f->n && s->q; j++)
        if (f->q[j] == sym)
            *at = (cg_slot){s->q, j};
    for (size_t r = 0; r < f->nv && s->v; r++)
        if (f->v[r] == sym)
            *at = (cg_slot){s->v, s->voff + r};
    for (size_t k = 0; k < f->nk && s->z; k++)
        if (f->z[k] == sym)
            *at = (cg_slot){s->z, k};
    for (size_t i = 0; i < f->np && !at->array; i++)
        if (qd_model_param(f->m, i) == sym)
            *at = (cg_slot){"qd_par", i};
    return QD_OK;
}

static qd_status block(const cg_form *f, src s, size_t nout, const qd_expr *const *out,
                       const char *array) {
    s.f = f;
    return qd__cg_block_to(f->ctx, f->c, nout, out, array, 0, bind, &s);
}

static size_t dim(const cg_form *f) { return f->n + f->nv; }

static qd_status fn_kinematics(const cg_form *f) {
    qd_buf_printf(f->c, "void %s_kinematics(double t, const double *qd_q, const double *qd_u,\n"
                        "    const double *qd_par, double *qd_qd) {\n", f->P);
    qd__cg_unused(f->c, "    (void)qd_q;\n    (void)qd_u;\n");
    qd_status st = block(f, (src){.q = "qd_q", .v = "qd_u"}, f->n, f->kin, "qd_qd");
    qd_buf_puts(f->c, "}\n\n");
    return st;
}

static qd_status fn_mass(const cg_form *f) {
    qd_buf_printf(f->c, "void %s_mass(double t, const double *qd_q, const double *qd_par, "
                        "double *qd_M) {\n", f->P);
    qd__cg_unused(f->c, "    (void)qd_q;\n");
    qd_status st = block(f, (src){.q = "qd_q"}, f->nv * f->nv, f->M, "qd_M");
    qd_buf_puts(f->c, "}\n\n");
    return st;
}

static qd_status fn_forcing(const cg_form *f) {
    char unused[64];
    qd_buf_printf(f->c, "void %s_forcing(double t, const double *qd_q, const double *%s,\n"
                        "    const double *qd_par, double *qd_f) {\n", f->P, f->vname);
    snprintf(unused, sizeof unused, "    (void)qd_q;\n    (void)%s;\n", f->vname);
    qd__cg_unused(f->c, unused);
    qd_status st = block(f, (src){.q = "qd_q", .v = f->vname}, f->nv, f->f, "qd_f");
    qd_buf_puts(f->c, "}\n\n");
    return st;
}

/* The kinematics (when given) into dydt and K, r into qd_K, in one block. */
static qd_status rhs_block(const cg_form *f) {
    size_t nkin = f->kin ? f->n : 0, nKr = f->nk * f->nk + f->nk, nout = nkin + nKr;
    char(*names)[48] = qd__malloc(f->ctx, (nout + 1) * sizeof *names);
    const char **lhs = qd__malloc(f->ctx, (nout + 1) * sizeof *lhs);
    const qd_expr **out = qd__malloc(f->ctx, (nout + 1) * sizeof *out);
    qd_status st = names && lhs && out ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK) {
        if (nkin) /* memcpy from NULL is undefined even for 0 bytes */
            memcpy(out, f->kin, nkin * sizeof *out);
        memcpy(out + nkin, f->Kr, nKr * sizeof *out);
        qd__cg_lhs_names(names, lhs, "qd_dydt", 0, nkin);
        qd__cg_lhs_names(names + nkin, lhs + nkin, "qd_K", 0, nKr);
        src s = {f, "qd_y", "qd_y", NULL, f->n};
        st = qd__cg_block(f->ctx, f->c, nout, out, lhs, bind, &s);
    } else {
        qd__oom(f->ctx);
    }
    qd__free(names);
    qd__free(lhs);
    qd__free(out);
    return st;
}

static qd_status fn_rhs(const cg_form *f) {
    qd_buf *c = f->c;
    size_t n = f->n, nv = f->nv;
    qd_buf_printf(c, "int %s_rhs(double t, const double *qd_y, const double *qd_par, "
                     "double *qd_dydt) {\n", f->P);
    qd_buf_puts(c, "    double qd_K[qd_NK * qd_NK + qd_NK];\n    double *qd_r = qd_K + qd_NK * "
                   "qd_NK;\n    qd_fac qd_fa;\n");
    qd__cg_unused(c, "");
    qd_status st = rhs_block(f);
    if (!f->kin)
        qd_buf_printf(c, "    for (int i = 0; i < %zu; i++)\n        qd_dydt[i] = qd_y[%zu + i];\n",
                      n, n);
    qd_buf_printf(c,
                  "    if (qd_factor(qd_K, &qd_fa)) {\n"
                  "        for (int i = 0; i < %zu; i++)\n            qd_dydt[%zu + i] = NAN;\n"
                  "        return 1;\n    }\n"
                  "    qd_solve(qd_K, &qd_fa, qd_r);\n"
                  "    for (int i = 0; i < %zu; i++)\n        qd_dydt[%zu + i] = qd_r[i];\n"
                  "    return 0;\n}\n\n",
                  nv, n, nv, n);
    return st;
}

static qd_status fn_energy(const cg_form *f) {
    qd_buf *c = f->c;
    qd_buf_printf(c, "double %s_energy(double t, const double *qd_y, const double *qd_par) {\n",
                  f->P);
    if (f->h && !f->h_decl_late)
        qd_buf_puts(c, "    double qd_h[1];\n");
    qd__cg_unused(c, "    (void)qd_y;\n");
    if (!f->h) {
        qd_buf_puts(c, "    return NAN;\n}\n\n");
        return QD_OK;
    }
    if (f->h_decl_late)
        qd_buf_puts(c, "    double qd_h[1];\n");
    qd_status st = block(f, (src){.q = "qd_y", .v = "qd_y", .voff = f->n}, 1, &f->h, "qd_h");
    qd_buf_puts(c, "    return qd_h[0];\n}\n\n");
    return st;
}

static qd_status fn_jacobian(const cg_form *f) {
    qd_buf *c = f->c;
    size_t n = f->n, nv = f->nv, d = dim(f);
    static const char zero[] = "    for (int i = 0; i < %zu; i++)\n        qd_J[i] = 0.0;\n";
    qd_buf_printf(c, "void %s_jacobian(double t, const double *qd_y, const double *qd_par, "
                     "double *qd_J) {\n", f->P);
    qd_buf_printf(c, "    double qd_K[qd_NK * qd_NK + qd_NK], qd_R[%zu];\n"
                     "    double *qd_z = qd_K + qd_NK * qd_NK;\n    qd_fac qd_fa;\n", d * f->nk);
    qd__cg_unused(c, "    (void)qd_y;\n");
    src s = {.q = "qd_y", .v = "qd_y", .voff = n};
    qd_status st = QD_OK;
    /* the rows of q': d kin/dy before K, the identity after it (the order
       each kind of file has always been written in) */
    if (f->kin) {
        qd_buf_printf(c, zero, d * d);
        qd_buf_puts(c, "    {\n");
        st = block(f, s, n * d, f->dkin, "qd_J");
        qd_buf_puts(c, "    }\n");
    }
    qd_buf_puts(c, "    {\n");
    if (st == QD_OK)
        st = block(f, s, f->nk * f->nk + f->nk, f->Kr, "qd_K");
    qd_buf_puts(c, "    }\n");
    if (!f->kin) {
        qd_buf_printf(c, zero, d * d);
        qd_buf_printf(c, "    for (int i = 0; i < %zu; i++)\n"
                         "        qd_J[i * %zu + %zu + i] = 1.0;\n", n, d, n);
    }
    qd_buf_printf(c,
                  "    if (qd_factor(qd_K, &qd_fa)) {\n"
                  "        for (int i = %zu; i < %zu; i++)\n            qd_J[i] = NAN;\n"
                  "        return;\n    }\n    qd_solve(qd_K, &qd_fa, qd_z);\n    {\n",
                  n * d, d * d);
    s.z = "qd_z";
    if (st == QD_OK)
        st = block(f, s, d * f->nk, f->R, "qd_R");
    qd_buf_printf(c,
                  "    }\n    for (int k = 0; k < %zu; k++)\n"
                  "        qd_solve(qd_K, &qd_fa, qd_R + k * qd_NK);\n"
                  "    for (int i = 0; i < %zu; i++)\n        for (int k = 0; k < %zu; k++)\n"
                  "            qd_J[(%zu + i) * %zu + k] = qd_R[k * qd_NK + i];\n}\n",
                  d, nv, d, n, d);
    return st;
}

qd_status qd__cg_system(const cg_form *f) {
    qd__cg_solvers(f->c, f->nk, f->cholesky);
    qd_status st = f->kin ? fn_kinematics(f) : QD_OK;
    if (st == QD_OK)
        st = fn_mass(f);
    if (st == QD_OK)
        st = fn_forcing(f);
    if (st == QD_OK)
        st = fn_rhs(f);
    if (st == QD_OK)
        st = fn_energy(f);
    if (st == QD_OK && !f->no_jacobian)
        st = fn_jacobian(f);
    return st;
}

void qd__cg_preamble(qd_buf *c, const char *P) {
    qd_buf_printf(c, "/* %s.c - generated by qdot codegen (see %s.h). */\n"
                     "#include <math.h>\n\n#include \"%s.h\"\n\n", P, P, P);
}

qd_status qd__cg_mass_free_of(qd_ctx *ctx, size_t nM, const qd_expr *const *M, size_t n,
                              const qd_expr *const *syms, const char *what) {
    for (size_t i = 0; i < nM; i++)
        for (size_t j = 0; j < n; j++)
            if (qd_has(M[i], syms[j])) {
                qd_ctx_error(ctx, QD_ERR_ARG, "cannot generate C: the mass matrix depends on "
                                              "the %s %s", what, qd_expr_name(syms[j]));
                return QD_ERR_ARG;
            }
    return QD_OK;
}
