# python/qdot/sim.py - simulation through qd_sim_run (qdot/sim.h) and the
# compiled right-hand side through qd_eom_prog_eval (qdot/mech.h).
#
# The rows the library hands to the sink are copied into numpy arrays; the
# qd_sim is made and freed inside one call, so nothing of it outlives the
# run.  Event text is read as `qdot simulate --event` reads it.
"""Simulation results and the compiled right-hand side (internal module)."""

import ctypes
import numbers
from ctypes import byref

import numpy as np

from ._core import Error, ModelError, name_of, number_expr, take_error
from ._lib import (lib, SimOpts, SimStats, SimSink, SimInputFn, exprs, doubles, DBL, QD_OK)


class Table:
    """Rows of a run, by column: t is the time (numpy array); table[NAME]
    is a column by coordinate, velocity ("NAME'"), momentum ("p_NAME"),
    speed, "energy", constraint residual ("res_NAME") or output name."""

    def __init__(self, columns, data):
        self.columns = list(columns)
        self.data = data  # rows x columns

    @property
    def t(self):
        """The times of the rows."""
        return self.data[:, 0]

    def __getitem__(self, name):
        """The column named name (a numpy array)."""
        try:
            return self.data[:, self.columns.index(name)]
        except ValueError:
            raise KeyError("no column '%s' (columns: %s)" % (name, ", ".join(self.columns)))

    def __contains__(self, name):
        return name in self.columns

    def __len__(self):
        return self.data.shape[0]

    def keys(self):
        """The column names."""
        return list(self.columns)


class Result(Table):
    """What Model.simulate returns: the sampled rows (a Table), plus

    events: one Table per event given (events in order, then stop_at),
        the rows where it fired;
    impacts: the rows before and after each impact of the model's
        unilateral contacts (a Table, empty without them);
    stats: the run's qd_sim_stats as a dict (steps, evals, rejected,
        energy_error_max, constraint_error_max, E0, events, t, impacts, ...);
    energy_error_max: max |E(t) - E(0)| / max(|E(0)|, max T) over the rows
        returned (dense output between steps included);
    energy_error_steps: the same at the integrator's accepted steps;
    method: the method's name.
    """

    def __init__(self, columns, rows, nev, stats, method):
        data = np.array([r[1] for r in rows], dtype=float).reshape(len(rows), len(columns))
        ev = np.array([r[0] for r in rows], dtype=int)
        super().__init__(columns, data[ev == -1])
        self.events = [Table(columns, data[ev == k]) for k in range(nev)]
        self.impacts = Table(columns, data[ev >= nev])
        self.stats = {name: getattr(stats, name) for name, _ in stats._fields_
                      if not name.startswith("_")}
        self.energy_error_max = stats.energy_error_max
        self.energy_error_steps = stats.energy_error_steps
        self.method = method

    def __repr__(self):
        return "<qdot.Result %d rows, t = %g..%g, %s>" % (
            len(self), self.t[0] if len(self) else 0, self.t[-1] if len(self) else 0,
            self.method)


def _items(text):
    """text split at its top-level commas."""
    out, depth, start = [], 0, 0
    for i, ch in enumerate(text):
        depth += ch in "([" and 1 or (ch in ")]" and depth > 0 and -1 or 0)
        if ch == "," and depth == 0:
            out.append(text[start:i])
            start = i + 1
    out.append(text[start:])
    return [s for s in out if s.strip()]


def _add_event(core, s, text, stop):
    """'g1 = g2, a > b, ...': the crossing g1 - g2 and guards a - b > 0."""
    what = "stop_at" if stop else "events"
    g, guards = None, []
    for item in _items(text):
        ops = [i for i, ch in enumerate(item) if ch in "=<>"]
        if not ops or (g is None) != (item[ops[0]] == "="):
            raise Error("%s takes \"EXPR = EXPR[, EXPR > EXPR]...\" (the crossing first, "
                        "then conditions with > or <), not '%s'" % (what, text))
        k = ops[0]
        lhs, rhs = core.read(item[:k], what), core.read(item[k + 1:], what)
        if item[k] == "=":
            g = lib.qd_sub(core.ctx, lhs, rhs)
        else:
            guards.append(lib.qd_sub(core.ctx, lhs, rhs) if item[k] == ">"
                          else lib.qd_sub(core.ctx, rhs, lhs))
    core.check(lib.qd_sim_add_event(s, g, len(guards), exprs(guards), stop))


