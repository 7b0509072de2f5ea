# python/qdot/kernel.py - the symbolic kernel from Python: `qdot diff`,
# `expand`, `simplify` and `print` as functions (qd_read, qd_read_variable,
# qd_diff, qd_expand, qd_simplify, qd_print: the calls cli/cmd_expr.c
# makes), and qdot.Code, the files `qdot codegen` writes.
#
# An Expr is a node of a libqdot context that it keeps alive; the kernel
# hash-conses its nodes, so two Exprs of one context are equal exactly when
# they are the same node (the canonical form, qdot/expr.h).
"""Expressions of the symbolic kernel (qdot.parse, diff, expand, simplify,
print_expr) and qdot.Code."""

import os

from ._core import ModelError, format_diag
from ._lib import ffi, lib, new, buf_text, QD_FMT_TEXT, QD_FMT_LATEX, QD_FMT_C, QD_FMT_SYMPY

_FORMATS = {"text": QD_FMT_TEXT, "latex": QD_FMT_LATEX, "c": QD_FMT_C, "sympy": QD_FMT_SYMPY}


class _Ctx:
    """A qd_ctx owned by the Exprs made in it."""

    def __init__(self):
        self.ctx = lib.qd_ctx_new()
        if not self.ctx:
            raise MemoryError("qdot: out of memory")

    def __del__(self):
        if getattr(self, "ctx", None):
            lib.qd_ctx_free(self.ctx)
            self.ctx = None

    def failed(self):
        """The context's error as an exception, the record cleared."""
        from ._core import take_error, Error
        diag = take_error(self.ctx)
        if diag.status == lib.QD_ERR_NOMEM:
            return MemoryError("qdot: out of memory")
        return Error(ffi.string(diag.message).decode() or "the kernel failed", diag.status)


class Expr:
    """An expression of the kernel (qdot.parse, diff, expand, simplify).

    str(x) is its text in the model language (what `qdot print` prints);
    x.latex(), x.c() and x.sympy_text() the other formats of `--format`;
    x.sympy() the SymPy value of the SymPy printer's text; x.symbols the
    names of its symbols.  x == y for Exprs of one context is identity of
    the canonical form; otherwise the texts are compared."""

    __module__ = "qdot"

    def __init__(self, owner, node):
        self._owner, self._node = owner, node

    def format(self, fmt="text"):
        """The expression printed in fmt: "text", "latex", "c" or "sympy"."""
        if fmt not in _FORMATS:
            raise ValueError("format is text, latex, c or sympy, not %r" % (fmt,))
        buf = new("qd_buf")
        st = lib.qd_print(self._owner.ctx, self._node, _FORMATS[fmt], buf)
        text = buf_text(buf)
        if st != lib.QD_OK:
            raise self._owner.failed()
        return text

    def __str__(self):
        return self.format("text")

    def __repr__(self):
        return "qdot.Expr(%r)" % str(self)

    def latex(self):
        return self.format("latex")

    def c(self):
        return self.format("c")

    def sympy_text(self):
        return self.format("sympy")

    def _repr_latex_(self):
        return "$%s$" % self.latex()

    @property
    def symbols(self):
        """The names of the symbols in the expression, in canonical order."""
        return [ffi.string(lib.qd_expr_name(s)).decode() for s in self._symbols()]

    def _symbols(self):
        ctx = self._owner.ctx
        k = lib.qd_free_symbols(ctx, self._node, ffi.NULL, 0)
        syms = ffi.new("const qd_expr *[]", max(k, 1))
        lib.qd_free_symbols(ctx, self._node, syms, k)
        return [syms[i] for i in range(k)]

    def sympy(self):
        """The expression as a SymPy value (needs sympy): the SymPy
        printer's text evaluated with each symbol a Symbol, each coordinate
        (a name written with a prime, r', whose symbol is named so: the
        jet, qdot/expr.h) a Function of t."""
        import sympy
        ns = dict(vars(sympy))
        t = ffi.string(lib.qd_print_time_name(self._owner.ctx)).decode()
        ns[t] = sympy.Symbol(t)
        for s in self._symbols():
            name = ffi.string(lib.qd_expr_name(s)).decode()
            if lib.qd_symbol_role(s) == lib.QD_ROLE_COORD:  # q, or its rate q' (the jet)
                ns[name.rstrip("'")] = sympy.Function(name.rstrip("'"))
            elif lib.qd_symbol_role(s) != lib.QD_ROLE_TIME and Expr(self._owner, s).format(
                    "sympy") == name:  # bound only where the printer writes it bare (not E)
                ns[name] = sympy.Symbol(name)
        return eval(self.sympy_text(), ns)  # noqa: S307 (the library printer's text)

    def __eq__(self, other):
        if isinstance(other, Expr):
            if other._owner is self._owner:
                return self._node == other._node
            return str(self) == str(other)
        return NotImplemented

    def __hash__(self):
        return hash(str(self))


