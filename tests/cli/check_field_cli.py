#!/usr/bin/env python3
"""Tests of field models (`field y(x, t) on x = A .. B`, qdot/field.h), run
against the built program.

    python3 tests/cli/check_field_cli.py --build BUILD_DIR

- The stretched string (Desloge ch. 83, Problem 4, seed 000 p. 842;
  examples/string.qd): `qdot eom` gives rho y_tt - tau y_xx = 0, i.e.
  y_tt = c^2 y_xx with c^2 = tau/rho (compared by SymPy), and `qdot modes`
  the exact modes omega_n = (n pi/l) sqrt(tau/rho), shapes sin(n pi x/l).
- Free ends (natural condition tau y_x = 0): free-free omega_0 = 0 and
  n pi c/l with cos(n pi x/l); fixed-free (n - 1/2) pi c/l; a restoring
  term -kappa/2 y^2 adds kappa/rho to omega^2 (the field equation gets
  kappa y).  An interval not at 0 shifts the shapes.
- The hanging chain (examples/hanging_chain.qd: tau = rho g x, x up from the free lower end, fixed at
  x = l): by finite elements, omega_n = (j_0n/2) sqrt(g/l) with j_0n the
  zeros of Bessel's J0 (Lord Rayleigh; the standard result), within the
  reported error estimate (and that estimate below the tolerance).
- A variable-density string fixed at both ends, rho = rho0/(1 + x)^2 on
  0 .. 1 with tau = 1: Y = sqrt(1 + x) sin(beta ln(1 + x)) with
  beta = n pi/ln 2 gives omega_n^2 = (beta^2 + 1/4)/rho0 (an Euler
  equation), again within the estimate.
- Errors (exit 2, located FILE:LINE:COL): a density not quadratic, a
  condition at a point that is not an end, a missing condition, a field
  model given to a command for coordinates, options that a field does not
  take.

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import math
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import sympy as sp

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
results = {'passed': 0, 'failed': 0}
J0_ZEROS = [2.404825557695773, 5.520078110286311, 8.653727912911013,
            11.79153443901428, 14.93091770848779]


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, detail))


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=300)
    return p.returncode, p.stdout, p.stderr


def write(tmp, name, text):
    path = Path(tmp) / name
    path.write_text(text)
    return str(path)


def modes(qdot, path, *args):
    rc, out, err = run(qdot, 'modes', path, '--format', 'json', *args)
    return rc, (json.loads(out) if rc == 0 else None), err


def string(qdot):
    path = str(EXAMPLES / 'string.qd')
    rc, out, err = run(qdot, 'eom', path, '--format', 'json')
    check('string eom runs', rc == 0, err)
    if rc == 0:
        j = json.loads(out)
        names = {n: sp.Symbol(n) for n in ('rho', 'tau', 'y_tt', 'y_xx')}
        e = sp.sympify(j['equation'].replace('^', '**'), locals=names)
        rho, tau, ytt, yxx = (names[n] for n in ('rho', 'tau', 'y_tt', 'y_xx'))
        check('string: rho y_tt - tau y_xx = 0', sp.simplify(e - (rho * ytt - tau * yxx)) == 0,
              j['equation'])
        check('string: boundary fixed-fixed', j['boundary'] == ['fixed', 'fixed'], out)
    rc, out, err = run(qdot, 'eom', path)
    check('string eom text', rc == 0 and 'rho*y_tt - tau*y_xx = 0' in out, out + err)
    rc, j, err = modes(qdot, path, '--count', '4')
    check('string modes run', rc == 0, err)
    if rc == 0:
        rho, tau, l = 0.01, 100.0, 0.5
        check('string: exact', j['method'] == 'exact' and j['converged'], j['method'])
        for n, m in enumerate(j['modes'], 1):
            want = n * math.pi / l * math.sqrt(tau / rho)
            check('string omega_%d' % n, abs(m['omega'] - want) <= 1e-12 * want,
                  '%r vs %r' % (m['omega'], want))
            k = float(re.match(r'sin\(([0-9.e+-]+)\*x\)', m['shape']).group(1))
            check('string shape %d is sin(n pi x/l)' % n, abs(k - n * math.pi / l) < 1e-12 * k,
                  m['shape'])


def free_ends(qdot, tmp):
    body = 'parameters c = 3\nfield u(s, t) on s = 0..2\nLdensity = u_t^2/2 - c^2/2*u_s^2\n'
    ff = write(tmp, 'ff.qd', body + 'boundary u(0) free, u(2) free\n')
    rc, j, err = modes(qdot, ff, '--count', '3')
    check('free-free runs', rc == 0, err)
    if rc == 0:
        w = [m['omega'] for m in j['modes']]
        check('free-free: 0, pi c/l, 2 pi c/l',
              w[0] == 0 and abs(w[1] - 3 * math.pi / 2) < 1e-12 and
              abs(w[2] - 3 * math.pi) < 1e-12, w)
        check('free-free shapes cos', j['modes'][1]['shape'].startswith('cos('),
              j['modes'][1]['shape'])
    fr = write(tmp, 'fr.qd', body + 'boundary u(0) = 0, u(2) free\n')
    rc, j, err = modes(qdot, fr, '--count', '2')
    check('fixed-free runs', rc == 0, err)
    if rc == 0:
        w = [m['omega'] for m in j['modes']]
        want = [(n - 0.5) * math.pi * 3 / 2 for n in (1, 2)]
        check('fixed-free: (n - 1/2) pi c/l', all(abs(a - b) < 1e-12 for a, b in zip(w, want)), w)
    kp = write(tmp, 'kp.qd', 'field y(x, t) on x = 1 .. 3\n'
               'Ldensity = y_t^2/2 - y_x^2/2 - 2*y^2\nboundary y(1) = 0, y(3) free\n')
    rc, j, err = modes(qdot, kp, '--count', '1')
    if rc == 0:
        k = math.pi / 4
        check('kappa adds to omega^2', abs(j['modes'][0]['omega2'] - (k * k + 4)) < 1e-12,
              j['modes'][0])
        check('shape shifted to the interval', j['modes'][0]['shape'] ==
              'sin(%s*(x - 1))' % repr(k), j['modes'][0]['shape'])
    rc, out, err = run(qdot, 'eom', kp)
    check('eom with kappa: 4*y + y_tt - y_xx = 0', rc == 0 and '4*y + y_tt - y_xx = 0' in out,
          out + err)


def converged(name, j, want):
    check(name + ': finite elements, converged', j['method'] == 'finite elements' and
          j['converged'] and j['elements'] > 0, j['method'])
    for n, (m, w) in enumerate(zip(j['modes'], want), 1):
        check('%s omega_%d within its estimate' % (name, n),
              abs(m['omega'] - w) <= max(m['error'], 1e-12 * w) and
              m['error'] <= 1e-6 * w, '%r vs %r (estimate %r)' % (m['omega'], w, m['error']))


def hanging_chain(qdot):
    path = str(EXAMPLES / 'hanging_chain.qd')
    rc, j, err = modes(qdot, path, '--count', '4')
    check('hanging chain runs', rc == 0, err)
    if rc == 0:
        converged('hanging chain', j, [z / 2 * math.sqrt(9.81 / 2) for z in J0_ZEROS])
    rc, out, err = run(qdot, 'eom', path)
    check('hanging chain eom', rc == 0 and 'y_tt' in out and 'y_xx' in out and 'y_x' in out,
          out + err)


def variable_density(qdot, tmp):
    path = write(tmp, 'vd.qd', 'parameters rho0 = 2\nfield y(x, t) on x = 0 .. 1\n'
                 'Ldensity = rho0/(1 + x)^2/2*y_t^2 - y_x^2/2\nboundary y(0) = 0, y(1) = 0\n')
    rc, j, err = modes(qdot, path, '--count', '3')
    check('variable density runs', rc == 0, err)
    if rc == 0:
        want = [math.sqrt(((n * math.pi / math.log(2)) ** 2 + 0.25) / 2) for n in (1, 2, 3)]
        converged('variable density', j, want)


def errors(qdot, tmp):
    base = 'field y(x, t) on x = 0 .. 1\n'
    cases = [
        ('not quadratic', base + 'Ldensity = y_t^2/2 - y_x^4/2\nboundary y(0) = 0, y(1) = 0\n',
         'modes', ':2:1: error: the density is not quadratic'),
        ('not an end', base + 'Ldensity = y_t^2/2 - y_x^2/2\nboundary y(0) = 0, y(3) free\n',
         'modes', ':3:22: error: 3 is not an end of the interval'),
        ('missing end', base + 'Ldensity = y_t^2/2 - y_x^2/2\nboundary y(0) = 0\n',
         'eom', ":1:1: error: the condition at the field's upper end is not given"),
        ('no density', base + 'boundary y(0) = 0, y(1) = 0\n',
         'eom', ':1:1: error: the field has no Lagrangian density'),
        ('one dot', 'field y(x, t) on x = 0 . 1\n', 'eom', ":1:26: error: expected '..'"),
        ('field with coordinates', 'coordinates q\n' + base, 'eom',
         ':2:1: error: a field and coordinates in one model'),
        ('not for check', base + 'Ldensity = y_t^2/2 - y_x^2/2\nboundary y(0) = 0, y(1) = 0\n',
         'check', ':1:1: error: a field model has no coordinates for this command'),
    ]
    for name, text, cmd, want in cases:
        path = write(tmp, 'e.qd', text)
        rc, out, err = run(qdot, cmd, path)
        check('error: ' + name, rc == 2 and want in err and '^' in err, 'rc %d: %s' % (rc, err))
    rc, out, err = run(qdot, 'eom', str(EXAMPLES / 'string.qd'), '--solve')
    check('eom --solve refused for a field', rc == 2 and 'field model' in err, err)
    rc, out, err = run(qdot, 'modes', str(EXAMPLES / 'string.qd'), '--about', 'q=0')
    check('modes --about refused for a field', rc == 2 and 'field model' in err, err)
    rc, out, err = run(qdot, 'modes', str(EXAMPLES / 'cart_pendulum.qd'), '--count', '3')
    check('--count refused for coordinates', rc == 2 and 'field model' in err, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    with tempfile.TemporaryDirectory() as tmp:
        string(qdot)
        free_ends(qdot, tmp)
        hanging_chain(qdot)
        variable_density(qdot, tmp)
        errors(qdot, tmp)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    sys.exit(1 if results['failed'] else 0)


if __name__ == '__main__':
    main()
