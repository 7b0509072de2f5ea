#!/usr/bin/env python3
"""`qdot simulate` on models with impacts, end to end.

- examples/bouncing_ball.qd (Newton's law of restitution, Desloge ch. 61;
  Byerly ch. III): the CSV has an `event` column, each impact two rows
  (before, after) at the floor with the velocity reversed by -e; the
  impact times are t1 (1 + 2e + ... + 2e^(n-1)), t1 = sqrt(2h/g); the run
  ends at rest in contact at t* = t1 (1+e)/(1-e) with the chattering
  message; JSON carries impacts, impact_energy_lost (= m g h: all of it)
  and contact.
- --set e=1: no rest, the energy kept, every flight 2 t1.
- examples/rhombus_wall.qd (Desloge ch. 57 ex. 1, reference T55): the row
  after the impact has x' = -3/7, th' = 3/7.
- examples/grazing_disc.qd (issue 33): the grazing pass inside one step of
  free flight gives exactly one impact, at t = 5 - sqrt(1 - b^2), with the
  velocity reflected about the normal there and the energy kept; without
  the disc, --event "x^2 + y^2 = 1" gives both crossings, 5 -+ sqrt(1 - b^2).
- qdot poincare on examples/pendulum_wall.qd: the amplitudes after each
  impact, 1 - cos(a_n) = e^(2n) (1 - cos th0), and no impact rows.
- Errors: a restitution outside [0, 1] (--set e=1.5) and a gap negative at
  t0 (--initial "y = -0.1") exit 2 with the contact named; nothing on
  stdout.

Usage: check_impact_cli.py --build BUILD_DIR
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
G, H, E = 9.81, 1.0, 0.5


def run(qdot, *args):
    p = subprocess.run([qdot, *map(str, args)], capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout, p.stderr


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    args = ap.parse_args()
    qdot = str(Path(args.build).resolve() / 'qdot')
    ball = str(ROOT / 'examples' / 'bouncing_ball.qd')
    rhombus = str(ROOT / 'examples' / 'rhombus_wall.qd')
    failed = []

    def check(cond, what):
        if not cond:
            failed.append(what)
            print('FAIL', what)

    t1 = math.sqrt(2 * H / G)
    tstar = t1 * (1 + E) / (1 - E)

    # the bounces as CSV: samples every 0.25 s, and the impacts' pairs
    rc, out, err = run(qdot, 'simulate', ball, '--t-end', 3, '--method', 'dop853', '--dt', 0.25,
                       '--rtol', 1e-12)
    check(rc == 0, f'ball: exit {rc} {err}')
    r = rows(out)
    imp = [x for x in r if x['event'] == '1']
    check(len(imp) == 2 * 20, f'ball: {len(imp)} impact rows, want 40 (20 impacts)')
    tn = t1
    for n in range(min(8, len(imp) // 2)):
        before, after = imp[2 * n], imp[2 * n + 1]
        t = float(before['t'])
        check(abs(t - tn) <= 1e-12 * tn, f'impact {n + 1} at {t}, want {tn}')
        check(before['t'] == after['t'], f'impact {n + 1}: rows at {before["t"]}, {after["t"]}')
        check(abs(float(before['y'])) < 1e-14, f'impact {n + 1}: y = {before["y"]}')
        vb, va = float(before["y'"]), float(after["y'"])
        check(abs(va + E * vb) <= 1e-12 * abs(vb), f'impact {n + 1}: {vb} -> {va}')
        tn += 2 * t1 * E ** (n + 1)
    last = r[-1]
    check(abs(float(last['t']) - tstar) <= 1e-12 * tstar, f'ball: ends at {last["t"]}, t* {tstar}')
    msg = ("qdot: simulate: impact 'floor': chattering; at rest in contact from t = %.6g after "
           "20 impacts; the run ends there" % tstar)
    check(msg in err.splitlines(), f'ball: message {err!r}')
    check('qdot: simulate: 20 impacts, energy lost 9.81' in err.splitlines(), f'ball: {err!r}')

    # JSON summary
    rc, out, err = run(qdot, 'simulate', ball, '--t-end', 3, '--rtol', 1e-12, '--format', 'json',
                       '--out', '/dev/null')
    check(rc == 0, f'ball json: exit {rc} {err}')
    if rc == 0:
        j = json.loads(out)
        check(j['impacts'] == 20, f'json impacts {j.get("impacts")}')
        check(abs(j['impact_energy_lost'] - G * H) <= 1e-12 * G * H,
              f'json energy lost {j.get("impact_energy_lost")}')
        rest = j['contact']
        check(rest and rest['impact'] == 'floor' and rest['chattering'] and rest['at_rest'] and
              abs(rest['t'] - tstar) <= 1e-12 * tstar, f'json at_rest {rest}')
        check(j['energy_error_max'] < 1e-12, f'json energy error {j["energy_error_max"]}')

    # E = 1: the energy is kept, no rest
    rc, out, err = run(qdot, 'simulate', ball, '--t-end', 10 * t1, '--rtol', 1e-12, '--set', 'e=1',
                       '--format', 'json', '--out', '/dev/null')
    check(rc == 0, f'elastic: exit {rc} {err}')
    if rc == 0:
        j = json.loads(out)
        check(j['impacts'] == 5 and j['contact'] is None, f'elastic: {j["impacts"]} {j["contact"]}')
        check(abs(j['impact_energy_lost']) < 1e-12 and j['energy_error_max'] < 1e-12,
              f'elastic: lost {j["impact_energy_lost"]}, error {j["energy_error_max"]}')

    # Desloge's rhombus (T55): C stops, th'+ = 3/7, x'+ = -3/7
    rc, out, err = run(qdot, 'simulate', rhombus, '--t-end', 1, '--method', 'dop853', '--dt', 0.5,
                       '--rtol', 1e-12)
    check(rc == 0, f'rhombus: exit {rc} {err}')
    imp = [x for x in rows(out) if x.get('event') == '1']
    check(len(imp) == 2, f'rhombus: {len(imp)} impact rows')
    if len(imp) == 2:
        check(abs(float(imp[1]["x'"]) + 3 / 7) < 1e-13 and abs(float(imp[1]["th'"]) - 3 / 7) < 1e-13,
              f'rhombus after: {imp[1]}')
    check('qdot: simulate: 1 impact, energy lost 1.14286' in err.splitlines(), f'rhombus: {err!r}')

    # the grazing disc (issue 33): each step of free flight grows until one
    # spans the whole pass, so only the dense output's samples see it
    graze = ROOT / 'examples' / 'grazing_disc.qd'
    b = 0.9
    w = math.sqrt(1 - b * b)
    rc, out, err = run(qdot, 'simulate', graze, '--t-end', 10, '--rtol', 1e-10)
    check(rc == 0, f'graze: exit {rc} {err}')
    imp = [x for x in rows(out) if x.get('event') == '1']
    check(len(imp) == 2, f'graze: {len(imp)} impact rows, want 2 (1 impact)')
    if len(imp) == 2:
        xc = -w
        vx, vy = 1 - 2 * xc * xc, -2 * xc * b  # v - 2 (v.n) n, n = (x_c, b)
        before, after = imp
        check(abs(float(before['t']) - (5 - w)) < 1e-9 and abs(float(before['x']) - xc) < 1e-9 and
              abs(float(before['y']) - b) < 1e-9, f'graze: impact at {before}')
        check(abs(float(after["x'"]) - vx) < 1e-9 and abs(float(after["y'"]) - vy) < 1e-9,
              f'graze: velocity after {after}, want ({vx}, {vy})')
        check(abs(float(after['energy']) - 0.5) < 1e-12, f'graze: energy {after["energy"]}')
    check(any(line.startswith('qdot: simulate: 1 impact,') for line in err.splitlines()),
          f'graze: {err!r}')
    free = Path(tempfile.mkdtemp()) / 'graze_free.qd'
    free.write_text(''.join(line for line in graze.read_text().splitlines(True)
                            if not line.startswith('impact ')))
    rc, out, err = run(qdot, 'simulate', free, '--t-end', 10, '--rtol', 1e-10,
                       '--event', 'x^2 + y^2 = 1')
    check(rc == 0, f'graze --event: exit {rc} {err}')
    ev = [float(x['t']) for x in rows(out) if x.get('event') == '1']
    check(len(ev) == 2 and abs(ev[0] - (5 - w)) < 1e-9 and abs(ev[1] - (5 + w)) < 1e-9,
          f'graze --event: crossings {ev}, want {5 - w}, {5 + w}')
    free.unlink()
    free.parent.rmdir()

    # poincare on the pendulum at a wall: only the section's crossings (the
    # impacts' rows are not crossings); 1 - cos(a_n) = e^(2n) (1 - cos th0)
    pend = str(ROOT / 'examples' / 'pendulum_wall.qd')
    rc, out, err = run(qdot, 'poincare', pend, '--section', "th' = 0, th > 0", '--crossings', 3,
                       '--rtol', 1e-12)
    check(rc == 0, f'poincare: exit {rc} {err}')
    a = 0.5
    got = rows(out)
    check(len(got) == 3, f'poincare: {len(got)} rows')
    for n, x in enumerate(got):
        a = math.acos(1 - 0.7 ** 2 * (1 - math.cos(a)))
        check(abs(float(x['th']) - a) < 1e-10, f'poincare crossing {n + 1}: {x["th"]} vs {a}')

    # errors
    rc, out, err = run(qdot, 'simulate', ball, '--t-end', 1, '--set', 'e=1.5')
    check(rc == 2 and out == '' and 'restitution' in err and '1.5' in err,
          f'restitution 1.5: {rc} {err!r}')
    rc, out, err = run(qdot, 'simulate', ball, '--t-end', 1, '--initial', 'y = -0.1')
    check(rc == 2 and out == '' and "impact 'floor': the gap is negative at t0 (-0.1): the bodies "
          "start interpenetrating" in err, f'negative gap: {rc} {err!r}')

    print('%d failed' % len(failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