def _add_outputs(core, s, outputs):
    """Columns: the model's `outputs`, then those of outputs (a list of
    expressions or {name: expression}), as `qdot simulate` orders them."""
    m = core.model
    for i in range(lib.qd_model_noutputs(m)):
        core.check(lib.qd_sim_add_output(s, lib.qd_model_output_name(m, i),
                                         lib.qd_model_output(m, i)))
    items = outputs.items() if isinstance(outputs, dict) else [(o, o) for o in outputs]
    for name, text in items:
        core.check(lib.qd_sim_add_output(s, name.encode(), core.read(text, "outputs")))


def _initial(core, initial, kind):
    """q0, qd0, t0 (model order) and the extra initial values (momenta of a
    model given by H, speeds of a model simulated in them) or None, from the
    model's `initial` line overridden by the dict initial; a value may be
    text ("pi/2") in the parameters."""
    syms, vals = core.state()
    n = len(core.coords())
    names = [name_of(x) for x in syms[:2 * n + 1]]
    extra = _extra(core, kind, syms, vals)
    names += [name for name, _ in extra]
    given = [value for _, value in extra]
    if kind == "speeds" and any(name in initial for name in names[n:2 * n]):
        given = [None] * len(given)  # velocities named: the speeds follow them
    for name, value in initial.items():
        if name not in names:
            raise Error("initial: '%s' is not among %s" % (name, ", ".join(names)))
        if isinstance(value, str):
            value = core.eval(core.read(value, "initial " + name), syms, vals)
        i = names.index(name)
        if i > 2 * n:
            given[i - 2 * n - 1] = float(value)
        else:
            vals[i] = float(value)
    more = None
    if any(v is not None for v in given):
        more = doubles([_missing(core, kind, r, syms, vals) if v is None else v
                        for r, v in enumerate(given)])
    return vals[:n], vals[n:2 * n], vals[2 * n], more


def _extra(core, kind, syms, vals):
    """[(name, initial value or None)] of the momenta or the speeds."""
    m = core.model
    if kind == "hamilton":
        return [(name_of(lib.qd_model_momentum(m, j)), None)
                for j in range(lib.qd_model_ncoords(m))]
    if kind != "speeds":
        return []
    out = []
    for r in range(lib.qd_model_nspeeds(m)):
        x = lib.qd_model_speed_initial(m, r)
        out.append((name_of(lib.qd_model_speed(m, r)),
                    core.eval(x, syms, vals) if x else None))
    return out


def _missing(core, kind, r, syms, vals):
    """A momentum not given is 0; a speed not given is its definition at
    the initial velocities (as `qdot simulate` takes it)."""
    if kind != "speeds":
        return 0.0
    return core.eval(lib.qd_model_speed_definition(core.model, r), syms, vals)


def _method(core, s, method, dt, rtol):
    """The qd_sim_method by name, or the default the command line uses."""
    if method is None:  # dt with rtol: the output grid of an adaptive run
        return lib.qd_sim_default_method(s, dt is not None and rtol is None)
    m = ctypes.c_int()
    if not lib.qd_sim_method_from_name(method.encode(), byref(m)):
        raise Error("method takes dopri5, dop853, gl2, gl4, gl6, verlet, yoshida4, yoshida6, "
                    "yoshida8, bdf or taylor, not '%s'" % method)
    return m.value


def _new_sim(core, kind):
    """The qd_sim (and the speeds equations it reads, or None): Hamilton's
    equations for a model given by H, the equations in speeds for a model
    with `speeds`, else Lagrange's."""
    se = None
    if kind == "hamilton":
        s = lib.qd_sim_new_hamilton(core.ctx, core.model)
    elif kind == "speeds":
        se = lib.qd_speeds_derive(core.ctx, core.model, None)
        if not se:
            raise core.error(cls=ModelError)
        s = lib.qd_sim_new_speeds(core.ctx, core.model, se)
    else:
        s = lib.qd_sim_new(core.ctx, core.model, core.eom_ptr())
    if not s:
        err = core.error(cls=ModelError)
        if se:
            lib.qd_speeds_eom_free(se)
        raise err
    return s, se


