/*
 * cli/args.c - the option parser of args.h: every command declares its
 * options in a table and parses them here.
 */
#include "cli.h"
#include "out.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* ---- the table parser (args.h) ----------------------------------------- */

/* The name of option arg ("--t-end" of "--t-end=2"), as [arg, arg + len). */
static size_t option_name_len(const char *arg) {
    const char *eq = strchr(arg, '=');
    return eq ? (size_t)(eq - arg) : strlen(arg);
}

static bool same(const char *name, const char *arg, size_t len) {
    return name && strlen(name) == len && !strncmp(name, arg, len);
}

/* The option of the table(s) spelt arg[0..len), with the base of its struct. */
static const cli_opt *lookup(const cli_spec *spec, const char *arg, size_t len, size_t *base) {
    for (const cli_opt *o = spec->opts; o && o->name; o++)
        if (same(o->name, arg, len) || same(o->alias, arg, len)) {
            *base = 0;
            return o;
        }
    for (const cli_group *g = spec->groups; g && g->opts; g++)
        for (const cli_opt *o = g->opts; o->name; o++)
            if (same(o->name, arg, len) || same(o->alias, arg, len)) {
                *base = g->base;
                return o;
            }
    return NULL;
}

/* -o/--out FILE of a command that prints to standard output and has no
 * --out of its own: standard output goes to FILE (cli_stdout_to). */
static const cli_opt stdout_opt = {"--out", "-o", CLI_TEXT, 0, "FILE",
                                   "write the output to FILE (default: standard output)", NULL,
                                   NULL};

/* Options renamed so that one word means one thing in every command
 * (issue 31): the old spelling still works where the command has the new
 * one, with a warning. */
static const struct {
    const char *old, *now, *why;
} renamed[] = {
    {"--near", "--guess", "the starting point of a search, as in stability and path"},
};

/* The option arg[0..len) names: the table's, else the new spelling of a
 * renamed one (said on stderr), else the generic -o/--out. */
static const cli_opt *find_option(const cli_spec *spec, const char *arg, size_t len,
                                  size_t *base) {
    const cli_opt *o = lookup(spec, arg, len, base);
    for (size_t k = 0; !o && k < sizeof renamed / sizeof renamed[0]; k++)
        if (same(renamed[k].old, arg, len) &&
            (o = lookup(spec, renamed[k].now, strlen(renamed[k].now), base)) != NULL)
            fprintf(stderr, "qdot: warning: %s is now %s (%s)\n", renamed[k].old,
                    renamed[k].now, renamed[k].why);
    if (!o && (same(stdout_opt.name, arg, len) || same(stdout_opt.alias, arg, len)) &&
        !lookup(spec, stdout_opt.name, strlen(stdout_opt.name), base))
        o = &stdout_opt;
    return o;
}

/* Every option name of the spec, for "did you mean" (at most max). */
static size_t option_names(const cli_spec *spec, const char **names, size_t max) {
    size_t n = 0;
    for (const cli_opt *o = spec->opts; o && o->name && n < max; o++)
        names[n++] = o->name;
    for (const cli_group *g = spec->groups; g && g->opts; g++)
        for (const cli_opt *o = g->opts; o->name && n < max; o++)
            names[n++] = o->name;
    return n;
}

static int unknown_option(const cli_spec *spec, const char *arg, size_t len) {
    const char *names[256];
    size_t n = option_names(spec, names, 256);
    const char *near = qd_nearest_name(arg, len, names, n);
    if (near)
        cli_diag_error("'%s' has no option '%.*s'; did you mean '%s'? (qdot %s --help lists them)",
                       spec->name, (int)len, arg, near, spec->name);
    else
        cli_diag_error("'%s' has no option '%.*s' (qdot %s --help lists them)", spec->name,
                       (int)len, arg, spec->name);
    return QD_EXIT_USAGE;
}

static int set_choice(const cli_spec *spec, const cli_opt *o, const char *v, const char **slot) {
    size_t n = 0;
    for (; o->choices && o->choices[n]; n++)
        if (!strcmp(o->choices[n], v)) {
            *slot = o->choices[n];
            return QD_EXIT_OK;
        }
    const char *near = qd_nearest_name(v, strlen(v), o->choices, n);
    char list[512] = "";
    for (size_t k = 0; k < n; k++) {
        size_t at = strlen(list);
        snprintf(list + at, sizeof list - at, "%s%s", k ? ", " : "", o->choices[k]);
    }
    if (near)
        cli_diag_error("%s %s: unknown value '%s'; did you mean '%s'? (one of %s)", spec->name,
                       o->name, v, near, list);
    else
        cli_diag_error("%s %s: unknown value '%s' (one of %s)", spec->name, o->name, v, list);
    return QD_EXIT_USAGE;
}

