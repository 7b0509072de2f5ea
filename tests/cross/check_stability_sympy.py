#!/usr/bin/env python3
"""Cross-check of `qdot stability` roots against SymPy on the characteristic polynomials
the reference derives (seed-goldstein-britannica.md):

- B13, the spherical bowl turned at omega with friction k relative to the bowl:
  (s^2 + k s + p^2)^2 + k^2 omega^2 = 0 (fixed axes), p^2 = g/a.  In the bowl's axes the
  roots are shifted by +-i omega, so the real parts agree;
- B15, the ellipsoidal bowl without friction, in the bowl's axes:
  s^4 + (p1^2 + p2^2 + 2 w^2) s^2 + (p1^2 - w^2)(p2^2 - w^2) = 0;
- B11, the sleeping top: (A s^2 - M g h)^2 + nu^2 s^2 = 0.

Random parameters; each qdot root must be a root of the polynomial (|P(s)| small against
the size of its terms), and the largest real parts must agree.
Run: python3 check_stability_sympy.py --build BUILD_DIR
"""
import argparse
import json
import random
import subprocess
import sys
from pathlib import Path

import sympy as sp

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
s = sp.symbols('s')


def roots_of(qdot, model, *args):
    out = subprocess.run([qdot, 'stability', str(EXAMPLES / model), *args, '--format', 'json'],
                         capture_output=True, text=True, timeout=60, check=True).stdout
    return json.loads(out)


def agree(poly, roots, label):
    P = sp.Poly(poly, s)
    want = [complex(r) for r in P.nroots(n=30)]
    got = [complex(re, im) for re, im in roots]
    ok = len(got) == len(want)
    for z in got:
        size = sum(abs(complex(c)) * abs(z) ** k for k, c in enumerate(reversed(P.all_coeffs())))
        ok = ok and abs(complex(P.eval(z))) <= 1e-9 * size
    ok = ok and abs(max(z.real for z in got) - max(z.real for z in want)) <= 1e-8
    if not ok:
        print('FAIL %s: qdot %s, sympy %s' % (label, got, want))
    return ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build) / 'qdot')
    rng = random.Random(20261121)
    failed = 0
    for _ in range(3):
        a, g, k, w = rng.uniform(0.5, 2), rng.uniform(0.5, 2), rng.uniform(0.02, 0.3), \
            rng.uniform(0.2, 3)
        d = roots_of(qdot, 'rotating_bowl.qd', '--driven', "phi' = %r" % w,
                     '--set', 'a=%r' % a, '--set', 'g=%r' % g, '--set', 'k=%r' % k)
        p2 = sp.Rational(repr(g)) / sp.Rational(repr(a))
        kk, ww = sp.Rational(repr(k)), sp.Rational(repr(w))
        fixed = (s**2 + kk * s + p2)**2 + kk**2 * ww**2
        # the bowl's axes turn at w: s_bowl = s_fixed - i w for the co-rotating pair
        rotated = sp.expand(fixed.subs(s, s + sp.I * ww) * fixed.subs(s, s - sp.I * ww))
        # rotated has 8 roots (both shifts); qdot's 4 must be among them
        P = sp.Poly(rotated, s)
        want = [complex(r) for r in P.nroots(n=30)]
        got = [complex(re, im) for re, im in d['dissipation']['eigenvalues']]
        ok = all(min(abs(z - y) for y in want) <= 1e-7 * (1 + abs(z)) for z in got)
        re_fixed = max(complex(r).real for r in sp.Poly(fixed, s).nroots(n=30))
        ok = ok and abs(max(z.real for z in got) - re_fixed) <= 1e-8
        if not ok:
            print('FAIL bowl a=%g g=%g k=%g w=%g: %s' % (a, g, k, w, got))
        failed += not ok
    for _ in range(3):
        p1, p2, w = rng.uniform(0.5, 1.5), rng.uniform(1.6, 3), rng.uniform(0.1, 4)
        d = roots_of(qdot, 'ellipsoidal_bowl.qd', '--driven', "phi' = %r" % w,
                     '--set', 'p1=%r' % p1, '--set', 'p2=%r' % p2)
        P1, P2, W = (sp.Rational(repr(x)) for x in (p1, p2, w))
        poly = s**4 + (P1**2 + P2**2 + 2 * W**2) * s**2 + (P1**2 - W**2) * (P2**2 - W**2)
        failed += not agree(poly, d['eigenvalues'], 'ellipsoid p1=%g p2=%g w=%g' % (p1, p2, w))
        stable = not (min(p1, p2) < w < max(p1, p2))
        if d['stable'] is not stable:
            print('FAIL ellipsoid verdict w=%g: %s' % (w, d['verdict']))
            failed += 1
    for _ in range(3):
        nu, A = rng.uniform(0.5, 4), rng.uniform(0.7, 1.5)
        d = roots_of(qdot, 'sleeping_top.qd', '--ignore', 'psi', '--momentum', 'p_psi=%r' % nu,
                     '--set', 'A=%r' % A)
        NU, AA, mgh = sp.Rational(repr(nu)), sp.Rational(repr(A)), 1  # M g h = 1 in the model
        poly = (AA * s**2 - mgh)**2 + NU**2 * s**2
        failed += not agree(poly, d['eigenvalues'], 'top nu=%g A=%g' % (nu, A))
    print('%d failed' % failed)
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
