#!/usr/bin/python3
"""The Taylor integrator (issue 22) against qdot's other methods, in one run.

1. The claim: the 1000 s double pendulum from (pi/2, pi/2)
   (examples/double_pendulum.qd), taylor at rtol = atol = 1e-15 against dop853
   at 1e-12: time, steps, evaluations (program passes for taylor: one per
   order per step), the energy error of each and the time ratio.  It holds
   when taylor's energy error is below 1e-13 and it is faster.  Beside them
   taylor --native (the recurrences as generated C, the object compiled by
   an untimed first run): its speed-up over the interpreted recurrences,
   and its final state, which must be the interpreter's to the bit.
2. Cost against accuracy, same problem: taylor, dop853, gl6 (fixed steps) and
   bdf (CVODE) at several tolerances; the time and energy error over 1000 s,
   and the error of the state at t = 10 against a reference (taylor in
   __float128 at 1e-30; the motion is chaotic, so the state is compared early).
3. The 20-link pendulum (10 s from every link at 0.5 rad) and Kepler at
   e = 0.9 over 1000 orbits (a = 1, T = 2 pi; the error is the distance from
   perihelion at the end): taylor at 1e-15 against dop853 at 1e-12 and 1e-15.

Times are the child's CPU time (user + system, the least of --reps runs),
which the machine's other load disturbs less than wall time.

Usage: run_taylor.py BUILD_DIR [--reps N] [--quick]
"""
import argparse
import json
import math
import os
import resource
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
DP = os.path.join(ROOT, 'examples', 'double_pendulum.qd')
DP_INIT = 'theta1=1.5707963267948966, theta2=1.5707963267948966'

KEPLER = """coordinates x, y
parameters m = 1, k = 1
particle m at (x, y)
V = -k/sqrt(x^2 + y^2)
initial x = 0.1, y = 0, x' = 0, y' = 4.358898943540674
"""


def chain(n):
    lines = ['coordinates ' + ', '.join(f'th{i}' for i in range(1, n + 1)),
             'parameters m = 1, l = 1, g = 9.81']
    x = y = ''
    for i in range(1, n + 1):
        x += (' + ' if i > 1 else '') + f'l*sin(th{i})'
        y += f' - l*cos(th{i})'
        lines += [f'x{i} = {x}', f'y{i} = {y}', f'particle m at (x{i}, y{i})']
    lines.append('V = ' + ' + '.join(f'm*g*y{i}' for i in range(1, n + 1)))
    lines.append('initial ' + ', '.join(f'th{i} = 0.5' for i in range(1, n + 1)))
    return '\n'.join(lines) + '\n'


def cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def sim(build, model, t_end, method, reps, extra=(), init=None):
    """The least CPU time of reps runs and the JSON of the last."""
    cmd = [os.path.join(build, 'qdot'), 'simulate', model, '--t-end', str(t_end),
           '--method', method, '--format', 'json', '--out', os.devnull, *map(str, extra)]
    if init:
        cmd += ['--initial', init]
    best, d = math.inf, None
    for _ in range(reps):
        c0 = cpu()
        p = subprocess.run(cmd, capture_output=True, text=True)
        best = min(best, cpu() - c0)
        if p.returncode != 0:
            raise RuntimeError(' '.join(cmd) + ': ' + p.stderr[:300])
        d = json.loads(p.stdout)
    d['cpu'] = best
    return d


def tol(t):
    return ['--rtol', t, '--atol', t]


def claim(build, reps, t_end):
    print(f'## 1. The {t_end:g} s double pendulum from (pi/2, pi/2)\n')
    print('| method | tolerance | CPU s | steps | evaluations | energy error |')
    print('|---|---|---|---|---|---|')
    rows = {}
    for method, t in (('taylor', 1e-15), ('dop853', 1e-12)):
        d = sim(build, DP, t_end, method, reps, tol(t) + ['--dt', t_end], DP_INIT)
        rows[method] = d
        print(f"| {method} | {t:g} | {d['cpu']:.3f} | {d['steps']} | {d['evaluations']} | "
              f"{d['energy_error_max']:.2g} |")
    # --native: the recurrences as generated C; one run first to compile (or find) the object
    nat = tol(1e-15) + ['--dt', t_end, '--native']
    sim(build, DP, t_end, 'taylor', 1, nat, DP_INIT)
    tn = sim(build, DP, t_end, 'taylor', reps, nat, DP_INIT)
    print(f"| taylor --native | 1e-15 | {tn['cpu']:.3f} | {tn['steps']} | {tn['evaluations']} | "
          f"{tn['energy_error_max']:.2g} |")
    ta, do = rows['taylor'], rows['dop853']
    ratio = do['cpu'] / ta['cpu'] if ta['cpu'] > 0 else math.inf
    ok = ta['energy_error_max'] < 1e-13 and ratio > 1
    print(f"\ntaylor is {ratio:.2f}x as fast as dop853 with {do['energy_error_max'] / ta['energy_error_max']:.3g}x "
          f"smaller energy error: the claim {'holds' if ok else 'FAILS'}\n")
    same = tn['final'] == ta['final'] and tn['steps'] == ta['steps']
    print(f"taylor --native is {ta['cpu'] / tn['cpu'] if tn['cpu'] > 0 else math.inf:.2f}x as fast "
          f"as the interpreted recurrences, {do['cpu'] / tn['cpu'] if tn['cpu'] > 0 else math.inf:.2f}x "
          f"as dop853; final state {'identical' if same else 'DIFFERENT'}\n")
    return ok and same


