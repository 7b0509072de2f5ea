/*
 * qdot/symmetry.h - symmetry-adapted small oscillations (Desloge ch. 66 and
 * App. 28-30): the symmetry group of an equilibrium, its character table,
 * the decomposition of the displacements into irreducible representations,
 * symmetry coordinates that block-diagonalize K0, and modes labelled by
 * their irreps.
 *
 * An operation g acts on the displacements dq = q - q0 by an n*n matrix
 * S_g with S_g^T M0 S_g = M0 and S_g^T K0 S_g = K0 (T and V invariant to
 * second order).  From particles (`particle m at r(q)`), g is a pair (R, P):
 * R an orthogonal 3x3 map about the centre of mass, P a permutation of
 * equal-mass particles with R y_i = y_P(i) (y the positions at q0 from the
 * centre of mass); the displacement dr_i = J_i dq (J_i = dr_i/dq at q0)
 * goes to dr_P(i) = R dr_i, so S = J^+ (R, P) J, kept when J S = (R, P) J
 * (the image is a displacement of the model) and M0, K0 are invariant.
 * Without particle geometry (T, V or L given, rigid bodies) the operations
 * are the signed permutations of the coordinates that leave M0 and K0
 * invariant: an abstract group, without a point-group name.
 *
 * The reducible character is chi(g) = tr S_g; the multiplicity of irrep i
 * is n_i = (1/|G|) sum_g conj(chi_i(g)) chi(g); its projector
 * P_i = (d_i/|G|) sum_g conj(chi_i(g)) S_g is M0-self-adjoint, and an
 * M0-orthonormal basis of its range (the symmetry coordinates of irrep i;
 * a complex-conjugate pair of irreps gives one real block, P_i + P_i*)
 * makes U^T K0 U block diagonal.  Each block is a symmetric eigenproblem;
 * its w^2 come d_i times (the essential degeneracy).  Ownership: every
 * array of a qd_symmetry is the library's; qd_symmetry_free releases them.
 */
#ifndef QDOT_SYMMETRY_H
#define QDOT_SYMMETRY_H

#include <stdbool.h>
#include <stddef.h>
#include "expr.h"
#include "json.h"
#include "mech.h"
#include "model.h"
#include "modes.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Relative size under which an invariance residual (S^T M0 S - M0,
 * S^T K0 S - K0 against max |M0|, max |K0|) or a displacement outside the
 * model's range counts as round-off. */
#define QD_SYMMETRY_TOL 1e-10
/* The largest group searched (signed permutations of uncoupled equal
 * oscillators grow as 2^n n!): beyond it QD_ERR_TOOBIG. */
#define QD_SYMMETRY_MAX_ORDER 1024

typedef enum qd_mode_kind {
    QD_MODE_VIBRATION,     /* w^2 != 0, or a zero mode not rigid */
    QD_MODE_TRANSLATION,   /* a rigid translation of every particle */
    QD_MODE_ROTATION,      /* a rigid rotation about the centre of mass */
    QD_MODE_ZERO           /* w^2 = 0, not a rigid motion */
} qd_mode_kind;

/* "vibration", "translation", "rotation" or "zero mode".  Static storage. */
QD_API const char *qd_mode_kind_name(qd_mode_kind k);

