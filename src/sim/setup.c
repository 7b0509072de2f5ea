/*
 * src/sim/setup.c - a simulation set up from a model (qdot/simsetup.h):
 * which equations, the initial state and its policy (a model's speeds
 * give way to velocities given; momenta not given are 0), the method's
 * defaults and the checks made before a run writes anything, and the
 * native right-hand side's fallback.  The command line and Python both
 * come here, so a run is the same run from either.
 */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../base/args.h"
#include "qdot/state.h" /* qd_state_item_end: the one item splitter */
#include "setup.h"

qd_sim_form qd_sim_form_of(const qd_model *m, bool no_speeds) {
    QD_ARGS(QD_SIM_FORM_LAGRANGE, m);
    if (qd_model_hamiltonian_given(m))
        return QD_SIM_FORM_HAMILTON;
    return qd_model_nspeeds(m) && !no_speeds ? QD_SIM_FORM_SPEEDS : QD_SIM_FORM_LAGRANGE;
}

static bool nomem(qd_ctx *ctx) {
    qd_ctx_error(ctx, QD_ERR_NOMEM, "out of memory");
    return false;
}

/* q, q', t, the parameters at their values, then the momenta (H) or the
 * speeds (NaN until given). */
static bool state_init(qd_sim_setup *s) {
    const qd_model *m = s->m;
    size_t nq = qd_model_ncoords(m), np = qd_model_nparams(m);
    s->extra = s->form == QD_SIM_FORM_HAMILTON ? nq : qd_model_nspeeds(m);
    s->nq = nq;
    s->n = 2 * nq + 1 + np + s->extra;
    s->syms = calloc(s->n + 1, sizeof *s->syms);
    s->vals = calloc(s->n + 1, sizeof *s->vals);
    if (!s->syms || !s->vals)
        return nomem(s->ctx);
    for (size_t i = 0; i < nq; i++) {
        s->syms[i] = qd_model_coord(m, i);
        s->syms[nq + i] = qd_jet(s->ctx, qd_model_coord(m, i), 1);
    }
    s->syms[2 * nq] = qd_time(s->ctx);
    for (size_t i = 0; i < np; i++) {
        s->syms[2 * nq + 1 + i] = qd_model_param(m, i);
        if (qd_model_param_number(m, i, &s->vals[2 * nq + 1 + i]) != QD_OK) {
            if (qd_ctx_status(s->ctx) == QD_OK)
                qd_ctx_error(s->ctx, QD_ERR_ARG, "parameter %s has no finite value",
                             qd_expr_name(qd_model_param(m, i)));
            return false;
        }
    }
    size_t at = s->n - s->extra;
    for (size_t j = 0; j < s->extra; j++) {
        s->syms[at + j] = s->form == QD_SIM_FORM_HAMILTON ? qd_model_momentum(m, j)
                                                          : qd_model_speed(m, j);
        s->vals[at + j] = NAN;
    }
    for (size_t i = 0; i < nq; i++)
        for (unsigned o = 0; o < 2; o++) {
            const qd_expr *v = qd_model_initial(m, i, o);
            if (v && qd_eval(s->ctx, v, s->n, s->syms, s->vals, &s->vals[o * nq + i]) != QD_OK)
                return false;
        }
    /* a model's speeds given by `initial`, before any given from outside */
    for (size_t r = 0; s->form != QD_SIM_FORM_HAMILTON && r < s->extra; r++) {
        const qd_expr *v = qd_model_speed_initial(m, r);
        if (v && qd_eval(s->ctx, v, s->n, s->syms, s->vals, &s->vals[at + r]) != QD_OK)
            return false;
    }
    return true;
}

