/*
 * src/json/model_key.c - the "model" member every command's JSON that reads a
 * model starts with (qd_json_add_model, qdot/json.h; issue 31's one
 * vocabulary: `model`, not `file` or nothing), put into a document a
 * printer wrote without it.
 */
#include "qdot/json.h"

#include <string.h>

#include "base/args.h"

static const char KEY[] = "\n  \"model\":";

qd_status qd_json_add_model(qd_buf *doc, const char *model) {
    QD_ARGS(QD_ERR_ARG, doc);
    if (doc->failed)
        return QD_ERR_NOMEM;
    const char *s = qd_buf_str(doc);
    if (s[0] != '{')
        return QD_ERR_ARG;
    if (!strncmp(s + 1, KEY, sizeof KEY - 1))
        return QD_OK; /* it has one */
    qd_buf b = QD_BUF_WITH(doc->alloc);
    qd_json j;
    qd_json_init(&j, &b);
    qd_buf_puts(&b, "{");
    qd_buf_puts(&b, KEY);
    qd_buf_puts(&b, " ");
    qd_json_string(&j, model);
    size_t i = 1;
    while (s[i] == ' ' || s[i] == '\n')
        i++;
    /* an empty object gets the member alone; else a comma before the rest */
    qd_buf_puts(&b, s[i] == '}' ? "\n" : ",");
    qd_buf_puts(&b, s[i] == '}' ? s + i : s + 1);
    if (b.failed) { /* the document is lost, not written without its model */
        qd_buf_free(&b);
        doc->failed = true;
        return QD_ERR_NOMEM;
    }
    qd_buf_free(doc);
    *doc = b;
    return QD_OK;
}
