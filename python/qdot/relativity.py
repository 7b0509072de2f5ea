# python/qdot/relativity.py - special relativity's toolkit (qdot/relativity.h,
# Desloge vol. 2 ch. 86-91): qdot.lorentz, qdot.proper_time, qdot.collide.
#
# The results are objects whose attributes are the keys of the JSON of
# `qdot lorentz` and `qdot collide` (docs/cli.md); every number comes from
# the C library.  The prototypes are declared here, beside their only user.
"""Lorentz transformations and relativistic collisions (internal module)."""

from ctypes import POINTER, Structure, byref, c_double, c_int, c_size_t, c_void_p
import math

import numpy as np

from ._core import Error, take_error
from ._lib import lib, Diag, ReadOpts, exprs

DBL = POINTER(c_double)


class Particle(Structure):
    """qd_rel_particle: rest mass, velocity, energy and momentum."""
    _fields_ = [("m", c_double), ("v", c_double * 3), ("E", c_double), ("p", c_double * 3)]


class _Threshold(Structure):
    _fields_ = [("E", c_double), ("K", c_double), ("speed", c_double)]


class _Tau(Structure):
    _fields_ = [("tau", c_double), ("error", c_double), ("vmax", c_double), ("evals", c_size_t)]


_V = POINTER(c_double)
_PROTOS = {
    "qd_rel_gamma": [c_void_p, c_double, _V, DBL],
    "qd_lorentz_event": [c_void_p, c_double, _V, _V, _V],
    "qd_lorentz_velocity": [c_void_p, c_double, _V, _V, _V],
    "qd_lorentz_acceleration": [c_void_p, c_double, _V, _V, _V, _V],
    "qd_lorentz_momentum": [c_void_p, c_double, _V, c_double, _V, DBL, _V],
    "qd_lorentz_boost": [c_void_p, c_double, _V, _V],
    "qd_rel_mass": [c_void_p, c_double, c_double, _V, DBL],
    "qd_rel_compose": [c_void_p, c_double, _V, _V, _V],
    "qd_rel_wigner_angle": [c_void_p, c_double, _V, _V, DBL],
    "qd_rel_dilate": [c_void_p, c_double, _V, c_double, DBL],
    "qd_rel_contract": [c_void_p, c_double, _V, _V, _V],
    "qd_rel_proper_time": [c_void_p, c_double, POINTER(c_void_p), c_double, c_double, c_double,
                           POINTER(_Tau)],
    "qd_rel_particle_make": [c_void_p, c_double, c_double, _V, POINTER(Particle)],
    "qd_rel_total": [c_void_p, c_double, c_size_t, POINTER(Particle), POINTER(Particle)],
    "qd_rel_elastic": [c_void_p, c_double, POINTER(Particle), c_double, c_double,
                       POINTER(Particle)],
    "qd_rel_elastic_lab": [c_void_p, c_double, POINTER(Particle), c_double, _V,
                           POINTER(c_size_t)],
    "qd_rel_threshold_of": [c_void_p, c_double, c_double, c_double, c_double,
                            POINTER(_Threshold)],
    "qd_rel_decay": [c_void_p, c_double, POINTER(Particle), c_double, c_double, c_double,
                     c_double, POINTER(Particle), DBL],
}
for _name, _args in _PROTOS.items():
    getattr(lib, _name).restype = c_int
    getattr(lib, _name).argtypes = _args
lib.qd_lorentz_metric_error.restype = c_double
lib.qd_lorentz_metric_error.argtypes = [_V]
lib.qd_rel_lab_angle.restype = c_double
lib.qd_rel_lab_angle.argtypes = [POINTER(Particle), POINTER(Particle), c_int]


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
            raise Error(take_error(self.ctx).message.decode(), status)


def _vec(x, n=3, what="vector"):
    x = [float(v) for v in x]
    if len(x) != n:
        raise Error("%s needs %d numbers, not %d" % (what, n, len(x)))
    return (c_double * n)(*x)


def _list(a):
    return [float(v) for v in a]