static int set_count(const cli_spec *spec, const cli_opt *o, const char *v, size_t *slot) {
    char *end;
    errno = 0;
    unsigned long long k = (v[0] >= '0' && v[0] <= '9') ? strtoull(v, &end, 10) : 0;
    if (v[0] < '0' || v[0] > '9' || *end || errno || k < 1 || k > SIZE_MAX / 2)
        return cli_usage_error("%s %s: '%s' is not a whole number >= 1", spec->name, o->name, v);
    *slot = (size_t)k;
    return QD_EXIT_OK;
}

static int set_nonneg(const cli_spec *spec, const cli_opt *o, const char *v, double *slot) {
    char *end;
    double x = strtod(v, &end);
    if (end == v || *end || !isfinite(x) || x < 0)
        return cli_usage_error("%s %s takes a number >= 0, not '%s'", spec->name, o->name, v);
    *slot = x;
    return QD_EXIT_OK;
}

/* A number within o's bounds (CLI_RANGE), or a whole one (CLI_WHOLE, into
 * a uint64_t). */
static int set_in(const cli_spec *spec, const cli_opt *o, const char *v, void *slot) {
    char *end;
    double lo = strtod(o->choices[0], NULL), hi = strtod(o->choices[1], NULL), x = strtod(v, &end);
    bool whole = o->kind == CLI_WHOLE;
    if (end == v || *end || !(x >= lo && x <= hi) || (whole && x != floor(x)))
        return cli_usage_error(whole ? "%s %s takes a whole number from %.0f to %.0f, not '%s'"
                                     : "%s %s takes a number from %g to %g, not '%s'",
                               spec->name, o->name, lo, hi, v);
    if (whole)
        *(uint64_t *)slot = (uint64_t)x;
    else
        *(double *)slot = x;
    return QD_EXIT_OK;
}

/* Store the value v (NULL for a flag) of option o into args + base. */
static int store(const cli_spec *spec, const cli_opt *o, size_t base, const char *v, void *args) {
    char *field = (char *)args + base + o->offset;
    switch (o->kind) {
    case CLI_FLAG: *(bool *)(void *)field = true; return QD_EXIT_OK;
    case CLI_TEXT: *(const char **)(void *)field = v; return QD_EXIT_OK;
    case CLI_LIST: {
        cli_list *l = (cli_list *)(void *)field;
        if (l->n == CLI_LIST_MAX)
            return cli_usage_error("%s %s: at most %d of them", spec->name, o->name, CLI_LIST_MAX);
        l->items[l->n++] = v;
        return QD_EXIT_OK;
    }
    case CLI_CHOICE:
    case CLI_MAYBE: return set_choice(spec, o, v, (const char **)(void *)field);
    case CLI_COUNT: return set_count(spec, o, v, (size_t *)(void *)field);
    case CLI_NONNEG: return set_nonneg(spec, o, v, (double *)(void *)field);
    case CLI_WHOLE:
    case CLI_RANGE: return set_in(spec, o, v, field);
    case CLI_CALL: return o->call(v, (char *)args + base);
    }
    return QD_EXIT_FAIL;
}

/* Is arg an option of this spec's syntax?  With expressions as positionals,
 * "-x" is an expression and only "--NAME" (and a table's short alias) is
 * an option; otherwise anything starting with '-' but "-" itself. */
static bool looks_like_option(const cli_spec *spec, const char *arg) {
    if (arg[0] != '-' || !arg[1])
        return false;
    if (!spec->expressions)
        return true;
    size_t base;
    return cli_is_option(arg) || find_option(spec, arg, option_name_len(arg), &base);
}

/* One positional more than the command takes. */
static int too_many(const cli_spec *spec, const char *arg) {
    cli_diag_error("'%s' takes %s%u %s; unexpected '%s' (qdot %s --help)", spec->name,
                   spec->min_pos == spec->max_pos ? "" : "at most ", spec->max_pos,
                   spec->pos_name ? spec->pos_name : "arguments", arg, spec->name);
    return QD_EXIT_USAGE;
}

