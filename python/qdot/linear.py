# python/qdot/linear.py - Model.equilibria and Model.modes: the point and
# the search as `qdot equilibria` and `qdot modes` take them, by the same
# library calls (qdot/linpoint.h, qd_equilibria_find_text, qd_modes_at_choose,
# qd_modes_at_solve, qd_modes_symmetry, qd_modes_print).
#
# Nothing is decided here: which equilibrium the modes are about, what
# counts as "not an equilibrium" and how the symmetry is had are the
# library's; a note the command writes on stderr is a Python warning here.
"""Equilibria and small oscillations (internal module)."""

import warnings

import numpy as np

from ._core import ArgumentError, ModelError, NumericalError, format_diag, take_error
from ._lib import ffi, lib, new, buf_text, cstr
from . import commands as _commands

QD_ERR_NUMERIC = lib.QD_ERR_NUMERIC


class Point:
    """The equations the linear commands analyse (holonomic constraints
    eliminated) and the state of a point (a qd_linpoint), freed by free()."""

    def __init__(self, core):
        self.core = core
        self.e = core.eom_eliminated()
        self.pt = new("qd_linpoint")
        st = lib.qd_linpoint_init(core.ctx, core.model, self.e, self.pt)
        if st != lib.QD_OK:
            lib.qd_linpoint_free(self.pt)
            raise core.error(st)
        self.names = [cstr(lib.qd_expr_name(self.e.q[j])) for j in range(self.e.n)]

    def free(self):
        lib.qd_linpoint_free(self.pt)


def located(core, what, text):
    """The context's error about an argument's text: a ModelError shown in
    it when located there (as the command line shows --about), else an
    ArgumentError naming the argument."""
    diag = take_error(core.ctx)
    if diag.status == lib.QD_ERR_NOMEM:
        return MemoryError("qdot: out of memory")
    if diag.located:
        return ModelError(format_diag(diag, what, text), diag, what)
    return ArgumentError("%s: %s" % (what, ffi.string(diag.message).decode()), diag.status)


def _range_text(box):
    """box as --box's text: "x=A:B, ..." as given, or {name: (A, B)}."""
    if isinstance(box, dict):
        items = []
        for name, r in box.items():
            if isinstance(r, str):
                items.append("%s=%s" % (name, r))
                continue
            if not isinstance(r, (tuple, list)) or len(r) != 2:
                raise TypeError("equilibria: box maps a coordinate to (low, high), not %r" % (r,))
            items.append("%s=%s:%s" % (name, *(x if isinstance(x, str) else repr(float(x))
                                                 for x in r)))
        box = ", ".join(items)
    return box


def _point_text(about, what):
    """A point at rest as the text the library reads: {coordinate: value},
    an Equilibrium (its q), or "q1=VALUE, ..."; None stays None."""
    if about is not None and hasattr(about, "q") and isinstance(about.q, dict):
        about = about.q
    if about is not None and not isinstance(about, (dict, str)):
        raise TypeError("%s: a dict {coordinate: value}, an Equilibrium or text, not %s"
                        % (what, type(about).__name__))
    return about


def equilibrium(core, names, pt):
    """An Equilibrium of the C struct pt."""
    from .model import Equilibrium
    n = len(names)
    q = {names[j]: pt.q[j] for j in range(n)}
    exact = {names[j]: core.text_of(pt.exact[j]) for j in range(n)} if pt.exact else None
    return Equilibrium(q, exact, cstr(lib.qd_eq_kind_name(pt.kind)), pt.residual)


class SpeedsPoint:
    """A model with `speeds`: its equations in the speeds and the state
    (q, q', t, the parameters, then the speeds u), as `qdot equilibria` and
    `qdot modes` take them (qd_speeds_derive, qd_state_init, qd_state_append)."""

    def __init__(self, core):
        self.core, self.st = core, new("qd_state")
        self.se = lib.qd_speeds_derive(core.ctx, core.model, ffi.NULL)
        if not self.se:
            raise core.error(cls=ModelError)
        try:
            core.check(lib.qd_state_init(core.ctx, core.model, self.st))
            core.check(lib.qd_state_append(core.ctx, self.st, self.se.m, self.se.u, ffi.NULL))
        except BaseException:
            self.free()
            raise
        self.names = [cstr(lib.qd_expr_name(self.se.q[j])) for j in range(self.se.n)]

    def free(self):
        lib.qd_state_free(self.st)
        lib.qd_speeds_eom_free(self.se)
        self.se = ffi.NULL