class Result:
    """Attributes named as the JSON keys of `qdot lorentz` / `qdot collide`."""

    def __repr__(self):
        return "%s(%s)" % (type(self).__name__, ", ".join(
            "%s=%r" % kv for kv in sorted(vars(self).items())))


def _particle(ctx, c, spec):
    """(m, v), {"m": .., "v": ..} or a Particle into a Particle."""
    if isinstance(spec, dict):
        m, v = spec["m"], spec.get("v", (0, 0, 0))
    else:
        m, v = spec
    p = Particle()
    ctx(lib.qd_rel_particle_make(ctx.ctx, c, float(m), _vec(v, 3, "v"), byref(p)))
    return p


def _pdict(p):
    r = Result()
    r.mass, r.velocity, r.energy, r.momentum = p.m, _list(p.v), p.E, _list(p.p)
    return r


def lorentz(frame, c=1.0, event=None, velocity=None, acceleration=None, momentum=None,
            compose=None, dilate=None, contract=None):
    """The Lorentz transformation to the frame moving with `frame` (a
    3-vector), as `qdot lorentz`: event (t, x, y, z), velocity, acceleration
    (with velocity), momentum (E, px, py, pz) or {"m": M, "v": (...)};
    velocity composition, time dilation, contraction of a displacement."""
    r = Result()
    with _Ctx() as ctx:
        V = _vec(frame, 3, "frame")
        O = (c_double * 16)()
        g = c_double()
        ctx(lib.qd_lorentz_boost(ctx.ctx, c, V, O))
        ctx(lib.qd_rel_gamma(ctx.ctx, c, V, byref(g)))
        r.c, r.frame, r.gamma = float(c), _list(V), g.value
        r.boost = np.array(_list(O)).reshape(4, 4)
        r.metric_error = lib.qd_lorentz_metric_error(O)
        out4, out3, x = (c_double * 4)(), (c_double * 3)(), c_double()
        if event is not None:
            ctx(lib.qd_lorentz_event(ctx.ctx, c, V, _vec(event, 4, "event"), out4))
            r.event = _list(out4)
        if acceleration is not None and velocity is None:
            raise Error("acceleration needs velocity")
        if velocity is not None:
            v = _vec(velocity, 3, "velocity")
            ctx(lib.qd_lorentz_velocity(ctx.ctx, c, V, v, out3))
            r.velocity = _list(out3)
            ctx(lib.qd_rel_gamma(ctx.ctx, c, out3, byref(x)))
            r.particle_gamma = x.value
            if acceleration is not None:
                ctx(lib.qd_lorentz_acceleration(ctx.ctx, c, V, v,
                                                _vec(acceleration, 3, "acceleration"), out3))
                r.acceleration = _list(out3)
        if momentum is not None:
            if isinstance(momentum, dict):
                p = _particle(ctx, c, momentum)
                E, pv = p.E, p.p
            else:
                m4 = _list(momentum)
                if len(m4) != 4:
                    raise Error("momentum needs (E, px, py, pz) or {'m': M, 'v': (...)}")
                E, pv = m4[0], _vec(m4[1:])
            ctx(lib.qd_lorentz_momentum(ctx.ctx, c, V, E, pv, byref(x), out3))
            r.energy, r.momentum = x.value, _list(out3)
            ctx(lib.qd_rel_mass(ctx.ctx, c, E, pv, byref(x)))
            r.invariant_mass = x.value
        if compose is not None:
            u = _vec(compose, 3, "compose")
            ctx(lib.qd_rel_compose(ctx.ctx, c, V, u, out3))
            r.composed = _list(out3)
            ctx(lib.qd_rel_compose(ctx.ctx, c, u, V, out3))
            r.composed_reverse = _list(out3)
            ctx(lib.qd_rel_wigner_angle(ctx.ctx, c, V, u, byref(x)))
            r.wigner_angle = x.value
        if dilate is not None:
            ctx(lib.qd_rel_dilate(ctx.ctx, c, V, float(dilate), byref(x)))
            r.dilated = x.value
        if contract is not None:
            ctx(lib.qd_rel_contract(ctx.ctx, c, V, _vec(contract, 3, "contract"), out3))
            r.contracted = _list(out3)
    return r


