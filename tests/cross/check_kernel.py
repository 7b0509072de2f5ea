#!/usr/bin/env python3
"""Cross-check qdot's derivatives and expansions against SymPy.

gen_kernel prints random expressions with qdot's partial derivative, total
time derivative and expansion, in SymPy syntax.  For each case SymPy
differentiates and expands the expression itself, and the difference from
qdot's answer must simplify to zero.
"""
import argparse
import os
import subprocess
import sys

import sympy
from sympy import Function, Symbol, diff, expand, simplify


def namespace(header):
    ns = {name: getattr(sympy, name) for name in dir(sympy) if not name.startswith('_')}
    t = Symbol('t')
    for kind, names in header:
        for n in names:
            ns[n] = Function(n) if kind == 'coordinates' else Symbol(n)
    ns['t'] = t
    return ns, t


def is_zero(d):
    if d == 0 or expand(d) == 0:
        return True
    return simplify(d) == 0


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.add_argument('-n', type=int, default=250)
    ap.add_argument('--seed', type=int, default=2026)
    args = ap.parse_args()
    gen = os.path.join(args.build, 'tests', 'gen_kernel')
    out = subprocess.run([gen, str(args.n), str(args.seed)], check=True,
                         capture_output=True, text=True).stdout.splitlines()
    header = [(l.split()[0], l.split()[1:]) for l in out[:2]]
    ns, t = namespace(header)
    q = ns['q']
    cases, failures = 0, []
    i = 2
    while i < len(out):
        assert out[i].startswith('case '), out[i]
        var = out[i + 1].split()[1]
        fields = dict(l.split(' ', 1) for l in out[i + 2:i + 6])
        i += 6
        e = eval(fields['expr'], ns)
        # A partial derivative on the jet treats q and q' as independent
        # symbols: replace q' (first) and q by dummies, differentiate, put back.
        Q, QD = Symbol('_q'), Symbol('_qd')
        flat = e.subs(q(t).diff(t), QD).subs(q(t), Q)
        v = {'q': Q, "q'": QD}.get(var) or ns[var]
        sympy_diff = diff(flat, v).subs(Q, q(t)).subs(QD, q(t).diff(t))
        checks = [('diff', sympy_diff), ('dt', diff(e, t)), ('expand', expand(e))]
        for name, ref in checks:
            got = eval(fields[name], ns)
            if not is_zero(got - ref):
                failures.append('case %s %s wrt %s\n  expr   %s\n  qdot   %s\n  sympy  %s'
                                % (out[i - 6], name, var, fields['expr'], fields[name], ref))
        cases += 1
    for f in failures[:10]:
        print(f)
    print('%d passed, %d failed' % (cases * 3 - len(failures), len(failures)))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
