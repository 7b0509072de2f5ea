/*
 * cli/cmd_tour.c - `qdot tour`: one minute with the symbolic kernel, the
 * library's qd_tour_print (qdot/print.h).
 */
#include "driver.h"

static const cli_opt tour_opts[] = {{0}};
static const cli_spec tour_spec = {
    "tour", "", "a one-minute tour of the symbolic kernel", tour_opts, NULL, 0, 0, NULL, false,
};

static int run(cli_run *c) {
    qd_buf b = QD_BUF_INIT;
    return cli_emit_status(c->ctx, qd_tour_print(c->ctx, &b), &b, "tour");
}

CLI_COMMAND(tour, cli_run, &tour_spec, 0, 0, NULL, run, NULL)
