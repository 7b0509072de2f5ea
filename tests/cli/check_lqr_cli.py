#!/usr/bin/env python3
"""End-to-end checks of `qdot lqr` (the Riccati equation, qdot/control.h).

Expected values are closed forms, not output of the code under test:
  - the double integrator x'' = u with Q = diag(q1, q2), R = r: the (1,1),
    (1,2), (2,2) entries of the Riccati equation give x12 = sqrt(q1 r),
    x11 = x12 x22 / r, x22 = sqrt(r (q2 + 2 x12)), so
    K = [sqrt(q1/r), sqrt((q2 + 2 sqrt(q1 r))/r)] (Bryson & Ho, "Applied
    Optimal Control", the double-integrator regulator), and A - B K has the
    characteristic polynomial s^2 + k2 s + k1;
  - the scalar x' = a x + b u: x = (a + sqrt(a^2 + b^2 q/r)) r / b^2;
  - the text, JSON and C forms give the same K;
  - refusals with exit 2 and the cause named: an unstable mode the input
    does not reach, R not positive definite, a non-square A, a weight of
    the wrong size (with a caret under it), a missing option.
Run: python3 check_lqr_cli.py --build BUILD_DIR
"""
import argparse
import cmath
import json
import math
import re
import subprocess
import sys

FAILED = []
PASSED = []


def run(qdot, *args):
    p = subprocess.run([qdot, 'lqr', *args], capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout, p.stderr


def check(name, cond, detail=''):
    (PASSED if cond else FAILED).append(name)
    if not cond:
        print('FAIL %s %s' % (name, detail))


def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * max(1.0, abs(b))


DI = ('--A', '[[0, 1], [0, 0]]', '--B', '[[0], [1]]')


def double_integrator(qdot):
    for q1, q2, r in [(1, 1, 1), (4, 0, 0.25), (10, 3, 2), (0.01, 100, 7)]:
        rc, out, err = run(qdot, *DI, '--weights', 'Q = diag(%r, %r), R = %r' % (q1, q2, r),
                           '--format', 'json')
        if rc != 0:
            check('double integrator %s' % ((q1, q2, r),), False, err)
            continue
        got = json.loads(out)
        k1, k2 = math.sqrt(q1 / r), math.sqrt((q2 + 2 * math.sqrt(q1 * r)) / r)
        K = got['K'][0]
        check('double integrator K %s' % ((q1, q2, r),), close(K[0], k1) and close(K[1], k2),
              '%s vs %s' % (K, [k1, k2]))
        x12 = math.sqrt(q1 * r)
        x22 = math.sqrt(r * (q2 + 2 * x12))
        want = [[x12 * x22 / r, x12], [x12, x22]]
        check('double integrator X %s' % ((q1, q2, r),),
              all(close(got['X'][i][j], want[i][j]) for i in range(2) for j in range(2)))
        roots = sorted([(-k2 + cmath.sqrt(k2 * k2 - 4 * k1)) / 2,
                        (-k2 - cmath.sqrt(k2 * k2 - 4 * k1)) / 2], key=lambda z: (-z.real, -z.imag))
        eig = [complex(re_, im) for re_, im in got['closed_loop_eigenvalues']]
        check('double integrator closed loop %s' % ((q1, q2, r),),
              all(abs(a - b) <= 1e-9 * max(1, abs(b)) for a, b in zip(eig, roots)),
              '%s vs %s' % (eig, roots))
        check('states and inputs named', got['states'] == ['x1', 'x2'] and got['inputs'] == ['u1'])


def scalar(qdot):
    a, b, q, r = 3.0, 0.5, 2.0, 0.1
    rc, out, err = run(qdot, '--A', '[[%r]]' % a, '--B', '[[%r]]' % b, '--weights',
                       'R = %r, Q = %r' % (r, q), '--format', 'json')
    x = (a + math.sqrt(a * a + b * b * q / r)) * r / (b * b)
    check('scalar closed form', rc == 0 and close(json.loads(out)['X'][0][0], x), err)


def formats_agree(qdot):
    w = ('--weights', 'Q = [[2, 0.5], [0.5, 1]], R = 3')
    _, js, _ = run(qdot, *DI, *w, '--format', 'json')
    _, text, _ = run(qdot, *DI, *w)
    _, c, _ = run(qdot, *DI, *w, '--format', 'c')
    K = json.loads(js)['K'][0]
    row = re.search(r'^  u1 +(\S+) +(\S+)$', text, re.M)
    check('text K to 10 digits', row is not None and
          all(close(float(row.group(i + 1)), K[i], 1e-9) for i in range(2)), text)
    cvals = re.search(r'\{\{?\s*\n\s*\{([^}]*)\}', c)
    check('C K every digit', cvals is not None and
          [float(v) for v in cvals.group(1).split(',')] == K, c)
    check('text says the residual', re.search(r'^relative residual: \S+e-\d+$', text, re.M) is not None)


def refusals(qdot):
    rc, _, err = run(qdot, '--A', '[[1, 0], [0, -1]]', '--B', '[[0], [1]]', '--weights',
                     'Q = 1, R = 1')
    check('not stabilizable', rc == 2 and 'the mode s = 1 of A (Re s >= 0) is not reached' in err,
          err)
    rc, _, err = run(qdot, *DI, '--weights', 'Q = 1, R = -2')
    check('R not positive definite', rc == 2 and 'R is not positive definite' in err, err)
    rc, _, err = run(qdot, *DI, '--weights', 'Q = diag(1, -1), R = 1')
    check('Q indefinite', rc == 2 and 'Q is not positive semidefinite' in err, err)
    rc, _, err = run(qdot, *DI, '--weights', 'Q = 0, R = 1')
    check('Q = 0 not detectable', rc == 2 and '(Q, A) is not detectable' in err, err)
    rc, _, err = run(qdot, '--A', '[[0, 1]]', '--B', '[[1]]', '--weights', 'Q = 1, R = 1')
    check('A not square', rc == 2 and 'A must be square' in err, err)
    rc, _, err = run(qdot, *DI, '--weights', 'Q = diag(1, 2, 3), R = 1')
    check('weight of the wrong size, the caret under the entry too many',
          rc == 2 and err.splitlines()[1:3] == ['  Q = diag(1, 2, 3), R = 1', ' ' * 17 + '^'], err)
    rc, _, err = run(qdot, *DI)
    check('missing --weights', rc == 2 and 'needs --A, --B and --weights' in err, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = ap.parse_args().build + '/qdot'
    double_integrator(qdot)
    scalar(qdot)
    formats_agree(qdot)
    refusals(qdot)
    print('%d passed, %d failed' % (len(PASSED), len(FAILED)))
    return 1 if FAILED else 0


if __name__ == '__main__':
    sys.exit(main())
