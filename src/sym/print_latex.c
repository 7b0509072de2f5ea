/*
 * src/sym/print_latex.c - expressions as LaTeX math (no surrounding $).
 *
 * Quotients are \frac{}{}, powers x^{2}, square roots \sqrt{}, calls
 * \sin{\left(x \right)} (SymPy's spelling, which MathJax and KaTeX render).
 * Names: a Greek letter name becomes its command (phi -> \phi); trailing
 * digits or the part after the first '_' become a subscript (theta1 ->
 * \theta_{1}, m_arm -> m_{\mathrm{arm}}); other names of several letters are
 * set upright (\mathrm{mass}).  Jet symbols put the dots on the letter:
 * theta1' -> \dot{\theta}_{1}, '' -> \ddot, ''' -> \dddot, '''' -> \ddddot,
 * higher orders \theta^{(5)}_{1}; with t renamed (qd_print_set_time_name)
 * primes instead: y', \theta_{1}''.  A derivative of a user function prints
 * V'(r) as V'{\left(r \right)} for one argument, else as
 * \partial_{1}\partial_{2} V{\left(x, y \right)}.
 */
#include "prec.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *const greek[] = {
    "alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta",
    "vartheta", "iota", "kappa", "lambda", "mu", "nu", "xi", "pi", "varpi", "rho", "sigma",
    "tau", "upsilon", "phi", "varphi", "chi", "psi", "omega", "Gamma", "Delta", "Theta",
    "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi", "Omega"};

typedef struct lp {
    qd_ctx *ctx;
    qd_buf *b;
} lp;

static void expr(lp *p, const qd_expr *e);

static bool is_greek(const char *s, size_t n) {
    for (size_t i = 0; i < sizeof greek / sizeof greek[0]; i++)
        if (strlen(greek[i]) == n && !strncmp(s, greek[i], n))
            return true;
    return false;
}

/* One word of a name: a Greek command, a single letter, or \mathrm{word}. */
static void word(lp *p, const char *s, size_t n) {
    if (is_greek(s, n)) {
        qd_buf_puts(p->b, "\\");
        qd_buf_putn(p->b, s, n);
    } else if (n == 1 || strspn(s, "0123456789") >= n) {
        qd_buf_putn(p->b, s, n);
    } else {
        qd_buf_puts(p->b, "\\mathrm{");
        for (size_t i = 0; i < n; i++)
            qd_buf_puts(p->b, s[i] == '_' ? "\\_" : (char[2]){s[i], 0});
        qd_buf_puts(p->b, "}");
    }
}

/* name -> base and subscript; order > 0 puts dots on the base, or primes
 * after it when t is renamed (the derivatives are then not in time). */
static void name(lp *p, const char *s, unsigned order) {
    static const char *const dots[] = {"", "\\dot{", "\\ddot{", "\\dddot{", "\\ddddot{"};
    if (order && p->ctx->sym->tname) {
        name(p, s, 0);
        if (order <= 4)
            qd_buf_putn(p->b, "''''", order);
        else
            qd_buf_printf(p->b, "^{(%u)}", order);
        return;
    }
    size_t n = strcspn(s, "'"), cut = strcspn(s, "_"), sub = n;
    if (cut < n) {
        sub = cut + 1;
    } else {
        cut = n;
        while (cut > 1 && s[cut - 1] >= '0' && s[cut - 1] <= '9')
            cut--;
        sub = cut;
    }
    qd_buf_puts(p->b, order <= 4 ? dots[order] : "");
    word(p, s, cut);
    qd_buf_puts(p->b, order && order <= 4 ? "}" : "");
    if (order > 4)
        qd_buf_printf(p->b, "^{(%u)}", order);
    if (sub < n) {
        qd_buf_puts(p->b, "_{");
        word(p, s + sub, n - sub);
        qd_buf_puts(p->b, "}");
    }
}

static void operand(lp *p, const qd_expr *e, int need) {
    bool paren = qd__prec(e) < need;
    qd_buf_puts(p->b, paren ? "\\left(" : "");
    expr(p, e);
    qd_buf_puts(p->b, paren ? "\\right)" : "");
}

