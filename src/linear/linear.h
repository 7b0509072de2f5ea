/*
 * src/linear/linear.h - what the small-oscillation files share: the
 * equations at rest and their first derivatives, compiled once, and the
 * dense LAPACK calls.
 */
#ifndef QD_LINEAR_LINEAR_H
#define QD_LINEAR_LINEAR_H

#include "qdot/eval.h"
#include "qdot/mech.h"
#include "qdot/modes.h"

/* The equations of e at rest, F(q) = f(q, q' = 0), with
 *   J = dF/dq (n*n), B = df/dq' at q' = 0 (n*n), M at q' = 0 (n*n),
 * so that about a point x = q - q0:  M x'' = F(q0) + J x + B x'.
 * The symbolic entries are kept; the numbers come from one compiled
 * program whose inputs are every free symbol (missing ones are 0). */
typedef struct qd__lin {
    qd_ctx *ctx;                       /* where the arrays come from */
    size_t n;
    const qd_expr *const *q;           /* e's coordinates (borrowed) */
    const qd_expr **F, **J, **B, **M;  /* malloc'd arrays of nodes */
    qd_prog *prog;
    size_t nin;
    const qd_expr **inputs;
    size_t *qslot;                     /* n: the input index of q_j, or SIZE_MAX */
    double *in, *out;                  /* nin; n + 3 n^2 */
} qd__lin;

/* Build the derivatives and compile.  QD_ERR_ARG for a model with
 * multipliers (constraints kept). */
qd_status qd__lin_init(qd_ctx *ctx, const qd_eom *e, qd__lin *L);
void qd__lin_free(qd__lin *L);
/* The springs and rods of pic (its np and rest set) into pic->links and
 * pic->pivot (modes_links.c): jac[(j*np + i)*3 + k] = d(position k of
 * particle i)/dq_j at the equilibrium, far (laid out alike) the positions
 * at q0 + H along q_j, H = size/1000, then (at 3 np n and 6 np n) at q0 - H
 * and q0 + 2H, K the n x n stiffness the springs between
 * particles make and Kw that of the springs to walls (NULL: no springs),
 * size the configuration's, owner n to work in. */
void qd__lin_modes_links(qd_modes_picture *pic, const double *jac, const double *far, size_t n,
                         const double *K, const double *Kw, double size, size_t *owner);

/* V's terms that are not linear in the particles' positions (gravity and
 * uniform forces left out; modes_terms.c): nt of them, term k's Hessian at
 * q0 at K + k n^2, and centre[k] the particle it holds to the origin by
 * their distance alone (a spring from there), or SIZE_MAX. */
typedef struct qd__lin_springs {
    size_t nt;
    double *K;
    size_t *centre;
} qd__lin_springs;

/* The terms of m's V at q0 (syms/vals as qd_linear_about takes them, jac
 * as qd__lin_modes_links', size the configuration's).  QD_ERR_ARG for a
 * model without V (L given) or with more terms than are looked at. */
qd_status qd__lin_springs_find(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                               const qd_expr *const *syms, const double *vals, const double *q0,
                               const double *jac, size_t np, double size,
                               qd__lin_springs *out);
void qd__lin_springs_free(qd__lin_springs *s);
/* Set every input from syms/vals (the rest 0). */
void qd__lin_bind(qd__lin *L, size_t nvals, const qd_expr *const *syms, const double *vals);
/* Evaluate at q (n values; NULL keeps the bound ones): L->out then holds
 * F (n), J, B, M (n*n each, row-major). */
void qd__lin_run(qd__lin *L, const double *q);
static inline const double *qd__lin_F(const qd__lin *L) { return L->out; }
static inline const double *qd__lin_J(const qd__lin *L) { return L->out + L->n; }
static inline const double *qd__lin_B(const qd__lin *L) { return L->out + L->n + L->n * L->n; }
static inline const double *qd__lin_M(const qd__lin *L) {
    return L->out + L->n + 2 * L->n * L->n;
}

/* The zero test of the linear analyses (linearize, modes, stability,
 * equilibria): |x| at most QD_LINEAR_ZERO_TOL times the scale of the
 * numbers x came from (a matrix entry against the matrix's own scale). */
#define QD_LINEAR_ZERO_TOL 1e-12
bool qd__lin_negligible(double x, double scale);
/* M0, C0, G0, K0's round-off zeros set to 0, judged in the coordinates where
 * M0's diagonal is 1 against the problem's own rate (linearize.c). */
void qd__lin_linear_chop(qd_linear *l);

