#!/usr/bin/env python3
"""End-to-end checks of `--method taylor` (issue 22) in every form the
simulation has.

Physics checked:
- the Chaplygin sleigh in generalized speeds (the (q, u) form): v = V tanh(c V t
  + atanh(v0/V)), c = m b/(J + m b^2), V^2 = 2E/m (derived in
  tests/sim/test_sim_speeds.c), in every row to 1e-12;
- the pendulum in Cartesian coordinates with its rod as a constraint
  (examples/pendulum_cartesian.qd: the saddle system's series, then the
  projection): the same motion as dop853 at 1e-13 to 1e-9 at t = 5, the rod's
  residual at round-off;
- a system given by H (Hamilton's equations, (q, p)): the Stark problem of
  examples/hj_stark.qd against dop853 to 1e-9, H conserved to 1e-12;
- Kepler at e = 0.9 over 100 orbits: back at perihelion to 1e-9 after each
  period T = 2 pi a^(3/2) sqrt(m/k) (Goldstein, Poole & Safko, sec. 3.7);
- qdot poincare --method taylor finds dop853's crossings to 1e-9;
- the exit statuses of --precision: a value other than 64, 80, 128, and a
  precision for another method, are usage errors (2); --precision 128 agrees
  with double to 1e-12 at t = 1;
- --native prints the same rows (the recurrences are not generated C yet).
"""
import argparse
import csv
import io
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / 'examples'

SLEIGH = """coordinates x, y, theta
parameters m = 2, J = 0.3, b = 0.4
T = m/2*(x'^2 + y'^2) + J/2*theta'^2
constraint knife: cos(theta)*y' - sin(theta)*x' = b*theta'
speeds v = cos(theta)*x' + sin(theta)*y', w = theta'
initial x = 0.2, y = -0.1, theta = 0.3, v = -0.3, w = 1.5
"""

# a = 1: r_min = a (1 - e) = 0.1, v = sqrt(k/m (1 + e)/(a (1 - e))) = sqrt(19)
KEPLER = """coordinates x, y
parameters m = 1, k = 1
particle m at (x, y)
V = -k/sqrt(x^2 + y^2)
initial x = 0.1, y = 0, x' = 0, y' = 4.358898943540674
"""


def run(qdot, *args):
    p = subprocess.run([str(qdot), *map(str, args)], capture_output=True, text=True,
                       timeout=300)
    return p.returncode, p.stdout, p.stderr


def rows(text):
    r = list(csv.reader(io.StringIO(text)))
    return r[0], [[float(x) for x in row] for row in r[1:]]