def _refuse(what, **given):
    """A model with `speeds` takes none of these arguments (the command's
    refusal of the same options)."""
    for name, value in given.items():
        if value not in (None, False):
            raise ValueError("%s: %s is not available for a model with speeds (the state is q "
                             "and u)" % (what, name))


def speeds_equilibria(core):
    """qd_speeds_equilibria_find at the model's state: an Equilibria whose
    points give the coordinates the equations at rest solve (kind None: no
    Hessian is taken in the speeds)."""
    from .model import Equilibria, Equilibrium
    p = SpeedsPoint(core)
    out = new("qd_speeds_equilibria")
    try:
        core.check(lib.qd_speeds_equilibria_find(core.ctx, p.se, core.model, p.st.n, p.st.syms,
                                                 p.st.vals, ffi.NULL, out), NumericalError)
        eq = out.eq
        names = [p.names[out.solved[j]] for j in range(out.nsolved)]
        found = Equilibria()
        for k in range(eq.count):
            pt = eq.pts[k]
            q = {names[j]: pt.q[j] for j in range(len(names))}
            exact = ({names[j]: core.text_of(pt.exact[j]) for j in range(len(names))}
                     if pt.exact else None)
            found.append(Equilibrium(q, exact, None, pt.residual))
        found.output = _commands.output(core, "equilibria", lambda buf: (
            lib.qd_speeds_equilibria_print(core.ctx, p.se, out, True, buf)))
        return found
    finally:
        lib.qd_speeds_equilibria_free(out)
        p.free()


def _steps(steps, what):
    if steps is not None and (isinstance(steps, bool) or not isinstance(steps, int) or
                              not 1 <= steps <= 100000):
        raise ValueError("%s: steps is a number of steps from 1 to 100000, not %r"
                         % (what, steps))
    return steps or 0


def speeds_modes(core, about, scan_=None, steps=None):
    """The eigenvalues of the reduced first-order system about a state
    (qd_speeds_linear_about, qd_speeds_modes_solve, qd_speeds_modes_print):
    about's coordinates and speeds ("theta=pi/2, u3=6"), else the first
    equilibrium at rest (qd_speeds_equilibria_choose)."""
    from .model import Modes
    p = SpeedsPoint(core)
    lin, res = new("qd_speeds_linear"), new("qd_modes_result")
    text = _commands.text_arg(_point_text(about, "about"), "about")
    try:
        if text is not None:
            o = new("qd_state_read_opts", {"refuse": lib.QD_STATE_VELOCITIES |
                                           lib.QD_STATE_TIME | lib.QD_STATE_PARAMS})
            if lib.qd_state_read(core.ctx, core.model, p.st, text, o) != lib.QD_OK:
                raise located(core, "about", ffi.string(text))
        else:
            found = ffi.new("bool *")
            core.check(lib.qd_speeds_equilibria_choose(core.ctx, p.se, core.model, p.st.n,
                                                       p.st.syms, p.st.vals, found))
            if not found[0]:
                raise NumericalError("modes: no equilibrium found (Model.equilibria() lists "
                                     "none): give a state with about={...}", QD_ERR_NUMERIC)
        if scan_ is not None:  # qd_speeds_modes_scan_text at that state
            return _speeds_scan(core, p, _range_arg(scan_, "modes"), text, _steps(steps, "modes"))
        core.check(lib.qd_speeds_linear_about(core.ctx, p.se, p.st.n, p.st.syms, p.st.vals, lin))
        core.check(lib.qd_speeds_modes_solve(core.ctx, lin, res), NumericalError)
        output = _commands.output(core, "modes", lambda buf: lib.qd_speeds_modes_print(
            core.ctx, p.se, p.st.n, p.st.syms, p.st.vals, lin, res, True, buf))
        eig = np.array([complex(res.eig_re[k], res.eig_im[k]) for k in range(res.neig)])
        out = Modes([], dict(output.json["state"]), False, eig, res.stable)
        out.output = output
        return out
    finally:
        lib.qd_modes_result_free(res)
        lib.qd_speeds_linear_free(lin)
        p.free()


