/*
 * cli/args.c - the argument loop the commands on a model file share:
 * one FILE, and options handed to the command's own parser; and what counts
 * as an option where a command also takes expressions ("-x" is one).
 */
#include "cli.h"

#include <stdlib.h>
#include <string.h>

int cli_file_args(int argc, char **argv, const char *cmd, const char *usage,
                     const char **file, cli_option opt, void *data) {
    for (int i = 0; i < argc; i++) {
        int rc = QD_EXIT_OK;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            /* the command's own usage, on stdout: asked for, not an error */
            printf("%s\n", usage);
            exit(QD_EXIT_OK);
        }
        if (argv[i][0] == '-' && argv[i][1])
            rc = opt(argc, argv, &i, data);
        else if (!*file)
            *file = argv[i];
        else {
            cli_diag_error("'%s' takes one FILE; unexpected '%s'\n%s", cmd, argv[i], usage);
            rc = QD_EXIT_USAGE;
        }
        if (rc != QD_EXIT_OK)
            return rc;
    }
    if (!*file) {
        cli_diag_error("FILE is missing\n%s", usage);
        return QD_EXIT_USAGE;
    }
    return QD_EXIT_OK;
}

bool cli_is_option(const char *arg) {
    return (arg[0] == '-' && arg[1] == '-' && arg[2]) || !strcmp(arg, "-h");
}

const char *cli_value(int argc, char **argv, int *i, const char *opt) {
    size_t len = strlen(opt);
    if (strncmp(argv[*i], opt, len))
        return NULL;
    if (argv[*i][len] == '=')
        return argv[*i] + len + 1;
    if (argv[*i][len] || *i + 1 >= argc)
        return NULL;
    return argv[++*i];
}

size_t cli_item_end(const char *text, size_t i) {
    for (int depth = 0; text[i] && (text[i] != ',' || depth); i++)
        depth += text[i] == '(' ? 1 : text[i] == ')' && depth ? -1 : 0;
    return i;
}
