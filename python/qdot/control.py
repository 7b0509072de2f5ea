# python/qdot/control.py - the state-space form of a model with inputs
# (qd_linearize, qdot/statespace.h) and the LQR gain from it (qd_care_solve,
# qdot/control.h).
#
# The C results are copied into numpy arrays and freed before the call
# returns; a StateSpace keeps only numbers, names and the Core it came from
# (whose context records the errors of a later lqr()).
"""State-space form and linear-quadratic regulation (internal module)."""

import numpy as np

import json as _json

from ._core import Error, NumericalError, name_of
from ._lib import ffi, lib, new, buf_text, cstr, doubles, doubles_of, FLOATS
from . import commands as _commands

# the words of each qd_care_failure (qdot/control.h), by its enum value
CARE_FAILURES = {lib.QD_CARE_OK: "ok", lib.QD_CARE_R_NOT_PD: "R not positive definite",
                 lib.QD_CARE_Q_NOT_PSD: "Q not positive semidefinite",
                 lib.QD_CARE_NOT_STABILIZABLE: "not stabilizable",
                 lib.QD_CARE_NOT_DETECTABLE: "not detectable",
                 lib.QD_CARE_IMAGINARY_AXIS: "imaginary axis",
                 lib.QD_CARE_ILL_CONDITIONED: "ill-conditioned",
                 lib.QD_CARE_NOT_STABILIZING: "not stabilizing"}


def _matrix(ptr, rows, cols):
    """A row-major C array as a rows x cols numpy array (a copy)."""
    return doubles_of(ptr, rows * cols).reshape(rows, cols)


def linearize(core, about):
    """Model.linearize's work (see there): qd_linearize_about on the
    equations `qdot linearize` takes (holonomic constraints eliminated), the
    point read from about's text as --about is."""
    from .linear import located
    if about is not None and not isinstance(about, (dict, str)):
        raise TypeError("linearize: about is a dict {name: value} or text, not %s"
                        % type(about).__name__)
    e = core.eom_eliminated()
    if e.ncon:
        raise Error("linearize: a model that keeps constraints with multipliers is not "
                    "linearized from Python yet (`qdot linearize` reduces it onto the "
                    "constraints)")
    text = _commands.text_arg(about, "about") if about else None
    out = new("qd_statespace")
    try:
        if lib.qd_linearize_about(core.ctx, e, core.model,
                                  text if text is not None else ffi.NULL, out) != lib.QD_OK:
            if text is not None and lib.qd_ctx_diag(core.ctx).located:
                raise located(core, "about", ffi.string(text))
            raise core.error()
        ss = StateSpace(core, out, dict(about) if isinstance(about, dict) else about or {})
        ss.output = _commands.output(core, "linearize", lambda buf: lib.qd_statespace_render(
            core.ctx, out, ffi.NULL, lib.QD_SS_JSON, buf))
        return ss
    finally:
        lib.qd_statespace_free(out)


def _exact(core, syms, rows, cols):
    """The symbolic matrix as lists of text, or None when not kept."""
    if not syms:
        return None
    return [[core.text_of(syms[i * cols + j]) for j in range(cols)] for i in range(rows)]


