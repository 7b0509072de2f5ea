/*
 * src/sim/friction_lcp.c - the consistent choice of stick/slip modes.
 *
 * At the start and at every switch each contact gets a few candidate modes:
 * a moving contact (slip velocity not 0) slips on in its direction; one at
 * rest may stick, or slip either way (1-D) or against the friction force it
 * would need to stick (2-D); the contact whose static limit was just
 * reached slips (against its friction force: no stick candidate, else it
 * would stick again at the limit).  With a normal force that is a
 * multiplier, a slipping contact is tried with either sign of it, since
 * |N| enters its law.  Every combination is solved (the saddle system of
 * that mode set at the state) and kept when each contact's law holds:
 * stick |lambda| <= mu_s |N|; slip from rest accelerating the way it
 * slips; the normal multiplier of the sign assumed.  This is the finite
 * enumeration of the linear complementarity problem's cases (Pfeiffer &
 * Glocker, Multibody Dynamics with Unilateral Contacts, ch. 6).  Of the
 * consistent sets the ones with the most sticking contacts win (static
 * friction holds when it can, as with mu_s > mu_k where slipping would
 * also be consistent); none, or several left, is Painleve's paradox.
 */
#include "simint.h"
#include "../base/mem.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define MAXCAND 5
#define REST_TOL 1e-9  /* |v| below this times the speed scale: at rest */

typedef struct choice {
    qd__sim_fmode cand[QD__FMAX][MAXCAND];
    size_t ncand[QD__FMAX];
    bool rest[QD__FMAX];    /* at rest: a slip candidate must accelerate its way */
} choice;

static double speed_scale(const qd_sim *s, const double *y) {
    double v = 0;
    for (size_t j = 0; j < s->n; j++)
        v = fmax(v, fabs(y[s->n + j]));
    return 1 + v;
}

static void lambda_of(const qd_sim *s, size_t c, double l[2]) {
    const qd__sim_fcon *fc = &s->fc[c];
    l[0] = s->rhs[s->n + fc->con[0]];
    l[1] = fc->ncon > 1 ? s->rhs[s->n + fc->con[1]] : 0;
}

/* The slip velocity (s1, s2) of contact c at the state fprog last saw. */
static void slip_of(const qd_sim *s, size_t c, double v[2]) {
    const double *f = s->fprog_out + QD__FSTRIDE * c;
    v[0] = f[3];
    v[1] = s->fc[c].ncon > 1 ? f[4] : 0;
}

static void add(choice *ch, size_t c, bool slip, double d0, double d1, double sn) {
    ch->cand[c][ch->ncand[c]++] = (qd__sim_fmode){.slip = slip, .dir = {d0, d1}, .sn = sn};
}

/* Slip candidates of contact c in direction (d0, d1), for each sign of a
 * multiplier normal force. */
static void add_slip(const qd_sim *s, choice *ch, size_t c, double d0, double d1) {
    add(ch, c, true, d0, d1, 1);
    if (s->fc[c].normal != (size_t)-1)
        add(ch, c, true, d0, d1, -1);
}

/* Against the force l (2-D), or (0, 0) for no force: along the first axis. */
static void against(const double l[2], double *d0, double *d1) {
    double a = hypot(l[0], l[1]);
    *d0 = a > 0 ? -l[0] / a : 1;
    *d1 = a > 0 ? -l[1] / a : 0;
}

/* The candidates of every contact; the modes in fr->mode are the ones in
 * force before the switch, and s->rhs holds their solution at the state. */
