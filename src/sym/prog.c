/*
 * src/sym/prog.c - compile expressions into a straight-line program over
 * doubles, and run it (include/qdot/eval.h).
 *
 * Registers: the inputs first, then the constants (filled once here), then
 * temporaries.  Compilation runs over the distinct nodes in topological order:
 *   1. walk: an iterative post-order walk (deep DAGs must not overflow the C
 *      stack) lists every node reachable from the outputs; inputs are leaves.
 *      Unbound symbols and user functions are reported here.
 *   2. mark: from the outputs down, each node records what its users need:
 *      its value and/or its "alternate", which is -t for a term with a
 *      negative coefficient (so a sum subtracts instead of negating) and b^k
 *      for a factor b^-k (so a product divides instead of taking reciprocals).
 *   3. emit: constants get registers, then each needed node emits code.
 *      Passes 2 and 3 run the same generator; in pass 2 it only marks.
 *   4. registers of dead temporaries are reused, so a long program touches a
 *      small, cache-resident register file.  (Reordering instructions by
 *      level and opcode, for independent neighbours and predictable dispatch,
 *      measured no faster: the longer live ranges cost more than it gained.)
 * Node values follow qd_eval (evaltree.c): powers with small integer or
 * half-integer exponents become multiplications and square roots.
 */
#include "node.h"
#include "qdot/eval.h"
#include "base/mem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "prog_int.h"
#include "../base/args.h"

enum { NEED_VAL = 1, NEED_ALT = 2 };
enum { INNER, LEAF_INPUT, LEAF_NUMBER };

typedef struct node_info {
    const qd_expr *e;
    uint32_t val, alt; /* registers, once emitted */
    uint8_t need, leaf;
} node_info;

typedef struct reglist {
    uint32_t *r;
    size_t n, cap;
} reglist;

typedef struct comp {
    qd_ctx *ctx;
    qd__ptrmap index; /* node -> 1 + its position in nodes */
    node_info *nodes;
    size_t nnodes, nodes_cap;
    instr *code;
    size_t ncode, code_cap;
    uint32_t *opnd;
    size_t nopnd, opnd_cap;
    reglist pos, neg; /* the operands of the sum or product being generated */
    double *consts;
    size_t nconst, const_cap;
    size_t nin;
    uint32_t nreg;
    bool emit; /* pass 3; false while marking */
    bool oom;
} comp;

#define MAX_REGS 0xfffffff0u

/* arr with room for need elements (maybe moved), or NULL when out of memory. */
static void *grow(comp *c, void *arr, size_t *cap, size_t need, size_t size) {
    if (need <= *cap)
        return arr;
    size_t n = *cap ? 2 * *cap : 64;
    while (n < need)
        n *= 2;
    void *p = qd__realloc(c->ctx, arr, n * size);
    if (!p) {
        c->oom = true;
        return NULL;
    }
    *cap = n;
    return p;
}

/* ---- pass 1: the walk ---------------------------------------------------- */

static node_info *info(const comp *c, const qd_expr *e) {
    return &c->nodes[(uintptr_t)qd__ptrmap_get(&c->index, e) - 1];
}

static bool add_node(comp *c, const qd_expr *e, uint8_t leaf) {
    node_info *nodes = grow(c, c->nodes, &c->nodes_cap, c->nnodes + 1, sizeof *nodes);
    if (!nodes)
        return false;
    c->nodes = nodes;
    c->nodes[c->nnodes] = (node_info){e, 0, 0, 0, leaf};
    c->nnodes++;
    if (!qd__ptrmap_put(&c->index, e, (void *)(uintptr_t)c->nnodes))
        c->oom = true;
    return !c->oom;
}

static bool is_leaf_kind(const qd_expr *e) {
    return qd__is_num(e) || e->kind == QD_CONSTANT;
}

