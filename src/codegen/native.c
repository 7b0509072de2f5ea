/*
 * src/codegen/native.c - compile the generated C and load it.
 *
 * The generated file (one translation unit, header inlined, prefix qdm) is
 * named by the FNV-1a 64-bit hash of its text and of the compiler command,
 * so an edited model, another $CC or another generator version never finds
 * a stale object, and an unchanged one is compiled once.
 *
 * The cache holds code that is run, so it is trusted only when it is the
 * user's alone: the directory is made 0700, and a directory or an object
 * owned by another user or writable by group or others is refused
 * (QD_ERR_UNSUPPORTED: the caller falls back to the interpreter).  Every file
 * is created with O_CREAT|O_EXCL|O_NOFOLLOW under a name private to the call
 * (qdot-HASH.PID.N.c, .log, .so) and renamed into place, so that concurrent
 * compiles of one model share no file and a symlink at a final name is
 * replaced, never followed; the object is opened with O_NOFOLLOW and checked
 * before dlopen, and carries the hash it was compiled for (qdot_cache_key),
 * checked after.  The compiler runs through /bin/sh so that $CC may carry
 * options ("ccache gcc"); its output goes to a .log next to the object when
 * it fails, and its first lines into the context's message.
 */
#define _XOPEN_SOURCE 700 /* realpath, S_ISVTX */
#include "cg.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#define PREFIX "qdm"
#define FLAGS "-std=c11 -O2 -fno-math-errno -shared -fPIC"
/* Part of the hash: bump when the generated code changes meaning. */
#define GENERATOR "qdot-codegen-1"

static uint64_t fnv1a(uint64_t h, const char *s) {
    for (; *s; s++) {
        h ^= (unsigned char)*s;
        h *= 0x100000001b3ULL;
    }
    return h;
}

/* mkdir -p, each directory it makes private (0700, as the XDG base
 * directories are). */
static int make_dirs(const char *path) {
    char buf[4096];
    size_t len = strlen(path);
    if (len >= sizeof buf)
        return ENAMETOOLONG;
    memcpy(buf, path, len + 1);
    for (size_t i = 1; i <= len; i++) {
        if (buf[i] != '/' && buf[i] != '\0')
            continue;
        char c = buf[i];
        buf[i] = '\0';
        if (mkdir(buf, 0700) != 0 && errno != EEXIST)
            return errno;
        buf[i] = c;
    }
    return 0;
}

/* A directory or file others could have written is not trusted: it must be
 * the user's and writable by no one else. */
static const char *untrusted(const struct stat *st) {
    if (st->st_uid != geteuid())
        return "it is not owned by you";
    if (st->st_mode & (S_IWGRP | S_IWOTH))
        return "it is writable by group or others";
    return NULL;
}

/* Each directory above the cache must keep others from renaming it away: the
 * user's or root's, and writable by group or others only when sticky (as
 * /tmp); else another user could put a directory of theirs in its place
 * between the checks and the dlopen by name. */
static const char *unsafe_ancestor(const char *dir, char *which, size_t cap) {
    char real[4096];
    if (!realpath(dir, real))
        return strerror(errno);
    for (size_t i = strlen(real); i > 0; i--) {
        if (real[i] != '/' && i != strlen(real))
            continue;
        char c = real[i];
        real[i] = '\0';
        struct stat st;
        const char *why = NULL;
        if (stat(i ? real : "/", &st) != 0)
            why = strerror(errno);
        else if (st.st_uid != 0 && st.st_uid != geteuid())
            why = "it is not owned by you or root";
        else if ((st.st_mode & (S_IWGRP | S_IWOTH)) && !(st.st_mode & S_ISVTX))
            why = "others may rename what is in it (writable by group or others, not sticky)";
        if (why) {
            snprintf(which, cap, "%s", i ? real : "/");
            return why;
        }
        real[i] = c;
    }
    return NULL;
}

/* The cache directory, opened (*dfd) and checked: created 0700 when missing,
 * refused (QD_ERR_UNSUPPORTED, so the caller falls back to the interpreter)
 * when another user owns it or others may write to it. */
