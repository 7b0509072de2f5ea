# python/qdot/runs.py - the runs that are not one simulation's rows:
# poincare (the state at each crossing of a section), lyapunov (the
# exponents of the tangent flow) and animate (the page qd_scene_html
# writes).  Each is set up by the library's qd_sim_setup, as cli/sim_cli.c
# sets up `qdot poincare`, `qdot lyapunov` and `qdot animate`, so the same
# names, defaults, checks and messages apply; nothing here integrates.
"""Model.poincare, Model.lyapunov and Model.animate (see there)."""

import json as _json
import warnings

import cffi

from ._core import ModelError, NumericalError, take_error
from ._lib import ffi, lib, new, cstr, buf_text
from . import commands as _commands
from .sim import Result, _initial_text, _number, _text_error

QD_OK = lib.QD_OK

_libc_ffi = cffi.FFI()
_libc_ffi.cdef("void free(void *);")
_libc = _libc_ffi.dlopen(None)


def _free(ptr):
    """free() of a block the library malloc'd for the caller (qdot/scene.h:
    qd_scene_links' links), through the process's C library."""
    _libc.free(_libc_ffi.cast("void *", int(ffi.cast("uintptr_t", ptr))))


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

    def options(self, t_end, method, rtol, atol, dt, step, max_steps, fixed=False):
        """The run's qd_sim_opts by the library's rule (qd_sim_setup_options)."""
        texts = {"t_end": _number(t_end), "dt": _number(dt), "rtol": _number(rtol),
                 "atol": _number(atol), "step": _number(step),
                 "max_steps": str(int(max_steps)).encode() if max_steps else None,
                 "method": method.encode() if method is not None else None}
        keep = {k: ffi.new("char[]", v) for k, v in texts.items() if v is not None}
        so = new("qd_sim_setup_opts", dict(keep, fixed=bool(fixed)))
        opts = new("qd_sim_opts")
        self.core.check(lib.qd_sim_setup_options(self.ptr, so, opts))
        return opts


def _count(value, what, most):
    if isinstance(value, bool) or not isinstance(value, int) or not 0 < value <= most:
        raise ValueError("%s is a whole number from 1 to %g, not %r" % (what, most, value))
    return value


def poincare(core, section, crossings, t_end, method, rtol, atol, dt, step, initial,
             max_steps, speeds):
    """Model.poincare's work: the section as the run's one event (not
    stopping), the rows kept at its crossings, the run ended at the last
    one wanted, as `qdot poincare` does."""
    if not isinstance(section, str):
        raise TypeError("poincare: section is text \"EXPR = EXPR[, EXPR > EXPR]\", not %s"
                        % type(section).__name__)
    want = _count(crossings, "poincare: crossings", 1e9)
    setup = _Setup(core, speeds, initial)
    if lib.qd_sim_setup_event(setup.ptr, section.encode(), False) != QD_OK:
        raise _text_error(core, "section", section)
    opts = setup.options(1e6 if t_end is None else t_end, method, rtol, atol, dt, step,
                         max_steps)
    s = setup.sim
    ncol = lib.qd_sim_columns(s, opts.method, ffi.NULL, 0)
    names = ffi.new("const char *[]", max(ncol, 1))
    lib.qd_sim_columns(s, opts.method, names, ncol)
    rows, failed = [], []

    def sink(_data, event, row):
        try:
            if event != 0:  # the samples between crossings, an impact's rows
                return 0
            rows.append((-1, ffi.unpack(row, ncol)))
            return 1 if len(rows) >= want else 0
        except BaseException as err:  # noqa: B036 (re-raised below)
            failed.append(err)
            return -1

    stats = new("qd_sim_stats")
    callback = ffi.callback("qd_sim_sink", sink, error=-1)
    st = lib.qd_sim_run(s, opts, callback, ffi.NULL, stats, ffi.NULL)
    if failed:
        take_error(core.ctx)
        raise failed[0]
    if st != QD_OK:
        raise core.error(st, cls=NumericalError)
    if len(rows) < want:  # the CLI's note
        warnings.warn("poincare: only %d of %d crossings before t = %g (raise t_end)"
                      % (len(rows), want, stats.t), stacklevel=3)
    method_name = cstr(lib.qd_sim_method_name(opts.method))
    return Result([cstr(names[k]) for k in range(ncol)], rows, 0, stats, method_name)