/* Can e be computed at all?  (It is not an input: those are indexed first.) */
static bool computable(comp *c, const qd_expr *e) {
    if (qd__is_num(e))
        return qd__number_finite(c->ctx, e);
    if (e->kind == QD_SYMBOL && e->tag == QD_ROLE_COORD && e->order >= 3) {
        qd_ctx_error(c->ctx, QD_ERR_UNBOUND,
                     "%s is a derivative of order %u: only a coordinate, its velocity (q') "
                     "and its acceleration (q'') have values", e->u.sym.name, (unsigned)e->order);
        return false;
    }
    if (e->kind == QD_SYMBOL) {
        qd_ctx_error(c->ctx, QD_ERR_UNBOUND, "'%s' has no value: it is not an input",
                     e->u.sym.name);
        return false;
    }
    if (e->kind == QD_UFUNC || e->kind == QD_UDERIV) {
        qd_ctx_error(c->ctx, QD_ERR_ARG, "the function '%s' has no numeric definition",
                     e->u.fn.name);
        return false;
    }
    return true;
}

typedef struct frame {
    const qd_expr *e;
    uint32_t next;
} frame;

#define PENDING ((void *)~(uintptr_t)0)

static bool walk_push(comp *c, frame **st, size_t *n, size_t *cap, const qd_expr *e) {
    if (qd__ptrmap_has(&c->index, e))
        return true;
    if (!computable(c, e))
        return false;
    frame *s = grow(c, *st, cap, *n + 1, sizeof *s);
    if (s)
        *st = s;
    if (!s || !qd__ptrmap_put(&c->index, e, PENDING)) {
        c->oom = true;
        return false;
    }
    (*st)[(*n)++] = (frame){e, 0};
    return true;
}

/* Post-order: a node is listed after all its arguments. */
static bool walk(comp *c, const qd_expr *root) {
    frame *st = NULL;
    size_t n = 0, cap = 0;
    bool ok = walk_push(c, &st, &n, &cap, root);
    while (ok && n) {
        frame *f = &st[n - 1];
        const qd_expr *e = f->e;
        size_t nargs = is_leaf_kind(e) ? 0 : e->nargs;
        if (f->next < nargs) {
            ok = walk_push(c, &st, &n, &cap, e->args[f->next++]);
            continue;
        }
        n--;
        ok = add_node(c, e, is_leaf_kind(e) ? LEAF_NUMBER : INNER);
    }
    qd__free(st);
    return ok;
}

/* ---- passes 2 and 3: the generator ---------------------------------------- */

static uint32_t use(comp *c, const qd_expr *e, int which) {
    node_info *n = info(c, e);
    if (!c->emit) {
        n->need |= (uint8_t)which;
        return 0;
    }
    return which == NEED_ALT ? n->alt : n->val;
}

static uint32_t emit(comp *c, op o, uint32_t a, uint32_t b) {
    if (!c->emit)
        return 0;
    instr *code = grow(c, c->code, &c->code_cap, c->ncode + 1, sizeof *code);
    if (!code || c->nreg >= MAX_REGS) {
        c->oom = true;
        return 0;
    }
    c->code = code;
    c->code[c->ncode++] = (instr){o, c->nreg, {a, b}};
    return c->nreg++;
}

static void push(comp *c, reglist *l, uint32_t r) {
    uint32_t *a = grow(c, l->r, &l->cap, l->n + 1, sizeof *a);
    if (!a)
        return;
    l->r = a;
    l->r[l->n++] = r;
}

static uint32_t emit_nary(comp *c, op o) {
    size_t np = c->pos.n, nn = c->neg.n, at = c->nopnd, h = o == OP_SUMN || o == OP_PRODN ? 2 : 0;
    if (!c->emit)
        return 0;
    uint32_t *a = grow(c, c->opnd, &c->opnd_cap, at + h + np + nn, sizeof *a);
    if (!a || at > MAX_REGS) {
        c->oom = true;
        return 0;
    }
    c->opnd = a;
    if (h) {
        a[at] = (uint32_t)np;
        a[at + 1] = (uint32_t)nn;
    }
    if (np)
        memcpy(a + at + h, c->pos.r, np * sizeof *a);
    if (nn)
        memcpy(a + at + h + np, c->neg.r, nn * sizeof *a);
    c->nopnd = at + h + np + nn;
    return emit(c, o, (uint32_t)at, (uint32_t)at);
}

