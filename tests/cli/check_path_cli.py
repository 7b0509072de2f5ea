#!/usr/bin/env python3
"""Tests of `qdot path`, run against the built program.

    python3 tests/cli/check_path_cli.py --build BUILD_DIR

Expected values computed here independently of qdot (Desloge ch. 82-84,
Hamilton's principle and Maupertuis'; Byerly ch. IV; seed-desloge-D.md):

- examples/path_projectile.qd from (0,0) to (X,0) in T: one path,
  v0 = (X/T, g T/2), S = m X^2/(2T) - m g^2 T^3/24 (the integral of
  m/2 v^2 - m g y done by hand), the samples on y = (g T/2) t - g t^2/2;
- the same at energy E = m v^2/2 through (X, Y) with --all: the two lobs,
  tan(theta) = (v^2 +- sqrt(v^4 - g (g X^2 + 2 Y v^2)))/(g X), each with the
  time of flight X/(v cos theta);
- examples/path_pendulum.qd from 0.1 to 0.2 rad in 4.5 (omega = pi) with
  --all: more than one path, distinct, sorted by action, each starting and
  ending at the given angles and keeping its energy along the samples;
- small pendulum swings from the equilibrium: the kinetic focus at
  pi sqrt(l/g) and no minimum past it, a minimum before it;
- errors: an end off the rod of examples/pendulum_cartesian.qd (exit 1, the
  constraint and the residual named); at fixed energy an end beyond the
  turning point (exit 1, "out of reach"); bad options (exit 2);
- isoperimetric (Desloge vol. 2 App. 32 Thm 5, seed-desloge-D.md C15, P19):
  examples/catenary.qd from (0,0) to (2,1) with l = 3 (and --set w=2, l=4):
  y = c + a cosh((x - x0)/a) with sqrt(l^2 - h^2) = 2 a sinh(d/(2a)) (a by
  bisection here), x0 = mid - a atanh(h/l), the multiplier lambda_length =
  w c (the model's L = F - lambda G), the integral F = w (c l + a^2/2
  [u + sinh u cosh u]); a chain shorter than the chord: exit 2, the message;
- free ends (Gelfand and Fomin ch. 1 sec. 6): the chain sliding on x = 1
  (horizontal there: l = a sinh(1/a)); examples/path_point_to_line.qd (the
  perpendicular, one end coordinate free or both); the brachistochrone to the
  line x = pi from the point th0 = pi/3 of the cycloid R = 1
  (examples/brachistochrone_free_end.qd: y' = sqrt(3) at the start, y = 2 at
  the line, time (2 pi/3)/sqrt(g)).

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
results = {'passed': 0, 'failed': 0}


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, detail))


def close(name, got, want, tol):
    ok = got is not None and abs(got - want) <= tol * max(1.0, abs(want))
    check(name, ok, 'got %r, want %r' % (got, want))


def run(qdot, *args):
    p = subprocess.run([qdot, *args], capture_output=True, text=True, timeout=120)
    return p.returncode, p.stdout, p.stderr


def paths(qdot, model, *args):
    rc, out, err = run(qdot, 'path', str(EXAMPLES / model), '--format', 'json', *args)
    if rc != 0:
        check('path %s %s' % (model, ' '.join(args)), False, err)
        return None
    return json.loads(out)


def projectile_time(qdot):
    m, g, X, T = 2.0, 9.81, 10.0, 2.0
    r = paths(qdot, 'path_projectile.qd', '--from', 'x=0, y=0, t=0', '--to', 'x=10, y=0, t=2')
    if not r:
        return
    check('projectile one path', r['count'] == 1 and len(r['paths']) == 1, r['count'])
    p = r['paths'][0]
    close("projectile x'", p['initial_velocities']["x'"], X / T, 1e-9)
    close("projectile y'", p['initial_velocities']["y'"], g * T / 2, 1e-9)
    close('projectile action', p['action'], m * X * X / (2 * T) - m * g * g * T**3 / 24, 1e-9)
    worst = max(abs(y - (g * T / 2 * t - g * t * t / 2)) for t, x, y in p['samples'])
    check('projectile samples on the parabola', worst < 1e-9, worst)
    check('projectile keys', set(p) >= {'action', 'initial_velocities', 'samples',
                                        'kinetic_foci', 'minimum'}, sorted(p))


def projectile_energy(qdot):
    m, g, X, Y, v = 2.0, 9.81, 8.0, 2.0, 12.0
    r = paths(qdot, 'path_projectile.qd', '--from', 'x=0, y=0', '--to', 'x=8, y=2',
              '--energy', '%r' % (m * v * v / 2), '--all')
    if not r:
        return
    check('lobs: two paths', r['count'] == 2, r['count'])
    disc = math.sqrt(v**4 - g * (g * X * X + 2 * Y * v * v))
    want = sorted(math.atan((v * v + s * disc) / (g * X)) for s in (-1, 1))
    got = sorted(math.atan2(p['initial_velocities']["y'"], p['initial_velocities']["x'"])
                 for p in r['paths'])
    for k in range(min(2, len(got))):
        close('lob %d angle' % k, got[k], want[k], 1e-8)
    for p in r['paths']:
        ang = math.atan2(p['initial_velocities']["y'"], p['initial_velocities']["x'"])
        close('lob flight time', p['samples'][-1][0], X / (v * math.cos(ang)), 1e-8)


def pendulum(qdot):
    g = 9.8696044010893586
    r = paths(qdot, 'path_pendulum.qd', '--from', 'th=0.1, t=0', '--to', 'th=0.2, t=4.5', '--all')
    if not r:
        return
    ps = r['paths']
    check('pendulum several paths', len(ps) >= 2, len(ps))
    v0 = [p['initial_velocities']["th'"] for p in ps]
    check('pendulum distinct', all(abs(a - b) > 1e-6 for i, a in enumerate(v0) for b in v0[:i]), v0)
    check('pendulum by action', all(ps[i]['action'] <= ps[i + 1]['action']
                                    for i in range(len(ps) - 1)))
    # --guess picks the start: near the linear oscillator's v0 = omega (b - a
    # cos wT)/sin wT = 0.2 pi, the near-linear path (the largest action here)
    g1 = paths(qdot, 'path_pendulum.qd', '--from', 'th=0.1, t=0', '--to', 'th=0.2, t=4.5',
               '--guess', "th'=0.63")
    if g1 and ps:
        close('pendulum --guess', g1['paths'][0]['initial_velocities']["th'"],
              max(ps, key=lambda p: p['action'])['initial_velocities']["th'"], 1e-8)
        close('pendulum near-linear v0', g1['paths'][0]['initial_velocities']["th'"],
              0.2 * math.pi, 0.05)
    for p in ps:
        s = p['samples']
        close('pendulum start', s[0][1], 0.1, 1e-12)
        close('pendulum end', s[-1][1], 0.2, 1e-8)
        h0 = v0[ps.index(p)] ** 2 / 2 - g * math.cos(0.1)
        # energy at the midpoint from a five-point difference of the samples
        k = len(s) // 2
        dt = s[k + 1][0] - s[k][0]
        vk = (-s[k + 2][1] + 8 * s[k + 1][1] - 8 * s[k - 1][1] + s[k - 2][1]) / (12 * dt)
        # (its own error, (omega dt)^4/30 times the higher harmonics of a
        # large libration, is about 1e-3 here; a curve that is not a motion
        # is off by tens of per cent)
        close('pendulum energy kept', vk * vk / 2 - g * math.cos(s[k][1]), h0, 2e-3)


def pendulum_focus(qdot):
    # small swings about the stable equilibrium: the kinetic focus of t0 at
    # pi sqrt(l/g) = 1 (Desloge ch. 84), up to the amplitude's correction
    # (1 + theta0^2/16, below 1e-5 here); before it the path is a minimum
    r = paths(qdot, 'path_pendulum.qd', '--from', 'th=0, t=0', '--to', 'th=0.01, t=1.5')
    if r:
        p = r['paths'][0]
        check('pendulum one focus', len(p['kinetic_foci']) == 1, p['kinetic_foci'])
        if p['kinetic_foci']:
            close('pendulum focus at pi sqrt(l/g)', p['kinetic_foci'][0], 1.0, 1e-4)
        check('pendulum past the focus: no minimum', p['minimum'] is False)
    r = paths(qdot, 'path_pendulum.qd', '--from', 'th=0, t=0', '--to', 'th=0.01, t=0.8')
    if r:
        p = r['paths'][0]
        check('pendulum before the focus: minimum', p['minimum'] is True and
              not p['kinetic_foci'], p)


def isotropic_focus(qdot):
    # the isotropic plane oscillator (w = 1): every path from a point comes
    # back together at t = pi, where both Jacobi fields vanish: one focus of
    # multiplicity 2, where det J = (sin t)^2 touches 0 without changing sign
    r = paths(qdot, 'hj_anisotropic.qd', '--set', 'ky=1', '--from', 'x=0, y=0, t=0',
              '--to', 'x=0.5, y=0.3, t=4')
    if r:
        p = r['paths'][0]
        check('isotropic: one focus', len(p['kinetic_foci']) == 1, p['kinetic_foci'])
        if p['kinetic_foci']:
            close('isotropic focus at pi', p['kinetic_foci'][0], math.pi, 1e-8)
        check('isotropic focus multiplicity 2', p.get('kinetic_foci_multiplicity') == [2],
              p.get('kinetic_foci_multiplicity'))
        check('isotropic past pi: no minimum', p['minimum'] is False)


def errors(qdot):
    rc, out, err = run(qdot, 'path', str(EXAMPLES / 'pendulum_cartesian.qd'),
                       '--from', 'x=0, y=-1.4, t=0', '--to', 'x=2, y=0, t=1')
    check('off the rod exit 1', rc == 1 and 'rod' in err and 'residual' in err, (rc, err))
    proj = str(EXAMPLES / 'path_projectile.qd')
    # from (0,0) at E = m g y_max with y_max = 1 the point (0, 3) is out of reach
    rc, out, err = run(qdot, 'path', proj, '--from', 'x=0, y=0', '--to', 'x=0, y=3',
                       '--energy', '19.62')
    # said before any search: V = m g y = 58.86 at y = 3, the energy at rest there, exceeds E
    check('beyond reach exit 1', rc == 1 and 'out of reach' in err and '58.86' in err, (rc, err))
    for bad in (['--from', 'x=0, y=0, t=0'],
                ['--from', 'x=0, y=0, t=0', '--to', 'x=1, y=0'],
                ['--from', 'x=0, y=0, t=1', '--to', 'x=1, y=0, t=0'],
                ['--from', 'x=0, y=0, t=0', '--to', 'x=1, y=0, t=1', '--segments', '0'],
                ['--from', 'x=0, y=0, t=0', '--to', 'x=1, y=0, t=1', '--format', 'csv'],
                ['--from', 'x=0, y=0, t=0', '--to', 'x=1, y=0, t=1', '--bogus'],
                ['--from', 'z=0, t=0', '--to', 'x=1, y=0, t=1']):
        rc, out, err = run(qdot, 'path', proj, *bad)
        check('bad options exit 2: %s' % ' '.join(bad), rc == 2, (rc, err))


def half_width(r, s):
    """a with 2 a sinh(s/a) = r, by bisection (the left side falls)."""
    lo, hi = 1e-3, 1e3
    for _ in range(300):
        a = math.sqrt(lo * hi)
        if 2 * a * math.sinh(s / a) > r:
            lo = a
        else:
            hi = a
    return math.sqrt(lo * hi)


def catenary_length(qdot):
    for w, l in ((1.0, 3.0), (2.0, 4.0)):
        xa, ya, xb, yb = 0.0, 0.0, 2.0, 1.0
        r = paths(qdot, 'catenary.qd', '--from', 'x=0, y=0', '--to', 'x=2, y=1',
                  '--set', 'w=%g' % w, '--set', 'l=%g' % l)
        if not r:
            continue
        p = r['paths'][0]
        a = half_width(math.sqrt(l * l - (yb - ya) ** 2), (xb - xa) / 2)
        x0 = (xa + xb) / 2 - a * math.atanh((yb - ya) / l)
        c = ya - a * math.cosh((xa - x0) / a)
        tag = 'catenary w=%g l=%g' % (w, l)
        close(tag + ' multiplier', p['multipliers'].get('lambda_length'), w * c, 1e-7)
        close(tag + " y'(0)", p['initial_velocities']["y'"], math.sinh((xa - x0) / a), 1e-7)
        worst = max(abs(y - (c + a * math.cosh((x - x0) / a))) for x, y in p['samples'])
        check(tag + ' samples on the catenary', worst < 1e-7, worst)
        ua, ub = (xa - x0) / a, (xb - x0) / a
        F = w * (c * l + a * a / 2 * (ub - ua + math.sinh(ub) * math.cosh(ub)
                                     - math.sinh(ua) * math.cosh(ua)))
        close(tag + ' integral F', p['action'], F, 1e-7)
        check(tag + ' second variation not examined', p['examined'] is False, p['examined'])
    rc, out, err = run(qdot, 'path', str(EXAMPLES / 'catenary.qd'), '--from', 'x=0, y=0',
                       '--to', 'x=2, y=2.5')
    check('chain shorter than the chord exit 2', rc == 2 and
          'the length l = 3 is shorter than the distance 3.201562119 between the end points: '
          'no curve' in err, (rc, err))
    r = paths(qdot, 'path_projectile.qd', '--from', 'x=0, y=0, t=0', '--to', 'x=10, y=0, t=2')
    check('no multipliers, examined', r and r['paths'][0]['multipliers'] == {} and
          r['paths'][0]['examined'] is True, r and r['paths'][0]['multipliers'])


def free_ends(qdot):
    r = paths(qdot, 'catenary.qd', '--from', 'x=0, y=0', '--to', 'x=1, y=free')
    if r:
        p = r['paths'][0]
        a = half_width(6.0, 1.0)  # l = a sinh(1/a) = 3
        c = -a * math.cosh(1 / a)
        close('sliding chain multiplier', p['multipliers']['lambda_length'], c, 1e-7)
        close('sliding chain end height', p['samples'][-1][1], c + a, 1e-7)
        close("sliding chain y'(0)", p['initial_velocities']["y'"], -math.sinh(1 / a), 1e-6)
    r = paths(qdot, 'path_point_to_line.qd', '--from', 'x=0, y=1, z=2',
              '--to', 'x=3, y=free, z=free')
    if r:
        p = r['paths'][0]
        close('perpendicular length', p['action'], 3.0, 1e-9)
        close("perpendicular y'", p['initial_velocities']["y'"], 0.0, 1e-9)
        close('perpendicular end', p['samples'][-1][2], 2.0, 1e-9)
    r = paths(qdot, 'path_point_to_line.qd', '--from', 'x=0, y=1, z=2',
              '--to', 'x=3, y=5, z=free')
    if r:
        p = r['paths'][0]
        close('one free coordinate: length', p['action'], 5.0, 1e-9)
        close("one free coordinate: y'", p['initial_velocities']["y'"], 4 / 3, 1e-9)
        close("one free coordinate: z'", p['initial_velocities']["z'"], 0.0, 1e-9)
    g = 9.8
    r = paths(qdot, 'brachistochrone_free_end.qd', '--from', 'x=pi/3 - sqrt(3)/2, y=1/2',
              '--to', 'x=pi, y=free', '--guess', "y'=1")
    if r:
        p = r['paths'][0]
        close("brachistochrone y' at th0", p['initial_velocities']["y'"], math.sqrt(3), 1e-6)
        close('brachistochrone meets x = pi at y = 2', p['samples'][-1][1], 2.0, 1e-6)
        close('brachistochrone time', p['action'], 2 * math.pi / 3 / math.sqrt(g), 1e-7)
    proj = str(EXAMPLES / 'path_projectile.qd')
    for bad in (['--from', 'x=0, y=0, t=0', '--to', 'x=1, m=free, t=1'],
                ['--from', 'x=0, y=0', '--to', 'x=1, y=free', '--energy', '5']):
        rc, out, err = run(qdot, 'path', proj, *bad)
        check('bad free end exit 2: %s' % ' '.join(bad), rc == 2 and 'free' in err, (rc, err))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    args = ap.parse_args()
    qdot = str(Path(args.build) / 'qdot')
    projectile_time(qdot)
    projectile_energy(qdot)
    pendulum(qdot)
    pendulum_focus(qdot)
    isotropic_focus(qdot)
    errors(qdot)
    catenary_length(qdot)
    free_ends(qdot)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())
