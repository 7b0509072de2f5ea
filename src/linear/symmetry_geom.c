/*
 * src/linear/symmetry_geom.c - the symmetry operations of an equilibrium
 * from its particles (Desloge ch. 66: an operation permutes equal particles
 * and moves the figure onto itself by a rotation or reflection).
 *
 * The figure y_i (positions at q0 from the centre of mass) spans r <= 3
 * dimensions: in a frame F whose first r axes span it, an operation is
 * R = F diag(Q, D) F^T with Q r*r orthogonal and D = diag(+-1) on the
 * complement.  Q is fixed by the images of r reference particles a_k
 * (chosen far apart): every r-tuple b_k of equal masses, equal distances
 * from the centre and equal mutual dot products gives Q = Z_b Z_a^-1; the
 * candidates that map every particle onto one of equal mass are kept.  Each
 * induces S = (J^T J)^-1 J^T B on the displacements, B the stacked J_i
 * moved by (R, P): row block P(i) is R J_i.
 */
#include "symmetry.h"
#include "linear.h"

#include "base/mem.h"
#include "num/num.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The figure at q0: masses, positions from the centre, Jacobians. */
typedef struct geom {
    size_t np, n;
    double *mass;   /* np */
    double *y;      /* np*3 */
    double *J;      /* np*3 rows of n: J[(3i + k) n + j] = d r_ik / d q_j */
    double *JtJ;    /* n*n */
    double F[9];    /* columns: the frame, first r spanning the figure */
    double *z;      /* np*3: F^T y */
    size_t r;
    double len;     /* max |y_i| (1 when all at the centre) */
} geom;

static void geom_free(geom *g) {
    qd__free(g->mass);
    qd__free(g->y);
    qd__free(g->J);
    qd__free(g->JtJ);
    qd__free(g->z);
}

/* The particle positions with the eliminated coordinates substituted:
 * the expressions the Jacobian is taken of. */
static const qd_expr *position(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t i,
                               unsigned k) {
    const qd_expr *p = qd_model_particle_position(m, i, k);
    for (size_t j = 0; p && j < e->nelim; j++)
        p = qd_subs(ctx, p, 1, &e->elim[j].q, &e->elim[j].value);
    return p ? p : qd_int(ctx, 0);
}

/* Masses, positions and Jacobians as one compiled program, run once. */
static qd_status evaluate(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                          const qd_expr *const *syms, const double *vals, geom *g) {
    size_t np = g->np, n = g->n, nout = np * (4 + 3 * n), nin = 0;
    const qd_expr **out = qd__calloc(ctx, nout + 1, sizeof *out);
    if (!out)
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < np; i++) {
        out[i] = qd_model_particle_mass(m, i);
        for (unsigned k = 0; k < 3; k++) {
            const qd_expr *p = position(ctx, e, m, i, k);
            out[np + 3 * i + k] = p;
            for (size_t j = 0; p && j < n; j++)
                out[4 * np + (3 * i + k) * n + j] = qd_diff(ctx, p, e->q[j]);
        }
    }
    qd_status st = qd_ctx_status(ctx);
    const qd_expr **in = st == QD_OK ? qd__num_inputs(ctx, nout, out, &nin) : NULL;
    qd_prog *prog = in ? qd_prog_new(ctx, nin, in, nout, out) : NULL;
    double *x = qd__calloc(ctx, nin + 1, sizeof *x), *res = qd__malloc(ctx, (nout + 1) * sizeof *res);
    if (prog && x && res) {
        for (size_t a = 0; a < nin; a++)
            for (size_t k = 0; k < nvals; k++)
                if (syms[k] == in[a]) {
                    x[a] = vals[k];
                    break;
                }
        qd_prog_run(prog, x, res);
        memcpy(g->mass, res, np * sizeof *res);
        memcpy(g->y, res + np, 3 * np * sizeof *res);
        memcpy(g->J, res + 4 * np, 3 * np * n * sizeof *res);
    } else if (st == QD_OK) {
        st = qd_ctx_status(ctx) ? qd_ctx_status(ctx) : QD_ERR_NOMEM;
    }
    qd_prog_free(prog);
    qd__free(in);
    qd__free(x);
    qd__free(res);
    qd__free(out);
    return st;
}

