/*
 * cli/args.h - the one option parser of the qdot program (issue 31).
 *
 * A command declares its options in a table, one cli_opt per option; the
 * parser fills the command's argument struct from argv, refuses what the
 * table does not hold (with "did you mean" for a misspelt option or choice),
 * refuses an option given twice unless it is a list (a CLI_CALL reader too is
 * called once), takes "--NAME VALUE", "--NAME=VALUE" and, after "--", only
 * positionals; and answers --help with
 * a usage generated from the same table: one described line per option.
 * Values that may be expressions in the model's parameters (--t-end "2*pi")
 * are kept as text and read after the model is loaded (qd_model_number).
 */
#ifndef QDOT_CLI_ARGS_H
#define QDOT_CLI_ARGS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h> /* CLI_WHOLE's uint64_t */
#include <stdio.h>

/* The most items a list option (--set, --event, ...) takes in one run. */
#define CLI_LIST_MAX 64

typedef struct cli_list {
    const char *items[CLI_LIST_MAX];
    size_t n;
} cli_list;

typedef enum cli_kind {
    CLI_FLAG,   /* bool: present or not, takes no value */
    CLI_TEXT,   /* const char *: the value as given */
    CLI_LIST,   /* cli_list: may be given again, each time one more item */
    CLI_CHOICE, /* const char *: one of choices (a misspelt one gets "did you mean") */
    CLI_COUNT,  /* size_t: a whole number >= 1 */
    CLI_NONNEG, /* double: a finite number >= 0 (a time, an interval) */
    CLI_WHOLE,  /* uint64_t: a whole number from the bounds' first to their second */
    CLI_RANGE,  /* double: a number from the bounds' first to their second (a tolerance) */
    CLI_MAYBE,  /* const char *: CLI_CHOICE whose value may be left out: choices[0] then
                 * ("--variational" or "--variational columns") */
    CLI_CALL    /* call(value, args): the command's own reader (value NULL for a flag) */
} cli_kind;

typedef struct cli_opt {
    const char *name;     /* "--t-end" */
    const char *alias;    /* "-o", or NULL */
    cli_kind kind;
    size_t offset;        /* of the field in the argument struct (offsetof) */
    const char *metavar;  /* "T" in "--t-end T"; NULL: the option takes no value */
    const char *help;     /* one line for --help */
    const char *const *choices; /* CLI_CHOICE: NULL-terminated; CLI_WHOLE, CLI_RANGE: the
                                 * bounds {"MIN", "MAX"} (CLI_OPT_IN) */
    int (*call)(const char *value, void *args); /* CLI_CALL: returns an exit status */
} cli_opt;

/* A table of options shared by several commands (the simulation options of
 * simulate, poincare, animate, sweep, lyapunov), whose fields sit in a
 * struct embedded at byte base of each command's argument struct. */
typedef struct cli_group {
    const cli_opt *opts; /* ended by an entry with name NULL */
    size_t base;
} cli_group;

typedef struct cli_spec {
    const char *name;     /* "simulate" */
    const char *synopsis; /* "FILE [options]" */
    const char *summary;  /* one line: what the command does */
    const cli_opt *opts;  /* the command's own, ended by an entry with name NULL */
    const cli_group *groups; /* more tables, ended by {NULL, 0}; may be NULL */
    unsigned min_pos, max_pos; /* positional arguments taken (a model command: 1, 1) */
    const char *pos_name;      /* "FILE", "EXPR": in messages */
    bool expressions; /* positionals are expressions: "-x" is one, not an option */
} cli_spec;

/* One plain entry of a table whose fields sit in the struct TYPE:
 * CLI_OPT(TYPE, "--t-end", CLI_TEXT, t_end, "T", "the end time"). */
#define CLI_OPT(TYPE, NAME, KIND, FIELD, META, HELP) \
    {NAME, NULL, KIND, offsetof(TYPE, FIELD), META, HELP, NULL, NULL}
/* An entry whose values lie from MIN to MAX, numbers or macros of numbers
 * (CLI_WHOLE, CLI_RANGE): CLI_OPT_IN(TYPE, "--seed", CLI_WHOLE, seed, "S",
 * "the seed", 0, 9007199254740992). */
#define CLI_OPT_IN(TYPE, NAME, KIND, FIELD, META, HELP, MIN, MAX)                   \
    {NAME, NULL, KIND, offsetof(TYPE, FIELD), META, HELP,                            \
     (const char *const[]){CLI_STR_(MIN), CLI_STR_(MAX), NULL}, NULL}
#define CLI_STR_(X) CLI_STR__(X)
#define CLI_STR__(X) #X

/* The options every model command spells alike, one wording for each
 * (issue 31's one vocabulary): --set NAME=VALUE and --format FORMAT with other choices than
 * CLI_OPT_FORMAT's text|json (cli/out.h). */
#define CLI_OPT_SET(TYPE, FIELD)                                                              \
    {"--set", NULL, CLI_LIST, offsetof(TYPE, FIELD), "NAME=VALUE",                           \
     "give a parameter a value (a number or an expression in the others)", NULL, NULL}
#define CLI_OPT_FORMATS(TYPE, FIELD, CHOICES) \
    {"--format", NULL, CLI_CHOICE, offsetof(TYPE, FIELD), "FORMAT", "the output format", CHOICES, NULL}

/* Parse argv[0..argc) (the arguments after the command name) into args and
 * pos[0..spec->max_pos) (unset ones NULL).  --help (or -h) prints the usage
 * on stdout and exits 0.  Returns 0, or 2 after printing why (an unknown or
 * repeated option, a missing value or positional, a bad choice or count). */
int cli_parse(const cli_spec *spec, int argc, char **argv, void *args, const char **pos);

/* The usage of --help: synopsis, summary and one line per option. */
void cli_usage(const cli_spec *spec, FILE *out);

#endif
