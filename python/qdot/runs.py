# python/qdot/runs.py - the runs that are not one simulation's rows:
# poincare (the state at each crossing of a section), lyapunov (the
# exponents of the tangent flow), flow (its Jacobian), sweep (many runs, a row each) and animate
# (the page qd_scene_html writes).  Each is the library's set-up of its
# command (qd_sim_setup, then qd_poincare_run, qd_lyap_setup_run,
# qd_sweep_setup_new, qd_scene_setup_new), called as cli/cmd_*.c call them,
# so the same defaults, checks and messages apply; here are only Python's
# argument types, the progress bar and Ctrl-C (_progress.Run).
"""Model.poincare, Model.lyapunov, Model.flow, Model.sweep and Model.animate (see there)."""

import json as _json
import warnings

from ._core import Error, ModelError, NumericalError, take_error
from ._lib import ffi, lib, new, cstr, buf_text
from . import commands as _commands
from ._progress import Run
from .sim import Result, _initial_text, _number, _text_error

QD_OK = lib.QD_OK

class _Setup:
    """A qd_sim_setup (qdot/simsetup.h) with its initial values given, freed
    with this object: the model's equations as a run takes them."""

    def __init__(self, core, speeds, initial):
        self.core = core
        self.ptr = lib.qd_sim_setup_new(core.ctx, core.model, not speeds)
        if not self.ptr:
            raise core.error(cls=ModelError)
        if initial:
            text = _initial_text(initial)
            if lib.qd_sim_setup_initial(self.ptr, text.encode()) != QD_OK:
                raise _text_error(core, "initial", text)

    def __del__(self):
        if getattr(self, "ptr", None):
            lib.qd_sim_setup_free(self.ptr)

    @property
    def sim(self):
        return lib.qd_sim_setup_sim(self.ptr)

    def event(self, what, text, stop=False):
        if not isinstance(text, str):
            raise TypeError("%s is text (a condition such as \"x = 0, x' > 0\"), not %s"
                            % (what, type(text).__name__))
        if lib.qd_sim_setup_event(self.ptr, text.encode(), stop) != QD_OK:
            raise _text_error(self.core, what, text)

    def options(self, t_end, method, rtol, atol, dt, step, max_steps, fixed=False, period=None):
        """The run's qd_sim_opts by the library's rule (qd_sim_setup_options);
        period (a number or an expression in the parameters) instead of t_end."""
        if isinstance(period, str):
            period = period.encode()
        elif period is not None:
            period = _number(period)
        texts = {"t_end": _number(t_end), "period": period, "dt": _number(dt),
                 "rtol": _number(rtol),
                 "atol": _number(atol), "step": _number(step),
                 "max_steps": str(int(max_steps)).encode() if max_steps else None,
                 "method": method.encode() if method is not None else None}
        keep = {k: ffi.new("char[]", v) for k, v in texts.items() if v is not None}
        so = new("qd_sim_setup_opts", dict(keep, fixed=bool(fixed)))
        opts = new("qd_sim_opts")
        self.core.check(lib.qd_sim_setup_options(self.ptr, so, opts))
        return opts


def _count(value, what, most):
    """A count argument: the CLI's option parser refuses the same."""
    if isinstance(value, bool) or not isinstance(value, int) or not 0 < value <= most:
        raise ValueError("%s is a whole number from 1 to %g, not %r" % (what, most, value))
    return value


def _time(value, what):
    """renorm, transient: a number >= 0 (None: the library's default)."""
    if value is None:
        return 0.0
    if not float(value) >= 0 or float(value) == float("inf"):
        raise ValueError("%s takes a number >= 0, not %r" % (what, value))
    return float(value)