static qd_status cache_dir(qd_ctx *ctx, const char *given, char *out, size_t cap, int *dfd) {
    const char *xdg = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");
    int len;
    *dfd = -1;
    if (given)
        len = snprintf(out, cap, "%s", given);
    else if (xdg && *xdg)
        len = snprintf(out, cap, "%s/qdot", xdg);
    else if (home && *home)
        len = snprintf(out, cap, "%s/.cache/qdot", home);
    else {
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: no cache directory ($HOME is not set)");
        return QD_ERR_ARG;
    }
    if (len < 0 || (size_t)len >= cap - 64) {
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: the cache directory's name is too long");
        return QD_ERR_ARG;
    }
    int err = make_dirs(out);
    int fd = err ? -1 : open(out, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: cannot create the cache directory %s: %s",
                     out, strerror(err ? err : errno));
        return QD_ERR_ARG;
    }
    struct stat st;
    const char *why = fstat(fd, &st) != 0 ? strerror(errno) : untrusted(&st);
    if (why) {
        close(fd);
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED,
                     "native code: the cache directory %s is not safe to load code from: %s "
                     "(make it yours and private: chmod 700; or set XDG_CACHE_HOME)",
                     out, why);
        return QD_ERR_UNSUPPORTED;
    }
    char above[4096];
    if ((why = unsafe_ancestor(out, above, sizeof above))) {
        close(fd);
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED,
                     "native code: the cache directory %s is not safe to load code from: "
                     "the directory %s above it: %s (set XDG_CACHE_HOME to a private place)",
                     out, above, why);
        return QD_ERR_UNSUPPORTED;
    }
    *dfd = fd;
    return QD_OK;
}

/* A new file in the cache under a private name ("qdot-HASH.PID.N.EXT"),
 * never through a symlink and never an existing file; -1 (errno) on failure. */
static int create_private(int dfd, const char *stem, const char *ext, char *name, size_t cap) {
    static atomic_ulong seq;
    for (int tries = 0; tries < 100; tries++) {
        struct timespec ts;
        clock_gettime(CLOCK_REALTIME, &ts);
        snprintf(name, cap, "%s.%ld.%lu%lx.%s", stem, (long)getpid(),
                 (unsigned long)atomic_fetch_add(&seq, 1), (unsigned long)ts.tv_nsec, ext);
        int fd = openat(dfd, name, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    errno = EEXIST;
    return -1;
}

static bool write_all(int fd, const char *text, size_t len) {
    while (len) {
        ssize_t n = write(fd, text, len);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        text += n;
        len -= (size_t)n;
    }
    return true;
}

/* The first lines of the compiler's output, for the message. */
static void log_head(int dfd, const char *name, char *out, size_t cap) {
    out[0] = '\0';
    int fd = openat(dfd, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0)
        return;
    ssize_t n = read(fd, out, cap - 1);
    out[n > 0 ? n : 0] = '\0';
    close(fd);
    for (char *p = out; *p; p++)
        if (*p == '\n' && p[1] == '\0')
            *p = '\0';
}

/* Run the compiler, its output into logfd: 0 on success, else its exit
 * status (127: not found). */
static int compile(const char *src, const char *obj, int logfd) {
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        dup2(logfd, 1);
        dup2(logfd, 2);
        execl("/bin/sh", "sh", "-c", "exec ${CC:-cc} " FLAGS " -o \"$1\" \"$2\" -lm", "sh", obj,
              src, (char *)NULL);
        _exit(127);
    }
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR)
            return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

static void *sym(void *h, const char *name) {
    char full[64];
    snprintf(full, sizeof full, PREFIX "_%s", name);
    return dlsym(h, full);
}

/* Object pointer to function pointer: memcpy, as ISO C has no cast. */
#define FN(dst, h, name)                                                                       \
    do {                                                                                       \
        void *p_ = sym(h, name);                                                               \
        ok = ok && p_;                                                                         \
        memcpy(&(dst), &p_, sizeof p_);                                                        \
    } while (0)

static qd_status bind(qd_ctx *ctx, qd_native *out, bool jacobian) {
    bool ok = true;
    FN(out->rhs, out->handle, "rhs");
    FN(out->mass, out->handle, "mass");
    FN(out->forcing, out->handle, "forcing");
    FN(out->energy, out->handle, "energy");
    if (jacobian)
        FN(out->jacobian, out->handle, "jacobian");
    out->par_default = sym(out->handle, "par_default");
    if (ok && out->par_default)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_ARG, "native code: %s lacks the generated functions", out->path);
    return QD_ERR_ARG;
}