qd_sim_setup *qd_sim_setup_new(qd_ctx *ctx, const qd_model *m, bool no_speeds) {
    QD_ARGS(NULL, ctx);
    if (!m) {
        qd_ctx_error(ctx, QD_ERR_ARG, "qd_sim_setup_new: a NULL argument");
        return NULL;
    }
    qd_sim_setup *s = calloc(1, sizeof *s);
    if (!s) {
        nomem(ctx);
        return NULL;
    }
    s->period = NAN;
    s->ctx = ctx;
    s->m = m;
    s->form = qd_sim_form_of(m, no_speeds);
    if (s->form == QD_SIM_FORM_HAMILTON) {
        s->sim = qd_sim_new_hamilton(ctx, m); /* no Lagrangian needed */
    } else if (s->form == QD_SIM_FORM_SPEEDS) {
        s->se = qd_speeds_derive(ctx, m, NULL); /* no multipliers to solve for */
        s->sim = s->se ? qd_sim_new_speeds(ctx, m, s->se) : NULL;
    } else {
        s->e = qd_eom_derive(ctx, m);
        s->sim = s->e ? qd_sim_new(ctx, m, s->e) : NULL;
    }
    bool ok = s->sim && state_init(s);
    if (ok && (!(s->given = calloc(s->n + 1, sizeof *s->given)) ||
               !(s->qd0_given = calloc(s->nq + 1, sizeof *s->qd0_given))))
        ok = nomem(ctx);
    if (ok && !(s->vals0 = malloc((s->n + 1) * sizeof *s->vals0)))
        ok = nomem(ctx);
    if (ok) /* the model's own initial state, for qd_sim_setup_restart */
        memcpy(s->vals0, s->vals, s->n * sizeof *s->vals);
    for (size_t i = 0; ok && i < qd_model_noutputs(m); i++) /* before any caller's */
        ok = qd_sim_add_output(s->sim, qd_model_output_name(m, i), qd_model_output(m, i)) ==
             QD_OK;
    if (!ok) {
        qd_sim_setup_free(s);
        return NULL;
    }
    return s;
}

void qd_sim_setup_free(qd_sim_setup *s) {
    if (!s)
        return;
    if (s->native)
        qd_native_unload(s->native);
    free(s->native);
    free(s->input_given);
    free(s->given);
    free(s->qd0_given);
    free(s->q0);
    free(s->p0);
    free(s->u0);
    qd_sim_free(s->sim);
    if (s->se)
        qd_speeds_eom_free(s->se);
    if (s->e)
        qd_eom_free(s->e);
    free(s->syms);
    free(s->vals);
    free(s->vals0);
    free(s);
}

qd_sim *qd_sim_setup_sim(const qd_sim_setup *s) {
    QD_ARGS(NULL, s);
    return s->sim;
}

qd_sim_form qd_sim_setup_form(const qd_sim_setup *s) {
    QD_ARGS(QD_SIM_FORM_LAGRANGE, s);
    return s->form;
}

const qd_eom *qd_sim_setup_eom(const qd_sim_setup *s) {
    QD_ARGS(NULL, s);
    return s->e;
}

const qd_speeds_eom *qd_sim_setup_speeds_eom(const qd_sim_setup *s) {
    QD_ARGS(NULL, s);
    return s->se;
}

size_t qd_sim_setup_ncon(const qd_sim_setup *s) {
    QD_ARGS(0, s);
    return s->se ? s->se->ncon : s->e ? s->e->ncon : 0;
}

const qd_con *qd_sim_setup_con(const qd_sim_setup *s, size_t k) {
    QD_ARGS(NULL, s);
    if (k >= qd_sim_setup_ncon(s))
        return NULL;
    return s->se ? &s->se->con[k] : &s->e->con[k];
}

size_t qd_sim_setup_state(const qd_sim_setup *s, const qd_expr *const **syms,
                          const double **vals) {
    QD_ARGS(0, s);
    if (syms)
        *syms = s->syms;
    if (vals)
        *vals = s->vals;
    return s->n;
}

/* ---- the initial state ------------------------------------------------------ */

