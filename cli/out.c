/*
 * cli/out.c - checked writes and closes (out.h).  A write error (a full
 * disk, /dev/full, a closed pipe's end) is a failure of the run: the data
 * is lost, so the exit status says so.
 */
#define _GNU_SOURCE
#include "out.h"

#include <errno.h>
#include <signal.h>
#include <stdio_ext.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli.h"

static bool is_dir(const char *path) {
    struct stat sb;
    return stat(path, &sb) == 0 && S_ISDIR(sb.st_mode);
}

/* path opened with mode "w" or "r", or why not ("cannot write ...") and
 * *rc the usage error. */
static FILE *open_file(const char *path, const char *mode, int *rc) {
    const char *verb = mode[0] == 'w' ? "write" : "read";
    FILE *f = is_dir(path) ? NULL : fopen(path, mode);
    if (!f) {
        cli_diag_error("cannot %s %s: %s", verb, path, is_dir(path) ? "is a directory"
                                                                    : strerror(errno));
        *rc = QD_EXIT_USAGE;
    }
    return f;
}

FILE *cli_out_open(const char *path, int *rc) { return open_file(path, "w", rc); }
FILE *cli_in_open(const char *path, int *rc) { return open_file(path, "r", rc); }

bool cli_out_write(FILE *f, const void *data, size_t len, int *err) {
    errno = 0;
    if (fwrite(data, 1, len, f) == len)
        return true;
    if (!*err)
        *err = errno ? errno : EIO;
    return false;
}

int cli_out_put(void *data, const char *bytes, size_t len) {
    cli_out_file *o = data;
    if (ferror(o->f))
        return 1; /* an earlier write failed: said at the close */
    return cli_out_write(o->f, bytes, len, &o->err) ? 0 : 1;
}

/* What standard output is, for messages: a file after -o FILE. */
static const char *stdout_name = "standard output";

int cli_stdout_to(const char *path) {
    if (!strcmp(path, "-"))
        return QD_EXIT_OK;
    int rc = QD_EXIT_OK;
    FILE *f = cli_out_open(path, &rc);
    if (!f)
        return rc;
    fflush(stdout); /* nothing is written before the options are read; if it were, it stays */
    int fd = fileno(f);
    if (fd != STDOUT_FILENO) { /* fd 1 itself when qdot started with stdout closed (>&-) */
        if (dup2(fd, STDOUT_FILENO) < 0) {
            cli_diag_error("cannot write %s: %s", path, strerror(errno));
            fclose(f);
            return QD_EXIT_FAIL;
        }
        fclose(f);
    }
    clearerr(stdout); /* a closed stdout's earlier error belongs to the old file */
    stdout_name = path;
    return QD_EXIT_OK;
}

static void cannot_write(const char *name, int err) {
    cli_diag_error("cannot write %s: %s", name, err ? strerror(err) : "write error");
}

int cli_out_close(FILE *f, const char *name, int err) {
    errno = 0;
    bool bad = fflush(f) != 0;
    if (bad && !err)
        err = errno;
    bad = bad || ferror(f) || err;
    if (f == stdout) {
        if (bad) {
            cannot_write(stdout_name, err);
            clearerr(f); /* said once: main does not repeat it */
        }
        return bad ? QD_EXIT_FAIL : QD_EXIT_OK;
    }
    errno = 0;
    if (fclose(f) != 0) {
        if (!err)
            err = errno;
        bad = true;
    }
    if (bad)
        cannot_write(name, err);
    return bad ? QD_EXIT_FAIL : QD_EXIT_OK;
}

const char *const cli_formats_text_json[] = {"text", "json", NULL};

bool cli_json(const char *format) {
    return format && strcmp(format, "json") == 0;
}

int cli_out_emit(qd_buf *b, const char *path) {
    int rc = QD_EXIT_OK, err = 0;
    bool to_file = path && strcmp(path, "-") != 0;
    FILE *f = to_file ? cli_out_open(path, &rc) : stdout;
    if (f) {
        cli_out_write(f, qd_buf_str(b), b->len, &err);
        rc = cli_out_close(f, to_file ? path : "standard output", err);
    }
    qd_buf_free(b);
    return rc;
}

int cli_close_stdout(int rc) {
    /* as gnulib's close_stdout: a stdout closed before qdot ran (>&-) is
     * an error only when something was to be written to it */
    bool pending = __fpending(stdout) != 0, failed = ferror(stdout) != 0;
    errno = 0;
    bool close_failed = fclose(stdout) != 0;
    int err = errno;
    if (failed || (close_failed && (pending || err != EBADF))) {
        cannot_write(stdout_name, close_failed ? err : 0);
        return rc != 0 ? rc : QD_EXIT_FAIL;
    }
    return rc;
}

static volatile sig_atomic_t interrupted;
static struct sigaction old_int;

static void on_sigint(int sig) {
    (void)sig;
    interrupted = 1;
}

void cli_interrupt_begin(void) {
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART | SA_RESETHAND; /* writes go on; a second ^C kills */
    interrupted = 0;
    sigaction(SIGINT, &sa, &old_int);
}

bool cli_interrupted(void) {
    return interrupted != 0;
}

void cli_interrupt_end(void) {
    sigaction(SIGINT, &old_int, NULL);
}
