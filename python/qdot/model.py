# python/qdot/model.py - qdot.Model: a model file read by libqdot, its
# equations, Hamiltonian, equilibria and small oscillations.
#
# Every result comes from a libqdot call (qdot/mech.h, hamilton.h,
# equilibria.h, modes.h); this file only moves numbers and strings between
# C and Python and frees what the C calls allocate.
"""qdot.Model and the symbolic results it returns."""

import json as _json

import numpy as np

from ._core import (ArgumentError, Core, Error, ModelError, NumericalError, format_diag,
                    name_of)
from ._lib import (ffi, lib, new, buf_text, cstr, exprs, QD_FMT_SYMPY, QD_FMT_LATEX,
                   QD_FMT_TEXT)
from . import sim as _sim
from . import runs as _runs
from . import control as _control
from . import commands as _commands
from . import linear as _linear
from . import _progress


class _Printed:
    """The renderings of a whole system (qdot/render.h), as `qdot eom
    --format F` prints them: text(), latex(), sympy_text(), c_code() and
    json() (a dict).  at={name: value} or text (text and JSON): the numbers
    at that state, read by the library as `qdot eom --at` reads it (q, q',
    t, parameters; with speeds the speeds; the names not given at 0), an
    error in it a qdot.ModelError shown in its text."""

    _print = None  # set by Model: (format name, at) -> str

    def text(self, at=None):
        """The equations as `qdot eom` prints them."""
        return self._print("text", at)

    def latex(self):
        """One LaTeX align environment."""
        return self._print("latex", None)

    def sympy_text(self):
        """A Python script for SymPy that rebuilds the equations (exec it:
        its M, f, ... are SymPy matrices)."""
        return self._print("sympy", None)

    def c_code(self):
        """One C block assigning M, f, ... (common subexpressions shared)."""
        return self._print("c", None)

    def json(self, at=None):
        """The equations as a dict (`qdot eom --format json`)."""
        return _json.loads(self._print("json", at))

    def _repr_latex_(self):
        """latex() for Jupyter: its align environment as a displayed aligned block."""
        rows = [ln for ln in self.latex().splitlines() if not ln.lstrip().startswith("%")]
        body = "\n".join(rows).replace("{align}", "{aligned}").replace("{align*}", "{aligned}")
        return "$$%s$$" % body.strip()


class Equations(_Printed):
    """Lagrange's equations M(q, q', t) q'' = f(q, q', t) (qdot/mech.h).

    coordinates: the names of q in order; M: n lists of n entries; f: n
    entries.  Entries are strings in the model language, or SymPy
    expressions (M a sympy.Matrix, f a column Matrix) when made with
    sympy=True.  constraints: the names of the constraints, whose
    multipliers lambda_NAME enter f through A^T lambda (not included in f).
    """

    def __init__(self, coordinates, M, f, constraints):
        self.coordinates = coordinates
        self.M = M
        self.f = f
        self.constraints = constraints

    def __repr__(self):
        return "Equations(coordinates=%r, M=%r, f=%r)" % (self.coordinates, self.M, self.f)


class SpeedsEquations(_Printed):
    """The equations in generalized speeds (qdot/speeds.h): q' = W u + w
    (kinematics: one expression per coordinate) and M_u u' = f_u.  Entries
    are strings in the model language; coordinates and speeds are names.
    The printers of _Printed give the whole system; hamel() Hamel's
    coefficients as text."""

    def __init__(self, coordinates, speeds, kinematics, M, f, method):
        self.coordinates, self.speeds = coordinates, speeds
        self.kinematics, self.M, self.f, self.method = kinematics, M, f, method

    def __repr__(self):
        return "SpeedsEquations(speeds=%r, method=%r)" % (self.speeds, self.method)


class Hamiltonian:
    """Hamilton's function and equations (qdot/hamilton.h).

    H: H(q, p, t); momenta: the names of p; dq, dp: dq_j/dt = dH/dp_j and
    dp_j/dt = -dH/dq_j + Q_j (strings, or SymPy with sympy=True);
    conserved: H has no explicit t and no forces act; is_energy: H = T + V.
    """

    def __init__(self, H, momenta, dq, dp, conserved, is_energy):
        self.H = H
        self.momenta = momenta
        self.dq = dq
        self.dp = dp
        self.conserved = conserved
        self.is_energy = is_energy
        self.output = None  # the qdot.Output of `qdot hamiltonian --format json`

    @property
    def json(self):
        """The dict `qdot hamiltonian FILE --format json` prints."""
        return self.output.json

    def __getattr__(self, name):
        # the other JSON keys (dq_dt, dp_dt, definitions, velocities, ...)
        out = self.__dict__.get("output")
        if out is not None and name in out:
            return out[name]
        raise AttributeError("Hamiltonian has no field %r" % name)

    def _repr_latex_(self):
        return self.output._repr_latex_() if self.output is not None else None

    def __repr__(self):
        return "Hamiltonian(H=%r)" % (self.H,)


class Equilibrium:
    """A configuration of rest (qdot/equilibria.h): q maps each coordinate
    to its value; exact to its exact value as text, or is None when found
    numerically; kind is "minimum", "maximum", "saddle" or "degenerate";
    residual the largest generalized force left there."""

    def __init__(self, q, exact, kind, residual):
        self.q = q
        self.exact = exact
        self.kind = kind
        self.residual = residual

    def __repr__(self):
        return "Equilibrium(q=%r, kind=%r)" % (self.q, self.kind)

    def _repr_html_(self):
        return _equilibria_html([self], "qdot equilibrium")


class Equilibria(list):
    """The equilibria found (a list of Equilibrium); .output is the
    qdot.Output of `qdot equilibria --format json`, whose keys (method,
    exact, continuum, equilibria) are attributes too, .json its dict."""

    output = None

    @property
    def json(self):
        return self.output.json

    def __getattr__(self, name):
        out = self.__dict__.get("output") or type(self).output
        if out is not None and name in out:
            return out[name]
        raise AttributeError("Equilibria has no field %r" % name)

    def __repr__(self):
        return "<qdot.Equilibria %d: %s>" % (len(self), "; ".join(
            "%s%s" % (e.kind + " " if e.kind else "", ", ".join(
                "%s = %.6g" % kv for kv in e.q.items())) for e in self))

    def _repr_html_(self):
        return _equilibria_html(self, "qdot equilibria")


def _equilibria_html(eqs, title):
    """A table of equilibria: a row each, the coordinates' values, the
    kind, the exact values (as the library printed them) and the residual."""
    from . import display
    if not eqs:
        return display.block(title, "none found")
    names = list(eqs[0].q)
    rows = [[e.q[k] for k in names] + [e.kind, ", ".join(
        "%s = %s" % kv for kv in e.exact.items()) if e.exact else None, e.residual]
        for e in eqs]
    return display.block(title, display.table(names + ["kind", "exact", "residual"], rows))


class Mode:
    """One normal mode (qdot/modes.h): omega2 the eigenvalue w^2 of
    K a = w^2 M a (negative: an unstable direction), omega = sqrt(omega2)
    (NaN when omega2 < 0), shape the eigenvector a as {coordinate: value},
    normalized so that a^T M a = 1."""

    def __init__(self, omega2, shape):
        self.omega2 = omega2
        self.omega = float(np.sqrt(omega2)) if omega2 >= 0 else float("nan")
        self.shape = shape

    def __repr__(self):
        return "Mode(omega=%.12g, shape=%r)" % (self.omega, self.shape)

    def _repr_html_(self):
        from . import display
        return display.fields({"omega": self.omega, "omega2": self.omega2, "shape": self.shape})


class Modes(list):
    """The modes about a point, ascending in omega2 (a list of Mode).

    about: the point {coordinate: value}; conservative: no damping or
    gyroscopic terms (only then are there Mode entries); eigenvalues: the
    2n state-space eigenvalues s (numpy complex array); stable: 1 stable,
    0 unstable, -1 borderline (qd_modes_result.stable)."""

    output = None  # the qdot.Output of `qdot modes --format json`
    choice_note = None  # which equilibrium the library chose, when it chose
    equilibrium = None  # the Equilibrium the point is, or None for a point given
    residual = None  # the generalized forces left at rest there

    def __init__(self, modes, about, conservative, eigenvalues, stable):
        super().__init__(modes)
        self.about = about
        self.conservative = conservative
        self.eigenvalues = eigenvalues
        self.stable = stable

    @property
    def json(self):
        """The dict `qdot modes FILE --format json` prints."""
        return self.output.json

    def __getattr__(self, name):
        # the other JSON keys (mass_matrix, frequencies, verdict, symmetry, ...)
        out = self.__dict__.get("output") or type(self).output
        if out is not None and name in out:
            return out[name]
        raise AttributeError("Modes has no field %r" % name)

    def __repr__(self):
        about = ", ".join("%s = %.6g" % kv for kv in (self.about or {}).items())
        if not self.conservative:
            return "<qdot.Modes about %s: eigenvalues %s>" % (about, np.round(
                self.eigenvalues, 6).tolist())
        return "<qdot.Modes about %s: omega = %s>" % (
            about, ", ".join("%.10g" % m.omega for m in self))

    def _repr_html_(self):
        """The modes as a table (omega^2, omega, the shape's entries), or the
        eigenvalues when the system is not conservative."""
        from . import display
        about = ", ".join("%s = %s" % (k, display.number(v))
                          for k, v in (self.about or {}).items())
        verdict = {1: "stable", 0: "unstable", -1: "borderline"}.get(self.stable, "")
        title = "qdot modes about %s (%s)" % (about, verdict)
        eig = display.table(["Re s", "Im s"], [[z.real, z.imag] for z in self.eigenvalues],
                            caption="eigenvalues s of the state-space form")
        if not len(self):
            return display.block(title, eig)
        names = list(self[0].shape)
        rows = [[m.omega2, m.omega] + [m.shape[k] for k in names] for m in self]
        return display.block(title, display.table(["omega^2", "omega"] + names, rows,
                                                  caption="shapes normalized a^T M a = 1"),
                             eig)


