/*
 * src/base/module.c - finding and opening libqdot's optional modules
 * (the search order is in module.h).
 */
#define _GNU_SOURCE /* dladdr */
#include "module.h"

#include <dlfcn.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef QDOT_MODULE_INSTALL_DIR
#define QDOT_MODULE_INSTALL_DIR "/usr/local/lib/qdot-modules"
#endif
/* The same relative to the prefix, for a tree installed elsewhere than it
 * was configured for (make install PREFIX=...): PREFIX/bin/qdot finds
 * PREFIX/<libdir>/qdot-modules. */
#ifndef QDOT_MODULE_REL_DIR
#define QDOT_MODULE_REL_DIR "lib/qdot-modules"
#endif

/* An object of libqdot's own, whose address dladdr maps to the file that
 * holds libqdot (ISO C has no function-to-object pointer cast). */
static const char anchor = 0;

/* dir/SUB/qdot_NAME.so, dir the directory part of file; false when file
 * has none or the path does not fit. */
static bool beside(char *out, size_t cap, const char *file, const char *sub, const char *name) {
    const char *slash = file ? strrchr(file, '/') : NULL;
    if (!slash)
        return false;
    int n = snprintf(out, cap, "%.*s/%s/qdot_%s.so", (int)(slash - file), file, sub, name);
    return n > 0 && (size_t)n < cap;
}

/* The k-th place to look (module.h), or false past the last. */
static bool candidate(int k, char *out, size_t cap, const char *name, bool *exists) {
    int n = 0;
    *exists = false;
    switch (k) {
    case 0: {
        const char *dir = getenv("QDOT_MODULE_DIR");
        if (!dir || !*dir)
            return true;
        n = snprintf(out, cap, "%s/qdot_%s.so", dir, name);
        break;
    }
    case 1: {
        Dl_info info;
        if (!dladdr(&anchor, &info) || !beside(out, cap, info.dli_fname, "qdot-modules", name))
            return true;
        n = 1;
        break;
    }
    case 2:
    case 3: { /* beside the running program; then PREFIX/<libdir>/... from PREFIX/bin */
        char exe[PATH_MAX];
        ssize_t len = readlink("/proc/self/exe", exe, sizeof exe - 1);
        if (len <= 0)
            return true;
        exe[len] = '\0';
        if (!beside(out, cap, exe, k == 2 ? "qdot-modules" : "../" QDOT_MODULE_REL_DIR, name))
            return true;
        n = 1;
        break;
    }
    case 4:
        n = snprintf(out, cap, "%s/qdot_%s.so", QDOT_MODULE_INSTALL_DIR, name);
        break;
    default:
        return false;
    }
    *exists = n > 0 && (size_t)n < cap && access(out, R_OK) == 0;
    return true;
}

void *qd__module_open(qd_ctx *ctx, const char *name, int flags, unsigned abi, const char *what,
                      const char *pkg) {
    char path[PATH_MAX + 64];
    bool exists = false;
    for (int k = 0; candidate(k, path, sizeof path, name, &exists); k++)
        if (exists)
            break;
    if (!exists) {
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED,
                     "this qdot has no %s module (qdot_%s.so): it was built without %s, or "
                     "the module is not installed (install %s and build again, or set "
                     "QDOT_MODULE_DIR)",
                     what, name, what, pkg);
        return NULL;
    }
    void *h = dlopen(path, RTLD_NOW | flags);
    if (!h) {
        const char *why = dlerror();
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED, "cannot load the %s module %s: %s", what, path,
                     why ? why : "unknown reason");
        return NULL;
    }
    char sym[64];
    snprintf(sym, sizeof sym, "qd_ext_%s_abi", name);
    unsigned (*abi_of)(void) = NULL;
    if (!qd__module_fn(ctx, h, path, sym, &abi_of, sizeof abi_of))
        return NULL;
    if (abi_of() != abi) {
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED,
                     "the %s module %s is of another qdot (interface %u, this one %u): "
                     "install the qdot it came with, or set QDOT_MODULE_DIR",
                     what, path, abi_of(), abi);
        return NULL;
    }
    return h;
}

bool qd__module_fn(qd_ctx *ctx, void *module, const char *name, const char *sym, void *fn,
                   size_t fnsize) {
    void *f = dlsym(module, sym);
    if (!f || fnsize != sizeof f) {
        qd_ctx_error(ctx, QD_ERR_UNSUPPORTED, "the module %s lacks %s", name, sym);
        return false;
    }
    memcpy(fn, &f, sizeof f);
    return true;
}