/* The slot of name[0, len) in the state, or s->n with the error recorded. */
static size_t slot_of(qd_sim_setup *s, const char *text, size_t at, size_t len) {
    const char *x = qd_model_independent(s->m);
    char name[128];
    snprintf(name, sizeof name, "%.*s", (int)len, text + at);
    if (x && !strcmp(name, x))
        snprintf(name, sizeof name, "t"); /* `independent x`: x is t */
    len = strlen(name);
    size_t primes = 0;
    while (primes < len && name[len - 1 - primes] == '\'')
        primes++;
    for (size_t i = 0; i < s->n; i++) {
        bool velocity = i >= s->nq && i < 2 * s->nq;
        const char *nm = qd_expr_name(s->syms[velocity ? i - s->nq : i]);
        size_t k = strlen(nm);
        if (k + (velocity ? 1 : 0) == len && !strncmp(nm, name, k) &&
            primes == (velocity ? 1u : 0u))
            return i;
        if (i < s->nq && primes > 1 && k + primes == len && !strncmp(nm, name, k)) {
            qd_ctx_error(s->ctx, QD_ERR_ARG, "'%s' is an acceleration: qdot computes it; give "
                                             "%s and %s'", name, nm, nm);
            qd_ctx_error_at(s->ctx, text, at, len);
            return s->n;
        }
    }
    /* "did you mean": q, q', t, the parameters, momenta, speeds */
    size_t k = 0;
    const char **names = malloc((s->n + 1) * sizeof *names);
    char (*primed)[130] = malloc((s->nq + 1) * sizeof *primed);
    const char *near = NULL;
    if (names && primed) {
        for (size_t i = 0; i < s->n; i++) {
            if (i >= s->nq && i < 2 * s->nq) {
                snprintf(primed[i - s->nq], sizeof primed[0], "%s'",
                         qd_expr_name(s->syms[i - s->nq]));
                names[k++] = primed[i - s->nq];
            } else {
                names[k++] = i == 2 * s->nq && x ? x : qd_expr_name(s->syms[i]);
            }
        }
        near = qd_nearest_name(text + at, len, names, k);
    }
    char known[512];
    size_t used = 0;
    known[0] = '\0';
    for (size_t i = 0; i < s->nq && used < sizeof known; i++)
        used += (size_t)snprintf(known + used, sizeof known - used, "%s%s", i ? ", " : "",
                                 qd_expr_name(s->syms[i]));
    for (size_t r = 0; r < s->extra && used < sizeof known; r++)
        used += (size_t)snprintf(known + used, sizeof known - used, "%s%s",
                                 r                                ? ", "
                                 : s->form == QD_SIM_FORM_HAMILTON ? "; the momenta are "
                                                                   : "; the speeds are ",
                                 qd_expr_name(s->syms[s->n - s->extra + r]));
    qd_ctx_error(s->ctx, QD_ERR_ARG, "unknown name '%.*s' (the coordinates are %s; velocities "
                                     "are written with a prime, and %s is the %s)", (int)len,
                 text + at, known, x ? x : "t", x ? "independent variable" : "time");
    char hint[200];
    snprintf(hint, sizeof hint, "did you mean '%s'?", near ? near : "");
    qd_ctx_error_about(s->ctx, QD_SUBJECT_TEXT, 0, NULL, QD_REASON_NONE, near ? hint : NULL);
    qd_ctx_error_at(s->ctx, text, at, len);
    free(names);
    free(primed);
    return s->n;
}

/* The value text[a, b): a constant expression in the parameters, its error
 * located in text. */
static bool value_of(qd_sim_setup *s, const char *text, size_t a, size_t b, double *out) {
    char *v = malloc(b - a + 1);
    if (!v)
        return nomem(s->ctx);
    memcpy(v, text + a, b - a);
    v[b - a] = '\0';
    char *end;
    double x = strtod(v, &end);
    while (*end && isspace((unsigned char)*end))
        end++;
    qd_status st = QD_OK;
    if (end != v && !*end && !isfinite(x))
        *out = x; /* "nan", "inf": the run says the initial state is not finite */
    else
        st = qd_model_number(s->ctx, s->m, v, out);
    free(v);
    if (st == QD_OK)
        return true;
    /* located in the value alone: at its place in text instead */
    qd_diag *d = (qd_diag *)qd_ctx_diag(s->ctx);
    if (d->located) {
        size_t off = a + d->offset, len = d->length;
        d->located = false;
        qd_ctx_error_at(s->ctx, text, off, len);
    }
    return false;
}


static qd_status bad_item(qd_sim_setup *s, const char *text, size_t a, size_t b, const char *why) {
    qd_ctx_error(s->ctx, QD_ERR_ARG, "%s", why);
    qd_ctx_error_at(s->ctx, text, a, b > a ? b - a : 1);
    return QD_ERR_ARG;
}