def equilibria(core, guess=None, box=None):
    """qd_equilibria_find_text from guess and box; an Equilibria."""
    from .model import Equilibria
    if lib.qd_model_nspeeds(core.model):
        _refuse("equilibria", guess=guess, box=box)
        return speeds_equilibria(core)
    p = Point(core)
    out = new("qd_equilibria")
    where = ffi.new("const char **")
    texts = {"guess": _commands.text_arg(_point_text(guess, "guess"), "guess"),
             "box": _commands.text_arg(_range_text(box), "box")}
    c = {k: v if v is not None else ffi.NULL for k, v in texts.items()}
    try:
        st = lib.qd_equilibria_find_text(core.ctx, p.pt, c["guess"], c["box"], out, where)
        if st != lib.QD_OK:
            if where[0] != ffi.NULL:
                which = "guess" if where[0] == c["guess"] else "box"
                raise located(core, which, ffi.string(texts[which]))
            raise core.error(st, cls=NumericalError if st == QD_ERR_NUMERIC else None)
        found = Equilibria(equilibrium(core, p.names, out.pts[k]) for k in range(out.count))
        found.output = _commands.output(core, "equilibria", lambda buf: (
            lib.qd_equilibria_print(core.ctx, p.e, out, True, buf)))
        return found
    finally:
        lib.qd_equilibria_free(out)
        p.free()


def _choose(core, p, about, at_equilibrium, at):
    """Step 1 (qd_modes_at_choose): the point given, equilibrium number
    at_equilibrium, or the library's choice."""
    text = _commands.text_arg(_point_text(about, "about"), "about")
    st = lib.qd_modes_at_choose(core.ctx, p.pt, text if text is not None else ffi.NULL,
                                at_equilibrium, at)
    if st == lib.QD_OK:
        return
    if text is not None and lib.qd_ctx_diag(core.ctx).located:
        raise located(core, "about", ffi.string(text))
    if st == lib.QD_ERR_ARG:
        raise ArgumentError("at_equilibrium %d: %s" % (at_equilibrium,
                                                       cstr(lib.qd_ctx_message(core.ctx))), st)
    if st == QD_ERR_NUMERIC and not at.pt:
        lib.qd_ctx_clear_error(core.ctx)
        raise NumericalError("modes: no equilibrium found (Model.equilibria() lists none): "
                             "give a point with about={...}", st)
    raise core.error(st, cls=NumericalError if st == QD_ERR_NUMERIC else None)


def _symmetry(core, p, at, sym, cyc):
    """qd_modes_symmetry about the point; its note (no symmetry) a warning.
    True when the symmetry's modes replace the plain ones."""
    note = new("qd_buf")
    st_ = p.pt.st
    st = lib.qd_modes_symmetry(core.ctx, p.e, core.model, st_.n, st_.syms, st_.vals,
                               ffi.addressof(at.lin), sym, cyc, note)
    text = buf_text(note)
    core.check(st)
    if text:
        warnings.warn("modes: symmetry: %s" % text, UserWarning, stacklevel=4)
    return cyc.n > 0 or sym.order > 1


def _initial(core, p, at, initial):
    """--initial's normal coordinates (qd_modes_at_initial): Q, Qd arrays."""
    text = _commands.text_arg(initial, "initial")
    n = p.e.n
    Q, Qd = ffi.new("double[]", n + 1), ffi.new("double[]", n + 1)
    if lib.qd_modes_at_initial(core.ctx, p.pt, at, text, Q, Qd) != lib.QD_OK:
        raise located(core, "initial", ffi.string(text))
    return Q, Qd


def _range_arg(range_, what):
    """A scan's range as --scan's text: "NAME=A:B", or (name, a, b)."""
    if isinstance(range_, (tuple, list)) and len(range_) == 3:
        name, a, b = range_
        range_ = "%s=%s:%s" % (name, *(x if isinstance(x, str) else repr(float(x))
                                       for x in (a, b)))
    if not isinstance(range_, str):
        raise TypeError("%s: scan is \"NAME=A:B\" or (name, a, b), not %r" % (what, range_))
    return range_


def scan_range(core, range_, what):
    """(name, a, b) of a scan's range, read as --scan is
    (qd_state_named_range: A and B constant expressions in the parameters);
    an error shown in its text."""
    text = _range_arg(range_, what).encode()
    name = ffi.new("char[]", 128)
    a, b = new("double"), new("double")
    if lib.qd_state_named_range(core.ctx, ffi.NULL, text, name, 128, a, b) != lib.QD_OK:
        raise located(core, "scan", text)
    return name, a[0], b[0]