/* The sum (or product) of c->pos minus (over) c->neg, with the short cases
 * as binary instructions. */
static uint32_t combine(comp *c, bool prod) {
    size_t np = c->pos.n, nn = c->neg.n;
    const uint32_t *p = c->pos.r, *n = c->neg.r;
    if (np == 1 && nn == 0)
        return p[0];
    if (np == 2 && nn == 0)
        return emit(c, prod ? OP_MUL : OP_ADD, p[0], p[1]);
    if (np == 1 && nn == 1)
        return emit(c, prod ? OP_DIV : OP_SUB, p[0], n[0]);
    if (np == 0 && nn == 1)
        return emit(c, prod ? OP_RECIP : OP_NEG, n[0], n[0]);
    if (np == 3 && nn == 0)
        return emit_nary(c, prod ? OP_MUL3 : OP_ADD3);
    return emit_nary(c, prod ? OP_PRODN : OP_SUMN);
}

static bool is_input(const comp *c, const qd_expr *e) {
    return info(c, e)->leaf == LEAF_INPUT;
}

/* Twice the exponent of a power with a small integer or half-integer
 * exponent, else 0.  qd__pow_value's limit |e| <= 64 is kept. */
static long pow_twice(const qd_expr *e) {
    if (e->kind != QD_POW || !qd__is_num(e->args[1]))
        return 0;
    double k = 2 * qd_number_value(e->args[1]);
    return k == (double)(long)k && fabs(k) <= 128 ? (long)k : 0;
}

/* Is e best used as -(its alternate) in a sum? */
static bool neg_alt(const comp *c, const qd_expr *e) {
    if (is_input(c, e))
        return false;
    if (qd__is_num(e))
        return qd_number_sign(e) < 0;
    return e->kind == QD_MUL && qd__is_num(e->args[0]) && qd_number_sign(e->args[0]) < 0;
}

/* Is e best used as 1/(its alternate) in a product? */
static bool inv_alt(const comp *c, const qd_expr *e) {
    return !is_input(c, e) && pow_twice(e) < 0;
}

/* x^n, n >= 1, by the binary method of qd__pow_value. */
static uint32_t powi(comp *c, uint32_t x, unsigned long n) {
    uint32_t r = 0;
    bool have = false;
    for (; n; n >>= 1) {
        if (n & 1) {
            r = have ? emit(c, OP_MUL, r, x) : x;
            have = true;
        }
        if (n > 1)
            x = emit(c, OP_MUL, x, x);
    }
    return r;
}

/* b^(k/2), k >= 1. */
static uint32_t power(comp *c, const qd_expr *b, long k) {
    uint32_t x = use(c, b, NEED_VAL);
    if (!(k & 1))
        return powi(c, x, (unsigned long)k / 2);
    uint32_t s = emit(c, OP_SQRT, x, x);
    return k == 1 ? s : emit(c, OP_MUL, powi(c, x, (unsigned long)k / 2), s);
}

/* coef * e->args[from] * ..., dividing by the negative powers. */
static uint32_t product(comp *c, const qd_expr *e, size_t from, bool has_coef, uint32_t coef) {
    c->pos.n = c->neg.n = 0;
    if (has_coef)
        push(c, &c->pos, coef);
    for (size_t i = from; i < e->nargs; i++) {
        const qd_expr *f = e->args[i];
        if (inv_alt(c, f))
            push(c, &c->neg, use(c, f, NEED_ALT));
        else
            push(c, &c->pos, use(c, f, NEED_VAL));
    }
    return combine(c, true);
}