class Metric:
    """What Model.metric returns: its attributes are given by name (see
    Model.metric); in Jupyter the table of `qdot metric --format json`."""

    __module__ = "qdot"

    def __init__(self, **fields):
        self.__dict__.update(fields)

    def __repr__(self):
        return "<qdot.Metric of %s: det g = %s%s>" % (
            ", ".join(self.coordinates), self.det, ", orthogonal" if self.orthogonal else "")

    def _repr_html_(self):
        return self.output.html()


class _SpeedsHandle:
    """A qd_speeds_eom kept while a SpeedsEquations uses it."""

    def __init__(self, core, se):
        self.core, self.se = core, se
        self.speeds = [se.u[r] for r in range(se.m)]

    def __del__(self):
        if self.se:
            lib.qd_speeds_eom_free(self.se)
            self.se = None


def _speeds_result(core, se, method):
    """A SpeedsEquations of the qd_speeds_eom se (strings in the model language)."""
    e = se
    n, m = e.n, e.m
    text = core.text_of
    return SpeedsEquations([name_of(e.q[j]) for j in range(n)],
                           [name_of(e.u[r]) for r in range(m)],
                           [text(e.kin[j]) for j in range(n)],
                           [[text(e.M[r * m + k]) for k in range(m)] for r in range(m)],
                           [text(e.f[r]) for r in range(m)], method)


def _render_lagrange(core, fmt, at):
    """qd_render_eom of Lagrange's equations of a model that declares
    `speeds` (`qdot eom` renders its speeds form: Model.speeds_eom).  at
    ({name: value} or text) is read by the library's state reader as
    `qdot eom --at` reads it on a model without speeds (qd_state_init: the
    names not given at 0; qd_state_read), an error in it a ModelError
    shown in its text (file `at`)."""
    from .linear import located
    k = new("qd_render_format")
    if not lib.qd_render_format_parse(fmt.encode(), k):
        raise ValueError("eom: no format %r" % (fmt,))
    source = ffi.new("char[]", core.file.encode())
    opts = new("qd_render_opts", {"source": source})
    st = new("qd_state")
    try:
        if at:
            text = _commands.text_arg(at, "at")
            core.check(lib.qd_state_init(core.ctx, core.model, st))
            if lib.qd_state_read(core.ctx, core.model, st, text, ffi.NULL) != lib.QD_OK:
                raise located(core, "at", ffi.string(text))
            opts.nstate, opts.syms, opts.vals = st.n, st.syms, st.vals
        return _commands.rendered(core, lambda buf: lib.qd_render_eom(
            core.ctx, core.model, core.eom_ptr(), opts, k[0], buf))
    finally:
        lib.qd_state_free(st)


def _render(core, fmt, at, speeds=None):
    """What `qdot eom --format fmt [--at ...]` prints (qd_eom_request_render:
    the library derives, reads at's state and renders); speeds: the
    qd_speeds_opts of a model with `speeds`.  A note the command prints
    (a solution too large, the renderer's) is a UserWarning; an error in at
    a ModelError shown in its text."""
    import warnings
    from .linear import located
    k = new("qd_render_format")
    if not lib.qd_render_format_parse(fmt.encode(), k):
        raise ValueError("eom: no format %r" % (fmt,))
    src = _commands.source(core)
    text = _commands.text_arg(at, "at") if at else None
    rq = new("qd_eom_request", {"fmt": k[0], "source": src,
                                "at": text if text is not None else ffi.NULL})
    if speeds is not None:
        rq.speeds = speeds[0]
    out, notes, step = new("qd_buf"), new("qd_buf"), new("qd_eom_step")
    st = lib.qd_eom_request_render(core.ctx, core.model, rq, out, notes, step)
    note = buf_text(notes)
    if st != lib.QD_OK:
        lib.qd_buf_free(out)
        if step[0] == lib.QD_EOM_STEP_AT and text is not None:
            raise located(core, "at", ffi.string(text))
        raise core.error(st, cls=ModelError if step[0] == lib.QD_EOM_STEP_DERIVE else None)
    for line in note.splitlines():
        warnings.warn("eom: " + line, UserWarning, stacklevel=4)
    return buf_text(out)


def _sympy_namespace(core, extra=()):
    """A namespace in which QD_FMT_SYMPY text evaluates: sympy, t, each
    coordinate a Function of t, each parameter (and each name in extra) a
    Symbol, bound only when the printer writes it bare (a name that would
    shadow SymPy, like E, is printed self-contained)."""
    import sympy
    ns = dict(vars(sympy))
    t = cstr(lib.qd_print_time_name(core.ctx))
    ns[t] = sympy.Symbol(t)
    for c in core.coords():
        name = name_of(c)
        if core.text_of(c, QD_FMT_SYMPY) == "%s(%s)" % (name, t):
            ns[name] = sympy.Function(name)
    for sym in [p[1] for p in core.params()] + list(extra):
        name = name_of(sym)
        if core.text_of(sym, QD_FMT_SYMPY) == name:
            ns[name] = sympy.Symbol(name)
    return ns


def _converter(core, sympy, extra=()):
    """A function from an expression to its text or its SymPy value."""
    if not sympy:
        return core.text_of
    ns = _sympy_namespace(core, extra)
    return lambda x: eval(core.text_of(x, QD_FMT_SYMPY), ns)  # noqa: S307 (our printer's text)


