# python/qdot/_core.py - one parsed model and what it owns in C: the context,
# the qd_model, the derived qd_eom; errors turned into Python exceptions.
#
# Ownership (qdot/expr.h): the context owns every expression, the model and
# the equations are freed by their own calls before the context.  A _Core is
# never changed after it is made (Model.set makes a new one), so an object
# that keeps a _Core alive (a compiled right-hand side) can never see its
# equations freed under it.
"""The C objects behind a qdot.Model (internal)."""

from ._lib import ffi, lib, new, buf_text, cstr, exprs, doubles, QD_OK, QD_FMT_TEXT

QD_ERR_NOMEM = lib.QD_ERR_NOMEM
QD_ERR_ARG = lib.QD_ERR_ARG


class Error(Exception):
    """A libqdot call failed: status is the qd_status code, message its text."""

    __module__ = "qdot"

    def __init__(self, message, status=None):
        super().__init__(message)
        self.message = message
        self.status = status


class ModelError(Error):
    """An error in a model: str(err) is qd_diag_format's rendering, which
    starts "FILE:LINE:COL: error: MESSAGE" and shows the line with a caret.
    file, line, col (1-based; 0 when the error has no place in the text),
    hint and status are attributes."""

    __module__ = "qdot"

    def __init__(self, text, diag, file):
        super().__init__(text, diag.status)
        self.file = file
        self.line = diag.line if diag.located else 0
        self.col = diag.col if diag.located else 0
        self.message = ffi.string(diag.message).decode()
        self.hint = ffi.string(diag.hint).decode()


class ArgumentError(Error, ValueError):
    """An argument the library refused (the CLI's "... (--exponents)"):
    a qdot.Error that is also a ValueError, its message naming the
    argument."""

    __module__ = "qdot"


# option fields (qd_diag.name) whose Model argument has another name
_ARGUMENT = {"event": "events or stop_at", "no_speeds": "speeds"}


class NumericalError(Error):
    """A computation that failed on its numbers (a value that is not
    finite, Newton that did not converge, an integration that stopped):
    message the library's text, status the qd_status."""

    __module__ = "qdot"


def format_diag(diag, file, text):
    """qd_diag_format of diag (a qd_diag *) against text (bytes or None)."""
    buf = new("qd_buf")
    lib.qd_diag_format(diag, file.encode(), text or ffi.NULL, buf)
    return buf_text(buf).rstrip("\n")


def take_error(ctx):
    """A copy of the context's error record, and the record cleared (errors
    are sticky: the next call must not report this one again)."""
    d = lib.qd_ctx_diag(ctx)
    diag = new("qd_diag")
    if d:
        diag[0] = d[0]
    lib.qd_ctx_clear_error(ctx)
    return diag


def _number(ctx, name, value):
    """A parameter value for --set name (see number_expr)."""
    return number_expr(ctx, "set " + name, value)


def number_expr(ctx, what, value):
    """A value as an exact number node: 9.81 stays 9.81, and a string is
    read in the model language ("pi/6"); what names it in messages."""
    if isinstance(value, str):
        diag = new("qd_diag")
        opts = new("qd_read_opts", {"new_symbols": False})
        x = lib.qd_read(ctx, value.encode(), opts, diag)
        if not x:
            lib.qd_ctx_clear_error(ctx)
            raise ModelError(format_diag(diag, what, value.encode()), diag, what)
        if lib.qd_is_number(x):
            return x
        # a constant expression (pi/6) goes in as its value, as --set gives it
        out = new("double")
        if lib.qd_eval(ctx, x, 0, ffi.NULL, ffi.NULL, out) != QD_OK:
            lib.qd_ctx_clear_error(ctx)
            raise Error("%s: '%s' is not a number" % (what, value))
        value = out[0]
    x = float(value)
    if isinstance(value, bool) or not x == x or x in (float("inf"), float("-inf")):
        raise Error("%s: %r is not a finite number" % (what, value))
    text = str(value) if isinstance(value, int) else repr(x)
    x = lib.qd_rat_str(ctx, text.encode())
    if not x:
        raise Error("%s: %r is not a number" % (what, value))
    return x