typedef struct qd_symmetry {
    size_t n;              /* coordinates */
    size_t order;          /* |G|; element 0 is the identity */
    bool geometric;        /* from particles: R holds the 3x3 maps */
    double *S;             /* order * n*n, row-major S_g */
    double *R;             /* order * 9, row-major (geometric), else NULL */
    size_t *table;         /* order*order: table[a*order + b] = index of S_a S_b */
    char name[16];         /* Schoenflies ("C3v", "Td") or "" (abstract) */
    size_t nclass;
    size_t *class_of;      /* order: element -> class (class 0 is {E}) */
    size_t *class_size;    /* nclass */
    size_t *class_rep;     /* nclass */
    size_t nirrep;         /* = nclass */
    size_t *irrep_dim;     /* nirrep */
    double *chi_re, *chi_im;  /* nirrep*nclass: [i*nclass + c] */
    char (*label)[12];     /* nirrep: Mulliken labels (A1, E, T2, Ag...) */
    /* qd_symmetry_reduce: */
    double *chi;           /* nclass: the reducible character tr S_g */
    size_t *mult;          /* nirrep: n_i */
    size_t nblock;         /* real blocks: an irrep, or a complex pair */
    size_t *block_irrep;   /* nblock: the irrep (the first of a pair) */
    size_t *block_pair;    /* nblock: the conjugate irrep of a pair, or the irrep itself */
    size_t *block_start, *block_size;   /* nblock: columns of U */
    double *U;             /* n*n, column j a symmetry coordinate, U^T M0 U = I */
    double *Kb;            /* n*n, U^T K0 U (row-major) */
    double offblock;       /* max |Kb| off the blocks / max |Kb| */
    double *omega2;        /* n, ascending */
    double *shapes;        /* n*n, shapes[i*n + j]: mode j, a^T M0 a = 1 */
    size_t *mode_block;    /* n */
    size_t *mode_degeneracy;  /* n: d_i (2 d_i for a complex pair) */
    qd_mode_kind *mode_kind;  /* n */
    /* rigid motions found in the displacements (geometric only) */
    size_t nrigid;
    double *rigid;         /* nrigid * n: translations x, y, z then rotations */
    qd_mode_kind *rigid_kind; /* nrigid */
} qd_symmetry;

/* The symmetry group of the equilibrium q0 (the state syms/vals, as for
 * qd_linear_about; lin its linearization there), with its classes,
 * character table, name and labels.  A group of order 1 is not an error:
 * out->order = 1 (the caller says "no symmetry").  QD_ERR_TOOBIG beyond
 * QD_SYMMETRY_MAX_ORDER; QD_ERR_ARG for a system that is not conservative
 * (C0 or G0 not zero). */
QD_API qd_status qd_symmetry_find(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                                  const qd_expr *const *syms, const double *vals,
                                  const qd_linear *lin, qd_symmetry *out);

/* The group of given operations: order matrices S (n*n each, the identity
 * among them) and, when R is not NULL, their 3x3 maps for the point-group
 * name.  QD_ERR_ARG when they are not closed under products, or leave M0
 * or K0 of lin not invariant. */
QD_API qd_status qd_symmetry_from_ops(qd_ctx *ctx, const qd_linear *lin, size_t order,
                                      const double *S, const double *R, qd_symmetry *out);

/* Decompose and solve: chi, mult, the symmetry coordinates, Kb and the
 * labelled modes.  QD_ERR_NUMERIC when a multiplicity is not an integer,
 * a projector's rank is not n_i d_i, or Kb is not block diagonal (1e-8). */
QD_API qd_status qd_symmetry_reduce(qd_ctx *ctx, const qd_linear *lin, qd_symmetry *sym);

/* The classes, character table, Schoenflies name and Mulliken labels of
 * the finite group with Cayley table table (order*order, row-major:
 * table[a*order + b] the index of a b), and, when R is not NULL, the 3x3
 * orthogonal maps of its elements (order*9, for the point-group name and
 * the labels; NULL: an abstract group, irreps G1, G2, ...).  out is filled
 * as a qd_symmetry without operations (n = 0, S NULL: no reduction), order,
 * table and R copied; qd_symmetry_free releases it.  QD_ERR_ARG when the
 * table is not a group's (closure, identity, inverses, associativity) or
 * order exceeds 4096; nothing to free on failure. */
QD_API qd_status qd_group_characters(qd_ctx *ctx, size_t order, const size_t *table,
                                     const double *R, qd_symmetry *out);
/* Block b's label: the irrep's, or a complex pair's without the letter a/b
 * where their labels differ ("E" from Ea and Eb, "E1" from E1a and E1b, "E'"
 * from Ea' and Eb'; else "A+B").  cap >= 32. */
QD_API void qd_symmetry_block_label(const qd_symmetry *sym, size_t b, char *buf, size_t cap);
/* Class c's name: geometric from its R (E, C3, C2, sigma, i, S4, C3^2) with
 * its size in front ("2C3", "3sigma"); abstract "E" or "2g3" (2 elements of
 * order 3).  cap >= 24. */
