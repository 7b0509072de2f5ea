/*
 * src/model/parse.c - reading a model: the whole text (qd_model_parse, with
 * parameter values given from outside), and one more statement added to a
 * parsed model (qd_model_add_statement).
 *
 * Parameter values from outside are input to the parse, not a patch on its
 * results: `parameters k = 1, m = 2*k` read with k = 5 gives m = 10, and
 * everything derived from the model sees both.
 */
#include "parser.h"
#include "base/mem.h"
#include "../base/args.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Statements one per line until the end of the text, then the unclosed
 * brackets. */
static void read_statements(parser *p) {
    while (!p->failed && p->lx.tok.kind != TK_EOF) {
        if (p->lx.tok.kind == TK_NEWLINE) {
            qd__mdl_lex_next(&p->lx);
            continue;
        }
        if (qd__mdl_statement(p) && p->lx.tok.kind == TK_NEWLINE)
            qd__mdl_lex_next(&p->lx);
    }
    if (!p->failed && p->lx.depth > 0) {
        size_t open = p->lx.open[p->lx.depth - 1 < LEX_MAX_DEPTH ? p->lx.depth - 1 : 0];
        qd__mdl_perr(p, open, 1, "every bracket opened must be closed", "unclosed '%c'",
                     p->lx.src[open]);
    }
}

/* What the text must be before it is read: at most QD_MODEL_MAX_BYTES,
 * valid UTF-8 (an overlong or cut character is an error at its byte, not a
 * strange letter), and no name longer than QD_MDL_NAME_MAX - 1 bytes (two
 * long names must not be told apart by a cut prefix).  One pass of the
 * lexer, so a comment may say anything in UTF-8. */
static bool check_text(parser *p, const char *text) {
    size_t n = strlen(text);
    if (n > QD_MODEL_MAX_BYTES) {
        qd_ctx_error(p->ctx, QD_ERR_TOOBIG, "the model text is %zu bytes; at most %zu MiB are read",
                     n, QD_MODEL_MAX_BYTES >> 20);
        p->failed = true;
        if (p->diag)
            *p->diag = *qd_ctx_diag(p->ctx);
        return false;
    }
    size_t bad = qd__diag_utf8_check(text, n);
    if (bad < n) {
        const unsigned char *u = (const unsigned char *)text + bad;
        bool overlong = u[0] == 0xC0 || u[0] == 0xC1 || (u[0] == 0xE0 && u[1] < 0xA0) ||
                        (u[0] == 0xF0 && u[1] < 0x90);
        const char *hint = "qdot reads UTF-8 text: was this written in another encoding?";
        p->lx.src = text; /* no token yet: the error is about the byte itself */
        qd__mdl_perr(p, bad, 1, hint, "invalid UTF-8 at byte %zu: byte 0x%02x %s", bad, u[0],
                     overlong ? "starts an overlong encoding" : "is not UTF-8 there");
        qd_ctx_error_about(p->ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_BAD_BYTE, hint);
        if (p->diag)
            *p->diag = *qd_ctx_diag(p->ctx);
        return false;
    }
    lexer lx;
    for (qd__mdl_lex_init(&lx, text); lx.tok.kind != TK_EOF; qd__mdl_lex_next(&lx))
        if (lx.tok.kind == TK_IDENT && lx.tok.len >= QD_MDL_NAME_MAX) {
            p->lx.src = text;
            return qd__mdl_perr(p, lx.tok.off, lx.tok.len, "choose a shorter name",
                                "a name of %zu bytes; names are at most %d bytes", lx.tok.len,
                                QD_MDL_NAME_MAX - 1);
        }
    return true;
}

/* An error that is not in the text (a value given from outside): not located. */
static void unlocated(parser *p, const char *message) {
    p->failed = true;
    if (!p->diag)
        return;
    *p->diag = *qd_ctx_diag(p->ctx); /* the record qd_ctx_error made, with no range */
    if (!p->diag->message[0])
        snprintf(p->diag->message, sizeof p->diag->message, "%s", message);
}

/* Every value given from outside is a number and names a parameter. */
static bool check_given(parser *p, bool after) {
    const qd_model_opts *o = p->opts;
    for (size_t k = 0; o && k < o->nparams; k++) {
        const qd_param_value *v = &o->params[k];
        if (!after && (!v->name || !v->value || !qd_is_number(v->value))) {
            qd_ctx_error(p->ctx, QD_ERR_ARG, "the value of '%s' must be a number",
                         v->name ? v->name : "(null)");
            unlocated(p, qd_ctx_message(p->ctx));
            return false;
        }
        if (after && !p->set_used[k]) {
            qd__mdl_unknown_param(p->ctx, p->m, v->name);
            unlocated(p, qd_ctx_message(p->ctx));
            return false;
        }
    }
    return true;
}

