/* cli/cmd_simulate.c - placeholder while `qdot simulate` is being written. */
#include "cli.h"

int qd_cmd_simulate(int argc, char **argv) {
    (void)argc;
    (void)argv;
    qd_diag_error("'simulate' is not built yet");
    return QD_EXIT_FAIL;
}