qd_status qd_sim_setup_initial(qd_sim_setup *s, const char *text) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, text);
    if (s->initial_given)
        return bad_item(s, text, 0, strlen(text), "the initial state is given twice; name every "
                                                  "value in one list");
    double *g = malloc((s->n + 1) * sizeof *g);
    bool *given = calloc(s->n + 1, sizeof *given); /* (a value may be NaN: refused by the run) */
    if (!g || !given) {
        free(g);
        free(given);
        return nomem(s->ctx), QD_ERR_NOMEM;
    }
    qd_status st = QD_OK;
    for (size_t p = 0; text[p] && st == QD_OK;) {
        size_t end = qd_state_item_end(text, p), na = p;
        while (na < end && isspace((unsigned char)text[na]))
            na++;
        const char *eq = memchr(text + na, '=', end - na);
        size_t nb = eq ? (size_t)(eq - text) : end;
        while (nb > na && isspace((unsigned char)text[nb - 1]))
            nb--;
        if (na == end) {
            /* an empty item ("a=1,") */
        } else if (!eq || na == nb || nb - na >= 128) {
            st = bad_item(s, text, na, end, "expected NAME=VALUE");
        } else {
            size_t i = slot_of(s, text, na, nb - na);
            if (i == s->n)
                st = QD_ERR_ARG;
            else if (i > 2 * s->nq && i < s->n - s->extra) /* the run's parameters are fixed */
                st = QD_ERR_ARG, qd_ctx_error(s->ctx, st, "'%.*s' is a parameter, not part of "
                                              "the state: its value is given by --set %.*s=VALUE",
                                              (int)(nb - na), text + na, (int)(nb - na),
                                              text + na),
                qd_ctx_error_at(s->ctx, text, na, nb - na);
            else if (given[i])
                st = QD_ERR_ARG, qd_ctx_error(s->ctx, st, "'%.*s' is given twice",
                                              (int)(nb - na), text + na),
                qd_ctx_error_at(s->ctx, text, na, nb - na);
            else if (!value_of(s, text, (size_t)(eq + 1 - text), end, &g[i]))
                st = qd_ctx_status(s->ctx);
            else
                given[i] = true;
        }
        p = text[end] ? end + 1 : end;
    }
    /* velocities given: the model's initial speeds not given follow them */
    bool motion = false;
    for (size_t i = s->nq; i < 2 * s->nq; i++)
        motion = motion || given[i];
    size_t at = s->n - s->extra;
    for (size_t i = 0; st == QD_OK && i < s->n; i++)
        s->given[i] = given[i];
    for (size_t i = 0; st == QD_OK && i < s->n; i++)
        if (given[i])
            s->vals[i] = g[i];
        else if (motion && s->form != QD_SIM_FORM_HAMILTON && i >= at)
            s->vals[i] = NAN;
    free(g);
    free(given);
    s->initial_given = st == QD_OK;
    return st;
}

/* Lagrange's form with speeds given (no_speeds): the velocities they stand
 * for, by the kinematics q' = W u + w (which also keep the constraints). */
static qd_status velocities_from_speeds(qd_sim_setup *s) {
    qd_speeds_eom *se = qd_speeds_derive(s->ctx, s->m, NULL);
    if (!se)
        return qd_ctx_status(s->ctx);
    size_t n = se->n;
    double *qd = malloc((n + 1) * sizeof *qd);
    qd_status st = qd ? qd_speeds_eval(s->ctx, se, s->n, s->syms, s->vals, qd, NULL, NULL)
                      : (nomem(s->ctx), QD_ERR_NOMEM);
    for (size_t j = 0; st == QD_OK && j < n; j++)
        for (size_t i = 0; i < n; i++)
            if (se->q[i] == s->e->q[j])
                s->qd0[j] = qd[i];
    free(qd);
    qd_speeds_eom_free(se);
    free(s->u0); /* the multiplier form takes velocities */
    s->u0 = NULL;
    return st;
}

/* The run's initial values: q0 and qd0 in the equations' order; momenta
 * (H) when any is given, the others 0; speeds when any is given, the
 * others from their definitions at the initial velocities. */
