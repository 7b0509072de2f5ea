#!/usr/bin/env python3
"""--set on every command that takes it: a parameter defined from another
follows the value given on the command line.

    python3 tests/cli/check_params_cli.py --build BUILD_DIR

Two models whose physics turns on a derived parameter:

- a mass on a vertical spring with m = 2*k: whatever k is given, m/k = 2,
  so the equilibrium stretch is x0 = m g / k = 2 g, the frequency
  w^2 = k/m = 1/2 and the period 2 pi sqrt(2) (Desloge ch. 22; Goldstein
  sec. 1.6).  With --set k=5 a model that kept the text's m = 2 (the bug this
  guards against) would give x0 = 2g/5 and w^2 = 5/2;
- a spherical pendulum of length l = 2*a: with --set a=3 it is 6 long, so
  the conical pendulum at th0 = pi/3 turns at phi'^2 = g/(l cos th0) and
  swings about it at w^2 = (g/(l cos th0))(1 + 3 cos^2 th0) (Byerly Art. 5
  Ex. 3, as in docs/cli.md), its small oscillations about the bottom at
  w^2 = g/l, its effective potential is p^2/(2 m l^2 sin^2) - m g l cos.

Each command that takes --set (grep --set in cli/ and docs/cli.md: eom,
hamiltonian, routh, integrals, codegen, equilibria, modes, stability,
simulate, poincare, canonical) is asked a question whose answer depends on
the derived value.  Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import csv
import io
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

G = 9.81
SPRING = """# a mass on a vertical spring, x down; the mass is twice the stiffness
coordinates x
parameters k = 1, m = 2*k, g = 9.81
initial x = 0.5
T = m/2*x'^2
V = k/2*x^2 - m*g*x
"""
PENDULUM = """# a spherical pendulum of length l = 2*a, th from the downward vertical
coordinates th, ph
parameters m = 1, a = 1, l = 2*a, g = 9.81
initial th = 0.5, ph' = 2
T = m/2*l^2*(th'^2 + sin(th)^2*ph'^2)
V = -m*g*l*cos(th)
"""
results = {'passed': 0, 'failed': 0}


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, detail))


def close(a, b, tol=1e-9):
    return isinstance(a, (int, float)) and abs(a - b) <= tol * max(1.0, abs(b))


def run(qdot, *args):
    p = subprocess.run([qdot, *map(str, args)], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def js(qdot, *args):
    rc, out, err = run(qdot, *args, '--format', 'json')
    if rc != 0:
        print('  %s -> exit %d: %s' % (' '.join(map(str, args)), rc, err.strip()))
        return None
    return json.loads(out)


def ev(text, values):
    """A printed expression (qdot's text syntax) at values (velocities named
    with a trailing ')."""
    expr = text.replace('^', '**')
    env = {n: getattr(math, n) for n in ('sin', 'cos', 'tan', 'sqrt', 'exp', 'log', 'pi')}
    for k in sorted(values, key=len, reverse=True):
        safe = k.replace("'", '_d')
        expr = expr.replace(k, safe)
        env[safe] = values[k]
    try:
        return eval(expr, {'__builtins__': {}}, env)
    except (NameError, SyntaxError, ZeroDivisionError, ValueError):
        return None  # a name left unvalued: the check using it fails


def csv_rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def check_eom(qdot, spring, pend):
    # x'' = g - (k/m) x: at x = 1, 9.81 - 1/2
    d = js(qdot, 'eom', spring, '--set', 'k=5', '--at', 'x=1')
    check('eom --at: acceleration with m = 2k', d and close(d['accelerations'][0], G - 0.5),
          d and d['accelerations'])
    check('eom: the derived value is shown', d and close(d['parameters']['m'], 10),
          d and d['parameters'])
    # printed equations: a and l are numbers now; th'' = -(g/l) sin th
    d = js(qdot, 'eom', pend, '--set', 'a=3')
    if check_ok(d, 'eom symbolic'):
        vals = {'th': 0.4, 'ph': 0.0, "th'": 0.3, "ph'": 0.2, 'm': 1.0, 'g': G}
        M = [[ev(e, vals) for e in row] for row in d['mass_matrix']]
        f = [ev(e, vals) for e in d['forcing']]
        thdd = f[0] / M[0][0] if None not in (f[0], M[0][0]) else None
        want = math.sin(0.4) * math.cos(0.4) * 0.2 ** 2 - G / 6 * math.sin(0.4)
        check('eom symbolic: th\'\' with l = 6', close(thdd, want), '%r vs %r' % (thdd, want))
        text = ' '.join(sum(d['mass_matrix'], []) + d['forcing'])
        check('eom symbolic: a and l are written in', 'l' not in text.replace('g', ''), text)
    # a value written as an expression of constants is shown as its number
    # (it was nan in the text and broke the JSON)
    with tempfile.TemporaryDirectory() as tmp:
        tilted = Path(tmp) / 'tilted.qd'
        tilted.write_text("coordinates th\nparameters m = 1, al = pi/6\n"
                          "T = m*th'^2/2\nV = -cos(th - al)\n")
        d = js(qdot, 'eom', str(tilted))
        check('eom: al = pi/6 in the JSON', d and close(d['parameters']['al'], math.pi / 6),
              d and d['parameters'])
        rc, out, _ = run(qdot, 'eom', str(tilted))
        check('eom: al = pi/6 in the text', rc == 0 and 'al = 0.5235987755982988' in out, out)
        rc, out, _ = run(qdot, 'check', str(tilted))
        check('check: al = pi/6', rc == 0 and 'al = 0.5235987755982988' in out, out)


def check_ok(d, name):
    check(name + ' runs', d is not None)
    return d is not None


def check_hamiltonian(qdot, spring):
    d = js(qdot, 'hamiltonian', spring, '--set', 'k=5')
    if check_ok(d, 'hamiltonian'):
        vals = {'x': 1.3, 'p_x': 2.0, 'g': G}
        want = 2.0 ** 2 / (2 * 10) + 5 / 2 * 1.3 ** 2 - 10 * G * 1.3
        check('hamiltonian: H = p^2/2m + k x^2/2 - m g x with m = 10',
              close(ev(d['H'], vals), want), d['H'])
        check('hamiltonian: dp/dt = m g - k x', close(ev(d['dp_dt'][0], vals), 10 * G - 5 * 1.3),
              d['dp_dt'])


def check_routh(qdot, pend):
    d = js(qdot, 'routh', pend, '--ignore', 'ph', '--set', 'a=3')
    if check_ok(d, 'routh'):
        vals = {'th': 0.7, 'p_ph': 1.5, 'm': 1.0, 'g': G}
        want = 1.5 ** 2 / (2 * 36 * math.sin(0.7) ** 2) - G * 6 * math.cos(0.7)
        check('routh: V_eff with l = 6', close(ev(d['effective_potential'], vals), want),
              d['effective_potential'])


def check_integrals(qdot, pend):
    # the energy over m l with l = 6 written out: conserved only when l
    # follows a (the motion depends on g/l alone, so a stale l = 2 fails)
    E = "E: m*(3*(th'^2 + sin(th)^2*ph'^2) - g*cos(th))"
    d = js(qdot, 'integrals', pend, '--set', 'a=3', '--integral', E)
    ok = d and d['proposed'] and d['proposed'][0]['conserved'] is True
    check('integrals: E/(m l) with l = 6 is conserved', ok, d and d['proposed'])
    d = js(qdot, 'integrals', pend, '--set', 'a=2', '--integral', E)
    ok = d and d['proposed'] and d['proposed'][0]['conserved'] is False
    check('integrals: ... and not for l = 4', ok, d and d['proposed'])


def check_codegen(qdot, spring, tmp):
    rc, out, err = run(qdot, 'codegen', spring, '--set', 'k=5', '-o', tmp / 'cg')
    src = (tmp / 'cg' / 'spring.c').read_text() if rc == 0 else ''
    line = next((l for l in src.splitlines() if 'spring_par_default[]' in l), '')
    nums = [eval(x, {'__builtins__': {}}) for x in line.split('{')[-1].split('}')[0].split(',')
            if x.strip()] if line else []
    check('codegen: defaults k = 5, m = 10, g', len(nums) == 3 and close(nums[0], 5) and
          close(nums[1], 10) and close(nums[2], G), line or err)


def check_equilibria(qdot, spring):
    d = js(qdot, 'equilibria', spring, '--set', 'k=5')
    xs = [e['equilibrium']['x'] for e in d['equilibria']] if d else []
    check('equilibria: x0 = m g / k = 2 g', len(xs) == 1 and close(xs[0], 2 * G), xs)


def check_modes(qdot, spring):
    d = js(qdot, 'modes', spring, '--set', 'k=5')
    w2 = d['modes'][0]['omega2'] if d else None
    check('modes: w^2 = k/m = 1/2', close(w2, 0.5), w2)
    check('modes: about x0 = 2 g', d and close(d['equilibrium']['x'], 2 * G), d and d['equilibrium'])


def check_stability(qdot, pend):
    d = js(qdot, 'stability', pend, '--ignore', 'ph', '--at', 'th=pi/3', '--set', 'a=3')
    if check_ok(d, 'stability'):
        c = math.cos(math.pi / 3)
        rate2 = G / (6 * c)
        check('stability: conical rate phi\'^2 = g/(l cos th0)',
              close(d['steady']["ph'"] ** 2, rate2), d['steady'])
        check('stability: w^2 = g/(l cos th0)(1 + 3 cos^2 th0)',
              close(d['frequencies'][0] ** 2, rate2 * (1 + 3 * c * c)), d['frequencies'])


def check_simulate(qdot, spring):
    period = 2 * math.pi * math.sqrt(2)
    rc, out, err = run(qdot, 'simulate', spring, '--set', 'k=5', '--t-end', 10, '--rtol', 1e-11,
                       '--event', "x' = 0, x < 1")
    rows = [r for r in csv_rows(out) if r.get('event') == '1'] if rc == 0 else []
    t = float(rows[0]['t']) if rows else None
    check('simulate: back at rest after 2 pi sqrt(m/k)', close(t, period, 1e-7), (t, err))


def check_poincare(qdot, spring):
    period = 2 * math.pi * math.sqrt(2)
    rc, out, err = run(qdot, 'poincare', spring, '--set', 'k=5', '--section', "x' = 0, x < 1",
                       '--crossings', 2)
    ts = [float(r['t']) for r in csv_rows(out)] if rc == 0 else []
    check('poincare: crossings one period apart', len(ts) == 2 and close(ts[0], period, 1e-7)
          and close(ts[1], 2 * period, 1e-7), (ts, err))


def check_canonical(qdot, spring):
    # F2 = x P is the identity: K(Q, P) is H with m = 10, k = 5 written in
    d = js(qdot, 'canonical', spring, '--set', 'k=5', '--generator', 'F2', 'x*P')
    if check_ok(d, 'canonical --set'):
        want = 0.5 ** 2 / 20 + 5 / 2 * 1.3 ** 2 - 10 * G * 1.3
        check('canonical: K(Q, P) with m = 10', close(ev(d['K_new'], {'Q': 1.3, 'P': 0.5, 'g': G}),
                                                      want), d['K_new'])
    # a map canonical only for m = 10: the user's m is the model's
    rc, out, err = run(qdot, 'canonical', spring, '--set', 'k=5', '--Q', 'm*x', '--P', 'p_x/10')
    check('canonical --Q with the set value', rc == 0 and out.strip() == 'canonical', out + err)


def check_errors(qdot, spring):
    for cmd in (['eom'], ['modes'], ['simulate', '--t-end', 1], ['canonical', '--generator',
                                                                  'F2', 'x*P']):
        rc, out, err = run(qdot, cmd[0], spring, *cmd[1:], '--set', 'mm=2')
        check('%s: unknown --set name exits 2' % cmd[0], rc == 2 and "'mm'" in err and
              out == '', err)
    # a value that leaves a later parameter without a finite one
    bad = spring.parent / 'sqrt.qd'
    bad.write_text('coordinates x\nparameters a = 2, b = sqrt(a - 1)\nT = b*x\'^2\n')
    rc, out, err = run(qdot, 'eom', bad, '--set', 'a=0')
    check('--set a=0 makes b = sqrt(-1): located at b', rc == 2 and ':2:' in err, err)


def check_energy_names(qdot, tmp):
    # docs/language.md: a pendulum of length L, a central potential V(r)
    pend = tmp / 'length_L.qd'
    pend.write_text("coordinates th\nparameters m = 1, L = 2, g = 9.81\n"
                    "T = m/2*L^2*th'^2\nV = -m*g*L*cos(th)\n")
    d = js(qdot, 'modes', pend, '--set', 'L=4')
    w2 = d['modes'][0]['omega2'] if d else None
    check('a parameter named L: w^2 = g/L', close(w2, G / 4), w2)
    central = tmp / 'central.qd'
    central.write_text("coordinates r, th\nparameters m = 1\nfunctions V\n"
                       "T = m/2*(r'^2 + r^2*th'^2)\nV = V(r)\n")
    d = js(qdot, 'eom', central)
    f = d['forcing'][0] if d else ''
    check("functions V: f[r] = m r th'^2 - V'(r)", f.replace(' ', '') == "m*r*th'^2-V'(r)", f)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        spring, pend = tmp / 'spring.qd', tmp / 'pendulum.qd'
        spring.write_text(SPRING)
        pend.write_text(PENDULUM)
        check_eom(qdot, spring, pend)
        check_hamiltonian(qdot, spring)
        check_routh(qdot, pend)
        check_integrals(qdot, pend)
        check_codegen(qdot, spring, tmp)
        check_equilibria(qdot, spring)
        check_modes(qdot, spring)
        check_stability(qdot, pend)
        check_simulate(qdot, spring)
        check_poincare(qdot, spring)
        check_canonical(qdot, spring)
        check_errors(qdot, spring)
        check_energy_names(qdot, tmp)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    sys.exit(1 if results['failed'] else 0)


if __name__ == '__main__':
    main()
