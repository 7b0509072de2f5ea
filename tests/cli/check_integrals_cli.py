#!/usr/bin/env python3
"""End-to-end checks of `qdot integrals` on the example models.

Every verdict asserted is a textbook result (reference notes in
/work/shared/reference/):
  * kepler_polar.qd: theta cyclic, p_theta = m r^2 theta' (Desloge ch. 56 thm 4;
    seed-desloge-B.md C3); h = E conserved (ch. 56 thm 3).
  * kepler_cartesian.qd: the model's `symmetry rot` gives m (x y' - y x')
    (Desloge ch. 56 Noether Ex. 4); its integrals (energy, Runge-Lenz Ax, Ay)
    are conserved; --integral "m*x'" is not, with remainder -k x/r^3 (Newton).
  * two_masses_spring.qd, two_particles_spring_2d.qd: total momentum (and
    angular momentum about z) found automatically (ch. 56 thms 5, 6).
  * bead_rotating_wire.qd: h = m/2 (r'^2 - omega^2 r^2) conserved, not the
    energy (Goldstein sec. 1.6 ex. 3; seed-goldstein-britannica.md G03,
    seed-desloge-A.md pitfall 6).
  * damped_oscillator.qd: dE/dt = -2D = -b x'^2 (Goldstein sec. 1.5).
  * charged_particle_landau.qd: p_x = m x' - q B y conserved (Desloge T35,
    pitfall 8: canonical, not mechanical, momentum).
Expressions are compared by value at random points (Python's math only).
Usage: check_integrals_cli.py --build BUILD_DIR
"""
import argparse
import json
import math
import random
import subprocess
import sys
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
FAILS = []


def run(qdot, *args, rc=0):
    p = subprocess.run([qdot, 'integrals', *args], capture_output=True, text=True, timeout=60)
    if p.returncode != rc:
        FAILS.append('%s: exit %d, expected %d\n%s' % (' '.join(args), p.returncode, rc, p.stderr))
        return None
    return p


def js(qdot, name, *extra):
    p = run(qdot, str(EXAMPLES / name), '--format', 'json', *extra)
    return json.loads(p.stdout) if p else None


def value(expr, env):
    """An expression printed by qdot (text format) evaluated with Python's math."""
    py = expr.replace('^', '**')
    for q in sorted((k for k in env if k.endswith("'")), key=len, reverse=True):
        py = py.replace(q, '__v_' + q[:-1])
    names = {('__v_' + k[:-1] if k.endswith("'") else k): v for k, v in env.items()}
    names.update({f: getattr(math, f) for f in ('sin', 'cos', 'sqrt', 'exp', 'log', 'pi')})
    return eval(py, {'__builtins__': {}}, names)


def same(what, got, expected, symbols, rng=random.Random(5)):
    for _ in range(6):
        env = {s: rng.uniform(0.4, 1.6) for s in symbols}
        a, b = value(got, env), value(expected, env)
        if abs(a - b) > 1e-9 * max(1, abs(b)):
            FAILS.append('%s: got %s, expected %s (%g vs %g)' % (what, got, expected, a, b))
            return


def expect(what, cond):
    if not cond:
        FAILS.append(what)


def check_kepler(qdot):
    d = js(qdot, 'kepler_polar.qd')
    syms = ['m', 'k', 'r', 'theta', "r'", "theta'"]
    expect('kepler_polar: one cyclic coordinate', [c['coordinate'] for c in d['cyclic']] == ['theta'])
    same('kepler_polar p_theta', d['cyclic'][0]['momentum'], "m*r**2*theta'", syms)
    j = d['jacobi']
    expect('kepler_polar: h conserved, = E', j['conserved'] and j['equals_energy'])
    same('kepler_polar h', j['h'], "m/2*(r'**2 + r**2*theta'**2) - k/r", syms)

    d = js(qdot, 'kepler_cartesian.qd', '--integral', "wrong: m*x'")
    syms = ['m', 'k', 'x', 'y', "x'", "y'"]
    rot = [n for n in d['noether'] if n['name'] == 'rot']
    expect('kepler_cartesian: symmetry rot reported', len(rot) == 1)
    expect('kepler_cartesian: rot invariant and conserved', rot[0]['invariant'] and rot[0]['conserved'])
    same('kepler_cartesian rot integral', rot[0]['integral'], "m*(x*y' - y*x')", syms)
    found = {f['name']: f for f in d['found']}
    expect('kepler_cartesian: rotation about z found', 'angular momentum about z' in found)
    prop = {p['name']: p for p in d['proposed']}
    for name in ('energy', 'Ax', 'Ay'):
        expect('kepler_cartesian: %s conserved' % name, prop[name]['conserved'])
    expect('kepler_cartesian: m x\' not conserved', not prop['wrong']['conserved'])
    same('kepler_cartesian wrong remainder', prop['wrong']['remainder'],
         '-k*x/(x**2 + y**2)**1.5', syms)