def _order(core, kind, q, qd):
    """The initial values in the order of the equations' coordinates."""
    if kind != "lagrange":
        return q, qd
    coords = core.coords()
    e = core.eom()
    pos = [coords.index(e.q[j]) for j in range(e.n)]
    return [q[i] for i in pos], [qd[i] for i in pos]


def _kind(core, speeds):
    """Which equations simulate integrates."""
    if lib.qd_model_hamiltonian_given(core.model):
        return "hamilton"
    return "speeds" if speeds and lib.qd_model_nspeeds(core.model) else "lagrange"


class _InputFn:
    """A Python callable f(t, y) -> float as a qd_sim_input_fn.  y is the
    state (q, q') in model order, a fresh numpy array per call.  The C side
    cannot be unwound through, so an exception is kept (the first one) and
    NaN returned, which ends the run (a failed input callback, qdot/sim.h);
    simulate raises the exception after qd_sim_run returns."""

    def __init__(self, name, fn, pos):
        self.name, self.fn = name, fn
        n = len(pos)
        # x from C is in the equations' order: model coordinate i is x[pos[i]]
        self.take = np.array(pos + [n + j for j in pos], dtype=int)
        self.error = None
        self.c = SimInputFn(self._call)  # kept alive with self for the whole run

    def _call(self, _data, t, x):
        if self.error is not None:
            return float("nan")
        try:
            y = np.ctypeslib.as_array(x, shape=(len(self.take),))[self.take]
            v = np.asarray(self.fn(t, y), dtype=float).reshape(-1)
            if v.size != 1:
                raise ValueError("inputs: %s(t, y) returned %d values, not one number"
                                 % (self.name, v.size))
            return float(v[0])
        except BaseException as err:  # noqa: B036 (re-raised by simulate)
            self.error = err
            return float("nan")


def _input_names(core):
    """The names of the model's inputs, in declaration order."""
    m = core.model
    return [name_of(lib.qd_model_input(m, k)) for k in range(lib.qd_model_ninputs(m))]


def _add_inputs(core, s, inputs):
    """Each input's source: a number (constant), text (an expression in t,
    the state and the parameters, read as --input reads it) or a callable
    f(t, y); the list of _InputFn, which must outlive the run."""
    names, fns = _input_names(core), []
    for name, value in inputs.items():
        if name not in names:
            raise Error("inputs: '%s' is not an input of the model (inputs: %s)"
                        % (name, ", ".join(names) or "none"))
        if callable(value):
            coords = core.coords()
            e = core.eom()
            pos = [[e.q[j] for j in range(e.n)].index(c) for c in coords]
            fn = _InputFn(name, value, pos)
            core.check(lib.qd_sim_input_callback(s, name.encode(), fn.c, None))
            fns.append(fn)
            continue
        if isinstance(value, str):
            x = core.read(value, "inputs " + name)
        elif isinstance(value, numbers.Real) and not isinstance(value, bool):
            x = number_expr(core.ctx, "inputs " + name, value)
        else:
            raise Error("inputs: %s takes a number, an expression (text) or a callable "
                        "f(t, y), not %r" % (name, value))
        core.check(lib.qd_sim_input_expr(s, name.encode(), x))
    return fns


def simulate(core, t_end, method, rtol, atol, dt, initial, events, stop_at, outputs,
             max_steps, speeds, inputs, every=None):
    """Model.simulate's work (see there)."""
    kind = _kind(core, speeds and not inputs)
    s, se = _new_sim(core, kind)
    try:
        q, qd, t0, more = _initial(core, initial, kind)
        q, qd = _order(core, kind, q, qd)
        _add_outputs(core, s, outputs)
        fns = _add_inputs(core, s, inputs)
        for text in events:
            _add_event(core, s, text, False)
        if stop_at:
            _add_event(core, s, stop_at, True)
        m = _method(core, s, method, dt, rtol)
        if not lib.qd_sim_method_adaptive(m) and dt is None:
            raise Error("method %s takes fixed steps: give dt" % lib.qd_sim_method_name(m)
                        .decode())
        q0, qd0 = doubles(q), doubles(qd)
        opts = SimOpts(method=m, t0=t0, t_end=float(t_end), dt=float(dt or 0),
                       rtol=float(rtol or 0), atol=float(atol or 0), max_steps=max_steps,
                       q0=q0, qd0=qd0, every=float(every or 0))
        if kind == "hamilton":
            opts.p0 = more
        elif kind == "speeds":
            opts.u0 = more
        core.check(lib.qd_sim_check_opts(core.ctx, byref(opts)))
        return _run(core, s, opts, len(events) + bool(stop_at), fns)
    finally:
        lib.qd_sim_free(s)
        if se:
            lib.qd_speeds_eom_free(se)


