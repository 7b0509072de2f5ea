/*
 * src/form/fourier.c - the Fourier series of a trigonometric polynomial in
 * several angles (qd_fourier_series, qdot/form.h; Desloge App. 31 and
 * ch. 79: a multiply periodic function as a sum of harmonics).
 *
 * f is expanded into a sum of products; each product's factors free of the
 * variables are its coefficient, and each cos(u) or sin(u) with u linear in
 * them, u = k.x + c, is the harmonic (k.x) with the phase c moved into its
 * coefficients.  Products of harmonics are linearized by
 *     cos a cos b = [cos(a - b) + cos(a + b)]/2,
 *     sin a sin b = [cos(a - b) - cos(a + b)]/2,
 *     sin a cos b = [sin(a + b) + sin(a - b)]/2,
 * so a term (a, C, S) = C cos a + S sin a times (b, C', S') gives
 * a + b: ((C C' - S S')/2, (C S' + S C')/2) and a - b: ((C C' + S S')/2,
 * (S C' - C S')/2).  An argument and its negative are one harmonic (the
 * sine's coefficient changes sign).  The sum is checked against f by the
 * zero test.
 */
#include <string.h>
#include "qdot/form.h"
#include "base/args.h"
#include "base/mem.h"

#define FS_MAX 4096 /* harmonics a series may hold */

typedef struct fs_term {
    const qd_expr *arg, *c, *s;
} fs_term;

typedef struct fs_list {
    size_t n;
    struct {
        size_t n;
        const qd_expr *const *x;
    } vars; /* the variables, for the harmonics' sign */
    fs_term t[FS_MAX];
} fs_list;

void qd_fourier_free(qd_fourier *f) {
    if (!f)
        return;
    qd__free(f->terms);
    qd__free(f->k);
    qd__free(f);
}

static const qd_expr *tidy(qd_ctx *ctx, const qd_expr *e) {
    return qd_simplify(ctx, qd_cancel(ctx, qd_expand(ctx, e)));
}

/* The sign of k by its form (numbers, pi, positive symbols and their
 * products), else 0. */
static int sign_of(const qd_expr *k) {
    switch (qd_expr_kind(k)) {
    case QD_RATIONAL:
    case QD_FLOAT:
        return qd_number_sign(k);
    case QD_CONSTANT:
        return 1;
    case QD_SYMBOL:
        return qd_symbol_is_positive(k) ? 1 : 0;
    case QD_MUL: {
        int s = 1;
        for (size_t i = 0; i < qd_expr_nargs(k) && s; i++)
            s *= sign_of(qd_expr_arg(k, i));
        return s;
    }
    default:
        return 0;
    }
}

/* arg or -arg: the one whose first numeric wave-vector component is
 * positive (else whichever sorts first); sign -1 when flipped; 0 stays 0. */
static const qd_expr *canonical(qd_ctx *ctx, const qd_expr *arg, int *sign, size_t n,
                                const qd_expr *const *x) {
    const qd_expr *a = qd_expand(ctx, arg), *m = qd_expand(ctx, qd_neg(ctx, arg));
    *sign = 1;
    if (qd_is_zero(a))
        return a;
    for (size_t i = 0; i < n; i++) {
        const qd_expr *k = qd_simplify(ctx, qd_diff(ctx, a, x[i]));
        if (!k || qd_is_zero(k))
            continue;
        if (sign_of(k)) {
            *sign = sign_of(k);
            return *sign < 0 ? m : a;
        }
        break;
    }
    if (qd_expr_cmp(a, m) <= 0)
        return a;
    *sign = -1;
    return m;
}

static bool add_term(qd_ctx *ctx, fs_list *L, const qd_expr *arg, const qd_expr *c,
                     const qd_expr *s) {
    int sg;
    arg = canonical(ctx, arg, &sg, L->vars.n, L->vars.x);
    if (sg < 0)
        s = qd_neg(ctx, s);
    if (qd_is_zero(arg))
        s = qd_int(ctx, 0);
    for (size_t i = 0; i < L->n; i++)
        if (L->t[i].arg == arg) {
            L->t[i].c = qd_add(ctx, L->t[i].c, c);
            L->t[i].s = qd_add(ctx, L->t[i].s, s);
            return true;
        }
    if (L->n == FS_MAX) {
        qd_ctx_error(ctx, QD_ERR_TOOBIG, "the series has more than %d harmonics", FS_MAX);
        return false;
    }
    L->t[L->n++] = (fs_term){arg, c, s};
    return true;
}