QD_API void qd_symmetry_class_name(const qd_symmetry *sym, size_t c, char *buf, size_t cap);
QD_API void qd_symmetry_free(qd_symmetry *sym);

/* ---- the cyclic fast path (src/linear/symmetry_cyclic.c) -------------------
 *
 * A system invariant under the shift of its coordinates by c places
 * (q_j -> q_{j+c mod n}: N = n/c identical cells in a ring, each of c
 * coordinates) has Bloch modes x_{j,a} = u_a e^{i theta_k j}, theta_k =
 * 2 pi k/N: harmonic k is the c*c Hermitian pencil
 *     Khat_k[a][b] = sum_j K0[a][j c + b] e^{i theta_k j}   (and Mhat_k),
 * the irreps of the cyclic group C_N.  n^2 work to form, N pencils of size
 * c to solve, instead of the n^3 of the full eigenproblem: the ring of N
 * masses, N = 1000, in milliseconds. */
typedef struct qd_cyclic_modes {
    size_t n, cells, cell;  /* coordinates, N, c */
    double *omega2;         /* n, ascending */
    size_t *harmonic;       /* n: k in 0..N/2 (k and N - k are one real pair) */
    size_t *degeneracy;     /* n: 1 for k = 0 and k = N/2, else 2 */
} qd_cyclic_modes;

/* The smallest cell c (a divisor of n with N = n/c >= 3) for which lin is
 * shift-invariant to QD_SYMMETRY_TOL, or 0 when none is. */
QD_API size_t qd_cyclic_cell(const qd_linear *lin);
/* The modes by harmonics for cell c (qd_cyclic_cell).  QD_ERR_ARG when lin
 * is not invariant under that shift; QD_ERR_SINGULAR when some Mhat_k is
 * not positive definite. */
QD_API qd_status qd_cyclic_solve(qd_ctx *ctx, const qd_linear *lin, size_t cell,
                                 qd_cyclic_modes *out);
QD_API void qd_cyclic_modes_free(qd_cyclic_modes *c);

/* From this many coordinates on, a system invariant under a shift of its
 * coordinates takes the cyclic fast path (no group table): below it the
 * group and its character table are cheap and say more. */
#define QD_SYMMETRY_FAST_N 48

/* Which way the symmetry of lin is had (src/linear/symmetry_method.c): the
 * cell c of the cyclic fast path (qd_cyclic_cell, qd_cyclic_solve) when
 * lin->n >= QD_SYMMETRY_FAST_N and lin is shift-invariant, else 0: the
 * group (qd_symmetry_find, qd_symmetry_reduce). */
QD_API size_t qd_symmetry_fast_cell(const qd_linear *lin);

/* What `qdot modes --symmetry` and Python's Model.modes(symmetry=True)
 * compute about the point syms/vals (lin its linearization there, e
 * derived from m): the cyclic fast path when qd_symmetry_fast_cell gives a
 * cell (cyc filled, cyc->n > 0), else the group (qd_symmetry_find, then
 * qd_symmetry_reduce: sym filled, order > 1).  When the point has no
 * symmetry (order 1) or its group cannot be had (qd_symmetry_find failed
 * other than for memory: damped, too large), neither is filled, a sentence
 * saying why, ending "; the plain modes follow", is appended to note, the
 * error is cleared and QD_OK returned: the plain modes stand.  sym and cyc
 * are zeroed first; free both (qd_symmetry_free, qd_cyclic_modes_free),
 * also after a failure. */
QD_API qd_status qd_modes_symmetry(qd_ctx *ctx, const qd_eom *e, const qd_model *m, size_t nvals,
                                   const qd_expr *const *syms, const double *vals,
                                   const qd_linear *lin, qd_symmetry *sym, qd_cyclic_modes *cyc,
                                   qd_buf *note);