static qd_model *parse_text(qd_ctx *ctx, const char *text, const qd_model_opts *opts,
                            qd_diag *diag, bool field) {
    qd_model *m = qd__calloc(ctx, 1, sizeof *m);
    bool *used = opts && opts->nparams ? qd__calloc(ctx, opts->nparams, sizeof *used) : NULL;
    if (!m || (opts && opts->nparams && !used)) {
        qd__free(m);
        qd__free(used);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return NULL;
    }
    m->ctx = ctx;
    m->text = m->src = text;
    parser p = {ctx, {0}, m, diag, false, NULL, false, false, 0, opts, used, false, false, false};
    p.field_ok = field;
    if (check_text(&p, text)) {
        qd__mdl_lex_init(&p.lx, text);
        if (check_given(&p, false))
            read_statements(&p);
    }
    if (!p.failed)
        qd__mdl_finish(&p);
    if (!p.failed)
        check_given(&p, true);
    qd__free(used);
    if (p.failed) {
        qd_model_free(m);
        return NULL;
    }
    return m;
}

qd_model *qd_model_parse_opts(qd_ctx *ctx, const char *text, const qd_model_opts *opts,
                              qd_diag *diag) {
    QD_ARGS(NULL, ctx && text);
    return parse_text(ctx, text, opts, diag, false);
}

qd_model *qd__mdl_parse_field(qd_ctx *ctx, const char *text, const qd_model_opts *opts,
                              qd_diag *diag) {
    return parse_text(ctx, text, opts, diag, true);
}

qd_model *qd_model_parse(qd_ctx *ctx, const char *text, qd_diag *diag) {
    QD_ARGS(NULL, ctx && text);
    return qd_model_parse_opts(ctx, text, NULL, diag);
}

/* ---- adding a statement ------------------------------------------------- */

/* What a statement may change, to put the model back when it fails: the
 * lists only grow (their counts are kept), the energies and the per
 * coordinate forces and initial values are replaced (copies are kept). */
typedef struct mark {
    qd_model m;
    const qd_expr **percoord; /* Q, then init, then init_defs, then Qhat */
    speed *speeds;            /* their initial values may be replaced */
} mark;

static bool mark_take(const qd_model *m, mark *k) {
    size_t n = m->ncoords;
    k->m = *m;
    k->percoord = qd__malloc(m->ctx, (6 * n + 1) * sizeof *k->percoord);
    k->speeds = qd__malloc(m->ctx, (m->nspeeds + 1) * sizeof *k->speeds);
    if (!k->percoord || !k->speeds) {
        qd__free(k->percoord);
        qd__free(k->speeds);
        return false;
    }
    if (m->nspeeds)
        memcpy(k->speeds, m->speeds, m->nspeeds * sizeof *m->speeds);
    memcpy(k->percoord, m->Q, n * sizeof *m->Q);
    memcpy(k->percoord + n, m->init, 2 * n * sizeof *m->init);
    memcpy(k->percoord + 3 * n, m->init_defs, 2 * n * sizeof *m->init_defs);
    memcpy(k->percoord + 5 * n, m->Qhat, n * sizeof *m->Qhat);
    return true;
}

