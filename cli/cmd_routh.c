/* cli/cmd_routh.c - placeholder while `qdot routh` is being written. */
#include "cli.h"

int qd_cmd_routh(int argc, char **argv) {
    (void)argc;
    (void)argv;
    qd_diag_error("'routh' is not built yet");
    return QD_EXIT_FAIL;
}
