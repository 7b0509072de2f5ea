# python/qdot/commands.py - the results of the Model methods that stand for
# CLI commands: the JSON the library writes for `qdot CMD --format json`
# (the same printer the command calls), read back into Python.
#
# Nothing here computes: a method of Model calls the library function that
# the command's cli/cmd_NAME.c calls to print its JSON, and wraps the text.
"""qdot.Output: a command's JSON as a Python object (internal helpers too)."""

import json as _json
import numbers

import numpy as np

from ._lib import ffi, lib, new, buf_text


def _is_number(x):
    return isinstance(x, numbers.Real) and not isinstance(x, bool)


def _value(x):
    """A JSON value as the package gives it: a list of numbers a numpy
    array (a list of equal lists of numbers a 2-D one), an object a Fields,
    everything else as JSON reads it (strings stay strings)."""
    if isinstance(x, dict):
        return Fields(x)
    if isinstance(x, list):
        if x and all(_is_number(v) for v in x):
            return np.array(x, dtype=float)
        if (x and all(isinstance(v, list) and v and all(_is_number(u) for u in v) for v in x)
                and len({len(v) for v in x}) == 1):
            return np.array(x, dtype=float)
        return [_value(v) for v in x]
    if _is_number(x) and not isinstance(x, int):
        return float(x)
    return x


class Fields(dict):
    """A JSON object: a dict whose keys are also attributes; f.KEY and
    f["KEY"] give the values as Output gives them."""

    __module__ = "qdot"

    def __getitem__(self, key):
        return _value(dict.__getitem__(self, key))

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError("no field %r (the fields: %s)"
                                 % (name, ", ".join(self))) from None

    def _repr_html_(self):
        from . import display
        return display.fields(self)


class Output:
    """The result of a command: its fields are the keys of the JSON that
    `qdot COMMAND FILE --format json` prints (the same names, written by the
    same library printer).  out.KEY or out["KEY"] is a field, numbers as
    floats, lists of numbers as numpy arrays, objects as Fields (a dict
    with attribute access), formulas as strings in the model language;
    out.json is the whole dict as JSON reads it; out.command the command's
    name.  In Jupyter, _repr_latex_ shows the library's LaTeX rendering
    where the command has one; out.sympy(KEY) gives a field's formulas as
    SymPy values."""

    __module__ = "qdot"

    def __init__(self, command, data, latex=None, core=None):
        self.__dict__.update(command=command, json=data, _latex=latex, _core=core)

    def __getattr__(self, name):
        data = self.__dict__.get("json")
        if data is not None and name in data:
            return _value(data[name])
        raise AttributeError("%s has no field %r (the fields: %s)"
                             % (self.__dict__.get("command"), name, ", ".join(data or ())))

    def __setattr__(self, name, value):
        raise AttributeError("a qdot.Output is read-only")

    def __getitem__(self, key):
        return _value(self.json[key])

    def __contains__(self, key):
        return key in self.json

    def keys(self):
        """The JSON keys, in the printer's order."""
        return list(self.json)

    def __dir__(self):
        return sorted(set(object.__dir__(self)) | set(self.json))

    def __repr__(self):
        parts = []
        for k, v in self.json.items():
            r = repr(v)
            parts.append("%s=%s" % (k, r if len(r) <= 60 else r[:57] + "..."))
        return "<qdot.Output %s: %s>" % (self.command, ", ".join(parts))

    def _repr_latex_(self):
        """The command's own LaTeX rendering (routh, hj, bracket, impulse,
        hamiltonian), or None for a command that has none."""
        if self._latex is None:
            return None
        return latex_display(self._latex())

    def _repr_html_(self):
        """A table of the fields for Jupyter, unless the command has a LaTeX
        rendering (shown instead).  Rows of numbers under their column names
        (sweep's "columns" and "rows") are one table headed by them."""
        if self._latex is not None:
            return None
        return self.html()

    def html(self):
        """The fields as an HTML table (what Jupyter shows without LaTeX)."""
        from . import display
        data = dict(self.json)
        parts = []
        cols, rows = data.get("columns"), data.get("rows")
        if (isinstance(cols, list) and isinstance(rows, list) and
                all(isinstance(r, list) and len(r) == len(cols) for r in rows)):
            del data["rows"], data["columns"]
            parts.append(display.table(cols, rows, caption="%d rows" % len(rows)))
        return display.block("qdot " + self.command, display.fields(data), *parts)

    def sympy(self, key):
        """The field key with each formula in it a SymPy value (needs sympy):
        each string read by the library against the model's names (qd_read)
        and printed by its SymPy printer (QD_FMT_SYMPY), lists and objects
        keeping their shape; a string that is not a formula (a reason, a
        name the model does not know as an expression) stays a string, a
        number stays a number."""
        if self._core is None:
            raise ValueError("%s: its fields are not formulas of a model" % self.command)
        return _sympy_tree(self._core, self.json[key])


