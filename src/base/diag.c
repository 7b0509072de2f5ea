/*
 * src/base/diag.c - the one renderer of error records, and the plain-words
 * name of a byte the readers do not accept.
 *
 * jq's way (src/locfile.c): a location is a byte range; one function turns it
 * into FILE:LINE:COL, the source line and a caret underline.  Both readers
 * (the kernel's expressions, the model language) and the derivations record
 * qd_diag; every caller shows it through qd_diag_format.
 */
#include "diag.h"
#include "args.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static size_t utf8_char(const unsigned char *s, unsigned long *cp);

/* A UTF-8 continuation byte: the caret does not advance under it. */
static bool continuation(unsigned char c) { return (c & 0xC0) == 0x80; }

void qd__diag_line_col(const char *text, size_t off, size_t *line, size_t *col, size_t *start) {
    size_t l = 1, s = 0;
    for (size_t i = 0; i < off && text[i]; i++)
        if (text[i] == '\n' || (text[i] == '\r' && text[i + 1] != '\n')) {
            l++;
            s = i + 1;
        }
    *line = l;
    *col = off - s + 1;
    if (start)
        *start = s;
}

size_t qd__diag_line_len(const char *s) { return strcspn(s, "\r\n"); }

static void line_col(const char *text, size_t off, size_t *line, size_t *col, size_t *start) {
    qd__diag_line_col(text, off, line, col, start);
}

#define SHOW 100 /* bytes of a long line shown around the caret */

/* The source line and a caret under [off, off + w), clipped to the line; a
 * long line (10,000 brackets) is cut to SHOW bytes around the caret. */
static void caret(qd_buf *out, const char *text, size_t start, size_t off, size_t w) {
    size_t end = start + qd__diag_line_len(text + start), from = start, to = end;
    if (end - start > SHOW) {
        from = off > start + SHOW / 2 ? off - SHOW / 2 : start;
        while (from < off && continuation((unsigned char)text[from]))
            from++;
        to = from + SHOW < end ? from + SHOW : end;
        while (to < end && continuation((unsigned char)text[to]))
            to++;
    }
    const char *cut = from > start ? "..." : "";
    qd_buf_printf(out, "  %s", cut);
    for (size_t i = from; i < to;) { /* a byte that is not UTF-8 is shown as '?' */
        unsigned long cp;
        size_t k = (unsigned char)text[i] < 0x80 ? 1 : utf8_char((const unsigned char *)text + i, &cp);
        if (k == 0 || i + k > to) {
            qd_buf_putn(out, "?", 1);
            i++;
            continue;
        }
        qd_buf_putn(out, text + i, k);
        i += k;
    }
    qd_buf_printf(out, "%s\n  %s", to < end ? "..." : "", cut[0] ? "   " : "");
    for (size_t i = from; i < off;) { /* one column per character shown */
        unsigned long cp;
        size_t k = (unsigned char)text[i] < 0x80 ? 1 : utf8_char((const unsigned char *)text + i, &cp);
        qd_buf_putn(out, text[i] == '\t' ? "\t" : " ", 1);
        i += k == 0 || i + k > to ? 1 : k;
    }
    if (off + w > to)
        w = to > off ? to - off : 1; /* the caret stays on the text shown */
    qd_buf_puts(out, "^");
    for (size_t i = off + 1; i < off + w; i++)
        if (!continuation((unsigned char)text[i]))
            qd_buf_puts(out, "~");
    qd_buf_puts(out, "\n");
}

void qd_diag_format(const qd_diag *d, const char *file, const char *text, qd_buf *out) {
    QD_ARGS(, d && out);
    const char *msg = d->message[0] ? d->message : qd_status_str(d->status);
    if (!d->located || !text) {
        qd_buf_printf(out, "%s: error: %s\n", file, msg);
    } else {
        size_t len = strlen(text), off = d->offset <= len ? d->offset : len;
        size_t line, col, start;
        line_col(text, off, &line, &col, &start);
        qd_buf_printf(out, "%s:%zu:%zu: error: %s\n", file, line, col, msg);
        caret(out, text, start, off, d->length ? d->length : 1);
    }
    if (d->hint[0])
        qd_buf_printf(out, "  hint: %s\n", d->hint);
}

/* Bytes of the well-formed UTF-8 character at s and its code point; 0 when s
 * does not start one (a stray continuation byte, an overlong or cut form). */