static uint32_t gen_add(comp *c, const qd_expr *e) {
    c->pos.n = c->neg.n = 0;
    for (size_t i = 0; i < e->nargs; i++) {
        const qd_expr *t = e->args[i];
        if (neg_alt(c, t))
            push(c, &c->neg, use(c, t, NEED_ALT));
        else
            push(c, &c->pos, use(c, t, NEED_VAL));
    }
    return combine(c, false);
}

static uint32_t gen_mul(comp *c, const qd_expr *e, uint8_t need) {
    const qd_expr *k = e->args[0];
    bool hk = qd__is_num(k);
    if (hk && qd_number_sign(k) < 0) {
        if (need & NEED_ALT) { /* -(|k| * rest), already computed */
            uint32_t a = use(c, e, NEED_ALT);
            return emit(c, OP_NEG, a, a);
        }
        if (qd_number_value(k) == -1) {
            uint32_t a = product(c, e, 1, false, 0);
            return emit(c, OP_NEG, a, a);
        }
    }
    return product(c, e, hk ? 1 : 0, hk, hk ? use(c, k, NEED_VAL) : 0);
}

static uint32_t gen_val(comp *c, const qd_expr *e, uint8_t need) {
    switch ((qd_kind)e->kind) {
    case QD_ADD:
        return gen_add(c, e);
    case QD_MUL:
        return gen_mul(c, e, need);
    case QD_POW: {
        long k = pow_twice(e);
        if (k < 0) {
            uint32_t a = use(c, e, NEED_ALT);
            return emit(c, OP_RECIP, a, a);
        }
        if (k > 0)
            return power(c, e->args[0], k);
        return emit(c, OP_POW, use(c, e->args[0], NEED_VAL), use(c, e->args[1], NEED_VAL));
    }
    case QD_FUNC: {
        uint32_t a = use(c, e->args[0], NEED_VAL);
        uint32_t b = e->nargs > 1 ? use(c, e->args[1], NEED_VAL) : a;
        return emit(c, (op)(OP_SIN + e->tag), a, b);
    }
    default: /* leaves are never generated; the walk refused the rest */
        return 0;
    }
}

/* The alternate: |k| * rest for a product with k < 0, b^k for b^-k. */
static uint32_t gen_alt(comp *c, const qd_expr *e) {
    if (e->kind == QD_POW)
        return power(c, e->args[0], -pow_twice(e));
    const qd_expr *k = e->args[0];
    if (qd_number_value(k) == -1)
        return product(c, e, 1, false, 0);
    return product(c, e, 1, true, use(c, k, NEED_ALT));
}

static void mark(comp *c) {
    c->emit = false;
    for (size_t i = c->nnodes; i-- > 0;) {
        node_info *n = &c->nodes[i];
        if (n->leaf != INNER)
            continue;
        if (n->need & NEED_VAL)
            gen_val(c, n->e, n->need); /* may mark the node's own alternate */
        if (n->need & NEED_ALT)
            gen_alt(c, n->e);
    }
}

static double leaf_value(const qd_expr *e) {
    if (e->kind == QD_CONSTANT)
        return e->tag == QD_PI ? 3.14159265358979323846 : 2.71828182845904523536;
    return qd_number_value(e);
}

static uint32_t add_const(comp *c, double v) {
    double *consts = grow(c, c->consts, &c->const_cap, c->nconst + 1, sizeof *consts);
    if (!consts)
        return 0;
    c->consts = consts;
    c->consts[c->nconst++] = v;
    return c->nreg++;
}

static void generate(comp *c) {
    c->emit = true;
    c->nreg = (uint32_t)c->nin;
    for (size_t i = 0; i < c->nnodes; i++) {
        node_info *n = &c->nodes[i];
        if (n->leaf != LEAF_NUMBER)
            continue;
        if (n->need & NEED_VAL)
            n->val = add_const(c, leaf_value(n->e));
        if (n->need & NEED_ALT)
            n->alt = add_const(c, -leaf_value(n->e));
    }
    for (size_t i = 0; i < c->nnodes && !c->oom; i++) {
        node_info *n = &c->nodes[i];
        if (n->leaf != INNER)
            continue;
        if (n->need & NEED_ALT)
            n->alt = gen_alt(c, n->e);
        if (n->need & NEED_VAL)
            n->val = gen_val(c, n->e, n->need);
    }
}