int cli_parse(const cli_spec *spec, int argc, char **argv, void *args, const char **pos) {
    unsigned npos = 0;
    const char *stdout_path = NULL;
    const char *seen_name[256];
    const char *seen_arg[256];
    size_t nseen = 0;
    for (unsigned k = 0; k < spec->max_pos; k++)
        pos[k] = NULL;
    for (int i = 0; i < argc; i++) {
        const char *arg = argv[i];
        if (!strcmp(arg, "--help") || !strcmp(arg, "-h")) {
            cli_usage(spec, stdout); /* asked for, not an error: stdout and 0 */
            exit(cli_out_close(stdout, "standard output", 0)); /* a full disk said, with errno */
        }
        if (!strcmp(arg, "--")) { /* the rest are positionals, even "-x" */
            for (i++; i < argc; i++) {
                if (npos == spec->max_pos)
                    return too_many(spec, argv[i]);
                pos[npos++] = argv[i];
            }
            break;
        }
        if (!looks_like_option(spec, arg)) {
            if (npos == spec->max_pos)
                return too_many(spec, arg);
            pos[npos++] = arg;
            continue;
        }
        size_t len = option_name_len(arg), base = 0;
        const cli_opt *o = find_option(spec, arg, len, &base);
        if (!o)
            return unknown_option(spec, arg, len);
        if (o->kind != CLI_LIST) {
            for (size_t k = 0; k < nseen; k++)
                if (seen_name[k] == o->name) {
                    cli_diag_error("%s is given twice ('%s', then '%s'); give it once", o->name,
                                   seen_arg[k], arg);
                    return QD_EXIT_USAGE;
                }
            if (nseen < 256) {
                seen_name[nseen] = o->name;
                seen_arg[nseen++] = arg;
            }
        }
        const char *v = NULL;
        bool takes = o->metavar != NULL;
        if (arg[len] == '=') {
            if (!takes)
                return cli_usage_error("%s takes no value (given '%s')", o->name, arg);
            v = arg + len + 1;
        } else if (o->kind == CLI_MAYBE) { /* the next word when it is a choice */
            v = o->choices[0];
            for (size_t k = 0; i + 1 < argc && o->choices[k]; k++)
                if (!strcmp(argv[i + 1], o->choices[k]))
                    v = argv[++i];
        } else if (takes) {
            if (i + 1 >= argc)
                return cli_usage_error("%s needs a value: %s %s", o->name, o->name, o->metavar);
            v = argv[++i];
        }
        if (o == &stdout_opt) {
            stdout_path = v;
            continue;
        }
        int rc = store(spec, o, base, v, args);
        if (rc != QD_EXIT_OK)
            return rc;
    }
    if (npos < spec->min_pos)
        return cli_usage_error("%s is missing (usage: qdot %s %s)",
                               spec->pos_name ? spec->pos_name : "an argument", spec->name,
                               spec->synopsis ? spec->synopsis : "");
    /* last, so that a usage error above leaves no file behind */
    return stdout_path ? cli_stdout_to(stdout_path) : QD_EXIT_OK;
}

static void usage_line(FILE *out, const cli_opt *o) {
    char left[96];
    int n = snprintf(left, sizeof left, "%s%s%s%s%s", o->alias ? o->alias : "",
                     o->alias ? ", " : "", o->name, o->metavar ? " " : "",
                     o->metavar ? o->metavar : "");
    if (o->kind == CLI_LIST && n > 0 && (size_t)n + 4 < sizeof left)
        strcat(left, " ...");
    fprintf(out, "  %-26s %s", left, o->help ? o->help : "");
    if ((o->kind == CLI_CHOICE || o->kind == CLI_MAYBE) && o->choices) {
        fputs(" (", out);
        for (size_t k = 0; o->choices[k]; k++)
            fprintf(out, "%s%s", k ? ", " : "", o->choices[k]);
        fputs(")", out);
    }
    fputs("\n", out);
}

void cli_usage(const cli_spec *spec, FILE *out) {
    fprintf(out, "usage: qdot %s %s\n", spec->name, spec->synopsis ? spec->synopsis : "");
    if (spec->summary)
        fprintf(out, "\n%s\n", spec->summary);
    fputs("\noptions:\n", out);
    for (const cli_opt *o = spec->opts; o && o->name; o++)
        usage_line(out, o);
    size_t base;
    for (const cli_group *g = spec->groups; g && g->opts; g++)
        for (const cli_opt *o = g->opts; o->name; o++)
            if (lookup(spec, o->name, strlen(o->name), &base) == o) /* not the command's own */
                usage_line(out, o);
    if (!lookup(spec, stdout_opt.name, strlen(stdout_opt.name), &base))
        usage_line(out, &stdout_opt);
    fprintf(out, "  %-26s %s\n", "-h, --help", "this help");
}

bool cli_is_option(const char *arg) {
    return (arg[0] == '-' && arg[1] == '-' && arg[2]) || !strcmp(arg, "-h");
}
