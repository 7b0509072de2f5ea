/*
 * cli/opt_diag.c - library errors shown under the option they are about
 * (opt_diag.h).
 */
#include "opt_diag.h"

#include <string.h>

/* Is opt "--" followed by field with '_' for '-'? */
static bool names(const cli_opt *opt, const char *field) {
    const char *s = opt->name;
    if (strncmp(s, "--", 2) != 0)
        return false;
    for (s += 2; *s && *field; s++, field++)
        if (*field != (*s == '-' ? '_' : *s))
            return false;
    return !*s && !*field;
}

/* The option of opts (fields at byte base of args) about field, and its text. */
static const cli_opt *find(const cli_opt *opts, size_t base, const void *args, const qd_diag *d,
                           const char **text) {
    for (const cli_opt *o = opts; o && o->name; o++) {
        if (!names(o, d->name))
            continue;
        const char *p = (const char *)args + base + o->offset;
        if (o->kind == CLI_TEXT || o->kind == CLI_CHOICE)
            *text = *(const char *const *)(const void *)p;
        else if (o->kind == CLI_LIST) {
            const cli_list *l = (const cli_list *)(const void *)p;
            *text = d->index < l->n ? l->items[d->index] : NULL;
        }
        return *text ? o : NULL;
    }
    return NULL;
}

int cli_diag_opts(const qd_ctx *ctx, const cli_spec *spec, const void *args) {
    const qd_diag *d = qd_ctx_diag(ctx);
    const char *text = NULL;
    const cli_opt *o = NULL;
    /* located records about text have subject TEXT (qd_ctx_error_at) */
    if ((d->subject == QD_SUBJECT_NONE || d->subject == QD_SUBJECT_TEXT) && d->located &&
        d->name[0]) {
        o = find(spec->opts, 0, args, d, &text);
        for (const cli_group *g = spec->groups; !o && g && g->opts; g++)
            o = find(g->opts, g->base, args, d, &text);
    }
    if (!o)
        return cli_diag_ctx(ctx);
    cli_diag_show(o->name, text, d);
    return cli_exit(qd_ctx_status(ctx));
}