/* A part x of one of r's state-space roots as every printer shows it (text
 * and JSON of modes, stability and constrained modes): 0 when |x| is within
 * QD_RESULT_ZERO of the largest |s|, the eigen-solver's round-off (a bowl's
 * ring of relative equilibria turning at w = 3 printed s = 2.1e-17 beside
 * s = 0 and +-3.79i; issue 33).  The result's own numbers stay as solved:
 * the scan bisects the margin's sign. */
double qd__lin_root_shown(const qd_modes_result *r, double x);

/* Eigenvalues (ascending) and, when vecs is not NULL, orthonormal
 * eigenvectors (column-major, vecs[i + j n] = component i of vector j) of
 * the symmetric n*n matrix A (row-major; only its symmetric part is used).
 * false when LAPACK fails. */
bool qd__lin_sym_eig(qd_ctx *ctx, size_t n, const double *A, double *w, double *vecs);

/* ---- models in generalized speeds (speeds_lin.c) ----------------------- */

struct qd_speeds_eom;
/* kept[j] (e->n): q_j enters f_u or M_u, or the kinematic row of another
 * kept coordinate; the others are ignorable for the reduced system. */
void qd__lin_speeds_kept(const struct qd_speeds_eom *e, bool *kept);

/* ---- numeric root finding (newton.c, multistart.c) ------------------------ */

/* A force scale at q: |F|_inf + |J|_inf (1 + |q|_inf); residuals are judged
 * against it. */
double qd__lin_scale(qd__lin *L, const double *q);

/* Damped Newton (Levenberg-Marquardt on |F|^2) from q, in place.  true when
 * max |F_j| <= ftol; *res is max |F_j| at the final q. */
bool qd__lin_lm_solve(qd__lin *L, double *q, double ftol, int maxit, double *res);

/* A found root, angles wrapped into (-pi, pi]. */
typedef struct qd__roots {
    size_t n, count, cap;
    double *q;      /* count * n */
    double *res;    /* count */
} qd__roots;

/* Add q unless it duplicates a root already there (the better residual is
 * kept); false when out of memory. */
bool qd__lin_roots_add(qd_ctx *ctx, qd__roots *r, const double *q, double res, const bool *angle);
void qd__lin_roots_free(qd__roots *r);
void qd__lin_wrap_angles(size_t n, double *q, const bool *angle);
/* The same point: every coordinate within 1e-6 of the largest (and 1),
 * angles (angle may be NULL) modulo 2 pi. */
bool qd__lin_roots_same(size_t n, const double *a, const double *b, const bool *angle);

/* The multi-start search over [lo, hi] (quasi-random starts and axis scans
 * through the centre); roots with max |F| <= ftol go to out.  Each scan and
 * start is reported to the context's progress function (qd_ctx_set_progress);
 * QD_ERR_ARG, recorded, when it asks to stop; QD_ERR_NOMEM. */
qd_status qd__lin_multistart(qd__lin *L, const double *lo, const double *hi, const bool *angle,
                             size_t starts, double ftol, qd__roots *out);

/* The i-th point (i >= 1) of the van der Corput sequence in base, in [0, 1):
 * coordinate j of a Halton start uses base qd__lin_halton_primes[j % 16]
 * (multistart.c, constrained.c). */
double qd__lin_halton(size_t i, unsigned base);
extern const unsigned qd__lin_halton_primes[16];

/* An equilibrium's kind from the n eigenvalues ev of its stiffness (the
 * Hessian of the potential, or K_r of the reduced equations): npos, nneg
 * and nzero (|ev| <= QD_MODES_ZERO_TOL of the largest, or all when every
 * one is 0) and kind (equilibria.c, constrained.c). */
struct qd_equilibrium;
void qd__lin_eq_classify(size_t n, const double *ev, struct qd_equilibrium *p);

/* The search box of qd_equilibria_find into angle, lo, hi (e->n each): the
 * default box (qd_equilibria_default_box), or o's; QD_ERR_ARG naming the
 * coordinate when a range is empty or its width overflows a double. */
struct qd_equilibria_opts;
qd_status qd__lin_eq_box(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                     const struct qd_equilibria_opts *o, bool *angle, double *lo, double *hi);

/* ---- equilibria as JSON (equilibria_print.c), shared with the speeds
 * printer (speeds_print.c) ------------------------------------------------ */
struct qd_json;
/* "method", "exact", "continuum" of eq. */
void qd__lin_eq_json_head(struct qd_json *j, const qd_equilibria *eq);
/* The keys "equilibrium" ({name: value}) and, when p was found exactly,
 * "exact" ({name: expression}) of p, whose k-th value is coordinate
 * q[idx[k]] (idx NULL: q[k]), n of them, into the open object of j. */
void qd__lin_eq_point_json(qd_ctx *ctx, struct qd_json *j, const qd_equilibrium *p, size_t n,
                           const qd_expr *const *q, const size_t *idx);

#endif
