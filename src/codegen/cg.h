/*
 * src/codegen/cg.h - what the code generator's files share (beyond
 * codegen_export.h, what src/sim uses too).
 */
#ifndef QD_CODEGEN_CG_H
#define QD_CODEGEN_CG_H

#include "codegen_export.h"
#include "qdot/codegen.h"

/* The C of e's equations.  embed: one self-contained file (the header's
 * declarations inlined, no #include "prefix.h"), as native loading compiles
 * it; otherwise c includes "<prefix>.h" and h (not NULL) receives it.
 * jacobian false leaves <prefix>_jacobian out (declared, not defined). */
qd_status qd__cg_emit(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *prefix,
                      bool embed, bool jacobian, qd_buf *c, qd_buf *h);

/* The generated file's dense solvers (LU with partial pivoting, Cholesky
 * with an LU fallback), for nk unknowns; appended to out. */
void qd__cg_solvers(qd_buf *out, size_t nk, bool cholesky);

/* The tables every generated file has for the model's parameters:
 * <P>_param_names (NULL-terminated) and <P>_par_default, the values; QD_ERR_ARG
 * (recorded) when a parameter has no value. */
qd_status qd__cg_param_tables(qd_ctx *ctx, const qd_model *m, const char *P, qd_buf *c);

/* ---- a first-order system y = (q, v), as every generated file has it (system.c) ---- */

/* What the functions of a generated file are written from: the coordinates'
 * equations (emit.c: v = q', K = M or [M -A^T; A 0], z = (q'', lambda)) or
 * the speeds' (speeds.c: v = u, K = M_u, z = u').  The arrays are the
 * expressions as printed (after the angle-sum rewrite) and stay the
 * caller's. */
typedef struct cg_form {
    qd_ctx *ctx;
    const qd_model *m;
    const char *P;      /* the prefix */
    qd_buf *c;          /* the .c text, appended to */
    size_t n, nv, nk, np; /* coordinates, the state's second half, unknowns z, parameters */
    const qd_expr *const *q, *const *v, *const *z; /* their symbols: n, nv, nk */
    const char *vname;  /* forcing's argument for v: "qd_qd" or "qd_u" */
    const qd_expr *const *kin;  /* q' = kin (n), with NAME_kinematics; NULL: q' = v */
    const qd_expr *const *dkin; /* d kin/dy (n rows of n + nv), when kin */
    const qd_expr *const *M, *const *f; /* NAME_mass (nv*nv), NAME_forcing (nv) */
    const qd_expr *const *Kr;   /* K (nk*nk) then r (nk), solved by rhs */
    const qd_expr *const *R;    /* dr/dy_k - (dK/dy_k) z: column k at k*nk */
    const qd_expr *h;           /* NAME_energy; NULL: it returns NAN */
    bool h_decl_late;           /* qd_h declared after the (void)s (the speeds' text) */
    bool cholesky;              /* K symmetric: Cholesky with an LU fallback */
    bool no_jacobian;           /* leave NAME_jacobian out (a run's object: half the
                                   text and most of the compiler's time) */
} cg_form;

/* The solvers, then NAME_kinematics (when kin), _mass, _forcing, _rhs,
 * _energy and _jacobian (unless no_jacobian), appended to f->c.  QD_ERR_ARG / QD_ERR_UNBOUND as
 * qd__cg_block. */
qd_status qd__cg_system(const cg_form *f);

/* QD_OK when no entry of M[0..nM) involves syms[0..n); else QD_ERR_ARG
 * recorded: "the mass matrix depends on the WHAT NAME" (rhs factors M before
 * it reads them, and NAME_mass has no argument for them). */
qd_status qd__cg_mass_free_of(qd_ctx *ctx, size_t nM, const qd_expr *const *M, size_t n,
                              const qd_expr *const *syms, const char *what);
/* The .c file's first lines: its name, <math.h> and "P.h". */
void qd__cg_preamble(qd_buf *c, const char *P);

/* ---- the pieces of every generated function (block.c) ---- */

/* Where a function reads a symbol's value: array[index]. */
typedef struct cg_slot {
    const char *array;
    size_t index;
} cg_slot;
/* The generator's answer for sym (never t, which is an argument): its slot,
 * or slot->array left NULL when the function has no value for it. */
typedef qd_status (*cg_bind)(void *data, const qd_expr *sym, cg_slot *slot);

/* The declarations of the symbols out[0..nout) use, then one block
 * assigning out[i] to lhs[i], appended to c (indented one level).  A user
 * function without definition is QD_ERR_ARG; a symbol bind has no slot for
 * is QD_ERR_UNBOUND ("'x' has no value there"). */
qd_status qd__cg_block(qd_ctx *ctx, qd_buf *c, size_t nout, const qd_expr *const *out,
                       const char *const *lhs, cg_bind bind, void *data);
/* The same, the outputs going to array[offset + i]. */
qd_status qd__cg_block_to(qd_ctx *ctx, qd_buf *c, size_t nout, const qd_expr *const *out,
                          const char *array, size_t offset, cg_bind bind, void *data);
/* "array[offset + i]" for i < count, into names (rows of 48), pointed to by lhs. */
void qd__cg_lhs_names(char (*names)[48], const char **lhs, const char *array, size_t offset,
                      size_t count);
void qd__cg_indent(qd_buf *out, const char *text); /* every line, one level in */
/* "(void)t; (void)qd_par;" and names, for arguments a body may not use. */
void qd__cg_unused(qd_buf *c, const char *names);
/* The header's include guard and extern "C" (open), or their ends. */
void qd__cg_guard(qd_buf *h, const char *P, bool open);
/* const char *const <P>_<what>_names[] = {"a", "b", 0}; */
void qd__cg_name_list(qd_buf *c, const char *P, const char *what, size_t n,
                      const qd_expr *const *syms);
/* QD_OK when prefix is a C identifier of at most 60 characters, else
 * QD_ERR_ARG recorded. */
qd_status qd__cg_prefix(qd_ctx *ctx, const char *prefix);

#endif