def check_springs(qdot):
    d = js(qdot, 'two_masses_spring.qd')
    found = {f['name']: f for f in d['found']}
    expect('two_masses_spring: momentum found', 'linear momentum along x' in found)
    same('two_masses_spring P', found['linear momentum along x']['integral'],
         "m1*x1' + m2*x2'", ['m1', 'm2', "x1'", "x2'", 'x1', 'x2', 'k', 'd'])
    d = js(qdot, 'two_particles_spring_2d.qd')
    found = {f['name']: f for f in d['found']}
    syms = ['m1', 'm2', 'x1', 'y1', 'x2', 'y2', "x1'", "y1'", "x2'", "y2'"]
    expect('two_particles_spring_2d: three found',
           sorted(found) == ['angular momentum about z', 'linear momentum along x',
                             'linear momentum along y'])
    same('2d Lz', found['angular momentum about z']['integral'],
         "m1*(x1*y1' - y1*x1') + m2*(x2*y2' - y2*x2')", syms)
    same('2d Py', found['linear momentum along y']['integral'], "m1*y1' + m2*y2'", syms)


def check_wire(qdot):
    d = js(qdot, 'bead_rotating_wire.qd')
    j = d['jacobi']
    syms = ['m', 'omega', 'r', "r'"]
    expect('bead_rotating_wire: h conserved', j['conserved'])
    expect('bead_rotating_wire: h is not the energy', j['equals_energy'] is False)
    expect('bead_rotating_wire: reason names T0', 'T0' in j['reason'])
    same('wire h', j['h'], "m/2*(r'**2 - omega**2*r**2)", syms)
    same('wire h - E', j['h_minus_energy'], '-m*omega**2*r**2', syms)
    p = run(qdot, str(EXAMPLES / 'bead_rotating_wire.qd'))
    expect('bead_rotating_wire text: "h = E: no"', p and 'h = E: no' in p.stdout)


def check_damped(qdot):
    d = js(qdot, 'damped_oscillator.qd')
    b = d['energy_balance']
    syms = ['m', 'k', 'b', 'x', "x'"]
    expect('damped: balance verified, D quadratic', b['verified'] and b['D_quadratic'])
    expect('damped: h not conserved', not d['jacobi']['conserved'])
    same('damped dh/dt', b['dhdt'], "-b*x'**2", syms)
    # --set b=0: conservative, h conserved
    d = js(qdot, 'damped_oscillator.qd', '--set', 'b=0')
    expect('damped --set b=0: h conserved', d['jacobi']['conserved'])


def check_landau(qdot):
    d = js(qdot, 'charged_particle_landau.qd')
    cyc = {c['coordinate']: c for c in d['cyclic']}
    expect('landau: x and z cyclic', sorted(cyc) == ['x', 'z'])
    same('landau p_x', cyc['x']['momentum'], "m*x' - q*B*y", ['m', 'q', 'B', 'y', "x'"])
    expect('landau: p_x conserved', cyc['x']['conserved'])


def check_cli_symmetry(qdot):
    path = str(EXAMPLES / 'kepler_cartesian.qd')
    for spec in ('R: delta x = -y, delta y = x',
                 'R: x -> x*cos(eps) - y*sin(eps), y -> x*sin(eps) + y*cos(eps)'):
        d = js(qdot, 'kepler_cartesian.qd', '--symmetry', spec)
        r = [n for n in d['noether'] if n['name'] == 'R']
        expect('--symmetry %s: invariant' % spec, r and r[0]['invariant'] and r[0]['conserved'])
        if r:
            same('--symmetry integral', r[0]['integral'], "m*(x*y' - y*x')",
                 ['m', 'k', 'x', 'y', "x'", "y'"])
    d = js(qdot, 'kepler_cartesian.qd', '--symmetry', 'T: x -> x + eps')
    t = [n for n in d['noether'] if n['name'] == 'T'][0]
    expect('translation of Kepler: not invariant', not t['invariant'])
    same('Kepler translation dL/deps', t['remainder'], '-k*x/(x**2 + y**2)**1.5',
         ['m', 'k', 'x', 'y'])
    p = run(qdot, path, '--symmetry', 'delta w = 1', rc=2)
    expect('unknown coordinate: a message', p and 'coordinate' in p.stderr)
    run(qdot, path, '--integral', 'x + nosuchname', rc=2)
    run(qdot, path, '--format', 'yaml', rc=2)
    p = run(qdot, path)
    expect('text output lists the sections',
           p and all(s in p.stdout for s in ('cyclic coordinates', "Jacobi's integral",
                                             'energy balance', 'proposed integrals')))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    for check in (check_kepler, check_springs, check_wire, check_damped, check_landau,
                  check_cli_symmetry):
        try:
            check(qdot)
        except Exception as exc:  # a crash or bad JSON
            FAILS.append('%s: %s: %s' % (check.__name__, type(exc).__name__, exc))
    for f in FAILS:
        print('FAIL', f)
    print('%d failures' % len(FAILS))
    return 1 if FAILS else 0


if __name__ == '__main__':
    sys.exit(main())
