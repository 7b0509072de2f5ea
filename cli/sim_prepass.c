/*
 * cli/sim_prepass.c - the simulation options taken out of argv before
 * cli_parse reads a command's own (interim: see sim_prepass.h).
 */
#include "sim_prepass.h"

#include <string.h>

#include "cli.h"

static size_t name_len(const char *arg) {
    const char *eq = strchr(arg, '=');
    return eq ? (size_t)(eq - arg) : strlen(arg);
}

static bool repeats(const char *arg, size_t len) {
    static const char *const lists[] = {"--set", "--input", "--event", "--stop-at"};
    for (size_t k = 0; k < sizeof lists / sizeof *lists; k++)
        if (strlen(lists[k]) == len && !strncmp(arg, lists[k], len))
            return true;
    return false;
}

int cli_sim_prepass(int argc, char **argv, cli_sim_args *a, char **rest, int *nrest) {
    const char *seen[256], *given[256]; /* the option's name, and as written */
    size_t nseen = 0;
    *nrest = 0;
    for (int i = 0; i < argc; i++) {
        char *arg = argv[i];
        /* -o is --out: the fake argv lends the value its long name */
        char out_name[] = "--out";
        char *fake[2] = {out_name, i + 1 < argc ? argv[i + 1] : NULL};
        bool o = !strcmp(arg, "-o") && i + 1 < argc;
        int j = 0, rc = QD_EXIT_OK;
        const char *name = o ? "--out" : arg;
        size_t len = name_len(name);
        int before = i;
        if (!(o ? cli_sim_took_option(2, fake, &j, a, &rc)
                : cli_sim_took_option(argc, argv, &i, a, &rc))) {
            rest[(*nrest)++] = arg;
            continue;
        }
        if (o)
            i++;
        for (size_t k = 0; k < nseen && !repeats(name, len); k++)
            if (name_len(seen[k]) == len && !strncmp(seen[k], name, len)) {
                cli_diag_error("%.*s is given twice ('%s', then '%s'); give it once", (int)len,
                               name, given[k], argv[before]);
                return QD_EXIT_USAGE;
            }
        if (nseen < 256) {
            given[nseen] = argv[before];
            seen[nseen++] = name;
        }
        if (rc != QD_EXIT_OK)
            return rc;
    }
    return QD_EXIT_OK;
}
