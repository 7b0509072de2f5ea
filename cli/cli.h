/*
 * cli/cli.h - what the command files of the qdot program share.
 *
 * Only the program prints or exits; every command returns an exit status:
 * 0 success, 1 failure (numerical or internal), 2 bad input or usage, and 3
 * a certified "no" to the question a command asks (canonical: the map is not
 * canonical; check: the model fails a check), printed with its witness.
 */
#ifndef QDOT_CLI_H
#define QDOT_CLI_H

#include <stdio.h>
#include "qdot/qdot.h"
#include "args.h"

enum { QD_EXIT_OK = 0, QD_EXIT_FAIL = 1, QD_EXIT_USAGE = 2, QD_EXIT_NO = 3 };

/* The one rule from a library status to the exit status: the input's fault
 * (a bad argument, text that does not read, a symbol with no value, an exact
 * division by zero, a form the call needs and the input lacks) is 2; every
 * other error (numerical, memory, I/O, unsupported) is 1. */
int cli_exit(qd_status st);

typedef struct cli_cmd {
    const char *name;
    const char *args;     /* usage after the name */
    const char *summary;
    int (*run)(int argc, char **argv);
} cli_cmd;

/* Diagnostics (diag.c): "qdot: error: ..." and the caret under a source span. */
void cli_diag_error(const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* The same, for the many places a bad command line ends at: returns
 * QD_EXIT_USAGE so that they read "return cli_usage_error(...)". */
int cli_usage_error(const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 1, 2)))
#endif
    ;
int cli_out_of_memory(void); /* "out of memory", then QD_EXIT_FAIL */
/* An error record shown through the library's one renderer: located ones as
 * FILE:LINE:COL, the line of text and a caret, then the hint. */
void cli_diag_show(const char *file, const char *text, const qd_diag *d);
void cli_diag_read(const char *file, const char *text, const qd_diag *err); /* a reader's */
int cli_diag_ctx(const qd_ctx *ctx); /* prints the context's error, returns the exit status */
/* The context's error after a derivation from model m read from file: at the
 * statement, constraint or coordinate it is about, with its hint. */
int cli_diag_model(const qd_ctx *ctx, const char *file, const char *text, const qd_model *m);


/* Is arg an option ("--NAME", "--NAME=V", "-h") where a command also takes
 * expressions?  "-x", "-p_x*2" and "-1" are expressions, not options. */
bool cli_is_option(const char *arg);

/* Parse "--format NAME" values; false for an unknown name. */
bool cli_format(const char *name, qd_format *out);
/* The same for a --format whose other choices (json) print elsewhere:
 * NULL or a name cli_format does not know is text. */
qd_format cli_format_or_text(const char *name);
/* --format NAME for the library's renderers (qd_render_*): NULL is text;
 * cli_parse has checked the name against the command's choices. */
qd_render_format cli_render_format(const char *name);

int cli_cmd_tour(int argc, char **argv);
int cli_cmd_diff(int argc, char **argv);
int cli_cmd_expand(int argc, char **argv);
int cli_cmd_simplify(int argc, char **argv);
int cli_cmd_print(int argc, char **argv);
int cli_cmd_eom(int argc, char **argv);   /* cmd_eom.c */
int cli_cmd_check(int argc, char **argv); /* cmd_check.c */
int cli_cmd_hamiltonian(int argc, char **argv); /* cmd_hamiltonian.c */
int cli_cmd_bracket(int argc, char **argv);   /* cmd_bracket.c */
int cli_cmd_canonical(int argc, char **argv); /* cmd_canonical.c */
int cli_cmd_routh(int argc, char **argv);      /* cmd_routh.c */
int cli_cmd_integrals(int argc, char **argv);  /* cmd_integrals.c */
int cli_cmd_simulate(int argc, char **argv);   /* cmd_simulate.c */
int cli_cmd_poincare(int argc, char **argv);   /* cmd_poincare.c */
int cli_cmd_lyapunov(int argc, char **argv);   /* cmd_lyapunov.c */
int cli_cmd_codegen(int argc, char **argv);    /* cmd_codegen.c */
int cli_cmd_equilibria(int argc, char **argv); /* cmd_equilibria.c */
int cli_cmd_modes(int argc, char **argv);      /* cmd_modes.c */
int cli_cmd_linearize(int argc, char **argv);  /* cmd_linearize.c */
int cli_cmd_stability(int argc, char **argv);  /* cmd_stability.c */
int cli_cmd_orbit(int argc, char **argv);      /* cmd_orbit.c */
int cli_cmd_hj(int argc, char **argv);         /* cmd_hj.c */
int cli_cmd_action(int argc, char **argv);     /* cmd_action.c */
int cli_cmd_action_of(int argc, char **argv);  /* cmd_action_of.c */
int cli_cmd_zvc(int argc, char **argv);        /* cmd_zvc.c */
int cli_cmd_impulse(int argc, char **argv);    /* cmd_impulse.c */
int cli_cmd_scatter(int argc, char **argv);    /* cmd_scatter.c */
int cli_cmd_path(int argc, char **argv);       /* cmd_path.c */
int cli_cmd_animate(int argc, char **argv);    /* cmd_animate.c */
int cli_cmd_metric(int argc, char **argv);     /* cmd_metric.c */
int cli_cmd_sweep(int argc, char **argv);      /* cmd_sweep.c */
int cli_cmd_lorentz(int argc, char **argv);    /* cmd_lorentz.c */
int cli_cmd_collide(int argc, char **argv);    /* cmd_collide.c */
int cli_cmd_form(int argc, char **argv);       /* cmd_form.c */


#endif