static void candidates(qd__sim_run *r, const double *y, size_t ev, choice *ch) {
    qd_sim *s = r->s;
    const qd__sim_fric_run *fr = s->fr;
    double scale = speed_scale(s, y);
    double lnow[QD__FMAX][2];
    for (size_t c = 0; c < s->nfc; c++)
        lambda_of(s, c, lnow[c]);
    for (size_t c = 0; c < s->nfc; c++) {
        double v[2], d0, d1;
        slip_of(s, c, v);
        ch->ncand[c] = 0;
        bool mine = ev != (size_t)-1 && ev / 2 == c && ev % 2 == 0;
        bool limit = mine && !fr->mode[c].slip;
        /* a slip that just stopped is at rest by its event (v . u = 0),
         * whatever is left across u by the integration's drift */
        ch->rest[c] = hypot(v[0], v[1]) <= REST_TOL * scale || (mine && fr->mode[c].slip);
        if (limit) {
            /* the static limit reached: slips against the force it needed */
            against(lnow[c], &d0, &d1);
            add_slip(s, ch, c, d0, d1);
            ch->rest[c] = false; /* its direction is the law's, not a test's */
        } else if (!ch->rest[c]) {
            double a = hypot(v[0], v[1]);
            add_slip(s, ch, c, v[0] / a, v[1] / a);
        } else {
            /* 2-D: the direction needs the stuck solution (rest_directions) */
            add(ch, c, false, 1, 0, 1);
            if (s->fc[c].ncon == 1) {
                add_slip(s, ch, c, 1, 0);
                add_slip(s, ch, c, -1, 0);
            }
        }
    }
}

/* 2-D contacts at rest: slip against the force they need with every resting
 * contact stuck (and the moving ones as the candidates say). */
static void rest_directions(qd__sim_run *r, double t, const double *y, choice *ch) {
    qd_sim *s = r->s;
    qd__sim_fric_run *fr = s->fr;
    bool any = false;
    for (size_t c = 0; c < s->nfc; c++) {
        fr->mode[c] = ch->cand[c][0];
        any = any || (ch->rest[c] && s->fc[c].ncon > 1);
    }
    if (!any || !qd__sim_saddle(s, t, y))
        return; /* no stuck solution: only sticking is tried, and fails */
    for (size_t c = 0; c < s->nfc; c++) {
        if (!(ch->rest[c] && s->fc[c].ncon > 1))
            continue;
        double l[2], d0, d1;
        lambda_of(s, c, l);
        against(l, &d0, &d1);
        add_slip(s, ch, c, d0, d1);
    }
}

/* Does every contact's law hold in the solution s->rhs of the trial set? */
static bool consistent(const qd_sim *s, const choice *ch) {
    const qd__sim_fric_run *fr = s->fr;
    size_t n = s->n, m = s->m;
    const double *A = s->acc_out + n * n + n, *b = A + m * n, *qdd = s->rhs;
    for (size_t c = 0; c < s->nfc; c++) {
        const qd__sim_fcon *fc = &s->fc[c];
        const qd__sim_fmode *md = &fr->mode[c];
        const double *f = s->fprog_out + QD__FSTRIDE * c;
        double N = qd__sim_fric_normal(s, c);
        if (!md->slip) {
            if (qd__sim_fric_force(s, c) > f[0] * N * (1 + 1e-12) + 1e-300)
                return false;
            continue;
        }
        if (fc->normal != (size_t)-1 && md->sn * s->rhs[n + fc->normal] < 0)
            return false;
        if (!ch->rest[c])
            continue;
        /* from rest: the slip velocity's rate, A q'' - b, along the direction */
        double acc = 0;
        for (size_t i = 0; i < fc->ncon; i++) {
            size_t row = fc->con[i];
            double a = -b[row];
            for (size_t j = 0; j < n; j++)
                a += A[row * n + j] * qdd[j];
            acc += md->dir[i] * a;
        }
        if (!(acc > 0))
            return false;
    }
    return true;
}

static size_t nstick(const qd__sim_fmode *md, size_t k) {
    size_t c = 0;
    for (size_t i = 0; i < k; i++)
        c += !md[i].slip;
    return c;
}

/* "A slip (lambda_N > 0), B stick": a slip's normal sign says which of
 * the two solutions of |N| it is. */
static void describe(const qd_sim *s, const qd__sim_fmode *md, char *buf, size_t cap) {
    size_t k = 0;
    for (size_t c = 0; c < s->nfc && k < cap; c++) {
        const qd__sim_fcon *fc = &s->fc[c];
        k += (size_t)snprintf(buf + k, cap - k, "%s%s %s", c ? ", " : "", fc->name,
                              md[c].slip ? "slip" : "stick");
        if (md[c].slip && fc->normal != (size_t)-1 && k < cap)
            k += (size_t)snprintf(buf + k, cap - k, " (lambda_%s %s 0)",
                                  s->cons[fc->normal].name, md[c].sn > 0 ? ">" : "<");
    }
}

