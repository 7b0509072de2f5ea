#!/usr/bin/python3
"""tests/cross/relativistic_sympy.py - `qdot hamiltonian` on Lagrangians not
quadratic in the velocities against SymPy's own Legendre transform.

SymPy forms p = dL/dv from the Lagrangian written here by hand and solves it
for v itself: exactly for the 1-D relativistic particle (then
H_qdot - H_sympy must simplify to 0, with m, c positive), and numerically
(mpmath's findroot, 30 digits) at random points for the rest; H = p.v - L,
dq/dt = v and dp/dt = dL/dq there must agree with qdot's --format sympy
output.  Cases: Desloge ch. 92-93 (seed-desloge-D.md C5, T19, T22, T23, T25):
the relativistic oscillator (examples/relativistic_particle_1d.qd), a charge
in uniform E and B fields (H = sqrt(m^2 c^4 + c^2 (p - e A)^2) + e phi), the
relativistic Kepler problem in polar coordinates; and L = x'^2/2 + x'^4/12
+ ..., whose H qdot keeps implicit (its H and equations hold q', which is
set to SymPy's root)."""
import os
import random
import subprocess
import sys
import tempfile

import mpmath
from sympy import (Matrix, Symbol, diff, lambdify, simplify, solve, sqrt, symbols,
                   sympify)

t = Symbol('t')
ROOT = __file__.rsplit('/tests/', 1)[0]
random.seed(4021)

FIELDS = """coordinates x, y, z
parameters m = 1.3, e = 0.8, c = 3, Ex = 0.5, Ey = -1.2, Ez = 0.3, Bx = 0.4, By = 0.7, Bz = 2
r = (x, y, z)
phi = -dot((Ex, Ey, Ez), r)
A = cross((Bx, By, Bz), r)/2
L = -m*c^2*sqrt(1 - dot(r', r')/c^2) - e*phi + e*dot(A, r')
"""
KEPLER = """coordinates r, theta
parameters m = 1, c = 1, k = 0.1
L = -m*c^2*sqrt(1 - (r'^2 + r^2*theta'^2)/c^2) + k/r
"""
QUARTIC = """coordinates x, y
parameters k = 1.3
L = x'^2/2 + x'^4/12 + y'^2/2 + x'*y'/3 - k*(x^2 + y^2)/2 + x*y'
"""


def case_fields():
    m, e, c = symbols('m e c')
    E = Matrix(symbols('Ex Ey Ez'))
    B = Matrix(symbols('Bx By Bz'))
    r = Matrix(symbols('x y z'))
    v = Matrix(symbols('xd yd zd'))
    L = -m * c**2 * sqrt(1 - v.dot(v) / c**2) + e * E.dot(r) + e * (B.cross(r) / 2).dot(v)
    return 'fields', FIELDS, list(r), list(v), L


def case_kepler():
    m, c, k, r, th, rd, thd = symbols('m c k r theta rd thetad')
    return 'kepler', KEPLER, [r, th], [rd, thd], \
        -m * c**2 * sqrt(1 - (rd**2 + r**2 * thd**2) / c**2) + k / r


def case_quartic():
    k, x, y, xd, yd = symbols('k x y xd yd')
    L = xd**2 / 2 + xd**4 / 12 + yd**2 / 2 + xd * yd / 3 - k * (x**2 + y**2) / 2 + x * yd
    return 'quartic', QUARTIC, [x, y], [xd, yd], L


def qdot_sympy(build, path):
    out = subprocess.run([build + '/qdot', 'hamiltonian', path, '--format', 'sympy'],
                         capture_output=True, text=True, check=True, cwd=ROOT).stdout
    ns = {}
    exec(out, ns)
    return ns


def plain(ns, q, qd, x):
    """qdot prints q as functions of t and q' as their derivatives."""
    x = sympify(x)
    x = x.subs({ns[s.name](t).diff(t): v for s, v in zip(q, qd)})
    return x.subs({ns[s.name](t): s for s in q})


