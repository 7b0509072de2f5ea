#!/usr/bin/env python3
"""Cross-check qdot's equations of motion against SymPy's LagrangesMethod.

For each example that SymPy can express, and for the planar n-link pendulum
(n = 1..6, point masses m_i on rods l_i, all symbolic), this script builds the
Lagrangian itself with sympy.physics.mechanics (dynamicsymbols), independently
of the .qd file, and asks LagrangesMethod for the mass matrix and the forcing
(M q'' = f).  qdot prints its M and f with `qdot eom FILE --format json`
(strings in the model language's syntax); every entry of qdot - SymPy must
simplify to zero.  Rayleigh dissipation and applied forces enter SymPy through
its forcelist (a drag -k v on a point has D = k/2 |v|^2).

Usage: check_lagrange_sympy.py --build BUILD_DIR [--examples DIR] [--only a,b]
       check_lagrange_sympy.py --selftest   (SymPy's equations against the
       textbook formulas of tests/examples/check_examples.py; no qdot needed)
Prints "N passed, N failed"; exits 1 on any failure.
"""
import argparse
import json
import os
import random
import re
import subprocess
import sys
import tempfile
import time

import sympy
from sympy import (Abs, E, Function, Matrix, Pow, Rational, Symbol, cos, diff, expand,
                   expand_trig, numer, pi, reduced, simplify, sin, sqrt, symbols,
                   together)
from sympy.physics.mechanics import LagrangesMethod, Point, ReferenceFrame, dynamicsymbols

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
t = dynamicsymbols._t


class System:
    """A model in SymPy: coordinates as dynamicsymbols, parameters as symbols,
    point masses, T/V/U terms, and forces on points (for forcelist)."""

    def __init__(self, coords, params):
        self.names = coords.split()
        self.q = [dynamicsymbols(n) for n in self.names]
        self.p = symbols(params, seq=True)
        self.T = 0
        self.V = 0
        self.U = 0
        self.N = ReferenceFrame('N')
        self.forces = []

    def vel(self, r):
        return Matrix(r).diff(t)

    def particle(self, m, r):
        v = self.vel(r)
        self.T += m / 2 * v.dot(v)

    def point(self, r):
        """A mechanics Point moving with position r (2 or 3 components)."""
        r = list(r) + [0] * (3 - len(r))
        P = Point('P%d' % len(self.forces))
        N = self.N
        v = self.vel(r)
        P.set_vel(N, v[0] * N.x + v[1] * N.y + v[2] * N.z)
        return P

    def force(self, F, r):
        F = list(F) + [0] * (3 - len(F))
        N = self.N
        self.forces.append((self.point(r), F[0] * N.x + F[1] * N.y + F[2] * N.z))

    def drag(self, k, r):
        """Rayleigh's D = k/2 |r'|^2 is the force -k r' on the point."""
        self.force([-k * c for c in self.vel(r)], r)

    def lagrange(self):
        L = self.T - self.V - self.U
        if self.forces:
            lm = LagrangesMethod(L, self.q, forcelist=self.forces, frame=self.N)
        else:
            lm = LagrangesMethod(L, self.q)
        lm.form_lagranges_equations()
        return lm.mass_matrix, lm.forcing


MODELS = {}


def model(fn):
    MODELS[fn.__name__] = fn
    return fn


def polar(r, th):
    return [r * cos(th), r * sin(th)]


@model
def double_pendulum():
    # Goldstein ch. 1 Exercise 22 (reference G13)
    s = System('theta1 theta2', 'm1 m2 l1 l2 g')
    th1, th2 = s.q
    m1, m2, l1, l2, g = s.p
    r1 = [l1 * sin(th1), -l1 * cos(th1)]
    r2 = [r1[0] + l2 * sin(th2), r1[1] - l2 * cos(th2)]
    s.particle(m1, r1)
    s.particle(m2, r2)
    s.V = m1 * g * r1[1] + m2 * g * r2[1]
    return s


