/*
 * cli/args.c - the argument loop the commands on a model file share:
 * one FILE, and options handed to the command's own parser; and what counts
 * as an option where a command also takes expressions ("-x" is one).
 */
#include "cli.h"

#include <stdlib.h>
#include <string.h>

/* The options that may be given more than once, each time adding one item;
 * every other option is given at most once (a second --t-end is refused,
 * not the last one silently taken). */
static const char *const repeatable[] = {
    "--set", "--input", "--event", "--stop-at", "--trace", "--spring", "--prescribe",
    "--symmetry", "--integral", "--guess", "--driven", NULL,
};

/* The name of option arg ("--t-end" of "--t-end=2"), as [arg, arg + *len). */
static size_t option_name_len(const char *arg) {
    const char *eq = strchr(arg, '=');
    return eq ? (size_t)(eq - arg) : strlen(arg);
}

static bool may_repeat(const char *arg, size_t len) {
    for (size_t k = 0; repeatable[k]; k++)
        if (strlen(repeatable[k]) == len && !strncmp(arg, repeatable[k], len))
            return true;
    return false;
}

/* argv[i] is an option ("--NAME" or -o) given before at an index in seen[0..n). */
static int repeated(char **argv, const int *seen, size_t n, int i) {
    const char *arg = argv[i];
    size_t len = option_name_len(arg);
    if (!(cli_is_option(arg) || !strcmp(arg, "-o")) || may_repeat(arg, len))
        return -1;
    for (size_t k = 0; k < n; k++)
        if (option_name_len(argv[seen[k]]) == len && !strncmp(argv[seen[k]], arg, len))
            return seen[k];
    return -1;
}

int cli_file_args(int argc, char **argv, const char *cmd, const char *usage,
                     const char **file, cli_option opt, void *data) {
    int *seen = malloc(((size_t)argc + 1) * sizeof *seen);
    size_t nseen = 0;
    if (!seen) {
        cli_diag_error("out of memory");
        return QD_EXIT_FAIL;
    }
    for (int i = 0; i < argc; i++) {
        int rc = QD_EXIT_OK;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            /* the command's own usage, on stdout: asked for, not an error */
            printf("%s\n", usage);
            free(seen);
            exit(QD_EXIT_OK);
        }
        int first = argv[i][0] == '-' && argv[i][1] ? repeated(argv, seen, nseen, i) : -1;
        if (first >= 0) {
            int len = (int)option_name_len(argv[i]);
            cli_diag_error("%.*s is given twice ('%s', then '%s'); give it once", len, argv[i],
                           argv[first], argv[i]);
            rc = QD_EXIT_USAGE;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            seen[nseen++] = i;
            rc = opt(argc, argv, &i, data);
        } else if (!*file)
            *file = argv[i];
        else {
            cli_diag_error("'%s' takes one FILE; unexpected '%s'\n%s", cmd, argv[i], usage);
            rc = QD_EXIT_USAGE;
        }
        if (rc != QD_EXIT_OK) {
            free(seen);
            return rc;
        }
    }
    free(seen);
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
