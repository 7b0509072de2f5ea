# python/qdot/forms.py - quadratic forms: Lagrange's reduction to a sum of
# squares and Sylvester's inertia (qd_qform_reduce; Desloge App. 27).
"""qdot.quadratic_form(expr, variables): the reduction of a quadratic form;
qdot.homogeneity, qdot.periods (App. 20, App. 31); qdot.tour(): the kernel's tour."""

import json

from ._lib import ffi, lib, new, buf_text, cstr, exprs, QD_FMT_TEXT
from ._core import ArgumentError, Error, format_diag, take_error


class QuadraticForm:
    """phi = sum coefficients[k] * linear_forms[k]^2 (texts), matrix (rows of
    texts), inertia (n+, n-, n0) or None when undecided, kind, rank."""

    __module__ = "qdot"

    def __init__(self, matrix, coefficients, linear_forms, inertia, kind, paired):
        self.matrix, self.coefficients, self.linear_forms = matrix, coefficients, linear_forms
        self.inertia, self.kind, self.paired = inertia, kind, paired
        self.rank = len(coefficients)

    _printed = ("", "{}")  # (text, JSON) of qd_render_qform, set by quadratic_form

    def text(self):
        """The reduction as `qdot form` prints it (qdot/render.h)."""
        return self._printed[0]

    def json(self):
        """The reduction as a dict (`qdot form --format json`)."""
        return json.loads(self._printed[1])

    def _repr_html_(self):
        from . import display
        return display.fields(self.json(), "qdot form")

    def __repr__(self):
        return "QuadraticForm(%s, inertia=%r)" % (" + ".join(
            "(%s)*(%s)^2" % (c, y) for c, y in zip(self.coefficients, self.linear_forms)) or "0",
            self.inertia)


def _variables(ctx, variables):
    """The variables named (a list of names, or one name) read as `qdot form
    --vars` reads them (qd_qform_vars_read): each a symbol's name, so a
    constant (pi, e) or t' is refused, as is a name given twice.  A
    qdot.ArgumentError (a ValueError) with the located message otherwise."""
    if isinstance(variables, str):
        variables = [variables]
    if not all(isinstance(v, str) for v in variables):
        raise TypeError("variables are names (str), not %r" % (variables,))
    text = ", ".join(variables).encode()
    xs = ffi.new("const qd_expr *[]", max(1, len(variables)))
    count = ffi.new("size_t *")
    st = lib.qd_qform_vars_read(ctx, text, xs, len(variables), count)
    if st == lib.QD_ERR_NOMEM:
        raise MemoryError("qdot: out of memory")
    if st != 0:  # pi, e, t' (= 1), a name twice, none at all
        diag = take_error(ctx)
        raise ArgumentError(format_diag(diag, "variables", text), st)
    return [xs[k] for k in range(count[0])]


def quadratic_form(expr, variables):
    """Lagrange's reduction of the quadratic form expr (model-language text)
    in the named variables (a list of names, read as `qdot form --vars`
    reads them); qdot.Error when it is not a quadratic form, a ValueError
    (qdot.ArgumentError) when a variable is not a name: pi and e are
    constants, not variables."""
    ctx = lib.qd_ctx_new()
    if not ctx:
        raise MemoryError("qdot: out of memory")
    try:
        diag = new("qd_diag")
        phi = lib.qd_read(ctx, expr.encode(), ffi.NULL, diag)
        if not phi:
            raise Error(ffi.string(diag.message).decode() or "cannot read the form")
        xs = _variables(ctx, variables)
        f = lib.qd_qform_reduce(ctx, phi, len(xs), exprs(xs))
        if not f:
            raise Error(cstr(lib.qd_ctx_message(ctx)))
        try:
            q = f

            def text(x):
                buf = new("qd_buf")
                lib.qd_print(ctx, x, QD_FMT_TEXT, buf)
                return buf_text(buf)
            n = q.n
            matrix = [[text(q.a[i * n + j]) for j in range(n)] for i in range(n)]
            coefs = [text(q.coef[k]) for k in range(q.nsq)]
            lins = [text(q.lin[k]) for k in range(q.nsq)]
            inertia = (q.npos, q.nneg, q.nzero) if q.decided else None
            kind = cstr(q.kind)
            out = QuadraticForm(matrix, coefs, lins, inertia, kind, bool(q.paired))
            printed = []
            for fmt in (lib.QD_RENDER_TEXT, lib.QD_RENDER_JSON):
                buf = new("qd_buf")
                if lib.qd_render_qform(ctx, phi, f, fmt, buf) != 0:
                    lib.qd_buf_free(buf)
                    raise Error(cstr(lib.qd_ctx_message(ctx)))
                printed.append(buf_text(buf))
            out._printed = tuple(printed)
            return out
        finally:
            lib.qd_qform_free(f)
    finally:
        lib.qd_ctx_free(ctx)


class Homogeneity:
    """The homogeneity of a function (qd_homogeneity, Desloge App. 20):
    homogeneous (True, False, or None when undecided), degree (text, or
    None), verdict ("homogeneous", "every degree", "not homogeneous",
    "undecided"), euler (sum x_i df/dx_i), witness ({"point": {...},
    "value", "radius"} for "not homogeneous", else None); json() the dict of
    `qdot form --homogeneity --format json`, text() its text."""

    __module__ = "qdot"

    def __init__(self, printed):
        self._printed = printed
        d = json.loads(printed[1])
        self.homogeneous, self.degree, self.verdict = d["homogeneous"], d["degree"], d["verdict"]
        self.euler, self.witness, self.certainty = d["euler"], d["witness"], d["certainty"]

    def text(self):
        return self._printed[0]

    def json(self):
        return json.loads(self._printed[1])

    def _repr_html_(self):
        from . import display
        return display.fields(self.json(), "qdot form --homogeneity")

    def __repr__(self):
        return "Homogeneity(%s%s)" % (self.verdict,
                                      ", degree=%s" % self.degree if self.degree else "")


