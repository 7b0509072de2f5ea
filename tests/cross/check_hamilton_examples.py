#!/usr/bin/python3
"""Hamilton's equations of every example against its Lagrange equations.

For each model in examples/ that `qdot hamiltonian` accepts (unconstrained,
given by T, V, U or L), SymPy takes qdot's Lagrange equations M q'' = f
(`qdot eom --format sympy`; check_examples.py holds those to the books'
formulas) and, at random states and parameter values, to 25 digits:

  - the momenta invert: velocities(q, pdef(q, q')) = q';
  - dq/dt = dH/dp = q' at p = pdef(q, q');
  - dp/dt from Hamilton's equations equals d/dt pdef(q, q') along the
    Lagrangian motion (q'' = M^-1 f): Hamilton's and Lagrange's equations
    are the same motion (Goldstein sec. 8.1, Desloge ch. 71 thm 2);
  - without forces or dissipation dp/dt = -dH/dq, so H itself (not only the
    right-hand sides) is checked.

States where the momenta are not real (a relativistic L, |v| > c) are drawn
again. Models with constraints are skipped (qdot hamiltonian refuses them: exit 2
naming the constraint), and so are models with speeds (their equations are
in speeds, checked by check_speeds_sympy.py) and functionals (`independent`:
integrands not quadratic in the velocities); every other model must pass.

Usage: check_hamilton_examples.py --build BUILD_DIR
"""
import argparse
import random
import re
import subprocess
import sys
from pathlib import Path

from sympy import Float, Matrix, Symbol, diff, sympify

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
DIGITS = 25


# A derivation's time limit, generous: every example now takes well under a
# second (the rigid bodies in Euler angles took 8-55 s before issue 34), and
# a Debug build under AddressSanitizer runs about 10 times slower.
TIMEOUT = 120


def sanitized(build):
    """Is this build instrumented (CMakeCache: QDOT_SANITIZE=ON)?"""
    cache = Path(build) / 'CMakeCache.txt'
    return cache.exists() and 'QDOT_SANITIZE:BOOL=ON' in cache.read_text()


def sympy_output(qdot, cmd, path):
    r = subprocess.run([qdot, cmd, str(path), '--format', 'sympy'], capture_output=True,
                       text=True, timeout=TIMEOUT)
    return r.returncode, r.stdout, r.stderr


def namespace(code):
    ns = {}
    exec(code, ns)  # qdot's own sympy output: plain assignments of SymPy objects
    return ns