@model
def free_particle_spherical():
    # Desloge ch. 48 Ex. 1
    s = System('r theta phi', 'm')
    r, th, ph = s.q
    (m,) = s.p
    s.particle(m, [r * sin(th) * cos(ph), r * sin(th) * sin(ph), r * cos(th)])
    return s


@model
def atwood():
    # Goldstein sec. 1.6 example 2
    s = System('x', 'M1 M2 l g')
    (x,) = s.q
    M1, M2, l, g = s.p
    s.T = (M1 + M2) / 2 * x.diff(t)**2
    s.V = -M1 * g * x - M2 * g * (l - x)
    return s


@model
def compound_atwood():
    # Byerly Art. 8b (TC11): T = m/2 (8x'^2 + 3y'^2 - 2x'y'), V = -m g y
    s = System('x y', 'm g l1 l2')
    x, y = s.q
    m, g, l1, l2 = s.p
    xd, yd = x.diff(t), y.diff(t)
    s.T = m / 2 * (8 * xd**2 + 3 * yd**2 - 2 * xd * yd)
    s.V = -m * g * y
    return s


@model
def bead_rotating_wire():
    # Goldstein sec. 1.6 example 3
    s = System('r', 'm omega')
    (r,) = s.q
    m, w = s.p
    s.particle(m, polar(r, w * t))
    return s


@model
def bead_spinning_hoop():
    # Desloge ch. 50 Ex. 1: T = m/2 a^2 (th'^2 + w^2 sin^2 th), V = -m g a cos th
    s = System('theta', 'm a omega g')
    (th,) = s.q
    m, a, w, g = s.p
    s.T = m / 2 * a**2 * (th.diff(t)**2 + w**2 * sin(th)**2)
    s.V = -m * g * a * cos(th)
    return s


def _lorentz(gauge):
    s = System('x y z', 'm q Ex Ey Ez Bx By Bz k c w')
    x, y, z = s.q
    m, q, Ex, Ey, Ez, Bx, By, Bz, k, c, w = s.p
    r = Matrix([x, y, z])
    B = Matrix([Bx, By, Bz])
    phi = -Matrix([Ex, Ey, Ez]).dot(r)
    A = B.cross(r) / 2
    if gauge:
        psi = k * x * y * z * cos(w * t) + c * x**2 * t
        phi -= psi.diff(t)                      # partial: x, y, z held fixed
        phi = phi.subs({v.diff(t): 0 for v in s.q})
        A += Matrix([psi.diff(v) for v in s.q])
    s.particle(m, r)
    s.U = q * phi - q * A.dot(r.diff(t))
    return s


@model
def charged_particle_EB():
    # Goldstein eqs. 1.60-1.66: L = T - q phi + q A.v
    return _lorentz(False)


@model
def charged_particle_gauge():
    # Goldstein Derivation 9: A + grad psi, phi - dpsi/dt
    return _lorentz(True)


@model
def rotating_frame():
    # Byerly Art. 6 Ex. 2: T in rotating axes, V = mu/2 ((x - a)^2 + y^2)
    s = System('x y', 'm w mu a')
    x, y = s.q
    m, w, mu, a = s.p
    xd, yd = x.diff(t), y.diff(t)
    s.T = m / 2 * (xd**2 + yd**2 + w**2 * (x**2 + y**2) + 2 * w * (x * yd - y * xd))
    s.V = mu / 2 * ((x - a)**2 + y**2)
    return s


@model
def damped_pendulum():
    # Goldstein eqs. 1.67-1.70, drag -k v on the bob
    s = System('theta', 'm l g k')
    (th,) = s.q
    m, l, g, k = s.p
    r = [l * sin(th), -l * cos(th)]
    s.particle(m, r)
    s.V = m * g * r[1]
    s.drag(k, r)
    return s