def state(d):
    f = d['final']
    return [f['theta1'], f['theta2'], f["theta1'"], f["theta2'"]]


def table(build, reps, t_end):
    print(f'## 2. Cost against accuracy: the double pendulum, {t_end:g} s (energy), 10 s (state)\n')
    ref = state(sim(build, DP, 10, 'taylor', 1, tol(1e-30) + ['--dt', 10, '--precision', 128],
                    DP_INIT))
    runs = [('taylor', tol(t), f'rtol {t:g}') for t in (1e-9, 1e-12, 1e-15)]
    runs += [('dop853', tol(t), f'rtol {t:g}') for t in (1e-9, 1e-12, 1e-14)]
    runs += [('gl6', ['--dt', h], f'dt {h:g}') for h in (1e-2, 3e-3, 1e-3)]
    runs += [('bdf', tol(t), f'rtol {t:g}') for t in (1e-6, 1e-9, 1e-11)]
    print('| method | setting | CPU s | steps | energy error | state error at t = 10 |')
    print('|---|---|---|---|---|---|')
    for method, args, label in runs:
        grid = [] if method == 'gl6' else ['--dt', t_end]
        d = sim(build, DP, t_end, method, reps, args + grid, DP_INIT)
        early = sim(build, DP, 10, method, 1, args + ([] if method == 'gl6' else ['--dt', 10]),
                    DP_INIT)
        err = max(abs(a - b) for a, b in zip(state(early), ref))
        print(f"| {method} | {label} | {d['cpu']:.3f} | {d['steps']} | "
              f"{d['energy_error_max']:.2g} | {err:.2g} |")
    print()


def others(build, reps, n_orbits, tmp):
    print('## 3. The 20-link pendulum (10 s) and Kepler e = 0.9 (%d orbits)\n' % n_orbits)
    ch = os.path.join(tmp, 'chain20.qd')
    with open(ch, 'w') as f:
        f.write(chain(20))
    kp = os.path.join(tmp, 'kepler.qd')
    with open(kp, 'w') as f:
        f.write(KEPLER)
    T = 2 * math.pi
    print('CPU s: the run less the same command with --t-end 1e-9 (the 20-link '
          "pendulum's derivation is most of a short run)\n")
    print('| problem | method | tolerance | CPU s | steps | energy error | error at the end |')
    print('|---|---|---|---|---|---|---|')
    for name, model, t_end in (('20-link', ch, 10), ('Kepler', kp, n_orbits * T)):
        for method, t in (('taylor', 1e-15), ('dop853', 1e-12), ('dop853', 1e-15)):
            base = sim(build, model, 1e-9, method, reps, tol(t))['cpu']
            d = sim(build, model, t_end, method, reps, tol(t) + ['--dt', t_end])
            f = d['final']
            end = math.hypot(f['x'] - 0.1, f['y']) if name == 'Kepler' else float('nan')
            print(f"| {name} | {method} | {t:g} | {max(d['cpu'] - base, 0):.3f} | {d['steps']} | "
                  f"{d['energy_error_max']:.2g} | {end:.2g} |")
    print()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('build')
    ap.add_argument('--reps', type=int, default=3)
    ap.add_argument('--quick', action='store_true', help='100 s and 100 orbits, one run each')
    a = ap.parse_args()
    reps = 1 if a.quick else a.reps
    t_end = 100 if a.quick else 1000
    ok = claim(a.build, reps, t_end)
    table(a.build, reps, t_end)
    with tempfile.TemporaryDirectory() as tmp:
        others(a.build, reps, 100 if a.quick else 1000, tmp)
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