def latex_display(text):
    """The rows of a library LaTeX rendering (rows ending in \\\\, % comment
    lines) as one displayed gathered block, for Jupyter."""
    rows = [ln.strip() for ln in text.splitlines()
            if ln.strip() and not ln.lstrip().startswith("%")]
    rows = [r[:-2].rstrip() if r.endswith("\\\\") else r for r in rows]
    return "$$\\begin{gathered}%s\\end{gathered}$$" % " \\\\ ".join(rows)


def rendered(core, call):
    """The text call(buf) writes into a qd_buf, or the context's error raised."""
    buf = new("qd_buf")
    st = call(buf)
    if st != 0:
        lib.qd_buf_free(buf)
        core.check(st)
    return buf_text(buf)


def output(core, command, call, latex=None):
    """An Output of the JSON call(buf) writes (see rendered), with "model"
    (the model's file) first, as every command's JSON that reads a model
    has it (qd_json_add_model)."""
    def with_model(buf):
        st = call(buf)
        return st if st != 0 else lib.qd_json_add_model(buf, source(core))
    return Output(command, _json.loads(rendered(core, with_model)), latex, core)


def _sympy_tree(core, x):
    if isinstance(x, dict):
        return {k: _sympy_tree(core, v) for k, v in x.items()}
    if isinstance(x, list):
        return [_sympy_tree(core, v) for v in x]
    if isinstance(x, str):
        return sympy_of(core, x)
    return x


def sympy_of(core, text):
    """The formula text (the model language) as SymPy: read by qd_read,
    printed by QD_FMT_SYMPY and evaluated in a namespace of the model's
    coordinates (functions of t), parameters and the formula's other
    symbols (momenta p_x, ...); text that does not read stays text."""
    from ._core import ModelError, name_of
    from .model import _sympy_namespace
    try:
        x = core.read(text, "formula")
    except ModelError:
        return text
    k = lib.qd_free_symbols(core.ctx, x, ffi.NULL, 0)
    syms = ffi.new("const qd_expr *[]", max(k, 1))
    lib.qd_free_symbols(core.ctx, x, syms, k)
    ns = _sympy_namespace(core, [syms[i] for i in range(k)
                                 if lib.qd_symbol_role(syms[i]) == lib.QD_ROLE_PLAIN])
    from ._lib import QD_FMT_SYMPY
    try:
        return eval(core.text_of(x, QD_FMT_SYMPY), ns)  # noqa: S307 (the library printer's text)
    except (NameError, SyntaxError, TypeError):
        return text


def source(core):
    """The model's name as the printers take it (the file's path)."""
    return ffi.new("char[]", core.file.encode())


def coordinate_symbols(core, names, what):
    """The coordinate symbols named in names (a list or "a,b" text), in that
    order; ValueError for a name that is not a coordinate."""
    if isinstance(names, str):
        names = [s.strip() for s in names.split(",") if s.strip()]
    from ._core import name_of
    coords = {name_of(c): c for c in core.coords()}
    out = []
    for name in names:
        if name not in coords:
            raise ValueError("%s: '%s' is not a coordinate (%s)"
                             % (what, name, ", ".join(coords)))
        out.append(coords[name])
    if not out:
        raise ValueError("%s: name at least one coordinate" % what)
    return out


def text_arg(value, what):
    """An option's value as the C string the library reads (None stays
    None): text as given, a number as its repr, {name: value} as
    "name=value, ..." (the command line's spelling of it)."""
    if value is None:
        return None
    if isinstance(value, dict):
        value = ", ".join("%s=%s" % (k, v if isinstance(v, str) else repr(float(v)))
                          for k, v in value.items())
    elif _is_number(value):
        value = repr(float(value))
    elif not isinstance(value, str):
        raise TypeError("%s: a dict, a number or text, not %s" % (what, type(value).__name__))
    return ffi.new("char[]", value.encode())