@model
def spring_pendulum():
    # Goldstein Exercise 24
    s = System('r theta', 'm k l0 g')
    r, th = s.q
    m, k, l0, g = s.p
    s.T = m / 2 * (r.diff(t)**2 + r**2 * th.diff(t)**2)
    s.V = -m * g * r * cos(th) + k / 2 * (r - l0)**2
    return s


@model
def two_particles_interaction():
    # Goldstein eq. 1.36: V12 of the distance only
    s = System('x1 y1 x2 y2', 'm1 m2 k d g')
    x1, y1, x2, y2 = s.q
    m1, m2, k, d, g = s.p
    s.particle(m1, [x1, y1])
    s.particle(m2, [x2, y2])
    s.V = m1 * g * y1 + m2 * g * y2 + k / 2 * (sqrt((x1 - x2)**2 + (y1 - y2)**2) - d)**2
    return s


def _driven(P):
    s = System('theta', 'm a w b g')
    (th,) = s.q
    m, a, w, b, g = s.p
    P = P(a, w)
    bob = [P[0] + b * sin(th), P[1] - b * cos(th)]
    s.particle(m, bob)
    s.V = m * g * bob[1]
    return s


@model
def driven_pendulum_vertical():
    # Desloge ch. 54 P1 method, support (0, a cos wt)
    return _driven(lambda a, w: [0, a * cos(w * t)])


@model
def pendulum_support_circle():
    # Desloge ch. 54 P1 (T39)
    return _driven(lambda a, w: [a * cos(w * t), a * sin(w * t)])


@model
def total_derivative_potential():
    # Desloge ch. 54 P7: U = d/dt(-c/2 r.r - b x^2 y sin wt)
    s = System('x y', 'm K c b w')
    x, y = s.q
    m, K, c, b, w = s.p
    s.particle(m, [x, y])
    s.V = K / 2 * (x**2 + y**2)
    s.U = (-c / 2 * (x**2 + y**2) - b * x**2 * y * sin(w * t)).diff(t)
    return s


@model
def cylindrical_force():
    # Desloge ch. 48 P1 (T05), constant force at the particle
    s = System('rho ph z', 'm Fx Fy Fz')
    rho, ph, z = s.q
    m, Fx, Fy, Fz = s.p
    r = [rho * cos(ph), rho * sin(ph), z]
    s.particle(m, r)
    s.force([Fx, Fy, Fz], r)
    return s


@model
def polar_generalized_force():
    # Goldstein sec. 1.6 example 1(b): the force Fr e_r + Fth e_th at the particle
    s = System('r theta', 'm Fr Fth')
    r, th = s.q
    m, Fr, Fth = s.p
    pos = polar(r, th)
    s.particle(m, pos)
    s.force([Fr * cos(th) - Fth * sin(th), Fr * sin(th) + Fth * cos(th)], pos)
    return s


@model
def paraboloid():
    # Desloge ch. 72 P2, z = c rho^2
    s = System('rho ph', 'm c g')
    rho, ph = s.q
    m, c, g = s.p
    s.particle(m, [rho * cos(ph), rho * sin(ph), c * rho**2])
    s.V = m * g * c * rho**2
    return s


@model
def spherical_pendulum():
    # Byerly Art. 5 Ex. 3
    s = System('theta phi', 'm a g')
    th, ph = s.q
    m, a, g = s.p
    s.T = m * a**2 / 2 * (th.diff(t)**2 + sin(th)**2 * ph.diff(t)**2)
    s.V = -m * g * a * cos(th)
    return s


@model
def kepler_polar():
    # Desloge ch. 58
    s = System('r theta', 'm k')
    r, th = s.q
    m, k = s.p
    s.T = m / 2 * (r.diff(t)**2 + r**2 * th.diff(t)**2)
    s.V = -k / r
    return s