static void magnitude_number(lp *p, const qd_expr *e) {
    if (e->kind == QD_FLOAT) {
        qd_buf tmp = QD_BUF_WITH(p->b->alloc);
        qd__put_double(&tmp, fabs(e->u.f));
        const char *s = qd_buf_str(&tmp), *x = strchr(s, 'e');
        qd_buf_putn(p->b, s, x ? (size_t)(x - s) : strlen(s));
        if (x)
            qd_buf_printf(p->b, " \\cdot 10^{%d}", (int)strtol(x + 1, NULL, 10));
        p->b->failed |= tmp.failed;
        qd_buf_free(&tmp);
    } else if (mpz_cmp_ui(mpq_denref(e->u.q), 1) != 0) {
        qd_buf_puts(p->b, "\\frac{");
        qd__put_mpz(p->b, mpq_numref(e->u.q));
        qd_buf_puts(p->b, "}{");
        qd__put_mpz(p->b, mpq_denref(e->u.q));
        qd_buf_puts(p->b, "}");
    } else {
        qd__put_mpz(p->b, mpq_numref(e->u.q));
    }
}

static void number(lp *p, const qd_expr *e) {
    qd_buf_puts(p->b, qd_number_sign(e) < 0 ? "-" : "");
    magnitude_number(p, e);
}

/* Does f print starting with a digit (so juxtaposition needs \cdot)? */
static bool leads_with_digit(const qd_expr *f) {
    while (f->kind == QD_POW && !qd__is_rat(f->args[1], 1, 2))
        f = f->args[0];
    return qd__is_num(f) && qd_number_sign(f) > 0;
}

/* Factors side by side: a space, or \cdot before a digit.  flip prints the
 * denominator factors b^e (e < 0) as b^-e. */
static void factors(lp *p, size_t n, const qd_expr *const *f, bool flip, bool lead) {
    for (size_t i = 0; i < n; i++) {
        if (i || lead)
            qd_buf_puts(p->b, leads_with_digit(f[i]) ? " \\cdot " : " ");
        if (flip && qd__is_rat(f[i]->args[1], -1, 1)) {
            operand(p, f[i]->args[0], QD_PREC_POW);
        } else if (flip && qd__is_rat(f[i]->args[1], -1, 2)) {
            qd_buf_puts(p->b, "\\sqrt{");
            expr(p, f[i]->args[0]);
            qd_buf_puts(p->b, "}");
        } else if (flip) {
            operand(p, f[i]->args[0], QD_PREC_ATOM);
            qd_buf_puts(p->b, "^{");
            magnitude_number(p, f[i]->args[1]);
            qd_buf_puts(p->b, "}");
        } else {
            operand(p, f[i], QD_PREC_POW);
        }
    }
}

static void product(lp *p, const qd_expr *e, bool sign) {
    qd__product_split s;
    if (!qd__split(p->ctx, e, &s)) {
        p->b->failed = true;
        return;
    }
    bool q = s.coeff && s.coeff->kind == QD_RATIONAL &&
             mpz_cmp_ui(mpq_denref(s.coeff->u.q), 1) != 0;
    bool unit = s.coeff && s.coeff->kind == QD_RATIONAL &&
                mpz_cmpabs_ui(mpq_numref(s.coeff->u.q), 1) == 0;
    bool lead = s.coeff && !(unit && s.nnum);
    qd_buf_puts(p->b, s.neg && sign ? "- " : "");
    bool frac = q || s.nden;
    qd_buf_puts(p->b, frac ? "\\frac{" : "");
    if (lead && s.coeff->kind == QD_FLOAT)
        magnitude_number(p, s.coeff);
    else if (lead)
        qd__put_mpz(p->b, mpq_numref(s.coeff->u.q));
    factors(p, s.nnum, s.num, false, lead);
    qd_buf_puts(p->b, !lead && !s.nnum ? "1" : "");
    if (frac) {
        qd_buf_puts(p->b, "}{");
        if (q)
            qd__put_mpz(p->b, mpq_denref(s.coeff->u.q));
        factors(p, s.nden, s.den, true, q);
        qd_buf_puts(p->b, "}");
    }
    qd__split_free(&s);
}

