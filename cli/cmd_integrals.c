/* cli/cmd_integrals.c - placeholder while `qdot integrals` is being written. */
#include "cli.h"

int qd_cmd_integrals(int argc, char **argv) {
    (void)argc;
    (void)argv;
    qd_diag_error("'integrals' is not built yet");
    return QD_EXIT_FAIL;
}
