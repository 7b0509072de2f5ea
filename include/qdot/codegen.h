/*
 * qdot/codegen.h - equations of motion as self-contained C, and native loading.
 *
 * qd_codegen_c writes a C11 translation unit (and its header) that needs
 * nothing but <math.h>: for a model with n coordinates and npar parameters,
 * prefix P,
 *
 *   P_N, P_NPAR                       macros (and the constants P_n, P_npar)
 *   P_coord_names[], P_param_names[]  names in model order
 *   P_par_default[]                   the model's parameter values
 *   void   P_mass(t, q, par, M)       M n*n row-major
 *   void   P_forcing(t, q, qd, par, f)
 *   int    P_rhs(t, y, par, dydt)     y = (q, q'), dydt = (q', q''); nonzero
 *                                     when M (or the saddle matrix) is singular
 *   double P_energy(t, y, par)        T + V, or the Jacobi integral
 *                                     h = T2 - T0 + V when T has T1 or T0 terms
 *   void   P_jacobian(t, y, par, J)   2n x 2n row-major d(dydt)/dy, analytic
 *
 * Parameters are passed in `par` in model order, so changing a value needs
 * no regeneration.  With constraints, P_rhs solves [M -A^T; A 0] [q''; l] =
 * [f; b] (LU, partial pivoting) and P_jacobian differentiates that system.
 *
 * qd_native_load compiles that C with the system compiler ($CC, else cc;
 * `-O2 -shared -fPIC`) into cache_dir/<prefix>-<FNV-1a 64 of the text>.so,
 * reusing the file when it is already there, and dlopens it.  When no
 * compiler runs or compilation fails it returns QD_ERR_UNSUPPORTED with the reason
 * (and the compiler's first lines of output) in the context, so the caller
 * can fall back to qd_eom_eval.  So it does when the cache is not the user's
 * alone: a cache_dir owned by another user or writable by group or others,
 * or an object there that is a symlink, not the user's, writable by others
 * or not compiled for this text.
 */
#ifndef QDOT_CODEGEN_H
#define QDOT_CODEGEN_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "print.h"
#include "model.h"
#include "mech.h"

#ifdef __cplusplus
extern "C" {
#endif

struct qd_speeds_eom; /* qdot/speeds.h */

typedef int (*qd_native_rhs)(double t, const double *y, const double *par, double *dydt);

typedef struct qd_native {
    void *handle;              /* dlopen handle */
    size_t n, npar;
    qd_native_rhs rhs;
    void (*mass)(double, const double *, const double *, double *);
    void (*forcing)(double, const double *, const double *, const double *, double *);
    double (*energy)(double, const double *, const double *);
    void (*jacobian)(double, const double *, const double *, double *); /* NULL from
                                                                           qd_native_load_run */
    const double *par_default; /* npar values from the model */
    char path[4096];           /* the .so used */
    bool cached;               /* true when the .so was already there */
} qd_native;

/* ---- the prefix (src/codegen/prefix.c) -------------------------------------- */

/* The longest prefix of generated C, in bytes. */
#define QD_CODEGEN_PREFIX_MAX 60

/* prefix is one qd_codegen_c and qd_codegen_speeds_c take: a C identifier
 * (a letter or '_', then letters, digits and '_') of 1 to
 * QD_CODEGEN_PREFIX_MAX bytes.  false for NULL. */
QD_API bool qd_codegen_prefix_valid(const char *prefix);

/* The prefix a model file's name gives (what `qdot codegen` names NAME.c
 * and NAME.h by): path's last component up to its first '.', every byte
 * that is not a letter, digit or '_' made '_', an 'm' in front when it does
 * not start with a letter or '_', cut at QD_CODEGEN_PREFIX_MAX bytes;
 * "model" for "-" (standard input).  "dir/double-pendulum.qd" gives
 * "double_pendulum", "2body.qd" "m2body".  Written to out (cap bytes,
 * more than QD_CODEGEN_PREFIX_MAX: QD_ERR_ARG otherwise).  An empty base
 * name ("dir/" or ".qd") gives "m". */
QD_API qd_status qd_codegen_prefix_from_path(const char *path, char *out, size_t cap);

/* The C text (c_text) and header text (h_text) of e's equations, with every
 * name prefixed by `prefix` (a C identifier; NULL means "qdot_model").  The
 * .c includes "<prefix>.h".  h_text may be NULL when not wanted. */
QD_API qd_status qd_codegen_c(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *prefix,
                       qd_buf *c_text, qd_buf *h_text);

/* The same for a model in generalized speeds (qdot/speeds.h): the
 * first-order system y = (q, u), prefix P,
 *
 *   P_N, P_M, P_NPAR                  coordinates, speeds, parameters
 *   P_coord_names[], P_speed_names[], P_param_names[], P_par_default[]
 *   void P_kinematics(t, q, u, par, qd)  q' = W u + w (N)
 *   void P_mass(t, q, par, M)            M_u (M*M row-major)
 *   void P_forcing(t, q, u, par, f)      f_u (M)
 *   int  P_rhs(t, y, par, dydt)          y = (q, u), dydt = (q', u'), u' from
 *                                        M_u u' = f_u; nonzero when M_u is
 *                                        singular
 *   double P_energy(t, y, par)           T + V in q and u (NAN for a model
 *                                        given by L or with U)
 *   void P_jacobian(t, y, par, J)        (N+M) x (N+M) row-major d(dydt)/dy,
 *                                        analytic
 *
 * QD_ERR_ARG for a bad prefix or a mass matrix that depends on the speeds. */
QD_API qd_status qd_codegen_speeds_c(qd_ctx *ctx, const qd_model *m, const struct qd_speeds_eom *e,
                                     const char *prefix, qd_buf *c_text, qd_buf *h_text);

/* What `qdot codegen` writes for m (the files NAME.c and NAME.h): for a
 * model with `speeds` the system in (q, u) (qd_speeds_derive,
 * qd_codegen_speeds_c), else Lagrange's equations (qd_eom_derive_opts with
 * eliminate: the holonomic constraints solved for a coordinate substituted;
 * qd_codegen_c).  eliminate with speeds is QD_ERR_ARG about the option
 * "eliminate" (the speeds already take the constraints into account).  A
 * derivation's error is left in ctx as the derivation recorded it
 * (qd_model_locate places it in the model).  h_text may be NULL. */
QD_API qd_status qd_codegen_model_c(qd_ctx *ctx, const qd_model *m, bool eliminate,
                                    const char *prefix, qd_buf *c_text, qd_buf *h_text);

/* Generate, compile (or reuse) and load.  cache_dir NULL: $XDG_CACHE_HOME/qdot,
 * else $HOME/.cache/qdot (created 0700 when missing).  On failure *out is zeroed. */
QD_API qd_status qd_native_load(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *cache_dir,
                         qd_native *out);
/* The same for a run, which needs only P_rhs: the object is made without
 * P_jacobian (out->jacobian NULL), about half the text and a fifth of the
 * compiler's time for a large model (20 links: 5.4 s of gcc -O2 to 1.5 s),
 * and cached under its own name. */
QD_API qd_status qd_native_load_run(qd_ctx *ctx, const qd_model *m, const qd_eom *e,
                                    const char *cache_dir, qd_native *out);
QD_API void qd_native_unload(qd_native *nat);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_codegen_c (h_text);
 * qd_codegen_speeds_c (h_text); qd_native_load (cache_dir). An array whose
 * count is 0 may be NULL. */
#endif
