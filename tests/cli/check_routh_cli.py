#!/usr/bin/env python3
"""Tests of `qdot routh`, run against the built program.

    python3 tests/cli/check_routh_cli.py --build BUILD_DIR

Expected values are the books' (reference notes in /work/shared/reference/):

- the bead on the wire a^3 y = x^4 turning about the vertical (Desloge
  ch. 54 P6, seed-desloge-A.md pitfall 7, T42/T44): about the steady motion
  at x = a (phi'^2 = 4g/a) the period is 2 pi sqrt(17a/24g) when the
  rotation is free -- from the reduced equation `routh --ignore phi` prints,
  linearized here by central differences -- and 2 pi sqrt(17a/8g) when it
  is driven (examples/wire_curve_x4_driven.qd through `qdot eom --at`);
- the heavy symmetric top's effective potential (Desloge ch. 72 Ex. 2
  eq. 36; Goldstein sec. 5.7): (p_phi - p_psi cos)^2/(2 A sin^2) + M g h cos
  + p_psi^2/(2C);
- the spherical pendulum's centrifugal barrier: V_eff = V + p^2/(2 m a^2 sin^2);
- errors: a coordinate that is not cyclic is shown at the statement that
  makes it so (exit 2), an unknown name gets the nearest one (exit 2).

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "util"))
from clicheck import check, run, ev, finish  # noqa: E402  (tests/util/clicheck.py)

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'


def routh_json(qdot, model, ignore, *extra):
    rc, out, err = run(qdot, 'routh', str(EXAMPLES / model), '--ignore', ignore,
                       '--format', 'json', *extra)
    if rc != 0:
        raise RuntimeError('qdot routh %s failed: %s' % (model, err))
    return json.loads(out)


def test_wire_periods(qdot):
    m, a, g = 1.0, 1.0, 9.81  # the example's parameters
    omega = math.sqrt(4 * g / a)
    d = routh_json(qdot, 'wire_curve_x4.qd', 'phi')
    check('wire keys', all(k in d for k in ('ignored', 'momenta', 'R', 'R2', 'R1', 'R0',
                                            'effective_potential', 'equations', 'gyroscopic',
                                            'quadratures')), str(sorted(d)))
    check('wire momenta', d['momenta'] == ['p_phi'] and d['ignored'] == ['phi'], str(d['momenta']))
    base = {'m': m, 'a': a, 'g': g, 'p_phi': m * a * a * omega, "x'": 0.0}
    eq = d['equations'][0]
    h = 1e-5

    def f(x):
        return ev(eq['forcing'], dict(base, x=x))
    M = ev(eq['mass_matrix'][0], dict(base, x=a))
    check('wire steady', abs(f(a)) < 1e-9, 'f(a) = %g' % f(a))
    w2 = -(f(a + h) - f(a - h)) / (2 * h) / M
    free = 2 * math.pi * math.sqrt(17 * a / (24 * g))
    check('wire free period', abs(2 * math.pi / math.sqrt(w2) - free) < 1e-6 * free,
          '%g vs %g' % (2 * math.pi / math.sqrt(w2), free))
    # V_eff = m g x^4/a^3 + p^2/(2 m x^2): the barrier has the + sign.
    x = 0.8
    veff = m * g * x**4 / a**3 + base['p_phi']**2 / (2 * m * x * x)
    check('wire V_eff', abs(ev(d['effective_potential'], dict(base, x=x)) - veff) < 1e-9)
    phid = ev(d['quadratures']["phi'"], dict(base, x=x))
    check('wire quadrature', abs(phid - base['p_phi'] / (m * x * x)) < 1e-12)

    # Driven: the eom of the one-coordinate model, by central differences.
    def fd(x):
        rc, out, err = run(qdot, 'eom', str(EXAMPLES / 'wire_curve_x4_driven.qd'), '--at',
                           "x=%r, x'=0, t=0.3" % x, '--set', 'Omega=%r' % omega,
                           '--format', 'json')
        j = json.loads(out)
        return j['forcing'][0], j['mass_matrix'][0][0]
    (fp, _), (fm, _), (f0, Md) = fd(a + h), fd(a - h), fd(a)
    check('wire driven steady', abs(f0) < 1e-9, 'f(a) = %g' % f0)
    w2d = -(fp - fm) / (2 * h) / Md
    driven = 2 * math.pi * math.sqrt(17 * a / (8 * g))
    check('wire driven period', abs(2 * math.pi / math.sqrt(w2d) - driven) < 1e-6 * driven,
          '%g vs %g' % (2 * math.pi / math.sqrt(w2d), driven))


def test_top(qdot):
    M, h, A, C, g = 1.2, 0.3, 0.5, 0.8, 9.81  # heavy_top.qd
    d = routh_json(qdot, 'heavy_top.qd', 'phi,psi')
    check('top kept', d['kept'] == ['theta'], str(d['kept']))
    for th, pf, ps in ((0.4, 1.1, 0.7), (1.3, -0.4, 2.0), (2.2, 0.9, -0.5)):
        vals = {'M': M, 'h': h, 'A': A, 'C': C, 'g': g, 'theta': th, 'p_phi': pf, 'p_psi': ps,
                "theta'": 0.3}
        want = (pf - ps * math.cos(th))**2 / (2 * A * math.sin(th)**2) + M * g * h * math.cos(th) \
            + ps * ps / (2 * C)
        got = ev(d['effective_potential'], vals)
        check('top V_eff', abs(got - want) < 1e-9 * (1 + abs(want)), '%g vs %g' % (got, want))
        check('top R2', abs(ev(d['R2'], vals) + A * 0.09 / 2) < 1e-12)


def test_spherical(qdot):
    m, a, g = 1.1, 0.9, 9.81
    d = routh_json(qdot, 'spherical_pendulum.qd', 'phi')
    th, p = 0.7, 0.45
    want = -m * g * a * math.cos(th) + p * p / (2 * m * a * a * math.sin(th)**2)
    got = ev(d['effective_potential'], {'m': m, 'a': a, 'g': g, 'theta': th, 'p_phi': p})
    check('spherical barrier', abs(got - want) < 1e-12, '%g vs %g' % (got, want))
    # --set replaces a parameter in every printed expression.
    d2 = routh_json(qdot, 'spherical_pendulum.qd', 'phi', '--set', 'a=2')
    want2 = -m * g * 2 * math.cos(th) + p * p / (2 * m * 4 * math.sin(th)**2)
    got2 = ev(d2['effective_potential'], {'m': m, 'g': g, 'theta': th, 'p_phi': p})
    check('--set a=2', abs(got2 - want2) < 1e-12, '%g vs %g' % (got2, want2))


def test_formats(qdot):
    path = str(EXAMPLES / 'heavy_top.qd')
    rc, out, err = run(qdot, 'routh', path, '--ignore', 'psi')
    check('text', rc == 0 and 'V_eff = ' in out and 'G[theta,phi] = ' in out, err)
    rc, out, err = run(qdot, 'routh', path, '--ignore', 'psi', '--format', 'latex')
    check('latex', rc == 0 and '\\\\' in out and '\\theta' in out, err)
    rc, out, err = run(qdot, 'routh', path, '--ignore', 'psi', '--format', 'sympy')
    ns = {}
    try:
        exec(out, ns)
        ok = rc == 0 and ns['routh_M'].shape == (2, 2) and ns['routh_G'][0, 1] == -ns['routh_G'][1, 0]
    except Exception as ex:  # bad Python
        ok, err = False, repr(ex)
    check('sympy', ok, err)


def test_errors(qdot):
    top = str(EXAMPLES / 'heavy_top.qd')
    rc, out, err = run(qdot, 'routh', top, '--ignore', 'theta')
    check('not cyclic: exit 2', rc == 2, str(rc))
    check('not cyclic: located', 'heavy_top.qd:' in err and 'theta cannot be ignored' in err
          and 'V = ' in err, err)
    rc, out, err = run(qdot, 'routh', top, '--ignore', 'phy')
    check('unknown name', rc == 2 and "did you mean 'phi'" in err, err)
    rc, out, err = run(qdot, 'routh', top)
    check('no --ignore', rc == 2 and '--ignore' in err, err)
    rc, out, err = run(qdot, 'routh', top, '--ignore', 'phi,theta,psi')
    check('all ignored', rc == 2, err)
    rc, out, err = run(qdot, 'routh', top, '--ignore', 'phi', '--format', 'xml')
    check('bad format', rc == 2, err)
    rc, out, err = run(qdot, 'routh', str(EXAMPLES / 'polar_generalized_force.qd'), '--ignore',
                       'theta')
    # issue 35: reduced with p_theta' = Q_theta (Byerly Art. 20a), no longer refused
    check('generalized force', rc == 0 and 'p_theta_dot = Fth*r' in out
          and 'f[r] = Fr + p_theta^2/(m*r^3)' in out, out + err)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    for test in (test_wire_periods, test_top, test_spherical, test_formats, test_errors):
        try:
            test(qdot)
        except Exception as ex:  # a crash, bad JSON, a timeout
            check(test.__name__, False, repr(ex))
    return finish()


if __name__ == '__main__':
    sys.exit(main())
