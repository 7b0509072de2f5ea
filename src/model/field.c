/*
 * src/model/field.c - a continuous system in the model language (Desloge
 * ch. 83, Problem 4: the stretched string), read by qd_field_parse:
 *
 *   field y(x, t) on x = A .. B       the field and its interval
 *   Ldensity = EXPR                   in y, y_t, y_x, x, t and the parameters
 *   boundary y(A) = 0, y(B) free      each end fixed or free
 *
 * The statements are the parser's like any other; the model they fill has
 * no coordinates, so qd_model_parse refuses it at `field` (the commands that
 * read a field say so) and qd_field_parse checks it after the last line.
 */
#include "parser.h"
#include "qdot/field.h"
#include "../base/mem.h"
#include "../base/args.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

struct qd_field {
    qd_model *m;
};

static qd_ctx *C(parser *p) { return p->ctx; }

static bool tok_copy(parser *p, char **out) {
    *out = qd__malloc(C(p), p->lx.tok.len + 1);
    if (!*out)
        return qd__mdl_perr_tok(p, NULL, "out of memory");
    memcpy(*out, p->lx.src + p->lx.tok.off, p->lx.tok.len);
    (*out)[p->lx.tok.len] = '\0';
    return true;
}

static bool expect(parser *p, tk_kind k, const char *hint) {
    if (p->lx.tok.kind != k)
        return qd__mdl_perr_tok(p, hint, "expected %s, found %s", qd__mdl_lex_tk_name(k),
                                qd__mdl_lex_tk_name(p->lx.tok.kind));
    qd__mdl_lex_next(&p->lx);
    return true;
}

/* A name for the density to use: a definition of the symbol sym. */
static bool define(parser *p, const char *name, const qd_expr *sym, size_t off, size_t len) {
    if (!sym)
        return qd__mdl_perr(p, off, len, NULL, "%s", qd_ctx_message(C(p)));
    if (qd__mdl_find_def(p->m, name, strlen(name)))
        return qd__mdl_perr(p, off, len, "choose another name for the field or its variable",
                            "'%s' is already defined", name);
    value v = {VK_SCALAR, {sym}, off, len};
    if (!qd__mdl_add_def(p->m, name, v, off, len))
        return qd__mdl_perr(p, off, len, NULL, "out of memory");
    return true;
}

static const char usage[] = "write: field y(x, t) on x = 0 .. l";

/* A .. B: the lower end is read with '.' ending the expression (not a
 * component); "0..l" lexes as 0, '.', '.', l. */
static bool read_interval(parser *p, qd__field *f) {
    const qd_expr *def;
    p->no_dot = true;
    bool ok = qd__mdl_parse_constant(p, &def, &f->ends[0], "the interval's lower end");
    p->no_dot = false;
    if (!ok)
        return false;
    for (int k = 0; k < 2; k++) {
        if (p->lx.tok.kind != TK_DOT)
            return qd__mdl_perr_tok(p, usage, "expected '..' between the interval's ends");
        qd__mdl_lex_next(&p->lx);
    }
    size_t off = p->lx.tok.off;
    if (!qd__mdl_parse_constant(p, &def, &f->ends[1], "the interval's upper end"))
        return false;
    if (!(qd_number_value(f->ends[1]) > qd_number_value(f->ends[0])))
        return qd__mdl_perr(p, off, p->lx.tok.off > off ? p->lx.tok.off - off : 1,
                            "the interval is A .. B with A < B", "the interval is empty");
    return true;
}

