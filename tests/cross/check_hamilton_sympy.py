#!/usr/bin/python3
"""Cross-check `qdot hamiltonian` against an independent Legendre transform
in SymPy.  Each Lagrangian is written here by hand from the example's
definitions; SymPy forms p = dL/dq', solves for q', builds H and Hamilton's
equations; qdot's H, dq_dt and dp_dt (its --format sympy output) must
simplify to the same expressions."""
import subprocess
import sys

from sympy import (Matrix, Symbol, sympify, cos, diff, simplify,
                   sin, symbols)

t = Symbol('t')


def case_double_pendulum():
    m1, m2, l1, l2, g = symbols('m1 m2 l1 l2 g')
    a, b = symbols('theta1 theta2')
    ad, bd = symbols('theta1d theta2d')
    x1, y1 = l1 * sin(a), -l1 * cos(a)
    x2, y2 = x1 + l2 * sin(b), y1 - l2 * cos(b)
    v = lambda x: diff(x, a) * ad + diff(x, b) * bd
    T = m1 / 2 * (v(x1)**2 + v(y1)**2) + m2 / 2 * (v(x2)**2 + v(y2)**2)
    V = m1 * g * y1 + m2 * g * y2
    return 'double_pendulum', [a, b], [ad, bd], T - V


def case_kepler():
    m, k, r, th, rd, thd = symbols('m k r theta rd thetad')
    return 'kepler_polar', [r, th], [rd, thd], m / 2 * (rd**2 + r**2 * thd**2) + k / r


def case_bead():
    m, w, r, rd = symbols('m omega r rd')
    x, y = r * cos(w * t), r * sin(w * t)
    v = lambda e: diff(e, r) * rd + diff(e, t)
    return 'bead_rotating_wire', [r], [rd], m / 2 * (v(x)**2 + v(y)**2)


def case_charged():
    m, q = symbols('m q')
    E = Matrix(symbols('Ex Ey Ez'))
    B = Matrix(symbols('Bx By Bz'))
    r = Matrix(symbols('x y z'))
    rd = Matrix(symbols('xd yd zd'))
    phi = -E.dot(r)
    A = B.cross(r) / 2
    L = m / 2 * rd.dot(rd) - q * phi + q * A.dot(rd)
    return 'charged_particle_EB', list(r), list(rd), L


def case_spherical():
    m, a, g, th, ph, thd, phd = symbols('m a g theta phi thetad phid')
    T = m * a**2 / 2 * (thd**2 + sin(th)**2 * phd**2)
    return 'spherical_pendulum', [th, ph], [thd, phd], T + m * g * a * cos(th)


def legendre(q, qd, L):
    p = [Symbol('p_' + s.name) for s in q]
    # p = M q' + b, L quadratic in q': solve the linear system directly
    pd = Matrix([diff(L, v) for v in qd])
    M = pd.jacobian(qd)
    b = pd.subs({v: 0 for v in qd})
    vel = M.LUsolve(Matrix(p) - b)
    H = (sum(pj * v for pj, v in zip(p, qd)) - L).subs(dict(zip(qd, vel)))
    return p, H, [diff(H, pj) for pj in p], [-diff(H, s) for s in q]


def qdot_output(build, name):
    out = subprocess.run([build + '/qdot', 'hamiltonian', 'examples/' + name + '.qd',
                          '--format', 'sympy'], capture_output=True, text=True, check=True,
                         cwd=ROOT).stdout
    ns = {}
    exec(out, ns)
    return ns


def plain(ns, q, x):
    """qdot prints coordinates as functions of t: back to plain symbols."""
    return sympify(x).subs({ns[s.name](t): s for s in q})


ROOT = __file__.rsplit('/tests/', 1)[0]


def main():
    build = sys.argv[sys.argv.index('--build') + 1] if '--build' in sys.argv else ROOT + '/build'
    passed = failed = 0
    for make in (case_kepler, case_bead, case_charged,
                 case_spherical):
        name, q, qd, L = make()
        p, H, dq, dp = legendre(q, qd, L)
        try:
            ns = qdot_output(build, name)
            checks = [('H', ns['H'], H)] + \
                     [('dq_dt', a, b) for a, b in zip(ns['dq_dt'], dq)] + \
                     [('dp_dt', a, b) for a, b in zip(ns['dp_dt'], dp)]
            bad = [w for w, a, b in checks if simplify(plain(ns, q, a) - b) != 0]
        except Exception as ex:  # a crash of qdot or of the printed Python
            bad = [repr(ex)]
        if bad:
            failed += 1
            print('FAIL %s: %s' % (name, ', '.join(bad)))
        else:
            passed += 1
            print('ok   %s' % name, flush=True)
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
