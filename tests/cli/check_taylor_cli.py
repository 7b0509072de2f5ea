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
- --native (the recurrences as generated C) prints the interpreter's rows to the bit,
  in the four forms, compiles its object once, and falls back with a note.
"""
import argparse
import csv
import io
import json
import math
import os
import shutil
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


def run(qdot, *args, env=None):
    p = subprocess.run([str(qdot), *map(str, args)], capture_output=True, text=True,
                       timeout=300, env=env)
    return p.returncode, p.stdout, p.stderr


def rows(text):
    r = list(csv.reader(io.StringIO(text)))
    return r[0], [[float(x) for x in row] for row in r[1:]]


def final(qdot, model, *args):
    rc, out, err = run(qdot, 'simulate', model, '--format', 'json', '--out', '/dev/null', *args)
    return rc, (json.loads(out) if rc == 0 else err)


def cache_env(cache, **more):
    return {**os.environ, 'XDG_CACHE_HOME': str(cache), **more}


def objects(cache):
    return sorted((cache / 'qdot').glob('*.so'))


def native_checks(qdot, tmp, check):
    """--native for taylor: the generated recurrences (src/sym/taylor_emit.c) do the
    interpreter's operations in the interpreter's order, so every row is the same to the
    bit; the object is compiled once and reused."""
    dp = EX / 'double_pendulum.qd'
    cache = tmp / 'cache'
    have_cc = shutil.which(os.environ.get('CC', 'cc').split()[-1]) is not None
    sleigh = tmp / 'sleigh.qd'
    sleigh.write_text(SLEIGH)
    cases = [('double pendulum', dp, ['--t-end', 20]),
             ('bead on a turning wire (multiplier form)', EX / 'bead_wire_cartesian.qd',
              ['--t-end', 2]),
             ('Chaplygin sleigh (speeds form)', sleigh, ['--t-end', 5]),
             ('Stark problem (given by H, (q, p) form)', EX / 'hj_stark.qd', ['--t-end', 1, '--rtol', 1e-13]),
             ('Kepler e = 0.9', tmp / 'kepler.qd', ['--t-end', 20])]
    (tmp / 'kepler.qd').write_text(KEPLER)
    for name, model, extra in cases:
        rtol = [] if '--rtol' in extra else ['--rtol', 1e-15]  # an option is given once
        args = ['simulate', model, '--method', 'taylor', *rtol, '--atol', 1e-15, *extra]
        ri = run(qdot, *args, env=cache_env(cache))
        rn = run(qdot, *args, '--native', env=cache_env(cache))
        check(ri[0] == 0 and rn[0] == 0, f'{name}: taylor runs failed: {ri[2]} {rn[2]}')
        if ri[0] or rn[0]:
            continue
        check(ri[1] == rn[1] or not have_cc, f'{name}: --native changed the taylor rows')
        (_, a), (_, b) = rows(ri[1]), rows(rn[1])
        diff = max(abs(x - y) for ra, rb in zip(a, b) for x, y in zip(ra, rb))
        check(len(a) == len(b) and len(a) >= 5 and diff <= 1e-12,
              f'{name}: --native and interpreted differ by {diff} ({len(a)}, {len(b)} rows)')
        check('unavailable' not in rn[2] or not have_cc, f'{name}: {rn[2]}')
    objs = objects(cache)
    check(len(objs) == len(cases) or not have_cc,
          f'one object per model expected, the cache has {[o.name for o in objs]}')
    if not objs:
        return
    # the second run finds the object: nothing is compiled, the file is not rewritten
    before = [(o.name, o.stat().st_mtime_ns) for o in objects(cache)]
    rc, out, err = run(qdot, 'simulate', dp, '--method', 'taylor', '--rtol', 1e-13,
                       '--t-end', 5, '--native', env=cache_env(cache))
    after = [(o.name, o.stat().st_mtime_ns) for o in objects(cache)]
    check(rc == 0 and before == after,
          f'another tolerance recompiled the object: {before} -> {after} {err}')
    # no compiler: the same note as the rhs's, and the interpreted rows
    base = ['simulate', dp, '--method', 'taylor', '--t-end', 3, '--rtol', 1e-14]
    ri = run(qdot, *base, env=cache_env(tmp / 'nocc'))
    rn = run(qdot, *base, '--native', env=cache_env(tmp / 'nocc', CC='/nonexistent/cc'))
    check(rn[0] == 0 and 'note: --native unavailable' in rn[2] and rn[1] == ri[1],
          f'--native without a compiler: {rn[0]} {rn[2]}')
    # extended precision keeps the interpreter, and says so
    ri = run(qdot, *base, '--precision', 80, env=cache_env(cache))
    rn = run(qdot, *base, '--precision', 80, '--native', env=cache_env(cache))
    check(rn[0] == 0 and 'double only' in rn[2] and rn[1] == ri[1],
          f'--native --precision 80: {rn[0]} {rn[2]}')


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
                           "theta1 = 0, theta1' > 0", '--crossings', 5, '--initial',
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
    check(rc == 2 and "--precision: unknown value '96' (one of 64, 80, 128)" in err,
          f'--precision 96: {rc} {err}')
    rc, out, err = run(qdot, 'simulate', dp, '--t-end', 1, '--method', 'dop853',
                       '--precision', 80)
    check(rc == 2 and 'precision 80 is for the taylor method' in err, f'--precision with dop853: {rc} {err}')
    res = [final(qdot, dp, '--t-end', 1, '--method', 'taylor', '--rtol', 1e-15, '--atol',
                 1e-15, '--precision', p) for p in (64, 128)]
    check(all(r[0] == 0 for r in res), f'--precision 64/128: {res}')
    if all(r[0] == 0 for r in res):
        diff = max(abs(res[0][1]['final'][k] - res[1][1]['final'][k]) for k in ('theta1', 'theta2'))
        check(diff < 1e-12, f'double pendulum, 64 and 128 bits differ by {diff} at t = 1')

    native_checks(qdot, tmp, check)

    for f in failures:
        print('FAIL:', f)
    shutil.rmtree(tmp, ignore_errors=True)  # the native objects too
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
