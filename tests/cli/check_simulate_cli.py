#!/usr/bin/env python3
"""End-to-end checks of `qdot simulate` and `qdot poincare`.

Physics checked: the double pendulum (Goldstein ch. 1 ex. 22, seed 002) keeps
its energy; x2 = l1 sin(theta1) + l2 sin(theta2) as an --output column; the
undamped pendulum (examples/damped_pendulum.qd with k = 0) has the period
4 sqrt(l/g) K(sin(theta0/2)) (K by the arithmetic-geometric mean, Abramowitz &
Stegun 17.6), found by --stop-at; the rod pendulum in Cartesian coordinates
keeps its constraint; the exit statuses of the documented failures.
"""
import argparse
import csv
import io
import json
import math
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

EX = Path(__file__).resolve().parents[2] / 'examples'


def run(qdot, *args):
    p = subprocess.run([str(qdot), *map(str, args)], capture_output=True, text=True,
                       timeout=120)
    return p.returncode, p.stdout, p.stderr


def rows(text):
    r = list(csv.reader(io.StringIO(text)))
    return r[0], [[float(x) for x in row] for row in r[1:]]


def ellipk(k):
    a, b = 1.0, math.sqrt(1 - k * k)
    for _ in range(40):
        a, b = (a + b) / 2, math.sqrt(a * b)
    return math.pi / (2 * a)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = Path(ap.parse_args().build).resolve() / 'qdot'
    failures = []
    tmp = tempfile.mkdtemp(prefix='qdot-simulate-')

    def check(cond, what):
        if not cond:
            failures.append(what)

    dp = EX / 'double_pendulum.qd'
    # JSON summary: the documented keys, energy kept, final state by name
    rc, out, err = run(qdot, 'simulate', dp, '--t-end', 5, '--rtol', 1e-11, '--format', 'json',
                       '--out', '/dev/null')
    check(rc == 0, f'json run: {rc} {err}')
    if rc == 0:
        j = json.loads(out)
        for key in ('method', 'steps', 'evaluations', 'rejected', 'wall_s',
                    'energy_error_max', 'constraint_error_max', 'final'):
            check(key in j, f'json key {key}')
        check(j['method'] == 'dop853', 'default method with --rtol is dop853')
        check(j['energy_error_max'] < 1e-9, f"energy error {j['energy_error_max']}")
        check("theta1'" in j['final'] and j['final']['t'] == 5, 'final state')
        check('evaluations' in err, 'summary on stderr')

    # CSV: gl4 by default with --step (issue 33: --dt alone is dop853's rows), momenta columns,
    # one row per step
    rc, out, err = run(qdot, 'simulate', dp, '--t-end', 1, '--step', 0.01, '--output', 'x2, y2')
    check(rc == 0, f'csv run: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        check(head[:8] == ['t', 'theta1', 'theta2', "theta1'", "theta2'", 'p_theta1',
                           'p_theta2', 'energy'], f'header {head}')
        check(head[-2:] == ['x2', 'y2'], f'output columns {head}')
        check(len(data) == 101 and data[-1][0] == 1.0, f'{len(data)} rows')
        check('gl4' in err, 'default method with --step is gl4')
        for r in data:
            x2 = math.sin(r[1]) + math.sin(r[2])
            check(abs(r[-2] - x2) < 1e-12, f'x2 at t={r[0]}')
        e0 = data[0][7]
        check(max(abs(r[7] - e0) for r in data) < 1e-6 * 30, 'gl4 energy')

    # numbers: the shortest of 15, 16, 17 significant digits that reads back
    # (Python's %g, correctly rounded, is the reference), over every magnitude
    # a trajectory has: angles wound up to ~1e2, energies ~1e-9 near E = 0
    rc, out, err = run(qdot, 'simulate', dp, '--t-end', 20, '--rtol', 1e-10,
                       '--initial', 'theta1=pi/2, theta2=pi/2', '--output', 'x2*1e-7, y2*1e9')
    check(rc == 0, f'number run: {rc} {err}')
    if rc == 0:
        text = list(csv.reader(io.StringIO(out)))[1:]
        check(len(text) > 100, f'{len(text)} rows')
        bad = []
        for row in text:
            for field in row:
                x = float(field)
                want = next(s for p in (15, 16, 17)
                            for s in ['%.*g' % (p, x)] if p == 17 or float(s) == x)
                if field != want:
                    bad.append((field, want))
        check(not bad, f'numbers {bad[:5]}')

    # the pendulum's period by --stop-at (damped_pendulum.qd with k = 0: l = 1.2, theta0 = 1)
    rc, out, err = run(qdot, 'simulate', EX / 'damped_pendulum.qd', '--set', 'k=0', '--t-end', 5,
                       '--rtol', 1e-13, '--stop-at', "theta' = 0, theta > 0")
    check(rc == 0, f'stop-at run: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        period = 4 * math.sqrt(1.2 / 9.81) * ellipk(math.sin(0.5))
        check(head[-1] == 'event' and data[-1][-1] == 1, 'event row last')
        check(abs(data[-1][0] - period) < 1e-11 * period, f'period {data[-1][0]} vs {period}')

    # --event records without stopping: theta = 0 twice per period
    rc, out, err = run(qdot, 'simulate', EX / 'damped_pendulum.qd', '--set', 'k=0', '--t-end',
                       4 * 2.3433, '--rtol', 1e-12, '--event', 'theta = 0', '--dt', 0.5,
                       '--method', 'dop853')
    check(rc == 0, f'event run: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        ev = [r for r in data if r[-1] == 1]
        check(len(ev) == 8, f'{len(ev)} crossings')
        check(all(abs(r[1]) < 1e-12 for r in ev), 'theta = 0 at the crossings')

    # constrained: the rod pendulum keeps its constraint
    rc, out, err = run(qdot, 'simulate', EX / 'pendulum_cartesian.qd', '--t-end', 10,
                       '--format', 'json', '--out', '/dev/null')
    check(rc == 0, f'constrained run: {rc} {err}')
    if rc == 0:
        js = json.loads(out)
        check(js['constraint_error_max'] < 1e-12, 'constraint residual')
        per = js['constraint_errors']
        check(list(per) == ['rod'] and per['rod'] == js['constraint_error_max'],
              f'the residual of each constraint, by name: {per}')

    # an event on a constraint force: the particle leaves the sphere where the
    # multiplier (the normal force / 2a) vanishes.  From rest at height z0 on a
    # smooth sphere, v^2 = 2 g (z0 - z) and N = m (g z - v^2)/a = 0 at z = 2 z0/3
    # (Goldstein sec. 1.3; Desloge ch. 51 P6: cos theta = 2/3 from the top).
    rc, out, err = run(qdot, 'simulate', EX / 'particle_leaving_sphere.qd', '--t-end', 10,
                       '--rtol', '1e-12', '--stop-at', 'lambda_sphere = 0',
                       '--output', 'lambda_sphere')
    check(rc == 0, f'leaving the sphere: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        z, lam = head.index('z'), head.index('lambda_sphere')
        z0, zl = data[0][z], data[-1][z]
        check(data[-1][-1] == 1 and abs(data[-1][lam]) < 1e-9, 'stopped at lambda = 0')
        check(abs(zl - 2 * z0 / 3) < 1e-9, f'leaves at z = 2 z0/3: {zl} vs {2 * z0 / 3}')
        check(data[0][lam] > 0, 'the sphere pushes outward before (lambda > 0)')

    # poincare: n crossings of theta1 = 0 upward
    rc, out, err = run(qdot, 'poincare', dp, '--section', "theta1 = 0, theta1' > 0", '--crossings', 4,
                       '--initial', 'theta1=1, theta2=0.5')
    check(rc == 0, f'poincare: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        check(len(data) == 4, f'{len(data)} crossings')
        check(all(abs(r[1]) < 1e-12 and r[3] > 0 for r in data), 'section state')
        e = [r[head.index('energy')] for r in data]
        check(max(e) - min(e) < 1e-8, 'energy on the section')

    # failures: named, exit 1; usage, exit 2
    rc, out, err = run(qdot, 'simulate', dp, '--t-end', 1, '--dt', 0.1, '--method', 'verlet')
    check(rc == 1 and 'not separable' in err, f'verlet on non-separable H: {rc} {err}')
    check(out == '', f'a refused run prints nothing on stdout, not {out[:80]!r}')
    rc, out, err = run(qdot, 'poincare', dp, '--section', 'theta1 = 0', '--crossings', 1, '--dt', 0.1,
                       '--method', 'yoshida4')
    check(rc == 1 and 'not separable' in err and out == '', f'poincare yoshida4: {rc} {out!r}')
    rc, out, err = run(qdot, 'simulate', EX / 'kepler_polar.qd', '--t-end', 1, '--dt', 10,
                       '--method', 'gl6', '--set', 'k=4000')
    check(rc == 1 and 'Gauss-Legendre' in err, f'gl divergence: {rc} {err}')
    for args in (['--t-end', 1, '--method', 'rk4'], ['--dt', 0.1], ['--t-end', 'x'],
                 ['--t-end', 1, '--bogus'], ['--t-end', 1, '--method', 'gl4'],
                 ['--t-end', 1, '--output', 'nosuchname']):
        rc, out, err = run(qdot, 'simulate', dp, *args)
        check(rc == 2, f'usage {args}: {rc} {err}')
    rc, out, err = run(qdot, 'poincare', dp, '--crossings', 3)
    check(rc == 2, f'poincare without --section: {rc}')

    # a model given by H with d^2H/dp^2 singular (H = p x: no Lagrangian):
    # Hamilton's equations integrated as given, x = e^t, p = 2 e^-t from
    # the momentum in --initial; velocities alone cannot give p (exit 1)
    hm = Path(tmp) / 'h_px.qd'
    hm.write_text('coordinates x\nmomenta p\nH = p*x\ninitial x = 1\n')
    rc, out, err = run(qdot, 'simulate', hm, '--t-end', 1, '--initial', 'p = 2')
    check(rc == 0, f'H = p x: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        check(head == ['t', 'x', "x'", 'p', 'energy'], f'H = p x columns {head}')
        t, x, xd, p, e = data[-1]
        check(t == 1 and abs(x - math.e) < 1e-9 and abs(xd - x) < 1e-15
              and abs(p - 2 / math.e) < 1e-9 and abs(e - 2) < 1e-9, f'H = p x: {data[-1]}')
    rc, out, err = run(qdot, 'simulate', hm, '--t-end', 1)
    check(rc == 1 and 'give the momenta' in err and out == '', f'H = p x, no p: {rc} {err}')
    # the oscillator H = (p^2 + x^2)/2 from x = 1, x' = 0 (p from x' = dH/dp):
    # x' = 0 again with x < 0 at t = pi; outputs and events may use q' and p
    ho = Path(tmp) / 'h_osc.qd'
    ho.write_text('coordinates x\nmomenta p\nH = p^2/2 + x^2/2\ninitial x = 1\n')
    rc, out, err = run(qdot, 'simulate', ho, '--t-end', 4, '--rtol', 1e-12, '--output',
                       "x' - p", '--stop-at', "x' = 0, x < 0")
    check(rc == 0, f'H oscillator: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        last = data[-1]
        check(abs(last[0] - math.pi) < 1e-9 and abs(last[1] + 1) < 1e-9, f'half period {last}')
        check(all(r[head.index("x' - p")] == 0 for r in data), "x' = dH/dp = p")

    # a step count past --max-steps (default 1e8) is refused before the run,
    # naming the count: --dt 1e-300 over t = 0..1 is 1e300 steps, and an
    # output grid of 1e300 rows likewise (these used to run forever)
    for args, what in ((['--method', 'gl6', '--dt', '1e-300'], '1e+300 steps'),
                       (['--method', 'dop853', '--dt', '1e-300'], '1e+300 rows'),
                       (['--method', 'gl4', '--dt', 0.001, '--max-steps', 999], '1e+03 steps')):
        rc, out, err = run(qdot, 'simulate', dp, '--t-end', 1, *args, '--out', '/dev/null')
        check(rc == 2 and what in err and 'max-steps' in err, f'max steps {args}: {rc} {err}')
    rc, out, err = run(qdot, 'simulate', dp, '--t-end', 1, '--method', 'gl4', '--dt', 0.001,
                       '--max-steps', 1000, '--out', '/dev/null')
    check(rc == 0, f'exactly --max-steps steps: {rc} {err}')
    # an adaptive run stops at the bound with a failure (exit 1)
    rc, out, err = run(qdot, 'simulate', dp, '--t-end', 100, '--max-steps', 50, '--out',
                       '/dev/null')
    check(rc == 1 and 'more than 50 steps' in err, f'adaptive max steps: {rc} {err}')
    for bad in ('2.5', '0', 'x'):
        rc, out, err = run(qdot, 'simulate', dp, '--t-end', 1, '--max-steps', bad)
        check(rc == 2, f'--max-steps {bad}: {rc} {err}')

    shutil.rmtree(tmp, ignore_errors=True)
    for f in failures:
        print('FAIL:', f)
    print(f'{len(failures)} failures')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