def proper_time(v, t0, t1, c=1.0):
    """Proper time along the worldline of velocity v(t): three expressions
    in t (text in the model language, or numbers); a Result with
    proper_time, proper_time_error and max_speed."""
    with _Ctx() as ctx:
        xs = []
        for k, text in enumerate(v):
            diag = Diag()
            x = lib.qd_read(ctx.ctx, str(text).encode(), byref(ReadOpts(new_symbols=True)),
                            byref(diag))
            if not x:
                ctx(diag.status or 1)
            xs.append(x)
        if len(xs) != 3:
            raise Error("v needs three components")
        tau = _Tau()
        ctx(lib.qd_rel_proper_time(ctx.ctx, c, exprs(xs), float(t0), float(t1), 0.0,
                                   byref(tau)))
    r = Result()
    r.proper_time, r.proper_time_error, r.max_speed = tau.tau, tau.error, tau.vmax
    return r


def collide(particles, c=1.0, merge=False, elastic=False, angle=None, cm_angle=None,
            azimuth=0.0, threshold=None, decay=None):
    """Four-momenta of particles ((m, v) pairs or {"m":, "v":}) and their
    sum, as `qdot collide`: invariant_mass, velocity (the centre of
    momentum's, which a perfectly inelastic merge keeps), merged; final
    (elastic: lab `angle` of particle 1, or `cm_angle`), threshold (the
    products' masses on particle 2 at rest), decay (two masses)."""
    r = Result()
    with _Ctx() as ctx:
        ps = [_particle(ctx, c, s) for s in particles]
        arr = (Particle * max(len(ps), 1))(*ps)
        tot = Particle()
        ctx(lib.qd_rel_total(ctx.ctx, c, len(ps), arr, byref(tot)))
        r.c, r.particles = float(c), [_pdict(p) for p in ps]
        r.energy, r.momentum, r.invariant_mass, r.velocity = (tot.E, _list(tot.p), tot.m,
                                                              _list(tot.v))
        if merge:
            r.merged = _pdict(tot)
        if elastic or decay is not None:
            if elastic and len(ps) != 2:
                raise Error("elastic needs exactly two particles")
            if decay is not None and len(ps) != 1:
                raise Error("decay needs exactly one particle")
            chis = [float(cm_angle or 0)]
            if elastic and angle is not None:
                ch, n = (c_double * 2)(), c_size_t()
                ctx(lib.qd_rel_elastic_lab(ctx.ctx, c, arr, float(angle), ch, byref(n)))
                chis = list(ch)[:n.value]
            r.final = []
            for chi in chis:
                out, f = (Particle * 2)(), Result()
                if elastic:
                    ctx(lib.qd_rel_elastic(ctx.ctx, c, arr, chi, 0.0 if angle is not None
                                           else float(azimuth), out))
                    f.lab_angles = [lib.qd_rel_lab_angle(arr, out, k) for k in (0, 1)]
                else:
                    ps_ = c_double()
                    ctx(lib.qd_rel_decay(ctx.ctx, c, arr, float(decay[0]), float(decay[1]),
                                         chi, float(azimuth), out, byref(ps_)))
                    r.pstar = ps_.value
                f.cm_angle, f.particles = chi, [_pdict(out[0]), _pdict(out[1])]
                r.final.append(f)
        if threshold is not None:
            if len(ps) != 2:
                raise Error("threshold needs exactly two particles (the second the target)")
            th, M = _Threshold(), math.fsum(float(x) for x in threshold)
            ctx(lib.qd_rel_threshold_of(ctx.ctx, c, ps[0].m, ps[1].m, M, byref(th)))
            r.threshold = Result()
            r.threshold.products_mass, r.threshold.kinetic_energy = M, th.K
            r.threshold.energy, r.threshold.speed = th.E, th.speed
            r.threshold.allowed = tot.m >= M
    return r
