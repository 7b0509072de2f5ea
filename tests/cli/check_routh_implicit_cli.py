#!/usr/bin/env python3
"""tests/cli/check_routh_implicit_cli.py - `qdot routh` on a Lagrangian whose
ignored velocity has no closed form (issue 17: the implicit Routhian).

    python3 tests/cli/check_routh_implicit_cli.py --build BUILD_DIR

examples/routh_implicit.qd: L = cosh(x') + y'^2/2 + x' y' y/2 - y^2, x cyclic,
p_x = sinh(x') + y y'/2.  Lagrange's equations written out by hand,

    y'' + (y/2) x''            = -2 y
    (y/2) y'' + cosh(x') x''   = -y'^2/2      (dp_x/dt = 0),

are solved here as a 2x2 system at random states; the printed reduced
equation M y'' = f must give the same y'' (to 1e-12), and the printed R must
equal p_x x' - L.  The text must say the velocities have no closed form, the
JSON must carry "implicit": true, and a closed-form case (the relativistic
Kepler problem ignoring theta, legendre_family.c) must not.

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import math
import random
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "util"))
from clicheck import check, run, ev, finish  # noqa: E402  (tests/util/clicheck.py)

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'


def full_ydd(y, yd, xd):
    """y'' from the hand-written Lagrange equations (Cramer's rule)."""
    a, b, c, d = 1.0, y / 2, y / 2, math.cosh(xd)
    r1, r2 = -2 * y, -yd * yd / 2
    return (r1 * d - b * r2) / (a * d - b * c)


def implicit_text(qdot):
    model = str(EXAMPLES / 'routh_implicit.qd')
    rc, out, err = run(qdot, 'routh', model, '--ignore', 'x')
    check('routh on a non-quadratic L exits 0', rc == 0, err)
    check('the text says the velocities have no closed form',
          'no closed form, so R is implicit' in out, out)
    check('no quadrature is printed', "x' =" not in out, out)


def implicit_json(qdot):
    model = str(EXAMPLES / 'routh_implicit.qd')
    rc, out, err = run(qdot, 'routh', model, '--ignore', 'x', '--format', 'json')
    check('json exits 0', rc == 0, err)
    if rc != 0:
        return
    data = json.loads(out)
    check('json says implicit', data.get('implicit') is True, out)
    check('no effective potential in closed form', data.get('effective_potential') is None, out)
    M, f = data['equations'][0]['mass_matrix'][0], data['equations'][0]['forcing']
    rng = random.Random(1779)
    worst = worst_R = 0.0
    for _ in range(20):
        y, yd, xd = rng.uniform(-1.5, 1.5), rng.uniform(-2, 2), rng.uniform(-2, 2)
        px = math.sinh(xd) + y * yd / 2
        pt = {'y': y, "y'": yd, "x'": xd, 'p_x': px}
        want = full_ydd(y, yd, xd)
        worst = max(worst, abs(ev(f, pt) / ev(M, pt) - want) / (1 + abs(want)))
        L = math.cosh(xd) + yd * yd / 2 + xd * yd * y / 2 - y * y
        worst_R = max(worst_R, abs(ev(data['R'], pt) - (px * xd - L)))
    check("reduced y'' equals the full Lagrange equations' y''", worst < 1e-12, worst)
    check("R = p_x x' - L", worst_R < 1e-12, worst_R)


def closed_form_not_implicit(qdot):
    rc, out, err = run(qdot, 'routh', str(EXAMPLES / 'relativistic_kepler.qd'), '--ignore',
                       'th', '--format', 'json')
    check('relativistic Kepler routh exits 0', rc == 0, err)
    check('a closed-form R has no implicit key', rc == 0 and 'implicit' not in json.loads(out),
          out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    implicit_text(qdot)
    implicit_json(qdot)
    closed_form_not_implicit(qdot)
    return finish()


if __name__ == '__main__':
    sys.exit(main())