class Model:
    """A mechanical system in qdot's model language (docs/language.md).

    Model(text) reads the text; Model.load(path) reads a file.  A model
    that does not read raises qdot.ModelError with the file:line:col
    message.  Parameters keep the values written in the text until set()
    changes them.
    """

    def __init__(self, text, file="<string>"):
        """Read a model from its text; file names it in error messages."""
        if not isinstance(text, (str, bytes, bytearray)):
            raise TypeError("Model() takes the model text as str or bytes, not %s"
                            % type(text).__name__)
        if not isinstance(file, str):
            raise TypeError("Model(): file is a str, not %s" % type(file).__name__)
        if isinstance(text, str):
            text = text.encode()
        text = bytes(text)
        if b"\0" in text:  # C would read the text only up to it
            at = text.index(b"\0")
            line = text.count(b"\n", 0, at) + 1
            col = at - (text.rfind(b"\n", 0, at) + 1) + 1
            raise ValueError("%s:%d:%d: a NUL byte in the model text (byte %d)"
                             % (file, line, col, at))
        self._sets = {}
        self._core = Core(text, file, [])
        self._fixed = None  # the parse with the set() values fixed in, made when needed

    @classmethod
    def load(cls, path):
        """Read the model file at path."""
        with open(path, "rb") as fh:
            return cls(fh.read(), file=str(path))

    def set(self, **params):
        """Give parameters other values (numbers, or text such as "pi/6"),
        as the command line's --set does: parameters defined from them and
        the initial values follow.  Returns the model itself."""
        sets = dict(self._sets, **params)
        core = Core(self._core.text, self._core.file, list(sets.items()))
        self._core, self._sets, self._fixed = core, sets, None
        return self

    def _for(self, derivation):
        """The parse the command named derivation reads: by the library's
        rule (qd_model_opts_for, as the command line's --set) the values
        given by set() are written into its formulas as numbers
        (hamiltonian, eom, ...), or stay symbols holding them (simulate,
        modes, ...: self._core)."""
        opts = new("qd_model_opts")
        if lib.qd_model_opts_for(opts, derivation.encode()) != 0:
            raise ValueError("no parameter rule for %r" % (derivation,))
        if not opts.fix_params or not self._sets:
            return self._core
        if self._fixed is None:
            self._fixed = Core(self._core.text, self._core.file, list(self._sets.items()),
                               derivation)
        return self._fixed

    @property
    def coordinates(self):
        """The names of the generalized coordinates, in model order."""
        return [name_of(c) for c in self._core.coords()]

    @property
    def params(self):
        """{name: value} of every parameter, in model order."""
        return {name: value for name, _, value in self._core.params()}

    @property
    def initial(self):
        """The initial state {name: value} (coordinates, velocities NAME',
        t) from the model's `initial` line, 0 where it gives none."""
        syms, vals = self._core.state()
        n = len(self.coordinates)
        return {name_of(s): v for s, v in zip(syms[:2 * n + 1], vals)}

    def eom(self, sympy=False):
        """Lagrange's equations M q'' = f (an Equations); sympy=True gives
        SymPy matrices instead of strings (needs sympy)."""
        core = self._for("eom")
        e = core.eom()
        n = e.n
        lams = [getattr(e.con[k], "lambda") for k in range(e.ncon)]
        conv = _converter(core, sympy, lams)
        M = [[conv(e.M[i * n + j]) for j in range(n)] for i in range(n)]
        f = [conv(e.f[i]) for i in range(n)]
        if sympy:
            import sympy as sp
            M, f = sp.Matrix(M), sp.Matrix(f)
        cons = [cstr(e.con[k].name) for k in range(e.ncon)]
        out = Equations([name_of(e.q[j]) for j in range(n)], M, f, cons)
        if lib.qd_model_nspeeds(core.model):
            out._print = lambda fmt, at: _render_lagrange(core, fmt, at)
        else:
            out._print = lambda fmt, at: _render(core, fmt, at)
        return out

    def speeds_eom(self, method="kane", appell=False, multipliers=False):
        """The equations in the model's generalized speeds (a model with a
        `speeds` statement; `qdot eom` on it): a SpeedsEquations, derived by
        method "kane", "appell" or "hamel"; appell: also the Gibbs-Appell
        function S; multipliers: also the constraints' multipliers."""
        core = self._for("eom")
        k = new("qd_speeds_method")
        if not isinstance(method, str) or not lib.qd_speeds_method_from_name(method.encode(), k):
            raise Error("speeds_eom: method is kane, appell or hamel, not %r" % (method,))
        opts = new("qd_speeds_opts", {"method": k[0], "appell": bool(appell),
                                      "multipliers": bool(multipliers)})
        se = lib.qd_speeds_derive(core.ctx, core.model, opts)
        if not se:
            raise core.error(cls=ModelError)
        ptr = _SpeedsHandle(core, se)  # freed with the result
        out = _speeds_result(core, se, method)
        out._handle = ptr
        out._print = lambda fmt, at: _render(core, fmt, at, opts)

        def hamel(fmt="text"):
            """Hamel's coefficients gamma_ikm (text, or a dict for "json")."""
            k = lib.QD_RENDER_TEXT if fmt == "text" else lib.QD_RENDER_JSON
            text = _commands.rendered(core, lambda buf: lib.qd_render_hamel(core.ctx, ptr.se, k, buf))
            return text if fmt == "text" else _json.loads(text)
        out.hamel = hamel
        return out

    def metric(self, sympy=False, force=None):
        """The metric of the coordinates (qdot/metric.h, `qdot metric`): an
        object whose attributes are the JSON keys of `qdot metric --format
        json` that come from the library: coordinates, metric,
        metric_inverse, det, christoffel_first and christoffel_second
        (indexed [l][i][j] by coordinate names), T2, T1, T0, Q, geodesic,
        scale_factors, orthogonal, jacobian_det and singular (a list of
        (lhs, rhs, period)).  Expressions are strings, or SymPy values with
        sympy=True.  The other keys of the JSON (qd_metric_json: force,
        chart) are attributes too, .json is the whole dict and .output its
        qdot.Output; force: "G1, G2, ..." the covariant components of a
        force, as --force (default: the model's Q)."""
        core = self._for("metric")
        g = lib.qd_metric_new(core.ctx, core.model)
        if not g:
            raise core.error(cls=ModelError)
        try:
            m = g
            n = m.n
            conv = _converter(core, sympy)
            names = [name_of(m.q[i]) for i in range(n)]
            opt = lambda x: conv(x) if x else None  # noqa: E731
            vec = lambda a, k=0: {names[i]: conv(a[k + i]) for i in range(n)}  # noqa: E731
            mat = lambda a, k=0: {names[i]: vec(a, k + i * n) for i in range(n)}  # noqa: E731
            sym3 = lambda a: {names[l]: mat(a, l * n * n) for l in range(n)}  # noqa: E731,E741
            G = ffi.new("const qd_expr *[]", n + 1)
            if force is not None:
                if not isinstance(force, str):
                    raise TypeError("metric: force is text \"G1, G2, ...\", not %s"
                                    % type(force).__name__)
                core.check(lib.qd_metric_force_read(core.ctx, g, force.encode(), G))
            out = _commands.output(core, "metric", lambda buf: lib.qd_metric_json(
                core.ctx, g, G if force is not None else ffi.NULL, buf))
            ns = Metric(
                coordinates=names, source="L" if m.from_L else "T",
                T2=conv(m.T2), T1=conv(m.T1), T0=conv(m.T0),
                metric=mat(m.g), metric_inverse=mat(m.ginv), det=conv(m.det),
                christoffel_first=sym3(m.first), christoffel_second=sym3(m.second),
                Q=vec(m.Q), geodesic=vec(m.geodesic), constrained=m.constrained,
                scale_factors=vec(m.h),
                scale_from="positions" if m.scale_geometric else "metric",
                orthogonal=m.orthogonal, jacobian_det=opt(m.jac_det),
                singular=[(conv(m.sing[k].lhs), conv(m.sing[k].rhs), opt(m.sing[k].period))
                          for k in range(m.nsing)])
            for key in out.keys():
                if not hasattr(ns, key):
                    setattr(ns, key, out[key])
            ns.json, ns.output = out.json, out
            return ns
        finally:
            lib.qd_metric_free(g)

    def hamiltonian(self, sympy=False, at=None, second_kind=False):
        """The Hamiltonian and Hamilton's equations (a Hamiltonian); sympy=True
        gives SymPy expressions instead of strings.  Its other attributes
        are the keys of `qdot hamiltonian --format json` (qd_render_hamiltonian):
        model, coordinates, momenta, definitions, velocities, H, dq_dt,
        dp_dt, H_is_energy, H_minus_energy, conserved, H_given (L, L_error
        for a model given by H); .json is that dict.  at={name: value} or
        text (coordinates, momenta named as printed, p_x, t; the others 0,
        not the model's initial values), read as --at is (qd_ham_point_at):
        H, dq_dt and dp_dt of the JSON are then numbers there, and "at" the
        point.  second_kind=True gives Hamilton's equations of the second
        kind (qd_ham2_derive, Desloge ch. 72 Thm 1, `hamiltonian
        --second-kind`): H is then K = sum s q' - T, momenta the s_q =
        dT/dq', dp the ds/dt = -dK/dq + Q, is_energy K = T; the JSON keys K,
        forces, ds_dt, K_is_T, K_minus_T, s_is_p replace H, dp_dt and the H
        verdicts."""
        core = self._for("hamiltonian")
        given = lib.qd_model_hamiltonian_given(core.model)
        derive = lib.qd_ham2_derive if second_kind else lib.qd_ham_derive
        h = derive(core.ctx, core.model, ffi.NULL if given else core.eom_ptr())
        if not h:
            raise core.error(cls=ModelError)
        pt = new("qd_ham_point")
        try:
            hh = h
            n = hh.n
            point = ffi.NULL
            if at:  # read and evaluated as --at is (qd_ham_point_at)
                from .linear import located
                text = _commands.text_arg(at, "at")
                if lib.qd_ham_point_at(core.ctx, core.model, h, text, pt) != lib.QD_OK:
                    if lib.qd_ctx_diag(core.ctx).located:
                        raise located(core, "at", ffi.string(text))
                    raise core.error(cls=NumericalError)
                point = pt
            src = _commands.source(core)
            data = _json.loads(_commands.rendered(core, lambda buf: lib.qd_render_hamiltonian(
                core.ctx, core.model, h, src, point, lib.QD_RENDER_JSON, buf)))
            latex = _commands.rendered(core, lambda buf: lib.qd_render_hamiltonian(
                core.ctx, core.model, h, src, ffi.NULL, lib.QD_RENDER_LATEX, buf))
            conv = _converter(core, sympy, [hh.p[j] for j in range(n)])
            out = Hamiltonian(conv(hh.H), [name_of(hh.p[j]) for j in range(n)],
                              [conv(hh.dq[j]) for j in range(n)],
                              [conv(hh.dp[j]) for j in range(n)],
                              bool(hh.conserved), bool(hh.is_energy))
            out.output = _commands.Output("hamiltonian", data, lambda: latex, core)
            return out
        finally:
            lib.qd_ham_point_free(pt)
            lib.qd_ham_free(h)

    def _lookup(self, names, what, core=None, cyclic=False):
        """The coordinate symbols of names (a list, or "a,b" text), read by
        the library as --ignore is (qd_routh_ignore_read: each a coordinate,
        none twice, and with cyclic=True each cyclic); ValueError with its
        message ("did you mean", "r cannot be ignored: ...")."""
        core = core or self._core
        if not isinstance(names, str):
            if not names or not all(isinstance(x, str) and x for x in names):
                raise ValueError("%s: name coordinates (\"phi\" or [\"phi\", ...]), not %r"
                                 % (what, names))
            names = ", ".join(names)
        cap = lib.qd_model_ncoords(core.model)
        syms, n = ffi.new("const qd_expr *[]", cap or 1), ffi.new("size_t *")
        e = core.eom_ptr() if cyclic else ffi.NULL
        if lib.qd_routh_ignore_read(core.ctx, core.model, e, names.encode(), syms, cap, n,
                                    ffi.NULL) != lib.QD_OK:
            raise ValueError("%s: %s" % (what, core.error().message))
        return [syms[i] for i in range(n[0])]

    def _ignored(self, ignore, what, core=None):
        """The coordinate symbols of ignore, each cyclic (see _lookup)."""
        return self._lookup(ignore, what, core, cyclic=True)

    def routh(self, ignore):
        """Routh's reduction (`qdot routh FILE --ignore Q[,Q...]`, qd_routh_json):
        a qdot.Output with model, ignored, momenta, kept,
        momentum_definitions, R, R2, R1, R0, effective_potential,
        jacobi_integral, equations, gyroscopic, quadratures, conserved (and
        the forced and implicit keys where they apply).  ignore: a name, "a,b"
        or a list of names."""
        core = self._for("routh")
        ign = self._ignored(ignore, "routh", core)
        opts = new("qd_routh_opts", {"implicit": True, "forced": True})  # as `qdot routh`
        r = lib.qd_routh_derive_opts(core.ctx, core.model, core.eom_ptr(), len(ign),
                                     exprs(ign), opts)
        if not r:
            raise core.error(cls=ModelError)
        try:
            src = _commands.source(core)
            latex = _commands.rendered(core, lambda buf: lib.qd_routh_print(
                core.ctx, r, core.model, core.eom_ptr(), src, QD_FMT_LATEX, buf))
            return _commands.output(core, "routh", lambda buf: lib.qd_routh_json(
                core.ctx, r, core.model, core.eom_ptr(), src, buf), lambda: latex)
        finally:
            lib.qd_routh_free(r)

    def orbit(self, ignore, at=None, momentum=None, energy=None, equation=False):
        """The motion left in one coordinate (`qdot orbit FILE --ignore Q`,
        qd_orbit_solve_text and qd_orbit_render): a qdot.Output with the keys
        of `qdot orbit --format json` (V_eff, the turning points and the
        kind of orbit, the radial period and advances, the circular orbits,
        Kepler's conic, ...).  ignore: the cyclic coordinates (all but one);
        at ({name: value} or "r=1, theta'=1.5"), momentum ({"p_theta": 3}
        or text) and energy (a number or an expression in the parameters)
        as --at, --momentum and --energy; equation=True is --orbit."""
        core = self._core
        ign = self._ignored(ignore, "orbit")
        o = lib.qd_orbit_derive(core.ctx, core.model, core.eom_ptr(), len(ign), exprs(ign))
        if not o:
            raise core.error()
        res = new("qd_orbit_result")
        keep = [_commands.text_arg(x, what) for x, what in
                ((at, "at"), (momentum, "momentum"), (energy, "energy"))]
        t = new("qd_orbit_text", {k: (ffi.NULL if v is None else v)
                                  for k, v in zip(("at", "momentum", "energy"), keep)})
        try:
            core.check(lib.qd_orbit_solve_text(core.ctx, o, core.model, t, res))
            src = _commands.source(core)
            return _commands.output(core, "orbit", lambda buf: lib.qd_orbit_render(
                core.ctx, o, res, src, bool(equation), True, buf))
        finally:
            lib.qd_orbit_result_free(res)
            lib.qd_orbit_free(o)

    def action(self, at=None, angles=()):
        """The action-angle variables of a separable bounded motion (`qdot
        action`, qd_action_at and qd_action_print): a qdot.Output with
        separation, energy, coordinates (per coordinate: constant, value,
        kind, turning_points, J, omega, angle), actions, frequencies, angles,
        degeneracies, H_of_J.  at: {name: value} over the model's initial
        values (coordinates, velocities "NAME'", t, parameters), as --at;
        angles: coordinates to take as angles (--angle).  The state is read
        as --at is (qd_action_state_read): over the model's initial values,
        and for a model given by H the momenta at names."""
        from .linear import located
        core = self._for("action")
        angle_syms = self._lookup(angles, "action", core) if angles else []
        keep = exprs(angle_syms)
        opts = new("qd_action_opts", {"nangles": len(angle_syms), "angles": keep})
        act, st = new("qd_action"), new("qd_state")
        text = _commands.text_arg(at, "at") if at else None
        try:  # the state read as --at is (qd_action_state_read)
            if lib.qd_action_state_read(core.ctx, core.model,
                                        text if text is not None else ffi.NULL, st) != lib.QD_OK:
                if text is not None and lib.qd_ctx_diag(core.ctx).located:
                    raise located(core, "at", ffi.string(text))
                raise core.error()
            core.check(lib.qd_action_at(core.ctx, core.model, st.n, st.syms, st.vals, opts,
                                        act))
            return _commands.output(core, "action", lambda buf: lib.qd_action_print(
                core.ctx, act, True, buf))
        finally:
            lib.qd_action_free(act)
            lib.qd_state_free(st)

    def _phase_read(self, ph, text, what, core=None):
        """text read as a function on phase space (qd_phase_read); a
        ModelError shown in the text when it does not read."""
        core = core or self._core
        if not isinstance(text, str):
            raise TypeError("%s is an expression (text), not %s" % (what, type(text).__name__))
        diag = new("qd_diag")
        x = lib.qd_phase_read(core.ctx, ph, text.encode(), diag)
        if not x:
            lib.qd_ctx_clear_error(core.ctx)
            raise ModelError(format_diag(diag, what, text.encode()), diag, what)
        return x

    def bracket(self, F, G=None, dt=False):
        """The Poisson bracket [F, G] in the model's coordinates and momenta
        p_<q> (`qdot bracket FILE F G`), or with dt=True and no G the rate
        dF/dt along the motion (`qdot bracket --dt F`): a qdot.Output with
        the keys of `qdot bracket --format json` (qd_phase_bracket_print);
        LaTeX in Jupyter."""
        core = self._for("bracket")
        if bool(dt) == (G is not None):
            raise ValueError("bracket: give F and G, or F with dt=True")
        ph = new("qd_phase")
        try:
            core.check(lib.qd_phase_init(core.ctx, core.model, ph))
            f = self._phase_read(ph, F, "F", core)
            g = ffi.NULL if dt else self._phase_read(ph, G, "G", core)
            r = lib.qd_phase_dt(core.ctx, ph, f) if dt else lib.qd_bracket(
                core.ctx, ph.n, ph.q, ph.p, f, g)
            if not r:
                raise core.error()
            latex = _commands.rendered(core, lambda buf: lib.qd_phase_bracket_print(
                core.ctx, ph, f, g, r, QD_FMT_LATEX, False, buf))
            return _commands.output(core, "bracket", lambda buf: lib.qd_phase_bracket_print(
                core.ctx, ph, f, g, r, QD_FMT_TEXT, True, buf), lambda: latex)
        finally:
            lib.qd_phase_free(ph)

    def canonical(self, Q=None, P=None, lagrange=False, K=False, generator=None, F=None):
        """Is (q, p) -> (Q, P) canonical (`qdot canonical FILE --Q ... --P ...`,
        qd_canonical_examine and qd_canon_report_print)?  Or, with
        generator="F1".."F4" and its expression F (`--generator TYPE EXPR`),
        the map the generating function gives and K = H + dF/dt
        (qd_generate, qd_gen_result_print).  Q, P: "Q1, ..." text (one
        expression in q, p_q, t per coordinate) or a list of them;
        lagrange, K as --lagrange and --K.  A qdot.Output with the keys of
        `qdot canonical --format json`; a "no" is an answer, not an error."""
        core = self._for("canonical")
        if (generator is None) == (Q is None and P is None) or (generator is None) != (
                F is None) or (generator is None and (Q is None or P is None)):
            raise ValueError("canonical: give Q and P, or generator (\"F1\".. \"F4\") and F")
        if generator is not None and (lagrange or K):
            raise ValueError("canonical: lagrange and K go with Q and P")
        ph = new("qd_phase")
        try:
            core.check(lib.qd_phase_init(core.ctx, core.model, ph))
            if generator is not None:
                return self._generate(ph, generator, F, core)
            return self._examine(ph, Q, P, lagrange, K, core)
        finally:
            lib.qd_phase_free(ph)

    def _phase_list(self, ph, text, what, core=None):
        """"E1, E2, ..." (or a list) read as ph.n functions on phase space."""
        core = core or self._core
        if isinstance(text, (list, tuple)):
            text = ", ".join(text)
        if not isinstance(text, str):
            raise TypeError("canonical: %s is text \"E1, ...\" or a list, not %s"
                            % (what, type(text).__name__))
        out = ffi.new("const qd_expr *[]", ph.n + 1)
        diag = new("qd_diag")
        if lib.qd_phase_read_list(core.ctx, ph, text.encode(), out, diag) != 0:
            lib.qd_ctx_clear_error(core.ctx)
            raise ModelError(format_diag(diag, what, text.encode()), diag, what)
        return out

    def _examine(self, ph, Q, P, lagrange, K, core=None):
        core = core or self._core
        q, p = self._phase_list(ph, Q, "Q", core), self._phase_list(ph, P, "P", core)
        rep = new("qd_canon_report")
        try:
            st = lib.qd_canonical_examine(core.ctx, ph, q, p, bool(lagrange), bool(K), rep)
            if st != 0:
                raise core.error(st)
            return _commands.output(core, "canonical", lambda buf: lib.qd_canon_report_print(
                core.ctx, ph, rep, True, buf))
        finally:
            lib.qd_canon_report_free(rep)

    def _generate(self, ph, generator, F, core=None):
        core = core or self._core
        types_ = {"F1": lib.QD_GEN_F1, "F2": lib.QD_GEN_F2, "F3": lib.QD_GEN_F3,
                  "F4": lib.QD_GEN_F4}
        if generator not in types_:
            raise ValueError("canonical: generator is F1, F2, F3 or F4, not %r" % (generator,))
        core.check(lib.qd_phase_new_vars(core.ctx, ph))
        f = self._phase_read(ph, F, "generator", core)
        core.check(lib.qd_phase_ham(core.ctx, ph, True))
        g = new("qd_gen_result")
        kind = types_[generator]
        try:
            core.check(lib.qd_generate(core.ctx, kind, ph.n, ph.q, ph.p, ph.Q, ph.P, f,
                                       lib.qd_time(core.ctx), ph.h.H, g))
            return _commands.output(core, "canonical", lambda buf: lib.qd_gen_result_print(
                core.ctx, ph, kind, f, g, True, buf))
        finally:
            lib.qd_gen_result_free(g)

    def stability(self, ignore=None, driven=None, momentum=None, omega=None, at=None,
                  guess=None, scan=None, steps=None):
        """Steady motions of a system with cyclic coordinates and their
        stability (`qdot stability`: qd_stability_problem_read and _solve,
        qd_stability_print): a qdot.Output with model, kind ("free" or
        "driven"), steady, residual, Veff, the mass, damping, gyroscopic and
        stiffness matrices, hessian, frequencies, eigenvalues ([re, im]
        pairs), stable, secular, verdict (of the motion nearest the starting
        values), steady_motions (every one found) and complete.  Give either
        ignore (the cyclic coordinates, momenta free: "phi" or a list) or
        driven (maintained rates "phi' = 2", a list or text); momentum
        ("p_phi=3"), omega ("phi'=2"), at ("theta=pi/3") and guess as
        --momentum, --omega, --at and --guess (text or {name: value}).  An
        error in one of them is a qdot.ModelError shown in its text, the
        library's refusals (neither or both of ignore and driven) a
        qdot.ArgumentError.  scan ("NAME=A:B" or (name, a, b); --scan, steps
        as --steps): the steady motion followed along the parameter
        (qd_stability_problem_scan, qd_stability_scan_write), an Output
        with parameter, range, steps, samples and transitions."""
        from .linear import located
        core = self._for("stability")
        with _progress.watch(core, "stability"):  # the multistart's steps, Ctrl-C
            if steps is not None and scan is None:
                raise ValueError("stability: steps is the number of steps of scan: give "
                                 "scan=\"NAME=A:B\"")
            if isinstance(ignore, (list, tuple)):
                ignore = ", ".join(ignore)
            items = [driven] if isinstance(driven, str) else list(driven or [])
            texts = {k: _commands.text_arg(v, k) for k, v in
                     (("ignore", ignore), ("momentum", momentum), ("omega", omega), ("at", at),
                      ("guess", guess))}
            keep = [_commands.text_arg(x, "driven") for x in items]
            dr = ffi.new("const char *[]", keep) if keep else ffi.NULL
            c = lambda k: texts[k] if texts[k] is not None else ffi.NULL  # noqa: E731
            spec = new("qd_stability_spec", {"ignore": c("ignore"), "driven": dr,
                                             "ndriven": len(keep), "momentum": c("momentum"),
                                             "omega": c("omega"), "at": c("at"),
                                             "guess": c("guess")})
            p = new("qd_stability_problem")
            try:
                if lib.qd_stability_problem_read(core.ctx, core.model, core.eom_ptr(), spec,
                                                 p) != lib.QD_OK:
                    d = lib.qd_ctx_diag(core.ctx)
                    field = ffi.string(d.name).decode()
                    text = p.driven if field == "driven" else texts.get(field)
                    if d.located and text:
                        raise located(core, field, ffi.string(text))
                    raise core.error(cls=ArgumentError if d.status == lib.QD_ERR_ARG else None)
                src = _commands.source(core)
                if scan is not None:
                    return self._stability_scan(core, p, scan, steps, src)
                core.check(lib.qd_stability_problem_solve(core.ctx, p), NumericalError)
                rep = new("qd_stability_report", {"s": p.s, "given": ffi.addressof(p.given),
                                                  "set": ffi.addressof(p.set), "an": p.an,
                                                  "model": src})
                return _commands.output(core, "stability", lambda buf: lib.qd_stability_print(
                    core.ctx, rep, True, buf))
            finally:
                lib.qd_stability_problem_free(p)

    def _stability_scan(self, core, p, scan, steps, src):
        """stability(scan=...): qd_stability_problem_scan and its JSON."""
        from .linear import scan_range
        name, a, b = scan_range(core, scan, "stability")
        if steps is not None and (isinstance(steps, bool) or not isinstance(steps, int) or
                                  not 1 <= steps <= 100000):
            raise ValueError("stability: steps is a number from 1 to 100000, not %r" % (steps,))
        sc = new("qd_scan")
        try:
            core.check(lib.qd_stability_problem_scan(core.ctx, p, core.model, name, a, b,
                                                     steps or 0, sc), NumericalError)
            return _commands.output(core, "stability", lambda buf: lib.qd_stability_scan_write(
                core.ctx, p, name, sc, True, buf))
        finally:
            lib.qd_scan_free(sc)

    def zvc(self, box, level=None, cells=400, through=None, at=None):
        """Jacobi's integral and the zero-velocity curves W = level over a
        box (`qdot zvc FILE --box ... --level H`, qd_zvc_picture_make and
        qd_zvc_json): a qdot.Output with h, W, level, grid, equilibria (in
        the box, each with its kind and W there as "h") and curves (each
        "closed" and the two coordinates' arrays).  box: "x=A:B, y=C:D"
        (two coordinates, across and up); the level, exactly one of
        (qd_zvc_level_read): level, a number or an expression in the
        parameters (--level); through, a point at rest ({name: value} or
        "x=..., y=..."; --through), the level W there; at, a state
        ("x=..., x'=..."; --at), h there.  The other coordinates are those
        of the point (0 for a level).  cells: grid cells each way (--cells;
        the CLI's default 400).  Errors in a text are qdot.ModelErrors shown
        in it."""
        from .linear import Point, located
        core = self._for("zvc")
        if not isinstance(box, str):
            raise TypeError("zvc: box is text \"x=A:B, y=C:D\", not %s" % type(box).__name__)
        if isinstance(cells, bool) or not isinstance(cells, int) or not 2 <= cells <= 4000:
            raise ValueError("zvc: cells is a number of grid cells from 2 to 4000, not %r"
                             % (cells,))
        p = Point(core)
        e = p.e
        b, z, pic = new("qd_zvc_box"), new("qd_zvc"), new("qd_zvc_picture")
        texts = {k: _commands.text_arg(v, k) for k, v in
                 (("level", level), ("through", through), ("at", at))}
        c = {k: v if v is not None else ffi.NULL for k, v in texts.items()}
        try:
            if e.n < 2:
                raise ValueError("zvc: zero-velocity curves need two coordinates; the model "
                                 "has %d" % e.n)
            if lib.qd_zvc_box_read(core.ctx, core.model, e, box.encode(), b) != lib.QD_OK:
                raise located(core, "box", box.encode())
            core.check(lib.qd_zvc_derive(core.ctx, core.model, e, z))
            q, h = ffi.new("double[]", e.n + 1), new("double")
            where = ffi.new("const char **")
            if lib.qd_zvc_level_read(core.ctx, p.pt, z, c["level"], c["through"], c["at"], q,
                                     h, where) != lib.QD_OK:
                if where[0] == ffi.NULL:
                    raise core.error(cls=ArgumentError)
                which = next(k for k in c if c[k] == where[0])
                raise located(core, which, ffi.string(texts[which]))
            b.nx = b.ny = cells
            st = p.pt.st
            core.check(lib.qd_zvc_picture_make(core.ctx, core.model, e, z, b, st.n, st.syms,
                                               st.vals, h[0], True, pic))
            return _commands.output(core, "zvc", lambda buf: lib.qd_zvc_json(
                core.ctx, e, pic, buf))
        finally:
            lib.qd_zvc_picture_free(pic)
            p.free()

    def impulse(self, at=None, prescribe=None):
        """The motion just after a blow, a sudden constraint or a collision
        (`qdot impulse`, qd_impulse_solve and qd_render_impulse): a
        qdot.Output with velocities_before, velocities_after,
        generalized_impulses, impulsive_multipliers, redundant,
        impulsive_reactions, kinetic_energy_before, kinetic_energy_after,
        energy_lost, exact (the closed forms in the parameters), theorems
        (carnot, bertrand, thomson) and collision.  The state just before
        is the model's `initial` as written; at={name: value} or "th=pi/2"
        (coordinates, velocities "NAME'", t; numbers or exact text "pi/6")
        changes it, as --at (qd_impulse_state_read).  prescribe: velocities
        held just after, "x' = 1, up: y' = 0" or a list of such, as
        --prescribe (Thomson's problem; qd_model_add_given)."""
        core = self._core
        if prescribe:  # added to a parse of its own: the model keeps its statements
            core = Core(self._core.text, self._core.file, list(self._sets.items()), "impulse")
            for text in [prescribe] if isinstance(prescribe, str) else prescribe:
                d = new("qd_diag")
                if lib.qd_model_add_given(core.model, b"prescribe", ffi.NULL,
                                          text.encode(), d) != lib.QD_OK:
                    lib.qd_ctx_clear_error(core.ctx)
                    raise ArgumentError(format_diag(d, "prescribe", text.encode()), d.status)
        n = lib.qd_model_ncoords(core.model)
        q0, v0 = ffi.new("const qd_expr *[]", n or 1), ffi.new("const qd_expr *[]", n or 1)
        t0 = ffi.new("const qd_expr **")
        at_text = _commands.text_arg(at, "at") if at else ffi.NULL
        if lib.qd_impulse_state_read(core.ctx, core.model, at_text, q0, v0, t0) != lib.QD_OK:
            raise core.error(cls=ArgumentError)
        opts = new("qd_impulse_opts", {"q": q0, "qd": v0, "t": t0[0], "exact": True,
                                       "max_ops": 0})  # as `qdot impulse`
        res = new("qd_impulse")
        try:
            core.check(lib.qd_impulse_solve(core.ctx, core.model, opts, res))
            latex = _commands.rendered(core, lambda buf: lib.qd_render_impulse(
                core.ctx, core.model, res, lib.QD_RENDER_LATEX, buf))
            return _commands.output(core, "impulse", lambda buf: lib.qd_render_impulse(
                core.ctx, core.model, res, lib.QD_RENDER_JSON, buf), lambda: latex)
        finally:
            lib.qd_impulse_free(res)

    def scatter(self, energy, b=None, theta=None, lab_theta=None, masses=None, core=None,
                ignore=None, absorbing=False, recoil=False):
        """Classical scattering by a central potential (`qdot scatter`,
        qd_scatter_read, qd_scatter_answer_query and qd_scatter_render): a
        qdot.Output with the keys of `qdot scatter --format json` (model,
        potential, radius, energy, b, kind, closest_approach, deflection,
        cross_section, branches, range, total_cross_section, rainbows,
        glories, orbiting, capture_cross_section, ...).  energy (> 0) and
        one of b (impact parameter), theta (a centre-of-mass angle) or
        lab_theta (with masses "m1,m2" or (m1, m2)); core: a hard core's
        radius (absorbing: it captures what reaches it); recoil: count the
        target too (identical particles); ignore: the cyclic angle when two
        are cyclic.  Values are
        numbers or expressions in the parameters, as the options take them."""
        cr = self._for("scatter")
        if isinstance(masses, (list, tuple)):
            masses = ",".join(repr(float(x)) for x in masses)
        vals = {"energy": energy, "b": b, "theta": theta, "lab_theta": lab_theta,
                "core": core, "masses": masses}
        keep = {k: _commands.text_arg(v, k) for k, v in vals.items()}
        t = new("qd_scatter_text", {k: (ffi.NULL if v is None else v) for k, v in keep.items()})
        t.absorbing, t.recoil = bool(absorbing), bool(recoil)
        q = new("qd_scatter_query")
        cr.check(lib.qd_scatter_read(cr.ctx, cr.model, t, q))
        ign = _commands.text_arg(ignore, "ignore")
        s_ = lib.qd_scatter_from_model(cr.ctx, cr.model, cr.eom_ptr(),
                                       ign if ign is not None else ffi.NULL, q.core, ffi.NULL)
        if not s_:
            raise cr.error()
        try:
            ans = new("qd_scatter_answer")
            cr.check(lib.qd_scatter_answer_query(cr.ctx, s_, q, ans))
            src = _commands.source(cr)
            return _commands.output(cr, "scatter", lambda buf: lib.qd_scatter_render(
                cr.ctx, s_, ans, src, True, buf))
        finally:
            lib.qd_scatter_free(s_)

    def path(self, start, end, energy=None, all=False, segments=0, guess=None):
        """Stationary paths of the action between two configurations, with
        their kinetic foci (`qdot path FILE --from ... --to ...`,
        qd_path_end_read, qd_path_find or qd_path_find_energy, qd_path_json):
        a qdot.Output with count and paths (each action, initial_velocities,
        multipliers, residual, samples [[t, q...], ...], kinetic_foci,
        kinetic_foci_multiplicity, minimum, examined).  start, end: "q=VALUE,
        ..., t=T" or {name: value}, as --from and --to (the end's time unless
        energy is given: Maupertuis' paths of that energy); all=True is
        --all; segments as --segments; a free end "y=free" as in --from and --to;
        guess a list of starting velocities ("x'=1" or {name: value}) as --guess
        (qd_path_ends_read reads them all, as for the command line)."""
        core = self._core
        e = core.eom_ptr()
        E = new("double")
        if energy is not None:
            core.check(lib.qd_model_number(core.ctx, core.model,
                                           _commands.text_arg(energy, "energy"), E))
        ends = new("qd_path_ends")
        keep = [_commands.text_arg(g, "guess") for g in guess or []]
        gs = ffi.new("const char *[]", keep) if keep else []
        o = new("qd_path_opts", {"all": bool(all), "segments": int(segments)})
        ps = new("qd_path_set")
        try:
            core.check(lib.qd_path_ends_read(
                core.ctx, core.model, e, _commands.text_arg(start, "from"),
                _commands.text_arg(end, "to"), len(gs), gs or ffi.NULL, energy is not None,
                ends, o))
            if energy is None:
                core.check(lib.qd_path_find(core.ctx, core.model, e, o, ps), cls=NumericalError)
            else:
                core.check(lib.qd_path_find_energy(core.ctx, core.model, e, E[0], o, ps),
                           cls=NumericalError)
            return _commands.output(core, "path", lambda buf: lib.qd_path_json(
                core.ctx, ps, core.model, e, buf))
        finally:
            lib.qd_path_set_free(ps)
            lib.qd_path_ends_free(ends)

    def integrals(self, search=True):
        """Integrals of motion (`qdot integrals`, qd_integrals_json): a
        qdot.Output with model, coordinates, L, cyclic, jacobi,
        energy_balance, found, tested, noether (of the model's `symmetry`
        statements), proposed (its `integral` statements).  search=False is
        --no-search."""
        core = self._for("integrals")
        o = new("qd_integrals_opts", {"search": bool(search)})
        I = lib.qd_integrals_derive(core.ctx, core.model, core.eom_ptr(), o)  # noqa: E741
        if not I:
            raise core.error()
        g = new("qd_integrals_given")
        try:
            core.check(lib.qd_integrals_given_derive(core.ctx, I, core.model, g))
            src = _commands.source(core)
            latex = _commands.rendered(core, lambda buf: lib.qd_integrals_latex(
                core.ctx, I, g, buf))  # `qdot integrals --format latex`: Jupyter shows it
            return _commands.output(core, "integrals", lambda buf: lib.qd_integrals_json(
                core.ctx, I, g, src, buf), lambda: latex)
        finally:
            lib.qd_integrals_given_free(g)
            lib.qd_integrals_free(I)

    def hj(self, solve=False, energy=None):
        """The Hamilton-Jacobi equation (`qdot hj`, qd_hj_json): a qdot.Output
        with model, H, equation, time_independent, separable, form, why,
        separation (per coordinate), W, constants, energy_constant.
        solve=True is --solve (the motion where the quadratures close);
        energy names the energy constant (default E)."""
        core = self._for("hj")
        name = ffi.new("char[]", energy.encode()) if energy else ffi.NULL
        h = lib.qd_hj_derive(core.ctx, core.model, new("qd_hj_opts", {"energy_name": name}))
        if not h:
            raise core.error(cls=ModelError)
        try:
            if solve and h.separable:
                core.check(lib.qd_hj_solve(core.ctx, h))
            src = _commands.source(core)
            latex = _commands.rendered(core, lambda buf: lib.qd_hj_print(
                core.ctx, h, core.model, src, QD_FMT_LATEX, buf))
            return _commands.output(core, "hj", lambda buf: lib.qd_hj_json(
                core.ctx, h, src, buf), lambda: latex)
        finally:
            lib.qd_hj_free(h)

    def check(self):
        """The verdict and summary of `qdot check` (qd_check_verdict_of,
        qd_render_check): a qdot.Output whose keys are those of `qdot check
        --format json` ("ok"; "code", "reason", "message", "witness" for a no)."""
        core = self._core
        v = new("qd_check_verdict")
        core.check(lib.qd_check_verdict_of(core.ctx, core.model, core.eom_ptr(), v))
        src = _commands.source(core)
        o = new("qd_render_opts", {"source": src})
        return _commands.output(core, "check", lambda buf: lib.qd_render_check(
            core.ctx, core.model, core.eom_ptr(), o, v, lib.QD_RENDER_JSON, buf))

    def equilibria(self, guess=None, box=None, *, near=None):
        """Every equilibrium found (an Equilibria: a list of Equilibrium,
        sorted by q), as `qdot equilibria` finds them (qd_equilibria_find_text
        on the equations with the holonomic constraints eliminated): exact
        where the equations solve in closed form, else by a multi-start
        Newton search over the default box.  guess ({coordinate: value} or
        "q1=VALUE, ..."; an Equilibrium): Newton from there only, as --guess
        (near= is its old name, still taken with a DeprecationWarning);
        box ({coordinate: (low, high)} or "q1=LOW:HIGH, ..."): the numeric
        search there, as --box.  Its other attributes are the keys of `qdot
        equilibria --format json` (qd_equilibria_print): method, exact,
        continuum, equilibria (each with equilibrium, exact, kind,
        hessian_signs, symmetric, residual); .json is that dict."""
        if near is not None:
            import warnings
            warnings.warn("equilibria(near=) is now equilibria(guess=): the starting point of a "
                          "search, as in stability and path", DeprecationWarning, stacklevel=2)
            if guess is not None:
                raise TypeError("equilibria: give guess, not both guess and near")
            guess = near
        core = self._for("equilibria")
        with _progress.watch(core, "equilibria"):  # the multistart's steps, Ctrl-C
            return _linear.equilibria(core, guess, box)

    def modes(self, about=None, at_equilibrium=None, initial=None, symmetry=False,
              independent=None, scan=None, steps=None):
        """Small oscillations about a point at rest (a Modes list of Mode),
        as `qdot modes` takes it: about ({coordinate: value}, the others 0,
        an Equilibrium, or "q1=VALUE, ..." text; --about), at_equilibrium
        (N, 1-based, as equilibria() lists them; --at-equilibrium), or
        neither: the library's choice (qd_modes_at_choose: a minimum of the
        potential nearest the model's `initial` state, or of lowest V), said
        in .choice_note.  A point that is not an equilibrium gives the
        command's note as a UserWarning (qd_modes_rest_note).  initial
        ("q1=VALUE, q1'=VALUE" or a dict; --initial): the motion from there
        in normal coordinates (the JSON's Q0, Q0_dot).  symmetry=True
        (--symmetry): the point's group and the modes labelled by irreps
        (qd_modes_symmetry) in the JSON's "symmetry" and "modes"; a point
        without symmetry gives the library's note as a UserWarning.  The
        other attributes are the keys of `qdot modes --format json`
        (qd_modes_print): equilibrium, residual, choice, mass_matrix,
        stiffness_matrix, frequencies, verdict, ...; .json is that dict.
        A model that keeps constraints with multipliers: the modes on the
        constraint manifold (qd_constrained_at_solve), over the independent
        coordinates independent names ("x" or a list; --independent) or
        the library chooses, the JSON's keys those of
        qd_constrained_modes_print (independent, dependent, multipliers, M,
        K, modes, ...).  A model with `speeds`: the eigenvalues of the
        reduced system about about's coordinates and speeds, or the first
        equilibrium (qd_speeds_modes_print's keys: state, kept, ignorable,
        eigenvalues, verdict).

        scan ("NAME=A:B" or (name, a, b); --scan): the point (about, which
        may be written in the parameters, "x = 1/2 - mu", or the equilibrium
        chosen at A) followed as the parameter goes from A to B in steps
        (--steps; 200 by default), and where its stability changes
        (qd_modes_scan_text): a qdot.Output with parameter, range, steps,
        samples and transitions, not a Modes."""
        core = self._for("modes")
        with _progress.watch(core, "modes"):  # the multistart's steps, Ctrl-C
            return _linear.modes(core, about, at_equilibrium, initial, symmetry, independent,
                                 scan, steps)

    def linearize(self, about=None, independent=None):
        """The state-space form about an operating point (a StateSpace, from
        qd_linearize): A, B, C, D as numpy arrays with the names of the
        states (the coordinates, then their velocities, in model order),
        inputs and outputs, the eigenvalues of A, controllability and
        observability; .lqr(Q, R) gives the LQR gain.

        about: {name: value} over coordinates, velocities "NAME'", inputs
        and "t"; names not given are 0; values are numbers or exact text
        ("pi", "1/2").

        A model whose equations keep constraints (multipliers, `rolls`) is
        linearized on its state manifold as `qdot linearize` does it
        (qd_conlin_about, qdot/conlin.h): the point is the model's initial
        state with about (holonomic constraints alone and no about: the
        equilibrium `qdot modes` takes), the dependent states solved there;
        A, B, C, D are over the independent states (independent:
        "q2, q2'" or a list of names, as --independent; None: chosen), and
        .json is the CLI's JSON with independent, dependent, ignorable,
        point, core_eigenvalues, multipliers, stable, marginal and verdict
        (also readable as attributes: ss.verdict)."""
        return _control.linearize(self._core, about or {}, independent)

    def scene(self, which=0):
        """The points a picture of the motion draws (qd_scene_points,
        qdot/scene.h): a list of dicts {name, kind ("particle", "body" or
        "position"), position: three expression texts}.  which: 0 the
        default (particles and bodies, else the named positions x1,y1 or
        P1), or a sum of 1 particles, 2 bodies, 4 named positions."""
        core = self._core
        pp = new("qd_scene_point *")
        n = new("size_t")
        core.check(lib.qd_scene_points(core.ctx, core.model, which, pp, n))
        pts = pp[0]
        try:
            kinds = {lib.QD_SCENE_PARTICLE: "particle", lib.QD_SCENE_BODY: "body",
                     lib.QD_SCENE_POSITION: "position"}
            return [{"name": cstr(pts[i].name), "kind": kinds[pts[i].kind],
                     "position": [core.text_of(pts[i].pos[k]) for k in range(3)]}
                    for i in range(n[0])]
        finally:
            lib.qd_scene_points_free(pts)

    @staticmethod
    def scene_shape(positions):
        """The plane, bounding box and rods of sampled places
        (qd_scene_analyse): positions[frame][point] = (x, y, z).  Returns
        {plane: (u, v) or None for 3-D, lo, hi, rods: [(a, b, length)]}, a
        rod's end -1 for the origin."""
        arr = np.ascontiguousarray(positions, dtype=float)
        if arr.ndim != 3 or arr.shape[2] != 3:
            raise Error("scene_shape: positions[frame][point] = (x, y, z)")
        sh = new("qd_scene_shape")
        st = lib.qd_scene_analyse(ffi.NULL, ffi.from_buffer("double[]", arr),
                                  arr.shape[0], arr.shape[1], ffi.NULL, 0, sh)
        try:
            if st != 0:
                raise Error("scene_shape: %s" % cstr(lib.qd_status_str(st)))
            end = lambda i: -1 if i == lib.QD_SCENE_ORIGIN else i  # noqa: E731
            return {"plane": None if sh.plane[0] < 0 else (sh.plane[0], sh.plane[1]),
                    "lo": list(sh.lo), "hi": list(sh.hi),
                    "rods": [(end(sh.rods[k].a), end(sh.rods[k].b), sh.rods[k].length)
                             for k in range(sh.nrods)]}
        finally:
            lib.qd_scene_shape_free(sh)

    def simulate(self, t_end, method=None, rtol=None, atol=None, dt=None, initial=None,
                 events=(), stop_at=None, outputs=(), max_steps=0, speeds=True, inputs=None,
                 every=None, step=None, jit=None):
        """Integrate the equations of motion from the initial state to t_end
        (qd_sim_run) and return a qdot.Result.

        method: "dopri5", "dop853", "gl2", "gl4", "gl6", "verlet",
        "yoshida4/6/8" or "bdf"; None chooses as the command line does
        (libqdot's qd_sim_setup_options: gl4 when a step is given for a
        conservative system, else dop853).  rtol, atol: step control.
        dt: the output spacing, for every method (rows at t0 + k dt from
        the dense output, as --dt).  step: the step of a fixed-step method
        (as --step); without it a fixed-step method steps at dt.  every:
        dt's older name (given with dt, dt is then the step).  initial: {name: value} over the
        model's `initial` line (coordinates, velocities "NAME'", "t", the
        momenta of a model given by H).  events: conditions "EXPR = EXPR"
        with optional guards ", EXPR > EXPR" (as --event); their rows are
        in result.events[k].  stop_at: one such condition that ends the run.
        outputs: expressions (or {name: expression}) added as columns.
        A model with `speeds` is integrated in them, y = (q, u), its speeds
        columns by name (their initial values from `initial`, else from the
        initial velocities); speeds=False takes the multiplier form in
        q, q' instead (as --no-speeds; the speeds' initial values unused).
        inputs: {name: source} for the model's `inputs`, each a number
        (constant), text (an expression in t, the state and the
        parameters, as --input "F = EXPR") or a callable f(t, y) -> float,
        y = (q, q') a numpy array in model order (the order of
        linearize().states), called at every evaluation of the right-hand
        side; an exception it raises ends the run and is raised here.  A
        run with inputs takes the form (q, q'), even for a model with
        `speeds`.  jit: True compiles the programs to machine code from the
        start (as --jit), False never (as --no-jit), None once the run is
        long enough to pay for it (qd_sim_opts.jit); the numbers are the
        same bit for bit, result.stats["jit"] says whether it ended so.
        """
        return _sim.simulate(self._core, t_end, method=method, rtol=rtol, atol=atol, dt=dt,
                             initial=initial or {}, events=list(events), stop_at=stop_at,
                             outputs=outputs, max_steps=max_steps, speeds=speeds,
                             inputs=inputs or {}, every=every, step=step, jit=jit)

    def poincare(self, section, crossings, t_end=None, method=None, rtol=None, atol=None,
                 dt=None, step=None, initial=None, max_steps=0, speeds=True):
        """A Poincare surface of section (`qdot poincare FILE --section S
        --crossings N`): a qdot.Result whose rows are the states at the
        first `crossings` crossings of section ("q1 = 0, q1' > 0", an event
        located to round-off), the columns of `qdot poincare`'s CSV.  The
        run ends at the last one, or at t_end (1e6 by default) with a
        warning when fewer were found.  The other arguments as simulate's."""
        return _runs.poincare(self._for("poincare"), section, crossings, t_end, method, rtol,
                              atol, dt, step, initial, max_steps, speeds)

    def lyapunov(self, t_end, exponents=1, renorm=None, transient=None, method=None,
                 rtol=None, atol=None, dt=None, initial=None, max_steps=0, speeds=True):
        """The largest Lyapunov exponents of the motion from the initial
        state (`qdot lyapunov --format json`, qd_lyap_setup_run and
        qd_lyap_json): a qdot.Output with the JSON's keys (exponents,
        errors, sum, ...).  exponents: how many (1 .. 2n); renorm: the time
        between renormalizations (1); transient: the time run first (0);
        method dop853 unless named, dt its fixed step, as --dt."""
        return _runs.lyapunov(self._for("lyapunov"), t_end, exponents, renorm, transient,
                              method, rtol, atol, dt, initial, max_steps, speeds)

    def flow(self, t_end=None, period=None, method=None, rtol=None, atol=None, dt=None,
             initial=None, max_steps=0):
        """The flow Jacobian d(q, q')(t_end)/d(q, q')(t0) from the initial
        state (`qdot simulate --variational --format json`, qd_flow_run and
        qd_flow_json): a qdot.Output with flow_jacobian, flow_det,
        liouville_det, hamiltonian, flow_jacobian_canonical and
        symplectic_error (max |M^T J M - J| in (q, p), for a conservative
        model), multipliers ([re, im]) and closure.  period T (a number or an
        expression in the parameters, "2*pi*sqrt(l/g)") instead of t_end:
        one period, the matrix also as monodromy, its eigenvalues the
        Floquet multipliers.  method dopri5 or dop853 (the default); the
        rest as simulate's.  A model given by H is refused (qdot.Error)."""
        return _runs.flow(self._for("lyapunov"), t_end, period, method, rtol, atol, dt,
                          initial, max_steps)

    def sweep(self, t_end, measures, grid=None, random=None, runs=None, seed=1, section=None,
              events=(), stop_at=None, threads=0, renorm=None, transient=None, method=None,
              rtol=None, atol=None, dt=None, step=None, initial=None, max_steps=0,
              speeds=True):
        """Many runs of the model, a row each (`qdot sweep --format json`,
        qdot/sweep.h): a qdot.Output with columns (the inputs, then the
        measures' columns), rows (a numpy array, a row a run), status and
        stop per run.  measures: "final, energy_error, event, escape:EXPR>V,
        max:EXPR, min:EXPR, poincare-count, lyapunov, lyapunov-spectrum"
        (docs/cli.md); grid "NAME=A:B:N, ..." or random "NAME=A:B, ..." with
        runs and seed (NAME a coordinate, a velocity NAME' or a parameter);
        section the condition poincare-count counts, events/stop_at the
        events (the measure event reads the first); threads (0: one per
        core), renorm and transient for the lyapunov measures; the rest as
        simulate's.  Every run failing raises qdot.NumericalError."""
        return _runs.sweep(self._for("sweep"), t_end, measures, grid, random, runs, seed,
                           section, list(events), stop_at, threads, renorm, transient, method,
                           rtol, atol, dt, step, initial, max_steps, speeds)

    def animate(self, t_end=None, draw=None, trace=None, spring=None, method=None, rtol=None,
                atol=None, dt=None, step=None, initial=None, max_steps=0, speeds=True):
        """The motion as `qdot animate -o FILE.html` plays it (qdot/scene.h):
        a qdot.Animation, an Output of the scene's data (qd_scene_json: t,
        pos, points, links, plane, ...) whose .html is the self-contained
        page (qd_scene_html), shown inline in Jupyter; .save(path) writes
        it.  t_end 10 by default; draw, trace, spring: names (or lists) as
        --draw, --trace and --spring; the rest as simulate's."""
        return _runs.animate(self._for("animate"), t_end, draw, trace, spring, method, rtol,
                             atol, dt, step, initial, max_steps, speeds)

    def action_of(self, path, t):
        """The action of a trial path and the size of its first variation
        (`qdot action-of FILE --path ... --t T0:T1`, qd_path_action_of and
        qd_path_action_of_print; Desloge ch. 83): a qdot.Output with model,
        t0, t1, action (the integral of L along the path) and
        first_variation (the L2 norm over [t0, t1] of Lagrange's residual
        along it: 0 on a true path).  path: every coordinate as an
        expression in t and the parameters, "x = v*t, y = ..." or {name:
        expression}; t: "T0:T1" (expressions in the parameters) or a pair
        (t0, t1)."""
        core = self._for("action_of")
        e = core.eom_ptr()
        if isinstance(path, dict):
            path = ", ".join("%s = %s" % (k, v) for k, v in path.items())
        if isinstance(t, (tuple, list)) and len(t) == 2:
            t = ":".join(x if isinstance(x, str) else repr(float(x)) for x in t)
        for value, what in ((path, "path"), (t, "t")):
            if not isinstance(value, str):
                raise TypeError("action_of: %s is text, not %s" % (what, type(value).__name__))
        ptext, ttext = ffi.new("char[]", path.encode()), ffi.new("char[]", t.encode())
        q = ffi.new("const qd_expr *[]", lib.qd_model_ncoords(core.model) + 1)
        if lib.qd_path_trial_read(core.ctx, core.model, ptext, q) != lib.QD_OK:
            raise _linear.located(core, "path", path.encode())
        t0, t1 = new("double"), new("double")
        if lib.qd_state_range(core.ctx, core.model, ttext, 0, len(t.encode()), t0, t1) != 0:
            raise _linear.located(core, "t", t.encode())
        S, dS = new("double"), new("double")
        st = lib.qd_path_action_of(core.ctx, core.model, e, q, t0[0], t1[0], S, dS)
        if st != lib.QD_OK:
            raise core.error(st, cls=ArgumentError if st == lib.QD_ERR_ARG else NumericalError)
        return _commands.output(core, "action_of", lambda buf: lib.qd_path_action_of_print(
            core.ctx, _commands.source(core), t0[0], t1[0], S[0], dS[0], True, buf))

    def codegen(self, prefix=None, eliminate=False):
        """The self-contained C of `qdot codegen FILE` (qd_codegen_model_c):
        a qdot.Code with .prefix, .c and .h (the texts of PREFIX.c and
        PREFIX.h) and .save(directory).  prefix: the C name of the files and
        functions (a C identifier; default from the model's file name, as
        the command names them); eliminate: substitute the holonomic
        constraints that solve for a coordinate (--eliminate)."""
        from .kernel import Code
        core = self._for("codegen")
        if prefix is None:
            name = ffi.new("char[]", lib.QD_CODEGEN_PREFIX_MAX + 1)
            lib.qd_codegen_prefix_from_path(core.file.encode(), name, len(name))
            prefix = ffi.string(name).decode()
        elif not isinstance(prefix, str) or not lib.qd_codegen_prefix_valid(prefix.encode()):
            raise ValueError("codegen: prefix is a C identifier (up to %d bytes), not %r"
                             % (lib.QD_CODEGEN_PREFIX_MAX, prefix))
        c, h = new("qd_buf"), new("qd_buf")
        st = lib.qd_codegen_model_c(core.ctx, core.model, bool(eliminate), prefix.encode(), c, h)
        if st != lib.QD_OK:
            lib.qd_buf_free(c)
            lib.qd_buf_free(h)
            raise core.error(st)
        return Code(prefix, buf_text(c), buf_text(h))

    def compile(self):
        """The right-hand side of the first-order system y = (q, q') as a
        Python callable rhs(t, y) -> dy/dt (numpy arrays), evaluated by
        libqdot's compiled programs at the current parameter values, for
        one's own integrator (see qdot.Rhs)."""
        return _sim.Rhs(self._core)

    def __repr__(self):
        return "<qdot.Model %s: %s>" % (self._core.file, ", ".join(self.coordinates))
