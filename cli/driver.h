/*
 * cli/driver.h - the one entry point shape of the commands: parse the
 * arguments, check them, make the context, run, free.  Each command's run
 * state starts with a cli_run, so the driver owns the parts every command
 * has (context, model file, FILE operand) and the command's hooks own the
 * rest.  (simulate, poincare, lyapunov, animate and sweep get theirs from
 * cli_sim_setup instead.)
 */
#ifndef QDOT_CLI_DRIVER_H
#define QDOT_CLI_DRIVER_H

#include <stddef.h>
#include "model_cli.h" /* and cli.h, model_file.h: what every driven command uses */
#include "out.h"

/* The first member of every driven command's run state. */
typedef struct cli_run {
    qd_ctx *ctx;
    cli_model_file mf; /* freed by the driver after the free hook */
    const char *file;  /* the FILE operand when cli_driver.pos is 0 */
} cli_run;

/* What a command gives the driver; hooks take the run state by its first
 * member (cast back to the command's type). */
typedef struct cli_driver {
    const cli_spec *spec;
    size_t args; /* offset of the options struct in the run state */
    size_t pos;  /* offset of the operands; 0 (the context's place): &cli_run.file */
    int (*check)(cli_run *r); /* usage checks once parsed, before the context; may be NULL */
    int (*run)(cli_run *r);
    void (*free)(cli_run *r); /* what run made, before mf and ctx; may be NULL */
} cli_driver;

/* Parse argv into the run state r (zeroed by the caller, any defaults set),
 * check, make r->ctx ("out of memory" and 1 if it cannot), run, free.
 * Returns the first exit status that is not QD_EXIT_OK, or run's. */
int cli_drive(const cli_driver *d, cli_run *r, int argc, char **argv);

/* The entry point `int cli_cmd_NAME(int argc, char **argv)` of a command
 * whose run state TYPE starts with its cli_run, zeroed: cli_drive with the
 * cli_driver whose fields follow (spec, args, pos, check, run, free). */
#define CLI_COMMAND(NAME, TYPE, ...)                                     \
    int cli_cmd_##NAME(int argc, char **argv) {                          \
        static const cli_driver d = {__VA_ARGS__};                       \
        TYPE r = {0};                                                    \
        return cli_drive(&d, (cli_run *)(void *)&r, argc, argv);         \
    }

/* What the library printed into b with status st: on error b is freed and
 * the context's error shown, else b goes to standard output (cli_emit). */
int cli_emit_status(const qd_ctx *ctx, qd_status st, qd_buf *b, const char *what);

#endif
