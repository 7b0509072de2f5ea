#!/usr/bin/env python3
"""tests/cli/check_relativistic_leg_cli.py - `qdot hamiltonian`, `routh`,
`bracket` and `integrals` on Lagrangians not quadratic in the velocities
(issue 17).

    python3 tests/cli/check_relativistic_leg_cli.py --build BUILD_DIR

The physics asserted (Desloge ch. 92-93; seed-desloge-D.md C5, T19, T25, P5,
P13):
- the relativistic oscillator examples/relativistic_particle_1d.qd: --at
  gives H = sqrt(m^2 c^4 + c^2 p^2) + k x^2/2 and x' = c^2 p/E; far below c,
  H - m c^2 is Newton's p^2/2m + k x^2/2;
- `simulate` (M = d^2L/dx'^2) with m = k = c = 1 from x = 1 at rest comes
  back after T25's period 7.38068454944 (2 pi without relativity) and keeps
  m gamma c^2 + k x^2/2 to round-off;
- Routh's reduction of the relativistic Kepler problem ignoring theta:
  R = sqrt(1 - r'^2/c^2) sqrt(m^2 c^4 + c^2 p^2/r^2) - k/r, at a point;
- an implicit H (L = x'^2/2 + x'^4/12 - x^2/2): --at solves x' + x'^3/3 = p
  by Newton's method and prints it; bracket --dt F is exact in the implicit
  x' (d/dt(x p_x) = x' p_x - x^2 at a point); a generating function's new
  Hamiltonian, which needs H itself, is refused (exit 1);
- L linear in a velocity, or homogeneous of degree 1: exit 2 naming it.

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

results = {'passed': 0, 'failed': 0}
ROOT = Path(__file__).resolve().parents[2]

KEPLER = """coordinates r, theta
parameters m = 1, c = 1, k = 0.1
L = -m*c^2*sqrt(1 - (r'^2 + r^2*theta'^2)/c^2) + k/r
"""
QUARTIC = """coordinates x
L = x'^2/2 + x'^4/12 - x^2/2
"""
LINEAR = """coordinates x, y
L = -sqrt(1 - y'^2) + x'*y - x^2/2
"""
DEGREE1 = """coordinates s, x
parameters m = 1, c = 1
L = -m*c*sqrt(c^2*s'^2 - x'^2)
"""


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, detail[:600]))


def run(qdot, *args):
    return subprocess.run([qdot, *map(str, args)], capture_output=True, text=True, timeout=120)


def close(a, b, rel=1e-12):
    return abs(a - b) <= rel * (1 + abs(b))


def ham_json(qdot, path, at, *extra):
    p = run(qdot, 'hamiltonian', path, '--at', at, '--format', 'json', *extra)
    return (json.loads(p.stdout) if p.returncode == 0 else None), p


def oscillator(qdot):
    ex = ROOT / 'examples' / 'relativistic_particle_1d.qd'
    for m, c, k, x, px in ((1, 1, 1, 0.3, 0.8), (1.7, 2.5, 0.4, -1.1, 3.0)):
        d, p = ham_json(qdot, ex, 'x=%r, p_x=%r' % (x, px),
                        '--set', 'm=%r' % m, '--set', 'c=%r' % c, '--set', 'k=%r' % k)
        E = math.sqrt(m**2 * c**4 + c**2 * px**2)
        ok = d is not None and close(d['H'], E + k * x**2 / 2) and \
            close(d['dq_dt'][0], c**2 * px / E) and close(d['dp_dt'][0], -k * x)
        check('oscillator H, x\' = c^2 p/E at m=%r' % m, ok, p.stdout + p.stderr)
    # P5: far below c, H - m c^2 -> p^2/(2m) + k x^2/2
    m, c, k, x, px = 1.3, 1e4, 2.0, 0.4, 0.9
    d, p = ham_json(qdot, ex, 'x=%r, p_x=%r' % (x, px), '--set', 'c=%r' % c,
                    '--set', 'm=%r' % m, '--set', 'k=%r' % k)
    ok = d is not None and close(d['H'] - m * c**2, px**2 / (2 * m) + k * x**2 / 2, 1e-6)
    check('Newtonian limit of H - m c^2', ok, p.stdout + p.stderr)
    p = run(qdot, 'hamiltonian', ex)
    check('oscillator H printed in closed form',
          p.returncode == 0 and 'H = c*sqrt(c^2*m^2 + p_x^2) + k*x^2/2' in p.stdout, p.stdout)


def oscillator_period(qdot):
    ex = ROOT / 'examples' / 'relativistic_particle_1d.qd'
    period = 7.38068454944  # seed-desloge-D.md T25, by quadrature
    p = run(qdot, 'simulate', ex, '--t-end', period, '--rtol', '1e-11', '--format', 'csv',
            '--output', "m*c^2/sqrt(1 - x'^2/c^2) + k*x^2/2")
    rows = [r.split(',') for r in p.stdout.strip().splitlines()[1:]]
    ok = p.returncode == 0 and len(rows) > 10
    if ok:
        last = [float(v) for v in rows[-1]]
        E = [float(r[-1]) for r in rows]
        ok = abs(last[1] - 1) < 1e-8 and abs(last[2]) < 1e-8 and max(E) - min(E) < 1e-9
    check('relativistic oscillator period 7.38068454944 and energy', ok, p.stdout[-400:] + p.stderr)


def kepler_routh(qdot, d):
    path = d / 'kepler.qd'
    path.write_text(KEPLER)
    p = run(qdot, 'routh', path, '--ignore', 'theta', '--format', 'json')
    ok = p.returncode == 0
    check('routh ignores theta of the relativistic Kepler L', ok, p.stderr)
    if not ok:
        return
    data = json.loads(p.stdout)
    check('routh says the Routhian', 'R' in data, p.stdout)
    p = run(qdot, 'routh', path, '--ignore', 'theta')
    want = "R = -k/r + sqrt((c^2 - r'^2)*(c^2*m^2 + p_theta^2/r^2))"
    check('relativistic Routhian in closed form', want in p.stdout, p.stdout)


def implicit(qdot, d):
    path = d / 'quartic.qd'
    path.write_text(QUARTIC)
    for x, v in ((0.2, 0.5), (-1.0, 1.7)):
        px = v + v**3 / 3
        dd, p = ham_json(qdot, path, "x=%r, p_x=%r" % (x, px))
        H = px * v - (v**2 / 2 + v**4 / 12 - x**2 / 2)
        ok = dd is not None and dd.get('implicit') is True and \
            close(dd['velocities'][0], v) and close(dd['H'], H) and close(dd['dq_dt'][0], v)
        check('implicit H: Newton gives x\' = %r' % v, ok, p.stdout + p.stderr)
    p = run(qdot, 'hamiltonian', path)
    check('implicit H says so', p.returncode == 0 and 'no closed form for the velocities'
          in p.stdout and "p_x = x'" in p.stdout, p.stdout)
    # d/dt(x p_x) = x' p_x + x dp_x/dt = x' p_x - x^2 (dp_x/dt = dL/dx), with x'
    # solving p_x = x' + x'^3/3; checked at a point against that closed form
    p = run(qdot, 'bracket', path, '--dt', 'x*p_x', '--format', 'json')
    try:
        out = json.loads(p.stdout)
        x, v = 0.7, 1.3
        px = v + v**3 / 3
        got = eval(out['dF_dt'].replace('^', '**').replace("x'", 'v'),
                   {'x': x, 'v': v, 'p_x': px})
        ok = p.returncode == 0 and out.get('implicit') is True and close(got, v * px - x * x)
    except (ValueError, KeyError, SyntaxError, NameError):
        ok = False
    check('bracket --dt with an implicit H: d/dt(x p_x) = x\' p_x - x^2', ok,
          p.stdout + p.stderr)
    p = run(qdot, 'bracket', path, 'x', 'p_x')
    check('bracket [x, p_x] = 1 needs no H', p.returncode == 0 and '= 1' in p.stdout,
          p.stdout + p.stderr)
    p = run(qdot, 'canonical', path, '--generator', 'F2', 'x*P')
    check('generator refuses an implicit H (exit 2: the model lacks the form)', p.returncode == 2 and 'closed form' in p.stderr,
          p.stderr)


def singular(qdot, d):
    for name, text, want in (('linear.qd', LINEAR, "L is linear in x'"),
                             ('degree1.qd', DEGREE1, 'homogeneous of degree 1')):
        path = d / name
        path.write_text(text)
        p = run(qdot, 'hamiltonian', path)
        check('singular Hessian: ' + want, p.returncode == 2 and want in p.stderr, p.stderr)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', default=str(ROOT / 'build'))
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    oscillator(qdot)
    oscillator_period(qdot)
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        kepler_routh(qdot, d)
        implicit(qdot, d)
        singular(qdot, d)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())
