#!/usr/bin/env python3
"""End-to-end checks of `qdot stability` against the textbooks' closed forms.

Sources: Britannica 1911 "Dynamics" sec. 5-6 (seed 004_89e868a35cdf1de6.txt) with the
reference notes seed-goldstein-britannica.md (B08/B09 power-law orbits free versus driven,
B11 sleeping top, B13 rotating bowl with friction, B15 ellipsoidal bowl, pitfalls P4-P6);
Byerly Art. 5 Ex. 3 (the spherical pendulum, seed 001) for the conical pendulum.
Run: python3 check_stability_cli.py --build BUILD_DIR
"""
import argparse
import json
import math
import subprocess
import sys
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
FAILED = []


def run(qdot, *args):
    p = subprocess.run([qdot, 'stability', *args], capture_output=True, text=True, timeout=60)
    return p.returncode, p.stdout, p.stderr


def js(qdot, model, *args):
    rc, out, err = run(qdot, str(EXAMPLES / model), *args, '--format', 'json')
    if rc != 0:
        raise AssertionError('exit %d: %s' % (rc, err.strip()))
    return json.loads(out)


def check(name, cond, detail=''):
    if not cond:
        FAILED.append(name)
        print('FAIL %s %s' % (name, detail))


def close(a, b, tol=1e-8):
    return abs(a - b) <= tol * (1 + abs(b))


def power_law(qdot):
    # B08/B09: m = k = 1, circle r0 = 1: free stable iff n > -3, frequency^2 = (n + 3);
    # driven stable iff n > 1, frequency^2 = (n - 1).
    for n in (-2, 0, 2):
        d = js(qdot, 'power_law_orbit.qd', '--ignore', 'theta', '--at', 'r=1', '--set', 'n=%d' % n)
        check('free n=%d stable' % n, d['stable'] is True and d['secular'] is True, d['verdict'])
        check('free n=%d frequency' % n, close(d['frequencies'][0] ** 2, n + 3), d['frequencies'])
        check('free n=%d p' % n, close(d['steady']['p_theta'], 1.0))
        d = js(qdot, 'power_law_orbit.qd', '--driven', 'theta', '--at', 'r=1', '--set', 'n=%d' % n)
        check('driven n=%d verdict' % n, d['stable'] is (n > 1), d['verdict'])
        if n > 1:
            check('driven n=%d frequency' % n, close(d['frequencies'][0] ** 2, n - 1))
    d = js(qdot, 'power_law_orbit.qd', '--ignore', 'theta', '--at', 'r=1', '--set', 'n=-3')
    check('free n=-3 borderline', d['stable'] is None and 'borderline' in d['verdict'], d)
    d = js(qdot, 'power_law_orbit.qd', '--ignore', 'theta', '--at', 'r=1', '--set', 'n=-4')
    check('free n=-4 unstable', d['stable'] is False, d['verdict'])
    # the momentum given instead: p = 2 with n = 2 gives r0 = p^(2/5) (m r0^4 w^2 = p^2/r0^... )
    d = js(qdot, 'power_law_orbit.qd', '--ignore', 'theta', '--momentum', 'p_theta=2',
           '--guess', 'r=1')
    # m r0 w^2 = k r0^2 and p = m r0^2 w  =>  p^2 = m k r0^5
    check('momentum given', close(d['steady']['r'], 2 ** 0.4), d['steady'])
    # the driven rate given: m Omega^2 r0 = k r0^2 => r0 = Omega^2
    d = js(qdot, 'power_law_orbit.qd', '--driven', "theta' = 1.5", '--guess', 'r=2')
    check('rate given', close(d['steady']['r'], 2.25), d['steady'])


def conical(qdot):
    # Conical pendulum (spherical_pendulum.qd: m = 1.1, a = 0.9, g = 9.81):
    # phi'^2 = g/(a cos th0), Omega_osc^2 = (g/(a cos th0)) (1 + 3 cos^2 th0).
    g, a = 9.81, 0.9
    for th in (math.pi / 3, 0.4):
        d = js(qdot, 'spherical_pendulum.qd', '--ignore', 'phi', '--at', 'theta=%r' % th)
        c = math.cos(th)
        check('conical rate %g' % th, close(d['steady']["phi'"] ** 2, g / (a * c)), d['steady'])
        check('conical frequency %g' % th,
              close(d['frequencies'][0] ** 2, g / (a * c) * (1 + 3 * c * c)), d['frequencies'])
        check('conical stable %g' % th, d['stable'] is True and d['secular'] is True)
    # the same rate given through --omega finds theta0 = pi/3 back
    w = math.sqrt(g / (a * 0.5))
    d = js(qdot, 'spherical_pendulum.qd', '--ignore', 'phi', '--omega', "phi'=%r" % w,
           '--guess', 'theta=1')
    check('conical from omega', close(d['steady']['theta'], math.pi / 3), d['steady'])


