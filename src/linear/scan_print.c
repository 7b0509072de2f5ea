/*
 * src/linear/scan_print.c - a point followed along a parameter and the
 * changes of its stability (qd_modes_scan, qd_stability_scan) written for a
 * reader or a program (qd_scan_print, qd_scan_json: qdot/modes.h).
 */
#include "qdot/modes.h"

#include "qdot/json.h"
#include "../base/args.h"

static const char *verdict_name(int s) {
    return s == 1 ? "stable" : s == 0 ? "unstable" : "borderline";
}

/* x by the digit rule of a computed result, right-aligned in w columns. */
static void put_cell(qd_buf *b, double x, int w) {
    char s[QD_DOUBLE_MAX];
    qd_result_format(s, x, 1);
    qd_buf_printf(b, " %*s", w, s);
}

static bool all_conservative(const qd_scan *sc) {
    for (size_t k = 0; k < sc->count; k++)
        if (!sc->conservative[k])
            return false;
    return true;
}

static bool view_ok(const qd_scan_view *v, const qd_scan *sc) {
    return v->param && v->key && v->followed && (v->names || !sc->n) && sc->count >= 1 &&
           sc->value && sc->margin && sc->stable && sc->conservative && (sc->q || !sc->n) &&
           (sc->trans || !sc->ntrans);
}

qd_status qd_scan_print(const qd_scan_view *v, const qd_scan *sc, qd_buf *b) {
    QD_ARGS(QD_ERR_ARG, v && sc && b);
    if (!view_ok(v, sc))
        return QD_ERR_ARG;
    size_t n = sc->n;
    qd_buf_printf(b, "scan of %s from ", v->param);
    qd_buf_put_result(b, sc->value[0], 1);
    qd_buf_puts(b, " to ");
    qd_buf_put_result(b, sc->value[sc->count - 1], 1);
    qd_buf_printf(b, " in %zu steps, following %s\n", sc->count - 1, v->followed);
    qd_buf_printf(b, " %14s", v->param);
    for (size_t j = 0; j < n; j++)
        qd_buf_printf(b, " %14s", v->names[j]);
    qd_buf_printf(b, " %14s  verdict\n", all_conservative(sc) ? "min w^2" : "max Re s");
    for (size_t k = 0; k < sc->count; k++) {
        put_cell(b, sc->value[k], 14);
        for (size_t j = 0; j < n; j++)
            put_cell(b, sc->q[k * n + j], 14);
        put_cell(b, sc->margin[k], 14);
        qd_buf_printf(b, "  %s\n", verdict_name(sc->stable[k]));
    }
    if (!sc->ntrans)
        qd_buf_puts(b, "no change of stability\n");
    for (size_t t = 0; t < sc->ntrans; t++) {
        const qd_scan_transition *tr = &sc->trans[t];
        qd_buf_printf(b, "transition: %s = %.10g, %s -> %s\n", v->param, tr->value,
                      verdict_name(tr->from), verdict_name(tr->to));
    }
    return b->failed ? QD_ERR_NOMEM : QD_OK;
}

static void json_verdict(qd_json *j, int s) {
    qd_json_key(j, "stable");
    if (s == -1)
        qd_json_null(j);
    else
        qd_json_bool(j, s == 1);
    qd_json_key(j, "verdict");
    qd_json_string(j, verdict_name(s));
}

static void json_samples(const qd_scan_view *v, const qd_scan *sc, qd_json *j) {
    qd_json_key(j, "samples");
    qd_json_begin_array(j);
    for (size_t k = 0; k < sc->count; k++) {
        qd_json_begin_object(j);
        qd_json_key(j, v->param);
        qd_json_number(j, sc->value[k]);
        qd_json_key(j, v->key);
        qd_json_begin_object(j);
        for (size_t i = 0; i < sc->n; i++) {
            qd_json_key(j, v->names[i]);
            qd_json_number(j, sc->q[k * sc->n + i]);
        }
        qd_json_end_object(j);
        qd_json_key(j, sc->conservative[k] ? "min_omega2" : "max_re_s");
        qd_json_number(j, sc->margin[k]);
        json_verdict(j, sc->stable[k]);
        qd_json_end_object(j);
    }
    qd_json_end_array(j);
}

qd_status qd_scan_json(const qd_scan_view *v, const qd_scan *sc, qd_buf *b) {
    QD_ARGS(QD_ERR_ARG, v && sc && b);
    if (!view_ok(v, sc))
        return QD_ERR_ARG;
    qd_json j;
    qd_json_init(&j, b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "parameter");
    qd_json_string(&j, v->param);
    double range[2] = {sc->value[0], sc->value[sc->count - 1]};
    qd_json_vector(&j, "range", 2, range);
    qd_json_key(&j, "steps");
    qd_json_number(&j, (double)(sc->count - 1));
    json_samples(v, sc, &j);
    qd_json_key(&j, "transitions");
    qd_json_begin_array(&j);
    for (size_t t = 0; t < sc->ntrans; t++) {
        const qd_scan_transition *tr = &sc->trans[t];
        qd_json_begin_object(&j);
        qd_json_key(&j, v->param);
        qd_json_number(&j, tr->value);
        qd_json_key(&j, "from");
        qd_json_string(&j, verdict_name(tr->from));
        qd_json_key(&j, "to");
        qd_json_string(&j, verdict_name(tr->to));
        double bracket[2] = {tr->lo, tr->hi};
        qd_json_vector(&j, "bracket", 2, bracket);
        qd_json_end_object(&j);
    }
    qd_json_end_array(&j);
    qd_json_end_object(&j);
    qd_buf_puts(b, "\n");
    return b->failed ? QD_ERR_NOMEM : qd_json_ok(&j) ? QD_OK : QD_ERR_ARG;
}
