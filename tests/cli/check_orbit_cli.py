#!/usr/bin/env python3
"""Tests of `qdot orbit`, run against the built program.

    python3 tests/cli/check_orbit_cli.py --build BUILD_DIR

Expected values are the books' (reference notes in /work/shared/reference/),
computed here independently of qdot:

- Kepler (Desloge ch. 58, seed-desloge-B.md C3): at several states of
  examples/kepler_polar.qd the ellipse's turning points a(1 -+ e), radial
  period 2 pi sqrt(m a^3/k), advance 2 pi, p = h^2/(m k) and e = sqrt(1 +
  2 E h^2/(m k^2)); the hyperbola and the parabola unbound with no period
  (the hyperbola turning by 2 acos(-1/e) between its asymptotes),
  the circle circular; --momentum and --energy replace the state's values;
- power laws -k r^n (Desloge ch. 59 eq. 31, C3): the near-circular apsidal
  angle pi/sqrt(n + 3) for several n (examples/power_law_orbit.qd --set n);
- the spherical pendulum (Byerly Art. 5 Ex. 3, seed 001): the turning angles
  are roots of E = V_eff as printed, and the radial period agrees with a
  quadrature done here (theta = mid + half sin u, midpoint rule in u);
- a Yukawa orbit (Desloge ch. 58 P7, T07: V = -a e^(-b r)/r), which has no
  closed form: turning points, radial period and advance against mpmath
  (SymPy's, Debian python3-sympy) at 30 digits, r = (r1 + r2)/2 - (r2 -
  r1)/2 cos u removing the end-point singularities (C3's numerics);
- --orbit (C3): the printed conic through the state and its turning points
  (Kepler both ways round, Rutherford's repulsive branch, ch. 58 P9), and the
  printed quadrature, integrated by mpmath, equal to the apsidal angle;
- Desloge ch. 58 P10 b: at the top of V_eff the orbit is asymptotic to the
  unstable circle from both sides; just below it the inside orbit is captured;
- errors (exit 2): no --ignore, a coordinate that is not cyclic, two
  coordinates left, an energy below the minimum of V_eff (both numbers named).

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


def close(name, got, want, rel):
    ok = got is not None and abs(got - want) <= rel * max(1.0, abs(want))
    check(name, ok, 'got %r, want %r' % (got, want))


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout, p.stderr


def orbit(qdot, model, ignore, *extra):
    rc, out, err = run(qdot, 'orbit', str(EXAMPLES / model), '--ignore', ignore,
                       '--format', 'json', *extra)
    if rc != 0:
        check('orbit %s %s' % (model, ' '.join(extra)), False, err)
        return None
    return json.loads(out)


def ev(text, values):
    """A printed expression (qdot's text syntax) at values."""
    env = {n: getattr(math, n) for n in ('sin', 'cos', 'tan', 'sqrt', 'exp', 'log', 'pi')}
    env.update(values)
    return eval(text.replace('^', '**'), {'__builtins__': {}}, env)


M, K = 1.3, 4.0   # examples/kepler_polar.qd


def kepler(qdot):
    for r, rd, td in [(1.0, 0.0, 1.5), (1.0, 0.7, 1.2), (2.0, -0.3, 0.6), (0.5, 1.0, 3.0)]:
        j = orbit(qdot, 'kepler_polar.qd', 'theta', '--at', "r=%r, r'=%r, theta'=%r" % (r, rd, td))
        if not j:
            continue
        h = M * r * r * td
        E = M * (rd * rd + r * r * td * td) / 2 - K / r
        p = h * h / (M * K)
        e = math.sqrt(1 + 2 * E * h * h / (M * K * K))
        a = p / (1 - e * e)
        tag = 'kepler r=%g rd=%g td=%g' % (r, rd, td)
        close(tag + ' E', j['energy'], E, 1e-14)
        check(tag + ' kind', j['kind'] == 'bound', j['kind'])
        close(tag + ' r1', j['turning_points'][0], a * (1 - e), 1e-12)
        close(tag + ' r2', j['turning_points'][1], a * (1 + e), 1e-12)
        close(tag + ' period', j['radial_period'], 2 * math.pi * math.sqrt(M * a**3 / K), 1e-11)
        close(tag + ' advance', j['advance']['theta'], 2 * math.pi, 1e-11)
        close(tag + ' p', j['conic']['p'], p, 1e-13)
        close(tag + ' e', j['conic']['e'], e, 1e-13)
        close(tag + ' a', j['conic']['a'], a, 1e-12)
    # E > 0, E = 0 and the circle
    j = orbit(qdot, 'kepler_polar.qd', 'theta', '--at', "theta'=3")
    check('hyperbola unbound', j and j['kind'] == 'unbound' and j['radial_period'] is None
          and len(j['turning_points']) == 1 and j['conic']['e'] > 1, j)
    if j:   # between the asymptotes, cos(theta) = -1/e
        close('hyperbola turn', j['advance']['theta'], 2 * math.acos(-1 / j['conic']['e']), 1e-11)
    j = orbit(qdot, 'kepler_polar.qd', 'theta', '--at', "theta'=%r" % math.sqrt(2 * K / M))
    check('parabola unbound', j and j['kind'] == 'unbound' and j['conic']['a'] is None, j)
    if j:
        close('parabola e', j['conic']['e'], 1.0, 1e-14)
    j = orbit(qdot, 'kepler_polar.qd', 'theta', '--at', "r=2, theta'=%r" % math.sqrt(K / (M * 8)))
    check('circle circular', j and j['kind'] == 'circular', j and j['kind'])
    if j:
        close('circle period', j['radial_period'], 2 * math.pi * math.sqrt(M * 8 / K), 1e-12)
    # --momentum and --energy: the ellipse of that E and h
    h, E = 2.0, -1.0
    j = orbit(qdot, 'kepler_polar.qd', 'theta', '--momentum', 'p_theta=%r' % h, '--energy', '%r' % E)
    if j:
        e = math.sqrt(1 + 2 * E * h * h / (M * K * K))
        close('momentum given', j['momenta']['p_theta'], h, 0)
        close('energy given e', j['conic']['e'], e, 1e-13)
        close('energy given period', j['radial_period'],
              2 * math.pi * math.sqrt(M * (K / (-2 * E))**3 / K), 1e-11)


def power_laws(qdot):
    for n in (-2.5, -1.5, 0.0, 1.0, 2.0, 4.0):
        j = orbit(qdot, 'power_law_orbit.qd', 'theta', '--set', 'n=%r' % n,
                  '--at', "r=1, r'=0.01, theta'=1")
        if not j:
            continue
        circ = [c for c in j['circular'] if abs(c['r'] - 1) < 1e-9]
        check('power n=%g circle' % n, len(circ) == 1, j['circular'])
        if circ:
            close('power n=%g apsidal' % n, circ[0]['apsidal_angle']['theta'],
                  math.pi / math.sqrt(n + 3), 1e-12)
            close('power n=%g bertrand' % n, circ[0]['bertrand'], math.pi / math.sqrt(n + 3), 1e-12)


def spherical(qdot):
    j = orbit(qdot, 'spherical_pendulum.qd', 'phi')
    if not j:
        return
    m, a, g = 1.1, 0.9, 9.81
    p, E = j['momenta']['p_phi'], j['energy']
    V = lambda th: ev(j['effective_potential'], {'theta': th, 'p_phi': p, 'm': m, 'a': a, 'g': g})
    t1, t2 = j['turning_points']
    close('pendulum V(t1) = E', V(t1), E, 1e-13)
    close('pendulum V(t2) = E', V(t2), E, 1e-13)
    mid, half, n = (t1 + t2) / 2, (t2 - t1) / 2, 4000
    total = 0.0
    for k in range(n):   # the midpoint rule: spectral here, the integrand being even about +-pi/2
        u = -math.pi / 2 + math.pi * (k + 0.5) / n
        th = mid + half * math.sin(u)
        gap = E - V(th)
        if gap > 0:
            total += math.sqrt(m * a * a / (2 * gap)) * half * math.cos(u)
    close('pendulum period', j['radial_period'], 2 * total * math.pi / n, 1e-9)


YUKAWA = '''coordinates r, phi
parameters m = 1.2, a = 2, b = 0.6
particle m at r*(cos(phi), sin(phi))
V = -a*exp(-b*r)/r
initial r = 1, phi = 0, r' = 0.3, phi' = 1.1
'''


def yukawa(qdot, tmp):
    try:
        import mpmath
    except ImportError:
        check('mpmath available', False, 'python3-sympy (mpmath) is needed')
        return
    model = Path(tmp) / 'yukawa.qd'
    model.write_text(YUKAWA)
    rc, out, err = run(qdot, 'orbit', str(model), '--ignore', 'phi', '--format', 'json')
    check('yukawa runs', rc == 0, err)
    if rc != 0:
        return
    j = json.loads(out)
    mpmath.mp.dps = 30
    m, a, b = mpmath.mpf('1.2'), mpmath.mpf(2), mpmath.mpf('0.6')
    r0, rd0, pd0 = mpmath.mpf(1), mpmath.mpf('0.3'), mpmath.mpf('1.1')
    h = m * r0**2 * pd0
    U = lambda r: -a * mpmath.exp(-b * r) / r + h**2 / (2 * m * r**2)
    E = m * rd0**2 / 2 + U(r0)
    r1 = mpmath.findroot(lambda r: U(r) - E, j['turning_points'][0])
    r2 = mpmath.findroot(lambda r: U(r) - E, j['turning_points'][1])
    mid, half = (r1 + r2) / 2, (r2 - r1) / 2

    def dt(u):   # dt/du = dr/du / r', r = mid - half cos u
        r = mid - half * mpmath.cos(u)
        return half * mpmath.sin(u) * mpmath.sqrt(m / (2 * (E - U(r))))
    T = 2 * mpmath.quad(dt, [0, mpmath.pi])
    adv = 2 * mpmath.quad(lambda u: dt(u) * h / (m * (mid - half * mpmath.cos(u))**2), [0, mpmath.pi])
    # measured: E, r1, r2 to 6e-16, the period to 3e-14, the advance to 1e-14
    close('yukawa E', j['energy'], float(E), 1e-14)
    close('yukawa r1', j['turning_points'][0], float(r1), 1e-13)
    close('yukawa r2', j['turning_points'][1], float(r2), 1e-13)
    close('yukawa period', j['radial_period'], float(T), 1e-12)
    close('yukawa advance', j['advance']['phi'], float(adv), 1e-12)


def orbit_equation(qdot, tmp):
    """--orbit: the conic's equation, evaluated as printed, passes through the state
    and reaches the turning points at periapsis (Kepler, C3; Rutherford's repulsive
    branch p/(e cos - 1), T15); the quadrature's integrand, integrated here by mpmath
    between the turning points, gives the apsidal angle (Yukawa, T07)."""
    cases = [('kepler_polar.qd', 'theta', "r=1, r'=0.7, theta'=1.2", 1.0),
             ('kepler_polar.qd', 'theta', "r=1, r'=0.7, theta'=-1.2", 1.0),
             ('kepler_polar.qd', 'theta', "r=2, r'=-0.3, theta'=3", 2.0),
             ('rutherford.qd', 'phi', "r=1, r'=-1, phi'=0.5", 1.0),
             ('inverse_cube_orbit.qd', 'phi', None, None)]
    for model, c, at, r0 in cases:
        extra = ('--at', at) if at else ()
        j = orbit(qdot, model, c, '--orbit', *extra)
        if not j:
            continue
        lhs, rhs = j['orbit'].split(' = ', 1)
        tag = 'orbit equation %s %s' % (model, at)
        check(tag + ' form', lhs == 'r' and j['conic'] is not None, j['orbit'])
        if r0 is not None:
            close(tag + ' state', ev(rhs, {c: 0.0}), r0, 1e-10)  # 12 printed digits
        close(tag + ' periapsis', ev(rhs, {c: j['conic']['periapsis']}), j['turning_points'][0],
              1e-10)
        check(tag + ' repulsive', j['conic']['repulsive'] == (model == 'rutherford.qd'), j['conic'])
    try:
        import mpmath
    except ImportError:
        check('mpmath available', False, 'python3-sympy (mpmath) is needed')
        return
    model = Path(tmp) / 'yukawa.qd'
    model.write_text(YUKAWA)
    rc, out, err = run(qdot, 'orbit', str(model), '--ignore', 'phi', '--orbit', '--format', 'json')
    check('yukawa --orbit runs', rc == 0, err)
    if rc != 0:
        return
    j = json.loads(out)
    head, rest = j['orbit'].split(' = integral(', 1)
    check('yukawa quadrature form', head == 'phi - phi_1' and rest.endswith(', r, r_1, r)'),
          j['orbit'])
    body = rest[:-len(', r, r_1, r)')]
    mpmath.mp.dps = 30
    env = {n: getattr(mpmath, n) for n in ('sin', 'cos', 'sqrt', 'exp', 'log', 'pi')}
    env.update(m=mpmath.mpf('1.2'), a=mpmath.mpf(2), b=mpmath.mpf('0.6'),
               E=mpmath.mpf(j['energy']), p_phi=mpmath.mpf(j['momenta']['p_phi']))
    f = lambda r: eval(body.replace('^', '**'), {'__builtins__': {}}, dict(env, r=r))
    U = lambda r: eval(j['effective_potential'].replace('^', '**'), {'__builtins__': {}},
                       dict(env, r=r))
    r1 = mpmath.findroot(lambda r: U(r) - env['E'], j['turning_points'][0])
    r2 = mpmath.findroot(lambda r: U(r) - env['E'], j['turning_points'][1])
    mid, half = (r1 + r2) / 2, (r2 - r1) / 2
    alpha = mpmath.quad(lambda u: mpmath.re(f(mid - half * mpmath.cos(u))) * half * mpmath.sin(u),
                        [0, mpmath.pi])
    close('yukawa quadrature = apsidal angle', float(alpha), j['apsidal_angle']['phi'], 1e-12)


def separatrix(qdot):
    """Desloge ch. 58 P10 b (examples/r4_potential.qd, m = 2, a = 1, p_phi = 2): at the
    top of V_eff, E = p^4/(4 a m^2) = 1, the orbit creeps towards r = b = sqrt(a m)/p
    from either side; 1e-9 below it the inside orbit turns just short of b (the
    walk used to jump that gap and call the orbit unbound)."""
    b = 1 / math.sqrt(2)
    for at, lo, hi in (("r=0.5, phi'=4", 0.0, b), ("r=2, phi'=0.25", b, None)):
        j = orbit(qdot, 'r4_potential.qd', 'phi', '--at', at, '--energy', '1')
        if not j:
            continue
        check('separatrix %s kind' % at, j['kind'] == 'asymptotic', j['kind'])
        close('separatrix %s lo' % at, j['interval'][0], lo, 1e-12)
        check('separatrix %s hi' % at, (hi is None and j['interval'][1] is None) or
              (hi is not None and abs(j['interval'][1] - hi) < 1e-12), j['interval'])
        check('separatrix %s no period' % at, j['radial_period'] is None and
              j['advance']['phi'] is None, j)
    # the pendulum's separatrix, E = m g a given as an expression in the parameters
    j = orbit(qdot, 'spherical_pendulum.qd', 'phi', '--at', "theta=0.3, phi'=0", '--energy', 'm*g*a')
    if j:
        check('pendulum separatrix', j['kind'] == 'asymptotic' and
              abs(j['interval'][0] + math.pi) < 1e-12 and abs(j['interval'][1] - math.pi) < 1e-12, j)
    j = orbit(qdot, 'r4_potential.qd', 'phi', '--at', "r=0.5, phi'=4", '--energy', '0.999999999')
    if j:
        check('below the top: capture', j['kind'] == 'capture', j['kind'])
        t = j['turning_points']
        check('below the top: turns short of b', len(t) == 1 and 0.999 * b < t[0] < b, t)


def errors(qdot):
    path = str(EXAMPLES / 'kepler_polar.qd')
    rc, out, err = run(qdot, 'orbit', path)
    check('no --ignore exit 2', rc == 2 and '--ignore' in err, err)
    rc, out, err = run(qdot, 'orbit', path, '--ignore', 'r')
    check('not cyclic exit 2', rc == 2 and 'r cannot be ignored' in err, err)
    rc, out, err = run(qdot, 'orbit', str(EXAMPLES / 'free_particle_spherical.qd'), '--ignore', 'phi')
    check('two left exit 2', rc == 2 and 'r, theta' in err, err)
    rc, out, err = run(qdot, 'orbit', path, '--ignore', 'theta', '--energy', '-3')
    vmin = -M * K * K / (2 * (M * 1.5)**2)   # -m k^2/(2 h^2) at the example's h
    check('below minimum exit 2', rc == 2 and '-3' in err and ('%.12g' % vmin) in err, err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    args = ap.parse_args()
    qdot = str(Path(args.build) / 'qdot')
    kepler(qdot)
    power_laws(qdot)
    spherical(qdot)
    with tempfile.TemporaryDirectory() as tmp:
        yukawa(qdot, tmp)
        orbit_equation(qdot, tmp)
    separatrix(qdot)
    errors(qdot)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())