def exact_1d(build):
    """The oscillator: SymPy solves p = dL/dv in closed form."""
    m, c = symbols('m c', positive=True)
    k, x, v, p = symbols('k x v p_x', real=True)
    L = -m * c**2 * sqrt(1 - v**2 / c**2) - k * x**2 / 2
    eq = diff(L, v) - p
    trial = {m: 1.3, c: 2, p: 0.7}  # solve() squares: keep the root of p = dL/dv itself
    roots = [r for r in solve(eq, v) if abs(float(eq.subs(v, r).subs(trial))) < 1e-12]
    if len(roots) != 1:
        return ['SymPy found %d roots' % len(roots)]
    H = simplify((p * v - L).subs(v, roots[0]))
    ns = qdot_sympy(build, ROOT + '/examples/relativistic_particle_1d.qd')
    sub = {Symbol('m'): m, Symbol('c'): c, Symbol('k'): k, Symbol('p_x'): p}
    got = plain(ns, [x], [v], ns['H']).subs(sub)
    bad = []
    if simplify(got - H) != 0:
        bad.append('H: %s != %s' % (got, H))
    if simplify(plain(ns, [x], [v], ns['dq_dt'][0]).subs(sub) - roots[0]) != 0:
        bad.append('dq_dt')
    return bad


def random_point(q, qd, L):
    """Parameters in [1, 2], coordinates in [0.5, 1.5], slow velocities."""
    pt = {s: random.uniform(0.5, 1.5) for s in q}
    for s in sorted(L.free_symbols - set(q) - set(qd), key=lambda s: s.name):
        pt[s] = random.uniform(1, 2)
    pt.update({s: random.uniform(-0.2, 0.2) for s in qd})
    return pt


def numeric_case(build, name, text, q, qd, L):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, name + '.qd')
        with open(path, 'w') as fh:
            fh.write(text)
        ns = qdot_sympy(build, path)
    p = [Symbol(str(s)) for s in ns['momenta']]
    pdef = [diff(L, v) for v in qd]
    conv = lambda x: plain(ns, q, qd, x)
    H = conv(ns['H'])
    dq = [conv(x) for x in ns['dq_dt']]
    dp = [conv(x) for x in ns['dp_dt']]
    bad = []
    for _ in range(8):
        pt = random_point(q, qd, L)
        pvals = [pd.subs(pt) for pd in pdef]  # the momenta of a known state
        guess = {s: pt[s] for s in qd}
        # SymPy's own inverse: solve p = dL/dv for v from v = 0 (not from the answer)
        fns = [lambdify(qd, (pd - pv).subs({s: pt[s] for s in pt if s not in qd}), 'mpmath')
               for pd, pv in zip(pdef, pvals)]
        with mpmath.workdps(30):
            root = mpmath.findroot(lambda *v: [f(*v) for f in fns], [0] * len(qd))
        root = [root] if len(qd) == 1 else list(root)
        v = {s: float(r) for s, r in zip(qd, root)}
        if any(abs(v[s] - guess[s]) > 1e-12 for s in qd):
            bad.append('SymPy root %r is not the state %r' % (v, guess))
            continue
        at = {s: pt[s] for s in pt if s not in qd}
        at.update(dict(zip(p, pvals)))
        at.update(v)  # an implicit H holds q': the root goes in
        want_H = float((sum(pj * vj for pj, vj in zip(pvals, root)) - L).subs(at))
        checks = [('H', H, want_H)]
        checks += [('dq_dt', a, v[s]) for a, s in zip(dq, qd)]
        checks += [('dp_dt', a, float(diff(L, s).subs(at))) for a, s in zip(dp, q)]
        for what, expr, want in checks:
            got = float(expr.subs(at))
            if abs(got - want) > 1e-10 * (1 + abs(want)):
                bad.append('%s: %.15g != %.15g' % (what, got, want))
    implicit = ns.get('implicit', False)
    if (name == 'quartic') != implicit:
        bad.append('implicit = %r' % implicit)
    return bad


def main():
    build = sys.argv[sys.argv.index('--build') + 1] if '--build' in sys.argv else ROOT + '/build'
    passed = failed = 0
    cases = [('oscillator (exact)', lambda: exact_1d(build))]
    for make in (case_fields, case_kepler, case_quartic):
        args = make()
        cases.append((args[0], lambda args=args: numeric_case(build, *args)))
    for name, run in cases:
        try:
            bad = run()
        except Exception as ex:  # a crash of qdot or of the printed Python
            bad = [repr(ex)]
        if bad:
            failed += 1
            print('FAIL %s: %s' % (name, '; '.join(bad[:4])))
        else:
            passed += 1
            print('ok   %s' % name, flush=True)
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
