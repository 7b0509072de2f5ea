/*
 * src/sym/tour.c - `qdot tour` (qd_tour_print, qdot/print.h): one minute with
 * the symbolic kernel.  Builds the double pendulum's kinetic energy from the
 * positions of its two bobs, reads the mass matrix off it by
 * differentiation, simplifies it to the textbook form m2 l1 l2 cos(theta1 -
 * theta2), prints it as text, LaTeX, SymPy and C, and evaluates it through a
 * compiled program.  In the library so that a C or Python caller gets the
 * same text (until issue 31 it was cli/cmd_tour.c).
 */
#include "qdot/eval.h"
#include "qdot/print.h"
#include "qdot/read.h"

#include "base/args.h"

static void show(qd_ctx *ctx, qd_buf *out, const char *label, const qd_expr *e,
                 qd_format fmt) {
    qd_buf b = QD_BUF_WITH(out->alloc);
    qd_print(ctx, e, fmt, &b);
    qd_buf_printf(out, "  %-10s %s\n", label, qd_buf_str(&b));
    out->failed |= b.failed;
    qd_buf_free(&b);
}

/* The kinetic energy of the two bobs, expanded: step 3's T. */
static const qd_expr *kinetic(qd_ctx *ctx, const qd_expr *T1, const qd_expr *vx,
                              const qd_expr *vy) {
    const qd_expr *half = qd_rat(ctx, 1, 2), *m2 = qd_lookup(ctx, "m2");
    const qd_expr *v2 = qd_add(ctx, qd_powi(ctx, vx, 2), qd_powi(ctx, vy, 2));
    return qd_expand(ctx, qd_add(ctx, T1, qd_mul_n(ctx, 3, (const qd_expr *[]){half, m2, v2})));
}

/* Step 6: M compiled to a straight-line program and run at one point. */
static qd_status compiled(qd_ctx *ctx, const qd_expr *const *q, const qd_expr *const *outs,
                          qd_buf *out) {
    const qd_expr *in[6] = {q[0], q[1], qd_lookup(ctx, "m1"), qd_lookup(ctx, "m2"),
                            qd_lookup(ctx, "l1"), qd_lookup(ctx, "l2")};
    qd_prog *p = qd_prog_new(ctx, 6, in, 3, outs);
    if (!p)
        return qd_ctx_status(ctx);
    double x[6] = {0.3, -0.2, 1, 1, 1, 1}, y[3];
    qd_prog_run(p, x, y);
    qd_buf_printf(out, "  M = [[%.6f, %.6f], [%.6f, %.6f]]   (%zu instructions)\n", y[0], y[1],
                  y[1], y[2], qd_prog_ninstr(p));
    qd_prog_free(p);
    return QD_OK;
}

qd_status qd_tour_print(qd_ctx *ctx, qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && out);
    const qd_expr *q1 = qd_coord(ctx, "theta1"), *q2 = qd_coord(ctx, "theta2");
    const char *params[] = {"m1", "m2", "l1", "l2", "g"};
    for (size_t i = 0; i < 5; i++)
        qd_param(ctx, params[i]);
    qd_buf_puts(out, "1. Positions of the two bobs of a double pendulum, read from text:\n");
    const qd_expr *x2 = qd_read(ctx, "l1*sin(theta1) + l2*sin(theta2)", NULL, NULL);
    const qd_expr *y2 = qd_read(ctx, "-l1*cos(theta1) - l2*cos(theta2)", NULL, NULL);
    const qd_expr *T = qd_read(ctx, "m1/2*(l1*theta1')^2", NULL, NULL);
    if (!x2 || !y2 || !T)
        return qd_ctx_status(ctx);
    show(ctx, out, "x2 =", x2, QD_FMT_TEXT);
    show(ctx, out, "y2 =", y2, QD_FMT_TEXT);
    qd_buf_puts(out, "\n2. Velocities by the total time derivative over the jet (x2' = d/dt "
                     "x2):\n");
    const qd_expr *vx = qd_dt(ctx, x2), *vy = qd_dt(ctx, y2);
    show(ctx, out, "x2' =", vx, QD_FMT_TEXT);
    show(ctx, out, "y2' =", vy, QD_FMT_TEXT);
    qd_buf_puts(out, "\n3. Kinetic energy T = m1/2 (l1 theta1')^2 + m2/2 (x2'^2 + y2'^2), "
                     "expanded, then simplified:\n");
    T = kinetic(ctx, T, vx, vy);
    show(ctx, out, "T =", T, QD_FMT_TEXT);
    show(ctx, out, "T =", qd_simplify(ctx, T), QD_FMT_TEXT);
    qd_buf_puts(out, "\n4. Mass matrix M_jk = d^2T/dtheta_j' dtheta_k', simplified (sin a "
                     "sin b + cos a cos b = cos(a - b)):\n");
    const qd_expr *v[2] = {qd_jet(ctx, q1, 1), qd_jet(ctx, q2, 1)}, *M[4];
    for (int j = 0; j < 2; j++)
        for (int k = 0; k < 2; k++)
            M[2 * j + k] = qd_simplify(ctx, qd_diff(ctx, qd_diff(ctx, T, v[j]), v[k]));
    if (qd_ctx_status(ctx) != QD_OK)
        return qd_ctx_status(ctx);
    show(ctx, out, "M11 =", M[0], QD_FMT_TEXT);
    show(ctx, out, "M12 =", M[1], QD_FMT_TEXT);
    show(ctx, out, "M22 =", M[3], QD_FMT_TEXT);
    qd_buf_puts(out, "\n5. The same entry as LaTeX, SymPy and C:\n");
    show(ctx, out, "LaTeX", M[1], QD_FMT_LATEX);
    show(ctx, out, "SymPy", M[1], QD_FMT_SYMPY);
    const char *lhs[3] = {"M[0]", "M[1]", "M[3]"};
    const qd_expr *outs[3] = {M[0], M[1], M[3]};
    qd_buf_puts(out, "  C (shared subexpressions hoisted):\n");
    qd_status st = qd_print_c_block(ctx, 3, outs, lhs, out);
    qd_buf_puts(out, "\n6. Compiled to a straight-line program and evaluated at theta1 = 0.3, "
                     "theta2 = -0.2, m = l = 1:\n");
    if (st == QD_OK)
        st = compiled(ctx, (const qd_expr *[]){q1, q2}, outs, out);
    qd_buf_printf(out, "\nExpressions are hash-consed: this tour made %zu distinct nodes.\n",
                  qd_ctx_node_count(ctx));
    if (st == QD_OK && out->failed) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        st = QD_ERR_NOMEM;
    }
    return st;
}
