#!/usr/bin/python3
"""qdot sweep in one process and across 2 MPI ranks, timed in the same run
(issue 21: a run is independent of the others, so ranks should scale
near-linearly; docs/design.md, "Running sweeps on a cluster").

The sweep: run_sweep.py's, the double pendulum (examples/double_pendulum.qd)
on a 20 x 20 grid of initial angles in [-2, 2]^2, dop853 at rtol 1e-10 to
--t-end (default 20), measures final and energy_error; one thread per
process, so the ranks are the only parallelism.  Each way runs --repeat
times (default 3), alternating, the best wall time counting (the least
disturbed by other work on the machine); the CSVs are compared byte for
byte.  Also timed: the same sweep of one tiny run alone and under mpirun -np
2, the fixed costs (the model derived and compiled; MPI_Init and the ranks
started), so that what is left of the 2-rank time beyond half the runs' is
the messages and the imbalance at the end.

Usage: run_sweep_mpi.py BUILD_DIR [--t-end T] [--repeat K] [--runs-side N]

Prints the wall times, the ratio t(1)/t(2), the per-run cost, the start-up
cost and what is left for messages and imbalance, with the load average:
on a machine whose other work takes the second core the ratio says so.
Exits 0 (skipping, with the reason) when mpirun or MPI support is missing.
"""
import argparse
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
MODEL = os.path.join(os.path.dirname(HERE), 'examples', 'double_pendulum.qd')
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT='1', OMPI_ALLOW_RUN_AS_ROOT_CONFIRM='1')


def sweep_args(qdot, side, t_end):
    return [qdot, 'sweep', MODEL, '--grid', 'theta1=-2:2:%d, theta2=-2:2:%d' % (side, side),
            '--t-end', str(t_end), '--rtol', '1e-10', '--measure', 'final, energy_error',
            '--threads', '1']


def timed(cmd):
    t0 = time.perf_counter()
    r = subprocess.run(cmd, capture_output=True, text=True, check=True, env=ENV)
    return time.perf_counter() - t0, r.stdout, r.stderr


def mpirun(np):
    return [shutil.which('mpirun'), '--oversubscribe', '-np', str(np)]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('build')
    ap.add_argument('--t-end', type=float, default=20)
    ap.add_argument('--repeat', type=int, default=3)
    ap.add_argument('--runs-side', type=int, default=20)
    a = ap.parse_args()
    qdot = os.path.join(a.build, 'qdot')
    if not shutil.which('mpirun'):
        print('run_sweep_mpi: skipped (no mpirun: apt-get install openmpi-bin)')
        return 0
    _, _, err = timed(mpirun(2) + sweep_args(qdot, 1, 0.1))
    if '2 MPI ranks' not in err:
        print('run_sweep_mpi: skipped (this qdot was built without MPI)')
        return 0
    best = {1: float('inf'), 2: float('inf'), 'start1': float('inf'), 'start2': float('inf')}
    out = {}
    for _ in range(a.repeat):
        t, out[1], _ = timed(sweep_args(qdot, a.runs_side, a.t_end))
        best[1] = min(best[1], t)
        t, out[2], _ = timed(mpirun(2) + sweep_args(qdot, a.runs_side, a.t_end))
        best[2] = min(best[2], t)
        t, _, _ = timed(sweep_args(qdot, 1, 0.1))
        best['start1'] = min(best['start1'], t)
        t, _, _ = timed(mpirun(2) + sweep_args(qdot, 1, 0.1))
        best['start2'] = min(best['start2'], t)
    runs = a.runs_side ** 2
    ratio = best[1] / best[2]
    print('runs %d, t_end %g, cores %d, load average %.2f' %
          (runs, a.t_end, os.cpu_count() or 0, os.getloadavg()[0]))
    work = best[1] - best['start1']
    print('1 process   %.3f s   (%.2f ms a run)' % (best[1], 1e3 * work / runs))
    print('2 MPI ranks %.3f s' % best[2])
    print('ratio %.2f (ideal 2)' % ratio)
    print('start-up: 1 process %.3f s, mpirun -np 2 %.3f s' % (best['start1'], best['start2']))
    print('left for messages and imbalance: %.3f s' % (best[2] - best['start2'] - work / 2))
    print('CSV identical: %s' % ('yes' if out[1] == out[2] else 'NO'))
    return 0 if out[1] == out[2] else 1


if __name__ == '__main__':
    sys.exit(main())