static qd_status initial_values(qd_sim_setup *s) {
    size_t n = s->nq, at = s->n - s->extra;
    free(s->q0);
    free(s->p0);
    free(s->u0);
    s->p0 = s->u0 = NULL;
    s->q0 = malloc((2 * n + 1) * sizeof *s->q0);
    if (!s->q0)
        return nomem(s->ctx), QD_ERR_NOMEM;
    s->qd0 = s->q0 + n;
    for (size_t j = 0; j < n; j++) {
        size_t i = s->e ? 0 : j;
        while (s->e && i < n && qd_model_coord(s->m, i) != s->e->q[j])
            i++;
        s->q0[j] = s->vals[i];
        s->qd0[j] = s->vals[n + i];
        s->qd0_given[j] = s->given[n + i];
    }
    bool any = false;
    for (size_t r = 0; r < s->extra; r++)
        any = any || !isnan(s->vals[at + r]);
    if (!any)
        return QD_OK; /* the library finds them from the velocities */
    double *x = malloc((s->extra + 1) * sizeof *x);
    if (!x)
        return nomem(s->ctx), QD_ERR_NOMEM;
    for (size_t r = 0; r < s->extra; r++) {
        x[r] = s->vals[at + r];
        if (isnan(x[r]) && s->form == QD_SIM_FORM_HAMILTON)
            x[r] = 0;
        else if (isnan(x[r]) && qd_eval(s->ctx, qd_model_speed_definition(s->m, r), at, s->syms,
                                        s->vals, &x[r]) != QD_OK) {
            free(x);
            return qd_ctx_status(s->ctx);
        }
    }
    if (s->form == QD_SIM_FORM_HAMILTON) {
        s->p0 = x;
        return QD_OK;
    }
    for (size_t r = 0; r < s->extra; r++)
        s->vals[at + r] = x[r];
    s->u0 = x;
    return s->e ? velocities_from_speeds(s) : QD_OK;
}

/* ---- the options -------------------------------------------------------------- */

/* What each field is, in the messages (the caller adds its own name of it). */
static const char *noun(const char *field) {
    static const char *const f[][2] = {
        {"t_end", "the end time"},      {"dt", "the output spacing"},
        {"every", "the output spacing"}, {"step", "the step"},
        {"rtol", "the relative tolerance"},
        {"atol", "the absolute tolerance"}, {"max_steps", "the most steps"},
    };
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++)
        if (!strcmp(f[i][0], field))
            return f[i][1];
    return field;
}

/* An option's error: its field's name, so each caller names it its way. */
static qd_status refuse(qd_sim_setup *s, const char *field, const char *fmt, ...)
#ifdef __GNUC__
    __attribute__((format(printf, 3, 4)))
#endif
    ;
