/*
 * src/render/eom_request.c - `qdot eom` as one call (qd_eom_request_render,
 * qdot/render.h): derive Lagrange's equations or those in the speeds, read
 * the state, solve when asked (keeping M and f when the solution is too
 * large to be worth printing), render.  Which step failed is returned, so a
 * caller can say it in its own words.
 */
#include "render.h"

#include <string.h>

#include "qdot/state.h"
#include "../base/args.h"

/* A failure at step s. */
static qd_status at_step(qd_status st, qd_eom_step s, qd_eom_step *failed) {
    if (failed)
        *failed = st == QD_OK ? QD_EOM_STEP_NONE : s;
    return st;
}

/* qd_eom_solve or qd_speeds_solve's status: too large is a note, not an
 * error. */
static qd_status solved(qd_ctx *ctx, qd_status st, const char *what, size_t max_ops,
                        qd_buf *notes) {
    if (st != QD_ERR_TOOBIG)
        return st;
    qd_buf_printf(notes, "the solved %s exceed %zu operations; printing M and f instead (use "
                         "--at for numbers)\n", what, max_ops);
    qd_ctx_clear_error(ctx);
    return notes->failed ? QD_ERR_NOMEM : QD_OK;
}

static qd_render_opts render_opts(const qd_eom_request *rq, const qd_state *st, qd_buf *notes) {
    return (qd_render_opts){.source = rq->source, .nstate = rq->at ? st->n : 0,
                            .syms = st->syms, .vals = st->vals,
                            .multipliers = rq->speeds.multipliers, .notes = notes};
}

static qd_status coords(qd_ctx *ctx, const qd_model *m, const qd_eom_request *rq, qd_state *st,
                        qd_buf *out, qd_buf *notes, qd_eom_step *failed) {
    qd_eom_opts opts = {.eliminate = rq->eliminate};
    qd_eom *e = qd_eom_derive_opts(ctx, m, &opts);
    if (!e)
        return at_step(qd_ctx_status(ctx), QD_EOM_STEP_DERIVE, failed);
    qd_status s = QD_OK;
    if (rq->at) {
        s = qd_state_init(ctx, m, st);
        s = at_step(s == QD_OK ? qd_state_read(ctx, m, st, rq->at, NULL) : s, QD_EOM_STEP_AT,
                    failed);
    } else if (rq->solve)
        s = at_step(solved(ctx, qd_eom_solve(ctx, e, rq->max_ops), "accelerations", rq->max_ops,
                           notes), QD_EOM_STEP_SOLVE, failed);
    qd_render_opts o = render_opts(rq, st, notes);
    if (s == QD_OK)
        s = at_step(qd_render_eom(ctx, m, e, &o, rq->fmt, out), QD_EOM_STEP_RENDER, failed);
    qd_eom_free(e);
    return s;
}

static qd_status speeds(qd_ctx *ctx, const qd_model *m, const qd_eom_request *rq, qd_state *st,
                        qd_buf *out, qd_buf *notes, qd_eom_step *failed) {
    qd_speeds_eom *e = qd_speeds_derive(ctx, m, &rq->speeds);
    if (!e)
        return at_step(qd_ctx_status(ctx), QD_EOM_STEP_DERIVE, failed);
    qd_status s = QD_OK;
    if (rq->hamel)
        s = at_step(qd_render_hamel(ctx, e, rq->fmt == QD_RENDER_JSON ? QD_RENDER_JSON
                                                                       : QD_RENDER_TEXT, out),
                    QD_EOM_STEP_RENDER, failed);
    else if (rq->at)
        s = at_step(qd_speeds_state_read(ctx, m, e, rq->at, st), QD_EOM_STEP_AT, failed);
    else if (rq->solve)
        s = at_step(solved(ctx, qd_speeds_solve(ctx, e, rq->max_ops), "rates", rq->max_ops,
                           notes), QD_EOM_STEP_SOLVE, failed);
    qd_render_opts o = render_opts(rq, st, notes);
    if (s == QD_OK && !rq->hamel)
        s = at_step(qd_render_speeds(ctx, m, e, &o, rq->fmt, out), QD_EOM_STEP_RENDER, failed);
    qd_speeds_eom_free(e);
    return s;
}

qd_status qd_eom_request_render(qd_ctx *ctx, const qd_model *m, const qd_eom_request *rq,
                                qd_buf *out, qd_buf *notes, qd_eom_step *failed) {
    QD_ARGS_CTX(ctx, ctx && m && rq && out && notes);
    if (failed)
        *failed = QD_EOM_STEP_NONE;
    qd_state st = {0};
    qd_status s = qd_model_nspeeds(m) ? speeds(ctx, m, rq, &st, out, notes, failed)
                                      : coords(ctx, m, rq, &st, out, notes, failed);
    qd_state_free(&st);
    return s;
}
