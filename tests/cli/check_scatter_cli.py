#!/usr/bin/env python3
"""Tests of `qdot scatter`, run against the built program.

    python3 tests/cli/check_scatter_cli.py --build BUILD_DIR

Expected values are the books' (Desloge ch. 60-61, seed
000_46d037099a6cfcd7; reference /work/shared/reference/seed-desloge-B.md):

- Rutherford (C4, T15): tan(Theta/2) = k/(2 E b), dsigma/dOmega =
  (k/(4E))^2/sin^4(Theta/2), r0 = (k/2E)(1 + sqrt(1 + (2 E b/k)^2)), an
  infinite total cross section;
- the hard sphere (ch. 60 ex. 1): sigma = a^2/4, total pi a^2, via --core;
- the refracting sphere (ch. 60 problems; Landau sec. 18 pb. 2);
- the Gaussian well's rainbow: the deflection either side of the rainbow's
  b is smaller than the rainbow angle (a minimum of chi);
- capture by V = -k/r^4 (T19): sigma = 2 pi at k = E = 1;
- the lab frame with equal masses (ch. 61 pb. 7, T25): Theta/2, recoil at
  (pi - Theta)/2, energies cos^2 and sin^2 of Theta/2;
- the deflection of a Gaussian well and a Lennard-Jones potential against
  mpmath's 30-digit quadrature of Desloge's alpha integral in z = b/r;
- step(x) printed for SymPy is Heaviside, 1/2 at the jump as qdot's;
- --lab-theta with gamma = 2: both CM angles and their Jacobians (ch. 61 eq. 36);
- errors (exit 2): E <= 0, b < 0, both --b and --theta, a model with no
  cyclic coordinate, one that is not a central potential, a V that does
  not vanish at infinity.

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
results = {'passed': 0, 'failed': 0}


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, detail))


def close(a, b, rel):
    return a is not None and abs(a - b) <= rel * max(abs(b), 1e-300)


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def scatter(qdot, model, *args):
    rc, out, err = run(qdot, 'scatter', str(model), '--format', 'json', *args)
    if rc != 0:
        check('scatter %s %s' % (model, ' '.join(args)), False, err)
        return None
    return json.loads(out)


def model_file(tmp, name, V):
    p = Path(tmp) / name
    p.write_text('coordinates r, phi\nparameters m = 1, k = 1\n'
                 'particle m at r*(cos(phi), sin(phi))\nV = %s\n' % V)
    return p


def rutherford(qdot):
    k, E = 1.0, 2.0
    for b in (0.1, 0.5, 2.0):
        d = scatter(qdot, EXAMPLES / 'rutherford.qd', '--energy', '2', '--b', repr(b))
        if not d:
            return
        th = 2 * math.atan(k / (2 * E * b))
        check('rutherford deflection b=%g' % b, close(d['deflection'], th, 1e-11), d['deflection'])
        check('rutherford signed b=%g' % b, close(d['deflection_signed'], th, 1e-11))
        want = (k / (4 * E)) ** 2 / math.sin(th / 2) ** 4
        check('rutherford sigma b=%g' % b, close(d['cross_section'], want, 1e-7), d['cross_section'])
        r0 = k / (2 * E) * (1 + math.sqrt(1 + (2 * E * b / k) ** 2))
        check('rutherford r0 b=%g' % b, close(d['closest_approach'], r0, 1e-14))
        check('rutherford kind', d['kind'] == 'deflected')
    check('rutherford total', d['total_cross_section'] == 'infinite')
    check('rutherford no rainbow', d['rainbows'] == [] and d['orbiting'] is None)


def hard_sphere(qdot):
    a = 1.5
    for th in (0.4, 1.9, 3.0):
        d = scatter(qdot, EXAMPLES / 'hard_sphere.qd', '--core', 'a', '--energy', '1',
                    '--theta', repr(th))
        if not d:
            return
        check('hard sphere sigma th=%g' % th, close(d['cross_section'], a * a / 4, 1e-7),
              d['cross_section'])
        check('hard sphere b th=%g' % th, close(d['branches'][0]['b'], a * math.cos(th / 2), 1e-10))
    check('hard sphere total', close(d['total_cross_section'], math.pi * a * a, 1e-14))


def refracting_sphere(qdot):
    a, V0, E = 2.0, 3.0, 1.0
    n = math.sqrt(1 + V0 / E)
    for th in (0.5, 1.0, 1.8):
        d = scatter(qdot, EXAMPLES / 'refracting_sphere.qd', '--energy', '1', '--theta', repr(th))
        if not d:
            return
        c = math.cos(th / 2)
        want = n * n * a * a * (n * c - 1) * (n - c) / (4 * c * (1 + n * n - 2 * n * c) ** 2)
        check('refracting sigma th=%g' % th, close(d['cross_section'], want, 1e-7),
              (d['cross_section'], want))
    check('refracting total', close(d['total_cross_section'], math.pi * a * a, 1e-14))
    d = scatter(qdot, EXAMPLES / 'refracting_sphere.qd', '--energy', '1', '--theta', '2.3')
    check('refracting beyond 2 acos(1/n)', d and d['branches'] == [] and d['cross_section'] == 0)


def rainbow(qdot):
    m = EXAMPLES / 'gaussian_well.qd'
    d = scatter(qdot, m, '--energy', '1/2', '--theta', '1/2')
    if not d:
        return
    check('gaussian one rainbow', len(d['rainbows']) == 1, d['rainbows'])
    check('gaussian two branches', len(d['branches']) == 2, d['branches'])
    if len(d['rainbows']) != 1:
        return
    rb, ra = d['rainbows'][0]['b'], d['rainbows'][0]['angle']
    for db in (-0.05, -1e-3, 1e-3, 0.05):
        x = scatter(qdot, m, '--energy', '1/2', '--b', repr(rb + db))
        check('rainbow is the largest angle db=%g' % db, x and x['deflection'] < ra,
              x and (x['deflection'], ra))
    x = scatter(qdot, m, '--energy', '1/2', '--b', repr(rb))
    check('rainbow angle at its b', x and close(x['deflection'], ra, 1e-9))


def capture(qdot, tmp):
    d = scatter(qdot, model_file(tmp, 'r4.qd', '-k/r^4'), '--energy', '1', '--b', '1/2')
    if not d:
        return
    check('capture kind', d['kind'] == 'captured', d['kind'])
    check('capture sigma (T19)', close(d['capture_cross_section'], 2 * math.pi, 1e-10),
          d['capture_cross_section'])
    check('capture orbit radius', close(d['orbiting']['r'], 1.0, 1e-10))


def lab(qdot):
    d = scatter(qdot, EXAMPLES / 'rutherford.qd', '--energy', '2', '--b', '1/2', '--masses', '1,1')
    if not d:
        return
    th = d['deflection']
    check('lab angle T25', close(d['lab_angle'], th / 2, 1e-14))
    check('lab energy T25', close(d['lab_energy_ratio'], math.cos(th / 2) ** 2, 1e-14))
    check('recoil angle T25', close(d['recoil_angle'], (math.pi - th) / 2, 1e-14))
    check('recoil energy T25', close(d['recoil_energy_ratio'], math.sin(th / 2) ** 2, 1e-14))
    check('lab sigma', close(d['lab_cross_section'], d['cross_section'] * 4 * math.cos(th / 2), 1e-7))


def lab_angle(qdot):
    """--lab-theta with m1 = 2 m2 (gamma = 2 > 1): two CM angles reach each lab
    angle below asin(1/2), Theta = theta_L + asin(2 sin theta_L) and
    theta_L + pi - asin(...) (Desloge ch. 61 eq. 36), each weighted by
    (1 + g^2 + 2 g cos)^(3/2)/|1 + g cos|; beyond asin(1/2) nothing arrives."""
    m, g, tl = EXAMPLES / 'gaussian_well.qd', 2.0, 0.3
    d = scatter(qdot, m, '--energy', '1/2', '--lab-theta', repr(tl), '--masses', '2,1')
    if not d:
        return
    want, total = [tl + math.asin(g * math.sin(tl)), tl + math.pi - math.asin(g * math.sin(tl))], 0
    check('lab two CM angles', len(d['cm_angles']) == 2, d['cm_angles'])
    for k, th in enumerate(want):
        x = scatter(qdot, m, '--energy', '1/2', '--theta', repr(th))
        c = math.cos(th)
        J = (1 + g * g + 2 * g * c) ** 1.5 / abs(1 + g * c)
        check('lab CM angle %d' % k, close(d['cm_angles'][k]['angle'], th, 1e-13))
        check('lab jacobian %d' % k, close(d['cm_angles'][k]['jacobian'], J, 1e-12))
        total += x['cross_section'] * J if x else 0
    check('lab cross section, both branches', close(d['lab_cross_section'], total, 1e-9),
          (d['lab_cross_section'], total))
    d = scatter(qdot, m, '--energy', '1/2', '--lab-theta', '0.6', '--masses', '2,1')
    check('lab beyond asin(1/gamma)', d and d['cm_angles'] == [] and d['lab_cross_section'] == 0)


def errors(qdot, tmp):
    rut = str(EXAMPLES / 'rutherford.qd')
    cases = [
        ('energy <= 0', [rut, '--energy', '0', '--b', '1'], 'energy must be positive'),
        ('b < 0', [rut, '--energy', '1', '--b', '-1'], 'impact parameter must be >= 0'),
        ('both', [rut, '--energy', '1', '--b', '1', '--theta', '1'],
         'give one of the impact parameter, the centre-of-mass angle and the laboratory angle'),
        ('no cyclic', [str(EXAMPLES / 'kepler_cartesian.qd'), '--energy', '1', '--b', '1'],
         'no cyclic coordinate'),
        ('not central', [str(EXAMPLES / 'spherical_pendulum.qd'), '--energy', '1', '--b', '1'],
         'not a central potential'),
        ('not vanishing', [str(model_file(tmp, 'osc.qd', 'k*r^2')), '--energy', '1', '--b', '1'],
         'does not vanish at infinity'),
        ('bad number', [rut, '--energy', 'x+', '--b', '1'], '--energy:1:3: error: expected an operand'),
        ('unknown name', [rut, '--energy', '2*kk', '--b', '1'], "--energy:1:3: error: unknown name 'kk'"),
        ('lab without masses', [rut, '--energy', '1', '--lab-theta', '1'], 'depends on the masses: give them (--lab-theta)'),
    ]
    for name, args, msg in cases:
        rc, out, err = run(qdot, 'scatter', *args)
        check('error %s' % name, rc == 2 and msg in err, (rc, err))


def mp_deflection(V, E, b):
    """chi = pi - 2 alpha at 30 digits by mpmath's own tanh-sinh in z = b/r
    (Desloge ch. 60: alpha = int_0^z0 dz / sqrt(1 - V(b/z)/E - z^2), z0 the
    first root met from z = 0): an independent evaluation of the integral."""
    import mpmath as mp
    mp.mp.dps = 30
    E, b = mp.mpf(E), mp.mpf(b)
    F = lambda z: 1 - V(mp, b / z) / E - z * z
    z, h = mp.mpf(0), mp.mpf(1) / 2000
    while F(z + h) > 0:
        z += h
    z0 = mp.findroot(F, (z, z + h), solver='bisect')
    # F(z0) is zero to 30 digits, either sign: the rule never samples z0 itself,
    # and a point within round-off of it carries no weight
    f = lambda x: 1 / mp.sqrt(F(x)) if F(x) > 0 else mp.mpf(0)
    return float(mp.pi - 2 * mp.quad(f, [0, z0]))


def against_mpmath(qdot):
    try:
        import mpmath  # noqa: F401
    except ImportError:
        return
    cases = [('gaussian_well.qd', lambda mp, r: -mp.exp(-r * r), 0.5, (0.5, 1.0, 2.0)),
             ('lennard_jones.qd', lambda mp, r: 4 * (r**-12 - r**-6), 2.0, (0.9, 1.3, 2.5))]
    for model, V, E, bs in cases:
        for b in bs:
            d = scatter(qdot, EXAMPLES / model, '--energy', repr(E), '--b', repr(b))
            want = mp_deflection(V, E, b)
            check('%s chi b=%g against mpmath' % (model, b),
                  d and close(d['deflection_signed'], want, 1e-11),
                  d and (d['deflection_signed'], want))


def step_sympy(qdot):
    """step(x) printed for SymPy is Heaviside with the same value at the jump
    (1/2): a model's step potential means the same thing there."""
    try:
        import sympy
    except ImportError:
        return
    rc, out, err = run(qdot, 'print', 'V0*step(a - r)', '--format', 'sympy')
    if rc != 0:
        check('step sympy print', False, err)
        return
    V0, a, r = sympy.symbols('V0 a r')
    e = eval(out.strip(), {'V0': V0, 'a': a, 'r': r, 'Heaviside': sympy.Heaviside})
    for rv, want in ((1, 2), (2, 1), (3, 0)):
        got = e.subs({V0: 2, a: 2, r: rv})
        check('step sympy r=%d' % rv, got == want, (got, want))
    rc, out, err = run(qdot, 'print', 'step(2 - r)', '--format', 'text')
    check('step text', rc == 0 and out.strip() == 'step(-r + 2)', out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    with tempfile.TemporaryDirectory() as tmp:
        rutherford(qdot)
        hard_sphere(qdot)
        refracting_sphere(qdot)
        rainbow(qdot)
        capture(qdot, tmp)
        lab(qdot)
        lab_angle(qdot)
        errors(qdot, tmp)
        step_sympy(qdot)
        against_mpmath(qdot)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())
