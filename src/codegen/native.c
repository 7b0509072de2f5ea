/*
 * src/codegen/native.c - compile the generated C and load it.
 *
 * The generated file (one translation unit, header inlined, prefix qdm) is
 * named by the FNV-1a 64-bit hash of its text and of the compiler command,
 * so an edited model, another $CC or another generator version never finds
 * a stale object, and an unchanged one is compiled once.  The compiler
 * writes to a name private to this process, renamed into place when done:
 * two processes compiling the same model at once both end with a complete
 * file.  The compiler runs through /bin/sh so that $CC may carry options
 * ("ccache gcc"); its output goes to a .log next to the object, and the
 * first lines of it into the context's message when it fails.
 */
#define _POSIX_C_SOURCE 200809L
#include "cg.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
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

/* mkdir -p. */
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
        if (mkdir(buf, 0755) != 0 && errno != EEXIST)
            return errno;
        buf[i] = c;
    }
    struct stat st;
    return stat(path, &st) == 0 && S_ISDIR(st.st_mode) ? 0 : ENOTDIR;
}

static qd_status cache_dir(qd_ctx *ctx, const char *given, char *out, size_t cap) {
    const char *xdg = getenv("XDG_CACHE_HOME"), *home = getenv("HOME");
    int len;
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
    if (err) {
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: cannot create the cache directory %s: %s",
                     out, strerror(err));
        return QD_ERR_ARG;
    }
    return QD_OK;
}

static bool write_file(const char *path, const char *text) {
    FILE *f = fopen(path, "w");
    if (!f)
        return false;
    size_t len = strlen(text);
    bool ok = fwrite(text, 1, len, f) == len;
    return fclose(f) == 0 && ok;
}

/* The first lines of the compiler's output, for the message. */
static void log_head(const char *path, char *out, size_t cap) {
    out[0] = '\0';
    FILE *f = fopen(path, "r");
    if (!f)
        return;
    size_t n = fread(out, 1, cap - 1, f);
    out[n] = '\0';
    fclose(f);
    for (char *p = out; *p; p++)
        if (*p == '\n' && p[1] == '\0')
            *p = '\0';
}

/* Run the compiler: 0 on success, else its exit status (127: not found). */
static int compile(const char *src, const char *obj, const char *log) {
    pid_t pid = fork();
    if (pid < 0)
        return -1;
    if (pid == 0) {
        int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
            close(fd);
        }
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

static qd_status bind(qd_ctx *ctx, qd_native *out) {
    bool ok = true;
    FN(out->rhs, out->handle, "rhs");
    FN(out->mass, out->handle, "mass");
    FN(out->forcing, out->handle, "forcing");
    FN(out->energy, out->handle, "energy");
    FN(out->jacobian, out->handle, "jacobian");
    out->par_default = sym(out->handle, "par_default");
    if (ok && out->par_default)
        return QD_OK;
    qd_ctx_error(ctx, QD_ERR_ARG, "native code: %s lacks the generated functions", out->path);
    return QD_ERR_ARG;
}

static qd_status build_object(qd_ctx *ctx, const char *text, const char *dir, uint64_t hash,
                              const char *path) {
    char src[4200], tmp[4200], log[4200];
    snprintf(src, sizeof src, "%s/qdot-%016llx.c", dir, (unsigned long long)hash);
    snprintf(log, sizeof log, "%s/qdot-%016llx.log", dir, (unsigned long long)hash);
    snprintf(tmp, sizeof tmp, "%s/qdot-%016llx.%ld.tmp", dir, (unsigned long long)hash,
             (long)getpid());
    if (!write_file(src, text)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: cannot write %s: %s", src, strerror(errno));
        return QD_ERR_ARG;
    }
    int rc = compile(src, tmp, log);
    if (rc != 0) {
        char head[200];
        log_head(log, head, sizeof head);
        unlink(tmp);
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED, "native code: %s (exit %d)%s%s",
                     rc == 127 ? "no C compiler ($CC or cc) could be run"
                               : "the C compiler failed",
                     rc, head[0] ? ": " : "", head);
        return QD_ERR_UNSUPPORTED;
    }
    if (rename(tmp, path) != 0) {
        unlink(tmp);
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: cannot rename into %s: %s", path,
                     strerror(errno));
        return QD_ERR_ARG;
    }
    unlink(log);
    return QD_OK;
}

/* The shared object of text in the cache (compiled unless there), dlopened.
 * generator: part of the hash, the kind and version of the text. */
qd_status qd__native_object(qd_ctx *ctx, const char *text, const char *generator,
                            const char *cache, char path[4096], bool *cached, void **handle) {
    char dir[4000];
    *handle = NULL;
    qd_status st = cache_dir(ctx, cache, dir, sizeof dir);
    if (st != QD_OK)
        return st;
    const char *cc = getenv("CC");
    uint64_t h = fnv1a(fnv1a(0xcbf29ce484222325ULL, generator), "\n" FLAGS "\n");
    h = fnv1a(fnv1a(h, cc && *cc ? cc : "cc"), "\n");
    h = fnv1a(h, text);
    snprintf(path, 4096, "%s/qdot-%016llx.so", dir, (unsigned long long)h);
    *cached = access(path, R_OK) == 0;
    if (!*cached)
        st = build_object(ctx, text, dir, h, path);
    if (st == QD_OK && !(*handle = dlopen(path, RTLD_NOW | RTLD_LOCAL))) {
        const char *why = dlerror();
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: cannot load %s: %s", path,
                     why ? why : "unknown reason");
        st = QD_ERR_ARG;
    }
    return st;
}

qd_status qd_native_load(qd_ctx *ctx, const qd_model *m, const qd_eom *e, const char *cache,
                         qd_native *out) {
    QD_ARGS_CTX(ctx, ctx && m && e && out);
    if (!out)
        return QD_ERR_ARG;
    memset(out, 0, sizeof *out);
    if (!ctx || !m || !e)
        return QD_ERR_ARG;
    qd_buf text = QD_BUF_WITH(qd__ctx_allocator(ctx));
    qd_status st = qd__codegen(ctx, m, e, PREFIX, true, &text, NULL);
    if (st == QD_OK)
        st = qd__native_object(ctx, qd_buf_str(&text), GENERATOR, cache, out->path,
                               &out->cached, &out->handle);
    qd_buf_free(&text);
    if (st == QD_OK)
        st = bind(ctx, out);
    if (st != QD_OK) {
        qd_native_unload(out);
        return st;
    }
    out->n = e->n;
    out->npar = qd_model_nparams(m);
    return QD_OK;
}

void qd_native_unload(qd_native *nat) {
    if (!nat)
        return;
    if (nat->handle)
        dlclose(nat->handle);
    memset(nat, 0, sizeof *nat);
}
