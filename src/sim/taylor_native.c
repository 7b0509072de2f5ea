/*
 * src/sim/taylor_native.c - `--native` for the taylor method: the Taylor
 * mode of the system's programs emitted as C (src/sym/taylor_emit.c),
 * compiled and cached as the native right-hand side is
 * (src/codegen/native.c), and handed to each run's qd__tay.
 *
 * The object is made from a qd__tay of order 1: the renaming does not
 * depend on the order and the stride is the generated function's argument,
 * so one object serves every tolerance.  A run checks that its own qd__tay
 * has the object's registers and live instructions before using it.
 */
#define _POSIX_C_SOURCE 200809L
#include "taylor_native.h"
#include "codegen/codegen_export.h"
#include "base/mem.h"
#include "../base/args.h"

#include <dlfcn.h>
#include <string.h>

/* Part of the hash: bump when the emitted code changes meaning. */
#define GENERATOR "qdot-taylor-1"

/* The form taylor integrates (run.c: not symplectic). */
static bool speeds_form(const qd_sim *s) { return s->se != NULL; }

void qd__sim_taylor_inputs(const qd_sim *s, const qd_prog *progs[2], size_t *np, bool *var) {
    size_t n = s->n;
    memset(var, 0, s->nin * sizeof *var);
    for (size_t i = 0; i < (speeds_form(s) ? n : 2 * n); i++)
        var[i] = true;
    var[2 * n] = true;
    for (size_t r = 0; speeds_form(s) && r < s->nu; r++)
        var[2 * n + 1 + s->np + r] = true;
    progs[0] = s->hamilton ? s->mom : s->acc;
    progs[1] = s->force;
    *np = s->hamilton ? 2 : 1;
}

/* Object pointer to function pointer: memcpy, as ISO C has no cast. */
static qd_status bind(qd_ctx *ctx, qd_sim *s, const char *path) {
    void *fn = dlsym(s->tay_handle, "qdt_orderk");
    const unsigned long *nreg = dlsym(s->tay_handle, "qdt_nreg");
    const unsigned long *nlive = dlsym(s->tay_handle, "qdt_nlive");
    if (!fn || !nreg || !nlive) {
        qd_ctx_error(ctx, QD_ERR_ARG, "native code: %s lacks the generated functions", path);
        return QD_ERR_ARG;
    }
    memcpy(&s->tay_native, &fn, sizeof fn);
    s->tay_nreg = *nreg;
    s->tay_nlive = *nlive;
    return QD_OK;
}

static qd_status emit(qd_sim *s, qd_buf *text) {
    const qd_prog *progs[2];
    size_t np;
    bool *var = qd__malloc(s->ctx, s->nin + 1);
    if (!var)
        return QD_ERR_NOMEM;
    qd__sim_taylor_inputs(s, progs, &np, var);
    qd__tay *tp = qd__tay_new(s->ctx, np, progs, var, 1, QD__TAY_DOUBLE);
    qd__free(var);
    if (!tp)
        return qd_ctx_status(s->ctx) != QD_OK ? qd_ctx_status(s->ctx) : QD_ERR_NOMEM;
    qd_status st = qd__tay_emit_c(tp, text);
    qd__tay_free(tp);
    return st;
}

qd_status qd_sim_load_native_taylor(qd_sim *s, const char *cache_dir, bool *cached) {
    QD_ARGS(QD_ERR_ARG, s);
    if (!s)
        return QD_ERR_ARG;
    qd__sim_taylor_native_free(s);
    qd_buf text = QD_BUF_WITH(qd__ctx_allocator(s->ctx));
    char path[4096];
    bool was = false;
    qd_status st = emit(s, &text);
    if (st == QD_OK)
        st = qd__cg_native_object(s->ctx, qd_buf_str(&text), GENERATOR, cache_dir, path, &was,
                               &s->tay_handle);
    qd_buf_free(&text);
    if (st == QD_OK)
        st = bind(s->ctx, s, path);
    if (st != QD_OK)
        qd__sim_taylor_native_free(s);
    if (cached)
        *cached = st == QD_OK && was;
    return st;
}

qd__tay_native qd__sim_taylor_native_for(const qd_sim *s, const qd__tay *tp) {
    return s->tay_native && qd__tay_native_fits(tp, s->tay_nreg, s->tay_nlive) ? s->tay_native
                                                                                 : NULL;
}

void qd__sim_taylor_native_free(qd_sim *s) {
    if (s->tay_handle)
        dlclose(s->tay_handle);
    s->tay_handle = NULL;
    s->tay_native = NULL;
    s->tay_nreg = s->tay_nlive = 0;
}
