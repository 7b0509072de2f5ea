# python/qdot/appendix.py - the mathematical tools of Desloge's appendices
# that are not quadratic forms (forms.py): Gram-Schmidt (App. 21), the
# change of variables in an integral (App. 19).
"""qdot.gram_schmidt(expr, variables, vectors) or qdot.gram_schmidt(model): the
orthogonalization of vectors under a form's matrix, or of a model's
coordinate tangents under its kinetic metric (Desloge App. 21);
qdot.change_of_variables(expr, variables, change, new): the Jacobian of
x = x(y) and the integrand f(x(y)) |J| (App. 19); qdot.condensed(model, Q, P):
a map in the condensed notation of ch. 75; qdot.fourier(expr, variables): a
trigonometric polynomial as a sum of harmonics (App. 31)."""

import json

from ._lib import ffi, lib, new, buf_text, cstr
from ._core import Error


class GramSchmidt:
    """Vectors orthogonalized (qd_gram_schmidt, Desloge App. 21): vectors
    (the a's) and orthogonal (the b's), rows of texts; norms (b^T T b);
    coefficients (a(r)'s components along b(j), j < r); metric (T's rows,
    None for the identity); euclidean; json() the dict of `qdot form
    --gram-schmidt --format json` (or `qdot metric --gram-schmidt`), text()
    its text."""

    __module__ = "qdot"

    def __init__(self, printed):
        self._printed = printed
        d = json.loads(printed[1])
        self.vectors, self.orthogonal, self.norms = d["vectors"], d["orthogonal"], d["norms"]
        self.coefficients, self.metric, self.euclidean = (d["coefficients"], d["metric"],
                                                          d["euclidean"])

    def text(self):
        return self._printed[0]

    def json(self):
        return json.loads(self._printed[1])

    def __repr__(self):
        return "GramSchmidt(orthogonal=%r)" % (self.orthogonal,)


def _printed(ctx, g, x, T):
    out = []
    for fmt in (lib.QD_RENDER_TEXT, lib.QD_RENDER_JSON):
        buf = new("qd_buf")
        if lib.qd_render_gram(ctx, g, x, T, fmt, buf) != 0:
            lib.qd_buf_free(buf)
            raise Error(cstr(lib.qd_ctx_message(ctx)))
        out.append(buf_text(buf))
    return tuple(out)


def _of_model(model):
    core = model._for("metric")
    m = lib.qd_metric_new(core.ctx, core.model)
    if not m:
        raise core.error()
    try:
        g = lib.qd_metric_gram_schmidt(core.ctx, m)
        if not g:
            raise core.error()
        try:
            return GramSchmidt(_printed(core.ctx, g, m.q, m.g))
        finally:
            lib.qd_gram_free(g)
    finally:
        lib.qd_metric_free(m)


