/*
 * tests/codegen/test_native_cache.c - the --native cache holds code that is
 * run, so it is trusted only when it is the user's alone (issue 30):
 *   a cache directory qdot creates is 0700, and the object in it is
 *     writable by no one else;
 *   an object planted in a group-writable directory, in a directory of
 *     another user, or in a private directory inside one others may write
 *     to (not sticky), is not loaded (its constructor never runs), and the
 *     refusal says why (QD_ERR_UNSUPPORTED: the CLI falls back);
 *   a symlink, or a group-writable file, in place of the object is refused;
 *     an object without this model's key is refused;
 *   a symlink planted in place of the .c (or of the compiler's .log) is
 *     replaced, never followed: the file it points to is unchanged;
 *   20 processes compiling the same model into one cache at once all load
 *     it natively, and no temporary file is left.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "qdot/qdot.h"
#include "qdot/codegen.h"
#include "util/system.h"

static char root[256]; /* every directory of these tests lives under it */

static int group_setup(void **state) {
    (void)state;
    snprintf(root, sizeof root, "/tmp/qdot-test-cache-XXXXXX");
    return mkdtemp(root) ? 0 : -1;
}

static int group_teardown(void **state) {
    (void)state;
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", root);
    return system(cmd) == 0 ? 0 : -1;
}

static int teardown(void **state) { return qt_system_teardown(state); }

static bool have_cc(void) { return system("cc --version >/dev/null 2>&1") == 0; }

/* A five-link pendulum: a long text and a long compile, the widest window
 * for concurrent compiles to meet in. */
static const char *const MODEL =
    "coordinates a1, a2, a3, a4, a5\n"
    "parameters m = 1, l = 1, g = 9.81\n"
    "x1 = l*sin(a1)\ny1 = -l*cos(a1)\n"
    "x2 = x1 + l*sin(a2)\ny2 = y1 - l*cos(a2)\n"
    "x3 = x2 + l*sin(a3)\ny3 = y2 - l*cos(a3)\n"
    "x4 = x3 + l*sin(a4)\ny4 = y3 - l*cos(a4)\n"
    "x5 = x4 + l*sin(a5)\ny5 = y4 - l*cos(a5)\n"
    "particle m at (x1, y1, 0)\nparticle m at (x2, y2, 0)\nparticle m at (x3, y3, 0)\n"
    "particle m at (x4, y4, 0)\nparticle m at (x5, y5, 0)\n"
    "V = m*g*(y1 + y2 + y3 + y4 + y5)\n";

static const char *const SMALL = "coordinates x\nparameters m = 2, k = 3\n"
                                 "particle m at (x, 0)\nV = k*x^2/2 + x^4\n";

/* snprintf that fails the test rather than cut a name */
#define JOIN(out, cap, ...) assert_true(snprintf(out, cap, __VA_ARGS__) < (int)(cap))

static void subdir(char *out, size_t cap, const char *name) { JOIN(out, cap, "%s/%s", root, name); }

static void make_dir(const char *path, mode_t mode) {
    assert_int_equal(mkdir(path, 0700), 0);
    assert_int_equal(chmod(path, mode), 0);
}

static bool exists(const char *path) {
    struct stat st;
    return lstat(path, &st) == 0;
}

static void write_text(const char *path, const char *text) {
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    assert_int_equal(fputs(text, f) >= 0, 1);
    assert_int_equal(fclose(f), 0);
}

static bool file_is(const char *path, const char *text) {
    char buf[256] = "";
    FILE *f = fopen(path, "r");
    if (!f)
        return false;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    return !strcmp(buf, text);
}

/* The object's name for s in the cache: loaded once into a scratch directory. */
static void object_name(qt_system *s, const char *scratch, char *name, size_t cap) {
    qd_native nat;
    if (qd_native_load(s->ctx, s->model, s->eom, scratch, &nat) != QD_OK)
        fail_msg("qd_native_load: %s", qd_ctx_message(s->ctx));
    const char *slash = strrchr(nat.path, '/');
    JOIN(name, cap, "%s", slash ? slash + 1 : nat.path);
    qd_native_unload(&nat);
}

/* An object whose constructor leaves marker, planted as dir/name. */
static void plant(const char *dir, const char *name, const char *marker, mode_t mode) {
    char src[512], obj[512], cmd[1600];
    JOIN(src, sizeof src, "%s/planted.c", root);
    JOIN(obj, sizeof obj, "%s/%s", dir, name);
    FILE *f = fopen(src, "w");
    assert_non_null(f);
    fprintf(f, "#include <stdio.h>\n"
               "__attribute__((constructor)) static void planted(void) {\n"
               "    FILE *f = fopen(\"%s\", \"w\"); if (f) fclose(f);\n}\n"
               "int qdm_rhs;\n",
            marker);
    assert_int_equal(fclose(f), 0);
    JOIN(cmd, sizeof cmd, "cc -shared -fPIC -o '%s' '%s'", obj, src);
    assert_int_equal(system(cmd), 0);
    assert_int_equal(chmod(obj, mode), 0);
}

