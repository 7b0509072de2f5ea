/*
 * src/sim/cvode.c - BDF for stiff systems: SUNDIALS CVODE 6.4 (variable
 * order 1-5, Newton iteration with a dense difference-quotient Jacobian),
 * driven one internal step at a time so that events and the output grid
 * use CVODE's own interpolant (CVodeGetDky).  CVODE's messages are captured
 * into the context instead of being printed.
 */
#include "simint.h"
#include "../base/mem.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

typedef struct bdf {
    SUNContext sctx;
    void *mem;
    N_Vector y, tmp;
    SUNMatrix A;
    SUNLinearSolver LS;
    qd__sim_integ *it;
    qd_status rhs_status;
    char message[256];
} bdf;

static int rhs(realtype t, N_Vector y, N_Vector ydot, void *data) {
    bdf *b = data;
    qd_status st =
        qd__sim_rhs(b->it->s, b->it->form, t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
    if (st == QD_OK)
        return 0;
    /* a singular state may be an overshooting trial: let CVODE retry smaller */
    b->rhs_status = st;
    return 1;
}

static void on_error(int code, const char *module, const char *function, char *msg, void *data) {
    bdf *b = data;
    (void)code;
    (void)module;
    snprintf(b->message, sizeof b->message, "%s: %s", function, msg);
}

static void bdf_free(qd__sim_integ *it) {
    bdf *b = it->priv;
    if (!b)
        return;
    if (b->mem)
        CVodeFree(&b->mem);
    if (b->LS)
        SUNLinSolFree(b->LS);
    if (b->A)
        SUNMatDestroy(b->A);
    if (b->y)
        N_VDestroy(b->y);
    if (b->tmp)
        N_VDestroy(b->tmp);
    if (b->sctx)
        SUNContext_Free(&b->sctx);
    qd__free(b);
    it->priv = NULL;
}

static qd_status bdf_init(qd__sim_integ *it) {
    bdf *b = qd__calloc(it->s->ctx, 1, sizeof *b);
    if (!b)
        return QD_ERR_NOMEM;
    it->priv = b;
    b->it = it;
    sunindextype d = (sunindextype)it->dim;
    if (SUNContext_Create(NULL, &b->sctx))
        return QD_ERR_NOMEM;
    b->y = N_VNew_Serial(d, b->sctx);
    b->tmp = N_VNew_Serial(d, b->sctx);
    b->mem = CVodeCreate(CV_BDF, b->sctx);
    b->A = SUNDenseMatrix(d, d, b->sctx);
    if (!b->y || !b->tmp || !b->mem || !b->A)
        return QD_ERR_NOMEM;
    b->LS = SUNLinSol_Dense(b->y, b->A, b->sctx);
    if (!b->LS)
        return QD_ERR_NOMEM;
    memcpy(N_VGetArrayPointer(b->y), it->y, it->dim * sizeof *it->y);
    bool ok = CVodeSetErrHandlerFn(b->mem, on_error, b) == CV_SUCCESS &&
              CVodeInit(b->mem, rhs, it->t, b->y) == CV_SUCCESS &&
              CVodeSStolerances(b->mem, it->rtol, it->atol) == CV_SUCCESS &&
              CVodeSetUserData(b->mem, b) == CV_SUCCESS &&
              CVodeSetLinearSolver(b->mem, b->LS, b->A) == CV_SUCCESS &&
              CVodeSetStopTime(b->mem, it->tend) == CV_SUCCESS &&
              CVodeSetMaxNumSteps(b->mem, -1) == CV_SUCCESS &&
              (!(it->h > 0) || CVodeSetInitStep(b->mem, it->h) == CV_SUCCESS);
    if (!ok) {
        qd_ctx_error(it->s->ctx, QD_ERR_ARG, "CVODE setup failed: %s", b->message);
        return QD_ERR_ARG;
    }
    return QD_OK;
}

static qd_status bdf_step(qd__sim_integ *it) {
    bdf *b = it->priv;
    realtype tret = it->t;
    b->rhs_status = QD_OK;
    long fails0 = 0, fails1 = 0;
    CVodeGetNumErrTestFails(b->mem, &fails0);
    int flag = CVode(b->mem, it->tend, b->y, &tret, CV_ONE_STEP);
    CVodeGetNumErrTestFails(b->mem, &fails1);
    it->rejected += (size_t)(fails1 - fails0);
    if (flag < 0) {
        if (b->rhs_status != QD_OK)
            return b->rhs_status;
        bool underflow =
            flag == CV_TOO_MUCH_ACC || flag == CV_ERR_FAILURE || flag == CV_CONV_FAILURE;
        const char *what = underflow ? "step size underflow" : "BDF failure";
        qd__sim_stop(it->s, underflow ? QD_STOP_STEP_UNDERFLOW : QD_STOP_SOLVER_FAILURE, it->t,
                     NAN);
        qd_ctx_error(it->s->ctx, QD_ERR_NUMERIC, "%s at t = %.17g (CVODE %s)", what, it->t,
                     b->message);
        return QD_ERR_NUMERIC;
    }
    /* CVODE goes on with steps below round-off (it only warns "t + h = t"):
     * at a blow-up it would stream the same row until the step limit.  The
     * explicit pairs' rule (erk.c): a step within 10 ulps of t is an
     * underflow. */
    realtype hlast = 0;
    CVodeGetLastStep(b->mem, &hlast);
    if (!(fabs(hlast) > 10 * fabs(nextafter(it->t, INFINITY) - it->t)) || !(tret > it->t))
        return qd__sim_underflow(it, hlast);
    it->told = it->t;
    memcpy(it->yold, it->y, it->dim * sizeof *it->y);
    it->t = tret;
    memcpy(it->y, N_VGetArrayPointer(b->y), it->dim * sizeof *it->y);
    return QD_OK;
}

static void bdf_dense(qd__sim_integ *it, double t, double *y) {
    bdf *b = it->priv;
    if (CVodeGetDky(b->mem, t, 0, b->tmp) == CV_SUCCESS)
        memcpy(y, N_VGetArrayPointer(b->tmp), it->dim * sizeof *y);
    else
        memcpy(y, it->y, it->dim * sizeof *y);
}

const qd__sim_method qd__sim_bdf = {bdf_init, bdf_step, bdf_dense, NULL, bdf_free};
