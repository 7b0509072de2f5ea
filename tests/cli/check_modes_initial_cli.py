#!/usr/bin/env python3
"""`qdot modes` with no --about on the ring of N masses (issue 34): the
model's initial state, an equilibrium, is used without a search, and the
note says so; without an initial state the affine equations get one damped
Newton run.  Either way the frequencies are the ring's,
w_j = 2 sqrt(k/m) |sin(pi j/N)| (the cyclic group C_N, Desloge ch. 66,
seed-desloge-B.md ch. 66: K = k (2 I - S - S^T), M = m I), to 1e-10.

The ring is written here for N = 20: masses m on a circle of radius R, the
arc coordinate s_i from the place at angle 2 pi i/N, springs k along the
ring.  No time is measured (bench/run_modes.py has the ring of 100).

`qdot equilibria` on the spring triangle runs the multistart: on a
terminal (a pseudo-terminal, QDOT_PROGRESS_DELAY=0) the bar shows on stderr
and is erased; with stderr redirected nothing but the output.
"""
import argparse
import json
import math
import os
import pty
import select
import subprocess
import sys
import tempfile
from pathlib import Path

N, M, K = 20, 3.0, 2.0
EX = Path(__file__).resolve().parents[2] / 'examples'


def ring(initial):
    s = ['s%d' % i for i in range(1, N + 1)]
    lines = ['coordinates ' + ', '.join(s), 'parameters m = %g, k = %g, R = 1.5' % (M, K)]
    for i, x in enumerate(s):
        lines.append('particle m at R*(cos(2*pi*%d/%d + %s/R), sin(2*pi*%d/%d + %s/R))'
                     % (i, N, x, i, N, x))
    lines.append('V = k/2*(' + ' + '.join('(%s - %s)^2' % (s[(i + 1) % N], s[i])
                                           for i in range(N)) + ')')
    if initial:
        lines.append('initial ' + ', '.join('%s = 0' % x for x in s))
    return '\n'.join(lines) + '\n'


def on_terminal(cmd):
    env = dict(os.environ, QDOT_PROGRESS_DELAY='0')
    master, slave = pty.openpty()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=slave, env=env)
    os.close(slave)
    out = b''
    while True:
        ready, _, _ = select.select([master], [], [], 1)
        if not ready:
            if p.poll() is not None:
                break
            continue
        try:
            chunk = os.read(master, 4096)
        except OSError:
            break
        if not chunk:
            break
        out += chunk
    os.close(master)
    return p.wait(timeout=300), out.decode(errors='replace')


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build).resolve() / 'qdot')
    failures = []

    def check(cond, what):
        if not cond:
            failures.append(what)

    want = sorted(2 * math.sqrt(K / M) * abs(math.sin(math.pi * j / N)) for j in range(N))
    with tempfile.TemporaryDirectory() as d:
        for initial, reason in ((True, "the model's initial state is an equilibrium"),
                                (False, 'the minimum of the potential with the lowest V')):
            path = os.path.join(d, 'ring.qd')
            with open(path, 'w') as f:
                f.write(ring(initial))
            p = subprocess.run([qdot, 'modes', path], capture_output=True, text=True, timeout=300)
            check(p.returncode == 0, 'text: exit %d: %s' % (p.returncode, p.stderr))
            check(reason in p.stderr, 'the note: %r' % p.stderr[-300:])
            p = subprocess.run([qdot, 'modes', path, '--format', 'json'], capture_output=True,
                               text=True, timeout=300)
            check(p.returncode == 0, 'json: exit %d: %s' % (p.returncode, p.stderr))
            if p.returncode:
                continue
            r = json.loads(p.stdout)
            check(r['choice']['reason'].startswith(reason), 'reason %r' % r['choice'])
            check(r['choice'].get('code') == ('initial_state' if initial else 'lowest_minimum'),
                  'code %r' % r['choice'])
            w = sorted(r['frequencies'])
            check(len(w) == N, '%d frequencies' % len(w))
            err = max(abs(a - b) for a, b in zip(w, want))
            check(err <= 1e-10, 'initial=%s: frequencies off by %.3g' % (initial, err))
            check(all(abs(v - r['equilibrium']['s1']) < 1e-9 for v in r['equilibrium'].values()),
                  'not a rotation of the ring: %r' % r['equilibrium'])

    tri = [qdot, 'equilibria', str(EX / 'ring_three_masses.qd')]
    p = subprocess.run(tri, capture_output=True, text=True, timeout=300)
    check(p.returncode == 0 and 'multistart' in p.stdout, 'equilibria: %r' % p.stdout[:200])
    check('\r' not in p.stderr and '[#' not in p.stderr,
          'a bar on a redirected stderr: %r' % p.stderr[:200])
    rc, shown = on_terminal(tri)
    check(rc == 0, 'equilibria on a terminal: exit %d' % rc)
    check('qdot: equilibria [' in shown and 'step = ' in shown and 'left' in shown,
          'no bar on the terminal: %r' % shown[:300])
    check(shown.rstrip(' ').endswith('\r'), 'the bar is not erased: %r' % shown[-120:])

    for f in failures:
        print('FAIL:', f)
    print('check_modes_initial_cli: %d failure(s)' % len(failures))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