def gram_schmidt(expr, variables=None, vectors=None):
    """The vectors (a list of vectors, each a list of model-language texts,
    one per variable; or the --gram-schmidt text "1, 1, 0; 1, 0, 1")
    orthogonalized under the matrix of the quadratic form expr in the named
    variables (`qdot form EXPR --vars ... --gram-schmidt ...`; Thm 1 when
    it is x^2 + y^2 + ...); or, given a qdot.Model, its coordinate tangents
    under the kinetic metric g_ij (`qdot metric FILE --gram-schmidt`): a
    GramSchmidt.  ValueError for a bad variable or vector, qdot.Error for
    dependent vectors or a null vector of an indefinite form."""
    if hasattr(expr, "_for"):
        return _of_model(expr)
    if variables is None or vectors is None:
        raise TypeError("gram_schmidt(expr, variables, vectors), or gram_schmidt(model)")
    if not isinstance(vectors, str):
        vectors = "; ".join(", ".join(str(c) for c in v) for v in vectors)
    if isinstance(variables, str):
        variables = [variables]
    ctx = lib.qd_ctx_new()
    if not ctx:
        raise MemoryError("qdot: out of memory")
    w = ffi.new("const qd_expr ***")
    f = g = ffi.NULL
    try:
        diag = new("qd_diag")
        phi = lib.qd_read(ctx, expr.encode(), ffi.NULL, diag)
        if not phi:
            raise Error(ffi.string(diag.message).decode() or "cannot read the form")
        xs = ffi.new("const qd_expr *[]", max(1, len(variables)))
        n, s = ffi.new("size_t *"), ffi.new("size_t *")
        if lib.qd_qform_vars_read(ctx, ", ".join(variables).encode(), xs, len(variables), n) != 0:
            raise ValueError(cstr(lib.qd_ctx_message(ctx)))
        if lib.qd_periods_vectors_read(ctx, vectors.encode(), n[0], s, w) != 0:
            raise ValueError(cstr(lib.qd_ctx_message(ctx)))
        f = lib.qd_qform_reduce(ctx, phi, n[0], xs)
        if not f:
            raise Error(cstr(lib.qd_ctx_message(ctx)))
        g = lib.qd_gram_schmidt(ctx, n[0], f.a, s[0], w[0])
        if not g:
            raise Error(cstr(lib.qd_ctx_message(ctx)))
        return GramSchmidt(_printed(ctx, g, xs, f.a))
    finally:
        lib.qd_gram_free(g)
        lib.qd_qform_free(f)
        if w[0] != ffi.NULL:
            lib.qd_periods_vectors_free(w[0])
        lib.qd_ctx_free(ctx)


class ChangeOfVariables:
    """A change of variables in an integral (qd_change_vars, Desloge App. 19):
    jacobian (rows dx_i/dy_j), jacobian_det J(x/y), inverse_det J(y/x),
    sign ("nonnegative", "nonpositive", "unknown"), abs_det |J|, integrand
    f(x(y)) |J|, singular (the zeros of J: {"lhs", "rhs", "period"}), all
    texts; json() the dict of `qdot form --change --format json`, text()
    its text."""

    __module__ = "qdot"

    def __init__(self, printed):
        self._printed = printed
        d = json.loads(printed[1])
        self.jacobian, self.jacobian_det, self.inverse_det = (d["jacobian"], d["jacobian_det"],
                                                              d["inverse_det"])
        self.sign, self.abs_det, self.integrand = d["sign"], d["abs_det"], d["integrand"]
        self.singular = d["singular"]

    def text(self):
        return self._printed[0]

    def json(self):
        return json.loads(self._printed[1])

    def __repr__(self):
        return "ChangeOfVariables(J=%s, integrand=%s)" % (self.jacobian_det, self.integrand)


_alloc = new  # change_of_variables's argument new is the new variables


def _names(ctx, reader, text, cap):
    xs = ffi.new("const qd_expr *[]", max(1, cap))
    n = ffi.new("size_t *")
    if reader(ctx, text.encode(), xs, cap, n) != 0:
        raise ValueError(cstr(lib.qd_ctx_message(ctx)))
    return xs, n[0]


def change_of_variables(expr, variables, change, new, positive=None):
    """The integral of expr (model-language text) in the named variables
    under the change (text "x = r*cos(th), y = r*sin(th)", or a dict
    {"x": "r*cos(th)", ...}) to the new variables (`qdot form EXPR --vars
    ... --change ... --new ... [--positive ...]`): a ChangeOfVariables.
    positive: names assumed positive (for J's sign: "r, b" or a list).
    ValueError for a bad name or change, qdot.Error when J = 0 everywhere."""
    join = lambda v: v if isinstance(v, str) else ", ".join(v)  # noqa: E731
    if isinstance(change, dict):
        change = ", ".join("%s = %s" % kv for kv in change.items())
    ctx = lib.qd_ctx_new()
    if not ctx:
        raise MemoryError("qdot: out of memory")
    c = ffi.NULL
    try:
        if positive:
            _names(ctx, lib.qd_qform_positive_read, join(positive), 64)
        diag = _alloc("qd_diag")
        f = lib.qd_read(ctx, expr.encode(), ffi.NULL, diag)
        if not f:
            raise Error(ffi.string(diag.message).decode() or "cannot read the integrand")
        xs, n = _names(ctx, lib.qd_qform_vars_read, join(variables), 64)
        ys, m = _names(ctx, lib.qd_qform_vars_read, join(new), 64)
        if m != n:
            raise ValueError("%d new variables for %d old ones" % (m, n))
        maps = ffi.new("const qd_expr *[]", max(1, n))
        if lib.qd_change_read(ctx, change.encode(), n, xs, maps) != 0:
            raise ValueError(cstr(lib.qd_ctx_message(ctx)))
        c = lib.qd_change_vars(ctx, f, n, xs, ys, maps)
        if not c:
            raise Error(cstr(lib.qd_ctx_message(ctx)))
        out = []
        for fmt in (lib.QD_RENDER_TEXT, lib.QD_RENDER_JSON):
            buf = _alloc("qd_buf")
            if lib.qd_render_change(ctx, c, fmt, buf) != 0:
                lib.qd_buf_free(buf)
                raise Error(cstr(lib.qd_ctx_message(ctx)))
            out.append(buf_text(buf))
        return ChangeOfVariables(tuple(out))
    finally:
        lib.qd_change_free(c)
        lib.qd_ctx_free(ctx)


