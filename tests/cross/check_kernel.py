#!/usr/bin/env python3
"""Cross-check qdot's derivatives and expansions against SymPy.

gen_kernel prints random expressions with qdot's partial derivative, total
time derivative and expansion, in SymPy syntax.  For each case SymPy
differentiates and expands the expression itself, and the difference from
qdot's answer must simplify to zero.

Then the constructor's own rules (issue 11): an input such as
sin(e + Rational(17, 6)*pi) or (Rational(9, 1)*(x)**2*(e)**2)**Rational(1, 2)
that SymPy evaluates by its rules (real symbols), beside the node qdot made
of it; the two must be equal.
"""
import argparse
import os
import random
import signal
import subprocess
import sys

import sympy
from sympy import Function, Symbol, diff, expand, simplify, sympify


def namespace(header):
    ns = {name: getattr(sympy, name) for name in dir(sympy) if not name.startswith('_')}
    # Everything is real, as in mechanics: Abs and sign then differentiate
    # as qdot does (d|u| = sign(u) du).
    t = Symbol('t', real=True)
    for kind, names in header:
        for n in names:
            ns[n] = Function(n, real=True) if kind == 'coordinates' else Symbol(n, real=True)
    ns['t'] = t
    return ns, t


def even_form(e):
    """|u| = |-u|: qdot stores abs and sign with the sign of u chosen
    canonically, SymPy keeps u as it came.  Write |u| as sqrt(expand(u^2)) and
    sign(u) as u/|u| so that both meet."""
    e = e.replace(sympy.sign, lambda u: u / sympy.sqrt(expand(u**2)))
    return e.replace(sympy.Abs, lambda u: sympy.sqrt(expand(u**2)))


class Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise Timeout()


def numerically_zero(d, free):
    """d at three random real points, to 30 digits: ~0 everywhere?"""
    rng = random.Random(7)
    for _ in range(3):
        point = {s: sympy.Rational(rng.randint(-900, 900), 1000) for s in sorted(free, key=str)}
        try:
            v = complex(d.subs(point).evalf(30))
        except (TypeError, ValueError, ZeroDivisionError):
            return False
        if abs(v) > 1e-20:
            return False
    return True


def flat_zero(d):
    """d vanishes at random points, derivatives and q(t) made symbols
    (derivatives first, before the functions they differentiate)."""
    derivs = sorted(d.atoms(sympy.Derivative), key=lambda x: -x.derivative_count)
    funcs = list(d.atoms(sympy.core.function.AppliedUndef))
    flat = d.subs([(f, Symbol('_f%d' % i, real=True)) for i, f in enumerate(derivs + funcs)])
    return numerically_zero(flat, flat.free_symbols)


def verdict(d, seconds=10):
    """'proven' when SymPy reduces d to 0, 'numeric' when it could not in
    time (or, seconds=0, without trying simplify) but d vanishes
    numerically, else 'failed'."""
    if d == 0 or expand(d) == 0:
        return 'proven'
    d = even_form(d)
    if expand(d) == 0:
        return 'proven'
    # A cheap look first: a nonzero difference is not worth simplifying.
    if not flat_zero(d):
        return 'failed'
    if seconds == 0:
        return 'numeric'
    signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(seconds)
    try:
        return 'proven' if simplify(d) == 0 else 'numeric'
    except Timeout:
        return 'numeric'
    finally:
        signal.alarm(0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.add_argument('-n', type=int, default=250)
    ap.add_argument('--need', type=int, default=200)
    ap.add_argument('--seed', type=int, default=2026)
    args = ap.parse_args()
    gen = os.path.join(args.build, 'tests', 'gen_kernel')
    out = subprocess.run([gen, str(args.n), str(args.seed)], check=True,
                         capture_output=True, text=True).stdout.splitlines()
    header = [(l.split()[0], l.split()[1:]) for l in out[:2]]
    ns, t = namespace(header)
    q = ns['q']
    cases, proven, failures = 0, 0, []
    ops_equal, ops_diff = 0, []
    i = 2
    rules, rules_proven = 0, 0
    while i < len(out):
        if out[i].startswith('rule '):
            text, value = out[i][5:], out[i + 1].split(' ', 1)[1]
            i += 2
            # 30 digits at three random points are proof enough of a rule
            # (tan(x + pi/2) = -1/tan(x) against SymPy's -cot(x)).
            r = verdict(sympify(eval(value, ns)) - sympify(eval(text, ns)), seconds=0)
            rules += 1
            rules_proven += r == 'proven'
            if r == 'failed':
                failures.append('rule %s\n  qdot   %s' % (text, value))
            continue
        assert out[i].startswith('case '), out[i]
        var = out[i + 1].split()[1]
        fields = dict(l.split(' ', 1) for l in out[i + 2:i + 7])
        i += 7
        e = sympify(eval(fields['expr'], ns))
        # A partial derivative on the jet treats q and q' as independent
        # symbols: replace q' (first) and q by dummies, differentiate, put back.
        Q, QD = Symbol('_q', real=True), Symbol('_qd', real=True)
        flat = e.subs(q(t).diff(t), QD).subs(q(t), Q)
        v = {'q': Q, "q'": QD}.get(var) or ns[var]
        sympy_diff = diff(flat, v).subs(Q, q(t)).subs(QD, q(t).diff(t))
        checks = [('diff', sympy_diff), ('dt', diff(e, t)), ('expand', expand(e))]
        results = []
        for name, ref in checks:
            got = sympify(eval(fields[name], ns))
            r = verdict(got - ref)
            results.append(r)
            if r == 'failed':
                failures.append('%s %s wrt %s\n  expr   %s\n  qdot   %s\n  sympy  %s'
                                % (out[i - 7], name, var, fields['expr'], fields[name], ref))
        proven += all(r == 'proven' for r in results)
        # qd_count_ops counts as SymPy's count_ops does (with q, q' as symbols)
        if int(fields['ops']) == sympy.count_ops(e.subs(q(t).diff(t), QD).subs(q(t), Q)):
            ops_equal += 1
        elif len(ops_diff) < 5:
            ops_diff.append('%s: qdot %s, sympy %s' % (fields['expr'], fields['ops'],
                            sympy.count_ops(e.subs(q(t).diff(t), QD).subs(q(t), Q))))
        cases += 1
    for f in failures[:10]:
        print(f)
    # The issue asks for at least 200 expressions whose derivatives and
    # expansion SymPy proves equal; the rest must at least agree numerically.
    print('count_ops agrees with SymPy on %d of %d expressions' % (ops_equal, cases))
    for d in ops_diff:
        print('  ' + d)
    print('%d of %d expressions proven equal by SymPy (%d needed); the others '
          'agree numerically where SymPy gave up' % (proven, cases, args.need))
    print('%d of %d constructor rules proven equal by SymPy; the others agree numerically'
          % (rules_proven, rules))
    if rules < args.n // 4:
        failures.append('only %d rule cases' % rules)
    if proven < args.need:
        failures.append('only %d expressions proven' % proven)
    # SymPy evaluates some inputs further on reading them (atan2 with a
    # positive x, Abs of a positive sum), so its count can differ; on most
    # expressions the two measures must be the same.
    if ops_equal < 0.7 * cases:
        failures.append('count_ops agrees on only %d of %d' % (ops_equal, cases))
    print('%d passed, %d failed' % (cases * 3 + rules - len(failures), len(failures)))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
