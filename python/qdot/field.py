# python/qdot/field.py - a continuous system (`field y(x, t) on x = A .. B`,
# qdot/field.h; Desloge ch. 83): its field equation and normal modes, as
# `qdot eom` and `qdot modes` print them for a field model (cli/cmd_field.c
# calls the same functions).  Only Python's argument types are here.
"""qdot.Field: a field model's equation and normal modes (see there)."""

import json
import warnings

from ._core import Error, ModelError, NumericalError, format_diag, take_error, _number
from ._lib import ffi, lib, new, buf_text
from .commands import Output

QD_OK = lib.QD_OK


class Field:
    """A field model: `field y(x, t) on x = A .. B`, `Ldensity = ...` and
    `boundary` (docs/language.md, "Continuous systems"), parsed by
    qd_field_parse.  params: {name: value} over the model's `parameters`, as
    the command line's --set.  A text that does not read raises
    qdot.ModelError located in it."""

    __module__ = "qdot"

    def __init__(self, text, file="<string>", params=None):
        self.ctx = self.field = None
        self.ctx = lib.qd_ctx_new()
        if not self.ctx:
            raise MemoryError("qdot: out of memory")
        if not isinstance(text, (str, bytes)):
            raise TypeError("Field() takes the model text as str or bytes, not %s"
                            % type(text).__name__)
        text = text.encode() if isinstance(text, str) else text
        if b"\0" in text:
            raise ValueError("%s: a NUL byte in the model text" % file)
        self.text, self.file = text, str(file)
        self._ctext = ffi.new("char[]", text)  # the model keeps pointers into it
        params = list((params or {}).items())
        vals = ffi.new("qd_param_value[]", max(len(params), 1))
        names = [ffi.new("char[]", name.encode()) for name, _ in params]  # alive for the call
        for i, (name, value) in enumerate(params):
            vals[i].name = names[i]
            vals[i].value = _number(self.ctx, name, value)
        opts = new("qd_model_opts", {"params": vals, "nparams": len(params)})
        if lib.qd_model_opts_for(opts, b"field") != 0:
            raise ValueError("no parameter rule for a field")
        diag = new("qd_diag")
        self.field = lib.qd_field_parse(self.ctx, self._ctext, opts, diag)
        if not self.field:
            lib.qd_ctx_clear_error(self.ctx)
            raise ModelError(format_diag(diag, self.file, text), diag, self.file)

    @classmethod
    def load(cls, path, params=None):
        """The field model in the file at path."""
        with open(path, "rb") as fh:
            return cls(fh.read(), str(path), params)

    def __del__(self):
        if self.field:
            lib.qd_field_free(self.field)
        if self.ctx:
            lib.qd_ctx_free(self.ctx)

    def __repr__(self):
        return "<qdot.Field %s: %s(%s, t)>" % (
            self.file, ffi.string(lib.qd_field_name(self.field)).decode(),
            ffi.string(lib.qd_field_space(self.field)).decode())

    def _output(self, command, printer):
        buf = new("qd_buf")
        st = printer(buf)
        if st == QD_OK:  # "model" first, as the command's JSON has it
            st = lib.qd_json_add_model(buf, ffi.new("char[]", self.file.encode()))
        if st != QD_OK:
            lib.qd_buf_free(buf)
            diag = take_error(self.ctx)
            raise Error(ffi.string(diag.message).decode() or "cannot print the %s" % command, st)
        return Output(command, json.loads(buf_text(buf)))

    def eom(self):
        """The field equation d/dt dL/dy_t + d/dx dL/dy_x - dL/dy = 0
        (qd_field_equation, `qdot eom FIELDFILE --format json`): an Output
        with field, space, interval, boundary, density and equation (its
        left side, text in the model language)."""
        E = lib.qd_field_equation(self.ctx, self.field)
        if E == ffi.NULL:
            raise self._density_error()
        return self._output("eom", lambda buf: lib.qd_field_equation_json(self.ctx, self.field,
                                                                          E, buf))

    def modes(self, count=5, tol=1e-6):
        """The lowest count normal modes y = Y(x) cos(omega t)
        (qd_field_modes_compute, `qdot modes FIELDFILE --format json`): an
        Output with rho, tau, kappa, method ("exact" or "finite elements"),
        converged, elements, tolerance and modes (omega, omega2, error,
        shape, k each).  Exact for constant coefficients; otherwise finite
        elements refined until every error estimate is below tol * omega, a
        UserWarning (the command's failure) when they could not be."""
        if isinstance(count, bool) or not isinstance(count, int) or count < 1:
            raise ValueError("modes: count is a whole number >= 1, not %r" % (count,))
        if not float(tol) > 0:
            raise ValueError("modes: tol is a number > 0, not %r" % (tol,))
        o = new("qd_field_modes_opts", {"count": count, "tol": float(tol)})
        r = new("qd_field_modes")
        try:
            if lib.qd_field_modes_compute(self.ctx, self.field, o, r) != QD_OK:
                raise self._density_error()
            out = self._output("modes", lambda buf: lib.qd_field_modes_json(self.ctx, self.field,
                                                                            r, buf))
            if not r.converged:
                warnings.warn("modes: did not converge to tol on %d elements (the estimates "
                              "are in the result)" % r.elements, stacklevel=2)
            return out
        finally:
            lib.qd_field_modes_free(r)

    def _density_error(self):
        """The library's reason, at the Ldensity statement when it is about it."""
        diag = take_error(self.ctx)
        if diag.status == lib.QD_ERR_NOMEM:
            return MemoryError("qdot: out of memory")
        where = new("qd_diag")
        if diag.status == lib.QD_ERR_ARG and lib.qd_model_where(
                lib.qd_field_model(self.field), b"Ldensity", where):
            where.message = diag.message
            return ModelError(format_diag(where, self.file, self.text), where, self.file)
        return NumericalError(ffi.string(diag.message).decode(), diag.status)