static qd_status refuse(qd_sim_setup *s, const char *field, const char *fmt, ...) {
    char msg[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    qd_ctx_error(s->ctx, QD_ERR_ARG, "%s", msg);
    qd_ctx_error_about(s->ctx, QD_SUBJECT_NONE, 0, field, QD_REASON_NONE, NULL);
    return QD_ERR_ARG;
}

/* The number text of field (NULL: *out unchanged). */
static qd_status number(qd_sim_setup *s, const char *field, const char *text, bool positive,
                        double *out) {
    if (!text)
        return QD_OK;
    char *end;
    double x = strtod(text, &end);
    if (end != text && !*end && !isfinite(x)) {
        *out = x; /* "inf", "nan": qd_sim_check_opts says what the number must be */
        return QD_OK;
    }
    if (qd_model_number(s->ctx, s->m, text, out) != QD_OK) {
        qd_diag *d = (qd_diag *)qd_ctx_diag(s->ctx);
        if (d->subject == QD_SUBJECT_TEXT || d->subject == QD_SUBJECT_NONE)
            snprintf(d->name, sizeof d->name, "%s", field); /* the text is this field's */
        return qd_ctx_status(s->ctx);
    }
    if (positive && !(*out > 0))
        return refuse(s, field, "%s must be a positive number, not '%s'", noun(field), text);
    return QD_OK;
}

/* t_end = t0 + T, T the period text (qd_sim_setup_period), its error
 * under the field's name. */
static qd_status period(qd_sim_setup *s, const char *text, qd_sim_opts *out) {
    qd_status st = qd_sim_setup_period(s, text, out, &s->period);
    if (st != QD_OK)
        snprintf(((qd_diag *)qd_ctx_diag(s->ctx))->name, sizeof(qd_diag){0}.name, "period");
    return st;
}

double qd_sim_setup_period_of(const qd_sim_setup *s) {
    QD_ARGS(NAN, s);
    return s->period;
}

/* The model's impacts at the initial state: a gap below 0 is bad input. */
static qd_status check_gaps(qd_sim_setup *s) {
    for (size_t i = 0; i < qd_model_nimpacts(s->m); i++) {
        double g = 0;
        if (qd_eval(s->ctx, qd_model_impact_gap(s->m, i), s->n, s->syms, s->vals, &g) != QD_OK)
            return qd_ctx_status(s->ctx);
        if (g < 0) {
            qd_ctx_error(s->ctx, QD_ERR_ARG, "impact '%s': the gap is negative at t0 (%.6g): the "
                         "bodies start interpenetrating", qd_model_impact_name(s->m, i), g);
            return QD_ERR_ARG;
        }
    }
    return QD_OK;
}

qd_status qd_sim_setup_options(qd_sim_setup *s, const qd_sim_setup_opts *o, qd_sim_opts *out) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, o && out);
    double t_end = NAN, dt = 0, rtol = 0, atol = 0, every = 0, step = 0, steps = 0;
    s->period = NAN;
    qd_status st = o->period && o->t_end ? refuse(s, "period", "give the period or the end "
                                                  "time, not both")
                   : o->period           ? QD_OK
                   : o->t_end            ? number(s, "t_end", o->t_end, false, &t_end)
                                         : refuse(s, "t_end", "the end time is missing");
    if (st == QD_OK)
        st = number(s, "dt", o->dt, true, &dt);
    if (st == QD_OK)
        st = number(s, "every", o->every, true, &every);
    if (st == QD_OK)
        st = number(s, "step", o->step, true, &step);
    if (st == QD_OK)
        st = number(s, "rtol", o->rtol, true, &rtol);
    if (st == QD_OK)
        st = number(s, "atol", o->atol, true, &atol);
    if (st == QD_OK)
        st = number(s, "max_steps", o->max_steps, true, &steps);
    if (st == QD_OK && steps != floor(steps))
        st = refuse(s, "max_steps", "the most steps must be a whole number, not '%s'",
                    o->max_steps);
    if (st != QD_OK)
        return st;
    *out = (qd_sim_opts){0};
    /* dt is the output spacing, step the step of a fixed-step method
     * (issue 33).  every is dt's older name; given with dt (and no step),
     * dt is the step, as it was then. */
    const char *step_text = o->step;
    if (!step_text && o->every && o->dt) {
        step_text = o->dt;
        step = dt;
    }
    const char *grid_text = o->every ? o->every : o->dt;
    double grid = o->every ? every : dt;
    if (o->step && o->every && o->dt && every != dt)
        return refuse(s, "every", "every (%g) is the older name of dt (%g): give one", every,
                      dt);
    if (step_text && o->rtol && !o->method) {
        qd_ctx_error(s->ctx, QD_ERR_ARG, "give step (a fixed step) or rtol (step control), or "
                                         "name a method");
        qd_ctx_error_about(s->ctx, QD_SUBJECT_NONE, 0, "step", QD_REASON_NONE, NULL);
        return QD_ERR_ARG;
    }
    if (o->method && !qd_sim_method_from_name(o->method, &out->method))
        return refuse(s, "method", "the method takes dopri5, dop853, gl2, gl4, gl6, verlet, yoshida4, "
                      "yoshida6, yoshida8, bdf or taylor, not '%s'", o->method);
    if (!o->method) /* a fixed-step default only when a step is given */
        out->method = qd_sim_default_method(s->sim, step_text != NULL);
    if (o->precision && o->precision != 64 && o->precision != 80 && o->precision != 128)
        return refuse(s, "precision", "the precision takes 64, 80 or 128 (bits), not %d",
                      o->precision);
    if (o->precision && o->precision != 64 && out->method != QD_SIM_TAYLOR)
        return refuse(s, "precision", "precision %d is for the taylor method (%s takes doubles)",
                      o->precision, qd_sim_method_name(out->method));
    bool adaptive = qd_sim_method_adaptive(out->method);
    bool fixed = !adaptive || (o->fixed && (step_text || grid_text));
    if (fixed && !step_text && !grid_text)
        return refuse(s, "step", "the method %s takes fixed steps: give the step (or the "
                      "output spacing dt, which is then the step)",
                      qd_sim_method_name(out->method));
    if (!fixed && o->step)
        return refuse(s, "step", "the step is for a fixed-step method (gl2, gl4, gl6, verlet, "
                      "yoshida*); %s controls its step by rtol (dt is the output spacing)", qd_sim_method_name(out->method));
    if (fixed) { /* the step: given, else the output spacing; rows at the spacing */
        out->dt = step_text ? step : grid;
        out->every = grid_text && out->dt != grid ? grid : 0;
        out->fixed = o->fixed && adaptive;
    } else {
        out->dt = grid; /* an adaptive method's output grid (0: a row at every step) */
    }
    out->rtol = rtol;
    out->atol = atol;
    out->no_project = o->no_project;
    out->max_steps = steps >= 0x1p63 ? (size_t)-1 : (size_t)steps; /* (size_t) of more: UB */
    out->precision = o->precision;
    out->t0 = s->vals[2 * s->nq];
    out->t_end = t_end;
    if (o->period && (st = period(s, o->period, out)) != QD_OK)
        return st;
    t_end = out->t_end;
    if ((st = initial_values(s)) != QD_OK)
        return st;
    out->q0 = s->q0;
    out->qd0 = s->qd0;
    out->qd0_given = s->qd0_given;
    out->p0 = s->p0;
    out->u0 = s->u0;
    if (isfinite(t_end) && !(t_end > out->t0)) /* (not finite: qd_sim_check_opts says so) */
        return refuse(s, "t_end", "the end time must be after the start time (%g)", out->t0);
    if ((st = qd_sim_check_opts(s->ctx, out)) != QD_OK)
        return st;
    if ((st = check_gaps(s)) != QD_OK)
        return st;
    if ((st = qd_sim_inputs_ready(s->sim, out->t0, out->t_end)) != QD_OK)
        qd_ctx_error_about(s->ctx, QD_SUBJECT_NONE, 0, "inputs", QD_REASON_NONE, NULL);
    return st;
}

