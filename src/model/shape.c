/*
 * src/model/shape.c - the shape statement: what a picture draws a body as.
 *
 *   shape BODY as rod(l) | disk(a) | ring(a) | sphere(a) | box(a, b, c) [along x | y | z]
 *
 * It says nothing to the mechanics (the inertia does that): a rod lies
 * along body z, a disk or ring in the body xy plane, as the inertia
 * helpers rod(m, l), disk(m, a), ring(m, a) have them; `along` turns the
 * rod's axis, or the disk's or ring's normal, onto body x or y.  Sizes are
 * expressions in the parameters (a shape does not change as it moves).
 */
#include "parser.h"

#include <stdio.h>
#include <string.h>

static const char *const kinds[] = {"rod", "disk", "ring", "sphere", "box"};
static const size_t nargs[] = {1, 1, 1, 1, 3};
#define NKINDS 5

static const char *usage = "write: shape BODY as rod(l), disk(a), ring(a), sphere(a) or "
                           "box(a, b, c) [along x|y|z]";

/* The body named, its statement's own (a second shape is an error). */
static body *shape_body(parser *p) {
    if (p->lx.tok.kind != TK_IDENT) {
        qd__mdl_perr_tok(p, usage, "expected a body's name, found %s",
                         qd__mdl_lex_tk_name(p->lx.tok.kind));
        return NULL;
    }
    token at = p->lx.tok;
    const body *b = qd__mdl_expect_body(p, "shape");
    if (b && b->shape) {
        qd__mdl_perr(p, at.off, at.len, "give each body one shape statement",
                     "body '%s' has a shape already", b->name);
        return NULL;
    }
    return (body *)(size_t)b; /* the model's own, being built */
}

static int kind_index(parser *p) {
    for (int i = 0; i < NKINDS; i++)
        if (qd__mdl_lex_is(&p->lx, kinds[i]))
            return i;
    char word[64], hint[160];
    size_t n = p->lx.tok.len < 63 ? p->lx.tok.len : 63;
    snprintf(word, sizeof word, "%.*s", (int)n, p->lx.src + p->lx.tok.off);
    const char *near =
        p->lx.tok.kind == TK_IDENT ? qd__diag_nearest(word, n, kinds, NKINDS) : NULL;
    if (!near && (!strcmp(word, "hoop") || !strcmp(word, "shell") || !strcmp(word, "cylinder")))
        near = !strcmp(word, "hoop") ? "ring" : !strcmp(word, "shell") ? "sphere" : "disk";
    if (near)
        snprintf(hint, sizeof hint, "did you mean '%s'?", near);
    qd__mdl_perr_tok(p, near ? hint : usage, "unknown shape '%s'",
                     p->lx.tok.kind == TK_IDENT ? word : qd__mdl_lex_tk_name(p->lx.tok.kind));
    return -1;
}

/* A size: a scalar in the parameters alone. */
static bool size_arg(parser *p, const qd_expr **out) {
    size_t off = p->lx.tok.off;
    if (!qd__mdl_parse_scalar(p, out, "a size"))
        return false;
    const qd_expr *syms[64];
    size_t n = qd_free_symbols(p->ctx, *out, syms, 64);
    for (size_t i = 0; i < n && i < 64; i++)
        if (qd_symbol_role(syms[i]) == QD_ROLE_COORD || qd_symbol_role(syms[i]) == QD_ROLE_TIME)
            return qd__mdl_perr(p, off, p->lx.tok.off - off,
                                "a size is a number or an expression in the parameters",
                                "a shape's size does not change with the motion");
    return true;
}

/* KIND '(' size {',' size} ')' */
static bool parse_kind(parser *p, body *b) {
    int k = kind_index(p);
    if (k < 0)
        return false;
    size_t off = p->lx.tok.off;
    qd__mdl_lex_next(&p->lx);
    size_t open = p->lx.tok.off;
    if (p->lx.tok.kind != TK_LPAREN)
        return qd__mdl_perr_tok(p, usage, "expected '(' after '%s'", kinds[k]);
    qd__mdl_lex_next(&p->lx);
    size_t got = 0;
    for (;;) {
        const qd_expr *s;
        if (!size_arg(p, &s))
            return false;
        if (got < 3)
            b->size[got] = s;
        got++;
        if (p->lx.tok.kind != TK_COMMA)
            break;
        qd__mdl_lex_next(&p->lx);
    }
    if (!qd__mdl_expect_close(p, open))
        return false;
    if (!qd__mdl_check_arity(p, kinds[k], got, nargs[k], off, p->lx.tok.off - off))
        return false;
    b->shape = k + 1; /* QD_SHAPE_ROD ... QD_SHAPE_BOX */
    return true;
}

/* [along x|y|z]: for a rod, disk or ring */
static bool parse_along(parser *p, body *b) {
    b->axis = 2;
    if (!qd__mdl_lex_is(&p->lx, "along"))
        return true;
    size_t off = p->lx.tok.off;
    if (b->shape != QD_SHAPE_ROD && b->shape != QD_SHAPE_DISK && b->shape != QD_SHAPE_RING)
        return qd__mdl_perr_tok(p, "a sphere has no axis; a box's edges are along body x, y, z",
                                "'along' is for a rod, a disk or a ring");
    qd__mdl_lex_next(&p->lx);
    const char *w = p->lx.src + p->lx.tok.off;
    static const char axes[] = "xyz";
    const char *at = p->lx.tok.kind == TK_IDENT && p->lx.tok.len == 1 ? strchr(axes, *w) : NULL;
    int axis = at && *at ? (int)(at - axes) : -1;
    if (axis < 0)
        return qd__mdl_perr(p, off, p->lx.tok.off + p->lx.tok.len - off,
                            "write: along x, along y or along z (a body axis)",
                            "expected a body axis x, y or z after 'along'");
    b->axis = axis;
    qd__mdl_lex_next(&p->lx);
    return true;
}

bool qd__mdl_stmt_shape(parser *p) {
    qd__mdl_lex_next(&p->lx);
    body *b = shape_body(p);
    if (!b)
        return false;
    if (!qd__mdl_lex_is(&p->lx, "as"))
        return qd__mdl_perr_tok(p, usage, "expected 'as' after the body's name");
    qd__mdl_lex_next(&p->lx);
    body nb = *b;
    if (!parse_kind(p, &nb) || !parse_along(p, &nb) || !qd__mdl_end_of_statement(p))
        return false;
    *b = nb; /* only a whole statement gives the body its shape */
    return true;
}