@model
def table_hanging_mass():
    # Goldstein Exercise 21
    s = System('r theta', 'm1 m2 l g')
    r, th = s.q
    m1, m2, l, g = s.p
    s.T = (m1 + m2) / 2 * r.diff(t)**2 + m1 / 2 * r**2 * th.diff(t)**2
    s.V = -m2 * g * (l - r)
    return s


@model
def sphere_on_wedge():
    # Byerly Art. 9 Ex. 3 (TC19)
    s = System('x y', 'M m a kg alpha g')
    x, y = s.q
    M, m, a, kg, al, g = s.p
    xd, yd = x.diff(t), y.diff(t)
    s.T = (M + m) / 2 * xd**2 + m / 2 * (1 + kg**2 / a**2) * yd**2 - m * xd * yd * cos(al)
    s.V = -m * g * y * sin(al)
    return s


@model
def spring_supported_pendulum():
    # Desloge ch. 53 P2 (T37), drag -c v on the bob
    s = System('y theta', 'm b k c g')
    y, th = s.q
    m, b, k, c, g = s.p
    bob = [b * sin(th), -y - b * cos(th)]
    s.particle(m, bob)
    s.V = m * g * bob[1] + k / 2 * y**2 + m * g * y     # k/2 (y + m g/k)^2 + const
    s.drag(c, bob)
    return s


@model
def double_pendulum_force():
    # Goldstein Exercise 22 with Desloge ch. 50 P1: horizontal F at C
    s = System('theta1 theta2', 'm1 m2 l1 l2 g F')
    th1, th2 = s.q
    m1, m2, l1, l2, g, F = s.p
    r1 = [l1 * sin(th1), -l1 * cos(th1)]
    r2 = [r1[0] + l2 * sin(th2), r1[1] - l2 * cos(th2)]
    s.particle(m1, r1)
    s.particle(m2, r2)
    s.V = m1 * g * r1[1] + m2 * g * r2[1]
    s.force([F, 0], r2)
    return s


@model
def tethered_spinning_disk():
    # Desloge ch. 50 P5 (T17)
    s = System('theta', 'm a b w')
    (th,) = s.q
    m, a, b, w = s.p
    s.particle(m, [b * cos(w * t) + a * cos(w * t + th), b * sin(w * t) + a * sin(w * t + th)])
    return s


@model
def bead_helix():
    # Desloge ch. 51 Ex. 1 (T15), z up
    s = System('ph', 'm a b g')
    (ph,) = s.q
    m, a, b, g = s.p
    s.T = m / 2 * (a**2 + b**2) * ph.diff(t)**2
    s.V = m * g * b * ph
    return s


def nlink(n):
    """The planar n-link pendulum: .qd text and the SymPy system."""
    th = ['theta%d' % i for i in range(1, n + 1)]
    ms = ['m%d' % i for i in range(1, n + 1)]
    ls = ['l%d' % i for i in range(1, n + 1)]
    lines = ['# planar %d-link pendulum (generated by check_lagrange_sympy.py)' % n,
             'coordinates ' + ', '.join(th),
             'parameters ' + ', '.join('%s = 1' % p for p in ms + ls) + ', g = 9.81',
             'x0 = 0', 'y0 = 0']
    for i in range(1, n + 1):
        lines.append('x%d = x%d + l%d*sin(theta%d)' % (i, i - 1, i, i))
        lines.append('y%d = y%d - l%d*cos(theta%d)' % (i, i - 1, i, i))
    lines.append('T = ' + ' + '.join("m%d/2*(x%d'^2 + y%d'^2)" % (i, i, i) for i in range(1, n + 1)))
    lines.append('V = ' + ' + '.join('m%d*g*y%d' % (i, i) for i in range(1, n + 1)))
    s = System(' '.join(th), ' '.join(ms + ls + ['g']))
    g = s.p[-1]
    x = y = 0
    for i in range(n):
        x = x + s.p[n + i] * sin(s.q[i])
        y = y - s.p[n + i] * cos(s.q[i])
        s.particle(s.p[i], [x, y])
        s.V += s.p[i] * g * y
    return '\n'.join(lines) + '\n', s


