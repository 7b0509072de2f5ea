/*
 * tests/util/jsonwalk.c - the JSON walk of tests/util/jsonwalk.h.
 */
#include "jsonwalk.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *ws(const char *p) {
    while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')
        p++;
    return p;
}

static const char *skip_string(const char *p) {
    if (*p++ != '"')
        return NULL;
    while (*p != '"') {
        if ((unsigned char)*p < 0x20)
            return NULL; /* includes the end of the text */
        if (*p == '\\') {
            p++;
            if (*p == 'u') {
                for (int k = 1; k <= 4; k++)
                    if (!isxdigit((unsigned char)p[k]))
                        return NULL;
                p += 4;
            } else if (!strchr("\"\\/bfnrt", *p) || !*p)
                return NULL;
        }
        p++;
    }
    return p + 1;
}

static const char *digits(const char *p) {
    if (!isdigit((unsigned char)*p))
        return NULL;
    while (isdigit((unsigned char)*p))
        p++;
    return p;
}

static const char *skip_number(const char *p) {
    if (*p == '-')
        p++;
    if (*p == '0')
        p++;
    else if (!(p = digits(p)))
        return NULL;
    if (*p == '.' && !(p = digits(p + 1)))
        return NULL;
    if (*p == 'e' || *p == 'E') {
        p++;
        if (*p == '+' || *p == '-')
            p++;
        if (!(p = digits(p)))
            return NULL;
    }
    return p;
}

/* The members (object) or elements (array) after the opening bracket. */
static const char *skip_items(const char *p, char close, bool object) {
    p = ws(p);
    if (*p == close)
        return p + 1;
    for (;;) {
        if (object) {
            if (!(p = skip_string(ws(p))))
                return NULL;
            p = ws(p);
            if (*p++ != ':')
                return NULL;
        }
        if (!(p = qt_json_skip(p)))
            return NULL;
        p = ws(p);
        if (*p == close)
            return p + 1;
        if (*p++ != ',')
            return NULL;
    }
}

const char *qt_json_skip(const char *p) {
    if (!p)
        return NULL;
    p = ws(p);
    switch (*p) {
    case '{': return skip_items(p + 1, '}', true);
    case '[': return skip_items(p + 1, ']', false);
    case '"': return skip_string(p);
    case 't': return strncmp(p, "true", 4) ? NULL : p + 4;
    case 'f': return strncmp(p, "false", 5) ? NULL : p + 5;
    case 'n': return strncmp(p, "null", 4) ? NULL : p + 4;
    default: return skip_number(p);
    }
}

bool qt_json_valid(const char *text) {
    const char *end = qt_json_skip(text);
    return end && *ws(end) == '\0';
}

const char *qt_json_get(const char *obj, const char *key) {
    if (!obj || !qt_json_skip(obj))
        return NULL;
    const char *p = ws(obj);
    if (*p != '{')
        return NULL;
    p = ws(p + 1);
    while (*p == '"') {
        const char *end = skip_string(p);
        bool hit = qt_json_str_is(p, key);
        p = ws(end);
        p = ws(p + 1); /* the ':' (the document is valid) */
        if (hit)
            return p;
        p = ws(qt_json_skip(p));
        if (*p != ',')
            return NULL;
        p = ws(p + 1);
    }
    return NULL;
}

const char *qt_json_at(const char *arr, size_t i) {
    if (!arr || !qt_json_skip(arr))
        return NULL;
    const char *p = ws(arr);
    if (*p != '[')
        return NULL;
    p = ws(p + 1);
    if (*p == ']')
        return NULL;
    for (size_t k = 0; k < i; k++) {
        p = ws(qt_json_skip(p));
        if (*p != ',')
            return NULL;
        p = ws(p + 1);
    }
    return p;
}

/* One pass over the array (counting through qt_json_at would skip the
 * whole array once per element: quadratic, minutes under ASan on a list
 * of 500 equilibria). */
size_t qt_json_len(const char *arr) {
    if (!arr || !qt_json_skip(arr))
        return 0;
    const char *p = ws(arr);
    if (*p != '[')
        return 0;
    p = ws(p + 1);
    if (*p == ']')
        return 0;
    size_t n = 1;
    for (;;) {
        p = ws(qt_json_skip(p));
        if (*p != ',')
            return n;
        p = ws(p + 1);
        n++;
    }
}

double qt_json_num(const char *p) {
    if (!p)
        return NAN;
    p = ws(p);
    const char *end = skip_number(p);
    return end ? strtod(p, NULL) : NAN;
}

bool qt_json_str(const char *p, char *buf, size_t cap) {
    if (!p || !(p = ws(p)) || !skip_string(p) || cap == 0)
        return false;
    size_t n = 0;
    for (p++; *p != '"'; p++) {
        if (*p == '\\')
            p++;
        if (n + 1 >= cap)
            return false;
        buf[n++] = *p;
    }
    buf[n] = '\0';
    return true;
}

bool qt_json_str_is(const char *p, const char *s) {
    char buf[512];
    return qt_json_str(p, buf, sizeof buf) && strcmp(buf, s) == 0;
}