def scan(core, range_, about, steps):
    """`qdot modes --scan NAME=A:B` (qd_modes_scan_text): an Output of the
    scan's JSON."""
    range_ = _range_arg(range_, "modes")
    if steps is not None and (isinstance(steps, bool) or not isinstance(steps, int) or
                              not 1 <= steps <= 100000):
        raise ValueError("modes: steps is a number of steps from 1 to 100000, not %r" % (steps,))
    p = Point(core)
    texts = {"scan": _commands.text_arg(range_, "scan"),
             "about": _commands.text_arg(_point_text(about, "about"), "about")}
    where = ffi.new("const char **")
    try:
        if p.e.ncon:
            raise ValueError("modes: scan: not yet on the constraint manifold of a model that "
                             "keeps constraints with multipliers")
        return _commands.output(core, "modes", lambda buf: _scanned(core, p, texts, steps or 0,
                                                                     where, buf))
    finally:
        p.free()


def _scanned(core, p, texts, steps, where, buf):
    about = texts["about"] if texts["about"] is not None else ffi.NULL
    st = lib.qd_modes_scan_text(core.ctx, p.pt, texts["scan"], about, steps, True, buf, where)
    if st != lib.QD_OK and where[0] != ffi.NULL:
        which = "scan" if where[0] == texts["scan"] else "about"
        lib.qd_buf_free(buf)
        raise located(core, which, ffi.string(texts[which]))
    if st != lib.QD_OK:
        lib.qd_buf_free(buf)
        raise core.error(st, cls=ArgumentError if st == lib.QD_ERR_ARG else NumericalError)
    return st


def modes(core, about=None, at_equilibrium=None, initial=None, symmetry=False,
          independent=None, scan_=None, steps=None):
    """The modes about the point `qdot modes` takes (a Modes); with scan_
    the scan's Output."""
    from .model import Mode, Modes
    if scan_ is not None:
        if at_equilibrium is not None or initial is not None or symmetry or independent:
            raise ValueError("modes: scan follows the point given with about (or the "
                             "equilibrium chosen at the start of the range): give neither "
                             "at_equilibrium, initial, symmetry nor independent")
        if lib.qd_model_nspeeds(core.model):
            return speeds_modes(core, about, scan_, steps)
        return scan(core, scan_, about, steps)
    if steps is not None:
        raise ValueError("modes: steps is the number of steps of scan: give scan=\"NAME=A:B\"")
    if about is not None and at_equilibrium is not None:
        raise ValueError("modes: give either about or at_equilibrium, not both")
    if at_equilibrium is not None and (isinstance(at_equilibrium, bool) or
                                       not isinstance(at_equilibrium, int) or at_equilibrium < 1):
        raise ValueError("modes: at_equilibrium is a number from 1, as equilibria() lists "
                         "them, not %r" % (at_equilibrium,))
    if lib.qd_model_nspeeds(core.model):
        _refuse("modes", at_equilibrium=at_equilibrium, initial=initial, symmetry=symmetry,
                independent=independent)
        return speeds_modes(core, about)
    p = Point(core)
    if p.e.ncon and (initial is not None or symmetry):
        p.free()
        raise ValueError("modes: %s: not yet on the constraint manifold of a model that keeps "
                         "constraints with multipliers" % ("symmetry" if symmetry else "initial"))
    if not p.e.ncon and independent is not None:
        p.free()
        raise ValueError("modes: independent: the model keeps no constraints")
    at, sym, cyc = new("qd_modes_at"), new("qd_symmetry"), new("qd_cyclic_modes")
    try:
        _choose(core, p, about, at_equilibrium or 0, at)
        if p.e.ncon:
            return _constrained(core, p, at, independent)
        lib.qd_linpoint_set(p.pt, at.q0, ffi.NULL)
        st_ = p.pt.st
        core.check(lib.qd_modes_at_solve(core.ctx, p.e, core.model, st_.n, st_.syms, st_.vals,
                                         at), NumericalError)
        active = _symmetry(core, p, at, sym, cyc) if symmetry else False
        Q = Qd = ffi.NULL
        if initial is not None:
            Q, Qd = _initial(core, p, at, initial)
        choice = ffi.addressof(at.choice) if at.chosen else ffi.NULL
        rep = new("qd_modes_report", {
            "e": p.e, "q0": at.q0, "pt": at.pt, "choice": choice, "residual": at.residual,
            "lin": ffi.addressof(at.lin), "res": ffi.addressof(at.res),
            "w2exact": at.w2exact if at.have_exact else ffi.NULL,
            "w2exact_in_params": at.exact_in_params, "Q": Q, "Qd": Qd,
            "sym": sym if active and not cyc.n else ffi.NULL,
            "cyc": cyc if active and cyc.n else ffi.NULL})
        output = _commands.output(core, "modes", lambda buf: lib.qd_modes_print(
            core.ctx, rep, True, buf))
        note = new("qd_buf")
        if lib.qd_modes_rest_note(at.residual, note):
            warnings.warn("modes: " + buf_text(note), UserWarning, stacklevel=3)
        else:
            lib.qd_buf_free(note)
        res, names = at.res, p.names
        n = res.n
        eig = np.array([complex(res.eig_re[k], res.eig_im[k]) for k in range(res.neig)])
        shapes = []
        if res.conservative:
            shapes = [Mode(res.omega2[j], {names[i]: res.shapes[i * n + j] for i in range(n)})
                      for j in range(n)]
        out = Modes(shapes, {names[j]: at.q0[j] for j in range(n)}, bool(res.conservative),
                    eig, res.stable)
        out.output, out.residual = output, at.residual
        out.equilibrium = equilibrium(core, names, at.pt) if at.pt else None
        out.choice_note = _choice_note(p, at) if at.chosen else None
        return out
    finally:
        lib.qd_symmetry_free(sym)
        lib.qd_cyclic_modes_free(cyc)
        lib.qd_modes_at_free(at)
        p.free()


