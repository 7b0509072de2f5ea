# python/qdot/relativity.py - special relativity's toolkit (qdot/relativity.h,
# Desloge vol. 2 ch. 86-91): qdot.lorentz, qdot.proper_time, qdot.collide.
#
# The results are objects whose attributes are the keys of the JSON of
# `qdot lorentz` and `qdot collide` (docs/cli.md); every number comes from
# the C library; the structs and prototypes are those of the header.
"""Lorentz transformations and relativistic collisions (internal module)."""

import numpy as np

from ._core import Error, take_error
from ._lib import ffi, lib, new, exprs, buf_text

# the parts qd_lorentz_in.ask names, each by its bit QD_LORENTZ_FRAME ... (relativity.h)
_PARTS = ["frame", "event", "velocity", "acceleration", "momentum", "compose", "dilate",
          "contract"]
_COLLIDE_MAX, _PRODUCTS = lib.QD_COLLIDE_MAX, lib.QD_COLLIDE_PRODUCTS
_NONE, _ELASTIC, _DECAY = lib.QD_COLLIDE_NONE, lib.QD_COLLIDE_ELASTIC, lib.QD_COLLIDE_DECAY


class _Ctx:
    """A context for one call; its error becomes an Error."""

    def __init__(self):
        self.ctx = lib.qd_ctx_new()
        if not self.ctx:
            raise MemoryError("qdot: out of memory")

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        lib.qd_ctx_free(self.ctx)

    def __call__(self, status):
        if status != 0:
            # the record held in a name: a field of a temporary cdata does
            # not keep its owner alive (cffi frees it under the field's view)
            diag = take_error(self.ctx)
            raise Error(ffi.string(diag.message).decode(), status)


def _rendered(ctx, call):
    """The JSON call(buf) writes, as a dict (the context's error raised)."""
    import json
    buf = new("qd_buf")
    st = call(buf)
    text = buf_text(buf)
    ctx(st)
    return json.loads(text)


def _vec(x, n=3, what="vector"):
    x = [float(v) for v in x]
    if len(x) != n:
        raise Error("%s needs %d numbers, not %d" % (what, n, len(x)))
    return ffi.new("double[]", x)


def _list(a):
    return [float(v) for v in a]


class Result:
    """Attributes named as the JSON keys of `qdot lorentz` / `qdot collide`."""

    def __repr__(self):
        return "%s(%s)" % (type(self).__name__, ", ".join(
            "%s=%r" % kv for kv in sorted(vars(self).items())))

    def _repr_html_(self):
        from . import display
        data = vars(self).get("json") or dict(sorted(vars(self).items()))  # the command's JSON
        return display.fields(data, "qdot " + type(self).__name__)


def _particle(ctx, c, spec):
    """(m, v), {"m": .., "v": ..} or a Particle into a Particle."""
    if isinstance(spec, dict):
        m, v = spec["m"], spec.get("v", (0, 0, 0))
    else:
        m, v = spec
    p = new("qd_rel_particle")
    ctx(lib.qd_rel_particle_make(ctx.ctx, c, float(m), _vec(v, 3, "v"), p))
    return p


def _pdict(p):
    r = Result()
    r.mass, r.velocity, r.energy, r.momentum = p.m, _list(p.v), p.E, _list(p.p)
    return r


def _set(arr, x, n, what):
    arr[0:n] = list(_vec(x, n, what))


def lorentz(frame, c=1.0, event=None, velocity=None, acceleration=None, momentum=None,
            compose=None, dilate=None, contract=None):
    """The Lorentz transformation to the frame moving with `frame` (a
    3-vector), as `qdot lorentz` (qd_lorentz_run): event (t, x, y, z),
    velocity, acceleration (with velocity), momentum (E, px, py, pz) or
    {"m": M, "v": (...)}; velocity composition, time dilation, contraction
    of a displacement."""
    given = dict(frame=frame, event=event, velocity=velocity, acceleration=acceleration,
                 momentum=momentum, compose=compose, dilate=dilate, contract=contract)
    a, o = new("qd_lorentz_in", {"c": float(c)}), new("qd_lorentz_out")
    with _Ctx() as ctx:
        for name in _PARTS:
            x = given[name]
            if x is None:
                continue
            a.ask |= getattr(lib, "QD_LORENTZ_" + name.upper())
            if name == "dilate":
                a.dilate = float(x)
            elif name == "momentum" and isinstance(x, dict):
                p = _particle(ctx, c, x)
                a.energy, a.momentum[0:3] = p.E, list(p.p)
            elif name == "momentum":
                m4 = _list(x)
                if len(m4) != 4:
                    raise Error("momentum needs (E, px, py, pz) or {'m': M, 'v': (...)}")
                a.energy, a.momentum[0:3] = m4[0], m4[1:]
            else:
                _set(getattr(a, name), x, 4 if name == "event" else 3, name)
        ctx(lib.qd_lorentz_run(ctx.ctx, a, o))
        data = _rendered(ctx, lambda buf: lib.qd_lorentz_render(ctx.ctx, a, o, True, buf))
    r = Result()
    r.json = data  # what `qdot lorentz ... --format json` prints
    r.c, r.frame, r.gamma = float(c), _list(a.frame), o.gamma
    r.boost = np.array(_list(o.boost)).reshape(4, 4)
    r.metric_error = o.metric_error
    keys = {"event": ["event"], "velocity": ["velocity", "particle_gamma"],
            "acceleration": ["acceleration"], "momentum": ["energy", "momentum", "invariant_mass"],
            "compose": ["composed", "composed_reverse", "wigner_angle"], "dilate": ["dilated"],
            "contract": ["contracted"]}
    for name, ks in keys.items():
        for k in ks if given[name] is not None else []:
            v = getattr(o, k)
            setattr(r, k, v if isinstance(v, float) else _list(v))
    return r