/* ---- printed (src/linear/symmetry_print.c) ---------------------------------
 *
 * What `qdot modes --symmetry` prints in place of the plain modes (the
 * whole document: qd_modes_print, qdot/modes.h).  sym: reduced
 * (qd_symmetry_reduce), its n the number of coordinates of e, whose names
 * label the coordinates and shapes.  Numbers in the text: 12 significant
 * digits (qd_buf_put_result), w^2 and K0's blocks 0 at or below 1e-12
 * (scale 1), a symmetry coordinate's or a shape's components at or below
 * 1e-12 of its largest; w to 10 digits; characters as integers when they
 * are (else 4 digits, complex as a+bi).  JSON: every digit. */

/* Text appended to out: "symmetry group: NAME (order N, K classes)" (or an
 * abstract group's), the character table with the reducible character
 * Gamma below it, Gamma's decomposition ("Gamma = A1 + A2 + 2E"), the
 * symmetry coordinates (the columns of U) by block, K0 in them by block,
 * and each mode: w^2, w (or the growth rate), block label, multiplicity
 * and, for a rigid or zero mode, its kind; its shape.  QD_ERR_ARG when sym
 * is not reduced or not on e's coordinates; QD_ERR_NOMEM when out failed. */
QD_API qd_status qd_symmetry_print(const qd_symmetry *sym, const qd_eom *e, qd_buf *out);
/* The member "symmetry" (key and object) into j: "group" (the Schoenflies
 * name, or null for an abstract group), "order", "classes" (each "name",
 * "size"), "characters" (each "irrep", "dimension", "chi" and, when
 * complex, "chi_imag"), "reducible", "multiplicities" (irrep to n_i) and
 * "blocks" (each "irrep", "K", "coordinates": name to value per column).
 * Nothing when sym is not reduced on e's coordinates. */
QD_API void qd_symmetry_json(qd_json *j, const qd_symmetry *sym, const qd_eom *e);
/* The member "modes" (key and array) into j, each mode "omega2", "omega",
 * "period" (qd_json_frequency), "irrep" (its block's label),
 * "multiplicity", "kind" (qd_mode_kind_name) and "shape" (name to value).
 * Nothing when sym is not reduced on e's coordinates. */
QD_API void qd_symmetry_json_modes(qd_json *j, const qd_symmetry *sym, const qd_eom *e);

/* qd_modes_plot with a symmetry: the modes sym reduced (sym->omega2,
 * sym->shapes), ordered and paired as its irreps are, each panel noting its
 * irrep ("A1", "E"), when sym is a group of order > 1 with its modes; res's
 * own modes otherwise (sym NULL, the identity alone, or a cyclic fast path,
 * whose harmonics are not a point group's).  Arguments and failures as
 * qd_modes_plot's. */
QD_API qd_status qd_symmetry_modes_plot(qd_ctx *ctx, const qd_eom *e, const qd_model *m,
                                        size_t nvals, const qd_expr *const *syms,
                                        const double *vals, const qd_modes_result *res,
                                        const qd_symmetry *sym, const char *title,
                                        struct qd_plot **out);

/* The fast path's modes as text appended to out: the shift and the group
 * C_N, then each mode's w^2, w, harmonic k and multiplicity.  QD_ERR_ARG
 * for an empty c (n = 0); QD_ERR_NOMEM when out failed. */
QD_API qd_status qd_cyclic_print(const qd_cyclic_modes *c, qd_buf *out);
/* The member "symmetry" into j: "group" "cyclic", "order" N, "cell" c,
 * "fast_path" true.  Nothing for an empty c. */
QD_API void qd_cyclic_json(qd_json *j, const qd_cyclic_modes *c);
/* The member "modes" into j, each mode "omega2", "omega", "period",
 * "irrep" ("k=K"), "harmonic" and "multiplicity".  Nothing for an empty c. */
QD_API void qd_cyclic_json_modes(qd_json *j, const qd_cyclic_modes *c);

#ifdef __cplusplus
}
#endif

/* NULL (issue 30): a function of this header given NULL for a pointer it
 * needs does nothing and returns QD_ERR_ARG (recorded in ctx when ctx is
 * given), NULL, 0, false or NaN, as its return type has it; a void function
 * returns, and every _free accepts NULL. NULL is an accepted value, as
 * documented at the function, for: qd_symmetry_from_ops (R); qd_group_characters
 * (R). An array whose
 * count is 0 may be NULL. */
#endif