/* J^T J nonsingular: every coordinate moves some particle, so S is fixed
 * by the particles' displacements. */
static bool full_rank(geom *g) {
    size_t n = g->n, rows = 3 * g->np;
    for (size_t a = 0; a < n; a++)
        for (size_t b = 0; b < n; b++) {
            double s = 0;
            for (size_t i = 0; i < rows; i++)
                s += g->J[i * n + a] * g->J[i * n + b];
            g->JtJ[a * n + b] = s;
        }
    double *A = malloc((n * n + 1) * sizeof *A);
    size_t *pc = malloc((n + 1) * sizeof *pc);
    size_t rank = 0;
    if (A && pc) {
        memcpy(A, g->JtJ, n * n * sizeof *A);
        rank = qd__num_rank(n, A, NULL, 1e-10, pc, NULL, NULL);
    }
    free(A);
    free(pc);
    return rank == n;
}

/* Centre of mass, the frame of the figure and its dimension r. */
static bool frame(qd_ctx *ctx, geom *g) {
    double c[3] = {0}, mt = 0, C[9] = {0}, w[3], V[9];
    for (size_t i = 0; i < g->np; i++) {
        mt += g->mass[i];
        for (int k = 0; k < 3; k++)
            c[k] += g->mass[i] * g->y[3 * i + k];
    }
    if (!(mt > 0))
        return false;
    g->len = 0;
    for (size_t i = 0; i < g->np; i++) {
        double *y = g->y + 3 * i;
        for (int k = 0; k < 3; k++)
            y[k] -= c[k] / mt;
        g->len = fmax(g->len, sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]));
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                C[a * 3 + b] += y[a] * y[b];
    }
    if (g->len == 0)
        g->len = 1;
    if (!qd__lin_sym_eig(ctx, 3, C, w, V))
        return false;
    g->r = 0;
    for (int k = 2; k >= 0; k--) {   /* descending: the spanning axes first */
        for (int a = 0; a < 3; a++)
            g->F[a * 3 + (2 - k)] = V[a + 3 * k];
        if (w[k] > 1e-12 * w[2] && w[2] > 0)
            g->r++;
    }
    for (size_t i = 0; i < g->np; i++)
        for (int a = 0; a < 3; a++) {
            double s = 0;
            for (int b = 0; b < 3; b++)
                s += g->F[b * 3 + a] * g->y[3 * i + b];
            g->z[3 * i + a] = s;
        }
    return true;
}

static double dot_r(const double *a, const double *b, size_t r) {
    double s = 0;
    for (size_t k = 0; k < r; k++)
        s += a[k] * b[k];
    return s;
}

/* Reference particles: the farthest from the centre, then the one farthest
 * from the span of those chosen (a well-conditioned Z_a). */
static void references(const geom *g, size_t *ref) {
    for (size_t k = 0; k < g->r; k++) {
        double best = -1;
        for (size_t i = 0; i < g->np; i++) {
            double v[3];
            memcpy(v, g->z + 3 * i, sizeof v);
            for (size_t l = 0; l < k; l++) {   /* Gram-Schmidt against the chosen */
                const double *u = g->z + 3 * ref[l];
                double uu = dot_r(u, u, g->r), uv = dot_r(u, v, g->r);
                for (size_t a = 0; a < 3; a++)
                    v[a] -= uv / uu * u[a];
            }
            double d = dot_r(v, v, g->r);
            if (d > best) {
                best = d;
                ref[k] = i;
            }
        }
    }
}