def _run(core, s, opts, nev, fns=()):
    """qd_sim_run with a sink that copies every row; the Result.  An
    exception raised in an input callable (the callback then returns NaN,
    which ends the run) or in the sink itself (it then returns -1, a
    failure: qdot/sim.h) is raised here, in place of what the run
    reported; ctypes cannot unwind through C, and an exception left in a
    callback would only print "Exception ignored"."""
    ncol = lib.qd_sim_columns(s, opts.method, None, 0)
    names = (ctypes.c_char_p * ncol)()
    lib.qd_sim_columns(s, opts.method, names, ncol)
    columns = [x.decode() for x in names]
    rows = []
    failed = []

    def sink(_data, event, row):
        try:
            if any(fn.error is not None for fn in fns):
                return -1
            rows.append((event, row[:ncol]))
            return 0
        except BaseException as err:  # noqa: B036 (re-raised below)
            failed.append(err)
            return -1

    stats = SimStats()
    callback = SimSink(sink)  # kept alive until qd_sim_run returns
    st = lib.qd_sim_run(s, byref(opts), callback, None, byref(stats), None)
    for err in [fn.error for fn in fns if fn.error is not None] + failed:
        take_error(core.ctx)  # the failure's consequence: not the cause
        raise err
    if st != QD_OK:
        raise core.error(st)
    return Result(columns, rows, nev, stats, lib.qd_sim_method_name(opts.method).decode())


class Rhs:
    """The right-hand side of y' = F(t, y), y = (q, q') in the order of
    .coordinates, for one's own integrator: rhs(t, y) returns the numpy
    array (q', q''), q'' solving M q'' = f (with constraints, the
    saddle-point system of qdot/mech.h).  Parameters are the model's values
    when compile() was called (.params).  Evaluated by libqdot's compiled
    program (qd_eom_prog_eval); one Rhs must not be called from two threads
    at once."""

    def __init__(self, core):
        self._core = core  # keeps the context and the equations alive
        self._prog = self._work = None
        e = core.eom()
        self.n = n = e.n
        self.coordinates = [name_of(e.q[j]) for j in range(n)]
        params = core.params()
        self.params = {name: value for name, _, value in params}
        syms = ([e.q[j] for j in range(n)] + [e.qd[j] for j in range(n)] +
                [lib.qd_time(core.ctx)] + [p[1] for p in params])
        self._nsyms = len(syms)
        self._syms = exprs(syms)
        self._vals = doubles([0.0] * (2 * n + 1) + [p[2] for p in params])
        self._vals_np = np.ctypeslib.as_array(self._vals)
        self._qdd = doubles([0.0] * n)
        self._qdd_np = np.ctypeslib.as_array(self._qdd)
        self._prog = lib.qd_eom_compile(core.ctx, core.eom_ptr())
        if not self._prog:
            raise core.error()
        self._work = lib.qd_eom_work_new(core.ctx, self._prog)
        if not self._work:
            raise core.error()

    def __call__(self, t, y):
        """(q', q'') at time t and state y = (q, q')."""
        n = self.n
        y = np.asarray(y, dtype=float)
        if y.shape != (2 * n,):
            raise ValueError("rhs: y must have %d entries (q, q'), not shape %s"
                             % (2 * n, y.shape))
        self._vals_np[:2 * n] = y
        self._vals_np[2 * n] = t
        st = lib.qd_eom_prog_eval(self._core.ctx, self._prog, self._work, self._nsyms,
                                  self._syms, self._vals, None, None,
                                  ctypes.cast(self._qdd, DBL), None, None)
        if st != QD_OK:
            raise self._core.error(st)
        return np.concatenate([y[n:], self._qdd_np])

    def __del__(self):
        """Free the workspace, then the program."""
        if self._work:
            lib.qd_eom_work_free(self._work)
        if self._prog:
            lib.qd_eom_prog_free(self._prog)
