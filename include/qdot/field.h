/*
 * qdot/field.h - continuous systems: a field y(x, t) on an interval with a
 * Lagrangian density (Desloge ch. 83, Problem 4: the stretched string).
 *
 *     field y(x, t) on x = 0 .. l
 *     Ldensity = rho/2*y_t^2 - tau/2*y_x^2
 *     boundary y(0) = 0, y(l) = 0          (an end may be `free` instead)
 *
 * The field equation is the Euler-Lagrange equation of the density,
 *
 *     d/dt dL/dy_t + d/dx dL/dy_x - dL/dy = 0        (rho y_tt - tau y_xx = 0).
 *
 * Its normal modes y = Y(x) cos(omega t) solve the Sturm-Liouville problem
 * -(tau Y')' + kappa Y = omega^2 rho Y for a density of the form
 * rho(x)/2 y_t^2 - tau(x)/2 y_x^2 - kappa(x)/2 y^2 (terms linear in y shift
 * the equilibrium, not the modes).  A fixed end has Y = 0, a free end tau Y' = 0
 * (the natural condition).  With rho, tau, kappa constant the modes are exact:
 * Y = sin(k (x - a)) or cos(k (x - a)), k = n pi/l (fixed-fixed, n >= 1;
 * free-free, n >= 0) or (n - 1/2) pi/l (one end free), and
 * omega^2 = (tau k^2 + kappa)/rho.  Otherwise linear finite elements
 * (Galerkin, consistent mass, 3-point Gauss quadrature) on N, 2N, 4N, ...
 * elements give omega^2 = omega_h^2 + O(h^2); Richardson's extrapolation
 * (4 w_2N - w_N)/3 removes the h^2 term, and the error estimate is the
 * difference of two successive extrapolations plus the rounding of the
 * eigenvalue solver (eps times the largest eigenvalue, which grows as 1/h^2).
 * N doubles until every requested mode's estimate is below tol * omega; when
 * refining makes the estimates worse, or the largest N is met, the best
 * level is kept and the result says it did not converge.
 */
#ifndef QDOT_FIELD_H
#define QDOT_FIELD_H

#include "model.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct qd_field qd_field;

typedef enum qd_field_end { QD_FIELD_FIXED, QD_FIELD_FREE } qd_field_end;

/* Does the text declare a field (a line starting with `field`)?  Commands
 * use it to choose between qd_field_parse and qd_model_parse. */
QD_API bool qd_field_declared(const char *text);

/* Read a field model: the statements parameters, definitions, field,
 * Ldensity and boundary.  NULL with diag located on error (opts as for
 * qd_model_parse_opts; it may be NULL, and so may diag). */
QD_API qd_field *qd_field_parse(qd_ctx *ctx, const char *text, const qd_model_opts *opts,
                                qd_diag *diag);
QD_API void qd_field_free(qd_field *f);

/* The model the statements filled (for qd_model_where: "field",
 * "Ldensity", "boundary"); it has no coordinates. */
QD_API const qd_model *qd_field_model(const qd_field *f);
QD_API const char *qd_field_name(const qd_field *f);       /* "y" */
QD_API const char *qd_field_space(const qd_field *f);      /* "x" */
QD_API const qd_expr *qd_field_density(const qd_field *f); /* as written */
/* The interval's ends (numbers) and the condition at end 0 (a) or 1 (b). */
QD_API qd_status qd_field_interval(const qd_field *f, double *a, double *b);
QD_API qd_field_end qd_field_boundary(const qd_field *f, int end);

/* The left side E of the field equation E = 0, in y, y_t, y_x, y_tt, y_xt,
 * y_xx, x and t (the symbols named NAME, NAME_t, ... for the field NAME). */
QD_API const qd_expr *qd_field_equation(qd_ctx *ctx, const qd_field *f);

typedef enum qd_field_shape { QD_FIELD_SHAPE_NONE, QD_FIELD_SHAPE_SIN, QD_FIELD_SHAPE_COS } qd_field_shape;

typedef struct qd_field_mode {
    double omega, omega2;
    double error;          /* estimated absolute error of omega; 0 when exact */
    qd_field_shape shape;  /* exact modes: Y = sin or cos(k (x - a)) */
    double k;
} qd_field_mode;

typedef struct qd_field_modes_opts {
    size_t count;          /* modes wanted; 0: 5 */
    double tol;            /* relative; 0: 1e-6 */
    size_t max_elements;   /* 0: 16384 */
} qd_field_modes_opts;

typedef struct qd_field_modes {
    bool exact;            /* constant coefficients: closed form */
    bool converged;        /* discretized: every estimate below tol */
    double tol;            /* the tolerance the estimates were held to (opts or 1e-6) */
    size_t elements;       /* discretized: the finest mesh used */
    const qd_expr *rho, *tau, *kappa; /* the coefficients, in x */
    size_t n;
    qd_field_mode *mode;
} qd_field_modes;

/* The lowest count modes.  QD_ERR_ARG (with the reason in ctx) when the
 * density is not quadratic in y, y_t, y_x of the form above, depends on t,
 * or rho <= 0 or tau < 0 somewhere. */
QD_API qd_status qd_field_modes_compute(qd_ctx *ctx, const qd_field *f,
                                        const qd_field_modes_opts *opts, qd_field_modes *out);
QD_API void qd_field_modes_free(qd_field_modes *r);

/* ---- printers (src/field/print.c) ----------------------------------------
 * Appended to out.  The head of both: "field y(x, t) on x = A .. B: fixed
 * at x = A, free at x = B" (text) or the keys field, space, interval,
 * boundary ("fixed"/"free"), density (JSON).  QD_ERR_NOMEM when out could
 * not grow, QD_ERR_ARG when a JSON number was not finite (the reason in
 * ctx). */

/* The field equation E = 0 (E: qd_field_equation): text, or one JSON
 * document {head..., "equation"} and a newline. */
QD_API qd_status qd_field_equation_print(qd_ctx *ctx, const qd_field *f, const qd_expr *E,
                                         qd_buf *out);
QD_API qd_status qd_field_equation_json(qd_ctx *ctx, const qd_field *f, const qd_expr *E,
                                        qd_buf *out);
/* The modes r of f: text (the coefficients, how they were found, a table of
 * mode, omega ("unstable" where omega^2 < 0), omega^2 and the shape, exact,
 * or the error estimate; computed results by the digit rule of
 * qd_result_format, each column against its largest entry), or one JSON
 * document {head..., rho, tau, kappa, method ("exact" or "finite
 * elements"), converged, elements (null when exact), tolerance, modes:
 * [{omega (null when omega^2 < 0), omega2, error, shape ("sin(k*x)", null
 * when none), k}]} and a newline.  A shape is an expression one may
 * evaluate: k keeps every digit. */
QD_API qd_status qd_field_modes_print(qd_ctx *ctx, const qd_field *f, const qd_field_modes *r,
                                      qd_buf *out);
QD_API qd_status qd_field_modes_json(qd_ctx *ctx, const qd_field *f, const qd_field_modes *r,
                                     qd_buf *out);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_field_parse (opts, diag);
 * qd_field_modes_compute (opts). An array whose count is 0 may be NULL. */
#endif
