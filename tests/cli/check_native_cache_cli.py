#!/usr/bin/env python3
"""`qdot simulate --native` with a cache it must not trust (issue 30).

XDG_CACHE_HOME points at a directory whose qdot/ cache is writable by group
(as a shared directory would be): the run must not load from it, say so in
a note naming the reason, and give the interpreted run's rows (exit 0).
With a private cache the same run is native (no note) and creates the
cache 0700.  The model is the harmonic oscillator x'' = -x from x = 1:
x(t) = cos t at each row.

Usage: check_native_cache_cli.py --build BUILD_DIR
"""
import argparse
import math
import os
import shutil
import stat
import subprocess
import sys
import tempfile
from pathlib import Path

MODEL = "coordinates x\nparameters m = 1, k = 1\nparticle m at (x, 0)\nV = k*x^2/2\n" \
        "initial x = 1, x' = 0\n"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build).resolve() / 'qdot')
    failures, passed = [], 0

    def check(cond, what):
        nonlocal passed
        if cond:
            passed += 1
        else:
            failures.append(what)

    if not shutil.which(os.environ.get('CC', 'cc')):
        print('skipped: no C compiler')
        return 77
    with tempfile.TemporaryDirectory() as d:
        d = Path(d)
        model = d / 'osc.qd'
        model.write_text(MODEL)
        cmd = [qdot, 'simulate', str(model), '--t-end', '3', '--rtol', '1e-12',
               '--native']

        def run(xdg):
            return subprocess.run(cmd, capture_output=True, text=True, timeout=120,
                                  env=dict(os.environ, XDG_CACHE_HOME=str(xdg)))

        def rows_ok(out):
            lines = out.strip().splitlines()[1:]
            return len(lines) > 5 and all(
                abs(float(r.split(',')[1]) - math.cos(float(r.split(',')[0]))) < 1e-9
                for r in lines)

        shared = d / 'shared'
        (shared / 'qdot').mkdir(parents=True)
        os.chmod(shared / 'qdot', 0o775)
        p = run(shared)
        check(p.returncode == 0, 'group-writable cache: exit %d %s' % (p.returncode, p.stderr))
        check('--native unavailable' in p.stderr and 'writable by group or others' in p.stderr,
              'group-writable cache: no note naming the reason: %r' % p.stderr)
        check(rows_ok(p.stdout), 'group-writable cache: rows %r' % p.stdout[:300])
        check(not any((shared / 'qdot').iterdir()),
              'group-writable cache: written to: %s' % list((shared / 'qdot').iterdir()))

        private = d / 'private'
        private.mkdir(mode=0o700)
        p = run(private)
        check(p.returncode == 0 and 'note' not in p.stderr,
              'private cache: exit %d %r' % (p.returncode, p.stderr))
        check(rows_ok(p.stdout), 'private cache: rows %r' % p.stdout[:300])
        mode = stat.S_IMODE(os.stat(private / 'qdot').st_mode) if (private / 'qdot').exists() else None
        check(mode == 0o700, 'private cache: qdot/ created with mode %s' % (oct(mode) if mode else None))
        check(any(f.suffix == '.so' for f in (private / 'qdot').iterdir()),
              'private cache: no object compiled')
    for f in failures:
        print('FAIL', f)
    print('%d passed, %d failed' % (passed, len(failures)))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