def top(qdot):
    # B11: A = 1, M g h = 1; nu = 3: frequencies 0.3819660 and 2.6180340, gyroscopic
    # (V_eff a maximum): ordinarily stable, secularly unstable.  nu = 2: double root.
    d = js(qdot, 'sleeping_top.qd', '--ignore', 'psi', '--momentum', 'p_psi=3')
    f = d['frequencies']
    check('top frequencies', len(f) == 2 and close(f[0], (3 - 5 ** 0.5) / 2)
          and close(f[1], (3 + 5 ** 0.5) / 2), f)
    check('top ordinary', d['stable'] is True and d['secular'] is False, d['verdict'])
    check('top verdict', 'ordinarily stable but secularly unstable' in d['verdict'])
    d = js(qdot, 'sleeping_top.qd', '--ignore', 'psi', '--momentum', 'p_psi=2')
    check('top borderline', d['stable'] is None and 'repeated' in d['verdict'], d['verdict'])
    d = js(qdot, 'sleeping_top.qd', '--ignore', 'psi', '--momentum', 'p_psi=1.5')
    check('top unstable', d['stable'] is False, d['verdict'])
    d = js(qdot, 'sleeping_top.qd', '--ignore', 'psi', '--momentum', 'p_psi=3', '--set', 'k=0.1')
    check('top damped', d['dissipation']['stable'] is False and d['dissipation']['max_re'] > 0)


def heavy_top(qdot):
    # Steady precession of the heavy top in Euler angles (heavy_top.qd: M = 1.2, h = 0.3,
    # A = 0.5, C = 0.8, g = 9.81), Britannica sec. 5 (29)-(30), the model's header:
    # M g h = phi' (C w3 - A phi' cos theta), with C w3 = p_psi.
    d = js(qdot, 'heavy_top.qd', '--ignore', 'phi,psi', '--at', 'theta=0.5',
           '--momentum', 'p_psi=24')
    w = d['steady']["phi'"]
    check('precession', close(1.2 * 9.81 * 0.3, w * (24 - 0.5 * w * math.cos(0.5))), d['steady'])
    # upright in Euler angles: a coordinate singularity, named (exit 1)
    rc, _, err = run(qdot, str(EXAMPLES / 'heavy_top.qd'), '--ignore', 'phi,psi', '--at',
                     'theta=0', '--momentum', 'p_psi=24, p_phi=24')
    check('euler singular', rc == 1 and 'not defined' in err, err)


def torus(qdot):
    # examples/torus.qd (m = 1, R = 2, a = 1/2): both equators steady at any rate w; free
    # p_phi: V_eff'' = +-m a w^2 (R +- a), so about the outer equator frequency^2 =
    # w^2 (R + a)/a and about the inner one s^2 = +w^2 (R - a)/a (Britannica sec. 5-6).
    R, a, w = 2.0, 0.5, 2.0
    d = js(qdot, 'torus.qd', '--ignore', 'phi', '--at', 'th=pi', '--omega', "phi'=2")
    check('torus inner steady', close(d['steady']['p_phi'], (R - a) ** 2 * w), d['steady'])
    check('torus inner unstable', d['stable'] is False and d['secular'] is False, d['verdict'])
    check('torus inner growth', close(max(re for re, _ in d['eigenvalues']), w * ((R - a) / a) ** 0.5),
          d['eigenvalues'])
    d = js(qdot, 'torus.qd', '--ignore', 'phi', '--at', 'th=pi', '--momentum', 'p_phi=3')
    check('torus inner from p', close(d['steady']["phi'"], 3 / (R - a) ** 2), d['steady'])
    # a false steady motion still fails, at th = 1 and just off the inner equator
    for th in ('1', 'pi + 1e-6'):
        rc, _, err = run(qdot, str(EXAMPLES / 'torus.qd'), '--ignore', 'phi', '--at',
                         'th=%s' % th, '--omega', "phi'=2")
        check('torus th=%s refused' % th, rc == 1 and 'not a steady motion' in err, err)
    # the rate given, th free: both equators, every sign change over (-pi, pi]
    d = js(qdot, 'torus.qd', '--ignore', 'phi', '--omega', "phi'=2")
    ths = sorted(abs(m['steady']['th']) for m in d['steady_motions'])
    check('torus both equators', len(ths) == 2 and close(ths[0] + 1, 1) and
          close(ths[1], math.pi) and d['complete'] is True, d['steady_motions'])
    outer = [m for m in d['steady_motions'] if abs(m['steady']['th']) < 1][0]
    check('torus outer', outer['stable'] is True and
          close(outer['frequencies'][0] ** 2, w * w * (R + a) / a), outer)
    # no rate at the inner equator: every rate is steady there (a family), exit 2
    rc, _, err = run(qdot, str(EXAMPLES / 'torus.qd'), '--ignore', 'phi', '--at', 'th=pi')
    check('torus family', rc == 2 and "every value of phi'" in err, err)


