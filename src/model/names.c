/*
 * src/model/names.c - the model's name table: one open-addressing hash
 * table from a name to (kind, index) for the coordinates, parameters,
 * definitions, functions and statement places (qd_model_where), so that
 * reading n names costs O(n) and not O(n^2).
 *
 * The table keeps no copy of a name: an entry holds its kind and index,
 * and a lookup compares with the name the model's list holds at that
 * index.  When a statement added to a model fails (parse.c, mark_restore)
 * the lists shrink back; an entry left behind then points past the end of
 * its list or at a name that differs, and is skipped, so the table needs no
 * undo of its own.
 */
#include "parser.h"
#include "../base/mem.h"

#include <string.h>

typedef struct qd__name_entry {
    size_t index;
    unsigned hash;
    unsigned kind; /* QD_MDL_NAME_*; 0: empty slot */
} name_entry;

unsigned long qd__mdl_name_probes; /* slots looked at by lookups, for the tests */

static unsigned hash_of(const char *s, size_t n) {
    unsigned h = 2166136261u; /* FNV-1a */
    for (size_t i = 0; i < n; i++)
        h = (h ^ (unsigned char)s[i]) * 16777619u;
    return h ? h : 1;
}

/* The name the model's list of that kind holds at index, or NULL past its end. */
static const char *name_at(const qd_model *m, unsigned kind, size_t i) {
    switch (kind) {
    case QD_MDL_NAME_COORD: return i < m->ncoords ? qd_expr_name(m->coords[i]) : NULL;
    case QD_MDL_NAME_PARAM: return i < m->nparams ? qd_expr_name(m->params[i]) : NULL;
    case QD_MDL_NAME_DEF: return i < m->ndefs ? m->defs[i].name : NULL;
    case QD_MDL_NAME_FUNC: return i < m->nfuncs ? m->funcs[i] : NULL;
    case QD_MDL_NAME_WHERE: return i < m->nwheres ? m->wheres[i].what : NULL;
    default: return NULL;
    }
}

static bool same(const char *a, const char *s, size_t n) {
    return a && strncmp(a, s, n) == 0 && a[n] == '\0';
}

long qd__mdl_names_find(const qd_model *m, unsigned kind, const char *s, size_t n) {
    const name_entry *t = m->names;
    if (!t)
        return -1;
    unsigned h = hash_of(s, n);
    size_t mask = m->names_cap - 1;
    for (size_t i = h & mask;; i = (i + 1) & mask) {
        qd__mdl_name_probes++;
        if (!t[i].kind)
            return -1;
        if (t[i].hash == h && t[i].kind == kind && same(name_at(m, kind, t[i].index), s, n))
            return (long)t[i].index;
    }
}

static void put(name_entry *t, size_t cap, name_entry e) {
    size_t mask = cap - 1;
    size_t i = e.hash & mask;
    while (t[i].kind)
        i = (i + 1) & mask;
    t[i] = e;
}

bool qd__mdl_names_add(qd_model *m, unsigned kind, size_t index) {
    const char *name = name_at(m, kind, index);
    if (!name)
        return true;
    size_t n = strlen(name);
    if (qd__mdl_names_find(m, kind, name, n) >= 0)
        return true; /* the first one stays found (qd_model_where's rule) */
    if (2 * (m->names_used + 1) > m->names_cap) { /* at most half full */
        size_t cap = m->names_cap ? 2 * m->names_cap : 64;
        name_entry *t = qd__calloc(m->ctx, cap, sizeof *t);
        if (!t)
            return false;
        for (size_t i = 0; i < m->names_cap; i++)
            if (m->names[i].kind)
                put(t, cap, m->names[i]);
        qd__free(m->names);
        m->names = t;
        m->names_cap = cap;
    }
    put(m->names, m->names_cap, (name_entry){index, hash_of(name, n), kind});
    m->names_used++;
    return true;
}

void qd__mdl_names_free(qd_model *m) {
    qd__free(m->names);
    m->names = NULL;
    m->names_cap = m->names_used = 0;
}