def final(qdot, model, *args):
    rc, out, err = run(qdot, 'simulate', model, '--format', 'json', '--out', '/dev/null', *args)
    return rc, (json.loads(out) if rc == 0 else err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = Path(ap.parse_args().build).resolve() / 'qdot'
    failures = []
    tmp = Path(tempfile.mkdtemp(prefix='qdot-taylor-'))

    def check(cond, what):
        if not cond:
            failures.append(what)

    # the sleigh in speeds against its closed form
    m, J, b, v0, w0 = 2, 0.3, 0.4, -0.3, 1.5
    E = m / 2 * (v0 ** 2 + b ** 2 * w0 ** 2) + J / 2 * w0 ** 2
    V, c = math.sqrt(2 * E / m), m * b / (J + m * b * b)
    sleigh = tmp / 'sleigh.qd'
    sleigh.write_text(SLEIGH)
    rc, out, err = run(qdot, 'simulate', sleigh, '--t-end', 6, '--dt', 0.25, '--method',
                       'taylor', '--rtol', 1e-15, '--atol', 1e-15)
    check(rc == 0, f'sleigh: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        worst = max(abs(r[4] - V * math.tanh(c * V * r[0] + math.atanh(v0 / V))) for r in data)
        check(len(data) == 25 and worst < 1e-12, f'sleigh: {len(data)} rows, v off by {worst}')

    # constrained (q, q') and Hamilton's (q, p): the motion of dop853 at 1e-13
    for model, t_end, names in ((EX / 'pendulum_cartesian.qd', 5, ('x', 'y', "x'", "y'")),
                                (EX / 'hj_stark.qd', 1, None)):
        res = {}
        for method in ('taylor', 'dop853'):
            rc, j = final(qdot, model, '--t-end', t_end, '--method', method, '--rtol', 1e-13,
                          '--atol', 1e-13)
            check(rc == 0, f'{model.name} {method}: {rc} {j}')
            if rc == 0:
                res[method] = j
        if len(res) == 2:
            ft, fd = res['taylor']['final'], res['dop853']['final']
            keys = names or [k for k in ft if k not in ('t', 'energy')]
            diff = max(abs(ft[k] - fd[k]) for k in keys)
            check(diff < 1e-9, f'{model.name}: taylor and dop853 differ by {diff}')
            eerr = res['taylor']['energy_error_max']
            check(eerr < 1e-12, f'{model.name}: taylor energy error {eerr}')
            cerr = res['taylor']['constraint_error_max']
            check(cerr < 1e-12, f'{model.name}: taylor constraint error {cerr}')

    # Kepler e = 0.9: at perihelion after every period
    kepler = tmp / 'kepler.qd'
    kepler.write_text(KEPLER)
    T = 2 * math.pi
    rc, out, err = run(qdot, 'simulate', kepler, '--t-end', 100 * T, '--dt', T, '--method',
                       'taylor', '--rtol', 1e-15, '--atol', 1e-15)
    check(rc == 0, f'kepler: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        worst = max(abs(r[1] - 0.1) + abs(r[2]) for r in data)
        check(len(data) == 101 and worst < 1e-9, f'kepler: {len(data)} rows, off by {worst}')

    # poincare: the crossings of dop853
    sect = []
    for method in ('taylor', 'dop853'):
        rc, out, err = run(qdot, 'poincare', EX / 'double_pendulum.qd', '--section',
                           "theta1 = 0, theta1' > 0", '--n', 5, '--initial',
                           'theta1=1, theta2=0.5', '--method', method, '--rtol', 1e-13,
                           '--atol', 1e-13)
        check(rc == 0, f'poincare {method}: {rc} {err}')
        if rc == 0:
            sect.append(rows(out)[1])
    if len(sect) == 2:
        check(len(sect[0]) == len(sect[1]) == 5, f'poincare rows {len(sect[0])}, {len(sect[1])}')
        diff = max(abs(a - b) for ra, rb in zip(*sect) for a, b in zip(ra, rb))
        check(diff < 1e-9, f'poincare: taylor and dop853 crossings differ by {diff}')

    # --precision: usage errors, and a run in __float128
    dp = EX / 'double_pendulum.qd'
    rc, out, err = run(qdot, 'simulate', dp, '--t-end', 1, '--method', 'taylor',
                       '--precision', 96)
    check(rc == 2 and '--precision takes 64, 80 or 128' in err, f'--precision 96: {rc} {err}')
    rc, out, err = run(qdot, 'simulate', dp, '--t-end', 1, '--method', 'dop853',
                       '--precision', 80)
    check(rc == 2 and 'is for --method taylor' in err, f'--precision with dop853: {rc} {err}')
    res = [final(qdot, dp, '--t-end', 1, '--method', 'taylor', '--rtol', 1e-15, '--atol',
                 1e-15, '--precision', p) for p in (64, 128)]
    check(all(r[0] == 0 for r in res), f'--precision 64/128: {res}')
    if all(r[0] == 0 for r in res):
        diff = max(abs(res[0][1]['final'][k] - res[1][1]['final'][k]) for k in ('theta1', 'theta2'))
        check(diff < 1e-12, f'double pendulum, 64 and 128 bits differ by {diff} at t = 1')

    # --native leaves taylor's run as it is (a note says the recurrences are not native)
    res = [run(qdot, 'simulate', dp, '--t-end', 2, '--dt', 0.5, '--method', 'taylor', '--rtol',
               1e-14, '--atol', 1e-14, *extra) for extra in ([], ['--native'])]
    check(res[0][0] == 0 and res[1][0] == 0 and res[0][1] == res[1][1],
          f'--native changed the taylor run: {res[0][1]!r} {res[1][1]!r} {res[1][2]}')

    for f in failures:
        print('FAIL:', f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
