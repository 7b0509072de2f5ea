#!/usr/bin/env python3
"""The progress bar of the long runs (cli/progress.c): `qdot simulate` and
`qdot poincare` draw it on stderr when stderr is a terminal (a pseudo-
terminal here) and the run takes over a second, with the time left, and
erase it at the end; with stderr redirected they print only the summary.

The runs are the chaotic double pendulum (examples/double_pendulum.qd,
Goldstein ch. 1 ex. 22, seed 002) at a tight tolerance, long enough to take
a few seconds; the summary's energy error is checked too (the bar must not
disturb the run).
"""
import argparse
import os
import pty
import re
import select
import subprocess
import sys
from pathlib import Path

EX = Path(__file__).resolve().parents[2] / 'examples'
DP = EX / 'double_pendulum.qd'
START = ['--initial', 'theta1=1.5, theta2=1', '--rtol', '1e-12']
RUNS = {
    'simulate': ['simulate', DP, '--t-end', 5000, *START, '--out', os.devnull],
    'poincare': ['poincare', DP, '--section', "theta1 = 0, theta1' > 0", '--n', 3000, *START,
                 '--out', os.devnull],
}


def on_terminal(cmd):
    """Run with stderr on a pseudo-terminal; return (status, what it showed)."""
    master, slave = pty.openpty()
    p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=slave)
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
        except OSError:  # the child closed the terminal
            break
        if not chunk:
            break
        out += chunk
    os.close(master)
    return p.wait(timeout=300), out.decode(errors='replace')


def redirected(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    return p.returncode, p.stderr


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build).resolve() / 'qdot')
    failures = []

    def check(cond, what):
        if not cond:
            failures.append(what)

    for name, args in RUNS.items():
        cmd = [qdot, *map(str, args)]
        rc, err = redirected(cmd)
        check(rc == 0, f'{name} redirected: {rc} {err}')
        check('\r' not in err and '[#' not in err and 'left' not in err,
              f'{name}: a bar on a redirected stderr: {err[:200]!r}')
        m = re.search(r'energy error ([0-9.e+-]+)', err)
        check(m and float(m.group(1)) < 1e-7, f'{name}: energy error in {err!r}')
        check(err.count('\n') == 1, f'{name}: more than the summary: {err!r}')

        rc, shown = on_terminal(cmd)
        check(rc == 0, f'{name} on a terminal: {rc} {shown[-300:]}')
        bar = re.search(r'\rqdot: ' + name + r' \[#*\s*\]\s+\d+%\s+t = \S+\s+(\d+m)?\d+s left', shown)
        check(bar is not None, f'{name}: no bar with the time left on a terminal: {shown[:300]!r}')
        # erased before the summary: blanks, then a carriage return
        check(re.search(r'\r +\rqdot: ' + name + ': ', shown) is not None,
              f'{name}: the bar is not erased before the summary: {shown[-300:]!r}')

    for f in failures:
        print('FAIL:', f)
    if not failures:
        print('check_progress_cli: ok')
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
