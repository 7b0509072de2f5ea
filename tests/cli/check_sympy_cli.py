#!/usr/bin/env python3
"""`--format sympy` output runs as Python, user functions included.

    python3 tests/cli/check_sympy_cli.py --build BUILD_DIR

A particle in a plane under an unknown central potential W(r) (`functions W`)
and a particle on a surface of unknown shape z = h(x, y) (a function of two
arguments).  The scripts `qdot eom`, `qdot hamiltonian` and `qdot routh` print
must run under Debian's SymPy with nothing added (issue 11: W was used but
never defined), and what they define must be the textbook results, derived
here by SymPy itself:

- eom: M q'' - f equals Lagrange's d/dt dL/dq' - dL/dq for L = T - V;
- hamiltonian: H = p_r^2/(2m) + p_phi^2/(2 m r^2) + W(r) (Goldstein sec. 8.1,
  the central-force Hamiltonian);
- routh --ignore phi: V_eff = p_phi^2/(2 m r^2) + W(r) (Goldstein sec. 3.3,
  the centrifugal barrier; Desloge ch. 54).

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import os
import subprocess
import sys
import tempfile

import sympy
from sympy import Function, Matrix, Rational, Symbol, simplify

results = {'passed': 0, 'failed': 0}

CENTRAL = """coordinates r, phi
parameters m = 1
functions W
T = m/2*(r'^2 + r^2*phi'^2)
V = W(r)
"""

# A cart of mass M on a spring of unknown law f(x), with a pendulum (Desloge
# ch. 59's cart and pendulum): the names M and f are the model's, so the
# script must name its matrix and vector otherwise and still be right.
CART = """coordinates x, th
parameters M = 2, m = 1, l = 1, g = 981/100
functions f
T = M/2*x'^2 + m/2*((x' + l*cos(th)*th')^2 + (l*sin(th)*th')^2)
V = f(x) - m*g*l*cos(th)
"""

# A pendulum of length L given by its Hamiltonian (Goldstein sec. 8.1): the
# script's Lagrangian must not take the parameter's name L.
PENDULUM_H = """coordinates th
momenta p_th
parameters m = 1, L = 2, g = 981/100
H = p_th^2/(2*m*L^2) - m*g*L*cos(th)
"""

WIRE = """coordinates x, y
parameters m = 1, g = 981/100
functions h
particle m at (x, y, h(x, y))
V = m*g*h(x, y)
"""


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, detail))


def script(qdot, path, *args):
    """Run qdot and then its printed script in a fresh python3; the script's
    names, or None when either fails."""
    p = subprocess.run([qdot, *args[:1], path, *args[1:], '--format', 'sympy'],
                       capture_output=True, text=True, timeout=120)
    if p.returncode != 0:
        check('%s %s' % (args[0], path), False, p.stderr)
        return None
    # A separate interpreter, as a user would run it: nothing of ours in scope.
    run = subprocess.run([sys.executable, '-c', p.stdout], capture_output=True, text=True,
                         timeout=120)
    check('%s script runs' % args[0], run.returncode == 0, run.stderr[-400:])
    if run.returncode != 0:
        return None
    ns = {}
    exec(compile(p.stdout, '<qdot %s>' % args[0], 'exec'), ns)
    return ns


def zero(e):
    return simplify(sympy.expand(e)) == 0


def lagrange(L, qs, t):
    return Matrix([sympy.diff(L.diff(q.diff(t)), t) - L.diff(q) for q in qs])


def check_eom(qdot, path, L_of, name, Mname='M', fname='f'):
    ns = script(qdot, path, 'eom')
    if ns is None:
        return
    t, qs = ns['t'], list(ns['q'])
    check('%s names its matrix %s and vector %s' % (name, Mname, fname),
          isinstance(ns.get(Mname), sympy.MatrixBase) and isinstance(ns.get(fname), sympy.MatrixBase))
    if not isinstance(ns.get(Mname), sympy.MatrixBase) or not isinstance(ns.get(fname), sympy.MatrixBase):
        return
    lhs = ns[Mname] * Matrix([q.diff(t, 2) for q in qs]) - ns[fname]
    ref = lagrange(L_of(ns), qs, t)
    for k in range(len(qs)):
        check('%s eom row %d' % (name, k), zero(lhs[k] - ref[k]),
              '%s vs %s' % (lhs[k], ref[k]))


def central_L(ns):
    t, r, phi, m, W = ns['t'], ns['r'], ns['phi'], ns['m'], ns['W']
    return m / 2 * (r(t).diff(t)**2 + r(t)**2 * phi(t).diff(t)**2) - W(r(t))


def cart_L(ns):
    t, x, th = ns['t'], ns['x'], ns['th']
    M, m, l, g, f = ns['M'], ns['m'], ns['l'], ns['g'], ns['f']
    assert isinstance(M, sympy.Symbol), 'the parameter M was overwritten'
    T = M / 2 * x(t).diff(t)**2 + m / 2 * ((x(t).diff(t) + l * sympy.cos(th(t)) * th(t).diff(t))**2
                                          + (l * sympy.sin(th(t)) * th(t).diff(t))**2)
    return T - f(x(t)) + m * g * l * sympy.cos(th(t))


def wire_L(ns):
    t, x, y, m, g, h = ns['t'], ns['x'], ns['y'], ns['m'], ns['g'], ns['h']
    z = h(x(t), y(t))
    return m / 2 * (x(t).diff(t)**2 + y(t).diff(t)**2 + z.diff(t)**2) - m * g * z


def check_hamiltonian(qdot, path):
    ns = script(qdot, path, 'hamiltonian')
    if ns is None:
        return
    t, r, m, W = ns['t'], ns['r'], ns['m'], ns['W']
    p_r, p_phi = Symbol('p_r'), Symbol('p_phi')
    want = p_r**2 / (2 * m) + p_phi**2 / (2 * m * r(t)**2) + W(r(t))
    check('hamiltonian H', zero(ns['H'] - want), str(ns['H']))
    # dp_r/dt = -dH/dr = p_phi^2/(m r^3) - W'(r)
    dp = ns['dp_dt'][0]
    check('hamiltonian dp_r/dt', zero((dp - (-want.diff(r(t)))).doit()), str(dp))


def check_hamiltonian_names(qdot, path):
    ns = script(qdot, path, 'hamiltonian')
    if ns is None:
        return
    t, th, m, L, g = ns['t'], ns['th'], ns['m'], ns['L'], ns['g']
    check('hamiltonian keeps the parameter L', isinstance(L, sympy.Symbol), str(L))
    want = m * L**2 * th(t).diff(t)**2 / 2 + m * g * L * sympy.cos(th(t))
    check('hamiltonian Lagrangian L_', 'L_' in ns and zero(ns['L_'] - want), str(ns.get('L_')))
    p_th = Symbol('p_th')
    check('hamiltonian dq/dt uses the length', zero(ns['dq_dt'][0] - p_th / (m * L**2)),
          str(ns['dq_dt'][0]))


def check_routh(qdot, path):
    ns = script(qdot, path, 'routh', '--ignore', 'phi')
    if ns is None:
        return
    t, r, m, W = ns['t'], ns['r'], ns['m'], ns['W']
    p_phi = ns['p_phi']
    want = p_phi**2 / (2 * m * r(t)**2) + W(r(t))
    check('routh V_eff', zero(ns['routh_V_eff'] - want), str(ns['routh_V_eff']))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    args = ap.parse_args()
    qdot = os.path.join(args.build, 'qdot')
    with tempfile.TemporaryDirectory() as d:
        central, wire = os.path.join(d, 'central.qd'), os.path.join(d, 'wire.qd')
        cart = os.path.join(d, 'cart.qd')
        pend_h = os.path.join(d, 'pendulum_h.qd')
        with open(pend_h, 'w') as fh:
            fh.write(PENDULUM_H)
        with open(cart, 'w') as fh:
            fh.write(CART)
        with open(central, 'w') as fh:
            fh.write(CENTRAL)
        with open(wire, 'w') as fh:
            fh.write(WIRE)
        check_eom(qdot, central, central_L, 'central')
        check_eom(qdot, wire, wire_L, 'wire')
        check_eom(qdot, cart, cart_L, 'cart', 'M_', 'f_')
        check_hamiltonian(qdot, central)
        check_routh(qdot, central)
        check_hamiltonian_names(qdot, pend_h)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())