class Core:
    """The context, model and (lazily) equations of one parse."""

    def __init__(self, text, file, params, derivation="simulate"):
        """text parsed with params [(name, value)] as parameter values, fixed
        into the formulas or kept symbols as the library's rule says for the
        command named derivation (qd_model_opts_for)."""
        self.ctx = self.model = self._eom = self._eom_elim = None
        self.ctx = lib.qd_ctx_new()
        if not self.ctx:
            raise MemoryError("qdot: out of memory")
        self.text = text
        self._ctext = ffi.new("char[]", text)  # the model keeps pointers into it
        self.file = file
        vals = ffi.new("qd_param_value[]", max(len(params), 1))
        names = [ffi.new("char[]", name.encode()) for name, _ in params]  # alive for the call
        for i, (name, value) in enumerate(params):
            vals[i].name = names[i]
            vals[i].value = _number(self.ctx, name, value)
        opts = new("qd_model_opts", {"params": vals, "nparams": len(params)})
        if lib.qd_model_opts_for(opts, derivation.encode()) != 0:
            raise ValueError("no parameter rule for %r" % (derivation,))
        diag = new("qd_diag")
        self.model = lib.qd_model_parse_opts(self.ctx, self._ctext, opts, diag)
        if not self.model:
            lib.qd_ctx_clear_error(self.ctx)
            raise ModelError(format_diag(diag, file, text), diag, file)

    def __del__(self):
        """Free the equations, the model, then the context that owns their nodes."""
        if self._eom:
            lib.qd_eom_free(self._eom)
        if self._eom_elim:
            lib.qd_eom_free(self._eom_elim)
        if self.model:
            lib.qd_model_free(self.model)
        if self.ctx:
            lib.qd_ctx_free(self.ctx)

    # ---- errors ---------------------------------------------------------------

    def error(self, status=None, cls=None):
        """The exception for the context's error: located in the model text
        (qd_model_locate) when it is about a statement of it."""
        diag = take_error(self.ctx)
        if status is not None and diag.status == QD_OK:
            diag.status = status
        if diag.status == QD_ERR_NOMEM:
            return MemoryError("qdot: out of memory")
        if lib.qd_model_locate(self.model, diag) or cls is ModelError:
            return ModelError(format_diag(diag, self.file, self.text), diag, self.file)
        msg = ffi.string(diag.message).decode() or cstr(lib.qd_status_str(diag.status))
        name = ffi.string(diag.name).decode()
        if diag.subject == 0 and name:  # an option's field (qdot/sim.h): the argument
            msg += " (the argument %s)" % _ARGUMENT.get(name, name)
            if cls is None and diag.status == QD_ERR_ARG:
                cls = ArgumentError
        return (cls or Error)(msg, diag.status)

    def check(self, status, cls=None):
        """Raise the context's error unless status is QD_OK."""
        if status != QD_OK:
            raise self.error(status, cls)

    # ---- the model --------------------------------------------------------------

    def eom(self):
        """The qd_eom (derived once; parameters stay symbols in it)."""
        if not self._eom:
            e = lib.qd_eom_derive(self.ctx, self.model)
            if not e:
                raise self.error(cls=ModelError)
            self._eom = e
        return self._eom

    def eom_eliminated(self):
        """The qd_eom `qdot equilibria`, `modes` and `linearize` analyse: the
        holonomic constraints that solve for a coordinate eliminated
        (qd_eom_opts.eliminate; derived once)."""
        if not self._eom_elim:
            e = lib.qd_eom_derive_opts(self.ctx, self.model, new("qd_eom_opts",
                                                                 {"eliminate": True}))
            if not e:
                raise self.error(cls=ModelError)
            self._eom_elim = e
        return self._eom_elim

    def eom_ptr(self):
        """The qd_eom pointer itself, for calls that take it."""
        self.eom()
        return self._eom

    def coords(self):
        """The coordinate symbols in model order."""
        return [lib.qd_model_coord(self.model, i)
                for i in range(lib.qd_model_ncoords(self.model))]

    def params(self):
        """[(name, symbol, value)] in model order."""
        out = []
        for i in range(lib.qd_model_nparams(self.model)):
            sym = lib.qd_model_param(self.model, i)
            x = new("double")
            lib.qd_model_param_number(self.model, i, x)
            out.append((name_of(sym), sym, x[0]))
        return out

    def state(self):
        """The symbols and values of the model's state at its `initial`
        values (qd_state_init, qd_state_initial: every coordinate and
        velocity at its `initial` value, 0 when none, t = 0, the
        parameters), as lists."""
        st = new("qd_state")
        try:
            self.check(lib.qd_state_init(self.ctx, self.model, st))
            self.check(lib.qd_state_initial(self.ctx, self.model, st))
            return [st.syms[k] for k in range(st.n)], [st.vals[k] for k in range(st.n)]
        finally:
            lib.qd_state_free(st)

    def eval(self, x, syms, vals):
        """The value of expression x at syms = vals."""
        out = new("double")
        self.check(lib.qd_eval(self.ctx, x, len(syms), exprs(syms), doubles(vals), out))
        return out[0]

    def text_of(self, x, fmt=QD_FMT_TEXT):
        """x printed (QD_FMT_TEXT or QD_FMT_SYMPY)."""
        buf = new("qd_buf")
        st = lib.qd_print(self.ctx, x, fmt, buf)
        s = buf_text(buf)
        self.check(st)
        return s

    def read(self, text, what):
        """An expression read against the model: a definition's name
        (x2 = ...) stands for its value, NAME' for its time derivative."""
        raw = text.strip()
        if raw.endswith("'"):
            d = lib.qd_model_definition(self.model, raw[:-1].strip().encode())
            if d:
                return lib.qd_dt(self.ctx, d)
        diag = new("qd_diag")
        opts = new("qd_read_opts", {"new_symbols": True})
        x = lib.qd_read(self.ctx, raw.encode(), opts, diag)
        if not x:
            lib.qd_ctx_clear_error(self.ctx)
            raise ModelError(format_diag(diag, what, raw.encode()), diag, what)
        return self._definitions(x)

    def _definitions(self, x):
        """x with each plain symbol that names a definition replaced by its value."""
        k = lib.qd_free_symbols(self.ctx, x, ffi.NULL, 0)
        syms = ffi.new("const qd_expr *[]", max(k, 1))
        lib.qd_free_symbols(self.ctx, x, syms, k)
        for s in list(syms)[:k]:
            if lib.qd_symbol_role(s) != lib.QD_ROLE_PLAIN:
                continue
            d = lib.qd_model_definition(self.model, lib.qd_expr_name(s))
            if d:
                x = lib.qd_subs(self.ctx, x, 1, exprs([s]), exprs([d]))
        if not x:
            raise self.error()
        return x


def name_of(sym):
    """A symbol's name as str."""
    return ffi.string(lib.qd_expr_name(sym)).decode()