/* field NAME '(' X ',' t ')' on X '=' A '..' B */
bool qd__mdl_stmt_field(parser *p) {
    qd_model *m = p->m;
    size_t kw = p->lx.tok.off;
    if (m->src != m->text)
        return qd__mdl_perr_tok(p, "declare it in the model's text",
                                "a field cannot be added to a model already read");
    if (m->field)
        return qd__mdl_perr_tok(p, "a model has one field", "a second field");
    if (m->ncoords)
        return qd__mdl_perr_tok(p, "a field model has no coordinates: remove them",
                                "a field and coordinates in one model");
    qd__field *f = qd__calloc(C(p), 1, sizeof *f);
    if (!f)
        return qd__mdl_perr_tok(p, NULL, "out of memory");
    f->bc[0] = f->bc[1] = -1;
    m->field = f;
    qd__mdl_lex_next(&p->lx);
    token yt = p->lx.tok;
    if (yt.kind != TK_IDENT)
        return qd__mdl_perr_tok(p, usage, "expected the field's name, found %s",
                                qd__mdl_lex_tk_name(yt.kind));
    if (!qd__mdl_fresh_name(p, "field") || !tok_copy(p, &f->name))
        return false;
    qd__mdl_lex_next(&p->lx);
    if (!expect(p, TK_LPAREN, usage))
        return false;
    token xt = p->lx.tok;
    if (xt.kind != TK_IDENT)
        return qd__mdl_perr_tok(p, usage, "expected the space variable, found %s",
                                qd__mdl_lex_tk_name(xt.kind));
    if (qd__mdl_name_is(p->lx.src, xt.off, xt.len, "t"))
        return qd__mdl_perr_tok(p, usage, "t is the time; the space variable comes first");
    if (!qd__mdl_fresh_name(p, "space variable") || !tok_copy(p, &f->space))
        return false;
    qd__mdl_lex_next(&p->lx);
    if (!expect(p, TK_COMMA, usage))
        return false;
    if (!qd__mdl_lex_is(&p->lx, "t"))
        return qd__mdl_perr_tok(p, usage, "the second variable of a field is the time t");
    qd__mdl_lex_next(&p->lx);
    if (!expect(p, TK_RPAREN, usage))
        return false;
    if (!qd__mdl_lex_is(&p->lx, "on"))
        return qd__mdl_perr_tok(p, usage, "expected 'on' and the interval");
    qd__mdl_lex_next(&p->lx);
    if (p->lx.tok.kind != TK_IDENT ||
        !qd__mdl_name_is(p->lx.src, p->lx.tok.off, p->lx.tok.len, f->space))
        return qd__mdl_perr_tok(p, usage, "expected the space variable '%s'", f->space);
    qd__mdl_lex_next(&p->lx);
    if (!expect(p, TK_EQ, usage) || !read_interval(p, f))
        return false;
    char name[2 * QD_MDL_NAME_MAX + 2];
    qd_ctx *ctx = C(p);
    f->x = qd_symbol(ctx, f->space);
    f->y = qd_symbol(ctx, f->name);
    snprintf(name, sizeof name, "%s_t", f->name);
    f->yt = qd_symbol(ctx, name);
    bool ok = define(p, f->space, f->x, xt.off, xt.len) && define(p, f->name, f->y, yt.off, yt.len) &&
              define(p, name, f->yt, yt.off, yt.len);
    snprintf(name, sizeof name, "%s_%s", f->name, f->space);
    f->yx = qd_symbol(ctx, name);
    ok = ok && define(p, name, f->yx, yt.off, yt.len);
    if (ok && !qd__mdl_add_where(m, "field", kw, p->lx.tok.off - kw))
        return qd__mdl_perr_tok(p, NULL, "out of memory");
    return ok && qd__mdl_end_of_statement(p);
}