/* The registers instruction in reads. */
static uint32_t *operands(const qd_prog *p, instr *in, size_t *n) {
    if (in->op == OP_ADD3 || in->op == OP_MUL3) {
        *n = 3;
        return p->opnd + in->arg[0];
    }
    if (in->op != OP_SUMN && in->op != OP_PRODN) {
        *n = 2;
        return in->arg;
    }
    uint32_t *a = p->opnd + in->arg[0];
    *n = (size_t)a[0] + a[1];
    return a + 2;
}

/* ---- pass 4: register reuse ------------------------------------------------ */

#define FREED (SIZE_MAX - 1)

/* Linear scan: a temporary's register is free after its last reader.  An
 * instruction may write a register it reads: it reads them all first. */
static void reassign(qd_prog *p, uint32_t nfixed, size_t *last, uint32_t *map, uint32_t *freel) {
    uint32_t top = nfixed, nfree = 0;
    for (uint32_t r = 0; r < nfixed; r++)
        map[r] = r;
    for (size_t j = 0; j < p->ncode; j++) {
        instr *in = &p->code[j];
        size_t n;
        uint32_t *a = operands(p, in, &n), d = in->dst;
        for (size_t k = 0; k < n; k++) {
            uint32_t r = a[k];
            a[k] = map[r];
            if (r >= nfixed && last[r] == j) {
                freel[nfree++] = map[r];
                last[r] = FREED; /* a register read twice is freed once */
            }
        }
        in->dst = map[d] = nfree ? freel[--nfree] : top++;
        if (last[d] == j) /* never read */
            freel[nfree++] = map[d];
    }
    for (size_t k = 0; k < p->nout; k++)
        p->out[k] = map[p->out[k]];
    p->nreg = top;
}

static bool reuse_registers(qd_ctx *ctx, qd_prog *p, uint32_t nfixed) {
    size_t n = p->nreg, *last = qd__calloc(ctx, n, sizeof *last);
    uint32_t *map = qd__malloc(ctx, n * sizeof *map), *freel = qd__malloc(ctx, n * sizeof *freel);
    bool ok = last && map && freel;
    if (ok) {
        for (size_t j = 0; j < p->ncode; j++) {
            size_t na;
            uint32_t *a = operands(p, &p->code[j], &na);
            last[p->code[j].dst] = j;
            for (size_t k = 0; k < na; k++)
                last[a[k]] = j;
        }
        for (size_t k = 0; k < p->nout; k++)
            last[p->out[k]] = SIZE_MAX;
        reassign(p, nfixed, last, map, freel);
    }
    qd__free(last);
    qd__free(map);
    qd__free(freel);
    return ok;
}

/* ---- the public interface -------------------------------------------------- */

static bool index_inputs(comp *c, size_t nin, const qd_expr *const *inputs) {
    for (size_t i = 0; i < nin; i++) {
        if (!inputs[i]) {
            qd_ctx_error(c->ctx, QD_ERR_ARG, "input %zu of a program is NULL", i);
            return false;
        }
        if (qd__ptrmap_has(&c->index, inputs[i])) { /* a repeated input: the last wins */
            info(c, inputs[i])->val = (uint32_t)i;
            continue;
        }
        if (!add_node(c, inputs[i], LEAF_INPUT))
            return false;
        c->nodes[c->nnodes - 1].val = (uint32_t)i;
    }
    return true;
}

