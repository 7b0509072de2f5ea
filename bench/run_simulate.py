#!/usr/bin/python3
"""The 1000 s double-pendulum run (examples/double_pendulum.qd) with an
8th-order Dormand-Prince pair at rtol = atol = 1e-12, three ways in one run:

  qdot     build/qdot simulate --method dop853 (with and without --native), a
           CSV row per step to /dev/null; and with --dt T_END, rows at the
           start and end only, as GSL and SciPy keep no trajectory
  SciPy    solve_ivp(method='DOP853') on a SymPy-lambdified rhs
           (bench/rhs_sympy.py's derivation, cse=True)
  GSL      gsl_odeiv2 rk8pd with the hand-written rhs (bench/sim_gsl.c)
  CVODE    SUNDIALS CVODE, Adams with fixed-point iteration, the same rhs
           (bench/sim_cvode.c)

Usage: run_simulate.py BUILD_DIR [--t-end T] [--no-scipy] [--scipy-limit S]

Reports wall time, steps, evaluations, the energy error and the final state's
distance from GSL's.  SciPy is skipped when it exceeds --scipy-limit
(default 600 s).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
MODEL = os.path.join(ROOT, 'examples', 'double_pendulum.qd')
TOL = 1e-12


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def energy(y):
    c = math.cos(y[0] - y[1])
    return y[2]**2 + 0.5 * y[3]**2 + y[2] * y[3] * c - 2 * 9.81 * math.cos(y[0]) \
        - 9.81 * math.cos(y[1])


def qdot_run(build, t_end, native, rows=True):
    cmd = [os.path.join(build, 'qdot'), 'simulate', MODEL, '--t-end', str(t_end), '--rtol',
           str(TOL), '--atol', str(TOL), '--method', 'dop853', '--format', 'json',
           '--out', os.devnull] + (['--native'] if native else []) + \
          ([] if rows else ['--dt', str(t_end)])
    t0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        raise RuntimeError('qdot simulate: %s' % p.stderr[:400])
    d = json.loads(p.stdout)
    f = d['final']
    return {'wall': wall, 'int_s': d['wall_s'], 'steps': d['steps'], 'evals': d['evaluations'],
            'rejected': d['rejected'], 'energy': d['energy_error_max'],
            'final': [f['theta1'], f['theta2'], f["theta1'"], f["theta2'"]],
            'note': p.stderr.strip().splitlines()[0] if p.stderr.strip() else ''}


def gsl_run(build, t_end, prog='sim_gsl'):
    exe = os.path.join(build, 'bench', prog)
    t0 = time.perf_counter()
    p = subprocess.run([exe, str(t_end), str(TOL), str(TOL)], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        raise RuntimeError('%s: %s' % (prog, p.stderr[:400]))
    kv = dict(line.split(' ', 1) for line in p.stdout.splitlines())
    return {'wall': wall, 'int_s': float(kv['wall_s']), 'steps': int(kv['steps']),
            'evals': int(kv['evaluations']), 'rejected': int(kv['rejected']),
            'energy': float(kv['energy_error']),
            'final': [float(x) for x in kv['final'].split()], 'note': ''}


SCIPY = r'''
import json, math, sys, time
sys.path.insert(0, %r)
import numpy as np
from scipy.integrate import solve_ivp
import rhs_sympy
t0 = time.perf_counter()
fn = rhs_sympy.derive(2)
build = time.perf_counter() - t0
p = [1, 1, 1, 1, 9.81]
def rhs(t, y):
    M, f = fn(y[:2], y[2:], p)
    return np.concatenate([y[2:], np.linalg.solve(np.array(M), np.array(f))])
t0 = time.perf_counter()
r = solve_ivp(rhs, (0, %r), [0.5, 0, 0, 0], method='DOP853', rtol=%r, atol=%r)
wall = time.perf_counter() - t0
print(json.dumps({'build': build, 'int_s': wall, 'steps': len(r.t) - 1, 'evals': int(r.nfev),
                  'final': list(r.y[:, -1]), 'status': r.status,
                  'ys': [list(r.y[:, k]) for k in range(0, r.y.shape[1], 97)]}))
'''


def scipy_run(t_end, limit):
    t0 = time.perf_counter()
    p = subprocess.run(['/usr/bin/python3', '-c', SCIPY % (HERE, t_end, TOL, TOL)],
                       capture_output=True, text=True, timeout=limit)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        raise RuntimeError('scipy: %s' % p.stderr[-400:])
    d = json.loads(p.stdout)
    e0 = energy([0.5, 0, 0, 0])
    err = max(abs(energy(y) - e0) for y in d['ys'] + [d['final']]) / abs(e0)
    return {'wall': wall, 'int_s': d['int_s'], 'steps': d['steps'], 'evals': d['evals'],
            'rejected': None, 'energy': err, 'final': d['final'],
            'note': 'SymPy derivation + lambdify %.2f s' % d['build']}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('build')
    ap.add_argument('--t-end', type=float, default=1000.0)
    ap.add_argument('--no-scipy', action='store_true')
    ap.add_argument('--scipy-limit', type=float, default=600.0)
    a = ap.parse_args()
    rows = []
    log('running qdot simulate --native')
    rows.append(('qdot dop853 --native', qdot_run(a.build, a.t_end, True)))
    log('running qdot simulate')
    rows.append(('qdot dop853 (compiled program)', qdot_run(a.build, a.t_end, False)))
    log('running qdot simulate --native --dt T_END')
    rows.append(('qdot dop853 --native, no rows', qdot_run(a.build, a.t_end, True, False)))
    log('running GSL rk8pd')
    gsl = gsl_run(a.build, a.t_end)
    rows.append(('GSL rk8pd, hand-written C rhs', gsl))
    log('running SUNDIALS CVODE (Adams)')
    rows.append(('CVODE Adams, hand-written C rhs', gsl_run(a.build, a.t_end, 'sim_cvode')))
    if not a.no_scipy:
        log('running SciPy DOP853 (limit %g s)' % a.scipy_limit)
        try:
            rows.append(('SciPy DOP853, lambdified SymPy rhs', scipy_run(a.t_end, a.scipy_limit)))
        except subprocess.TimeoutExpired:
            rows.append(('SciPy DOP853, lambdified SymPy rhs', None))
    print('\nDouble pendulum, t = 0..%g, rtol = atol = %g' % (a.t_end, TOL))
    print('%-36s %10s %10s %8s %9s %9s %10s %10s' % ('program', 'integrate', 'process', 'steps',
                                                   'evals', 'rejected', 'energy err',
                                                   '|y - y_gsl|'))
    for name, r in rows:
        if r is None:
            print('%-36s  > %g s (not finished)' % (name, a.scipy_limit))
            continue
        dist = max(abs(x - y) for x, y in zip(r['final'], gsl['final']))
        print('%-36s %9.3fs %9.3fs %8d %9d %9s %10.2g %10.2g' % (
            name, r['int_s'], r['wall'], r['steps'], r['evals'],
            '-' if r['rejected'] is None else r['rejected'], r['energy'], dist))
    for name, r in rows:
        if r and r['note']:
            print('%s: %s' % (name, r['note']))
    sp = rows[-1][1] if not a.no_scipy and rows[-1][0].startswith('SciPy') else None
    for name, r in rows[:3]:
        line = '%s: integration %.2fx GSL\'s time' % (name, r['int_s'] / gsl['int_s'])
        if sp:
            line += ('; SciPy\'s integration takes %.0fx its integration, %.0fx its whole '
                     'process' % (sp['int_s'] / r['int_s'], sp['int_s'] / r['wall']))
        print(line)
    return 0


if __name__ == '__main__':
    sys.exit(main())