/* Ldensity '=' EXPR */
bool qd__mdl_stmt_ldensity(parser *p) {
    qd__field *f = p->m->field;
    size_t kw = p->lx.tok.off;
    if (f->density)
        return qd__mdl_perr_tok(p, "a field has one Lagrangian density", "Ldensity is given twice");
    qd__mdl_lex_next(&p->lx);
    qd__mdl_lex_next(&p->lx); /* '=' */
    size_t off = p->lx.tok.off;
    if (!qd__mdl_parse_scalar(p, &f->density, "a Lagrangian density"))
        return false;
    f->density_num = qd__mdl_subs_params(p->m, f->density, p->m->nparams);
    if (!f->density_num)
        return qd__mdl_perr(p, off, 1, NULL, "%s", qd_ctx_message(C(p)));
    if (!qd_has(f->density, f->yt) && !qd_has(f->density, f->yx) && !qd_has(f->density, f->y))
        return qd__mdl_perr(p, off, p->lx.tok.off > off ? p->lx.tok.off - off : 1,
                            "write it in the field and its derivatives, e.g. "
                            "rho/2*y_t^2 - tau/2*y_x^2",
                            "the density does not depend on the field");
    if (!qd__mdl_add_where(p->m, "Ldensity", kw, p->lx.tok.off - kw))
        return qd__mdl_perr_tok(p, NULL, "out of memory");
    return qd__mdl_end_of_statement(p);
}

static const char busage[] = "write: boundary y(0) = 0, y(l) free";

/* NAME '(' END ')' ('=' 0 | free) */
static bool read_end(parser *p, qd__field *f) {
    if (p->lx.tok.kind != TK_IDENT ||
        !qd__mdl_name_is(p->lx.src, p->lx.tok.off, p->lx.tok.len, f->name))
        return qd__mdl_perr_tok(p, busage, "expected the field '%s' at an end", f->name);
    qd__mdl_lex_next(&p->lx);
    size_t open = p->lx.tok.off;
    if (!expect(p, TK_LPAREN, busage))
        return false;
    size_t off = p->lx.tok.off;
    const qd_expr *def, *at;
    if (!qd__mdl_parse_constant(p, &def, &at, "an end of the interval"))
        return false;
    size_t len = p->lx.tok.off > off ? p->lx.tok.off - off : 1;
    if (!qd__mdl_expect_close(p, open))
        return false;
    double a = qd_number_value(f->ends[0]), b = qd_number_value(f->ends[1]), v = qd_number_value(at);
    double tol = 1e-12 * (fabs(a) + fabs(b) + 1);
    int end = fabs(v - a) <= tol ? 0 : fabs(v - b) <= tol ? 1 : -1;
    if (end < 0)
        return qd__mdl_perr(p, off, len, "a condition is at an end of the interval",
                            "%g is not an end of the interval %g .. %g", v, a, b);
    if (f->bc[end] >= 0)
        return qd__mdl_perr(p, off, len, "give each end once", "this end's condition is given twice");
    if (qd__mdl_lex_is(&p->lx, "free")) {
        f->bc[end] = QD_FIELD_FREE;
        qd__mdl_lex_next(&p->lx);
        return true;
    }
    if (!expect(p, TK_EQ, busage))
        return false;
    size_t zoff = p->lx.tok.off;
    if (!qd__mdl_parse_constant(p, &def, &at, "the end's value"))
        return false;
    if (!qd_is_zero(at))
        return qd__mdl_perr(p, zoff, p->lx.tok.off > zoff ? p->lx.tok.off - zoff : 1,
                            "a fixed end is at rest at y = 0; move the field's origin",
                            "only a fixed end at 0 is supported");
    f->bc[end] = QD_FIELD_FIXED;
    return true;
}

/* boundary END (',' END)* */
bool qd__mdl_stmt_boundary(parser *p) {
    qd__field *f = p->m->field;
    size_t kw = p->lx.tok.off;
    if (!f)
        return qd__mdl_perr_tok(p, "declare the field first: field y(x, t) on x = 0 .. l",
                                "boundary conditions without a field");
    qd__mdl_lex_next(&p->lx);
    for (;;) {
        if (!read_end(p, f))
            return false;
        if (p->lx.tok.kind != TK_COMMA)
            break;
        qd__mdl_lex_next(&p->lx);
    }
    if (!qd__mdl_add_where(p->m, "boundary", kw, p->lx.tok.off - kw))
        return qd__mdl_perr_tok(p, NULL, "out of memory");
    return qd__mdl_end_of_statement(p);
}