static void sum(lp *p, const qd_expr *e) {
    size_t c = qd__is_num(e->args[0]) ? 1 : 0;
    for (size_t k = c; k < e->nargs + c; k++) {
        const qd_expr *t = e->args[k < e->nargs ? k : 0];
        bool minus = qd__has_minus(t);
        qd_buf_puts(p->b, k == c ? (minus ? "- " : "") : (minus ? " - " : " + "));
        if (qd__is_num(t))
            magnitude_number(p, t);
        else if (t->kind == QD_MUL)
            product(p, t, false);
        else
            expr(p, t);
    }
}

static void power(lp *p, const qd_expr *e) {
    if (qd__is_recip(e)) {
        product(p, e, true);
    } else if (qd__is_rat(e->args[1], 1, 2)) {
        qd_buf_puts(p->b, "\\sqrt{");
        expr(p, e->args[0]);
        qd_buf_puts(p->b, "}");
    } else {
        operand(p, e->args[0], QD_PREC_ATOM);
        qd_buf_puts(p->b, "^{");
        expr(p, e->args[1]);
        qd_buf_puts(p->b, "}");
    }
}

static void args(lp *p, const qd_expr *e) {
    qd_buf_puts(p->b, "{\\left(");
    for (size_t i = 0; i < e->nargs; i++) {
        qd_buf_puts(p->b, i ? ", " : "");
        expr(p, e->args[i]);
    }
    qd_buf_puts(p->b, " \\right)}");
}

static void func(lp *p, const qd_expr *e) {
    static const char *const fn[QD_FUNC_COUNT] = {
        "\\sin", "\\cos", "\\tan", "\\arcsin", "\\arccos", "\\arctan",
        "\\operatorname{atan_{2}}", "\\sinh", "\\cosh", "\\tanh", "\\exp", "\\log",
        NULL, "\\operatorname{sign}", "\\theta"};
    if (e->tag == QD_ABS) {
        qd_buf_puts(p->b, "\\left|");
        expr(p, e->args[0]);
        qd_buf_puts(p->b, "\\right|");
        return;
    }
    qd_buf_puts(p->b, fn[e->tag]);
    args(p, e);
}

static void uderiv(lp *p, const qd_expr *e) {
    if (e->nargs == 1) {
        name(p, e->u.fn.name, 0);
        for (uint32_t i = 0; i < e->u.fn.nslots; i++)
            qd_buf_puts(p->b, "'");
    } else {
        for (uint32_t i = 0; i < e->u.fn.nslots; i++)
            qd_buf_printf(p->b, "\\partial_{%u} ", e->u.fn.slots[i] + 1);
        name(p, e->u.fn.name, 0);
    }
    args(p, e);
}

static void expr(lp *p, const qd_expr *e) {
    switch ((qd_kind)e->kind) {
    case QD_RATIONAL:
    case QD_FLOAT: number(p, e); break;
    case QD_CONSTANT: qd_buf_puts(p->b, e->tag == QD_PI ? "\\pi" : "e"); break;
    case QD_SYMBOL:
        name(p, e->tag == QD_ROLE_TIME ? qd_print_time_name(p->ctx) : e->u.sym.name, e->order);
        break;
    case QD_FUNC: func(p, e); break;
    case QD_UFUNC:
        name(p, e->u.fn.name, 0);
        args(p, e);
        break;
    case QD_UDERIV: uderiv(p, e); break;
    case QD_POW: power(p, e); break;
    case QD_MUL: product(p, e, true); break;
    case QD_ADD: sum(p, e); break;
    }
}

qd_status qd__print_latex(qd_ctx *ctx, const qd_expr *e, qd_buf *out) {
    lp p = {ctx, out};
    expr(&p, e);
    return out->failed ? QD_ERR_NOMEM : QD_OK;
}