def precessions(qdot):
    # The heavy top (heavy_top.qd: M = 1.2, h = 0.3, A = 0.5, C = 0.8, g = 9.81) at theta0 =
    # 0.5 with C n = p_psi = 24: A cos(th) phi'^2 - C n phi' + M g h = 0 (Goldstein 3rd ed.
    # sec. 5.7; Britannica sec. 5 (29)-(30), seed 004): the slow and the fast precession.
    A, C, Mgh, th, Cn = 0.5, 0.8, 1.2 * 9.81 * 0.3, 0.5, 24.0
    a, b, c = A * math.cos(th), -Cn, Mgh
    disc = math.sqrt(b * b - 4 * a * c)
    slow, fast = (-b - disc) / (2 * a), (-b + disc) / (2 * a)
    d = js(qdot, 'heavy_top.qd', '--ignore', 'phi,psi', '--at', 'theta=0.5',
           '--momentum', 'p_psi=24')
    rates = sorted(m['steady']["phi'"] for m in d['steady_motions'])
    check('two precessions', len(rates) == 2 and close(rates[0], slow) and
          close(rates[1], fast), (rates, slow, fast))
    check('precessions complete', d['complete'] is True)
    check('slow first', close(d['steady']["phi'"], slow), d['steady'])
    for m in d['steady_motions']:   # n = w3 = psi' + phi' cos th is C n / C for both
        s = m['steady']
        check('spin kept', close(s["psi'"] + s["phi'"] * math.cos(th), Cn / C), s)
    rc, out, err = run(qdot, str(EXAMPLES / 'heavy_top.qd'), '--ignore', 'phi,psi', '--at',
                       'theta=0.5', '--momentum', 'p_psi=24')
    check('precessions text', rc == 0 and out.count('steady motion ') == 2 and
          '2 steady motions' in out, out + err)
    # the rate of spin given instead: (A - C) cos(th) phi'^2 - C psi' phi' + M g h = 0
    d = js(qdot, 'heavy_top.qd', '--ignore', 'phi,psi', '--at', 'theta=0.5', '--omega',
           "psi'=30")
    a2, b2 = (A - C) * math.cos(th), -C * 30
    d2 = math.sqrt(b2 * b2 - 4 * a2 * c)
    want = sorted(((-b2 - d2) / (2 * a2), (-b2 + d2) / (2 * a2)))
    rates = sorted(m['steady']["phi'"] for m in d['steady_motions'])
    check('precessions from the spin rate', len(rates) == 2 and close(rates[0], want[0]) and
          close(rates[1], want[1]), (rates, want))
    # --guess orders them: a rate or a momentum near the fast precession puts it first
    for g in ("phi'=50", 'p_phi=27'):
        d = js(qdot, 'heavy_top.qd', '--ignore', 'phi,psi', '--at', 'theta=0.5',
               '--momentum', 'p_psi=24', '--guess', g)
        check('guess %s' % g, close(d['steady']["phi'"], fast), d['steady'])
    # a kept coordinate and a rate guessed together: theta found from both momenta
    p_phi = A * slow * math.sin(th) ** 2 + Cn * math.cos(th)
    d = js(qdot, 'heavy_top.qd', '--ignore', 'phi,psi', '--momentum',
           'p_phi=%r, p_psi=24' % p_phi, '--guess', "theta=0.45, phi'=0.15")
    check('guess theta and rate', close(d['steady']['theta'], th) and
          close(d['steady']["phi'"], slow), d['steady'])
    rc, _, err = run(qdot, str(EXAMPLES / 'heavy_top.qd'), '--ignore', 'phi,psi', '--at',
                     'theta=0.5', '--momentum', 'p_psi=24', '--guess', 'p_psi=3')
    check('guess of a given value exits 2', rc == 2 and 'given' in err, err)


