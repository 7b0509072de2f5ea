"""bench/timing.py - the one timer of the bench scripts: a whole command's
median wall time and processor time (user + system of the child)."""
import resource
import statistics
import subprocess
import time


def timed(cmd, reps, quiet=False):
    """Median wall and processor time of cmd over reps runs, its output
    dropped (and its standard error too when quiet)."""
    wall, cpu = [], []
    for _ in range(reps):
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        t0 = time.perf_counter()
        subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL if quiet else None)
        wall.append(time.perf_counter() - t0)
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu.append(r1.ru_utime - r0.ru_utime + r1.ru_stime - r0.ru_stime)
    return statistics.median(wall), statistics.median(cpu)