def condensed(model, Q, P):
    """The map (q, p) -> (Q, P) of a qdot.Model in Desloge's condensed
    notation (ch. 75; qd_phase_condensed, `qdot canonical FILE --Q ... --P
    ... --condensed`): a qdot.Output with the keys of its JSON: r, R,
    lambda, mu, grad_H and r_dot (Hamilton's equations r' = mu grad H, None
    for an implicit H), jacobian (dR/dr), lagrange (M^T mu M), jacobian_det,
    verdict ("canonical", "scaled", "not canonical", "undecided"), scale,
    entry, value, should_be and the zero test's keys.  Q, P: "Q1, ..." text
    or a list, as Model.canonical takes them; a "no" is an answer."""
    from . import commands as _commands
    core = model._for("canonical")
    ph = _alloc("qd_phase")
    try:
        core.check(lib.qd_phase_init(core.ctx, core.model, ph))
        q, p = model._phase_list(ph, Q, "Q", core), model._phase_list(ph, P, "P", core)
        cd = _alloc("qd_condensed")
        st = lib.qd_phase_condensed(core.ctx, ph, q, p, cd)
        if st != 0:
            raise core.error(st)
        try:
            return _commands.output(core, "canonical", lambda buf: lib.qd_condensed_print(
                core.ctx, cd, True, buf))
        finally:
            lib.qd_condensed_free(cd)
    finally:
        lib.qd_phase_free(ph)


def fourier(expr, variables):
    """expr (model-language text), a trigonometric polynomial in the named
    variables, as a sum of harmonics a cos(k.x) + b sin(k.x) (qd_fourier_series,
    `qdot form EXPR --vars ... --fourier`, Desloge App. 31): the dict of its
    JSON, "harmonics" a list of {"k", "argument", "cos", "sin"}.  ValueError
    for a bad variable, qdot.Error for an expr that is no such polynomial."""
    join = lambda v: v if isinstance(v, str) else ", ".join(v)  # noqa: E731
    ctx = lib.qd_ctx_new()
    if not ctx:
        raise MemoryError("qdot: out of memory")
    fs = ffi.NULL
    try:
        diag = _alloc("qd_diag")
        f = lib.qd_read(ctx, expr.encode(), ffi.NULL, diag)
        if not f:
            raise Error(ffi.string(diag.message).decode() or "cannot read the function")
        xs, n = _names(ctx, lib.qd_qform_vars_read, join(variables), 64)
        fs = lib.qd_fourier_series(ctx, f, n, xs)
        if not fs:
            raise Error(cstr(lib.qd_ctx_message(ctx)))
        buf = _alloc("qd_buf")
        if lib.qd_render_fourier(ctx, fs, f, xs, lib.QD_RENDER_JSON, buf) != 0:
            lib.qd_buf_free(buf)
            raise Error(cstr(lib.qd_ctx_message(ctx)))
        return json.loads(buf_text(buf))
    finally:
        lib.qd_fourier_free(fs)
        lib.qd_ctx_free(ctx)
