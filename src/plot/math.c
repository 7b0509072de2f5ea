/*
 * src/plot/math.c - a label's names as a textbook prints them
 * (qd_plot_math_text, qdot/plot.h): Greek letter names as Greek letters,
 * trailing digits as subscripts, primes as dots over the letter, for names
 * that are a Greek letter's or one letter (x1', E0, A1): a longer word is
 * a word (the method gl4, th').  Plain
 * UTF-8 with combining dots, so Cairo's text draws it and the layout
 * measures it like any text.
 */
#include "qdot/plot.h"
#include "../base/args.h"

#include <ctype.h>
#include <stdbool.h>
#include <string.h>

/* The names (lower case, then the capitals that differ from Latin ones),
 * and their letters in UTF-8. */
static const char *const greek[][2] = {
    {"alpha", "\xce\xb1"},   {"beta", "\xce\xb2"},    {"gamma", "\xce\xb3"},
    {"delta", "\xce\xb4"},   {"epsilon", "\xce\xb5"}, {"zeta", "\xce\xb6"},
    {"eta", "\xce\xb7"},     {"theta", "\xce\xb8"},   {"iota", "\xce\xb9"},
    {"kappa", "\xce\xba"},   {"lambda", "\xce\xbb"},  {"mu", "\xce\xbc"},
    {"nu", "\xce\xbd"},      {"xi", "\xce\xbe"},      {"pi", "\xcf\x80"},
    {"rho", "\xcf\x81"},     {"sigma", "\xcf\x83"},   {"tau", "\xcf\x84"},
    {"upsilon", "\xcf\x85"}, {"phi", "\xcf\x86"},     {"chi", "\xcf\x87"},
    {"psi", "\xcf\x88"},     {"omega", "\xcf\x89"},   {"Gamma", "\xce\x93"},
    {"Delta", "\xce\x94"},   {"Theta", "\xce\x98"},   {"Lambda", "\xce\x9b"},
    {"Xi", "\xce\x9e"},      {"Pi", "\xce\xa0"},      {"Sigma", "\xce\xa3"},
    {"Phi", "\xce\xa6"},     {"Psi", "\xce\xa8"},     {"Omega", "\xce\xa9"},
};

static bool ident(char c) { return isalnum((unsigned char)c) || c == '_'; }

typedef struct sink {
    char *out;
    size_t cap, n; /* n counts every byte, written or not */
} sink;

static void put(sink *s, const char *text, size_t len) {
    for (size_t i = 0; i < len; i++, s->n++)
        if (s->n + 1 < s->cap)
            s->out[s->n] = text[i];
}

static const char *greek_of(const char *w, size_t len) {
    for (size_t g = 0; g < sizeof greek / sizeof greek[0]; g++)
        if (strlen(greek[g][0]) == len && !strncmp(greek[g][0], w, len))
            return greek[g][1];
    return NULL;
}

/* One name w[0, len) with its primes (np of them): the letters (Greek when
 * the name is one), the dots over the last, the trailing digits below. */
static void put_name(sink *s, const char *w, size_t len, size_t np) {
    size_t stem = len;
    while (stem > 1 && isdigit((unsigned char)w[stem - 1]))
        stem--;
    const char *g = greek_of(w, stem);
    if (!g && stem > 1) { /* a word (gl4, dop853, th'): as written */
        put(s, w, len + np);
        return;
    }
    if (g)
        put(s, g, strlen(g));
    else
        put(s, w, stem);
    /* U+0307 one dot, U+0308 two; more primes stay primes */
    if (np == 1)
        put(s, "\xcc\x87", 2);
    else if (np == 2)
        put(s, "\xcc\x88", 2);
    for (size_t k = stem; k < len; k++) {
        char sub[3] = {'\xe2', '\x82', (char)(0x80 + (w[k] - '0'))}; /* U+2080 + digit */
        put(s, sub, 3);
    }
    for (size_t k = 0; np > 2 && k < np; k++)
        put(s, "'", 1);
}

size_t qd_plot_math_text(const char *text, char *out, size_t cap) {
    QD_ARGS(0, text && (out || !cap));
    sink s = {out, cap, 0};
    const char *p = text;
    while (*p) {
        bool starts = isalpha((unsigned char)*p) && (p == text || !ident(p[-1]));
        size_t len = 0, np = 0;
        while (starts && ident(p[len]))
            len++;
        while (starts && p[len + np] == '\'')
            np++;
        /* a file's name (ring6.qd, examples/x1) is left as it is written */
        char before = p > text ? p[-1] : ' ', after = p[len + np];
        bool name = starts && len && before != '.' && before != '/' && after != '.' &&
                    after != '/' && !memchr(p, '_', len);
        if (name) {
            put_name(&s, p, len, np);
            p += len + np;
        } else {
            size_t run = starts ? len : 1;
            put(&s, p, run);
            p += run;
        }
    }
    if (!cap)
        return s.n;
    size_t end = s.n < cap ? s.n : cap - 1;
    if (end < s.n) { /* cut at a whole character: Cairo refuses broken UTF-8 */
        size_t k = end;
        while (k > 0 && ((unsigned char)out[k - 1] & 0xc0) == 0x80)
            k--;
        /* k - 1 leads a sequence: keep it only when all of it fits */
        if (k > 0 && ((unsigned char)out[k - 1] & 0x80)) {
            unsigned char lead = (unsigned char)out[k - 1];
            size_t len = lead >= 0xf0 ? 4 : lead >= 0xe0 ? 3 : 2;
            if (k - 1 + len > end)
                end = k - 1;
        }
    }
    out[end] = 0;
    return s.n;
}