qd_status qd_sim_setup_restart(qd_sim_setup *s, const char *initial, qd_sim_opts *out) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, out);
    memcpy(s->vals, s->vals0, s->n * sizeof *s->vals);
    s->initial_given = false;
    for (size_t i = 0; i < s->n; i++)
        s->given[i] = false;
    qd_status st = initial ? qd_sim_setup_initial(s, initial) : QD_OK;
    if (st == QD_OK)
        st = initial_values(s);
    if (st != QD_OK)
        return st;
    out->t0 = s->vals[2 * s->nq];
    out->q0 = s->q0;
    out->qd0 = s->qd0;
    out->qd0_given = s->qd0_given;
    out->p0 = s->p0;
    out->u0 = s->u0;
    if (!(out->t_end > out->t0))
        return refuse(s, "t_end", "the end time must be after the start time (%g)", out->t0);
    return check_gaps(s);
}

/* ---- --native ------------------------------------------------------------------ */

static void say(char *note, size_t cap, const char *fmt, const char *a) {
    if (note && cap)
        snprintf(note, cap, fmt, a);
}

qd_status qd_sim_setup_native(qd_sim_setup *s, const qd_sim_opts *opts, char *note, size_t cap) {
    QD_ARGS(QD_ERR_ARG, s);
    QD_ARGS_CTX(s->ctx, opts);
    say(note, cap, "%s", "");
    if (opts->method == QD_SIM_TAYLOR) {
        /* taylor's own generated code: its recurrences, in every form, in double */
        if (opts->precision == 80 || opts->precision == 128)
            say(note, cap, "%s", opts->precision == 80
                    ? "native generates the taylor recurrences in double only; precision 80 "
                      "keeps the interpreted ones"
                    : "native generates the taylor recurrences in double only; precision 128 "
                      "keeps the interpreted ones");
        else if (qd_sim_load_native_taylor(s->sim, NULL, NULL) != QD_OK) {
            say(note, cap, "native unavailable (%s); using the compiled programs",
                qd_ctx_message(s->ctx));
            qd_ctx_clear_error(s->ctx);
        }
        return QD_OK;
    }
    if (s->se) {
        say(note, cap, "%s", "native takes the multiplier form (no speeds); using the compiled "
                             "programs");
        return QD_OK;
    }
    if (!s->e) {
        say(note, cap, "%s", "native takes models given by T and V or L; using the compiled "
                             "programs");
        return QD_OK;
    }
    if (!qd_sim_method_adaptive(opts->method) || s->native)
        return QD_OK;
    qd_native *nat = calloc(1, sizeof *nat);
    if (!nat)
        return nomem(s->ctx), QD_ERR_NOMEM;
    if (qd_native_load_run(s->ctx, s->m, s->e, NULL, nat) != QD_OK) {
        say(note, cap, "native unavailable (%s); using the compiled programs",
            qd_ctx_message(s->ctx));
        qd_ctx_clear_error(s->ctx);
        free(nat);
        return QD_OK;
    }
    s->native = nat;
    qd_sim_set_native(s->sim, nat->rhs);
    return QD_OK;
}
