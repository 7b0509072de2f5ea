/*
 * src/mech/isolate_api.c - the isolation of one unknown (isolate.c) as a
 * public function, for the modules above mech (action's p^2 from an H even
 * in p: issue 33).
 */
#include "mech.h"
#include "../base/args.h"

qd_status qd_isolate(qd_ctx *ctx, const qd_expr *eq, const qd_expr *y, const qd_expr **sol) {
    QD_ARGS_CTX(ctx, ctx && eq && y && sol);
    size_t failed = 0;
    *sol = NULL;
    qd_status st = qd__mech_isolate(ctx, 1, &eq, &y, sol, &failed);
    return st == QD_OK && *sol ? QD_OK : st == QD_OK ? QD_ERR_NONLINEAR : st;
}