def homogeneity(expr, variables):
    """The degree of homogeneity of expr (model-language text) in the named
    variables, the others passive (`qdot form EXPR --vars ... --homogeneity`):
    a Homogeneity; qdot.Error when expr does not read, ValueError when a
    variable is not a name (as --vars reads them: pi, t' refused)."""
    ctx = lib.qd_ctx_new()
    if not ctx:
        raise MemoryError("qdot: out of memory")
    try:
        diag = new("qd_diag")
        f = lib.qd_read(ctx, expr.encode(), ffi.NULL, diag)
        if not f:
            raise Error(ffi.string(diag.message).decode() or "cannot read the function")
        xs = _variables(ctx, variables)
        h = new("qd_homog")
        if lib.qd_homogeneity(ctx, f, len(xs), exprs(xs), h) != 0:
            raise Error(cstr(lib.qd_ctx_message(ctx)))
        printed = []
        for fmt in (lib.QD_RENDER_TEXT, lib.QD_RENDER_JSON):
            buf = new("qd_buf")
            if lib.qd_render_homog(ctx, h, len(xs), exprs(xs), fmt, buf) != 0:
                lib.qd_buf_free(buf)
                raise Error(cstr(lib.qd_ctx_message(ctx)))
            printed.append(buf_text(buf))
        return Homogeneity(tuple(printed))
    finally:
        lib.qd_ctx_free(ctx)


class Periods:
    """Shifts tested as periods of a function and the fundamental system of
    their integer combinations (qd_periods_reduce, Desloge App. 31):
    fundamental (rows of texts), coordinates (each shift's integers in it),
    is_period (True, False, or None when undecided, per shift), rank, unit;
    json() the dict of `qdot form --periods --format json`, text() its text."""

    __module__ = "qdot"

    def __init__(self, printed):
        self._printed = printed
        d = json.loads(printed[1])
        self.fundamental, self.coordinates = d["fundamental"], d["coordinates"]
        self.rank, self.unit = d["rank"], d["unit"]
        self.is_period = [t["is_period"] for t in d["tests"]]

    def text(self):
        return self._printed[0]

    def json(self):
        return json.loads(self._printed[1])

    def _repr_html_(self):
        from . import display
        return display.fields(self.json(), "qdot form --periods")

    def __repr__(self):
        return "Periods(fundamental=%r)" % (self.fundamental,)


def periods(expr, variables, shifts):
    """The shifts (a list of vectors, each a list of model-language texts,
    one per variable; or the --periods text "2*pi, 0; 0, 2*pi") tested as
    periods of expr, and their fundamental system (`qdot form EXPR --vars
    ... --periods ...`): a Periods; ValueError for a bad variable or shift,
    qdot.Error when the shifts are not commensurable."""
    if not isinstance(shifts, str):
        shifts = "; ".join(", ".join(str(c) for c in v) for v in shifts)
    ctx = lib.qd_ctx_new()
    if not ctx:
        raise MemoryError("qdot: out of memory")
    w = ffi.new("const qd_expr ***")
    try:
        diag = new("qd_diag")
        f = lib.qd_read(ctx, expr.encode(), ffi.NULL, diag)
        if not f:
            raise Error(ffi.string(diag.message).decode() or "cannot read the function")
        xl = _variables(ctx, variables)
        xs, g = exprs(xl), ffi.new("size_t *")
        if lib.qd_periods_vectors_read(ctx, shifts.encode(), len(xl), g, w) != 0:
            raise ValueError(cstr(lib.qd_ctx_message(ctx)))
        p = lib.qd_periods_reduce(ctx, f, len(xl), xs, g[0], w[0])
        if not p:
            raise Error(cstr(lib.qd_ctx_message(ctx)))
        try:
            printed = []
            for fmt in (lib.QD_RENDER_TEXT, lib.QD_RENDER_JSON):
                buf = new("qd_buf")
                if lib.qd_render_periods(ctx, f, p, xs, w[0], fmt, buf) != 0:
                    lib.qd_buf_free(buf)
                    raise Error(cstr(lib.qd_ctx_message(ctx)))
                printed.append(buf_text(buf))
            return Periods(tuple(printed))
        finally:
            lib.qd_periods_free(p)
    finally:
        if w[0] != ffi.NULL:
            lib.qd_periods_vectors_free(w[0])
        lib.qd_ctx_free(ctx)


def tour():
    """The text of `qdot tour` (qd_tour_print): the kernel on the double
    pendulum, from the bobs' positions to the mass matrix's compiled value."""
    ctx = lib.qd_ctx_new()
    if not ctx:
        raise MemoryError("qdot: out of memory")
    try:
        buf = new("qd_buf")
        if lib.qd_tour_print(ctx, buf) != 0:
            lib.qd_buf_free(buf)
            raise Error(cstr(lib.qd_ctx_message(ctx)))
        return buf_text(buf)
    finally:
        lib.qd_ctx_free(ctx)