class StateSpace:
    """x' = xdot0 + A dx + B du, y = y0 + C dx + D du about a point
    (qd_linearize): dx = x - x0, du = u - u0.

    A, B, C, D: numpy arrays (nx x nx, nx x nu, ny x nx, ny x nu); xdot0,
    y0: numpy vectors; states: the names of x, the coordinates then their
    velocities ("NAME'") in model order; inputs, outputs: the model's
    names; A_exact, B_exact, C_exact, D_exact: the same as text in the
    parameters, or None when the exact form grew too large; eigenvalues:
    those of A (numpy complex, Re descending); controllable, observable
    (ranks of the Kalman matrices rank_ctrb, rank_obsv against the
    relative tolerance rank_tolerance); uncontrollable, unobservable: the
    eigenvalues whose modes B does not reach and C does not see; about: the
    point as given.
    """

    rank_tolerance = FLOATS["QD_SS_RANK_TOL"]  # qdot/statespace.h
    output = None  # the qdot.Output of `qdot linearize --format json`

    @property
    def json(self):
        """The dict `qdot linearize FILE --about ... --format json` prints
        (qd_statespace_render): states, inputs, outputs, A, B, C, D, xdot0,
        A_exact, ..., eigenvalues as [re, im] pairs, rank_tolerance,
        controllable, controllability_rank, uncontrollable_modes,
        observable, observability_rank, unobservable_modes."""
        return self.output.json

    def __getattr__(self, name):
        # the JSON keys the StateSpace has no attribute of (controllability_rank, ...)
        out = self.__dict__.get("output")
        if out is not None and name in out:
            return out[name]
        raise AttributeError("StateSpace has no field %r" % name)

    def __init__(self, core, s, about):
        self._core = core
        nx, nu, ny = s.nx, s.nu, s.ny
        self.about = about
        self.states = [name_of(s.states[i]) for i in range(nx)]
        self.inputs = [name_of(s.inputs[i]) for i in range(nu)]
        self.outputs = [cstr(s.outputs[i]) for i in range(ny)]
        self.A, self.B = _matrix(s.A, nx, nx), _matrix(s.B, nx, nu)
        self.C, self.D = _matrix(s.C, ny, nx), _matrix(s.D, ny, nu)
        self.xdot0 = _matrix(s.xdot0, 1, nx)[0]
        self.y0 = _matrix(s.y0, 1, ny)[0] if ny else np.zeros(0)
        self.A_exact, self.B_exact = _exact(core, s.Asym, nx, nx), _exact(core, s.Bsym, nx, nu)
        # the expressions themselves (the context's, alive with core), for the LaTeX display
        self._sym = {"x": [s.states[i] for i in range(nx)],
                     "u": [s.inputs[i] for i in range(nu)],
                     "A": [s.Asym[k] for k in range(nx * nx)] if s.Asym else None,
                     "B": [s.Bsym[k] for k in range(nx * nu)] if s.Bsym else None}
        self.C_exact, self.D_exact = _exact(core, s.Csym, ny, nx), _exact(core, s.Dsym, ny, nu)
        self.eigenvalues = np.array([complex(s.eig_re[k], s.eig_im[k]) for k in range(nx)])
        self.rank_ctrb, self.rank_obsv = s.rank_ctrb, s.rank_obsv
        self.controllable, self.observable = bool(s.controllable), bool(s.observable)
        self.uncontrollable = [self.eigenvalues[s.uncontrollable[k]]
                               for k in range(s.nuncontrollable)]
        self.unobservable = ([self.eigenvalues[s.unobservable[k]]
                              for k in range(s.nunobservable)] if ny else [])

    def lqr(self, Q, R):
        """The LQR gain for J = integral of dx^T Q dx + du^T R du dt
        (qd_care_solve: the stabilizing solution X of the Riccati equation
        by the Schur method).  Q, R: square matrices, or a vector (the
        diagonal) or a number (times the identity).  Returns an Lqr;
        raises qdot.Error when there is no stabilizing solution (its
        .failure says why: "not stabilizable", "R not positive definite",
        ...)."""
        nx, nu = self.A.shape[0], self.B.shape[1]
        Qm, Rm = _square(Q, nx, "Q"), _square(R, nu, "R")
        out = new("qd_care_result")
        core = self._core
        try:
            st = lib.qd_care_solve(core.ctx, nx, nu, _flat(self.A), _flat(self.B), _flat(Qm),
                                   _flat(Rm), out)
            if st != 0:
                err = core.error(st)
                err.failure = CARE_FAILURES.get(out.failure, "failure %d" % out.failure)
                raise err
            return Lqr(_matrix(out.K, nu, nx), _matrix(out.X, nx, nx),
                       np.array([complex(out.eig_re[k], out.eig_im[k]) for k in range(nx)]),
                       out.residual, out.rcond)
        finally:
            lib.qd_care_result_free(out)

    def __repr__(self):
        return "<qdot.StateSpace states %s, inputs %s, outputs %s: eigenvalues %s>" % (
            self.states, self.inputs, self.outputs, np.round(self.eigenvalues, 6).tolist())

    def _repr_latex_(self):
        """d/dt dx = xdot0 + A dx + B du with the exact A and B, every entry and name
        printed by the library's LaTeX printer (None when the exact form
        was not kept: the HTML tables show the numbers)."""
        from ._lib import QD_FMT_LATEX
        from .display import latex_matrix
        sym = self._sym
        if sym["A"] is None or (self.inputs and sym["B"] is None):
            return None
        tex = lambda x: self._core.text_of(x, QD_FMT_LATEX)  # noqa: E731
        nx, nu = len(self.states), len(self.inputs)
        col = lambda xs: latex_matrix([[tex(x)] for x in xs])  # noqa: E731
        A = latex_matrix([[tex(sym["A"][i * nx + j]) for j in range(nx)] for i in range(nx)])
        rhs = A + r"\,\delta" + col(sym["x"])
        if nu:
            B = latex_matrix([[tex(sym["B"][i * nu + j]) for j in range(nu)]
                              for i in range(nx)])
            rhs += " + " + B + r"\,\delta" + col(sym["u"])
        if np.any(self.xdot0 != 0):  # not an equilibrium: the rates there, as numbers
            rhs = latex_matrix([["%.10g" % v] for v in self.xdot0]) + " + " + rhs
        # delta: the deviation from the point linearized about
        return r"$$\frac{d}{dt}\,\delta%s = %s$$" % (col(sym["x"]), rhs)

    def _repr_html_(self):
        """The numbers: A, B, C, D headed by the names, the eigenvalues of A,
        controllability and observability (shown when there is no LaTeX)."""
        if self._repr_latex_() is not None:
            return None
        return self.html()

    def html(self):
        """The numbers of the state-space form as HTML tables."""
        from . import display
        t = display.table
        parts = [t(self.states, self.A.tolist(), self.states, "A"),
                 t(self.inputs, self.B.tolist(), self.states, "B")]
        if self.outputs:
            parts += [t(self.states, self.C.tolist(), self.outputs, "C"),
                      t(self.inputs, self.D.tolist(), self.outputs, "D")]
        parts.append(t(["Re", "Im"], [[z.real, z.imag] for z in self.eigenvalues],
                       caption="eigenvalues of A"))
        parts.append(display.fields({"controllable": self.controllable,
                                     "controllability_rank": self.rank_ctrb,
                                     "observable": self.observable,
                                     "observability_rank": self.rank_obsv}))
        return display.block("qdot linearize about %s" % (self.about,), *parts)