def free_particle(qdot):
    # A free particle at rest on r = 1: phi' = 0 is a double root of m r sin^2 phi'^2 = 0, the
    # linearization has a double zero root (linear drift): borderline, neither "stable" nor
    # "grows exponentially" (docs: borderline for zero roots).
    for extra in ((), ('--momentum', 'p_phi=0')):
        d = js(qdot, 'free_particle_spherical.qd', '--ignore', 'phi', '--at',
               'r=1, theta=pi/2', *extra)
        check('free particle rate 0 %s' % (extra,), d['steady']["phi'"] == 0, d['steady'])
        check('free particle borderline %s' % (extra,), d['stable'] is None and
              'linearly' in d['verdict'], d['verdict'])
    d = js(qdot, 'torus.qd', '--ignore', 'phi', '--at', 'th=pi', '--momentum', 'p_phi=0')
    check('torus at rest borderline', d['stable'] is None and 'grows exponentially' not in
          d['verdict'], d['verdict'])


def bowl(qdot):
    # B13: p = 1; omega = 0.5 stable; omega = 2 ordinarily stable, secularly unstable; with
    # k = 0.1 max Re s = -0.024976544 and +0.049630741.
    for om, re in ((0.5, -0.024976544), (2.0, 0.049630741)):
        d = js(qdot, 'rotating_bowl.qd', '--driven', "phi' = %r" % om)
        check('bowl %g ordinary' % om, d['stable'] is True, d['verdict'])
        check('bowl %g secular' % om, d['secular'] is (om < 1), d['verdict'])
        check('bowl %g no dissipation' % om, 'dissipation' not in d)
        check('bowl %g frequencies' % om, close(d['frequencies'][0], abs(1 - om))
              and close(d['frequencies'][1], 1 + om), d['frequencies'])
        d = js(qdot, 'rotating_bowl.qd', '--driven', "phi' = %r" % om, '--set', 'k=0.1')
        check('bowl %g friction' % om, close(d['dissipation']['max_re'], re, 1e-7),
              d['dissipation'])
        check('bowl %g friction verdict' % om, d['dissipation']['stable'] is (om < 1))
    # B15: ellipsoidal bowl p1 = 1, p2 = 2
    d = js(qdot, 'ellipsoidal_bowl.qd', '--driven', "phi' = 3", '--set', 'k=0.05')
    f = d['frequencies']
    check('ellipsoid frequencies', close(f[0], 1.37670, 1e-5) and close(f[1], 4.59398, 1e-5), f)
    check('ellipsoid friction', close(d['dissipation']['max_re'], 0.0218379, 1e-6))
    d = js(qdot, 'ellipsoidal_bowl.qd', '--driven', "phi' = 1.5")
    check('ellipsoid unstable', d['stable'] is False)


def errors(qdot):
    pl = str(EXAMPLES / 'power_law_orbit.qd')
    rc, _, err = run(qdot, pl)
    check('no cyclic option exits 2', rc == 2, err)
    rc, _, err = run(qdot, pl, '--ignore', 'r', '--at', 'theta=1')
    check('not cyclic exits 2', rc == 2 and 'not cyclic' in err, err)
    rc, _, err = run(qdot, pl, '--ignore', 'zeta')
    check('unknown coordinate exits 2', rc == 2 and 'zeta' in err, err)
    rc, _, err = run(qdot, pl, '--ignore', 'theta')
    check('underdetermined exits 2', rc == 2 and 'unknowns' in err, err)
    rc, _, err = run(qdot, pl, '--driven', "theta' = 1", '--momentum', 'p_theta=1')
    check('momentum with driven exits 2', rc == 2, err)
    rc, _, err = run(qdot, pl, '--driven', "theta' = 1", '--at', 'r=3')
    check('not steady exits 1', rc == 1 and 'not a steady motion' in err, err)
    # n = 1 driven at m Omega^2 = k: every radius is steady (B09's borderline), a family
    # said as such rather than one radius picked by the starting value (or many by noise)
    rc, _, err = run(qdot, pl, '--driven', "theta' = 1", '--set', 'n=1', '--guess', 'r=2')
    check('driven family exits 2', rc == 2 and 'every value of r' in err, err)
    rc, out, err = run(qdot, pl, '--ignore', 'theta', '--at', 'r=1')
    check('text output', rc == 0 and 'verdict: stable' in out and 'frequencies: 2.236' in out,
          out + err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    for fn in (power_law, conical, top, heavy_top, torus, precessions, free_particle, bowl,
               errors):
        try:
            fn(qdot)
        except Exception as exc:  # a crash or bad JSON
            FAILED.append(fn.__name__)
            print('FAIL %s: %s: %s' % (fn.__name__, type(exc).__name__, exc))
    print('%d failed' % len(FAILED))
    return 1 if FAILED else 0


if __name__ == '__main__':
    sys.exit(main())
