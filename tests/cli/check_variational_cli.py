#!/usr/bin/env python3
"""Tests of `qdot simulate --variational`: the flow Jacobian, run against the
built program.

    python3 tests/cli/check_variational_cli.py --build BUILD_DIR

- The harmonic oscillator x'' = -w^2 x: d(x, x')(t)/d(x, x')(0) is the closed
  form [[cos wt, sin(wt)/w], [-w sin wt, cos wt]].
- The double pendulum (examples/double_pendulum.qd; Goldstein ch. 1 Ex. 22,
  seed 002): every column equals the central difference of two runs from
  initial states displaced by +-h along that component.
- Lagrange's bilinear invariant (Britannica 1911 "Dynamics" sec. 9 eq. 1,
  seed 004): in (q, p) the double pendulum's Jacobian is symplectic,
  |Phi^T J Phi - J| ~ 1e-10.
- Helmholtz's reciprocal theorems (ibid. sec. 9; reference
  seed-goldstein-britannica.md C15, P14): the reversed motion, started from
  the direct one's end with every velocity reversed, has the blocks
  d q/d p and d p/d q of the direct motion transposed, and its d q/d q and
  d p/d p are the direct d p/d p and d q/d q transposed (Phi_rev =
  [[D^T, B^T], [C^T, A^T]] for Phi = [[A, B], [C, D]]).
- A periodic orbit of the pendulum (period 4 K(sin^2(th0/2)) sqrt(l/g)):
  both Floquet multipliers are 1 and the monodromy matrix is not the
  identity (a Jordan block: the period changes with the energy); its rows
  every T/8 over --period T end where they began.
- Liouville: the damped oscillator's det = exp(-b t/m) (examples/
  damped_oscillator.qd; Goldstein sec. 1.5), and --variational columns
  prints t, the state and the columns, the first row the identity.
- Errors (exit 2): --period with --t-end; --variational columns with JSON.

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path



def ellipk(m):
    """K(m) = pi / (2 agm(1, sqrt(1 - m))), the complete elliptic integral."""
    a, b = 1.0, math.sqrt(1 - m)
    for _ in range(40):  # quadratic convergence: 6 would do
        a, b = (a + b) / 2, math.sqrt(a * b)
    return math.pi / (2 * a)

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
results = {'passed': 0, 'failed': 0}


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, detail))


def sim(qdot, *args):
    p = subprocess.run([qdot, 'simulate', *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def flow(qdot, model, *args):
    rc, out, err = sim(qdot, str(model), '--variational', '--format', 'json', '--rtol', '1e-12',
                       *args)
    if rc:
        check('simulate --variational %s %s' % (model, ' '.join(args)), False, err)
        return None
    return json.loads(out)


def maxdiff(A, B):
    return max(abs(a - b) for ra, rb in zip(A, B) for a, b in zip(ra, rb))


def oscillator(qdot, tmp):
    model = tmp / 'ho.qd'
    model.write_text('coordinates x\nparameters m = 1, k = 4\nT = m/2*x\'^2\nV = k/2*x^2\n'
                     'initial x = 1, x\' = 0\n')
    d = flow(qdot, model, '--t-end', '1.3')
    if not d:
        return
    w, t = 2.0, 1.3
    want = [[math.cos(w * t), math.sin(w * t) / w], [-w * math.sin(w * t), math.cos(w * t)]]
    check('oscillator: rotation matrix', maxdiff(d['flow_jacobian'], want) < 1e-9,
          d['flow_jacobian'])
    check('oscillator: hamiltonian', d['hamiltonian'] is True)


def final_state(qdot, model, init, t_end):
    rc, out, err = sim(qdot, str(model), '--t-end', str(t_end), '--rtol', '1e-12', '--format',
                       'json', '--initial', init)
    if rc:
        return None
    f = json.loads(out)['final']
    return [f['theta1'], f['theta2'], f["theta1'"], f["theta2'"]]


def double_pendulum(qdot):
    model = EXAMPLES / 'double_pendulum.qd'
    y0 = [0.5, 0.0, 0.0, 0.0]
    keys = ['theta1', 'theta2', "theta1'", "theta2'"]
    T = 1.5
    d = flow(qdot, model, '--t-end', str(T))
    if not d:
        return
    phi = d['flow_jacobian']
    h = 1e-5
    worst = 0
    for j in range(4):
        ends = []
        for s in (1, -1):
            y = list(y0)
            y[j] += s * h
            ends.append(final_state(qdot, model, ', '.join('%s=%.17g' % (k, v)
                                                          for k, v in zip(keys, y)), T))
        if None in ends:
            check('double pendulum: displaced runs', False)
            return
        for i in range(4):
            fd = (ends[0][i] - ends[1][i]) / (2 * h)
            worst = max(worst, abs(fd - phi[i][j]) / (1 + abs(phi[i][j])))
    check('double pendulum: columns = central differences', worst < 1e-5, worst)
    check('double pendulum: symplectic in (q, p)', d['symplectic_error'] < 1e-9,
          d['symplectic_error'])
    # Helmholtz: the reversed motion from the direct one's end
    f = d['final']
    rev = 'theta1=%.17g, theta2=%.17g, theta1\'=%.17g, theta2\'=%.17g' % (
        f['theta1'], f['theta2'], -f["theta1'"], -f["theta2'"])
    r = flow(qdot, model, '--t-end', str(T), '--initial', rev)
    if not r:
        return
    P, R = d['flow_jacobian_canonical'], r['flow_jacobian_canonical']
    n = 2

    def block(M, a, b):
        return [[M[a * n + i][b * n + j] for j in range(n)] for i in range(n)]

    def tr(M):
        return [list(x) for x in zip(*M)]

    # p -> -p maps Phi to S Phi S, S = diag(I, -I): the reversed blocks
    ok = (maxdiff(block(R, 0, 1), tr(block(P, 0, 1))) < 1e-8 and
          maxdiff(block(R, 1, 0), tr(block(P, 1, 0))) < 1e-8 and
          maxdiff(block(R, 0, 0), tr(block(P, 1, 1))) < 1e-8 and
          maxdiff(block(R, 1, 1), tr(block(P, 0, 0))) < 1e-8)
    check('Helmholtz reciprocity: reversed blocks are the direct ones transposed', ok,
          '%s vs %s' % (R, P))
    check('reversed run returns to the start', abs(r['final']['theta1'] - 0.5) < 1e-8,
          r['final'])


def pendulum(qdot, tmp):
    model = tmp / 'pendulum.qd'
    model.write_text('coordinates th\nparameters m = 1, l = 1, g = 9.81\n'
                     'T = m*l^2/2*th\'^2\nV = -m*g*l*cos(th)\ninitial th = 1, th\' = 0\n')
    period = 4 * ellipk(math.sin(0.5) ** 2) * math.sqrt(1 / 9.81)
    d = flow(qdot, model, '--period', '%.17g' % period)
    if not d:
        return
    mu = d['multipliers']
    check('pendulum: both multipliers 1', all(abs(re - 1) < 1e-6 and abs(im) < 1e-6
                                              for re, im in mu), mu)
    M = d['monodromy']
    off = max(abs(M[0][1]), abs(M[1][0]))
    check('pendulum: a Jordan block (monodromy != I)', off > 0.1, M)
    check('pendulum: closure', d['closure'] < 1e-8, d['closure'])
    # rows every T/8 over the period: counted over T, and back at the start
    rc, out, err = sim(qdot, str(model), '--period', '%.17g' % period, '--dt',
                       '%.17g' % (period / 8), '--rtol', '1e-12')
    rows = [[float(v) for v in ln.split(',')] for ln in out.splitlines()[1:]] if rc == 0 else []
    check('--period with --dt: rows over one period', len(rows) in (9, 10) and
          abs(rows[-1][0] - period) < 1e-12 and abs(rows[-1][1] - 1) < 1e-8 and
          abs(rows[-1][2]) < 1e-8, err or rows[-1:])


def damped(qdot):
    model = EXAMPLES / 'damped_oscillator.qd'
    d = flow(qdot, model, '--t-end', '2')
    if not d:
        return
    want = math.exp(-0.4 * 2 / 1.2)
    check('damped: det = exp(-b t/m)', abs(d['flow_det'] - want) < 1e-9, d['flow_det'])
    check('damped: not hamiltonian', d['hamiltonian'] is False and d['symplectic_error'] is None)
    rc, out, err = sim(qdot, str(model), '--t-end', '2', '--dt', '0.5', '--variational',
                       'columns')
    lines = out.splitlines()
    check('columns: header', rc == 0 and lines[0] == "t,x,x',dx/dx0,dx'/dx0,dx/dx'0,dx'/dx'0",
          out + err)
    check('columns: identity at t0', rc == 0 and lines[1] == '0,1,0,1,0,0,1', lines[:2])
    check('columns: 5 rows', rc == 0 and len(lines) == 6, len(lines))


def errors(qdot):
    model = EXAMPLES / 'damped_oscillator.qd'
    rc, _, err = sim(qdot, str(model), '--t-end', '1', '--period', '1')
    check('--period with --t-end: exit 2', rc == 2, err)
    rc, _, err = sim(qdot, str(model), '--t-end', '1', '--variational', 'columns', '--format',
                     'json')
    check('columns with json: exit 2', rc == 2, err)
    rc, _, err = sim(qdot, str(model), '--period', '-1')
    check('--period -1: exit 2', rc == 2, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        oscillator(qdot, tmp)
        double_pendulum(qdot)
        pendulum(qdot, tmp)
        damped(qdot)
        errors(qdot)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())
