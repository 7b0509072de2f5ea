/*
 * cli/out.h - files the qdot program writes and reads itself: every write,
 * flush and close checked, one message "cannot write FILE: reason" (exit 1),
 * a directory refused by name (exit 2), and the close of standard output
 * at exit.
 */
#ifndef QDOT_CLI_OUT_H
#define QDOT_CLI_OUT_H

#include <stdbool.h>
#include <stdio.h>
#include "qdot/print.h"

/* path opened for writing ("w"), or NULL with the error printed and *rc
 * set: a directory or a path that cannot be created is bad input (2). */
FILE *cli_out_open(const char *path, int *rc);

/* path opened for reading ("r"), or NULL with the error printed and *rc
 * set (2): a directory is refused ("is a directory"), not read as empty. */
FILE *cli_in_open(const char *path, int *rc);

/* One checked write of len bytes; on failure the first error's errno is
 * kept in *err (0 while all went well).  Returns false on failure. */
bool cli_out_write(FILE *f, const void *data, size_t len, int *err);
/* A file the library's writers write to (a qd_sim_write_fn's data):
 * cli_out_put writes with cli_out_write, the first errno kept in err. */
typedef struct cli_out_file {
    FILE *f;
    int err;
} cli_out_file;
int cli_out_put(void *data, const char *bytes, size_t len);

/* Flush and close f (stdout is only flushed: main closes it), then say
 * "cannot write NAME: reason" when this or an earlier write failed (err:
 * the errno kept by cli_out_write, or 0).  NAME is "standard output" for
 * stdout.  Returns 0 (QD_EXIT_OK) or 1 (QD_EXIT_FAIL). */
int cli_out_close(FILE *f, const char *name, int err);

/* b written to path (-o/--out FILE; NULL or "-": standard output), checked
 * as above, and freed.  Returns the exit status (0, 1 a failed write, 2 a
 * path that cannot be opened). */
int cli_out_emit(qd_buf *b, const char *path);

/* The two options of every command that prints one result: --format
 * text|json (json: the field is "json") and -o/--out FILE, as table
 * entries for a struct type with const char * fields. */
extern const char *const cli_formats_text_json[]; /* "text", "json", NULL */
#define CLI_OPT_FORMAT(type, field)                                                          \
    {"--format", NULL, CLI_CHOICE, offsetof(type, field), "FORMAT", "text or json",         \
     cli_formats_text_json, NULL}
#define CLI_OPT_OUT(type, field)                                                             \
    {"--out", "-o", CLI_TEXT, offsetof(type, field), "FILE",                                \
     "write the result to FILE (default: standard output)", NULL, NULL}
bool cli_json(const char *format); /* format is "json" */

/* -o/--out FILE of a command that has no --out of its own (cli_parse):
 * from now on standard output is FILE, opened as cli_out_open does (a
 * directory or a path that cannot be created: exit 2), and the messages
 * of cli_out_close and cli_close_stdout name FILE.  "-" keeps standard
 * output.  Returns the exit status (0 or 2). */
int cli_stdout_to(const char *path);

/* Close standard output once, at the end of main: exit status 1 with the
 * message when anything written to it was lost; else rc. */
int cli_close_stdout(int rc);

/* SIGINT during a run that writes rows (simulate, poincare): the handler
 * only sets a flag, which the row sink reads after writing a whole row and
 * then asks the library to stop (a sink's nonzero return).  begin installs
 * the handler (a second SIGINT kills as usual), end restores the old one. */
void cli_interrupt_begin(void);
bool cli_interrupted(void);
void cli_interrupt_end(void);
enum { CLI_EXIT_INTERRUPTED = 130 }; /* 128 + SIGINT, as a shell reports it */

#endif