def poincare(core, section, crossings, t_end, method, rtol, atol, dt, step, initial,
             max_steps, speeds):
    """Model.poincare's work: the section the run's one event, its crossings
    kept by qd_poincare_orbits_run (each orbit ended at the last one
    wanted), as `qdot poincare` does; initial a list: an orbit each, every
    initial state read before the first run, a Result each."""
    want = _count(crossings, "poincare: crossings", 1e9)
    several = isinstance(initial, (list, tuple))
    orbits = list(initial) if several else [initial]
    if not 1 <= len(orbits) <= lib.QD_POINCARE_MAX_ORBITS:
        raise ValueError("poincare: initial takes 1 to %d orbits, not %d"
                         % (lib.QD_POINCARE_MAX_ORBITS, len(orbits)))
    texts = [_initial_text(o) if o else None for o in orbits]
    setup = _Setup(core, speeds, None)
    setup.event("section", section)
    opts = setup.options(1e6 if t_end is None else t_end, method, rtol, atol, dt, step,
                         max_steps)
    keep = [ffi.new("char[]", t.encode()) if t is not None else ffi.NULL for t in texts]
    # a struct field does not own what it points to: the array lives in a name
    initial_c = ffi.new("const char *[]", keep)
    orb = new("qd_poincare_orbits", {"n": len(orbits), "initial": initial_c})
    at = ffi.new("size_t *")
    if lib.qd_poincare_orbits_check(core.ctx, setup.ptr, opts, orb, at) != QD_OK:
        raise _text_error(core, "initial", texts[at[0]] or "")
    s = setup.sim
    ncol = lib.qd_sim_columns(s, opts.method, ffi.NULL, 0)
    names = ffi.new("const char *[]", max(ncol, 1))
    lib.qd_sim_columns(s, opts.method, names, ncol)
    columns = [cstr(names[k]) for k in range(ncol)]
    rows, failed = [[] for _ in orbits], []
    with Run("poincare") as run:
        def sink(_data, row, crossing):
            try:
                if crossing:
                    rows[now[0]].append((-1, ffi.unpack(row, ncol)))
                return 1 if run.stop else 0  # ^C: after a whole row
            except BaseException as err:  # noqa: B036 (re-raised below)
                failed.append(err)
                return -1

        now = [0]
        sink_c = ffi.callback("int(void *, const double *, bool)", sink, error=-1)
        progress_c = ffi.callback("void(void *, double, double)",
                                  lambda _d, done, t: run.update(done, t))
        start_c = ffi.callback("void(void *, size_t)", lambda _d, k: now.__setitem__(0, k))
        orb.start = start_c
        po = new("qd_poincare_opts", {"event": 0, "want": want, "sink": sink_c,
                                      "progress": progress_c})
        r = ffi.new("qd_poincare_result[]", len(orbits))
        st = lib.qd_poincare_orbits_run(core.ctx, setup.ptr, opts, po, orb, r, at)
        if failed:
            take_error(core.ctx)
            raise failed[0]
        if st != QD_OK:
            raise core.error(st, cls=NumericalError)
        out = []
        for k, text in enumerate(texts):
            res = Result(columns, rows[k], 0, ffi.addressof(r[k], "stats"),
                         cstr(lib.qd_sim_method_name(opts.method)), ndof=lib.qd_sim_ndof(s))
            res._section, res.label, res._command = True, text, "poincare"
            out.append(res)
        run.partial = out if several else out[0]
        for k in range(len(orbits)):
            if r[k].got < want and not run.stop:  # the CLI's note
                warnings.warn("poincare: %sonly %d of %d crossings before t = %g (raise t_end)"
                              % ("orbit %d: " % (k + 1) if several else "", r[k].got, want,
                                 r[k].stats.t), stacklevel=3)
        return out if several else out[0]


def lyapunov(core, t_end, exponents, renorm, transient, method, rtol, atol, dt, initial,
             max_steps, speeds):
    """Model.lyapunov's work: qd_lyap_setup_run on the set-up's run, the
    report printed by qd_lyap_json, as `qdot lyapunov --format json`."""
    fields = {"nexp": _count(exponents, "lyapunov: exponents", 1e9),
              "renorm": _time(renorm, "lyapunov: renorm"),
              "transient": _time(transient, "lyapunov: transient")}
    setup = _Setup(core, speeds, initial)
    # Runge-Kutta: dop853 unless named; dt makes its step fixed (as the CLI)
    opts = setup.options(t_end, "dop853" if method is None else method, rtol, atol, dt, None,
                         max_steps, fixed=True)
    r = new("qd_lyap_result")
    try:
        with Run("lyapunov") as run:
            def progress(_data, done, t):
                run.update(done, t)
                return 1 if run.stop else 0  # ^C: stops after this renormalization
            progress_c = ffi.callback("int(void *, double, double)", progress, error=1)
            lo = new("qd_lyap_opts", dict(fields, progress=progress_c))
            st = lib.qd_lyap_setup_run(core.ctx, setup.ptr, core.model, opts, lo, r)
            if run.stop:
                take_error(core.ctx)  # "stopped at t": KeyboardInterrupt says it
                return None
        if st != QD_OK:
            raise core.error(st, cls=None if st == lib.QD_ERR_ARG else NumericalError)
        return _commands.output(core, "lyapunov",
                                lambda buf: lib.qd_lyap_json(ffi.addressof(r, "report"), buf))
    finally:
        lib.qd_lyap_result_free(r)


