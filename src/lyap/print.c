/*
 * src/lyap/print.c - the Lyapunov exponents of a run printed
 * (qdot/lyapunov.h): qd_lyap_print (the exponents to six decimals with
 * their error estimates, the mean tr J they must sum to by Liouville's
 * theorem, their sum when all 2n were computed and, for a conservative
 * system, the pairs lambda_i + lambda_{2n+1-i} that vanish) and
 * qd_lyap_json (the same numbers with the options used).  `qdot lyapunov`
 * prints these.
 */
#include "qdot/lyapunov.h"
#include "qdot/json.h"
#include "../base/args.h"

#include <math.h>

static bool report_ok(const qd_lyap_report *r) {
    return r->opts && r->stats && r->exps && r->ndof > 0 && r->opts->nexp >= 1 &&
           r->opts->nexp <= 2 * r->ndof;
}

double qd_lyap_sum(size_t k, const double *exps) {
    QD_ARGS(NAN, exps || !k);
    double s = 0;
    for (size_t j = 0; j < k; j++)
        s += exps[j];
    return s;
}

/* Round-off's -0.000000 printed as 0. */
static double clean(double x) { return fabs(x) < 5e-7 ? 0.0 : x; }

/* Six decimals, the digits the estimates have. */
static void fixed(qd_buf *out, const char *before, double x) {
    qd_buf_printf(out, "%s% .6f", before, clean(x));
}

qd_status qd_lyap_print(const qd_lyap_report *r, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, r && out);
    if (!report_ok(r))
        return QD_ERR_ARG;
    size_t k = r->opts->nexp, d = 2 * r->ndof;
    for (size_t j = 0; j < k; j++) {
        qd_buf_printf(out, "lambda_%zu", j + 1);
        fixed(out, " = ", r->exps[j]);
        double e = r->err ? r->err[j] : NAN;
        if (isnan(e))
            qd_buf_puts(out, "  (no error estimate: fewer than 2 renormalizations in the last "
                             "half)\n");
        else
            qd_buf_printf(out, "  +- %.2g\n", e);
    }
    fixed(out, "mean tr J = ", r->stats->trace_mean);
    qd_buf_printf(out, "  (the sum of all %zu exponents, Liouville%s)\n", d,
                  r->conservative ? "; -> 0 as T grows for a conservative system" : "");
    if (k == d) {
        fixed(out, "sum       = ", qd_lyap_sum(k, r->exps));
        qd_buf_puts(out, "\n");
    }
    if (k == d && r->conservative) {
        qd_buf_printf(out, "conservative: the exponents pair, lambda_i + lambda_%zu-i =", d + 1);
        for (size_t j = 0; j < d / 2; j++)
            qd_buf_printf(out, "%s%.6f", j ? ", " : " ", clean(r->exps[j] + r->exps[d - 1 - j]));
        qd_buf_puts(out, "\n");
    }
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}

/* x as an array, null where an entry is NaN (no estimate). */
static void numbers_or_null(qd_json *j, const char *key, size_t n, const double *x) {
    bool all = true;
    for (size_t i = 0; i < n; i++)
        all = all && !isnan(x[i]);
    if (all) {
        qd_json_vector(j, key, n, x);
        return;
    }
    qd_json_key(j, key);
    qd_json_begin_array(j);
    for (size_t i = 0; i < n; i++)
        if (isnan(x[i]))
            qd_json_null(j);
        else
            qd_json_number(j, x[i]);
    qd_json_end_array(j);
}

qd_status qd_lyap_json(const qd_lyap_report *r, qd_buf *out) {
    QD_ARGS(QD_ERR_ARG, r && out);
    if (!report_ok(r))
        return QD_ERR_ARG;
    size_t k = r->opts->nexp, d = 2 * r->ndof;
    qd_buf b = QD_BUF_WITH(out->alloc);
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "method");
    qd_json_string(&j, qd_sim_method_name(r->method));
    qd_json_key(&j, "t_avg");
    qd_json_number(&j, r->stats->t_avg);
    qd_json_key(&j, "transient");
    qd_json_number(&j, r->opts->transient);
    qd_json_key(&j, "renorm");
    qd_json_number(&j, r->opts->renorm > 0 ? r->opts->renorm : 1);
    qd_json_key(&j, "renormalizations");
    qd_json_number(&j, (double)r->stats->renorms);
    qd_json_vector(&j, "exponents", k, r->exps);
    if (r->err) {
        numbers_or_null(&j, "errors", k, r->err);
    } else {
        qd_json_key(&j, "errors");
        qd_json_begin_array(&j);
        for (size_t i = 0; i < k; i++)
            qd_json_null(&j);
        qd_json_end_array(&j);
    }
    qd_json_key(&j, "trace_mean");
    qd_json_number(&j, r->stats->trace_mean);
    if (k == d) {
        qd_json_key(&j, "sum");
        qd_json_number(&j, qd_lyap_sum(k, r->exps));
    }
    qd_json_key(&j, "conservative");
    qd_json_bool(&j, r->conservative);
    qd_json_end_object(&j);
    qd_status st = QD_OK;
    if (b.failed)
        st = QD_ERR_NOMEM;
    else if (!qd_json_ok(&j))
        st = QD_ERR_NUMERIC;
    if (st == QD_OK) {
        qd_buf_puts(out, qd_buf_str(&b));
        qd_buf_puts(out, "\n");
        if (out->failed)
            st = QD_ERR_NOMEM;
    }
    qd_buf_free(&b);
    return st;
}
