/*
 * src/group/symmetry.c - a symmetry group's classes, character table,
 * Schoenflies name and Mulliken labels from its Cayley table
 * (qd_group_characters, qdot/symmetry.h): the group module's analysis
 * (group.c, characters.c, pointgroup.c) in a qd_symmetry without
 * operations (n = 0, S NULL).
 */
#include "group.h"
#include "qdot/symmetry.h"

#include "../base/mem.h"
#include "../base/args.h"

#include <stdio.h>
#include <string.h>

static qd_status copy_classes(qd_ctx *ctx, qd_symmetry *s, const qd__group *grp) {
    size_t k = grp->nclass;
    s->nclass = k;
    s->class_of = qd__malloc(ctx, (s->order + 1) * sizeof *s->class_of);
    s->class_size = qd__malloc(ctx, (k + 1) * sizeof *s->class_size);
    s->class_rep = qd__malloc(ctx, (k + 1) * sizeof *s->class_rep);
    if (!s->class_of || !s->class_size || !s->class_rep)
        return QD_ERR_NOMEM;
    memcpy(s->class_of, grp->class_of, s->order * sizeof *s->class_of);
    memcpy(s->class_size, grp->class_size, k * sizeof *s->class_size);
    memcpy(s->class_rep, grp->class_rep, k * sizeof *s->class_rep);
    return QD_OK;
}

static qd_status copy_characters(qd_ctx *ctx, qd_symmetry *s, const qd__chartab *t) {
    size_t ni = t->n, nc = s->nclass;
    s->nirrep = ni;
    s->irrep_dim = qd__malloc(ctx, (ni + 1) * sizeof *s->irrep_dim);
    s->chi_re = qd__malloc(ctx, (ni * nc + 1) * sizeof *s->chi_re);
    s->chi_im = qd__malloc(ctx, (ni * nc + 1) * sizeof *s->chi_im);
    s->label = qd__calloc(ctx, ni + 1, sizeof *s->label);
    if (!s->irrep_dim || !s->chi_re || !s->chi_im || !s->label)
        return QD_ERR_NOMEM;
    memcpy(s->irrep_dim, t->dim, ni * sizeof *s->irrep_dim);
    memcpy(s->chi_re, t->re, ni * nc * sizeof *s->chi_re);
    memcpy(s->chi_im, t->im, ni * nc * sizeof *s->chi_im);
    return QD_OK;
}

/* Name and labels; an abstract group's irreps are G1, G2, ... when the
 * group module has no labels for it. */
static qd_status names(qd_ctx *ctx, qd_symmetry *s, const qd__group *grp,
                       const qd__chartab *t) {
    s->name[0] = 0;
    if (s->geometric && qd__group_pointgroup_name(ctx, grp, s->R, s->name) != QD_OK) {
        if (!qd__ctx_recover(ctx))
            return QD_ERR_NOMEM;
        s->name[0] = 0;
    }
    if (qd__group_irrep_labels(ctx, grp, s->geometric ? s->R : NULL, t, s->label) == QD_OK)
        return QD_OK;
    if (!qd__ctx_recover(ctx))
        return QD_ERR_NOMEM;
    for (size_t i = 0; i < s->nirrep; i++)
        snprintf(s->label[i], sizeof s->label[i], "G%u", (unsigned)(i + 1) % 1000000u);
    return QD_OK;
}

/* What this file allocated in out, on failure. */
static void release(qd_symmetry *out) {
    void *arrays[] = {out->R, out->table, out->class_of, out->class_size, out->class_rep,
                      out->irrep_dim, out->chi_re, out->chi_im, out->label};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++)
        qd__free(arrays[i]);
    memset(out, 0, sizeof *out);
}

qd_status qd_group_characters(qd_ctx *ctx, size_t order, const size_t *table, const double *R,
                              qd_symmetry *out) {
    QD_ARGS_CTX(ctx, ctx && table && out);
    memset(out, 0, sizeof *out);
    qd__group grp = {0};
    qd__chartab tab = {0};
    qd_status st = qd__group_from_table(ctx, order, table, &grp);
    if (st == QD_OK) {
        out->order = order;
        out->geometric = R != NULL;
        out->table = qd__malloc(ctx, (order * order + 1) * sizeof *out->table);
        out->R = R ? qd__malloc(ctx, (order * 9 + 1) * sizeof *out->R) : NULL;
        if (!out->table || (R && !out->R))
            st = QD_ERR_NOMEM;
    }
    if (st == QD_OK) {
        memcpy(out->table, table, order * order * sizeof *out->table);
        if (R)
            memcpy(out->R, R, order * 9 * sizeof *out->R);
        st = copy_classes(ctx, out, &grp);
    }
    if (st == QD_OK)
        st = qd__group_characters(ctx, &grp, &tab);
    if (st == QD_OK)
        st = copy_characters(ctx, out, &tab);
    if (st == QD_OK)
        st = names(ctx, out, &grp, &tab);
    qd__group_chartab_free(&tab);
    qd__group_free(&grp);
    if (st != QD_OK)
        release(out);
    return st;
}