/* out = A * (b, C', S'), the harmonic of one factor. */
static bool times(qd_ctx *ctx, const fs_list *A, const fs_term *h, fs_list *out) {
    const qd_expr *half = qd_rat(ctx, 1, 2);
    out->n = 0;
    for (size_t i = 0; i < A->n; i++) {
        const fs_term *a = &A->t[i];
        const qd_expr *cc = qd_mul(ctx, a->c, h->c), *ss = qd_mul(ctx, a->s, h->s);
        const qd_expr *cs = qd_mul(ctx, a->c, h->s), *sc = qd_mul(ctx, a->s, h->c);
        if (!add_term(ctx, out, qd_add(ctx, a->arg, h->arg), qd_mul(ctx, half, qd_sub(ctx, cc, ss)),
                      qd_mul(ctx, half, qd_add(ctx, cs, sc))) ||
            !add_term(ctx, out, qd_sub(ctx, a->arg, h->arg), qd_mul(ctx, half, qd_add(ctx, cc, ss)),
                      qd_mul(ctx, half, qd_sub(ctx, sc, cs))))
            return false;
    }
    return true;
}

static bool has_vars(const qd_expr *e, size_t n, const qd_expr *const *x) {
    for (size_t i = 0; i < n; i++)
        if (qd_has(e, x[i]))
            return true;
    return false;
}

/* cos(u) or sin(u) with u = k.x + c linear: its harmonic (k.x, C, S). */
static bool harmonic(qd_ctx *ctx, const qd_expr *fac, size_t n, const qd_expr *const *x,
                     fs_term *h) {
    if (qd_expr_kind(fac) != QD_FUNC ||
        (qd_expr_func(fac) != QD_SIN && qd_expr_func(fac) != QD_COS))
        return false;
    const qd_expr *u = qd_expr_arg(fac, 0);
    const qd_expr **zero = qd__calloc(ctx, n, sizeof *zero);
    if (!zero)
        return false;
    for (size_t i = 0; i < n; i++)
        zero[i] = qd_int(ctx, 0);
    const qd_expr *c = qd_simplify(ctx, qd_subs(ctx, u, n, x, zero));
    qd__free(zero);
    const qd_expr *lin = qd_expand(ctx, qd_sub(ctx, u, c));
    for (size_t i = 0; i < n; i++)
        if (has_vars(qd_diff(ctx, lin, x[i]), n, x))
            return false; /* not linear in the variables */
    bool cosine = qd_expr_func(fac) == QD_COS;
    const qd_expr *cc = qd_fn(ctx, QD_COS, c), *sc = qd_fn(ctx, QD_SIN, c);
    /* cos(a + c) = cos c cos a - sin c sin a; sin(a + c) = sin c cos a + cos c sin a */
    *h = (fs_term){lin, cosine ? cc : sc, cosine ? qd_neg(ctx, sc) : cc};
    return true;
}

/* One product of the expanded f into L (added to it). */
static bool product(qd_ctx *ctx, const qd_expr *p, size_t n, const qd_expr *const *x,
                    fs_list *L, fs_list *w1, fs_list *w2) {
    size_t nf = qd_expr_kind(p) == QD_MUL ? qd_expr_nargs(p) : 1;
    w1->n = 1;
    w1->t[0] = (fs_term){qd_int(ctx, 0), qd_int(ctx, 1), qd_int(ctx, 0)};
    for (size_t i = 0; i < nf; i++) {
        const qd_expr *fac = qd_expr_kind(p) == QD_MUL ? qd_expr_arg(p, i) : p;
        if (!has_vars(fac, n, x)) {
            for (size_t k = 0; k < w1->n; k++) {
                w1->t[k].c = qd_mul(ctx, w1->t[k].c, fac);
                w1->t[k].s = qd_mul(ctx, w1->t[k].s, fac);
            }
            continue;
        }
        long e = 1, den = 1;
        const qd_expr *base = fac;
        if (qd_expr_kind(fac) == QD_POW &&
            (!qd_rational_get(qd_expr_arg(fac, 1), &e, &den) || den != 1 || e < 1 || e > 64))
            e = 0;
        else if (qd_expr_kind(fac) == QD_POW)
            base = qd_expr_arg(fac, 0);
        fs_term h;
        if (e == 0 || !harmonic(ctx, base, n, x, &h)) {
            if (qd_ctx_status(ctx) == QD_OK)
                qd_ctx_error(ctx, QD_ERR_ARG, "not a trigonometric polynomial in the variables: "
                             "a factor is not a constant, or a power of cos or sin of a linear "
                             "combination of them (a series of another function is not computed)");
            return false;
        }
        for (long k = 0; k < e; k++) {
            if (!times(ctx, w1, &h, w2))
                return false;
            w1->n = w2->n;
            memcpy(w1->t, w2->t, w2->n * sizeof *w2->t);
        }
    }
    for (size_t k = 0; k < w1->n; k++)
        if (!add_term(ctx, L, w1->t[k].arg, w1->t[k].c, w1->t[k].s))
            return false;
    return true;
}