static bool compile(comp *c, size_t nin, const qd_expr *const *inputs, size_t nout,
                    const qd_expr *const *outputs) {
    if (nin >= MAX_REGS) {
        qd_ctx_error(c->ctx, QD_ERR_TOOBIG, "too many inputs");
        return false;
    }
    if (!index_inputs(c, nin, inputs))
        return false;
    for (size_t i = 0; i < nout; i++) {
        if (!outputs[i]) {
            qd_ctx_error(c->ctx, QD_ERR_ARG, "output %zu of a program is NULL", i);
            return false;
        }
        if (!walk(c, outputs[i]))
            return false;
        info(c, outputs[i])->need |= NEED_VAL;
    }
    mark(c);
    generate(c);
    return !c->oom;
}

static qd_prog *assemble(comp *c, size_t nout, const qd_expr *const *outputs) {
    qd_prog *p = qd__calloc(c->ctx, 1, sizeof *p);
    if (!p)
        return NULL;
    p->nin = c->nin;
    p->nout = nout;
    p->ncode = c->ncode;
    p->nreg = c->nreg;
    p->code = c->code;
    c->code = NULL;
    p->opnd = c->opnd;
    c->opnd = NULL;
    p->out = qd__malloc(c->ctx, (nout ? nout : 1) * sizeof *p->out);
    if (p->out)
        for (size_t k = 0; k < nout; k++)
            p->out[k] = info(c, outputs[k])->val;
    uint32_t nfixed = (uint32_t)(c->nin + c->nconst);
    if (!p->out || !reuse_registers(c->ctx, p, nfixed) ||
        !(p->regs = qd__calloc(c->ctx, p->nreg ? p->nreg : 1, sizeof *p->regs))) {
        qd_prog_free(p);
        return NULL;
    }
    p->nconst = c->nconst;
    p->consts = c->consts;
    c->consts = NULL;
    qd_prog_work_init(p, p->regs);
    return p;
}

qd_prog *qd_prog_new(qd_ctx *ctx, size_t nin, const qd_expr *const *inputs, size_t nout,
                     const qd_expr *const *outputs) {
    if (!ctx)
        return NULL;
    if ((nin && !inputs) || (nout && !outputs)) {
        qd_ctx_error(ctx, QD_ERR_ARG, "a program needs its input and output arrays");
        return NULL;
    }
    comp c = {.ctx = ctx, .index = QD_PTRMAP_AL(qd__ctx_allocator(ctx)), .nin = nin};
    qd_prog *p = NULL;
    if (compile(&c, nin, inputs, nout, outputs))
        p = assemble(&c, nout, outputs);
    if (!p && (c.oom || ctx->status == QD_OK))
        qd__oom(ctx);
    qd__ptrmap_free(&c.index);
    qd__free(c.nodes);
    qd__free(c.code);
    qd__free(c.opnd);
    qd__free(c.consts);
    qd__free(c.pos.r);
    qd__free(c.neg.r);
    return p;
}

void qd_prog_free(qd_prog *p) {
    if (!p)
        return;
    qd__prog_jit_release(p);
    qd__free(p->code);
    qd__free(p->opnd);
    qd__free(p->regs);
    qd__free(p->consts);
    qd__free(p->out);
    qd__free(p);
}

size_t qd_prog_ninstr(const qd_prog *p) { return p ? p->ncode : 0; }

static double sumn(const double *r, const uint32_t *a) {
    size_t np = a[0], n = np + a[1], k = 1;
    a += 2;
    double s = np ? r[a[0]] : -r[a[0]];
    for (; k < np; k++)
        s += r[a[k]];
    for (; k < n; k++)
        s -= r[a[k]];
    return s;
}

static double prodn(const double *r, const uint32_t *a) {
    size_t np = a[0], n = np + a[1], k = 1;
    a += 2;
    double m = np ? r[a[0]] : 1.0;
    for (; k < np; k++)
        m *= r[a[k]];
    if (np == n)
        return m;
    double d = r[a[np]];
    for (k = np + 1; k < n; k++)
        d *= r[a[k]];
    return m / d;
}