static void expect_refused(qt_system *s, const char *dir, const char *why) {
    qd_native nat;
    qd_status st = qd_native_load(s->ctx, s->model, s->eom, dir, &nat);
    if (st != QD_ERR_UNSUPPORTED || !strstr(qd_ctx_message(s->ctx), why))
        fail_msg("load from %s: status %d, '%s'; want UNSUPPORTED, '%s'", dir, (int)st,
                 qd_ctx_message(s->ctx), why);
    assert_null(nat.handle);
    assert_null(nat.rhs);
    qd_ctx_clear_error(s->ctx);
}

static void test_private_dir(void **state) {
    if (!have_cc())
        skip();
    qt_system *s = qt_system_derive(state, SMALL, false);
    char dir[300];
    subdir(dir, sizeof dir, "made/by/qdot");
    qd_native nat;
    if (qd_native_load(s->ctx, s->model, s->eom, dir, &nat) != QD_OK)
        fail_msg("qd_native_load: %s", qd_ctx_message(s->ctx));
    struct stat st;
    assert_int_equal(stat(dir, &st), 0);
    assert_int_equal(st.st_mode & 07777, 0700);
    subdir(dir, sizeof dir, "made");
    assert_int_equal(stat(dir, &st), 0);
    assert_int_equal(st.st_mode & 07777, 0700);
    assert_int_equal(stat(nat.path, &st), 0);
    assert_int_equal(st.st_mode & 022, 0);
    qd_native_unload(&nat);
}

static void test_planted_object(void **state) {
    if (!have_cc())
        skip();
    qt_system *s = qt_system_derive(state, SMALL, false);
    char scratch[300], shared[300], marker[300], name[128], obj[512];
    subdir(scratch, sizeof scratch, "scratch");
    subdir(marker, sizeof marker, "constructor-ran");
    object_name(s, scratch, name, sizeof name);

    /* a group-writable directory: another user of the group planted it */
    subdir(shared, sizeof shared, "shared");
    make_dir(shared, 0775);
    plant(shared, name, marker, 0755);
    expect_refused(s, shared, "writable by group or others");
    assert_false(exists(marker));
    make_dir(strcat(shared, "-other"), 0757);
    plant(shared, name, marker, 0755);
    expect_refused(s, shared, "writable by group or others");
    assert_false(exists(marker));

    /* a private directory in one that others may write to (not sticky): they
     * could rename it away and put theirs in its place */
    char inner[340];
    subdir(shared, sizeof shared, "open");
    make_dir(shared, 0777);
    JOIN(inner, sizeof inner, "%s/qdot", shared);
    make_dir(inner, 0700);
    plant(inner, name, marker, 0700);
    expect_refused(s, inner, "others may rename");
    assert_false(exists(marker));

    /* a directory of another user (as root, a directory given to nobody) */
    if (geteuid() == 0) {
        subdir(shared, sizeof shared, "nobodys");
        make_dir(shared, 0755);
        plant(shared, name, marker, 0755);
        assert_int_equal(chown(shared, 65534, 65534), 0);
        expect_refused(s, shared, "not owned by you");
        assert_false(exists(marker));
    }

    /* a private directory, but the object itself writable by others */
    char priv[300];
    subdir(priv, sizeof priv, "private");
    make_dir(priv, 0700);
    plant(priv, name, marker, 0777);
    expect_refused(s, priv, "writable by group or others");
    assert_false(exists(marker));

    /* a symlink in place of the object: not followed */
    JOIN(obj, sizeof obj, "%s/%s", priv, name);
    assert_int_equal(unlink(obj), 0);
    char target[320];
    JOIN(target, sizeof target, "%s/%s", scratch, name);
    assert_int_equal(symlink(target, obj), 0);
    expect_refused(s, priv, "symbolic link");

    /* the user's own object, but not this model's: refused by its key (its
     * constructor ran: the directory is the user's, who put it there) */
    assert_int_equal(unlink(obj), 0);
    plant(priv, name, marker, 0700);
    expect_refused(s, priv, "not the object of this model");
    unlink(marker);
}

/* The names the cache gives s's files under CC: its .c (and .log when the
 * compiler fails), found by a first run in a scratch directory. */
static void cache_names(qt_system *s, const char *scratch, char c_name[128], char log_name[128]) {
    qd_native nat;
    qd_status st = qd_native_load(s->ctx, s->model, s->eom, scratch, &nat);
    qd_ctx_clear_error(s->ctx);
    if (st == QD_OK)
        qd_native_unload(&nat);
    c_name[0] = log_name[0] = '\0';
    DIR *d = opendir(scratch);
    assert_non_null(d);
    for (struct dirent *e; (e = readdir(d));) {
        size_t n = strlen(e->d_name);
        if (n > 2 && !strcmp(e->d_name + n - 2, ".c"))
            JOIN(c_name, 128, "%s", e->d_name);
        if (n > 4 && !strcmp(e->d_name + n - 4, ".log"))
            JOIN(log_name, 128, "%s", e->d_name);
    }
    closedir(d);
    assert_true(c_name[0]);
}

