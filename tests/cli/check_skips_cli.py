#!/usr/bin/env python3
"""A check that skips must never turn a failure into a pass (issue 30).

The CLI checks that can skip (check_friction_cli, check_sweep_mpi_cli,
check_codegen_cli, check_progress_cli) are run against a fake build whose
`qdot` fails every command (exit 1, a message on stderr, nothing on stdout)
and whose tests/sweep_test_sweep_hdf5 fails too.  Each must then fail: exit
1 (or any status but 0 and 77, the status ctest reports as skipped).  With
MPI and HDF5 said to be built, the MPI check has nothing to skip; said to
be missing, it skips them but still fails on the parts it runs.

Usage: check_skips_cli.py --build BUILD_DIR (the real build is not used).
"""
import argparse
import os
import stat
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
FAILING = "#!/bin/sh\necho 'qdot: error: this qdot fails every command' >&2\nexit 1\n"
CHECKS = {
    'check_friction_cli.py': {},
    'check_codegen_cli.py': {},
    'check_progress_cli.py': {},
    'check_sweep_mpi_cli.py': {'QDOT_WITH_MPI': '1', 'QDOT_WITH_HDF5': '1',
                               'QDOT_MPIEXEC': '/bin/false'},
    'check_sweep_mpi_cli.py (without MPI, HDF5)': {'QDOT_WITH_MPI': '0', 'QDOT_WITH_HDF5': '0'},
}


def fake_build(root):
    for rel in ('qdot', 'tests/sweep_test_sweep_hdf5'):
        p = root / rel
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(FAILING)
        p.chmod(p.stat().st_mode | stat.S_IXUSR)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.parse_args()
    failures, passed = [], 0
    with tempfile.TemporaryDirectory() as d:
        root = Path(d)
        fake_build(root)
        for name, env in CHECKS.items():
            script = HERE / name.split(' ')[0]
            p = subprocess.run([sys.executable, str(script), '--build', str(root)],
                               capture_output=True, text=True, timeout=600,
                               env=dict(os.environ, **env))
            if p.returncode in (0, 77):
                failures.append('%s passed (exit %d) against a qdot that fails every command:\n%s'
                                % (name, p.returncode, (p.stdout + p.stderr)[-600:]))
            else:
                passed += 1
    for f in failures:
        print('FAIL', f)
    print('%d passed, %d failed' % (passed, len(failures)))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
