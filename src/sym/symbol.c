/*
 * src/sym/symbol.c - symbols and their roles.
 *
 * One name, one symbol per context.  A coordinate q is a function of the
 * time; its derivatives q', q'', ... are symbols of their own (the jet), made
 * on demand and chained from q so that d/dt can step along the chain.
 *
 * Every symbol is real.  A plain symbol or a parameter may also be made
 * positive (qd_symbol_positive), like SymPy's Symbol('m', positive=True):
 * then |m| = m and sqrt(m^2) = m on construction.
 */
#include "node.h"
#include "../base/args.h"

#include <string.h>

#define QD_MAX_JET 64 /* far beyond any mechanics; bounds the name buffer */

static const char *role_name(qd_role r) {
    switch (r) {
    case QD_ROLE_PLAIN: return "symbol";
    case QD_ROLE_TIME: return "time";
    case QD_ROLE_COORD: return "coordinate";
    case QD_ROLE_PARAM: return "parameter";
    }
    return "symbol";
}

static const qd_expr *make_symbol(qd_ctx *ctx, const char *name, qd_role role, unsigned order,
                                  const qd_expr *coord, bool positive) {
    if (!name || !*name) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a symbol needs a name");
        return NULL;
    }
    const char *iname = qd__intern_name(ctx, name);
    if (!iname)
        return NULL;
    const qd_expr *old = qd__ptrmap_get(&ctx->sym->symtab, iname);
    if (old) {
        if (old->tag != role || old->order != order) {
            qd_ctx_error(ctx, QD_ERR_ARG, "'%s' is already a %s", name,
                         role_name((qd_role)old->tag));
            return NULL;
        }
        /* The assumption is part of the symbol from its birth: expressions
         * already made with it could not take it into account. */
        if (positive && !old->u.sym.positive) {
            qd_ctx_error(ctx, QD_ERR_ARG, "'%s' is already a %s not assumed positive", name,
                         role_name((qd_role)old->tag));
            return NULL;
        }
        return old;
    }
    qd_expr proto = {0};
    proto.kind = QD_SYMBOL;
    proto.tag = (uint8_t)role;
    proto.order = (uint16_t)order;
    proto.u.sym.name = iname;
    proto.u.sym.positive = positive;
    qd_expr *e = (qd_expr *)qd__intern(ctx, &proto, 0, NULL);
    if (!e)
        return NULL;
    /* The jet links are caches on our own arena node, not part of its identity. */
    e->u.sym.coord = coord ? coord : e;
    if (!qd__ptrmap_put(&ctx->sym->symtab, iname, e)) {
        qd__oom(ctx);
        return NULL;
    }
    return e;
}

const qd_expr *qd_symbol(qd_ctx *ctx, const char *name) {
    QD_ARGS(NULL, ctx && name);
    return make_symbol(ctx, name, QD_ROLE_PLAIN, 0, NULL, false);
}

const qd_expr *qd_param(qd_ctx *ctx, const char *name) {
    QD_ARGS(NULL, ctx && name);
    return make_symbol(ctx, name, QD_ROLE_PARAM, 0, NULL, false);
}

const qd_expr *qd_symbol_positive(qd_ctx *ctx, const char *name, qd_role role) {
    QD_ARGS(NULL, ctx && name);
    if (role != QD_ROLE_PLAIN && role != QD_ROLE_PARAM) {
        qd_ctx_error(ctx, QD_ERR_ARG, "only a plain symbol or a parameter can be assumed positive");
        return NULL;
    }
    return make_symbol(ctx, name, role, 0, NULL, true);
}

bool qd_symbol_is_positive(const qd_expr *e) {
    QD_ARGS(false, e);
    return e && e->kind == QD_SYMBOL && e->u.sym.positive;
}

const qd_expr *qd_time(qd_ctx *ctx) { QD_ARGS(NULL, ctx); return make_symbol(ctx, "t", QD_ROLE_TIME, 0, NULL, false); }

const qd_expr *qd_coord(qd_ctx *ctx, const char *name) {
    QD_ARGS(NULL, ctx && name);
    if (name && strchr(name, '\'')) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a coordinate name cannot contain a prime: '%s'", name);
        return NULL;
    }
    return make_symbol(ctx, name, QD_ROLE_COORD, 0, NULL, false);
}

const qd_expr *qd_jet(qd_ctx *ctx, const qd_expr *coord, unsigned order) {
    QD_ARGS(NULL, ctx && coord);
    if (!coord)
        return NULL;
    if (coord->kind != QD_SYMBOL || coord->tag != QD_ROLE_COORD) {
        qd_ctx_error(ctx, QD_ERR_ARG, "only a coordinate has time derivatives as symbols");
        return NULL;
    }
    if (order > QD_MAX_JET) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "time derivative of order %u is beyond %d", order,
                     QD_MAX_JET);
        return NULL;
    }
    const qd_expr *q = coord->u.sym.coord;
    for (unsigned k = 1; k <= order; k++) {
        if (!q->u.sym.next) {
            const char *base = q->u.sym.coord->u.sym.name;
            size_t n = strlen(base);
            char *name = qd__alloc(ctx, n + k + 1);
            if (!name)
                return NULL;
            memcpy(name, base, n);
            memset(name + n, '\'', k);
            name[n + k] = '\0';
            const qd_expr *s = make_symbol(ctx, name, QD_ROLE_COORD, k, q->u.sym.coord, false);
            if (!s)
                return NULL;
            ((qd_expr *)q)->u.sym.next = s;
        }
        q = q->u.sym.next;
    }
    return q;
}

const qd_expr *qd_lookup(const qd_ctx *ctx, const char *name) {
    QD_ARGS(NULL, ctx && name);
    const char *iname = qd__find_name(ctx, name);
    return iname ? qd__ptrmap_get(&ctx->sym->symtab, iname) : NULL;
}