static void test_symlinks_not_followed(void **state) {
    if (!have_cc())
        skip();
    qt_system *s = qt_system_derive(state, SMALL, false);
    char scratch[300], dir[300], victim[300], c_name[128], log_name[128], link[512];
    subdir(victim, sizeof victim, "victim");
    write_text(victim, "precious\n");

    /* the .c, when compiling succeeds */
    subdir(scratch, sizeof scratch, "names-ok");
    cache_names(s, scratch, c_name, log_name);
    subdir(dir, sizeof dir, "links-ok");
    make_dir(dir, 0700);
    JOIN(link, sizeof link, "%s/%s", dir, c_name);
    assert_int_equal(symlink(victim, link), 0);
    qd_native nat;
    if (qd_native_load(s->ctx, s->model, s->eom, dir, &nat) != QD_OK)
        fail_msg("qd_native_load: %s", qd_ctx_message(s->ctx));
    qd_native_unload(&nat);
    assert_true(file_is(victim, "precious\n"));
    struct stat st;
    assert_int_equal(lstat(link, &st), 0);
    assert_true(S_ISREG(st.st_mode)); /* the link was replaced by the source */

    /* the .c and the .log, when the compiler fails */
    const char *old = getenv("CC");
    char *saved = old ? strdup(old) : NULL;
    setenv("CC", "false", 1);
    subdir(scratch, sizeof scratch, "names-fail");
    cache_names(s, scratch, c_name, log_name);
    assert_true(log_name[0]);
    subdir(dir, sizeof dir, "links-fail");
    make_dir(dir, 0700);
    char link_log[512];
    JOIN(link, sizeof link, "%s/%s", dir, c_name);
    JOIN(link_log, sizeof link_log, "%s/%s", dir, log_name);
    assert_int_equal(symlink(victim, link), 0);
    assert_int_equal(symlink(victim, link_log), 0);
    qd_status rc = qd_native_load(s->ctx, s->model, s->eom, dir, &nat);
    if (saved)
        setenv("CC", saved, 1);
    else
        unsetenv("CC");
    free(saved);
    assert_int_equal(rc, QD_ERR_UNSUPPORTED);
    assert_true(file_is(victim, "precious\n"));
    assert_int_equal(lstat(link, &st), 0);
    assert_true(S_ISREG(st.st_mode));
    assert_int_equal(lstat(link_log, &st), 0);
    assert_true(S_ISREG(st.st_mode));
}

#define NPROC 20

static void test_concurrent(void **state) {
    if (!have_cc())
        skip();
    qt_system *s = qt_system_derive(state, MODEL, false);
    char dir[300];
    subdir(dir, sizeof dir, "concurrent");
    int go[2];
    assert_int_equal(pipe(go), 0);
    pid_t pids[NPROC];
    for (int i = 0; i < NPROC; i++) {
        pids[i] = fork();
        assert_true(pids[i] >= 0);
        if (pids[i] == 0) { /* wait for the start, then compile (or find) and load */
            char c;
            close(go[1]);
            if (read(go[0], &c, 1) != 0)
                _exit(3);
            qd_native nat;
            if (qd_native_load(s->ctx, s->model, s->eom, dir, &nat) != QD_OK) {
                fprintf(stderr, "process %d: %s\n", i, qd_ctx_message(s->ctx));
                _exit(1);
            }
            double y[10] = {0.1, 0.2, 0.3, 0.4, 0.5, 0, 0, 0, 0, 0}, d[10];
            _exit(nat.rhs(0, y, nat.par_default, d) == 0 ? 0 : 2);
        }
    }
    close(go[0]);
    close(go[1]); /* all start now */
    int failed = 0;
    for (int i = 0; i < NPROC; i++) {
        int status;
        assert_int_equal(waitpid(pids[i], &status, 0), pids[i]);
        failed += !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    }
    if (failed)
        fail_msg("%d of %d concurrent processes did not load the native code", failed, NPROC);
    /* left: the source and the object, nothing private */
    DIR *d = opendir(dir);
    assert_non_null(d);
    int files = 0;
    for (struct dirent *e; (e = readdir(d));) {
        if (e->d_name[0] == '.')
            continue;
        files++;
        size_t n = strlen(e->d_name);
        if (!(n == 23 && !strcmp(e->d_name + 21, ".c")) &&
            !(n == 24 && !strcmp(e->d_name + 21, ".so")))
            fail_msg("left in the cache: %s", e->d_name);
    }
    closedir(d);
    assert_int_equal(files, 2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_teardown(test_private_dir, teardown),
        cmocka_unit_test_teardown(test_planted_object, teardown),
        cmocka_unit_test_teardown(test_symlinks_not_followed, teardown),
        cmocka_unit_test_teardown(test_concurrent, teardown),
    };
    return cmocka_run_group_tests(tests, group_setup, group_teardown);
}
