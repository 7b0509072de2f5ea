#!/usr/bin/python3
"""tests/cli/check_sim_start_cli.py - `qdot simulate` on constrained models
started off their velocity constraints, and a step that collapses near a
singular point (issues 33 and 37).

  1. The rolling disk (examples/rolling_disk_tilted.qd, Euler angles z-x-z)
     given only its angular rates by --initial: those are kept exactly, the
     centre's velocity is solved from the rolling constraints (a note names
     it), and it equals the rolling condition computed here independently,
     v_centre = omega x (centre - contact) with omega = phi' e_z + theta' e_N
     + psi' e_3 (Goldstein, Classical Mechanics, sec. 1.3 and 4.9: the disk
     rolling without slipping; Desloge ch. 49 Ex. 1).  The constraint forces
     of rolling do no work, so T + V is then kept to 1e-9 over the run.
  2. Velocities given that violate a constraint the others cannot make up
     (both wheel rates of the bicycle, which fix its speed twice over): exit
     2 naming the constraint and its residual.
  3. The Whipple bicycle (examples/whipple_bicycle.qd) at v = 2, below the
     weave speed, falls over and lies with its front wheel flat on the
     ground, where the rolling contact is singular: the step collapsed to
     1e-8 s and the run crawled for hours with no output (--dt 0.1).  It
     now stops with exit 1, naming the step size collapse and its time.

Usage: check_sim_start_cli.py --build BUILD_DIR
"""
import argparse
import csv
import io
import subprocess
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
failed = 0


def report(ok, what, detail=''):
    global failed
    print(('ok   ' if ok else 'FAIL ') + what + ('' if ok else ': ' + detail))
    failed += 0 if ok else 1


def run(qdot, *args, timeout=120):
    p = subprocess.run([qdot, *map(str, args)], capture_output=True, text=True,
                       timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def rows(text):
    r = list(csv.reader(io.StringIO(text)))
    return r[0], np.array([[float(x) for x in row] for row in r[1:]])


def rolling_disk(qdot):
    model = ROOT / 'examples' / 'rolling_disk_tilted.qd'
    rc, out, err = run(qdot, 'simulate', model, '--t-end', 10, '--dt', 0.05, '--rtol', 1e-11,
                       '--initial', "phi'=0.8, theta'=0, psi'=4")
    report(rc == 0, 'rolling disk from its rates runs', f'{rc} {err}')
    if rc != 0:
        return
    head, d = rows(out)
    c = {name: d[:, k] for k, name in enumerate(head)}
    report("solved from the velocity constraints" in err and "x'" in err,
           'the note names the velocities solved', err)
    rates = (c["phi'"][0], c["theta'"][0], c["psi'"][0])
    report(rates == (0.8, 0, 4), 'the rates given are kept exactly', str(rates))
    a = 0.35
    ph, th, ps = c['phi'][0], c['theta'][0], c['psi'][0]
    dph, dth, dps = c["phi'"][0], c["theta'"][0], c["psi'"][0]
    ez = np.array([0, 0, 1.0])
    e_n = np.array([np.cos(ph), np.sin(ph), 0])                                 # line of nodes
    e3 = np.array([np.sin(th) * np.sin(ph), -np.sin(th) * np.cos(ph), np.cos(th)])  # axle
    omega = dph * ez + dth * e_n + dps * e3
    down = ez - ez.dot(e3) * e3
    arm = a * down / np.linalg.norm(down)        # from the contact to the centre
    v_centre = np.cross(omega, arm)
    v = np.array([c["x'"][0], c["y'"][0], c["z'"][0]])
    report(np.allclose(v, v_centre, rtol=0, atol=1e-12),
           'the centre velocity solved is the rolling one, omega x (centre - contact)',
           f'{v} against {v_centre}')
    report(abs(c['z'][0] - a * np.sin(th)) < 1e-12, 'the centre on the contact: z = a sin(theta)',
           f"{c['z'][0]} {a * np.sin(th)}")
    drift = np.max(np.abs(c['energy'] - c['energy'][0])) / abs(c['energy'][0])
    report(drift < 1e-9, f'T + V kept over the run (relative drift {drift:.2e})', str(drift))


def over_given(qdot):
    model = ROOT / 'examples' / 'whipple_bicycle.qd'
    rc, out, err = run(qdot, 'simulate', model, '--t-end', 1, '--initial', "q3'=10, q6'=1")
    report(rc == 2 and 'violate constraint front_roll1 by 2.65' in err,
           'velocities given that fix the speed twice: refused, naming the constraint',
           f'{rc} {err}')
    rc, out, err = run(qdot, 'simulate', model, '--t-end', 1, '--dt', 1, '--initial', "x'=1")
    head, d = rows(out)
    c = {name: d[:, k] for k, name in enumerate(head)}
    report(rc == 0 and abs(c["q3'"][0] - 1 / 0.3) < 1e-12 and abs(c["q6'"][0] - 1 / 0.35) < 1e-12
           and "q3', q6'" in err, "x' = 1 given: the wheel rates solved, 1/rr and 1/rf",
           f'{rc} {err} {out}')


def collapse(qdot):
    model = ROOT / 'examples' / 'whipple_bicycle.qd'
    try:
        rc, out, err = run(qdot, 'simulate', model, '--set', 'v=2', '--t-end', 20, '--dt', 0.1,
                           '--initial', "q2'=0.5", '--out', '/dev/null', timeout=300)
    except subprocess.TimeoutExpired:
        report(False, 'the fallen bicycle stops', 'still running after 300 s')
        return
    report(rc == 1 and 'step size collapse at t = 4.127' in err,
           'the fallen bicycle: step size collapse named with its time, exit 1', f'{rc} {err}')


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    rolling_disk(qdot)
    over_given(qdot)
    collapse(qdot)
    print('FAILED %d' % failed if failed else 'all passed')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