def flow(core, t_end, period, method, rtol, atol, dt, initial, max_steps):
    """Model.flow's work, `qdot simulate --variational [--period T]
    --format json`'s flow: qd_flow_run on the Lagrange equations of the
    set-up (qd_lyap_new, qd_flow_sim_opts), its members by qd_flow_json."""
    if (t_end is None) == (period is None):
        raise ValueError("flow: give t_end or period (one of them), not %s"
                         % ("both" if period is not None else "neither"))
    setup = _Setup(core, False, initial)
    e = lib.qd_sim_setup_eom(setup.ptr)
    if e == ffi.NULL:
        raise Error("flow takes a model given by T and V or L (its equations M q'' = f), "
                         "not one given by H")
    opts = setup.options(t_end, method, rtol, atol, dt, None, max_steps, period=period)
    T = lib.qd_sim_setup_period_of(setup.ptr) if period is not None else 0.0
    l = lib.qd_lyap_new(core.ctx, core.model, e)
    if l == ffi.NULL:
        raise core.error(cls=ModelError)
    fopts, f = new("qd_sim_opts"), new("qd_flow")
    try:
        core.check(lib.qd_flow_sim_opts(opts, fopts))
        with Run("flow"):  # no hook to stop it: ^C is raised once it returns
            st = lib.qd_flow_run(core.ctx, l, fopts, ffi.NULL, f)
        if st != QD_OK:
            raise core.error(st, cls=None if st == lib.QD_ERR_ARG else NumericalError)

        def members(buf):
            j = new("qd_json")
            lib.qd_json_init(j, buf)
            lib.qd_json_begin_object(j)
            st = lib.qd_flow_json(j, f, e, fopts.method, T)
            lib.qd_json_end_object(j)
            return st
        return _commands.output(core, "flow", members)
    finally:
        lib.qd_flow_free(f)
        lib.qd_lyap_free(l)


def sweep(core, t_end, measures, grid, random, runs, seed, section, events, stop_at, threads,
          renorm, transient, method, rtol, atol, dt, step, initial, max_steps, speeds):
    """Model.sweep's work, the library calls of `qdot sweep`: the events,
    then the section after them, the sweep set up by qd_sweep_setup_new
    (its refusals, the measures' needs, the runs, the Lyapunov measures'
    equations), run on the library's thread pool (qd_sweep_result_run) and
    the rows as `--format json` writes them (qd_sweep_json)."""
    texts = {"measures": measures, "grid": grid, "random": random}
    for what, text in texts.items():
        if text is not None and not isinstance(text, str):
            raise TypeError("sweep: %s is text, not %s" % (what, type(text).__name__))
    if random is not None:
        nrand = _count(runs, "sweep: runs (the number of random runs)", 1e12)
    elif runs is not None:
        raise ValueError("sweep: runs is for random")
    setup = _Setup(core, speeds, initial)
    for text in events:
        setup.event("events", text)
    if stop_at is not None:
        setup.event("stop_at", stop_at, True)
    if section is not None:
        setup.event("section", section)
    opts = setup.options(t_end, method, rtol, atol, dt, step, max_steps)
    keep = {k: ffi.new("char[]", v.encode()) for k, v in texts.items() if v is not None}
    sp = new("qd_sweep_spec", dict(keep, n=nrand if random is not None else 0, seed=int(seed),
                                   nevents=len(events) + (stop_at is not None),
                                   section=section is not None,
                                   renorm=_time(renorm, "sweep: renorm"),
                                   transient=_time(transient, "sweep: transient")))
    where = ffi.new("const char **")
    w = lib.qd_sweep_setup_new(core.ctx, setup.ptr, core.model, sp, where)
    if not w:
        field = cstr(where[0]) if where[0] != ffi.NULL else None
        if field in texts:
            raise _text_error(core, field, texts[field])
        raise core.error()
    r = new("qd_sweep_result")
    try:
        with Run("sweep", "runs") as run:
            def progress(_data, done, total):
                run.update(done / total, done)
                return 1 if run.stop else 0  # ^C: no run starts after it
            progress_c = ffi.callback("int(void *, size_t, size_t)", progress, error=1)
            st = lib.qd_sweep_result_run(core.ctx, w, opts, int(threads), progress_c,
                                         ffi.NULL, r)
            if run.stop:
                take_error(core.ctx)  # "stopped after": KeyboardInterrupt says it
                return None
            core.check(st)
        if lib.qd_sweep_result_check(core.ctx, r) != QD_OK:
            raise core.error(cls=NumericalError)
        return _commands.output(core, "sweep", lambda buf: lib.qd_sweep_json(
            w, r.rows, r.outcome, buf))
    finally:
        lib.qd_sweep_result_free(r)
        lib.qd_sweep_free(w)


