#!/usr/bin/python3
"""tests/cross/check_whipple_speeds.py - the Whipple bicycle in generalized
speeds (tests/speeds/whipple_speeds.qd, issue 37) against the same model in
multiplier form and against its own geometry.

The bicycle is Meijaard, Papadopoulos, Ruina and Schwab's benchmark (Proc.
R. Soc. A 463 (2007) 1955-1982), in the frames and with the parameters of
SymPy's test_kane3.py.  Its velocity map is solved on the DAG (large
entries, src/speeds/dagsolve.c), so the checks are numeric, at random
states on the constraint manifold (the pitch q4 solved here from the front
contact height, computed from the geometry in plain Python):

  1. the kinematics q' = W u + w: each speed's definition (q2' = u2, ...),
     the front contact's height constant (its rate by central differences
     along q'), and both wheels' material points at the contact at rest
     (central differences of the wheel's rigid motion along q'): rolling
     without slip (Kane and Levinson, Dynamics, 1985, sec. 6.1; Desloge
     ch. 64, seed-desloge-B.md C11);
  2. the speeds' rates u' by each method (Kane, Gibbs-Appell,
     Boltzmann-Hamel) equal the accelerations of the
     same model in multiplier form, M q'' = f + A^T lambda, A q'' = b (the
     two formulations are the same dynamics, Desloge ch. 69 thm 2), to 1e-10;
  3. `qdot check` (the closure's numeric path, the forms being large):
     the benchmark's 3 degrees of freedom (lean, steer, rear wheel; Meijaard
     et al. sec. 2) and 7 configurational (8 coordinates less the front
     contact; the 4 rolling constraints are not integrable, together or
     alone), in speeds and in multiplier form;
  4. energy: the bicycle has no dissipation and ideal rolling constraints,
     so T + V is conserved (Desloge ch. 52); T + V computed here from the
     geometry (body velocities and angular velocities by central
     differences) at the start and after 5 s of `simulate` at rtol 1e-10,
     from the upright run at v = 5 m/s with a lean rate, agree to 1e-8.

Usage: check_whipple_speeds.py --build BUILD_DIR [--states N]
"""
import argparse
import json
import math
import random
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
MODEL = ROOT / 'tests' / 'speeds' / 'whipple_speeds.qd'
COORDS = ['x', 'y', 'q1', 'q2', 'q3', 'q4', 'q5', 'q6']
SPEEDS = {'u2': 'q2', 'u3': 'q3', 'u5': 'q5'}
METHODS = ['kane', 'appell', 'hamel']
ACC_TOL = 1e-10
KIN_TOL = 1e-7     # central differences, h = 1e-5: truncation ~1e-10
ENERGY_TOL = 1e-8
SEED = 20261204


def params(text):
    p = {'pi': math.pi}
    for line in text.splitlines():
        if line.startswith('parameters '):
            for item in line[len('parameters '):].split(','):
                name, val = item.split('=')
                p[name.strip()] = eval(val, {'__builtins__': {}}, p)
    return p