/* The key every cached object carries: the hash of what it was compiled
 * from, checked after loading (a stale or foreign object is refused). */
#define KEY_SYMBOL "qdot_cache_key"
#define CACHE_FORMAT "cache-2\n"

static void key_text(uint64_t hash, char out[32]) {
    snprintf(out, 32, "qdot-%016llx", (unsigned long long)hash);
}

/* Compile text into the cache as name (qdot-HASH.so): every file under a
 * private name first (the .c, the log, the object), renamed into place, so
 * that concurrent compiles of one model never share a file and a symlink
 * planted at a final name is replaced, not followed. */
static qd_status build_object(qd_ctx *ctx, const char *text, int dfd, const char *dir,
                              uint64_t hash, const char *name) {
    char stem[32], key[32], csrc[96], tobj[96], tlog[96], fsrc[48], flog[48];
    char src[4200], obj[4200];
    key_text(hash, key);
    snprintf(stem, sizeof stem, "qdot-%016llx", (unsigned long long)hash);
    snprintf(fsrc, sizeof fsrc, "%s.c", stem);
    snprintf(flog, sizeof flog, "%s.log", stem);
    int cfd = create_private(dfd, stem, "c", csrc, sizeof csrc);
    if (cfd < 0) {
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: cannot write in %s: %s", dir, strerror(errno));
        return QD_ERR_ARG;
    }
    char tail[128];
    snprintf(tail, sizeof tail, "\n/* the qdot cache's key */\nconst char " KEY_SYMBOL
             "[] = \"%s\";\n", key);
    bool ok = write_all(cfd, text, strlen(text)) && write_all(cfd, tail, strlen(tail));
    int wr_errno = errno;
    if (close(cfd) != 0 && ok) {
        ok = false;
        wr_errno = errno;
    }
    if (!ok) {
        unlinkat(dfd, csrc, 0);
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: cannot write %s/%s: %s", dir, csrc,
                     strerror(wr_errno));
        return QD_ERR_ARG;
    }
    int lfd = create_private(dfd, stem, "log", tlog, sizeof tlog);
    /* the object's private name: reserved here, written by the compiler */
    int ofd = lfd < 0 ? -1 : create_private(dfd, stem, "so", tobj, sizeof tobj);
    if (ofd < 0) {
        int e = errno;
        if (lfd >= 0) {
            close(lfd);
            unlinkat(dfd, tlog, 0);
        }
        unlinkat(dfd, csrc, 0);
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: cannot write in %s: %s", dir, strerror(e));
        return QD_ERR_ARG;
    }
    close(ofd);
    snprintf(src, sizeof src, "%s/%s", dir, csrc);
    snprintf(obj, sizeof obj, "%s/%s", dir, tobj);
    int rc = compile(src, obj, lfd);
    close(lfd);
    /* the source stays beside the object, for a look at what runs */
    renameat(dfd, csrc, dfd, fsrc);
    if (rc != 0) {
        char head[200];
        log_head(dfd, tlog, head, sizeof head);
        unlinkat(dfd, tobj, 0);
        renameat(dfd, tlog, dfd, flog);
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED, "native code: %s (exit %d)%s%s",
                     rc == 127 ? "no C compiler ($CC or cc) could be run"
                               : "the C compiler failed",
                     rc, head[0] ? ": " : "", head);
        return QD_ERR_UNSUPPORTED;
    }
    unlinkat(dfd, tlog, 0);
    /* private whatever the umask: the loader refuses what others may write */
    int fd = openat(dfd, tobj, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0 || fchmod(fd, 0700) != 0 || renameat(dfd, tobj, dfd, name) != 0) {
        int e = errno;
        if (fd >= 0)
            close(fd);
        unlinkat(dfd, tobj, 0);
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: cannot put %s/%s in place: %s", dir, name,
                     strerror(e));
        return QD_ERR_ARG;
    }
    close(fd);
    return QD_OK;
}

/* Open the object (never through a symlink) and check that it is a regular
 * file of the user's that no one else may write; -1 with *why when absent
 * (errno ENOENT) or refused. */