bool qd__mdl_field_finish(parser *p) {
    qd_model *m = p->m;
    qd__field *f = m->field;
    qd_diag at;
    if (!p->field_ok) {
        qd_model_where(m, "field", &at);
        return qd__mdl_perr(p, at.offset, at.length,
                            "qdot eom and qdot modes read a field model",
                            "a field model has no coordinates for this command");
    }
    if (!f)
        return qd__mdl_perr(p, 0, 1, "declare it: field y(x, t) on x = 0 .. l", "no field is declared");
    qd_model_where(m, "field", &at);
    if (m->ncoords || m->T || m->V || m->L || m->H || m->nparts || m->nbodies)
        return qd__mdl_perr(p, at.offset, at.length,
                            "write the energies in the density: Ldensity = rho/2*y_t^2 - tau/2*y_x^2",
                            "a field model has no coordinates, T, V, L or H");
    if (!f->density)
        return qd__mdl_perr(p, at.offset, at.length,
                            "give it: Ldensity = rho/2*y_t^2 - tau/2*y_x^2",
                            "the field has no Lagrangian density");
    if (f->bc[0] < 0 || f->bc[1] < 0)
        return qd__mdl_perr(p, at.offset, at.length, "give both: boundary y(0) = 0, y(l) free",
                            "the condition at the field's %s end is not given",
                            f->bc[0] < 0 ? "lower" : "upper");
    return true;
}

void qd__mdl_free_field(qd_model *m) {
    if (!m->field)
        return;
    qd__free(m->field->name);
    qd__free(m->field->space);
    qd__free(m->field);
    m->field = NULL;
}

/* ---- public ------------------------------------------------------------ */

bool qd_field_declared(const char *text) {
    QD_ARGS(false, text);
    lexer lx;
    bool start = true;
    for (qd__mdl_lex_init(&lx, text); lx.tok.kind != TK_EOF; qd__mdl_lex_next(&lx)) {
        if (start && qd__mdl_lex_is(&lx, "field")) {
            lexer look = lx;
            qd__mdl_lex_next(&look);
            if (look.tok.kind == TK_IDENT)
                return true;
        }
        start = lx.tok.kind == TK_NEWLINE;
    }
    return false;
}

qd_field *qd_field_parse(qd_ctx *ctx, const char *text, const qd_model_opts *opts,
                         qd_diag *diag) {
    QD_ARGS(NULL, ctx && text);
    qd_field *f = qd__calloc(ctx, 1, sizeof *f);
    if (!f) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
        return NULL;
    }
    f->m = qd__mdl_parse_field(ctx, text, opts, diag);
    if (!f->m) {
        qd__free(f);
        return NULL;
    }
    return f;
}

void qd_field_free(qd_field *f) {
    if (!f)
        return;
    qd_model_free(f->m);
    qd__free(f);
}

const char *qd_field_name(const qd_field *f) {
    QD_ARGS(NULL, f);
    return f->m->field->name;
}

const char *qd_field_space(const qd_field *f) {
    QD_ARGS(NULL, f);
    return f->m->field->space;
}

const qd_expr *qd_field_density(const qd_field *f) {
    QD_ARGS(NULL, f);
    return f->m->field->density;
}

qd_status qd_field_interval(const qd_field *f, double *a, double *b) {
    QD_ARGS(QD_ERR_ARG, f && a && b);
    *a = qd_number_value(f->m->field->ends[0]);
    *b = qd_number_value(f->m->field->ends[1]);
    return QD_OK;
}

qd_field_end qd_field_boundary(const qd_field *f, int end) {
    QD_ARGS(QD_FIELD_FIXED, f && (end == 0 || end == 1));
    return (qd_field_end)f->m->field->bc[end];
}

const qd_model *qd_field_model(const qd_field *f) {
    QD_ARGS(NULL, f);
    return f->m;
}

/* For src/field: the symbols. */
const qd__field *qd__mdl_field_data(const qd_field *f) { return f->m->field; }