# ---------------------------------------------------------------------------
# Reading qdot's strings and deciding that a difference is zero.

FUNCS = {'sin': sympy.sin, 'cos': sympy.cos, 'tan': sympy.tan, 'exp': sympy.exp,
         'log': sympy.log, 'sqrt': sympy.sqrt, 'sinh': sympy.sinh, 'cosh': sympy.cosh,
         'tanh': sympy.tanh, 'asin': sympy.asin, 'acos': sympy.acos, 'atan': sympy.atan,
         'atan2': sympy.atan2, 'abs': Abs, 'sign': sympy.sign, 'pi': pi, 'e': E}


def reader(s):
    ns = dict(FUNCS)
    ns['t'] = t
    for name, q in zip(s.names, s.q):
        ns[name] = q
        ns['_D_' + name] = q.diff(t)
        ns['_DD_' + name] = q.diff(t, 2)
    for p in s.p:
        ns[p.name] = p

    def read(text):
        text = re.sub(r"([A-Za-z_]\w*)''", r'_DD_\1', text)
        text = re.sub(r"([A-Za-z_]\w*)'", r'_D_\1', text)
        return sympy.parse_expr(text.replace('^', '**'), local_dict=dict(ns))
    return read


def normalize(e, s):
    """Plain symbols for q and q'; expanded bases under fractional powers."""
    rep = {}
    for name, q in zip(s.names, s.q):
        rep[q.diff(t)] = Symbol('_v_' + name)
    e = e.subs(rep)
    e = e.subs({q: Symbol('_q_' + n) for n, q in zip(s.names, s.q)})
    e = e.replace(lambda x: x.is_Pow and not x.exp.is_Integer,
                  lambda x: Pow(expand(x.base), x.exp))
    return e.replace(sympy.tan, lambda x: sin(x) / cos(x))


def is_zero(d):
    if d == 0 or expand(d) == 0:
        return True
    d = expand(expand_trig(d))
    if d == 0:
        return True
    num = expand(numer(together(d)))
    if num == 0:
        return True
    # Polynomial in sin and cos of each argument: reduce modulo s^2 + c^2 - 1.
    args = sorted({a.args[0] for a in num.atoms(sin, cos)}, key=sympy.default_sort_key)
    if args:
        S = [Symbol('_s%d' % i) for i in range(len(args))]
        C = [Symbol('_c%d' % i) for i in range(len(args))]
        rep = {}
        for a, si, ci in zip(args, S, C):
            rep[sin(a)] = si
            rep[cos(a)] = ci
        poly = num.xreplace(rep)
        try:
            _, rem = reduced(poly, [si**2 + ci**2 - 1 for si, ci in zip(S, C)], *(S + C))
            if expand(rem) == 0:
                return True
        except sympy.PolynomialError:
            pass
    return simplify(d) == 0


def numerically_zero(d, rng):
    vals = {x: rng.uniform(0.3, 1.3) for x in sorted(d.free_symbols, key=str)}
    try:
        return abs(complex(d.subs(vals).evalf())) < 1e-9
    except (TypeError, ValueError):
        return False


# ---------------------------------------------------------------------------

def qdot_eom(build, path):
    cmd = [os.path.join(build, 'qdot'), 'eom', path, '--format', 'json']
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    if proc.returncode != 0:
        raise RuntimeError('%s: exit %d: %s' % (' '.join(cmd), proc.returncode,
                                               proc.stderr.strip()[:400]))
    return json.loads(proc.stdout)


def flat(m):
    out = []
    for x in m:
        out.extend(flat(x) if isinstance(x, list) else [x])
    return out


