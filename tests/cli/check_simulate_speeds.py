#!/usr/bin/env python3
"""End-to-end checks of `qdot simulate` on models with generalized speeds
(issue 15; seed-desloge-C.md ch. 67-70).

Physics checked:
- the rolling disk (examples/rolling_disk_tilted.qd with the body components
  of its angular velocity as speeds, Desloge ch. 64 and 69): the motion in
  speeds and in the multiplier form (--no-speeds) agree to 1e-9 at t = 2,
  the energy is conserved and the rolling constraints' residuals stay at
  round-off in every row;
- the knife edge at its centre of mass (Neimark and Fufaev ch. II): v and
  w constant, the centre on the circle of radius v/w in every row, to 1e-10;
- the Chaplygin sleigh: v = V tanh(c V t + atanh(v0/V)), c = m b/(J + m b^2),
  V^2 = 2E/m (the derivation is in tests/sim/test_sim_speeds.c), with bdf
  and gl4, and the time theta reaches 1 (--stop-at) by the Gudermannian;
- Euler's free rigid body (Desloge ch. 68 Ex. 2): energy and |L| = |I w|
  conserved in every row;
- the columns, initial speeds from --initial, a speed's name in --output,
  and the exit statuses: verlet (1), impacts (2).
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

DISK = """coordinates x, y, z, phi, theta, psi
parameters m = 1.4, a = 0.35, g = 9.81
body disk mass m inertia disk(m, a) at (x, y, z) orientation euler(phi, theta, psi)
V = m*g*z
rolls disk on plane((0, 0, 1), (0, 0, 0)) as disk(a)
speeds w1 = omega(disk).x, w2 = omega(disk).y, w3 = omega(disk).z
initial x = 0, y = 0, z = 0.3, phi = 0, theta = 1.0, psi = 0, phi' = 0.8, theta' = 0, psi' = 4
"""

SLEIGH = """coordinates x, y, theta
parameters m = 2, J = 0.3, b = {b}
T = m/2*(x'^2 + y'^2) + J/2*theta'^2
constraint knife: cos(theta)*y' - sin(theta)*x' = b*theta'
speeds v = cos(theta)*x' + sin(theta)*y', w = theta'
initial x = 0.2, y = -0.1, theta = 0.3, v = {v}, w = {w}
"""

BODY = """coordinates phi, theta, psi
parameters A = 1, B = 2, C = 3
body b mass 1 inertia (A, B, C) at (0, 0, 0) orientation euler(phi, theta, psi)
speeds w1 = omega(b).x, w2 = omega(b).y, w3 = omega(b).z
initial phi = 0.1, theta = 1.0, psi = -0.4, w1 = 0.3, w2 = -0.2, w3 = 2
"""


def run(qdot, *args):
    p = subprocess.run([str(qdot), *map(str, args)], capture_output=True, text=True,
                       timeout=120)
    return p.returncode, p.stdout, p.stderr


def rows(text):
    r = list(csv.reader(io.StringIO(text)))
    return r[0], [[float(x) for x in row] for row in r[1:]]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = Path(ap.parse_args().build).resolve() / 'qdot'
    failures = []
    tmp = Path(tempfile.mkdtemp(prefix='qdot-speeds-'))

    def check(cond, what):
        if not cond:
            failures.append(what)

    def model(name, text):
        p = tmp / name
        p.write_text(text)
        return p

    # the rolling disk: columns, residuals, energy; the same motion as --no-speeds
    disk = model('disk.qd', DISK)
    rc, out, err = run(qdot, 'simulate', disk, '--t-end', 2, '--rtol', 1e-13)
    check(rc == 0, f'disk: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        check(head[:17] == ['t', 'x', 'y', 'z', 'phi', 'theta', 'psi', 'w1', 'w2', 'w3',
                            "x'", "y'", "z'", "phi'", "theta'", "psi'", 'energy'],
              f'disk header {head}')
        res = [i for i, h in enumerate(head) if h.startswith('res_disk_roll')]
        check(len(res) == 2, f'rolling residual columns {head}')
        worst = max(abs(r[i]) for r in data for i in res)
        check(worst < 1e-12, f'rolling residual {worst} with speeds')
        e = head.index('energy')
        drift = max(abs(r[e] - data[0][e]) for r in data)
        check(drift < 1e-10 * abs(data[0][e]), f'disk energy drift {drift}')
    finals = []
    for extra in ([], ['--no-speeds']):
        rc, out, err = run(qdot, 'simulate', disk, '--t-end', 2, '--rtol', 1e-13, '--format',
                           'json', '--out', '/dev/null', *extra)
        check(rc == 0, f'disk json {extra}: {rc} {err}')
        if rc == 0:
            j = json.loads(out)
            check(j['speeds'] == (not extra), f'"speeds" is {j["speeds"]} with {extra}')
            finals.append(j['final'])
    if len(finals) == 2:
        for name in ('x', 'y', 'z', 'phi', 'theta', 'psi', "phi'", "psi'"):
            d = abs(finals[0][name] - finals[1][name])
            check(d < 1e-9, f'disk {name}: speeds and multipliers differ by {d}')

    # the knife edge at its centre of mass: an exact circle
    v, w = 0.7, 1.3
    knife = model('knife.qd', SLEIGH.format(b=0, v=v, w=w))
    rc, out, err = run(qdot, 'simulate', knife, '--t-end', 10, '--dt', 0.05, '--rtol', 1e-13,
                       '--method', 'dop853')
    check(rc == 0, f'knife: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        R = v / w
        xc, yc = 0.2 - R * math.sin(0.3), -0.1 + R * math.cos(0.3)
        off = max(abs(math.hypot(r[1] - xc, r[2] - yc) - R) for r in data)
        check(len(data) == 201 and off < 1e-10, f'knife: {len(data)} rows, off circle {off}')
        spread = max(abs(r[4] - v) + abs(r[5] - w) for r in data)
        check(spread < 1e-12, f'knife: v, w not constant ({spread})')

    # the Chaplygin sleigh against its closed form, with bdf and gl4
    m, J, b, v0, w0 = 2, 0.3, 0.4, -0.3, 1.5
    E = m / 2 * (v0 ** 2 + b ** 2 * w0 ** 2) + J / 2 * w0 ** 2
    V, c = math.sqrt(2 * E / m), m * b / (J + m * b * b)
    sleigh = model('sleigh.qd', SLEIGH.format(b=b, v=v0, w=w0))
    for args, tol in ((['--method', 'bdf', '--rtol', 1e-10, '--dt', 0.5], 1e-6),
                      (['--method', 'gl4', '--dt', 0.005], 1e-8)):
        rc, out, err = run(qdot, 'simulate', sleigh, '--t-end', 6, *args)
        check(rc == 0, f'sleigh {args}: {rc} {err}')
        if rc == 0:
            head, data = rows(out)
            worst = max(abs(r[4] - V * math.tanh(c * V * r[0] + math.atanh(v0 / V)))
                        for r in data)
            check(worst < tol, f'sleigh {args[1]}: v off the closed form by {worst}')

    # an event in speeds: theta = 1 where the Gudermannian says,
    # theta - theta0 = w0 cosh(s0)/(c V) (gd(s) - gd(s0)), s = c V t + s0
    rc, out, err = run(qdot, 'simulate', sleigh, '--t-end', 5, '--rtol', 1e-12, '--stop-at',
                       'theta = 1, w > 0', '--format', 'json', '--out', '/dev/null')
    check(rc == 0, f'sleigh event: {rc} {err}')
    if rc == 0:
        s0 = math.atanh(v0 / V)
        g = 2 * math.atan(math.tanh(s0 / 2)) + 0.7 * c * V / (w0 * math.cosh(s0))
        t1 = (2 * math.atanh(math.tan(g / 2)) - s0) / (c * V)
        got = json.loads(out)['final']['t']
        check(abs(got - t1) < 1e-10, f'sleigh: theta = 1 at t = {got}, closed form {t1}')

    # --initial by a speed's name; a speed in --output is its definition
    rc, out, err = run(qdot, 'simulate', sleigh, '--t-end', 1, '--dt', 0.5, '--initial',
                       'w = 0.25', '--output', 'v*w, w')
    check(rc == 0, f'sleigh --initial: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        check(head[-2:] == ['v*w', 'w'], f'output columns {head}')
        check(data[0][5] == 0.25 and data[0][4] == v0, f'initial speeds {data[0][4:6]}')
        for r in data:
            check(abs(r[-2] - r[4] * r[5]) < 1e-14 and abs(r[-1] - r[5]) < 1e-15,
                  f'output v*w, w at t = {r[0]}')

    # Euler's free rigid body: energy and |L| = |I w| in every row
    body = model('body.qd', BODY)
    rc, out, err = run(qdot, 'simulate', body, '--t-end', 20, '--rtol', 1e-13)
    check(rc == 0, f'body: {rc} {err}')
    if rc == 0:
        head, data = rows(out)
        check(head[4:7] == ['w1', 'w2', 'w3'], f'body header {head}')
        E0 = 0.5 * (0.3 ** 2 + 2 * 0.2 ** 2 + 3 * 4)
        L0 = math.sqrt(0.3 ** 2 + 4 * 0.2 ** 2 + 9 * 4)
        e = head.index('energy')
        for r in data:
            w1, w2, w3 = r[4:7]
            L = math.sqrt(w1 ** 2 + 4 * w2 ** 2 + 9 * w3 ** 2)
            check(abs(L - L0) < 1e-10 * L0 and abs(r[e] - E0) < 1e-10 * E0,
                  f'body at t = {r[0]}: |L| {L} vs {L0}, h {r[e]} vs {E0}')

    # errors: verlet cannot take (q, u); impacts are refused with speeds
    rc, out, err = run(qdot, 'simulate', sleigh, '--t-end', 1, '--dt', 0.1, '--method',
                       'verlet')
    check(rc == 1 and 'dop853' in err and not out, f'verlet: {rc} {err}')
    wall = model('wall.qd', SLEIGH.format(b=b, v=v0, w=w0) +
                 'impact wall: 5 - x >= 0 restitution 1\n')
    rc, out, err = run(qdot, 'simulate', wall, '--t-end', 1)
    check(rc == 2 and '--no-speeds' in err and not out, f'impacts: {rc} {err}')
    rc, out, err = run(qdot, 'simulate', wall, '--t-end', 1, '--no-speeds')
    check(rc == 0, f'impacts --no-speeds: {rc} {err}')
    # an unknown name in --initial is named as --initial's, with the speeds listed
    rc, out, err = run(qdot, 'simulate', sleigh, '--t-end', 1, '--initial', 'vv=1')
    check(rc == 2 and "--initial:1:1: error: unknown name 'vv'" in err and
          'the speeds are v, w' in err,
          f'--initial unknown name: {rc} {err}')

    shutil.rmtree(tmp, ignore_errors=True)
    for f in failures:
        print('FAIL:', f)
    if len(failures) > 20:
        print(f'... {len(failures)} failures')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
