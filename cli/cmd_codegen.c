/* cli/cmd_codegen.c - placeholder while `qdot codegen` is being written. */
#include "cli.h"

int qd_cmd_codegen(int argc, char **argv) {
    (void)argc;
    (void)argv;
    qd_diag_error("'codegen' is not built yet");
    return QD_EXIT_FAIL;
}
