/* cli/cmd_stability.c - placeholder while `qdot stability` is being written. */
#include "cli.h"

int qd_cmd_stability(int argc, char **argv) {
    (void)argc;
    (void)argv;
    qd_diag_error("'stability' is not built yet");
    return QD_EXIT_FAIL;
}
