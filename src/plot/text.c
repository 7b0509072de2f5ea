/*
 * src/plot/text.c - a plot's text drawn as mathematics: the letters of
 * qd_plot_math_text, and its dots for primes painted by hand.  A font puts
 * a combining dot (U+0307) at a short letter's height: over x it reads,
 * inside theta or over a capital it is lost; so the dots are taken out of
 * the text and drawn just above each dotted letter's own ink.
 */
#include "plot_priv.h"

#include <string.h>

#define MAXDOTS 64

size_t qd__plot_plain_math(const char *text, char *out, size_t cap, size_t *base,
                           unsigned *dots) {
    char m[QD__PLOT_TEXT_MAX];
    qd_plot_math_text(text, m, sizeof m);
    size_t n = 0, nd = 0, last = 0;
    for (const unsigned char *s = (const unsigned char *)m; *s && n + 1 < cap;) {
        /* U+0307 is CC 87, U+0308 CC 88 */
        if (s[0] == 0xcc && (s[1] == 0x87 || s[1] == 0x88)) {
            if (base && dots && nd < MAXDOTS) {
                base[nd] = last;
                dots[nd++] = s[1] == 0x87 ? 1 : 2;
            }
            s += 2;
            continue;
        }
        size_t len = s[0] < 0x80 ? 1 : s[0] >= 0xf0 ? 4 : s[0] >= 0xe0 ? 3 : 2;
        if (n + len >= cap)
            break;
        last = n;
        memcpy(out + n, s, len);
        n += len;
        s += len;
    }
    out[n] = 0;
    return nd;
}

static size_t char_len(unsigned char c) { return c < 0x80 ? 1 : c >= 0xf0 ? 4 : c >= 0xe0 ? 3 : 2; }

void qd__plot_math_at(const pen *cr, const char *text, double x, double y, double ax, double ay) {
    char plain[QD__PLOT_TEXT_MAX];
    size_t base[MAXDOTS];
    unsigned dots[MAXDOTS];
    size_t nd = qd__plot_plain_math(text, plain, sizeof plain, base, dots);
    cr->op->text(cr->cv, plain, x, y, ax, ay);
    if (!nd)
        return;
    double xb, yb, w, h, adv, xh_b, xh_y, xh_w, xh_h, xh_adv;
    cr->op->extents(cr->cv, plain, &xb, &yb, &w, &h, &adv);
    cr->op->extents(cr->cv, "x", &xh_b, &xh_y, &xh_w, &xh_h, &xh_adv);
    /* the origin on the baseline where the op put the text */
    double ox = x - xb - ax * w, oy = y - yb - ay * h, r = 0.09 * xh_h + 0.3;
    for (size_t k = 0; k < nd; k++) {
        char head[QD__PLOT_TEXT_MAX], ch[8];
        size_t len = char_len((unsigned char)plain[base[k]]);
        memcpy(head, plain, base[k]);
        head[base[k]] = 0;
        memcpy(ch, plain + base[k], len);
        ch[len] = 0;
        double hb, hy, hw, hh, hadv, cb, cy, cw, chh, cadv;
        cr->op->extents(cr->cv, head, &hb, &hy, &hw, &hh, &hadv);
        cr->op->extents(cr->cv, ch, &cb, &cy, &cw, &chh, &cadv);
        double cx = ox + (base[k] ? hadv : 0) + cb + cw / 2, top = oy + cy - 2.2 * r;
        for (unsigned d = 0; d < dots[k]; d++) {
            double dx = dots[k] == 2 ? (d ? 1.6 : -1.6) * r : 0;
            cr->op->circle(cr->cv, cx + dx, top, r);
        }
        cr->op->fill(cr->cv);
    }
}