size_t qd_prog_work_size(const qd_prog *p) { QD_ARGS(0, p); return p && p->nreg ? p->nreg : 1; }

/* The constants sit in the registers after the inputs, which no
 * instruction overwrites (reuse_registers keeps them fixed): copying them
 * once makes the workspace ready for any number of runs. */
void qd_prog_work_init(const qd_prog *p, double *work) {
    QD_ARGS(, p && work);
    if (!p)
        return;
    memset(work, 0, qd_prog_work_size(p) * sizeof *work);
    if (p->nconst)
        memcpy(work + p->nin, p->consts, p->nconst * sizeof *work);
}

void qd_prog_run(qd_prog *p, const double *in, double *out) {
    if (p)
        qd_prog_eval(p, p->regs, in, out);
}

/* The hot loop: one switch per instruction, the common operations inline. */
void qd_prog_eval(const qd_prog *p, double *work, const double *in, double *out) {
    QD_ARGS(, p && work && in && out);
    if (!p)
        return;
    qd__jit_fn jit = atomic_load_explicit(&p->jit, memory_order_acquire);
    if (jit) { /* the same numbers, bit for bit (src/sym/jit.h) */
        jit(in, out);
        return;
    }
    double *r = work;
    const uint32_t *opnd = p->opnd;
    if (p->nin)
        memcpy(r, in, p->nin * sizeof *r);
#define X r[i->arg[0]]
#define Y r[i->arg[1]]
    /* (no pointer arithmetic on an empty program's NULL code) */
    const instr *end = p->ncode ? p->code + p->ncode : p->code;
    for (const instr *i = p->code; i < end; i++) {
        switch ((op)i->op) {
        case OP_ADD: r[i->dst] = X + Y; break;
        case OP_SUB: r[i->dst] = X - Y; break;
        case OP_MUL: r[i->dst] = X * Y; break;
        case OP_DIV: r[i->dst] = X / Y; break;
        case OP_NEG: r[i->dst] = -X; break;
        case OP_RECIP: r[i->dst] = 1 / X; break;
        case OP_SQRT: r[i->dst] = sqrt(X); break;
        case OP_POW: r[i->dst] = qd__pow_value(X, Y); break;
        case OP_ADD3: {
            const uint32_t *a = opnd + i->arg[0];
            r[i->dst] = r[a[0]] + r[a[1]] + r[a[2]];
            break;
        }
        case OP_MUL3: {
            const uint32_t *a = opnd + i->arg[0];
            r[i->dst] = r[a[0]] * r[a[1]] * r[a[2]];
            break;
        }
        case OP_SUMN: r[i->dst] = sumn(r, opnd + i->arg[0]); break;
        case OP_PRODN: r[i->dst] = prodn(r, opnd + i->arg[0]); break;
        case OP_SIN: r[i->dst] = sin(X); break;
        case OP_COS: r[i->dst] = cos(X); break;
        case OP_TAN: r[i->dst] = tan(X); break;
        case OP_ASIN: r[i->dst] = asin(X); break;
        case OP_ACOS: r[i->dst] = acos(X); break;
        case OP_ATAN: r[i->dst] = atan(X); break;
        case OP_ATAN2: r[i->dst] = atan2(X, Y); break;
        case OP_SINH: r[i->dst] = sinh(X); break;
        case OP_COSH: r[i->dst] = cosh(X); break;
        case OP_TANH: r[i->dst] = tanh(X); break;
        case OP_EXP: r[i->dst] = exp(X); break;
        case OP_LOG: r[i->dst] = log(X); break;
        case OP_ABS: r[i->dst] = fabs(X); break;
        case OP_SIGN: r[i->dst] = (X > 0) - (X < 0); break;
        case OP_STEP: r[i->dst] = qd__step_value(X); break;
        }
    }
#undef X
#undef Y
    for (size_t k = 0; k < p->nout; k++)
        out[k] = r[p->out[k]];
}