static qd_status paradox(qd_sim *s, double t, size_t found, const qd__sim_fmode *a,
                         const qd__sim_fmode *b) {
    qd__sim_stop(s, QD_STOP_PAINLEVE, t, (double)found);
    if (!found) {
        qd_ctx_error(s->ctx, QD_ERR_NUMERIC, "Painleve paradox at t = %.17g: no consistent "
                     "stick/slip mode", t);
        return QD_ERR_NUMERIC;
    }
    char da[256], db[256];
    describe(s, a, da, sizeof da);
    describe(s, b, db, sizeof db);
    qd_ctx_error(s->ctx, QD_ERR_NUMERIC, "Painleve paradox at t = %.17g: several consistent "
                 "modes (%s; %s)", t, da, db);
    return QD_ERR_NUMERIC;
}

/* Mixed-radix counter over the candidates; false after the last. */
static bool next_set(const choice *ch, size_t k, size_t *idx) {
    for (size_t c = 0; c < k; c++) {
        if (++idx[c] < ch->ncand[c])
            return true;
        idx[c] = 0;
    }
    return false;
}

static qd_status record(qd_sim *s, double t, size_t c, bool from, bool to) {
    qd__sim_fric_run *fr = s->fr;
    if (fr->ntr == fr->cap) {
        size_t cap = fr->cap ? 2 * fr->cap : 16;
        qd_sim_transition *tr = qd__realloc(s->ctx, fr->tr, cap * sizeof *tr);
        if (!tr) {
            qd_ctx_error(s->ctx, QD_ERR_NOMEM, "out of memory");
            return QD_ERR_NOMEM;
        }
        fr->tr = tr;
        fr->cap = cap;
    }
    fr->tr[fr->ntr++] = (qd_sim_transition){
        .t = t, .contact = c, .from = from ? QD_CONTACT_SLIP : QD_CONTACT_STICK,
        .to = to ? QD_CONTACT_SLIP : QD_CONTACT_STICK};
    return QD_OK;
}

/* Put the chosen set in force: the switches, the rows left out. */
static qd_status adopt(qd_sim *s, double t, const choice *ch, const qd__sim_fmode *prev,
                       bool start) {
    qd__sim_fric_run *fr = s->fr;
    qd_status st = QD_OK;
    for (size_t c = 0; c < s->nfc; c++) {
        fr->mode[c] = fr->best[c];
        fr->fresh[c] = fr->best[c].slip && (ch->rest[c] || !prev[c].slip);
        if (!start && prev[c].slip != fr->best[c].slip && st == QD_OK)
            st = record(s, t, c, prev[c].slip, fr->best[c].slip);
        for (size_t i = 0; i < s->fc[c].ncon; i++)
            fr->on[s->fc[c].con[i]] = !fr->best[c].slip;
    }
    return st;
}

qd_status qd__sim_fric_select(qd__sim_run *r, double t, const double *y, size_t ev) {
    qd_sim *s = r->s;
    qd__sim_fric_run *fr = s->fr;
    size_t k = s->nfc, idx[QD__FMAX] = {0}, found = 0, top = 0;
    qd__sim_fmode prev[QD__FMAX], other[QD__FMAX];
    choice ch;
    memcpy(prev, fr->mode, k * sizeof *prev);
    if (!qd__sim_saddle(s, t, y))
        memset(s->rhs, 0, (s->n + s->m) * sizeof *s->rhs); /* no force known: axis 1 */
    candidates(r, y, ev, &ch);
    rest_directions(r, t, y, &ch);
    do {
        for (size_t c = 0; c < k; c++)
            fr->mode[c] = ch.cand[c][idx[c]];
        if (!qd__sim_saddle(s, t, y) || !consistent(s, &ch))
            continue;
        size_t ns = nstick(fr->mode, k);
        if (found && ns < top)
            continue;
        if (!found || ns > top) {
            found = 0;
            top = ns;
            memcpy(fr->best, fr->mode, k * sizeof *fr->best);
        } else {
            memcpy(other, fr->mode, k * sizeof *other);
        }
        found++;
    } while (next_set(&ch, k, idx));
    if (found != 1) {
        memcpy(fr->mode, prev, k * sizeof *prev);
        return paradox(s, t, found, fr->best, other);
    }
    return adopt(s, t, &ch, prev, ev == (size_t)-1);
}