def check(qdot, path, rng):
    # a model with speeds has its equations in speeds (qdot eom prints
    # M_u u' = f_u): check_speeds_sympy.py holds those to their books
    if re.search(r'^\s*speeds\s', path.read_text(), re.M):
        return 'skip', 'speeds'
    # a functional's integrand (`independent x`: catenary, brachistochrone,
    # geodesic) is not quadratic in y', which qdot hamiltonian needs;
    # check_examples.py and check_cov_cli.py hold their Euler-Lagrange equations
    if re.search(r'^\s*independent\s', path.read_text(), re.M):
        return 'skip', 'a functional'
    # a field model (`field y(x, t) on ...`) has a density, not coordinates:
    # check_field_cli.py holds its field equation and modes
    if re.search(r'^\s*field\s', path.read_text(), re.M):
        return 'skip', 'a field'
    rc, ham, err = sympy_output(qdot, 'hamiltonian', path)
    if rc != 0:
        if 'constraint' in err:
            return 'skip', 'constrained'
        return 'fail', 'qdot hamiltonian: exit %d: %s' % (rc, err.strip()[:200])
    rc, eom, err = sympy_output(qdot, 'eom', path)
    if rc != 0:
        return 'fail', 'qdot eom: exit %d' % rc
    h, e = namespace(ham), namespace(eom)
    # the header names M, q and f (renamed with '_' when a parameter has the name)
    Mname, qname, fname = re.match(r'# qdot eom .*: (\w+)\*(\w+)\.diff\(t, 2\) = (\w+)',
                                   eom).groups()
    t = h['t']
    qs = list(e[qname])
    n = len(qs)
    funcs = [qq.func for qq in qs]
    qsym = [Symbol('Q%d' % i) for i in range(n)]
    vsym = [Symbol('V%d' % i) for i in range(n)]
    asym = [Symbol('A%d' % i) for i in range(n)]
    tsym = Symbol('T_')

    def plain(x):
        """Functions of t to plain symbols: q'' first, then q', then q."""
        x = sympify(x).subs({f(t).diff(t, 2): a for f, a in zip(funcs, asym)})
        x = x.subs({f(t).diff(t): v for f, v in zip(funcs, vsym)})
        x = x.subs({f(t): s for f, s in zip(funcs, qsym)})
        return x.subs(t, tsym)

    ps = list(h['momenta'])
    pdef = [plain(x) for x in h['pdef']]
    vel = [plain(x) for x in h['velocities']]
    H = plain(h['H'])
    dq = [plain(x) for x in h['dq_dt']]
    dp = [plain(x) for x in h['dp_dt']]
    M = Matrix(e[Mname]).applyfunc(plain)
    f = Matrix(e[fname]).applyfunc(plain)
    # d/dt pdef along the motion, by the chain rule on plain symbols
    dpdef = [sum(diff(x, qsym[k]) * vsym[k] + diff(x, vsym[k]) * asym[k] for k in range(n))
             + diff(x, tsym) for x in pdef]
    syms = set().union(*[x.free_symbols for x in pdef + vel + dq + dp + [H] + list(M) + list(f)])
    params = sorted((s for s in syms if s not in set(qsym + vsym + asym + ps + [tsym])),
                    key=str)
    text = path.read_text()
    forced = any(w in text for w in ('Q[', 'force ', 'dissipation', 'torque '))
    def draw(lo, hi):
        # the double carried exactly at DIGITS digits (a Python float would
        # be a 15-digit Float, and the evaluation only that precise): every
        # formula is then evaluated at the same point to DIGITS digits
        return Float(rng.uniform(lo, hi), DIGITS)

    used = 0
    for _ in range(30):
        if used == 3:
            break
        val = {s: draw(0.5, 1.5) for s in params}
        val.update({s: draw(0.3, 1.2) for s in qsym})
        val.update({s: draw(-1, 1) for s in vsym})
        val[tsym] = draw(0, 2)
        Mn = M.subs(val).evalf(DIGITS)
        fn = f.subs(val).evalf(DIGITS)
        if abs(Mn.det()) < 1e-12:
            continue
        acc = Mn.LUsolve(fn)
        val.update({a: acc[k] for k, a in enumerate(asym)})
        pn = [x.subs(val).evalf(DIGITS) for x in pdef]
        # a relativistic L is real only for |v| < c: draw again outside its domain
        if any(abs(complex(x).imag) > 0 for x in pn + list(acc)):
            continue
        used += 1
        at = dict(val)
        at.update(dict(zip(ps, pn)))

        def num(x):
            return complex(x.subs(at).evalf(DIGITS))

        def close(a, b):
            # the random values are doubles: agreement to 1e-12 leaves room for
            # rounding in different but equal formulas, not for a wrong term
            return abs(a - b) <= 1e-12 * max(1.0, abs(a), abs(b))

        for k in range(n):
            vk = complex(val[vsym[k]])
            if not close(num(vel[k]), vk):
                return 'fail', 'velocities do not invert the momenta (%s)' % qs[k]
            if not close(num(dq[k]), vk):
                return 'fail', 'dq/dt != q\' (%s)' % qs[k]
            if not close(num(diff(H, ps[k])), vk):
                return 'fail', 'dH/dp != q\' (%s)' % qs[k]
            want = complex(dpdef[k].subs(val).evalf(DIGITS))
            if not close(num(dp[k]), want):
                return 'fail', 'dp/dt != d/dt pdef along Lagrange\'s motion (%s): %s vs %s' % (
                    qs[k], num(dp[k]), want)
            if not forced and not close(num(-diff(H, qsym[k])), want):
                return 'fail', '-dH/dq != dp/dt (%s)' % qs[k]
    if not used:
        return 'fail', 'no state in the domain of L in 30 draws'
    return 'ok', '%d coordinates' % n


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    args = ap.parse_args()
    qdot = str(Path(args.build).resolve() / 'qdot')
    global TIMEOUT
    if sanitized(args.build):
        TIMEOUT = 1200
    checked, skipped, failed = 0, 0, []
    for path in sorted(EXAMPLES.glob('*.qd')):
        # a stream of its own per example: adding an example changes no
        # other example's states
        rng = random.Random('20261121:' + path.stem)
        verdict, why = check(qdot, path, rng)
        print('%-32s %s %s' % (path.stem, verdict, why))
        if verdict == 'ok':
            checked += 1
        elif verdict == 'skip':
            skipped += 1
        else:
            failed.append(path.stem)
    print('%d checked, %d skipped (constrained, speeds or functionals), %d failed' % (checked, skipped,
                                                                     len(failed)))
    return 1 if failed or checked < 30 else 0


if __name__ == '__main__':
    sys.exit(main())