/* Free what the failed statement added and restore the rest. */
static void mark_restore(qd_model *m, const mark *k) {
    const qd_model *b = &k->m;
    for (size_t i = b->ndefs; i < m->ndefs; i++)
        qd__free((char *)m->defs[i].name);
    for (size_t i = b->nfuncs; i < m->nfuncs; i++)
        qd__free((char *)m->funcs[i]);
    for (size_t i = b->ncons; i < m->ncons; i++)
        qd__free((char *)m->con_names[i]);
    for (size_t i = b->nbodies; i < m->nbodies; i++)
        qd__free((char *)m->bodies[i].name);
    for (size_t i = b->nreactions; i < m->nreactions; i++)
        qd__free((char *)m->reactions[i].name);
    for (size_t i = b->nsyms; i < m->nsyms; i++) {
        qd__free((char *)m->syms[i].name);
        qd__free(m->syms[i].xi);
    }
    for (size_t i = b->nints; i < m->nints; i++)
        qd__free((char *)m->ints[i].name);
    qd__mdl_free_blows(m->blows, b->nblows, m->nblows);
    qd__mdl_free_sudden(m->sudden, b->nsudden, m->nsudden);
    qd__mdl_free_sudden(m->impacts, b->nimpacts, m->nimpacts);
    qd__mdl_free_sudden(m->prescribed, b->nprescribed, m->nprescribed);
    m->nblows = b->nblows;
    m->nsudden = b->nsudden;
    m->nimpacts = b->nimpacts;
    m->nprescribed = b->nprescribed;
    m->nparts = b->nparts;
    m->nparams = b->nparams;
    m->nfuncs = b->nfuncs;
    m->ndefs = b->ndefs;
    m->nwheres = b->nwheres;
    m->ncons = b->ncons;
    m->nbodies = b->nbodies;
    m->nreactions = b->nreactions;
    m->nsyms = b->nsyms;
    m->nints = b->nints;
    m->nspeeds = b->nspeeds;
    if (b->nspeeds)
        memcpy(m->speeds, k->speeds, b->nspeeds * sizeof *m->speeds);
    m->T = b->T;
    m->V = b->V;
    m->U = b->U;
    m->L = b->L;
    m->D = b->D;
    m->H = b->H;
    size_t n = m->ncoords;
    memcpy(m->Q, k->percoord, n * sizeof *m->Q);
    memcpy(m->init, k->percoord + n, 2 * n * sizeof *m->init);
    memcpy(m->init_defs, k->percoord + 3 * n, 2 * n * sizeof *m->init_defs);
    memcpy(m->Qhat, k->percoord + 5 * n, n * sizeof *m->Qhat);
}

/* The statements that would change the number of coordinates or momenta,
 * which every list of the model is sized by. */
static bool shape_statement(parser *p) {
    if (p->lx.tok.kind != TK_IDENT)
        return false;
    const char *what = qd__mdl_lex_is(&p->lx, "coordinates") ? "coordinates"
                       : qd__mdl_lex_is(&p->lx, "momenta")   ? "momenta"
                                                         : NULL;
    if (!what)
        return false;
    lexer save = p->lx;
    qd__mdl_lex_next(&p->lx);
    bool eq = p->lx.tok.kind == TK_EQ; /* a definition of that name, not the statement */
    p->lx = save;
    if (eq)
        return false;
    qd__mdl_perr_tok(p, "declare them in the model's text",
                     "%s cannot be added to a model already read", what);
    return true;
}

static char *copy_text(qd_ctx *ctx, const char *text) {
    size_t n = strlen(text);
    char *c = qd__malloc(ctx, n + 1);
    if (c)
        memcpy(c, text, n + 1);
    return c;
}

/* One statement of text, with nothing after it but blank lines. */
static void read_one(parser *p) {
    while (p->lx.tok.kind == TK_NEWLINE)
        qd__mdl_lex_next(&p->lx);
    if (p->lx.tok.kind == TK_EOF) {
        qd__mdl_perr(p, 0, 1, "give a statement, e.g. integral m*x'", "no statement to add");
        return;
    }
    if (shape_statement(p) || !qd__mdl_statement(p))
        return;
    while (p->lx.tok.kind == TK_NEWLINE)
        qd__mdl_lex_next(&p->lx);
    if (p->lx.tok.kind != TK_EOF)
        qd__mdl_perr_tok(p, "add one statement at a time", "a second statement");
    else if (p->lx.depth > 0)
        read_statements(p); /* reports the unclosed bracket */
}

qd_status qd_model_add_statement(qd_model *m, const char *text, qd_diag *diag) {
    QD_ARGS(QD_ERR_ARG, m && text);
    qd_ctx *ctx = m->ctx;
    char *copy = copy_text(ctx, text);
    mark k;
    if (!copy || !mark_take(m, &k)) {
        qd__free(copy);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return QD_ERR_NOMEM;
    }
    size_t nadded = m->nadded;
    bool ok = qd__mdl_push(m->ctx, (void **)&m->added, &nadded, sizeof copy, &copy);
    if (ok) {
        m->src = copy;
        parser p = {ctx, {0}, m, diag, false, NULL, false, false, 0, NULL, NULL, false, false, false};
        if (check_text(&p, copy)) {
            qd__mdl_lex_init(&p.lx, copy);
            read_one(&p);
        }
        if (!p.failed)
            qd__mdl_finish(&p);
        ok = !p.failed;
        m->src = m->text;
    }
    if (ok)
        m->nadded = nadded;
    else {
        mark_restore(m, &k);
        qd__free(copy);
    }
    qd__free(k.percoord);
    qd__free(k.speeds);
    if (ok)
        return QD_OK;
    if (qd_ctx_status(ctx) == QD_ERR_NOMEM)
        return QD_ERR_NOMEM;
    return QD_ERR_PARSE;
}
