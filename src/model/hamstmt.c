/*
 * src/model/hamstmt.c - a model given by its Hamiltonian.
 *
 *   momenta NAME, ...       one per coordinate, in coordinate order
 *   H = EXPR                in the coordinates, those momenta, parameters, t
 *
 * A model gives either H or the energies (T, V, U, L, particles, bodies):
 * both at once would be two descriptions that need not agree.  `momenta`
 * alone, with T or L, only renames the momenta qdot hamiltonian uses.  The
 * momenta are plain symbols; the parser lets expressions name them only in
 * H and in `integral` (parser.momenta_ok), since elsewhere they mean nothing.
 */
#include "parser.h"
#include "../base/mem.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* prefix + "momenta p_r, p_theta" for this model's coordinates, as a hint. */
static void momenta_hint(const qd_model *m, const char *prefix, char *buf, size_t cap) {
    size_t n = (size_t)snprintf(buf, cap, "%smomenta ", prefix);
    for (size_t i = 0; i < m->ncoords && n < cap; i++)
        n += (size_t)snprintf(buf + n, cap - n, "%sp_%s", i ? ", " : "",
                              qd_expr_name(m->coords[i]));
}

/* momenta NAME (',' NAME)* */
bool qd__mdl_stmt_momenta(parser *p) {
    qd_model *m = p->m;
    token kw = p->lx.tok;
    if (m->mom) {
        qd_diag first;
        qd_model_where(m, "momenta", &first);
        return qd__mdl_perr(p, kw.off, kw.len, "give all the momenta on one line",
                    "momenta are declared twice (first on line %zu)", first.line);
    }
    if (m->ncoords == 0)
        return qd__mdl_perr(p, kw.off, kw.len, "declare the coordinates first: coordinates q1, q2",
                    "momenta before any coordinates");
    const qd_expr **mom = qd__calloc(p->ctx, m->ncoords, sizeof *mom);
    if (!mom)
        return qd__mdl_perr(p, kw.off, kw.len, NULL, "out of memory");
    size_t n = 0;
    token last = kw;
    bool ok = true;
    do {
        qd__mdl_lex_next(&p->lx);
        token at = p->lx.tok;
        if (at.kind != TK_IDENT) {
            ok = qd__mdl_perr_tok(p, "write: momenta p_q1, p_q2", "expected a momentum's name, found %s",
                          qd__mdl_lex_tk_name(at.kind));
            break;
        }
        if (n == m->ncoords) {
            char hint[160];
            snprintf(hint, sizeof hint, "one momentum per coordinate: there %s %zu coordinate%s",
                     m->ncoords == 1 ? "is" : "are", m->ncoords, m->ncoords == 1 ? "" : "s");
            ok = qd__mdl_perr(p, at.off, at.len, hint, "more momenta than coordinates");
            break;
        }
        char name[128];
        snprintf(name, sizeof name, "%.*s", (int)(at.len < 127 ? at.len : 127), p->lx.src + at.off);
        for (size_t i = 0; i < n && ok; i++)
            if (!strcmp(qd_expr_name(mom[i]), name))
                ok = qd__mdl_perr_tok(p, "each coordinate has its own momentum",
                              "momentum '%s' is named twice", name);
        if (!ok || !(ok = qd__mdl_fresh_name(p, "momentum")))
            break;
        mom[n] = qd_symbol(p->ctx, name);
        if (!mom[n]) {
            ok = qd__mdl_perr_tok(p, "choose another name", "%s", qd_ctx_message(p->ctx));
            break;
        }
        n++;
        last = at;
        qd__mdl_lex_next(&p->lx);
    } while (p->lx.tok.kind == TK_COMMA);
    if (ok && n < m->ncoords) {
        char hint[256];
        momenta_hint(m, "one momentum per coordinate, in coordinate order: ", hint, sizeof hint);
        ok = qd__mdl_perr(p, last.off, last.len, hint, "%zu moment%s for %zu coordinates", n,
                  n == 1 ? "um" : "a", m->ncoords);
    }
    if (!ok) {
        qd__free(mom);
        return false;
    }
    m->mom = mom;
    if (!qd__mdl_add_where(m, "momenta", kw.off, kw.len))
        return qd__mdl_perr(p, kw.off, kw.len, NULL, "out of memory");
    return qd__mdl_end_of_statement(p);
}

/* The first of T, L, V, U the model gives ("T" also for particles and
 * bodies), or NULL. */
static const char *energy_given(const qd_model *m) {
    if (m->T)
        return qd_model_where(m, "T", NULL) ? "T" : "T (from particles or bodies)";
    return m->L ? "L" : m->V ? "V" : m->U ? "U" : NULL;
}

bool qd__mdl_no_hamiltonian_yet(parser *p, const char *what, size_t off, size_t len) {
    if (!p->m->H)
        return true;
    qd_diag h;
    qd_model_where(p->m, "H", &h);
    return qd__mdl_perr(p, off, len, "a model gives either H (with momenta) or its energies T and V (or L)",
                "%s cannot be given with H (line %zu)", what, h.line);
}

/* The velocity (or acceleration) H depends on, or NULL. */
static const qd_expr *velocity_in(parser *p, const qd_expr *x) {
    for (size_t j = 0; j < p->m->ncoords; j++)
        for (unsigned order = 1; order <= 2; order++) {
            const qd_expr *v = qd_jet(p->ctx, p->m->coords[j], order);
            if (v && qd_has(x, v))
                return v;
        }
    return NULL;
}

/* H '=' EXPR */
bool qd__mdl_stmt_hamiltonian(parser *p) {
    qd_model *m = p->m;
    token at = p->lx.tok;
    if (m->H) {
        qd_diag first;
        qd_model_where(m, "H", &first);
        return qd__mdl_perr(p, at.off, at.len, "give it once; add the parts in one expression",
                    "H is given twice (first on line %zu)", first.line);
    }
    if (!qd__mdl_no_speeds_yet(p, "H", at.off, at.len))
        return false;
    const char *e = energy_given(m);
    if (e)
        return qd__mdl_perr(p, at.off, at.len,
                    "a model gives either H (with momenta) or its energies T and V (or L)",
                    "H cannot be given with %s", e);
    if (!m->mom) {
        char hint[256];
        momenta_hint(m, "declare one momentum per coordinate first: ", hint, sizeof hint);
        return qd__mdl_perr(p, at.off, at.len, m->ncoords ? hint : "declare the coordinates and momenta "
                    "first", "H is given before the momenta");
    }
    qd__mdl_lex_next(&p->lx); /* '=' */
    qd__mdl_lex_next(&p->lx);
    size_t off = p->lx.tok.off;
    p->momenta_ok = true;
    const qd_expr *H;
    bool ok = qd__mdl_parse_scalar(p, &H, "H");
    p->momenta_ok = false;
    if (!ok)
        return false;
    const qd_expr *v = velocity_in(p, H);
    if (v) {
        char hint[256];
        snprintf(hint, sizeof hint, "write H in the coordinates, the momenta (%s, ...), the "
                 "parameters and t", qd_expr_name(m->mom[0]));
        return qd__mdl_perr(p, off, p->lx.tok.off - off, hint, "H depends on the velocity %s",
                    qd_expr_name(v));
    }
    m->H = H;
    if (!qd__mdl_add_where(m, "H", at.off, at.len))
        return qd__mdl_perr(p, at.off, at.len, NULL, "out of memory");
    return qd__mdl_end_of_statement(p);
}
