#!/usr/bin/python3
"""The right-hand-side benchmark: one evaluation of q' , q'' for the double
pendulum and a 20-link pendulum, five C ways and SymPy, in one run.

Usage: run_rhs.py BUILD_DIR [--seconds S] [--no-sympy] [--sympy-limit S]

BUILD_DIR is a build configured with -DQDOT_BENCH=ON (Release) holding
bench/rhs_bench.  The native object is cached in BUILD_DIR/rhs-cache (the
first run compiles it; the compile time is shown).  SymPy (bench/rhs_sympy.py)
gets --sympy-limit seconds (default 60) per n to derive and lambdify; past
that it is reported as not built.  Ratios are against the hand-written
C of the same run.  Goals: native within 1.2x of hand-written; the 20-link
native rhs under 5 us.  Exits 1 when a program fails or results disagree.
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
NS = [2, 20]
METHODS = [('native', 'qdot --native (generated C, dlopen)'),
           ('eom_eval', 'qdot qd_eom_eval (compiled program + solver)'),
           ('prog', 'qdot qd_prog_run on M, f + Cholesky'),
           ('sincos', 'hand-written C, per-angle sin/cos'),
           ('textbook', 'hand-written C, sin/cos of differences'),
           ('sympy', 'SymPy lambdify(cse=True) + numpy.linalg.solve')]


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def parse(text):
    times, info = {}, {}
    for line in text.splitlines():
        f = line.split('\t')
        if f[0] == 'time' and len(f) == 4:
            times[f[1]] = float(f[3])
        elif f[0] == 'info' and len(f) == 3:
            info[f[1]] = f[2]
    return times, info


def fmt(ns):
    if ns is None:
        return '-'
    return '%.0f ns' % ns if ns < 1e4 else '%.1f us' % (ns / 1e3) if ns < 1e7 \
        else '%.1f ms' % (ns / 1e6)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('build')
    ap.add_argument('--seconds', type=float, default=2.0)
    ap.add_argument('--no-sympy', action='store_true')
    ap.add_argument('--sympy-limit', type=float, default=60.0)
    a = ap.parse_args()
    exe = os.path.join(a.build, 'bench', 'rhs_bench')
    cache = os.path.join(a.build, 'rhs-cache')
    times, infos = {}, {}
    for n in NS:
        log('running rhs_bench %d' % n)
        p = subprocess.run([exe, str(n), cache, str(a.seconds)], stdout=subprocess.PIPE, text=True)
        if p.returncode != 0:
            log('rhs_bench %d failed (exit %d)' % (n, p.returncode))
            return 1
        times[n], infos[n] = parse(p.stdout)
        if not a.no_sympy:
            log('running rhs_sympy.py %d (limit %g s)' % (n, a.sympy_limit))
            try:
                p = subprocess.run(['/usr/bin/python3', os.path.join(HERE, 'rhs_sympy.py'), str(n),
                                    str(a.seconds)], stdout=subprocess.PIPE, text=True,
                                   timeout=a.sympy_limit + 10 * a.seconds)
                if p.returncode != 0:
                    log('rhs_sympy %d failed (exit %d)' % (n, p.returncode))
                    return 1
                t, i = parse(p.stdout)
                times[n].update(t)
                infos[n].update(i)
            except subprocess.TimeoutExpired:
                infos[n]['sympy_build_s'] = '> %g (not built)' % a.sympy_limit
    print('\nRight-hand side (q\', q\'\') of the planar n-link pendulum, one call, best of 7 batches')
    print('%-48s %12s %8s %12s %8s' % ('method', 'n = 2', 'x hand', 'n = 20', 'x hand'))
    for key, label in METHODS:
        row = '%-48s' % label
        for n in NS:
            t, h = times[n].get(key), times[n].get('sincos')
            row += ' %12s %8s' % (fmt(t), '%.2f' % (t / h) if t and h else '-')
        print(row)
    print('(x hand: time / the per-angle hand-written C of the same run)')
    for n in NS:
        i = infos[n]
        print('n = %d: derive %s s, codegen %s s (%s bytes of C), native load %s s%s, '
              'qd_prog %s instructions, SymPy build %s s, max rel. difference %s'
              % (n, i.get('derive_s'), i.get('codegen_s'), i.get('codegen_bytes'),
                 i.get('native_load_s'), ' (cached)' if i.get('native_cached') == '1' else
                 ' (compiled)', i.get('prog_instructions'), i.get('sympy_build_s', '-'),
                 i.get('max_rel_diff')))
    r = times[20]['native'] / times[20]['sincos']
    r2 = times[2]['native'] / times[2]['sincos']
    print('goal native <= 1.2x hand-written: n = 2 %.2fx, n = 20 %.2fx: %s'
          % (r2, r, 'met' if max(r, r2) <= 1.2 else 'NOT met'))
    print('goal 20-link native rhs < 5 us: %s: %s'
          % (fmt(times[20]['native']), 'met' if times[20]['native'] < 5000 else 'NOT met'))
    return 0


if __name__ == '__main__':
    sys.exit(main())
