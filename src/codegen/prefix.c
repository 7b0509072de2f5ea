/*
 * src/codegen/prefix.c - the prefix of generated C (qdot/codegen.h): the
 * rule a prefix follows (qd_codegen_prefix_valid, the one qd__cg_prefix
 * enforces) and the default one made from a model file's name
 * (qd_codegen_prefix_from_path), what `qdot codegen` names its files by.
 */
#include <ctype.h>
#include <string.h>
#include "qdot/codegen.h"
#include "base/args.h"
#include "cg.h"

bool qd_codegen_prefix_valid(const char *prefix) {
    QD_ARGS(false, prefix);
    bool ok = (isalpha((unsigned char)*prefix) || *prefix == '_') &&
              strlen(prefix) <= QD_CODEGEN_PREFIX_MAX;
    for (const char *s = prefix; ok && *s; s++)
        ok = isalnum((unsigned char)*s) || *s == '_';
    return ok;
}

qd_status qd_codegen_prefix_from_path(const char *path, char *out, size_t cap) {
    QD_ARGS(QD_ERR_ARG, path && out && cap > QD_CODEGEN_PREFIX_MAX);
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    if (!strcmp(path, "-"))
        base = "model";
    size_t k = 0;
    if (!isalpha((unsigned char)*base) && *base != '_')
        out[k++] = 'm';
    for (; *base && *base != '.' && k < QD_CODEGEN_PREFIX_MAX; base++)
        out[k++] = isalnum((unsigned char)*base) ? *base : '_';
    out[k] = '\0';
    return QD_OK;
}