typedef struct search {
    qd_ctx *ctx;
    geom *g;
    const qd_linear *lin;
    qd__symm_ops *ops;
    size_t ref[3], img[3];
    double Ainv[9];      /* Z_a^-1, r*r row-major */
    double *B, *S, *A, *rhs, *x;   /* scratch */
    size_t *perm;
    bool *used;
    double tol;          /* positions: relative to len */
    qd_status st;
} search;

/* The permutation R induces, or false when some particle has no image. */
static bool match(search *s, const double *R) {
    geom *g = s->g;
    memset(s->used, 0, g->np * sizeof *s->used);
    for (size_t i = 0; i < g->np; i++) {
        double ry[3] = {0};
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                ry[a] += R[a * 3 + b] * g->y[3 * i + b];
        size_t j = 0;
        for (; j < g->np; j++) {
            if (s->used[j] || fabs(g->mass[j] - g->mass[i]) > 1e-12 * fabs(g->mass[i]))
                continue;
            double d = 0;
            for (int a = 0; a < 3; a++)
                d = fmax(d, fabs(ry[a] - g->y[3 * j + a]));
            if (d <= s->tol * g->len)
                break;
        }
        if (j == g->np)
            return false;
        s->perm[i] = j;
        s->used[j] = true;
    }
    return true;
}

/* x = (J^T J)^-1 J^T b for the stacked b (3 np); the residual
 * max |J x - b| back. */
static double least_squares(search *s, const double *b, double *x) {
    geom *g = s->g;
    size_t n = g->n, rows = 3 * g->np;
    for (size_t a = 0; a < n; a++) {
        double t = 0;
        for (size_t i = 0; i < rows; i++)
            t += g->J[i * n + a] * b[i];
        x[a] = t;
    }
    memcpy(s->A, g->JtJ, n * n * sizeof *s->A);
    qd__num_solve(n, s->A, x, 0);
    double res = 0;
    for (size_t i = 0; i < rows; i++) {
        double t = 0;
        for (size_t a = 0; a < n; a++)
            t += g->J[i * n + a] * x[a];
        res = fmax(res, fabs(t - b[i]));
    }
    return res;
}

/* S from (R, perm), kept when the image of every displacement is one of
 * the model's and M0, K0 are invariant. */
static void induce(search *s, const double *R) {
    geom *g = s->g;
    size_t n = g->n, np = g->np;
    double jmax = 0, res = 0;
    for (size_t i = 0; i < 3 * np * n; i++)
        jmax = fmax(jmax, fabs(g->J[i]));
    for (size_t i = 0; i < np; i++)
        for (int a = 0; a < 3; a++)
            for (size_t j = 0; j < n; j++) {
                double t = 0;
                for (int b = 0; b < 3; b++)
                    t += R[a * 3 + b] * g->J[(3 * i + b) * n + j];
                s->B[(3 * s->perm[i] + a) * n + j] = t;
            }
    for (size_t j = 0; j < n; j++) {
        for (size_t i = 0; i < 3 * np; i++)
            s->rhs[i] = s->B[i * n + j];
        res = fmax(res, least_squares(s, s->rhs, s->x));
        for (size_t a = 0; a < n; a++)
            s->S[a * n + j] = s->x[a];
    }
    if (res > 1e-9 * jmax)
        return;
    if (!qd__lin_symm_invariant(n, s->S, s->lin->M) || !qd__lin_symm_invariant(n, s->S, s->lin->K))
        return;
    if (!qd__lin_symm_ops_add(s->ctx, s->ops, s->S, R))
        s->st = QD_ERR_NOMEM;
}

