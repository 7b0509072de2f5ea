# python/qdot/forms.py - quadratic forms: Lagrange's reduction to a sum of
# squares and Sylvester's inertia (qd_qform_reduce; Desloge App. 27).
"""qdot.quadratic_form(expr, variables): the reduction of a quadratic form."""

import ctypes
import json
from ctypes import POINTER, Structure, byref, c_bool, c_char_p, c_int, c_size_t, c_void_p

from ._lib import lib, Buf, Diag, buf_text, exprs, QD_FMT_TEXT
from ._core import Error


class _QForm(Structure):
    _fields_ = [("n", c_size_t), ("x", POINTER(c_void_p)), ("a", POINTER(c_void_p)),
                ("nsq", c_size_t), ("coef", POINTER(c_void_p)), ("lin", POINTER(c_void_p)),
                ("npos", c_size_t), ("nneg", c_size_t), ("nzero", c_size_t),
                ("decided", c_bool), ("kind", c_char_p), ("paired", c_bool)]


for _name, _res, _args in (
        ("qd_qform_reduce", POINTER(_QForm), [c_void_p, c_void_p, c_size_t, POINTER(c_void_p)]),
        ("qd_qform_free", None, [POINTER(_QForm)]),
        ("qd_symbol", c_void_p, [c_void_p, c_char_p]),
        ("qd_ctx_message", c_char_p, [c_void_p]),
        ("qd_render_qform", c_int, [c_void_p, c_void_p, POINTER(_QForm), c_int, POINTER(Buf)])):
    getattr(lib, _name).restype = _res
    getattr(lib, _name).argtypes = _args


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
        diag = Diag()
        phi = lib.qd_read(ctx, expr.encode(), None, byref(diag))
        if not phi:
            raise Error(diag.message.decode() or "cannot read the form")
        xs = [lib.qd_symbol(ctx, v.encode()) for v in variables]
        arr = (c_void_p * max(len(xs), 1))(*xs)
        f = lib.qd_qform_reduce(ctx, phi, len(xs), arr)
        if not f:
            raise Error(lib.qd_ctx_message(ctx).decode())
        try:
            q = f.contents

            def text(x):
                buf = Buf()
                lib.qd_print(ctx, x, QD_FMT_TEXT, byref(buf))
                return buf_text(buf)
            n = q.n
            matrix = [[text(q.a[i * n + j]) for j in range(n)] for i in range(n)]
            coefs = [text(q.coef[k]) for k in range(q.nsq)]
            lins = [text(q.lin[k]) for k in range(q.nsq)]
            inertia = (q.npos, q.nneg, q.nzero) if q.decided else None
            kind = q.kind.decode() if q.kind else None
            out = QuadraticForm(matrix, coefs, lins, inertia, kind, bool(q.paired))
            printed = []
            for fmt in (0, 2):  # QD_RENDER_TEXT, QD_RENDER_JSON
                buf = Buf()
                if lib.qd_render_qform(ctx, phi, f, fmt, byref(buf)) != 0:
                    lib.qd_buf_free(byref(buf))
                    raise Error(lib.qd_ctx_message(ctx).decode())
                printed.append(buf_text(buf))
            out._printed = tuple(printed)
            return out
        finally:
            lib.qd_qform_free(f)
    finally:
        lib.qd_ctx_free(ctx)