static int open_object(int dfd, const char *name, const char **why) {
    *why = NULL;
    int fd = openat(dfd, name, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) {
        *why = errno == ELOOP ? "it is a symbolic link" : errno == ENOENT ? NULL : strerror(errno);
        return -1;
    }
    struct stat st;
    if (fstat(fd, &st) != 0)
        *why = strerror(errno);
    else if (!S_ISREG(st.st_mode))
        *why = "it is not a regular file";
    else
        *why = untrusted(&st);
    if (*why) {
        close(fd);
        return -1;
    }
    return fd;
}

/* The shared object of text in the cache (compiled unless there), dlopened.
 * generator: part of the hash, the kind and version of the text. */
qd_status qd__cg_native_object(qd_ctx *ctx, const char *text, const char *generator,
                            const char *cache, char path[4096], bool *cached, void **handle) {
    char dir[4000], name[48], key[32];
    int dfd;
    *handle = NULL;
    *cached = false;
    qd_status st = cache_dir(ctx, cache, dir, sizeof dir, &dfd);
    if (st != QD_OK)
        return st;
    const char *cc = getenv("CC");
    /* CACHE_FORMAT: objects made before the key are never found */
    uint64_t h = fnv1a(fnv1a(0xcbf29ce484222325ULL, generator), "\n" FLAGS "\n" CACHE_FORMAT);
    h = fnv1a(fnv1a(h, cc && *cc ? cc : "cc"), "\n");
    h = fnv1a(h, text);
    snprintf(name, sizeof name, "qdot-%016llx.so", (unsigned long long)h);
    snprintf(path, 4096, "%s/%s", dir, name);
    key_text(h, key);
    const char *why;
    int fd = open_object(dfd, name, &why);
    *cached = fd >= 0;
    if (fd < 0 && !why) {
        st = build_object(ctx, text, dfd, dir, h, name);
        if (st == QD_OK && (fd = open_object(dfd, name, &why)) < 0 && !why)
            why = "it vanished after compiling";
    }
    close(dfd);
    if (st == QD_OK && fd < 0) {
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED, "native code: %s is not loaded: %s", path, why);
        return QD_ERR_UNSUPPORTED;
    }
    if (st != QD_OK)
        return st;
    /* by name: the directory is the user's alone, so the file checked on fd
     * is the file the name holds (glibc knows a loaded object by its name: a
     * /proc/self/fd/N name, reused by another model, would find the first) */
    *handle = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    close(fd);
    if (!*handle) {
        const char *e = dlerror();
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: cannot load %s: %s", path,
                     e ? e : "unknown reason");
        return QD_ERR_ARG;
    }
    const char *got = dlsym(*handle, KEY_SYMBOL);
    if (!got || strcmp(got, key) != 0) {
        dlclose(*handle);
        *handle = NULL;
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED, "native code: %s is not the object of this model "
                     "(its key is %s%s%s, not %s): remove it", path, got ? "'" : "missing",
                     got ? got : "", got ? "'" : "", key);
        return QD_ERR_UNSUPPORTED;
    }
    return QD_OK;
}

static qd_status load(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *cache,
                      bool jacobian, qd_native *out) {
    if (!out)
        return QD_ERR_ARG;
    memset(out, 0, sizeof *out);
    if (!ctx || !m || !e)
        return QD_ERR_ARG;
    qd_buf text = QD_BUF_WITH(qd__ctx_allocator(ctx));
    qd_status st = qd__cg_emit(ctx, m, e, PREFIX, true, jacobian, &text, NULL);
    if (st == QD_OK)
        st = qd__cg_native_object(ctx, qd_buf_str(&text), GENERATOR, cache, out->path,
                               &out->cached, &out->handle);
    qd_buf_free(&text);
    if (st == QD_OK)
        st = bind(ctx, out, jacobian);
    if (st != QD_OK) {
        qd_native_unload(out);
        return st;
    }
    out->n = e->n;
    out->npar = qd_model_nparams(m);
    return QD_OK;
}

qd_status qd_native_load(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *cache,
                         qd_native *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && out);
    return load(ctx, m, e, cache, true, out);
}

qd_status qd_native_load_run(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *cache,
                             qd_native *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && out);
    return load(ctx, m, e, cache, false, out);
}

void qd_native_unload(qd_native *nat) {
    if (!nat)
        return;
    if (nat->handle)
        dlclose(nat->handle);
    memset(nat, 0, sizeof *nat);
}