def compare(name, build, path, s, rng):
    """Failures (a list of strings) of qdot's M, f against SymPy's."""
    data = qdot_eom(build, path)
    if data.get('coordinates') != s.names:
        return ['%s: coordinates %r, expected %r' % (name, data.get('coordinates'), s.names)]
    M, f = s.lagrange()
    n = len(s.q)
    read = reader(s)
    qM = [read(x) for x in flat(data['mass_matrix'])]
    qf = [read(x) for x in data['forcing']]
    errs = []
    pairs = [('M[%d][%d]' % (i, j), qM[i * n + j], M[i, j]) for i in range(n) for j in range(n)]
    pairs += [('f[%d]' % i, qf[i], f[i]) for i in range(n)]
    for what, a, b in pairs:
        d = normalize(a, s) - normalize(b, s)
        if not is_zero(d):
            how = 'numerically nonzero' if not numerically_zero(d, rng) else 'did not simplify'
            errs.append('%s %s: qdot %s, SymPy %s (%s)' % (name, what, a, b, how))
    return errs


def selftest():
    """SymPy's accelerations against check_examples.py's textbook formulas."""
    sys.path.insert(0, os.path.join(ROOT, 'tests', 'examples'))
    import check_examples as ce
    rng = random.Random(7)
    passed = failed = 0
    for name, make in MODELS.items():
        s = make()
        spec = ce.EXAMPLES[name]
        params = ce.read_parameters(os.path.join(ROOT, 'examples', name + '.qd'))
        M, f = s.lagrange()
        for _ in range(3):
            q = {c: rng.uniform(*spec['ranges'].get(c, (-1.5, 1.5))) for c in spec['coords']}
            v = {c: rng.uniform(-1.5, 1.5) for c in spec['coords']}
            tt = rng.uniform(0, 3)
            sub = {Symbol(k): x for k, x in params.items()}
            for c, qq in zip(s.names, s.q):
                sub[qq.diff(t)] = v[c]
            sub2 = {qq: q[c] for c, qq in zip(s.names, s.q)}
            Mn = M.subs(sub).subs(sub2).subs(t, tt).evalf()
            fn = f.subs(sub).subs(sub2).subs(t, tt).evalf()
            got = ce.solve(Mn.tolist(), list(fn))
            want = spec['acc'](q, v, tt, params)
            if ce.close(got, want):
                passed += 1
            else:
                failed += 1
                print('FAIL %s: SymPy %r, textbook %r' % (name, got, want))
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build')
    ap.add_argument('--examples', default=os.path.join(ROOT, 'examples'))
    ap.add_argument('--only', help='comma-separated names (examples, or nlinkN)')
    ap.add_argument('--max-links', type=int, default=6)
    ap.add_argument('--selftest', action='store_true')
    args = ap.parse_args()
    if args.selftest:
        return selftest()
    if not args.build:
        ap.error('--build is required')
    rng = random.Random(11)
    cases = [(name, os.path.join(args.examples, name + '.qd'), make)
             for name, make in MODELS.items()]
    tmp = tempfile.TemporaryDirectory()
    for n in range(1, args.max_links + 1):
        text, s = nlink(n)
        path = os.path.join(tmp.name, 'nlink%d.qd' % n)
        with open(path, 'w') as fh:
            fh.write(text)
        cases.append(('nlink%d' % n, path, (lambda s=s: s)))
    if args.only:
        keep = args.only.split(',')
        cases = [c for c in cases if c[0] in keep]
    passed = failed = 0
    for name, path, make in cases:
        start = time.time()
        try:
            errs = compare(name, args.build, path, make(), rng)
        except Exception as exc:
            errs = ['%s: %s: %s' % (name, type(exc).__name__, exc)]
        for e in errs:
            print('FAIL ' + e)
        if errs:
            failed += 1
        else:
            passed += 1
        print('%-28s %s (%.1f s)' % (name, 'ok' if not errs else 'FAILED', time.time() - start))
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