def lyapunov(core, t_end, exponents, renorm, transient, method, rtol, atol, dt, initial,
             max_steps, speeds):
    """Model.lyapunov's work: the tangent system of the set-up's equations
    (qd_lyap_new) run by qd_lyap_run_stats, the report printed by
    qd_lyap_json, as `qdot lyapunov --format json`."""
    for what, x in (("renorm", renorm), ("transient", transient)):
        if x is not None and not float(x) >= 0:
            raise ValueError("lyapunov: %s is a number >= 0, not %r" % (what, x))
    setup = _Setup(core, speeds, initial)
    # Runge-Kutta: dop853 unless named; dt makes its step fixed (as the CLI)
    opts = setup.options(t_end, "dop853" if method is None else method, rtol, atol, dt, None,
                         max_steps, fixed=True)
    e = lib.qd_sim_setup_eom(setup.ptr)
    if not e:
        raise ValueError("lyapunov takes a model given by T and V or L (its equations M q'' = "
                         "f), not one given by H or in speeds (try speeds=False)")
    d = 2 * e.n
    nexp = _count(exponents, "lyapunov: exponents", d)
    lo = new("qd_lyap_opts", {"nexp": nexp, "renorm": float(renorm or 0),
                              "transient": float(transient or 0)})
    l_ = lib.qd_lyap_new(core.ctx, core.model, e)
    if not l_:
        raise core.error()
    try:
        ls = new("qd_lyap_stats")
        ex = ffi.new("double[]", 2 * nexp)
        st = lib.qd_lyap_run_stats(core.ctx, l_, opts, lo, ex, ex + nexp, ls)
        if st != QD_OK:
            raise core.error(st, cls=None if st == lib.QD_ERR_ARG else NumericalError)
        rep = new("qd_lyap_report", {"opts": lo, "ndof": e.n, "exps": ex, "err": ex + nexp,
                                     "stats": ls, "conservative": lib.qd_sim_conservative(
                                         setup.sim), "method": opts.method})
        return _commands.output(core, "lyapunov", lambda buf: lib.qd_lyap_json(rep, buf))
    finally:
        lib.qd_lyap_free(l_)


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
    """Model.animate's work, the library calls of `qdot animate`: the points
    (qd_scene_choose), their masses, traces and springs, the run sampled at
    the frames (qd_scene_record), the links and plane (qd_scene_links), the
    page (qd_scene_html) and its data (qd_scene_json)."""
    ctx = core.ctx
    draw, trace, spring = _words(draw, "draw"), _words(trace, "trace"), _words(spring, "spring")
    setup = _Setup(core, speeds, initial)
    opts = setup.options(10 if t_end is None else t_end, method, rtol, atol, dt, step,
                         max_steps)
    keep = [ffi.new("char[]", w.encode()) for w in draw + trace + spring]
    words = lambda k, n: ffi.new("const char *[]", keep[k:k + n] or [ffi.NULL])  # noqa: E731
    pp, n = new("qd_scene_point *"), new("size_t")
    if lib.qd_scene_choose(ctx, core.model, words(0, len(draw)), len(draw), pp, n) != QD_OK:
        raise core.error()
    pts, npts = pp[0], n[0]
    fr = new("qd_scene_frames")
    links, nlinks = new("qd_scene_link *"), new("size_t")
    try:
        syms, vals = new("const qd_expr *const *"), new("const double *")
        nsyms = lib.qd_sim_setup_state(setup.ptr, syms, vals)
        mass = ffi.new("double[]", npts + 1)
        traces = ffi.new("size_t[]", len(trace) + 1)
        springs = ffi.new("size_t[]", 2 * len(spring) + 1)
        for st in (lib.qd_scene_masses(ctx, pts, npts, nsyms, syms[0], vals[0], mass),
                   lib.qd_scene_named(ctx, pts, npts, words(len(draw), len(trace)), len(trace),
                                      traces),
                   lib.qd_scene_pairs(ctx, pts, npts, words(len(draw) + len(trace),
                                                            len(spring)), len(spring), springs),
                   lib.qd_scene_add_outputs(ctx, setup.sim, core.model, pts, npts)):
            if st != QD_OK:
                raise core.error(st)
        stats = new("qd_sim_stats")
        st = lib.qd_scene_record(ctx, setup.sim, opts, pts, npts, ffi.NULL, ffi.NULL, fr, stats)
        if st != QD_OK:
            raise core.error(st, cls=NumericalError)
        view = new("qd_scene", {"pts": pts, "npts": npts, "mass": mass, "fr": fr,
                                "traces": traces, "ntraces": len(trace),
                                "energy_error_max": stats.energy_error_max,
                                "conservative": lib.qd_sim_conservative(setup.sim)})
        model_name = ffi.new("char[]", core.file.encode())
        view.model, view.method = model_name, lib.qd_sim_method_name(opts.method)
        st = lib.qd_scene_links(ctx, fr.pos, fr.nframes, npts, springs, len(spring), links,
                                nlinks, view.plane)
        if st != QD_OK:
            raise core.error(st)
        view.links, view.nlinks = links[0], nlinks[0]
        return Animation(_json.loads(_render(core, lib.qd_scene_json, view)),
                         _render(core, lib.qd_scene_html, view))
    finally:
        if links[0] != ffi.NULL:
            _free(links[0])
        lib.qd_scene_frames_free(fr)
        lib.qd_scene_points_free(pts)