def _square(x, n, what):
    """x as an n x n matrix: a number times I, a diagonal or the matrix."""
    a = np.asarray(x, dtype=float)
    if a.ndim == 0:
        return a * np.eye(n)
    if a.ndim == 1 and a.shape == (n,):
        return np.diag(a)
    if a.shape != (n, n):
        raise Error("lqr: %s must be a number, %d diagonal entries or %d x %d, not shape %s"
                    % (what, n, n, n, a.shape))
    return a


def _flat(a):
    """A row-major C array of a's entries."""
    return doubles(np.ascontiguousarray(a, dtype=float).reshape(-1))


class Lqr:
    """The regulator du = -K dx (qd_care_result): K (nu x nx), X the
    stabilizing solution of A^T X + X A - X B R^-1 B^T X + Q = 0,
    eigenvalues those of A - B K (Re descending), residual the Riccati
    residual relative to its terms, rcond the reciprocal condition number
    of the Schur basis block U11."""

    def __init__(self, K, X, eigenvalues, residual, rcond):
        self.K, self.X, self.eigenvalues = K, X, eigenvalues
        self.residual, self.rcond = residual, rcond

    def __repr__(self):
        return "Lqr(K=%s, residual=%.3g)" % (np.array2string(self.K, precision=6),
                                             self.residual)

    def _repr_html_(self):
        from . import display
        return display.block("qdot lqr", display.table(None, self.K.tolist(), caption="K"),
                             display.table(None, self.X.tolist(), caption="X"),
                             display.table(["Re", "Im"], [[z.real, z.imag]
                                                          for z in self.eigenvalues],
                                           caption="eigenvalues of A - B K"),
                             display.fields({"residual": self.residual, "rcond": self.rcond}))


def lqr(A, B, weights):
    """The linear-quadratic regulator of x' = A x + B u (`qdot lqr --A --B
    --weights`, qd_care_solve and qd_lqr_print): a qdot.Output with states
    (x1, ...), inputs (u1, ...), K, X, closed_loop_eigenvalues ([re, im]
    pairs), residual and rcond.  A: n x n, B: n x m (array-likes);
    weights: "Q = W, R = W" as --weights takes it (W a number, diag(...) or
    [[...], ...]), or a pair (Q, R) of numbers, diagonals or matrices.
    qdot.Error with the library's reason when there is no stabilizing
    solution (its .failure: "not stabilizable", ...)."""
    from ._core import take_error
    Am, Bm = np.asarray(A, dtype=float), np.asarray(B, dtype=float)
    if Am.ndim != 2 or Am.shape[0] != Am.shape[1]:
        raise ValueError("lqr: A must be square, not shape %s" % (Am.shape,))
    if Bm.ndim != 2 or Bm.shape[0] != Am.shape[0]:
        raise ValueError("lqr: B needs one row per state (%d), not shape %s"
                         % (Am.shape[0], Bm.shape))
    n, m = Bm.shape
    ctx = ffi.gc(lib.qd_ctx_new(), lib.qd_ctx_free)

    def fail(cls=Error):
        d = take_error(ctx)
        msg = ffi.string(d.message).decode() or cstr(lib.qd_status_str(d.status))
        return cls(msg, d.status) if cls is Error else cls("lqr: weights: " + msg)
    if isinstance(weights, str):
        Q, R = ffi.new("double[]", n * n), ffi.new("double[]", m * m)
        if lib.qd_lqr_weights_read(ctx, weights.encode(), n, m, Q, R) != 0:
            raise fail(ValueError)
    else:
        try:
            Qw, Rw = weights
        except (TypeError, ValueError):
            raise TypeError("lqr: weights is \"Q = W, R = W\" or a pair (Q, R)") from None
        Q, R = _flat(_square(Qw, n, "Q")), _flat(_square(Rw, m, "R"))
    out = new("qd_care_result")
    try:
        if lib.qd_care_solve(ctx, n, m, _flat(Am), _flat(Bm), Q, R, out) != 0:
            err = fail()
            err.failure = CARE_FAILURES.get(out.failure, "failure %d" % out.failure)
            raise err
        buf = new("qd_buf")
        st = lib.qd_lqr_print(ffi.NULL, out, lib.QD_LQR_JSON, buf)
        text = buf_text(buf)
        if st != 0:
            raise NumericalError("lqr: %s" % cstr(lib.qd_status_str(st)), st)
        return _commands.Output("lqr", _json.loads(text))
    finally:
        lib.qd_care_result_free(out)