static qd_fourier *collect(qd_ctx *ctx, const fs_list *L, size_t n, const qd_expr *const *x) {
    qd_fourier *f = qd__calloc(ctx, 1, sizeof *f);
    qd_fourier_term *t = f ? qd__calloc(ctx, L->n + 1, sizeof *t) : NULL;
    const qd_expr **k = t ? qd__calloc(ctx, (L->n + 1) * n, sizeof *k) : NULL;
    if (!k) {
        qd__free(t);
        qd__free(f);
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory writing a Fourier series");
        return NULL;
    }
    *f = (qd_fourier){.n = n, .terms = t, .k = k};
    for (size_t i = 0; i < L->n; i++) {
        const qd_expr *c = tidy(ctx, L->t[i].c), *s = tidy(ctx, L->t[i].s);
        if (!c || !s)
            break;
        if (qd_is_zero(c) && qd_is_zero(s))
            continue;
        qd_fourier_term *u = &t[f->nterms];
        *u = (qd_fourier_term){.arg = L->t[i].arg, .a = c, .b = s, .k = k + f->nterms * n};
        for (size_t j = 0; j < n; j++)
            k[f->nterms * n + j] = qd_simplify(ctx, qd_diff(ctx, u->arg, x[j]));
        f->nterms++;
    }
    return f;
}

/* The sum of the harmonics must be f. */
static bool verified(qd_ctx *ctx, qd_fourier *f, const qd_expr *fx) {
    const qd_expr *s = qd_int(ctx, 0);
    for (size_t i = 0; i < f->nterms; i++) {
        const qd_fourier_term *t = &f->terms[i];
        s = qd_add(ctx, s, qd_add(ctx, qd_mul(ctx, t->a, qd_fn(ctx, QD_COS, t->arg)),
                                  qd_mul(ctx, t->b, qd_fn(ctx, QD_SIN, t->arg))));
    }
    qd_zero_result z;
    if (qd_equal_test(ctx, s, fx, &z) != QD_OK)
        return false;
    f->check = z.kind;
    if (z.kind == QD_ZERO_PROVEN || z.kind == QD_ZERO_NUMERIC)
        return true;
    qd_ctx_error(ctx, QD_ERR_NUMERIC, "the harmonics do not sum back to f (a bug in the series)");
    return false;
}

qd_fourier *qd_fourier_series(qd_ctx *ctx, const qd_expr *f, size_t n, const qd_expr *const *x) {
    QD_ARGS(NULL, ctx && f && x);
    for (size_t i = 0; i < n; i++)
        if (!x[i] || qd_expr_kind(x[i]) != QD_SYMBOL) {
            qd_ctx_error(ctx, QD_ERR_ARG, "Fourier series: variable %zu is not a symbol", i + 1);
            return NULL;
        }
    fs_list *L = qd__calloc(ctx, 3, sizeof *L);
    if (!L) {
        qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory writing a Fourier series");
        return NULL;
    }
    for (size_t i = 0; i < 3; i++) {
        L[i].vars.n = n;
        L[i].vars.x = x;
    }
    const qd_expr *e = qd_expand(ctx, f);
    size_t np = e && qd_expr_kind(e) == QD_ADD ? qd_expr_nargs(e) : 1;
    bool ok = e != NULL;
    for (size_t i = 0; ok && i < np; i++)
        ok = product(ctx, qd_expr_kind(e) == QD_ADD ? qd_expr_arg(e, i) : e, n, x, L, L + 1,
                     L + 2);
    qd_fourier *out = ok ? collect(ctx, L, n, x) : NULL;
    qd__free(L);
    if (out && !verified(ctx, out, f)) {
        qd_fourier_free(out);
        return NULL;
    }
    return out;
}
