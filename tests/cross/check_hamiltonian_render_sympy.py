#!/usr/bin/python3
"""Cross-check the SymPy script of qd_render_hamiltonian (tests/cross/
gen_hamiltonian.c) in SymPy: the script runs as it is (exec) and defines
momenta, velocities, H, dq_dt and dp_dt, which must be, independently of
qdot:
  polar, polar_H  a particle in V = -k/r + c r^2 in polar coordinates:
                  H = p_r^2/(2m) + p_th^2/(2 m r^2) + V(r) (Goldstein
                  ch. 8 sec. 3), and polar_H's inverse Legendre transform
                  L = m/2 (r'^2 + r^2 th'^2) - V;
  rotating        a bead on a wire spinning at w, L = m/2 (s'^2 + w^2 s^2):
                  H = p^2/(2m) - m w^2 s^2/2, which is not T + V (Desloge
                  ch. 71: the Jacobi integral), conserved;
and for each, Hamilton's equations dq/dt = dH/dp, dp/dt = -dH/dq from the
script's own H."""
import argparse
import os
import subprocess
import sys

import sympy
from sympy import Rational, Symbol, simplify


def script(build, name):
    gen = os.path.join(build, 'tests', 'gen_hamiltonian')
    return subprocess.run([gen, name], check=True, capture_output=True, text=True).stdout


def run(build, name):
    ns = {}
    exec(script(build, name), ns)  # valid Python that SymPy reads, as it is
    return ns


def zero(x):
    return simplify(sympy.sympify(x)) == 0


def check(build, name, failures):
    ns = run(build, name)
    t = ns['t']
    m = Symbol('m')
    if name in ('polar', 'polar_H'):
        k, c = Symbol('k'), Symbol('c')
        r, th = ns['r'](t), ns['th'](t)
        pr, pth = ns['p_r'], ns['p_th']
        want = pr**2 / (2 * m) + pth**2 / (2 * m * r**2) - k / r + c * r**2
        qs, ps = [r, th], [pr, pth]
    else:
        w = Symbol('w')
        s, p = ns['s'](t), ns['p_s']
        want = p**2 / (2 * m) - m * w**2 * s**2 / 2
        qs, ps = [s], [p]
        if '# H = T + V: no' not in script(build, name):
            failures.append('%s: H = T + V should be no' % name)
    H = ns['H']
    ok = zero(H - want)
    if not ok:
        failures.append('%s: H = %s, want %s' % (name, H, want))
    if list(ns['momenta']) != ps:
        failures.append('%s: momenta %s' % (name, ns['momenta']))
        ok = False
    for j, (q, p) in enumerate(zip(qs, ps)):
        if not zero(ns['dq_dt'][j] - sympy.diff(H, p)) or \
                not zero(ns['dp_dt'][j] + sympy.diff(H, q)) or \
                not zero(ns['velocities'][j] - sympy.diff(want, p)):
            failures.append('%s: Hamilton\'s equations of %s' % (name, q))
            ok = False
    if name == 'polar_H':
        rd, thd = sympy.diff(qs[0], t), sympy.diff(qs[1], t)
        L = m / 2 * (rd**2 + qs[0]**2 * thd**2) + Symbol('k') / qs[0] - Symbol('c') * qs[0]**2
        if ns.get('L') is None or not zero(ns['L'] - L):
            failures.append('polar_H: L = %s, want %s' % (ns.get('L'), L))
            ok = False
    return ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    args = ap.parse_args()
    names = ['polar', 'polar_H', 'rotating']
    failures = []
    passed = sum(check(args.build, n, failures) for n in names)
    for f in failures:
        print('FAIL', f)
    print('%d passed, %d failed' % (passed, len(names) - passed))
    return 0 if passed == len(names) else 1


if __name__ == '__main__':
    sys.exit(main())