def _read_error(err, what, text):
    diag = new("qd_diag")
    diag[0] = err[0]
    return ModelError(format_diag(diag, what, text), diag, what)


def parse(expr):
    """An expression read from text in the model language (an Expr as
    given): unknown names become plain symbols, and coordinates when written
    with a prime (r' is then a rate of its own); a text that does not read
    raises qdot.ModelError, shown in it as `qdot print` shows it."""
    if isinstance(expr, Expr):
        return expr
    if not isinstance(expr, str):
        raise TypeError("an expression is text or a qdot.Expr, not %s" % type(expr).__name__)
    owner = _Ctx()
    err = new("qd_read_error")
    raw = expr.encode()
    x = lib.qd_read(owner.ctx, raw, ffi.NULL, err)
    if not x:
        raise _read_error(err, "<expression>", raw)
    return Expr(owner, x)


def _result(owner, x):
    if not x:
        raise owner.failed()
    return Expr(owner, x)


def diff(expr, *variables):
    """The partial derivative of expr with respect to each variable in turn
    (`qdot diff EXPR VAR...`): a name or a rate (r') of one of expr's
    symbols, read by qd_read_variable; one that does not occur in expr
    raises qdot.ModelError with the command's message and hint."""
    if not variables:
        raise TypeError("diff: name at least one variable")
    x = parse(expr)
    owner, node, e0 = x._owner, x._node, x._node
    for v in variables:
        if isinstance(v, Expr):
            v = str(v)
        if not isinstance(v, str):
            raise TypeError("diff: a variable is a name (text), not %s" % type(v).__name__)
        err = new("qd_read_error")
        var = lib.qd_read_variable(owner.ctx, v.encode(), e0, err)
        if not var:
            lib.qd_ctx_clear_error(owner.ctx)
            raise _read_error(err, "<variable>", v.encode())
        node = lib.qd_diff(owner.ctx, node, var)
        if not node:
            raise owner.failed()
    return Expr(owner, node)


def expand(expr):
    """Products and powers of sums distributed (`qdot expand`, qd_expand)."""
    x = parse(expr)
    r = _result(x._owner, lib.qd_expand(x._owner.ctx, x._node))
    kept = lib.qd_expand_kept(r._owner.ctx, r._node)
    if kept != ffi.NULL:  # said, as `qdot expand` says it
        import warnings
        warnings.warn("%s is kept as a power: its expansion would exceed 64 MiB "
                      "(docs/cli.md, qdot expand)" % _result(r._owner, kept), UserWarning,
                      stacklevel=2)
    return r


def simplify(expr):
    """Expanded, trigonometric identities, cancelled, factored (`qdot
    simplify`, qd_simplify)."""
    x = parse(expr)
    return _result(x._owner, lib.qd_simplify(x._owner.ctx, x._node))


def print_expr(expr, format="text"):
    """The canonical form of expr printed as `qdot print EXPR --format F`
    prints it: "text", "latex", "c" or "sympy" (a str)."""
    return parse(expr).format(format)


class Code:
    """The C that `qdot codegen` writes (Model.codegen): .prefix, .c and .h
    the texts of PREFIX.c and PREFIX.h; .save(directory) writes both
    (the directory made when missing) and returns their paths."""

    __module__ = "qdot"

    def __init__(self, prefix, c, h):
        self.prefix, self.c, self.h = prefix, c, h

    @property
    def files(self):
        """{file name: text} of the two files."""
        return {self.prefix + ".c": self.c, self.prefix + ".h": self.h}

    def save(self, directory="."):
        os.makedirs(directory, exist_ok=True)
        paths = []
        for name, text in self.files.items():
            path = os.path.join(directory, name)
            with open(path, "w") as fh:
                fh.write(text)
            paths.append(path)
        return paths

    def __repr__(self):
        return "<qdot.Code %s: %d + %d bytes>" % (self.prefix, len(self.c), len(self.h))
