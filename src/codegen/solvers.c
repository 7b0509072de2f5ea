/*
 * src/codegen/solvers.c - the dense solvers written into every generated
 * file, so that it needs nothing but <math.h>.
 *
 * Unconstrained systems factor M with Cholesky (M is symmetric and, for a
 * kinetic energy, positive definite; half the work of LU).  The factor L
 * goes below the diagonal and 1/L_jj to a separate array, so the diagonal
 * and the upper triangle still hold M: when a pivot is not positive (a
 * Lagrangian with an indefinite velocity part) the lower triangle is copied
 * back from the upper one and LU with partial pivoting takes over.  The
 * saddle-point matrix of a constrained system is indefinite: LU directly.
 * A pivot below 1e-14 times the largest entry counts as singular, as do NaNs.
 */
#include "cg.h"

static const char lu_text[] =
    "/* LU with partial pivoting in place: P a = L U; nonzero when singular. */\n"
    "static int qd_lu(double *a, int *piv) {\n"
    "    double big = 0.0;\n"
    "    for (int i = 0; i < qd_NK * qd_NK; i++)\n"
    "        big = fabs(a[i]) > big ? fabs(a[i]) : big;\n"
    "    if (!(big > 0.0) || big != big)\n"
    "        return 1;\n"
    "    for (int k = 0; k < qd_NK; k++) {\n"
    "        int p = k;\n"
    "        double best = fabs(a[k * qd_NK + k]);\n"
    "        for (int i = k + 1; i < qd_NK; i++)\n"
    "            if (fabs(a[i * qd_NK + k]) > best) {\n"
    "                best = fabs(a[i * qd_NK + k]);\n"
    "                p = i;\n"
    "            }\n"
    "        piv[k] = p;\n"
    "        if (!(best > 1e-14 * big))\n"
    "            return 1;\n"
    "        if (p != k)\n"
    "            for (int j = 0; j < qd_NK; j++) {\n"
    "                double s = a[k * qd_NK + j];\n"
    "                a[k * qd_NK + j] = a[p * qd_NK + j];\n"
    "                a[p * qd_NK + j] = s;\n"
    "            }\n"
    "        const double inv = 1.0 / a[k * qd_NK + k];\n"
    "        for (int i = k + 1; i < qd_NK; i++) {\n"
    "            const double l = a[i * qd_NK + k] *= inv;\n"
    "            if (l != 0.0)\n"
    "                for (int j = k + 1; j < qd_NK; j++)\n"
    "                    a[i * qd_NK + j] -= l * a[k * qd_NK + j];\n"
    "        }\n"
    "    }\n"
    "    return 0;\n"
    "}\n\n"
    "static void qd_lu_solve(const double *a, const int *piv, double *x) {\n"
    "    for (int k = 0; k < qd_NK; k++)\n"
    "        if (piv[k] != k) {\n"
    "            double s = x[k];\n"
    "            x[k] = x[piv[k]];\n"
    "            x[piv[k]] = s;\n"
    "        }\n"
    "    for (int i = 1; i < qd_NK; i++)\n"
    "        for (int j = 0; j < i; j++)\n"
    "            x[i] -= a[i * qd_NK + j] * x[j];\n"
    "    for (int i = qd_NK - 1; i >= 0; i--) {\n"
    "        for (int j = i + 1; j < qd_NK; j++)\n"
    "            x[i] -= a[i * qd_NK + j] * x[j];\n"
    "        x[i] /= a[i * qd_NK + i];\n"
    "    }\n"
    "}\n\n";

static const char chol_text[] =
    "/* Cholesky: L below the diagonal, 1/L_jj in dinv; the diagonal and the\n"
    "   upper triangle keep M.  Nonzero, with a restored, when not positive\n"
    "   definite. */\n"
    "static int qd_chol(double *a, double *dinv) {\n"
    "    for (int j = 0; j < qd_NK; j++) {\n"
    "        double s = a[j * qd_NK + j];\n"
    "        for (int k = 0; k < j; k++)\n"
    "            s -= a[j * qd_NK + k] * a[j * qd_NK + k];\n"
    "        if (!(s > 1e-14 * fabs(a[j * qd_NK + j]))) {\n"
    "            for (int i = 1; i < qd_NK; i++)\n"
    "                for (int k = 0; k < i; k++)\n"
    "                    a[i * qd_NK + k] = a[k * qd_NK + i];\n"
    "            return 1;\n"
    "        }\n"
    "        dinv[j] = 1.0 / sqrt(s);\n"
    "        for (int i = j + 1; i < qd_NK; i++) {\n"
    "            double v = a[i * qd_NK + j];\n"
    "            for (int k = 0; k < j; k++)\n"
    "                v -= a[i * qd_NK + k] * a[j * qd_NK + k];\n"
    "            a[i * qd_NK + j] = v * dinv[j];\n"
    "        }\n"
    "    }\n"
    "    return 0;\n"
    "}\n\n"
    "static void qd_chol_solve(const double *a, const double *dinv, double *x) {\n"
    "    for (int i = 0; i < qd_NK; i++) {\n"
    "        for (int k = 0; k < i; k++)\n"
    "            x[i] -= a[i * qd_NK + k] * x[k];\n"
    "        x[i] *= dinv[i];\n"
    "    }\n"
    "    for (int i = qd_NK - 1; i >= 0; i--) {\n"
    "        for (int k = i + 1; k < qd_NK; k++)\n"
    "            x[i] -= a[k * qd_NK + i] * x[k];\n"
    "        x[i] *= dinv[i];\n"
    "    }\n"
    "}\n\n";

/* One interface for both: kind 1 Cholesky, 0 LU. */
static const char factor_chol[] =
    "typedef struct qd_fac {\n"
    "    int chol, piv[qd_NK];\n"
    "    double dinv[qd_NK];\n"
    "} qd_fac;\n\n"
    "static int qd_factor(double *a, qd_fac *f) {\n"
    "    f->chol = !qd_chol(a, f->dinv);\n"
    "    return f->chol ? 0 : qd_lu(a, f->piv);\n"
    "}\n\n"
    "static void qd_solve(const double *a, const qd_fac *f, double *x) {\n"
    "    if (f->chol)\n"
    "        qd_chol_solve(a, f->dinv, x);\n"
    "    else\n"
    "        qd_lu_solve(a, f->piv, x);\n"
    "}\n\n";

static const char factor_lu[] =
    "typedef struct qd_fac {\n"
    "    int piv[qd_NK];\n"
    "} qd_fac;\n\n"
    "static int qd_factor(double *a, qd_fac *f) {\n"
    "    return qd_lu(a, f->piv);\n"
    "}\n\n"
    "static void qd_solve(const double *a, const qd_fac *f, double *x) {\n"
    "    qd_lu_solve(a, f->piv, x);\n"
    "}\n\n";

void qd__cg_solvers(qd_buf *out, size_t nk, bool cholesky) {
    qd_buf_printf(out, "enum { qd_NK = %zu };\n\n", nk);
    qd_buf_puts(out, lu_text);
    if (cholesky) {
        qd_buf_puts(out, chol_text);
        qd_buf_puts(out, factor_chol);
    } else {
        qd_buf_puts(out, factor_lu);
    }
}