# ---- geometry, as SymPy's test_kane3 builds it ---------------------------------------
def matmul(A, B):
    return [[sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def apply(A, v):
    return [sum(A[i][k] * v[k] for k in range(3)) for i in range(3)]


def rot(axis, a):
    c, s = math.cos(a), math.sin(a)
    if axis == 'x':
        return [[1, 0, 0], [0, c, -s], [0, s, c]]
    if axis == 'y':
        return [[c, 0, s], [0, 1, 0], [-s, 0, c]]
    return [[c, -s, 0], [s, c, 0], [0, 0, 1]]


def add(*vs):
    return [sum(v[i] for v in vs) for i in range(3)]


def scale(k, v):
    return [k * x for x in v]


def bodies(P, q):
    """{name: (mass, inertia in body axes, centre, R body->space)} and the contacts."""
    x, y, q1, q2, q3, q4, q5, q6 = (q[c] for c in COORDS)
    Rl = matmul(rot('z', q1), rot('x', q2))
    Fr = matmul(Rl, rot('y', q4 + P['hta']))
    Fk = matmul(Fr, rot('x', q5))
    wrc = add([x, y, 0], scale(P['rr'], apply(Rl, [0, 0, 1])))
    steer = add(wrc, scale(P['framel'], apply(Fr, [0, 0, 1])))
    frc = add(wrc, apply(Fr, [-P['framecg1'], 0, P['framecg3']]))
    fkc = add(steer, apply(Fk, [-P['forkcg1'], 0, P['forkcg3']]))
    wfc = add(steer, apply(Fk, [P['forkl'], 0, P['rake']]))
    fy = apply(Fk, [0, 1, 0])
    nrm = math.sqrt(1 - fy[2] ** 2)
    front_contact = add(wfc, scale(P['rf'] / nrm, [fy[2] * fy[0], fy[2] * fy[1], fy[2] ** 2 - 1]))
    I_frame = [[P['Iframe11'], 0, P['Iframe31']], [0, P['Iframe22'], 0],
               [P['Iframe31'], 0, P['Iframe33']]]
    I_fork = [[P['Ifork11'], 0, P['Ifork31']], [0, P['Ifork22'], 0],
              [P['Ifork31'], 0, P['Ifork33']]]
    wheel = matmul(rot('y', 0), rot('x', -math.pi / 2))
    b = {'frame': (P['mframe'], I_frame, frc, matmul(Rl, rot('y', q4))),
         'fork': (P['mfork'], I_fork, fkc, matmul(Fk, rot('y', -P['hta']))),
         'rear': (P['mwr'], [[P['Iwr11'], 0, 0], [0, P['Iwr11'], 0], [0, 0, P['Iwr22']]], wrc,
                  matmul(matmul(Fr, rot('y', q3)), wheel)),
         'front': (P['mwf'], [[P['Iwf11'], 0, 0], [0, P['Iwf11'], 0], [0, 0, P['Iwf22']]], wfc,
                   matmul(matmul(Fk, rot('y', q6)), wheel))}
    return b, {'rear': [x, y, 0], 'front': front_contact}


def front_height(P, q):
    return bodies(P, q)[1]['front'][2]


def solve_pitch(P, q):
    """q4 with the front contact on the ground, by the secant method from 0."""
    a, b = 0.0, 1e-3
    fa, fb = front_height(P, dict(q, q4=a)), front_height(P, dict(q, q4=b))
    for _ in range(60):
        if fb == fa:
            break
        a, b, fa = b, b - fb * (b - a) / (fb - fa), fb
        fb = front_height(P, dict(q, q4=b))
        if abs(fb) < 1e-15:
            break
    return b


def moved(q, v, h):
    return {c: q[c] + h * v[c] for c in COORDS}


def material_velocity(P, q, v, body, point, h=1e-5):
    """d/dt of the body's material point now at `point`, along q' = v."""
    def where(s):
        b = bodies(P, moved(q, v, s))[0][body]
        b0 = bodies(P, q)[0][body]
        Rt = [[b0[3][j][i] for j in range(3)] for i in range(3)]  # R0^T
        local = apply(Rt, [point[i] - b0[2][i] for i in range(3)])
        return add(b[2], apply(b[3], local))
    p1, p0 = where(h), where(-h)
    return [(p1[i] - p0[i]) / (2 * h) for i in range(3)]


def energy(P, q, v, h=1e-5):
    """T + V from the geometry: centre velocities and body angular velocities
    (skew part of R' R^T) by central differences."""
    b0, b1, bm = bodies(P, q)[0], bodies(P, moved(q, v, h))[0], bodies(P, moved(q, v, -h))[0]
    E = 0.0
    for name, (m, I, c, R) in b0.items():
        cd = [(b1[name][2][i] - bm[name][2][i]) / (2 * h) for i in range(3)]
        Rd = [[(b1[name][3][i][j] - bm[name][3][i][j]) / (2 * h) for j in range(3)]
              for i in range(3)]
        W = matmul(Rd, [[R[j][i] for j in range(3)] for i in range(3)])  # R' R^T = [w]x
        w = [W[2][1], W[0][2], W[1][0]]
        wb = apply([[R[j][i] for j in range(3)] for i in range(3)], w)  # body axes
        E += 0.5 * m * sum(x * x for x in cd) + 0.5 * sum(wb[i] * apply(I, wb)[i] for i in range(3))
        E += m * P['g'] * c[2]
    return E


# ---- running qdot ----------------------------------------------------------------------
def qdot(build, *args):
    p = subprocess.run([str(Path(build) / 'qdot'), *args], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True, timeout=120)
    if p.returncode != 0:
        raise RuntimeError('qdot %s: exit %d: %s' % (' '.join(args[:2]), p.returncode, p.stderr))
    return p.stdout


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.add_argument('--states', type=int, default=4)
    a = ap.parse_args()
    text = MODEL.read_text()
    P = params(text)
    mult_text = '\n'.join(l for l in text.splitlines()
                          if not l.startswith('speeds') and not l.startswith('initial'))
    rng = random.Random(SEED)
    passed = failed = 0

    def report(ok, what):
        nonlocal passed, failed
        passed, failed = passed + ok, failed + (not ok)
        print('%s %s' % ('ok  ' if ok else 'FAIL', what))

    with tempfile.TemporaryDirectory() as tmp:
        mult = Path(tmp) / 'whipple_mult.qd'
        mult.write_text(mult_text + '\n')
        for k in range(a.states):
            q = {'x': rng.uniform(-2, 2), 'y': rng.uniform(-2, 2),
                 'q1': rng.uniform(-math.pi, math.pi), 'q2': rng.uniform(-0.4, 0.4),
                 'q3': rng.uniform(-3, 3), 'q4': 0.0, 'q5': rng.uniform(-0.6, 0.6),
                 'q6': rng.uniform(-3, 3)}
            q['q4'] = solve_pitch(P, q)
            u = {'u2': rng.uniform(-1, 1), 'u3': rng.uniform(5, 20), 'u5': rng.uniform(-1, 1)}
            at = ','.join('%s=%.17g' % kv for kv in list(q.items()) + list(u.items()))
            runs = {m: json.loads(qdot(a.build, 'eom', str(MODEL), '--at', at, '--method', m,
                                       '--format', 'json')) for m in METHODS}
            d = runs['kane']
            v = dict(zip(COORDS, d['velocities']))
            kin = all(abs(v[c] - u[s]) <= 1e-12 * (1 + abs(u[s])) for s, c in SPEEDS.items())
            h = 1e-5
            dh = (front_height(P, moved(q, v, h)) - front_height(P, moved(q, v, -h))) / (2 * h)
            contacts = bodies(P, q)[1]
            slip = max(max(abs(x) for x in material_velocity(P, q, v, w, contacts[w]))
                       for w in ('rear', 'front'))
            size = max(abs(x) for x in v.values())
            report(kin and abs(dh) <= KIN_TOL * size and slip <= KIN_TOL * size,
                   'state %d: kinematics (speeds %s, contact rate %.1e, slip %.1e)'
                   % (k, kin, abs(dh), slip))
            at_m = ','.join('%s=%.17g' % kv for kv in list(q.items()) +
                            [(c + "'", v[c]) for c in COORDS])
            dm = json.loads(qdot(a.build, 'eom', str(mult), '--at', at_m, '--format', 'json'))
            acc = dict(zip(COORDS, dm['accelerations']))
            for m, dd in runs.items():
                rates = dict(zip(dd['speeds'], dd['rates']))
                err = max(abs(rates[s] - acc[c]) / (1 + abs(acc[c])) for s, c in SPEEDS.items())
                report(err <= ACC_TOL, "state %d: u' (%s) = q'' (multipliers), error %.1e"
                       % (k, m, err))
        for f in (MODEL, mult):
            out = qdot(a.build, 'check', str(f))
            m = re.search(r'degrees of freedom: (\d+) configurational, (\d+) motional', out)
            report(bool(m) and m.groups() == ('7', '3') and 'could not decide' not in out,
                   'check %s: %s configurational, %s motional (the benchmark: 7 and 3)'
                   % (f.name, *(m.groups() if m else ('?', '?'))))
        out = qdot(a.build, 'simulate', str(MODEL), '--t-end', '5', '--rtol', '1e-10', '--dt', '5')
        rows = [r.split(',') for r in out.strip().splitlines()]
        head = rows[0]
        E = []
        for r in (rows[1], rows[-1]):
            val = dict(zip(head, map(float, r)))
            E.append(energy(P, {c: val[c] for c in COORDS}, {c: val[c + "'"] for c in COORDS}))
        rel = abs(E[1] - E[0]) / abs(E[0])
        report(rel <= ENERGY_TOL and float(rows[-1][0]) == 5.0,
               'simulate 5 s at v = 5 m/s: T + V from the geometry %.10g -> %.10g (%.1e)'
               % (E[0], E[1], rel))
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