def _render(core, fn, view):
    buf = new("qd_buf")
    if fn(view, buf) != QD_OK:
        lib.qd_buf_free(buf)
        raise MemoryError("qdot: out of memory")
    return buf_text(buf)


def sweep(core, t_end, measures, grid, random, runs, seed, section, events, stop_at, threads,
          renorm, transient, method, rtol, atol, dt, step, initial, max_steps, speeds):
    """Model.sweep's work, the library calls of `qdot sweep`: the measures'
    needs (qd_sweep_needs), the events, then the section after them, the
    measures' outputs and crossings (qd_sweep_setup_measures), the runs
    (qd_sweep_grid or qd_sweep_random) on the library's thread pool
    (qd_sweep_result_run) and the rows as `--format json` writes them
    (qd_sweep_json)."""
    if not isinstance(measures, str):
        raise TypeError("sweep: measures is text \"final, max:EXPR, ...\", not %s"
                        % type(measures).__name__)
    if (grid is None) == (random is None):
        raise ValueError("sweep: give grid (\"NAME=A:B:N, ...\") or random (\"NAME=A:B, ...\")"
                         " with runs")
    if random is not None:
        nrand = _count(runs, "sweep: runs (the number of random runs)", 1e12)
    elif runs is not None:
        raise ValueError("sweep: runs is for random")
    flags = new("unsigned")
    lib.qd_sweep_needs(ffi.NULL, measures.encode(), ffi.NULL, 0, flags)
    nuser = len(events) + (stop_at is not None)
    if not nuser and flags[0] & lib.QD_SWEEP_NEEDS_EVENT:
        raise ValueError("sweep: the measure event needs events or stop_at (its first is the one)")
    if section is None and flags[0] & lib.QD_SWEEP_NEEDS_SECTION:
        raise ValueError("sweep: the measure poincare-count needs section")
    setup = _Setup(core, speeds, initial)
    for what, text, stop in ([("events", t, False) for t in events] +
                             ([("stop_at", stop_at, True)] if stop_at is not None else []) +
                             ([("section", section, False)] if section is not None else [])):
        if lib.qd_sim_setup_event(setup.ptr, text.encode(), stop) != QD_OK:
            raise _text_error(core, what, text)
    if lib.qd_sweep_setup_measures(core.ctx, setup.ptr, measures.encode()) != QD_OK:
        raise _text_error(core, "measures", measures)
    opts = setup.options(t_end, method, rtol, atol, dt, step, max_steps)
    s = setup.sim
    core.check(lib.qd_sim_compile(s))
    w = lib.qd_sweep_new(core.ctx, s, core.model)
    if not w:
        raise core.error()
    ly = ffi.NULL
    r = new("qd_sweep_result")
    try:
        for what, text, st in (
                ("grid", grid, lambda: lib.qd_sweep_grid(w, grid.encode())),
                ("random", random, lambda: lib.qd_sweep_random(w, random.encode(), nrand,
                                                               int(seed))),
                ("measures", measures, lambda: lib.qd_sweep_measures(w, measures.encode()))):
            if text is not None and st() != QD_OK:
                raise _text_error(core, what, text)
        if section is not None:
            core.check(lib.qd_sweep_set_section(w, nuser))
        if flags[0] & lib.QD_SWEEP_NEEDS_LYAP:
            e = lib.qd_sim_setup_eom(setup.ptr)
            if not e:
                raise ValueError("sweep: the lyapunov measures take a model in the multiplier "
                                 "form (not given by H, not in speeds: speeds=False)")
            ly = lib.qd_lyap_new(core.ctx, core.model, e)
            lo = new("qd_lyap_opts", {"renorm": float(renorm or 0),
                                      "transient": float(transient or 0)})
            if not ly or lib.qd_sweep_set_lyap(w, ly, lo) != QD_OK:
                raise core.error()
        core.check(lib.qd_sweep_result_run(core.ctx, w, opts, int(threads), ffi.NULL, ffi.NULL,
                                           r))
        if r.nruns and r.failed == r.nruns:
            why = ffi.new("char[]", lib.QD_SWEEP_OUTCOME_MAX)
            raise NumericalError("sweep: every run failed (the first: %s)"
                                 % cstr(lib.qd_sweep_outcome_str(r.outcome, why,
                                                                 lib.QD_SWEEP_OUTCOME_MAX)))
        return _commands.output(core, "sweep", lambda buf: lib.qd_sweep_json(
            w, r.rows, r.outcome, buf))
    finally:
        lib.qd_sweep_result_free(r)
        lib.qd_sweep_free(w)
        if ly:
            lib.qd_lyap_free(ly)
