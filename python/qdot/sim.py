# python/qdot/sim.py - simulation through qd_sim_run (qdot/sim.h) and the
# compiled right-hand side through qd_eom_prog_eval (qdot/mech.h).
#
# The rows the library hands to the sink are copied into numpy arrays; the
# qd_sim is made and freed inside one call, so nothing of it outlives the
# run.  Event text is read by the library's set-up, as `qdot simulate` reads
# it; the summary and the CSV are the library's (qd_sim_summary_print,
# qd_sim_csv_header, qd_sim_csv_row), the bytes `qdot simulate` writes.
"""Simulation results and the compiled right-hand side (internal module)."""

import json
import numbers
import time

import numpy as np

from ._core import (QD_ERR_NOMEM, Error, ModelError, format_diag, name_of, number_expr,
                    take_error)
from ._lib import ffi, lib, new, cstr, exprs, doubles, buf_text, QD_OK
from ._progress import Run


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

    def __repr__(self):
        return "<qdot.Table %d rows: %s>" % (len(self), ", ".join(self.columns))

    def _repr_html_(self):
        """The rows under their column names (the first ones of a long run)."""
        from . import display
        return display.table(self.columns, self.data.tolist(), caption="%d rows" % len(self))


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
    stop: why the run ended (qd_sim_stats.stop), the keys of the CLI's
        JSON "stop": {"code": "end", "event", ... (qd_stop_name), "reason":
        "reached the end time", "a terminal event" ..., "ok": it ended as
        asked, "t": when, "value": the quantity that decided it (the
        event's index, ...), nan where none};
    method: the method's name;
    summary: the lines `qdot simulate` prints on stderr after the run
        (without its "qdot: simulate: " prefix): method, steps, energy and
        constraint errors, events, impacts, friction.
    record: the same as the members of `qdot simulate --format json`
        (method, steps, ..., "stop" unless the run reached t_end, "final":
        column name to the last row's value), a dict;
    csv(): every row in the order of the run, as the CSV `qdot simulate`
        writes.
    """

    def __init__(self, columns, rows, nev, stats, method, summary="", header="",
                 event_column=False, record=None, ndof=0):
        data = np.array([r[1] for r in rows], dtype=float).reshape(len(rows), len(columns))
        ev = np.array([r[0] for r in rows], dtype=int)
        self._all, self._ev = data, ev
        self._header, self._event_column = header, event_column
        self.summary, self.record = summary, record
        super().__init__(columns, data[ev == -1])
        self.events = [Table(columns, data[ev == k]) for k in range(nev)]
        self.impacts = Table(columns, data[ev >= nev])
        code = stats.stop.code
        self.stop = {"code": cstr(lib.qd_stop_name(code)),
                     "reason": cstr(lib.qd_stop_str(code)), "ok": bool(lib.qd_stop_ok(code)),
                     "t": stats.stop.t, "value": stats.stop.value}
        # every field of qd_sim_stats (qdot/sim.h), by the header's names
        self.stats = {name: getattr(stats, name) for name, _ in ffi.typeof(stats[0]).fields
                      if name != "stop"}
        self.stats["stop"] = self.stop
        self.energy_error_max = stats.energy_error_max
        self.energy_error_steps = stats.energy_error_steps
        self.method = method
        self._ndof = ndof  # the coordinates' columns follow t (for plots)

    def csv(self):
        """The rows as the CSV text `qdot simulate` writes (qd_sim_csv_row:
        shortest round-trip numbers, the event column when the run had
        events, impacts or friction)."""
        buf = new("qd_buf")
        ncol = len(self.columns)
        try:
            for event, row in zip(self._ev, self._all):
                lib.qd_sim_csv_row(ncol, doubles(row), self._event_column, int(event), buf)
            if buf.failed:
                raise MemoryError("qdot: out of memory")
        except BaseException:
            lib.qd_buf_free(buf)
            raise
        return self._header + buf_text(buf)

    def _pick(self, y, phase):
        """qd_plot_pick_columns on these columns: which the plot draws."""
        ctx = lib.qd_ctx_new()
        if ctx == ffi.NULL:
            raise MemoryError("qdot: out of memory")
        try:
            names = [ffi.new("char[]", c.encode()) for c in self.columns]
            arr = ffi.new("const char *[]", names)
            pk = new("qd_plot_pick")
            keep = [ffi.new("char[]", v.encode()) if v is not None else ffi.NULL
                    for v in (y, phase)]
            if lib.qd_plot_pick_columns(ctx, keep[0], keep[1], arr, len(self.columns),
                                        self._ndof, pk) != QD_OK:
                raise _text_error_ctx(ctx, "plot")
            return pk
        finally:
            lib.qd_ctx_free(ctx)

    def png(self, y=None, phase=None, title=None, xlabel=None, ylabel=None, size=None,
            point_size=None, orbits=()):
        """The rows drawn as `qdot simulate --plot FILE.png` draws them (the
        library's qd_plot_run), as PNG bytes.  y: the columns, as --plot-y
        ("x, x'; energy_error": a semicolon starts a panel); phase: a
        coordinate Q for Q' against Q (as --phase); neither: every
        coordinate against t.  title, xlabel, ylabel ("A; B" per panel) and
        size ("WxH" pixels) as the CLI's options.  A section's (Model.poincare)
        crossings are dots, point_size their radius in pixels (as --point-size);
        orbits: more sections' Results of the same model, each drawn in its own
        colour, the legend naming each by its initial state (as `qdot poincare`
        with --initial given again)."""
        import os
        import tempfile
        mine = [self, *orbits]
        if any(list(o.columns) != list(self.columns) for o in mine):
            raise ValueError("png: the orbits' columns differ from this Result's")
        pk = self._pick(y, phase)
        ctx = lib.qd_ctx_new()
        if ctx == ffi.NULL:
            raise MemoryError("qdot: out of memory")
        fd, path = tempfile.mkstemp(suffix=".png")
        os.close(fd)
        try:
            width, height = ffi.new("int *"), ffi.new("int *")
            if size is not None and lib.qd_plot_size_of(ctx, size.encode(), width,
                                                         height) != QD_OK:
                raise _text_error_ctx(ctx, "size")
            texts = {k: ffi.new("char[]", v.encode()) for k, v in
                     (("title", title), ("xlabel", xlabel), ("ylabel", ylabel)) if v is not None}
            labels = [ffi.new("char[]", o.label.encode()) if getattr(o, "label", None)
                      else ffi.NULL for o in mine]
            counts = ffi.new("size_t[]", [o.data.shape[0] for o in mine])
            label_arr = ffi.new("const char *[]", labels)
            opts = new("qd_plot_run_opts", dict(texts, width=width[0], height=height[0],
                                                points=bool(getattr(self, "_section", False)),
                                                point_size=float(point_size or 0),
                                                norbits=len(mine), orbit_rows=counts,
                                                orbit_labels=label_arr))
            names = [ffi.new("char[]", c.encode()) for c in self.columns]
            arr = ffi.new("const char *[]", names)
            data = np.ascontiguousarray(np.vstack([r.data for r in mine]), dtype=float)
            plot = lib.qd_plot_run(ctx, pk, arr, ffi.cast("const double *", data.ctypes.data),
                                   data.shape[0], len(self.columns), opts)
            if plot == ffi.NULL:
                raise _text_error_ctx(ctx, "plot")
            try:
                if lib.qd_plot_write(plot, path.encode()) != QD_OK:
                    raise _text_error_ctx(ctx, "plot")
            finally:
                lib.qd_plot_free(plot)
            with open(path, "rb") as f:
                return f.read()
        finally:
            os.unlink(path)
            lib.qd_ctx_free(ctx)

    def _repr_png_(self):
        """Jupyter shows a run as its plot (every coordinate against t)."""
        return self.png() if len(self) else None

    def _repr_html_(self):
        """Jupyter shows a run as its plot (the PNG above, inline as a data
        URI: no file, no network) over its summary and its first rows."""
        import base64
        from . import display
        parts = []
        if len(self):
            try:
                parts.append('<img alt="the run\'s plot" src="data:image/png;base64,%s"/>'
                             % base64.b64encode(self.png()).decode())
            except Error:  # a plot the library refuses (no column to draw): the table only
                pass
        info = {"method": self.method, "rows": len(self), "stop": self.stop["reason"],
                "energy_error_max": self.energy_error_max}
        if self.events:
            info["events"] = [len(e) for e in self.events]
        parts += [display.fields(info), Table._repr_html_(self)]
        return display.block("qdot " + getattr(self, "_command", "simulate"), *parts)

    def plot(self, y=None, phase=None, ax=None):
        """A matplotlib figure of the same columns as png() (for users who
        style it themselves); ax: draw into these axes (one panel).  Needs
        matplotlib (Debian's python3-matplotlib)."""
        import matplotlib.pyplot as plt
        pk = self._pick(y, phase)
        if ax is not None:
            fig, axes = ax.figure, [ax] * pk.npanels
        else:
            fig, axes = plt.subplots(pk.npanels, 1, sharex=not pk.phase, squeeze=False)
            axes = [a[0] for a in axes]
        energy = self.data[:, pk.energy] if pk.energy_error else None
        for k in range(pk.ny):
            col = pk.y[k]
            if col == len(self.columns):  # E(t) - E(t0)
                yv, label = energy - energy[0], "energy error"
            else:
                yv, label = self.data[:, col], self.columns[col]
            axes[pk.panel[k]].plot(self.data[:, pk.x], yv, label=label)
        for a in set(axes):
            a.legend()
        axes[-1].set_xlabel(self.columns[pk.x] if pk.phase else "t")
        return fig

    def __repr__(self):
        return "<qdot.Result %d rows, t = %g..%g, %s>" % (
            len(self), self.t[0] if len(self) else 0, self.t[-1] if len(self) else 0,
            self.method)


def _text_error_ctx(ctx, what):
    """The context's error, unlocated, as an Error (ArgumentError for bad
    input)."""
    from ._core import ArgumentError
    diag = take_error(ctx)
    if diag.status == QD_ERR_NOMEM:
        return MemoryError("qdot: out of memory")
    return ArgumentError("%s: %s" % (what, ffi.string(diag.message).decode()), diag.status)


def _text_error(core, what, text):
    """The context's error about text (the user's): shown in it with a caret
    when located there, as the command line shows its options."""
    diag = take_error(core.ctx)
    if diag.status == QD_ERR_NOMEM:
        return MemoryError("qdot: out of memory")
    if diag.located:
        return ModelError(format_diag(diag, what, text.encode()), diag, what)
    return Error("%s: %s" % (what, ffi.string(diag.message).decode()), diag.status)


def _initial_text(initial):
    """{name: value} as the text qd_sim_setup_initial reads."""
    items = []
    for name, value in initial.items():
        if not isinstance(value, str):
            value = repr(float(value))
        items.append("%s=%s" % (name, value))
    return ", ".join(items)


def _number(x):
    """A number argument as the text the set-up reads (None stays None)."""
    return None if x is None else repr(float(x)).encode()
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
        # kept alive with self for the whole run; NaN (ends the run) if _call fails
        self.c = ffi.callback("qd_sim_input_fn", self._call, error=float("nan"))

    def _call(self, _data, t, x):
        if self.error is not None:
            return float("nan")
        try:
            y = np.frombuffer(ffi.buffer(x, len(self.take) * 8), dtype=float)[self.take]
            v = np.asarray(self.fn(t, y), dtype=float).reshape(-1)
            if v.size != 1:
                raise ValueError("inputs: %s(t, y) returned %d values, not one number"
                                 % (self.name, v.size))
            return float(v[0])
        except BaseException as err:  # noqa: B036 (re-raised by simulate)
            self.error = err
            return float("nan")


def _add_inputs(core, setup, s, inputs):
    """Each input's source: a number (constant), text (an expression in t,
    the state and the parameters, read as --input reads it) or a callable
    f(t, y); the list of _InputFn, which must outlive the run.  A name that
    is not an input is the library's refusal, as --input's."""
    fns = []
    for name, value in inputs.items():
        if callable(value):
            coords = core.coords()
            e = lib.qd_sim_setup_eom(setup)
            pos = [[e.q[j] for j in range(e.n)].index(c) for c in coords]
            fn = _InputFn(name, value, pos)
            core.check(lib.qd_sim_input_callback(s, name.encode(), fn.c, ffi.NULL))
            fns.append(fn)
            continue
        what = "inputs " + name
        if isinstance(value, str):
            if lib.qd_sim_setup_input(setup, name.encode(), value.encode(), 0,
                                      len(value.encode())) != QD_OK:
                raise _text_error(core, what, value)
            continue
        if isinstance(value, numbers.Real) and not isinstance(value, bool):
            x = number_expr(core.ctx, what, value)
        else:
            raise Error("inputs: %s takes a number, an expression (text) or a callable "
                        "f(t, y), not %r" % (name, value))
        core.check(lib.qd_sim_input_expr(s, name.encode(), x))
    return fns


def simulate(core, t_end, method, rtol, atol, dt, initial, events, stop_at, outputs,
             max_steps, speeds, inputs, every=None, step=None, jit=None):
    """Model.simulate's work (see there), by the set-up `qdot simulate`
    makes (qdot/simsetup.h): the same equations, initial state, names and
    checks, and the same messages."""
    setup = lib.qd_sim_setup_new(core.ctx, core.model, not (speeds and not inputs))
    if not setup:
        raise core.error(cls=ModelError)
    try:
        s = lib.qd_sim_setup_sim(setup)
        if initial:
            text = _initial_text(initial)
            if lib.qd_sim_setup_initial(setup, text.encode()) != QD_OK:
                raise _text_error(core, "initial", text)
        items = outputs.items() if isinstance(outputs, dict) else [(o, o) for o in outputs]
        for name, text in items:
            if lib.qd_sim_setup_output(setup, name.encode(), text.encode(), 0,
                                       len(text.encode())) != QD_OK:
                raise _text_error(core, "outputs", text)
        fns = _add_inputs(core, setup, s, inputs)
        for what, text, stop in ([("events", t, False) for t in events] +
                                 ([("stop_at", stop_at, True)] if stop_at else [])):
            if lib.qd_sim_setup_event(setup, text.encode(), stop) != QD_OK:
                raise _text_error(core, what, text)
        texts = {"t_end": _number(t_end), "dt": _number(dt), "rtol": _number(rtol),
                 "atol": _number(atol), "every": _number(every), "step": _number(step),
                 "max_steps": str(int(max_steps)).encode() if max_steps else None,
                 "method": method.encode() if method is not None else None}
        keep = {k: ffi.new("char[]", v) for k, v in texts.items() if v is not None}
        so = new("qd_sim_setup_opts", keep)
        opts = new("qd_sim_opts")
        core.check(lib.qd_sim_setup_options(setup, so, opts))
        if jit is not None and not isinstance(jit, bool):
            raise TypeError("simulate: jit is True, False or None, not %r" % (jit,))
        opts.jit = (lib.QD_SIM_JIT_AUTO if jit is None else
                    lib.QD_SIM_JIT_ON if jit else lib.QD_SIM_JIT_OFF)
        return _run(core, s, opts, len(events) + bool(stop_at), fns)
    finally:
        lib.qd_sim_setup_free(setup)
def _run(core, s, opts, nev, fns=()):
    """qd_sim_run with a sink that copies every row; the Result.  An
    exception raised in an input callable (the callback then returns NaN,
    which ends the run) or in the sink itself (it then returns -1, a
    failure: qdot/sim.h) is raised here, in place of what the run
    reported; Python cannot unwind through C, and an exception left in a
    callback would only print "Exception ignored"."""
    ncol = lib.qd_sim_columns(s, opts.method, ffi.NULL, 0)
    names = ffi.new("const char *[]", max(ncol, 1))
    lib.qd_sim_columns(s, opts.method, names, ncol)
    columns = [cstr(names[k]) for k in range(ncol)]
    rows = []
    failed = []
    t0, span = opts.t0, opts.t_end - opts.t0

    with Run("simulate") as run:
        def sink(_data, event, row):
            try:
                if any(fn.error is not None for fn in fns):
                    return -1
                rows.append((event, ffi.unpack(row, ncol)))
                run.update((row[0] - t0) / span if span > 0 else 1.0, row[0])
                return 1 if run.stop else 0  # ^C: the run ends after a whole row
            except BaseException as err:  # noqa: B036 (re-raised below)
                failed.append(err)
                return -1

        def step(_data, t):
            # after every step: the bar and ^C between rows far apart (an
            # output grid dt, a step crawling near a singular point)
            run.update((t - t0) / span if span > 0 else 1.0, t)
            return 1 if run.stop else 0

        stats = new("qd_sim_stats")
        final = doubles([0.0] * ncol)
        callback = ffi.callback("qd_sim_sink", sink, error=-1)  # alive until qd_sim_run returns
        step_c = ffi.callback("int(void *, double)", step, error=1)
        opts.progress = step_c
        wall = time.perf_counter()
        st = lib.qd_sim_run(s, opts, callback, ffi.NULL, stats, final)
        wall = time.perf_counter() - wall
        for err in [fn.error for fn in fns if fn.error is not None] + failed:
            take_error(core.ctx)  # the failure's consequence: not the cause
            raise err
        if st != QD_OK:
            raise core.error(st)
        rep = new("qd_sim_report", {"s": s, "opts": opts, "stats": stats, "final": final,
                                    "wall": wall})
        summary, header, record = _report(rep, s, opts.method)
        run.partial = Result(columns, rows, nev, stats,
                             cstr(lib.qd_sim_method_name(opts.method)), summary, header,
                             bool(lib.qd_sim_event_column(s)), record, lib.qd_sim_ndof(s))
        return run.partial


def _report(rep, s, method):
    """The library's words on a run while s lives: the summary's text
    (qd_sim_summary_print), the CSV header (qd_sim_csv_header) and the
    summary's JSON members as a dict (qd_sim_summary_json; None when one of
    its numbers is not finite, as the CLI then refuses the document)."""
    summary, header, doc = new("qd_buf"), new("qd_buf"), new("qd_buf")
    j = new("qd_json")
    lib.qd_json_init(j, doc)
    lib.qd_json_begin_object(j)
    st = lib.qd_sim_summary_json(j, rep)
    lib.qd_json_end_object(j)
    ok = (lib.qd_sim_summary_print(rep, ffi.NULL, summary) == QD_OK and
          lib.qd_sim_csv_header(s, method, header) == QD_OK and st != QD_ERR_NOMEM)
    summary, header, doc = buf_text(summary), buf_text(header), buf_text(doc)
    if not ok:
        raise MemoryError("qdot: out of memory")
    return summary, header, json.loads(doc) if st == QD_OK else None


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
        self._vals_np = np.frombuffer(ffi.buffer(self._vals), dtype=float)
        self._qdd = doubles([0.0] * n)
        self._qdd_np = np.frombuffer(ffi.buffer(self._qdd), dtype=float)[:n]
        self._prog = lib.qd_eom_compile(core.ctx, core.eom_ptr())
        if not self._prog:
            raise core.error()
        self._work = lib.qd_eom_work_new(core.ctx, self._prog)
        if not self._work:
            raise core.error()

    def __repr__(self):
        return "<qdot.Rhs %s: y = (q, q') of %s>" % (self._core.file, ", ".join(self.coordinates))

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
                                  self._syms, self._vals, ffi.NULL, ffi.NULL, self._qdd,
                                  ffi.NULL, ffi.NULL)
        if st != QD_OK:
            raise self._core.error(st)
        return np.concatenate([y[n:], self._qdd_np])

    def __del__(self):
        """Free the workspace, then the program."""
        if self._work:
            lib.qd_eom_work_free(self._work)
        if self._prog:
            lib.qd_eom_prog_free(self._prog)
