/* tests/util/system.c - see system.h. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdlib.h>

#include "system.h"

qt_system *qt_system_parse(void **state, const char *text) {
    qt_system *s = calloc(1, sizeof *s);
    *state = s;
    if (!s || !(s->ctx = qd_ctx_new()))
        fail_msg("out of memory");
    qd_diag d;
    s->model = qd_model_parse(s->ctx, text, &d);
    if (!s->model)
        fail_msg("model does not parse: %zu:%zu: %s (%s)\n%s", d.line, d.col, d.message, d.hint,
                 text);
    return s;
}

qt_system *qt_system_derive(void **state, const char *text, bool eliminate) {
    qt_system *s = qt_system_parse(state, text);
    qd_eom_opts opts = {.eliminate = eliminate};
    s->eom = qd_eom_derive_opts(s->ctx, s->model, &opts);
    if (!s->eom)
        fail_msg("derivation failed: %s", qd_ctx_message(s->ctx));
    return s;
}

int qt_system_teardown(void **state) {
    qt_system *s = *state;
    if (!s)
        return 0;
    qd_eom_free(s->eom);
    qd_model_free(s->model);
    qd_ctx_free(s->ctx);
    free(s);
    *state = NULL;
    return 0;
}

const qd_expr *qt_symbol(const qt_system *s, const char *name) {
    const qd_expr *x = qd_lookup(s->ctx, name);
    if (!x)
        fail_msg("no symbol %s", name);
    return x;
}