static size_t utf8_char(const unsigned char *s, unsigned long *cp) {
    size_t n = s[0] >= 0xF0 && s[0] <= 0xF4 ? 4 : s[0] >= 0xE0 ? 3 : s[0] >= 0xC2 ? 2 : 0;
    if (n == 0 || s[0] > 0xF4)
        return 0;
    unsigned long v = s[0] & (0x7F >> n);
    for (size_t i = 1; i < n; i++) {
        if (!continuation(s[i]))
            return 0;
        v = v << 6 | (s[i] & 0x3F);
    }
    static const unsigned long least[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (v < least[n] || v > 0x10FFFF || (v >= 0xD800 && v <= 0xDFFF))
        return 0;
    *cp = v;
    return n;
}

size_t qd__diag_utf8_check(const char *text, size_t n) {
    const unsigned char *u = (const unsigned char *)text;
    for (size_t i = 0; i < n;) {
        unsigned long cp;
        size_t k = u[i] < 0x80 ? 1 : utf8_char(u + i, &cp);
        if (k == 0 || i + k > n)
            return i;
        i += k;
    }
    return n;
}

size_t qd__diag_bad_char(const char *s, char *msg, size_t cap, const char **hint) {
    const unsigned char *u = (const unsigned char *)s;
    unsigned long cp = 0;
    size_t n = u[0] >= 0x80 ? utf8_char(u, &cp) : 1;
    if (u[0] >= 0x80 && n > 0) {
        snprintf(msg, cap,
                 "'%.*s' (U+%04lX) cannot be used in a name; names are ASCII letters, digits and _",
                 (int)n, s, cp);
        *hint = "spell it in ASCII letters: theta for a Greek theta, x_1 for a subscript";
        return n;
    }
    if (u[0] >= 0x80) {
        snprintf(msg, cap, "unexpected byte 0x%02x (not UTF-8 text)", u[0]);
        *hint = "qdot reads UTF-8 text: was this written in another encoding?";
        return 1;
    }
    if (u[0] < 0x20 || u[0] == 0x7F)
        snprintf(msg, cap, "unexpected control character 0x%02x", u[0]);
    else
        snprintf(msg, cap, "unexpected character '%c'", s[0]);
    *hint = "names are ASCII letters, digits and _; operators are + - * / ^ and '";
    if (s[0] == '>' || s[0] == '<') /* only a contact compares, and never strictly */
        *hint = "a contact's gap is compared with >= or <=: impact floor: y >= 0";
    return 1;
}

/* ---- suggestions: "did you mean ...?" ---------------------------------- */

static size_t edit_distance(const char *a, size_t na, const char *b) {
    size_t nb = strlen(b);
    if (na > 64 || nb > 64)
        return (size_t)-1;
    size_t row[65];
    for (size_t j = 0; j <= nb; j++)
        row[j] = j;
    for (size_t i = 1; i <= na; i++) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= nb; j++) {
            size_t up = row[j];
            size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            size_t best = diag + cost;
            if (row[j] + 1 < best)
                best = row[j] + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    return row[nb];
}

const char *qd__diag_nearest(const char *word, size_t n, const char *const *names, size_t count) {
    const char *best = NULL;
    size_t bestd = (size_t)-1;
    size_t limit = n <= 3 ? 1 : n <= 6 ? 2 : 3; /* a close name, not any name */
    if (n < 2)
        return NULL; /* every one-letter name is one edit from every other */
    for (size_t i = 0; i < count; i++) {
        if (strlen(names[i]) < 2)
            continue;
        size_t d = edit_distance(word, n, names[i]);
        if (d <= limit && d < bestd) {
            bestd = d;
            best = names[i];
        }
    }
    return best;
}

const char *qd_nearest_name(const char *word, size_t n, const char *const *names, size_t count) {
    QD_ARGS(NULL, word && (names || !count));
    return qd__diag_nearest(word, n, names, count);
}

char *qd__diag_blanked(const char *text, size_t start, size_t end) {
    size_t n = strlen(text);
    char *copy = malloc(n + 1);
    if (!copy)
        return NULL;
    for (size_t i = 0; i < n; i++)
        copy[i] = (i >= start && i < end) || text[i] == '\n' || text[i] == '\r' ? text[i] : ' ';
    copy[n] = '\0';
    return copy;
}