def proper_time(v, t0, t1, c=1.0):
    """Proper time along the worldline of velocity v(t): three expressions
    in t (text in the model language, or numbers); a Result with
    proper_time, proper_time_error and max_speed."""
    with _Ctx() as ctx:
        xs = []
        for k, text in enumerate(v):
            diag = new("qd_diag")
            opts = new("qd_read_opts", {"new_symbols": True})
            x = lib.qd_read(ctx.ctx, str(text).encode(), opts, diag)
            if not x:
                ctx(diag.status or 1)
            xs.append(x)
        if len(xs) != 3:
            raise Error("v needs three components")
        tau = new("qd_rel_tau")
        ctx(lib.qd_rel_proper_time(ctx.ctx, c, exprs(xs), float(t0), float(t1), 0.0, tau))
    r = Result()
    r.proper_time, r.proper_time_error, r.max_speed = tau.tau, tau.error, tau.vmax
    return r


def collide(particles, c=1.0, merge=False, elastic=False, angle=None, cm_angle=None,
            azimuth=0.0, threshold=None, decay=None):
    """Four-momenta of particles ((m, v) pairs or {"m":, "v":}) and their
    sum, as `qdot collide` (qd_collide_run): invariant_mass, velocity (the
    centre of momentum's, which a perfectly inelastic merge keeps), merged;
    final (elastic: lab `angle` of particle 1, or `cm_angle`), threshold
    (the products' masses on particle 2 at rest), decay (two masses)."""
    a, o = new("qd_collide_in", {"c": float(c), "merge": bool(merge)}), new("qd_collide_out")
    masses = _list(threshold if threshold is not None else decay if decay is not None else [])
    if len(particles) > _COLLIDE_MAX or len(masses) > _PRODUCTS:
        raise Error("collide takes at most %d particles and %d products" % (_COLLIDE_MAX,
                                                                            _PRODUCTS))
    with _Ctx() as ctx:
        ps = [_particle(ctx, c, s) for s in particles]
        a.n = len(ps)
        for k, p in enumerate(ps):
            a.particle[k] = p[0]
        a.final = _ELASTIC if elastic else _DECAY if decay is not None else _NONE
        a.lab, a.lab_angle = angle is not None, float(angle or 0)
        a.cm_angle, a.azimuth = float(cm_angle or 0), float(azimuth)
        a.threshold, a.nproducts = threshold is not None, len(masses)
        a.product[0:len(masses)] = masses
        ctx(lib.qd_collide_run(ctx.ctx, a, o))
        data = _rendered(ctx, lambda buf: lib.qd_collide_render(ctx.ctx, a, o, True, buf))
    tot = o.total
    r = Result()
    r.json = data  # what `qdot collide ... --format json` prints
    r.c, r.particles = float(c), [_pdict(p) for p in ps]
    r.energy, r.momentum, r.invariant_mass, r.velocity = (tot.E, _list(tot.p), tot.m,
                                                          _list(tot.v))
    if merge:
        r.merged = _pdict(tot)
    if a.final != _NONE:
        r.final = []
        for k in range(o.nfinal):
            f = Result()
            f.cm_angle, f.particles = o.cm_angle[k], [_pdict(o.final[k][0]),
                                                      _pdict(o.final[k][1])]
            if elastic:
                f.lab_angles = _list(o.lab_angles[k])
            r.final.append(f)
        r.conservation_error = o.conservation_error
        if decay is not None:
            r.pstar = o.pstar
    if threshold is not None:
        r.threshold = Result()
        r.threshold.products_mass, r.threshold.kinetic_energy = o.products_mass, o.threshold.K
        r.threshold.energy, r.threshold.speed = o.threshold.E, o.threshold.speed
        r.threshold.allowed = o.allowed
    return r
