/*
 * cli/main.c - the qdot program: finds the command and runs it.
 */
#include "cli.h"
#include "lqr_cli.h"
#include "out.h"

#include <stdlib.h>
#include <string.h>

static const cli_cmd commands[] = {
    {"tour", "", "a one-minute tour of the symbolic kernel", cli_cmd_tour},
    {"diff", "EXPR VAR [VAR...] [--format F]", "partial derivative (repeated for each VAR)",
     cli_cmd_diff},
    {"expand", "EXPR [--format F]", "distribute products and powers of sums", cli_cmd_expand},
    {"simplify", "EXPR [--format F]", "expand, trigonometric identities, cancel, factor",
     cli_cmd_simplify},
    {"print", "EXPR [--format F]", "print an expression in canonical form", cli_cmd_print},
    {"eom", "FILE [--format F] [OPTIONS]",
     "Lagrange's equations of a model, M q'' = f", cli_cmd_eom},
    {"check", "FILE [--format F]", "validate a model and summarize it", cli_cmd_check},
    {"hamiltonian", "FILE [--format F] [--at ...]", "momenta, H and Hamilton's equations",
     cli_cmd_hamiltonian},
    {"form", "EXPR --vars \"x, y\" [--format F]", "a quadratic form: sum of squares, inertia",
     cli_cmd_form},
    {"bracket", "FILE F G | FILE --dt F", "Poisson bracket [F, G], or dF/dt", cli_cmd_bracket},
    {"canonical", "FILE --Q ... --P ... | --generator", "canonical transformations, K = H + dF/dt",
     cli_cmd_canonical},
    {"routh", "FILE --ignore Q[,Q...]", "the Routhian and the reduced equations", cli_cmd_routh},
    {"integrals", "FILE", "integrals of motion: cyclic, Jacobi, Noether, proposed",
     cli_cmd_integrals},
    {"simulate", "FILE --t-end T [OPTIONS]", "integrate the motion; CSV or JSON", cli_cmd_simulate},
    {"poincare", "FILE --section ... --crossings N", "a Poincare surface of section", cli_cmd_poincare},
    {"lyapunov", "FILE --t-end T [--exponents K]", "Lyapunov exponents: Benettin, QR, the sum check",
     cli_cmd_lyapunov},
    {"codegen", "FILE [-o DIR]", "self-contained C for the right-hand side", cli_cmd_codegen},
    {"equilibria", "FILE [--guess ...|--box ...]", "equilibria and their kind",
     cli_cmd_equilibria},
    {"linearize", "FILE [--about ...] [--format F]", "state space x' = A x + B u, controllability",
     cli_cmd_linearize},
    {"modes", "FILE [--about ...]", "small oscillations: frequencies and mode shapes",
     cli_cmd_modes},
    {"stability", "FILE --ignore Q | --driven ...", "steady motions and their stability",
     cli_cmd_stability},
    {"lqr", "--A M --B M --weights \"Q=...,R=...\"", "the LQR gain of x' = A x + B u (Riccati)",
     cli_cmd_lqr},
    {"orbit", "FILE --ignore Q[,Q...] [--at ...]", "turning points, periods, apsides, conics",
     cli_cmd_orbit},
    {"hj", "FILE [--format F] [--solve]", "the Hamilton-Jacobi equation, its separation and W",
     cli_cmd_hj},
    {"action", "FILE [--at ...] [--format F]", "action-angle variables: J, frequencies",
     cli_cmd_action},
    {"action-of", "FILE --path ... --t T0:T1", "the action of a trial path, its first variation",
     cli_cmd_action_of},
    {"zvc", "FILE --box ... --level H", "Jacobi's integral and the zero-velocity curves",
     cli_cmd_zvc},
    {"impulse", "FILE [--at ...] [--prescribe ...]", "a blow, a sudden constraint, a collision",
     cli_cmd_impulse},
    {"scatter", "FILE --energy E --b B|--theta TH", "deflection and cross sections of a central potential",
     cli_cmd_scatter},
    {"path", "FILE --from ... --to ... [--all]", "stationary paths of the action between two points",
     cli_cmd_path},
    {"animate", "FILE -o FILE.html [OPTIONS]", "the motion as a self-contained HTML page",
     cli_cmd_animate},
    {"metric", "FILE [--force ...] [--format F]", "metric g_ij, Christoffel symbols, geodesic form, chart",
     cli_cmd_metric},
    {"sweep", "FILE --grid ... --measure M", "many runs on threads: grids, random, lists",
     cli_cmd_sweep},
    {"lorentz", "--frame \"Vx, Vy, Vz\" [--event ...]", "Lorentz transformation, boost, proper time",
     cli_cmd_lorentz},
    {"collide", "--particle \"m=..., v=(...)\" ...", "relativistic collisions, thresholds, decays",
     cli_cmd_collide},
};
#define NCOMMANDS (sizeof commands / sizeof commands[0])

static void usage(FILE *out) {
    fprintf(out, "usage: qdot COMMAND [ARGS]\n\ncommands:\n");
    for (size_t i = 0; i < NCOMMANDS; i++)
        fprintf(out, "  %-11s %-34s %s\n", commands[i].name, commands[i].args, commands[i].summary);
    fprintf(out, "\nformats (--format): text (default), json, latex, sympy, c, csv: each command\n"
                 "takes the ones that fit it (qdot COMMAND --help)\n"
                 "Expressions use the model language's syntax: x^2*sin(q) + q'/2.\n"
                 "See docs/cli.md and docs/language.md.\n");
}

/* Standard output is closed once, checked: in main after the command, or
 * here when a command ended the program with exit() (--help). */
static bool stdout_closed;

static void close_stdout_at_exit(void) {
    if (!stdout_closed && cli_close_stdout(QD_EXIT_OK) != QD_EXIT_OK)
        _Exit(QD_EXIT_FAIL);
}

static int run(int argc, char **argv);

int main(int argc, char **argv) {
    atexit(close_stdout_at_exit);
    int rc = run(argc, argv);
    stdout_closed = true;
    return cli_close_stdout(rc);
}

static int run(int argc, char **argv) {
    if (argc < 2) {
        usage(stderr);
        return QD_EXIT_USAGE;
    }
    if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h") || !strcmp(argv[1], "help")) {
        usage(stdout);
        return QD_EXIT_OK;
    }
    if (!strcmp(argv[1], "--version")) {
        printf("qdot %s\n", QDOT_VERSION);
        return QD_EXIT_OK;
    }
    for (size_t i = 0; i < NCOMMANDS; i++)
        if (!strcmp(argv[1], commands[i].name)) {
            /* `qdot CMD --help` too: every command answers it from its
             * option table (cli_parse) */
            return commands[i].run(argc - 2, argv + 2);
        }
    return cli_usage_error("unknown command '%s' (try 'qdot --help')", argv[1]);
}