/* Every R = F diag(Q, D) F^T for the images img of the references. */
static void candidate(search *s) {
    geom *g = s->g;
    size_t r = g->r;
    double Q[9] = {0}, Rf[9] = {0}, R[9];
    for (size_t a = 0; a < r; a++)           /* Q = Z_b Z_a^-1 */
        for (size_t b = 0; b < r; b++)
            for (size_t k = 0; k < r; k++)
                Q[a * 3 + b] += g->z[3 * s->img[k] + a] * s->Ainv[k * 3 + b];
    for (size_t a = 0; a < r; a++)           /* orthogonal? */
        for (size_t b = 0; b < r; b++) {
            double t = 0;
            for (size_t k = 0; k < r; k++)
                t += Q[k * 3 + a] * Q[k * 3 + b];
            if (fabs(t - (a == b)) > 1e-8)
                return;
        }
    for (unsigned signs = 0; signs < (1u << (3 - r)); signs++) {
        memset(Rf, 0, sizeof Rf);
        for (size_t a = 0; a < r; a++)
            for (size_t b = 0; b < r; b++)
                Rf[a * 3 + b] = Q[a * 3 + b];
        for (size_t a = r; a < 3; a++)
            Rf[a * 3 + a] = (signs >> (a - r)) & 1 ? -1 : 1;
        for (int a = 0; a < 3; a++)          /* R = F Rf F^T */
            for (int b = 0; b < 3; b++) {
                double t = 0;
                for (int k = 0; k < 3; k++)
                    for (int l = 0; l < 3; l++)
                        t += g->F[a * 3 + k] * Rf[k * 3 + l] * g->F[b * 3 + l];
                R[a * 3 + b] = t;
            }
        if (match(s, R))
            induce(s, R);
        if (s->st != QD_OK || s->ops->overflow)
            return;
    }
}

/* The images of reference k onward: equal mass, distance and dot
 * products with the images already chosen. */
static void extend(search *s, size_t k) {
    geom *g = s->g;
    if (k == g->r) {
        candidate(s);
        return;
    }
    size_t a = s->ref[k];
    double tol = s->tol * g->len * g->len;
    for (size_t b = 0; b < g->np && s->st == QD_OK && !s->ops->overflow; b++) {
        if (fabs(g->mass[b] - g->mass[a]) > 1e-12 * fabs(g->mass[a]))
            continue;
        bool ok = true;
        for (size_t l = 0; l <= k && ok; l++) {
            size_t al = l == k ? a : s->ref[l], bl = l == k ? b : s->img[l];
            ok = fabs(dot_r(g->z + 3 * al, g->z + 3 * a, g->r) -
                      dot_r(g->z + 3 * bl, g->z + 3 * b, g->r)) <= tol;
        }
        if (ok) {
            s->img[k] = b;
            extend(s, k + 1);
        }
    }
}

/* Z_a^-1 (r*r) by columns. */
static bool invert_refs(search *s) {
    size_t r = s->g->r;
    for (size_t c = 0; c < r; c++) {
        double A[9], x[3];
        for (size_t a = 0; a < r; a++) {
            for (size_t k = 0; k < r; k++)
                A[a * r + k] = s->g->z[3 * s->ref[k] + a];
            x[a] = a == c;
        }
        if (!qd__num_solve(r, A, x, 1e-12))
            return false;
        for (size_t a = 0; a < r; a++)
            s->Ainv[a * 3 + c] = x[a];
    }
    return true;
}

/* Translations along x, y, z and rotations about them that are
 * displacements of the model: dq with J dq = the rigid motion. */
