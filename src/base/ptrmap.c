/* src/base/ptrmap.c - see ptrmap.h.  Open addressing, linear probing. */
#include "ptrmap.h"

#include <stdint.h>
#include <stdlib.h>

static size_t slot_of(const void *key, size_t cap) {
    uint64_t h = (uint64_t)(uintptr_t)key;
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    return (size_t)h & (cap - 1);
}

void qd__ptrmap_free(qd__ptrmap *m) {
    qd__free(m->slots);
    m->slots = NULL;
    m->cap = m->len = 0;
}

void qd__ptrmap_clear(qd__ptrmap *m) {
    for (size_t i = 0; i < m->cap; i++)
        m->slots[i].key = NULL;
    m->len = 0;
}

static qd__ptrmap_slot *find(const qd__ptrmap *m, const void *key) {
    if (!m->cap)
        return NULL;
    size_t i = slot_of(key, m->cap);
    while (m->slots[i].key && m->slots[i].key != key)
        i = (i + 1) & (m->cap - 1);
    return &m->slots[i];
}

void *qd__ptrmap_get(const qd__ptrmap *m, const void *key) {
    qd__ptrmap_slot *s = find(m, key);
    return s && s->key ? s->val : NULL;
}

bool qd__ptrmap_has(const qd__ptrmap *m, const void *key) {
    qd__ptrmap_slot *s = find(m, key);
    return s && s->key;
}

static bool grow(qd__ptrmap *m) {
    size_t cap = m->cap ? m->cap * 2 : 64;
    qd__ptrmap_slot *slots = qd__mem_calloc(m->al, cap, sizeof *slots);
    if (!slots)
        return false;
    for (size_t i = 0; i < m->cap; i++) {
        if (!m->slots[i].key)
            continue;
        size_t j = slot_of(m->slots[i].key, cap);
        while (slots[j].key)
            j = (j + 1) & (cap - 1);
        slots[j] = m->slots[i];
    }
    qd__free(m->slots);
    m->slots = slots;
    m->cap = cap;
    return true;
}

bool qd__ptrmap_put(qd__ptrmap *m, const void *key, void *val) {
    if ((m->len + 1) * 2 > m->cap && !grow(m))
        return false;
    qd__ptrmap_slot *s = find(m, key);
    if (!s->key) {
        s->key = key;
        m->len++;
    }
    s->val = val;
    return true;
}