def _choice_note(p, at):
    """Which equilibrium the library took and that there are others, as
    `qdot modes` says it on stderr (qd_equilibrium_choice_note)."""
    buf = new("qd_buf")
    if lib.qd_equilibrium_choice_note(p.e, ffi.addressof(at.choice), buf) != lib.QD_OK:
        lib.qd_buf_free(buf)
        return None
    return buf_text(buf)


def _constrained(core, p, at, independent):
    """A model that keeps constraints: the modes on the constraint manifold
    about the point chosen (qd_constrained_at_solve over the independent
    coordinates named, or the library's; qd_constrained_modes_print)."""
    from .model import Mode, Modes
    e = p.e
    ix = ffi.NULL
    if independent is not None:
        if isinstance(independent, (list, tuple)):
            independent = ", ".join(independent)
        text = _commands.text_arg(independent, "independent")
        ix = ffi.new("size_t[]", e.n + 1)
        if lib.qd_constrained_indep_read(core.ctx, e, text, ix) != lib.QD_OK:
            raise located(core, "independent", ffi.string(text))
    lib.qd_linpoint_set(p.pt, at.q0, ffi.NULL)
    st_, ca = p.pt.st, new("qd_constrained_at")
    try:
        st = lib.qd_constrained_at_solve(core.ctx, e, core.model, st_.n, st_.syms, st_.vals, ix,
                                         False, ca)
        if st != lib.QD_OK:
            raise core.error(st, cls=ArgumentError if st in (lib.QD_ERR_ARG,
                                                             lib.QD_ERR_UNSUPPORTED) else None)
        c, res = ca.c, ca.res
        output = _commands.output(core, "modes", lambda buf: lib.qd_constrained_modes_print(
            core.ctx, e, ffi.addressof(ca.c), ffi.addressof(ca.res), True, buf))
        r = c.r
        names = [p.names[c.indep[i]] for i in range(r)]
        eig = np.array([complex(res.eig_re[k], res.eig_im[k]) for k in range(res.neig)])
        shapes = []
        if res.conservative:
            shapes = [Mode(res.omega2[j], {names[i]: res.shapes[i * r + j] for i in range(r)})
                      for j in range(r)]
        out = Modes(shapes, {p.names[j]: c.q[j] for j in range(e.n)}, bool(res.conservative),
                    eig, res.stable)
        out.output, out.residual = output, c.force_res
        out.equilibrium = equilibrium(core, p.names, at.pt) if at.pt else None
        out.choice_note = _choice_note(p, at) if at.chosen else None
        return out
    finally:
        lib.qd_constrained_at_free(ca)


def _speeds_scan(core, p, range_, about, steps):
    """`qdot modes --scan` of a model with speeds: an Output of the scan."""
    rtext, where = _commands.text_arg(range_, "scan"), ffi.new("const char **")

    def call(buf):
        st = lib.qd_speeds_modes_scan_text(core.ctx, p.se, p.st.n, p.st.syms, p.st.vals, rtext,
                                           about if about is not None else ffi.NULL, steps,
                                           True, buf, where)
        if st != lib.QD_OK:
            lib.qd_buf_free(buf)
            if where[0] != ffi.NULL:
                raise located(core, "scan", ffi.string(rtext))
            raise core.error(st, cls=ArgumentError if st == lib.QD_ERR_ARG else NumericalError)
        return st
    return _commands.output(core, "modes", call)
