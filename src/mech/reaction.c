/*
 * src/mech/reaction.c - the Cartesian force a constraint exerts at a point.
 *
 * Desloge ch. 49 thm 1 and ch. 52 thm 1: the constraint forces enter
 * Lagrange's equations as R_j = sum_k lambda_k a_kj, the virtual work of the
 * physical forces per unit dq_j at frozen time.  A force F acting at the
 * point r does the virtual work F . dr/dq_j dq_j, so the reaction of
 * constraint k at r solves
 *
 *     J^T F = lambda_k a_k,      J_ij = dr_i/dq_j   (3 x n),
 *
 * n equations for 3 unknowns.  When the constraint is written in terms of r
 * (g = G(r(q), t)), a_kj = grad G . dr/dq_j by the chain rule, so F =
 * lambda_k grad G solves it exactly: the normal force on a bead, the wall's
 * push on a ladder's end.  Otherwise (a rope pulling two masses) it is solved
 * in the least-squares sense and the residual says how much of R does not
 * work through r.  Among the solutions the one of least |F| is taken, via
 * the normal equations J J^T F = J R and the pseudo-inverse of the 3 x 3
 * matrix J J^T: the components of F normal to every dr/dq_j do no virtual
 * work and are not determined by R (they belong to the constraints built
 * into the coordinates), so they are reported as 0.
 */
#include "mech.h"

#include "qdot/print.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Eigenvalues w and orthonormal eigenvectors (columns of V) of the
 * symmetric 3 x 3 matrix S (destroyed), by cyclic Jacobi rotations. */
static void eigen3(double S[3][3], double w[3], double V[3][3]) {
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            V[i][j] = i == j;
    for (int sweep = 0; sweep < 50; sweep++) {
        double off = fabs(S[0][1]) + fabs(S[0][2]) + fabs(S[1][2]);
        if (off <= 1e-300 || off <= 1e-18 * (fabs(S[0][0]) + fabs(S[1][1]) + fabs(S[2][2])))
            break;
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                if (S[p][q] == 0)
                    continue;
                double th = (S[q][q] - S[p][p]) / (2 * S[p][q]);
                double t = (th >= 0 ? 1 : -1) / (fabs(th) + sqrt(th * th + 1));
                double c = 1 / sqrt(t * t + 1), s = t * c;
                for (int k = 0; k < 3; k++) { /* S <- S G */
                    double a = S[k][p], b = S[k][q];
                    S[k][p] = c * a - s * b;
                    S[k][q] = s * a + c * b;
                }
                for (int k = 0; k < 3; k++) { /* S <- G^T S */
                    double a = S[p][k], b = S[q][k];
                    S[p][k] = c * a - s * b;
                    S[q][k] = s * a + c * b;
                }
                for (int k = 0; k < 3; k++) {
                    double a = V[k][p], b = V[k][q];
                    V[k][p] = c * a - s * b;
                    V[k][q] = s * a + c * b;
                }
            }
    }
    for (int i = 0; i < 3; i++)
        w[i] = S[i][i];
}

/* The least-norm least-squares solution of J^T F = R (J is 3 x n, row-major). */
static void least_squares(size_t n, const double *J, const double *R, double F[3]) {
    double S[3][3] = {{0}}, y[3] = {0}, w[3], V[3][3], top = 0;
    for (int i = 0; i < 3; i++)
        for (size_t j = 0; j < n; j++) {
            y[i] += J[i * n + j] * R[j];
            for (int k = 0; k < 3; k++)
                S[i][k] += J[i * n + j] * J[k * n + j];
        }
    eigen3(S, w, V);
    for (int i = 0; i < 3; i++)
        top = fmax(top, fabs(w[i]));
    F[0] = F[1] = F[2] = 0;
    for (int i = 0; i < 3; i++) {
        if (!(w[i] > 1e-12 * top))
            continue;
        double c = (V[0][i] * y[0] + V[1][i] * y[1] + V[2][i] * y[2]) / w[i];
        for (int k = 0; k < 3; k++)
            F[k] += c * V[k][i];
    }
}

static double residual_of(size_t n, const double *J, const double *R, const double F[3]) {
    double res = 0, size = 0;
    for (size_t j = 0; j < n; j++) {
        double d = J[0 * n + j] * F[0] + J[1 * n + j] * F[1] + J[2 * n + j] * F[2] - R[j];
        res += d * d;
        size += R[j] * R[j];
    }
    return size > 0 ? sqrt(res / size) : 0;
}

/* The index of constraint `con`, or an error naming why there is none. */
static qd_status find(qd_ctx *ctx, const qd_eom *e, const char *con, size_t *k) {
    for (*k = 0; *k < e->ncon; ++*k)
        if (!strcmp(e->con[*k].name, con))
            return QD_OK;
    for (size_t i = 0; i < e->nelim; i++)
        if (!strcmp(e->elim[i].con, con)) {
            qd_ctx_error(ctx, QD_ERR_ARG,
                         "constraint %s was used to eliminate %s: it has no multiplier, so its "
                         "reaction is not computed (derive without elimination for it)",
                         con, qd_expr_name(e->elim[i].q));
            return QD_ERR_ARG;
        }
    qd_ctx_error(ctx, QD_ERR_ARG, "no constraint named %s", con);
    return QD_ERR_ARG;
}

/* J (3 x n) and R (n) at the state. */
static qd_status at_state(qd_ctx *ctx, const qd_eom *e, size_t k, const qd_expr *const r[3],
                          size_t nv, const qd_expr *const *syms, const double *vals,
                          double lambda, double *J, double *R) {
    size_t n = e->n, ne = e->nelim;
    const qd_expr *from[64], *to[64];
    if (ne > 64) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "reaction: at most 64 eliminated coordinates");
        return QD_ERR_TOOBIG;
    }
    for (size_t i = 0; i < ne; i++)
        from[i] = e->elim[i].q, to[i] = e->elim[i].value;
    qd_status st = QD_OK;
    for (int i = 0; i < 3 && st == QD_OK; i++) {
        const qd_expr *ri = ne ? qd_subs(ctx, r[i], ne, from, to) : r[i];
        for (size_t j = 0; j < n && st == QD_OK; j++)
            st = qd_eval(ctx, qd_diff(ctx, ri, e->q[j]), nv, syms, vals, &J[i * n + j]);
    }
    for (size_t j = 0; j < n && st == QD_OK; j++) {
        st = qd_eval(ctx, e->A[k * n + j], nv, syms, vals, &R[j]);
        R[j] *= lambda;
    }
    return st;
}

qd_status qd_eom_reaction(qd_ctx *ctx, const qd_eom *e, const char *con,
                          const qd_expr *const r[3], size_t nvals, const qd_expr *const *syms,
                          const double *vals, const double *lambda, double F[3],
                          double *residual) {
    QD_ARGS_CTX(ctx, ctx && e && con && r && (nvals == 0 || syms) && (nvals == 0 || vals) && lambda && F);
    size_t k, n = e->n;
    qd_status st = find(ctx, e, con, &k);
    if (st != QD_OK)
        return st;
    double *J = qd__malloc(ctx, (4 * n + 1) * sizeof *J);
    if (!J) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory computing a reaction");
        return QD_ERR_NOMEM;
    }
    double *R = J + 3 * n;
    st = at_state(ctx, e, k, r, nvals, syms, vals, lambda[k], J, R);
    if (st == QD_OK) {
        least_squares(n, J, R, F);
        if (residual)
            *residual = residual_of(n, J, R, F);
    }
    qd__free(J);
    return st;
}
