/* cli/cmd_poincare.c - placeholder while `qdot poincare` is being written. */
#include "cli.h"

int qd_cmd_poincare(int argc, char **argv) {
    (void)argc;
    (void)argv;
    qd_diag_error("'poincare' is not built yet");
    return QD_EXIT_FAIL;
}
