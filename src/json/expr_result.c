/*
 * src/json/expr_result.c - the JSON of an operation on one expression
 * (qd_json_expr_result, qdot/json.h): what `qdot diff`, `expand`, `simplify`
 * and `print` write with --format json, one shape for the four.
 */
#include "qdot/json.h"

#include "base/args.h"

qd_status qd_json_expr_result(qd_ctx *ctx, const char *operation, const char *input,
                              size_t nvars, const char *const *vars, const qd_expr *e,
                              qd_buf *out) {
    QD_ARGS_CTX(ctx, ctx && operation && input && (vars || !nvars) && e && out);
    static const struct {
        const char *key;
        qd_format fmt;
    } forms[] = {{"result", QD_FMT_TEXT}, {"latex", QD_FMT_LATEX}, {"c", QD_FMT_C},
                 {"sympy", QD_FMT_SYMPY}};
    qd_buf b = QD_BUF_WITH(out->alloc), s = QD_BUF_WITH(out->alloc);
    qd_json j;
    qd_json_init(&j, &b);
    qd_json_begin_object(&j);
    qd_json_key(&j, "operation");
    qd_json_string(&j, operation);
    qd_json_key(&j, "input");
    qd_json_string(&j, input);
    qd_json_key(&j, "variables");
    qd_json_begin_array(&j);
    for (size_t i = 0; i < nvars; i++)
        qd_json_string(&j, vars[i]);
    qd_json_end_array(&j);
    qd_status st = QD_OK;
    for (size_t k = 0; k < sizeof forms / sizeof *forms && st == QD_OK; k++) {
        qd_buf_clear(&s);
        st = qd_print(ctx, e, forms[k].fmt, &s);
        qd_json_key(&j, forms[k].key);
        qd_json_string(&j, qd_buf_str(&s));
    }
    qd_json_end_object(&j);
    qd_buf_puts(&b, "\n");
    qd_buf_free(&s);
    if (st != QD_OK) {
        qd_buf_free(&b);
        return st;
    }
    return qd_json_commit(ctx, &b, &j, out);
}