static qd_status rigid_motions(search *s, double **rigid, size_t *nrigid, qd_mode_kind **kind) {
    geom *g = s->g;
    size_t n = g->n, np = g->np;
    *rigid = qd__calloc(s->ctx, 6 * n + 1, sizeof **rigid);
    *kind = qd__calloc(s->ctx, 7, sizeof **kind);
    if (!*rigid || !*kind)
        return QD_ERR_NOMEM;
    *nrigid = 0;
    for (int t = 0; t < 6; t++) {
        int a = t % 3;
        double bmax = 0;
        for (size_t i = 0; i < np; i++) {
            double *b = s->rhs + 3 * i, *y = g->y + 3 * i;
            b[0] = b[1] = b[2] = 0;
            if (t < 3)
                b[a] = 1;
            else {                       /* e_a x y */
                b[(a + 1) % 3] = -y[(a + 2) % 3];
                b[(a + 2) % 3] = y[(a + 1) % 3];
            }
            for (int k = 0; k < 3; k++)
                bmax = fmax(bmax, fabs(b[k]));
        }
        double *x = *rigid + *nrigid * n;
        if (bmax > 1e-9 * g->len && least_squares(s, s->rhs, x) <= 1e-8 * bmax)
            (*kind)[(*nrigid)++] = t < 3 ? QD_MODE_TRANSLATION : QD_MODE_ROTATION;
        else
            memset(x, 0, n * sizeof *x);
    }
    return QD_OK;
}

static qd_status search_run(qd_ctx *ctx, geom *g, const qd_linear *lin, qd__symm_ops *ops,
                            double **rigid, size_t *nrigid, qd_mode_kind **kind) {
    size_t n = g->n, np = g->np;
    search s = {.ctx = ctx, .g = g, .lin = lin, .ops = ops, .tol = 1e-7};
    s.B = qd__malloc(ctx, (3 * np * n + 1) * sizeof *s.B);
    s.S = qd__malloc(ctx, (n * n + 1) * sizeof *s.S);
    s.A = qd__malloc(ctx, (n * n + 1) * sizeof *s.A);
    s.rhs = qd__malloc(ctx, (3 * np + 1) * sizeof *s.rhs);
    s.x = qd__malloc(ctx, (n + 1) * sizeof *s.x);
    s.perm = qd__malloc(ctx, (np + 1) * sizeof *s.perm);
    s.used = qd__malloc(ctx, (np + 1) * sizeof *s.used);
    if (!s.B || !s.S || !s.A || !s.rhs || !s.x || !s.perm || !s.used)
        s.st = QD_ERR_NOMEM;
    if (s.st == QD_OK) {
        references(g, s.ref);
        if (invert_refs(&s))
            extend(&s, 0);
    }
    if (s.st == QD_OK)
        s.st = rigid_motions(&s, rigid, nrigid, kind);
    qd__free(s.B);
    qd__free(s.S);
    qd__free(s.A);
    qd__free(s.rhs);
    qd__free(s.x);
    qd__free(s.perm);
    qd__free(s.used);
    return s.st;
}

qd_status qd__lin_symm_geometric(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                             const qd_expr *const *syms, const double *vals,
                             const qd_linear *lin, qd__symm_ops *ops, double **rigid,
                             size_t *nrigid, qd_mode_kind **rigid_kind, bool *found) {
    *found = false;
    geom g = {.np = qd_model_nparticles(m), .n = e->n};
    if (g.np == 0 || qd_model_nbodies(m) > 0 || g.n == 0)
        return QD_OK;
    size_t np = g.np, n = g.n;
    g.mass = qd__calloc(ctx, np + 1, sizeof *g.mass);
    g.y = qd__calloc(ctx, 3 * np + 1, sizeof *g.y);
    g.z = qd__calloc(ctx, 3 * np + 1, sizeof *g.z);
    g.J = qd__calloc(ctx, 3 * np * n + 1, sizeof *g.J);
    g.JtJ = qd__calloc(ctx, n * n + 1, sizeof *g.JtJ);
    qd_status st = g.mass && g.y && g.z && g.J && g.JtJ ? QD_OK : QD_ERR_NOMEM;
    if (st == QD_OK)
        st = evaluate(ctx, e, m, nvals, syms, vals, &g);
    if (st == QD_OK && full_rank(&g) && frame(ctx, &g)) {
        *found = true;
        st = search_run(ctx, &g, lin, ops, rigid, nrigid, rigid_kind);
    }
    geom_free(&g);
    return st;
}