class Animation(_commands.Output):
    """What Model.animate returns: a qdot.Output whose fields are the
    scene's data (qd_scene_json: model, method, plane, conservative,
    energy_error_max, points, links, traces, t, pos, ...), .html the
    self-contained page `qdot animate -o FILE.html` writes (qd_scene_html:
    no network), shown inline in Jupyter; .save(path) writes it."""

    __module__ = "qdot"

    def __init__(self, data, html):
        super().__init__("animate", data)
        self.__dict__["html"] = html

    def __repr__(self):
        t = self.json.get("t") or [0]
        return "<qdot.Animation %s: %d frames, t = %g..%g, %d points, %s>" % (
            self.json.get("model"), len(t), t[0], t[-1], len(self.json.get("points", [])),
            self.json.get("method"))

    def _repr_html_(self):
        # the page in an iframe of its own: its script and style stay apart
        import html as _html
        return ('<iframe srcdoc="%s" style="width:100%%;height:480px;border:0"></iframe>'
                % _html.escape(self.html, quote=True))

    def save(self, path):
        """The page written to path (.html)."""
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(self.html)


def _words(x, what):
    if x is None:
        return []
    if isinstance(x, str):
        return [x]
    if not all(isinstance(w, str) for w in x):
        raise TypeError("animate: %s are names (text)" % what)
    return list(x)


def animate(core, t_end, draw, trace, spring, method, rtol, atol, dt, step, initial,
            max_steps, speeds):
    """Model.animate's work, the library calls of `qdot animate`: the points,
    traces and springs chosen by qd_scene_setup_new, the run sampled at the
    frames (qd_scene_setup_record), the page (qd_scene_html) and its data
    (qd_scene_json)."""
    lists = [[ffi.new("char[]", w.encode()) for w in _words(x, what)]
             for x, what in ((draw, "draw"), (trace, "trace"), (spring, "spring"))]
    arrays = [ffi.new("const char *[]", k or [ffi.NULL]) for k in lists]
    setup = _Setup(core, speeds, initial)
    opts = setup.options(10 if t_end is None else t_end, method, rtol, atol, dt, step,
                         max_steps)
    title = ffi.new("char[]", core.file.encode())
    sp = new("qd_scene_spec", {"draws": arrays[0], "ndraws": len(lists[0]),
                               "traces": arrays[1], "ntraces": len(lists[1]),
                               "springs": arrays[2], "nsprings": len(lists[2]), "title": title})
    sc = lib.qd_scene_setup_new(core.ctx, setup.ptr, core.model, sp)
    if not sc:
        raise core.error()
    try:
        t0, t1 = opts.t0, opts.t_end
        with Run("animate") as run:
            def progress(_data, t):
                run.update((t - t0) / (t1 - t0), t)
                return 1 if run.stop else 0  # ^C: the motion so far, after a whole row
            progress_c = ffi.callback("int(void *, double)", progress, error=1)
            st = lib.qd_scene_setup_record(sc, opts, progress_c, ffi.NULL, ffi.NULL)
            if st != QD_OK:
                raise core.error(st, cls=NumericalError)
            view = lib.qd_scene_setup_scene(sc)
            anim = Animation(_json.loads(_render(lib.qd_scene_json, view)),
                             _render(lib.qd_scene_html, view))
            run.partial = anim  # KeyboardInterrupt's .result: the page up to the stop
        return anim
    finally:
        lib.qd_scene_setup_free(sc)


def _render(fn, view):
    buf = new("qd_buf")
    if fn(view, buf) != QD_OK:
        lib.qd_buf_free(buf)
        raise MemoryError("qdot: out of memory")
    return buf_text(buf)
