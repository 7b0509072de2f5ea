# python/qdot/forms.py - quadratic forms: Lagrange's reduction to a sum of
# squares and Sylvester's inertia (qd_qform_reduce; Desloge App. 27).
"""qdot.quadratic_form(expr, variables): the reduction of a quadratic form;
qdot.tour(): the kernel's tour."""

import json

from ._lib import ffi, lib, new, buf_text, cstr, exprs, QD_FMT_TEXT
from ._core import Error


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

    def __repr__(self):
        return "QuadraticForm(%s, inertia=%r)" % (" + ".join(
            "(%s)*(%s)^2" % (c, y) for c, y in zip(self.coefficients, self.linear_forms)) or "0",
            self.inertia)


def quadratic_form(expr, variables):
    """Lagrange's reduction of the quadratic form expr (model-language text)
    in the named variables; qdot.Error when it is not a quadratic form."""
    ctx = lib.qd_ctx_new()
    if not ctx:
        raise MemoryError("qdot: out of memory")
    try:
        diag = new("qd_diag")
        phi = lib.qd_read(ctx, expr.encode(), ffi.NULL, diag)
        if not phi:
            raise Error(ffi.string(diag.message).decode() or "cannot read the form")
        xs = [lib.qd_symbol(ctx, v.encode()) for v in variables]
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
