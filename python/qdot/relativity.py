# python/qdot/relativity.py - special relativity's toolkit (qdot/relativity.h,
# Desloge vol. 2 ch. 86-91): qdot.lorentz, qdot.proper_time, qdot.collide.
#
# The results are objects whose attributes are the keys of the JSON of
# `qdot lorentz` and `qdot collide` (docs/cli.md); every number comes from
# the C library.  The prototypes are declared here, beside their only user.
"""Lorentz transformations and relativistic collisions (internal module)."""

from ctypes import POINTER, Structure, byref, c_bool, c_double, c_int, c_size_t, c_uint, c_void_p

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


class _LorentzIn(Structure):
    """qd_lorentz_in: the parts asked (QD_LORENTZ_ bits) and their inputs."""
    _fields_ = [("ask", c_uint), ("c", c_double), ("frame", c_double * 3),
                ("event", c_double * 4), ("velocity", c_double * 3),
                ("acceleration", c_double * 3), ("energy", c_double), ("momentum", c_double * 3),
                ("compose", c_double * 3), ("dilate", c_double), ("contract", c_double * 3),
                ("worldline", c_void_p * 3), ("t0", c_double), ("t1", c_double)]


class _LorentzOut(Structure):
    _fields_ = [("gamma", c_double), ("boost", c_double * 16), ("metric_error", c_double),
                ("event", c_double * 4), ("velocity", c_double * 3),
                ("particle_gamma", c_double), ("acceleration", c_double * 3),
                ("energy", c_double), ("momentum", c_double * 3), ("invariant_mass", c_double),
                ("composed", c_double * 3), ("composed_reverse", c_double * 3),
                ("wigner_angle", c_double), ("dilated", c_double), ("contracted", c_double * 3),
                ("tau", _Tau)]


# QD_LORENTZ_FRAME .. QD_LORENTZ_CONTRACT (relativity.h), in this order
_PARTS = ["frame", "event", "velocity", "acceleration", "momentum", "compose", "dilate",
          "contract"]
_COLLIDE_MAX, _PRODUCTS = 64, 16
_NONE, _ELASTIC, _DECAY = 0, 1, 2  # qd_collide_final


class _CollideIn(Structure):
    _fields_ = [("c", c_double), ("n", c_size_t), ("particle", Particle * _COLLIDE_MAX),
                ("merge", c_bool), ("final", c_int), ("lab", c_bool), ("lab_angle", c_double),
                ("cm_angle", c_double), ("azimuth", c_double), ("nproducts", c_size_t),
                ("product", c_double * _PRODUCTS), ("threshold", c_bool)]


class _CollideOut(Structure):
    _fields_ = [("total", Particle), ("nfinal", c_size_t), ("cm_angle", c_double * 2),
                ("lab_angles", (c_double * 2) * 2), ("final", (Particle * 2) * 2),
                ("conservation_error", c_double), ("pstar", c_double),
                ("products_mass", c_double), ("threshold", _Threshold), ("allowed", c_bool)]


_V = POINTER(c_double)
_PROTOS = {
    "qd_lorentz_run": [c_void_p, POINTER(_LorentzIn), POINTER(_LorentzOut)],
    "qd_collide_run": [c_void_p, POINTER(_CollideIn), POINTER(_CollideOut)],
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


def _set(arr, x, n, what):
    arr[:] = list(_vec(x, n, what))


def lorentz(frame, c=1.0, event=None, velocity=None, acceleration=None, momentum=None,
            compose=None, dilate=None, contract=None):
    """The Lorentz transformation to the frame moving with `frame` (a
    3-vector), as `qdot lorentz` (qd_lorentz_run): event (t, x, y, z),
    velocity, acceleration (with velocity), momentum (E, px, py, pz) or
    {"m": M, "v": (...)}; velocity composition, time dilation, contraction
    of a displacement."""
    given = dict(frame=frame, event=event, velocity=velocity, acceleration=acceleration,
                 momentum=momentum, compose=compose, dilate=dilate, contract=contract)
    a, o = _LorentzIn(c=float(c)), _LorentzOut()
    with _Ctx() as ctx:
        for bit, name in enumerate(_PARTS):
            x = given[name]
            if x is None:
                continue
            a.ask |= 1 << bit
            if name == "dilate":
                a.dilate = float(x)
            elif name == "momentum" and isinstance(x, dict):
                p = _particle(ctx, c, x)
                a.energy, a.momentum[:] = p.E, list(p.p)
            elif name == "momentum":
                m4 = _list(x)
                if len(m4) != 4:
                    raise Error("momentum needs (E, px, py, pz) or {'m': M, 'v': (...)}")
                a.energy, a.momentum[:] = m4[0], m4[1:]
            else:
                _set(getattr(a, name), x, 4 if name == "event" else 3, name)
        ctx(lib.qd_lorentz_run(ctx.ctx, byref(a), byref(o)))
    r = Result()
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
    sum, as `qdot collide` (qd_collide_run): invariant_mass, velocity (the
    centre of momentum's, which a perfectly inelastic merge keeps), merged;
    final (elastic: lab `angle` of particle 1, or `cm_angle`), threshold
    (the products' masses on particle 2 at rest), decay (two masses)."""
    a, o = _CollideIn(c=float(c), merge=bool(merge)), _CollideOut()
    masses = _list(threshold if threshold is not None else decay if decay is not None else [])
    if len(particles) > _COLLIDE_MAX or len(masses) > _PRODUCTS:
        raise Error("collide takes at most %d particles and %d products" % (_COLLIDE_MAX,
                                                                            _PRODUCTS))
    with _Ctx() as ctx:
        ps = [_particle(ctx, c, s) for s in particles]
        a.n = len(ps)
        for k, p in enumerate(ps):
            a.particle[k] = p
        a.final = _ELASTIC if elastic else _DECAY if decay is not None else _NONE
        a.lab, a.lab_angle = angle is not None, float(angle or 0)
        a.cm_angle, a.azimuth = float(cm_angle or 0), float(azimuth)
        a.threshold, a.nproducts = threshold is not None, len(masses)
        a.product[:len(masses)] = masses
        ctx(lib.qd_collide_run(ctx.ctx, byref(a), byref(o)))
    tot = o.total
    r = Result()
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
