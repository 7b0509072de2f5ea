#!/usr/bin/python3
"""bench/run_startup.py - what a qdot process costs before it does anything
(issue 34: `qdot --version` <= 15M instructions), against a C program built
in the same run that links only the libraries libqdot needs at start-up
(GMP, FLINT with Arb, LAPACK, SUNDIALS' CVODE) and computes nothing: the
floor the dynamic loader sets for any program using them.

Instructions are counted by callgrind (deterministic: the machine's load
does not move them), for the whole process, the dynamic loader included.
Also: the libraries each process maps (ldd), and for the 8-link pendulum
(`qdot eom`, the model of bench/pendulum_qdot --emit, written here the same
way) the share of a whole process's instructions that is start-up.

The 1000x goal for the 8-link pendulum as a whole process (SymPy's
LagrangesMethod: 4.4 s, bench/run_pendulum.py) means 4.4 ms for everything;
the reference's wall time is what no program linking these libraries can go
below.

Usage: run_startup.py BUILD_DIR
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

REF = r"""
#include <arb.h>
#include <cvode/cvode.h>
#include <flint/fmpz.h>
#include <gmp.h>
#include <stdio.h>
void dgesv_(int *, int *, double *, int *, int *, double *, int *, int *);
int main(int argc, char **argv) {
    (void)argv;
    if (argc > 99) { /* never taken: the libraries are mapped and bound, nothing computed */
        mpz_t z; mpz_init(z); fmpz_t f; fmpz_init(f); arb_t a; arb_init(a);
        int n = 1, info; double m = 1, b = 1;
        dgesv_(&n, &n, &m, &n, &n, &b, &n, &info);
        CVodeCreate(CV_ADAMS, NULL);
    }
    puts("reference");
    return 0;
}
"""
GOAL = 15e6


def chain(n):
    """The planar n-link pendulum, named positions and T as a user writes it."""
    lines = ["coordinates " + ", ".join("theta%d" % i for i in range(1, n + 1)),
             "parameters g = 9.81, " + ", ".join("m%d = 1, l%d = 1" % (i, i)
                                                 for i in range(1, n + 1))]
    for i in range(1, n + 1):
        px = "x%d + " % (i - 1) if i > 1 else ""
        py = "y%d " % (i - 1) if i > 1 else ""
        lines.append("x%d = %sl%d*sin(theta%d)" % (i, px, i, i))
        lines.append("y%d = %s- l%d*cos(theta%d)" % (i, py, i, i))
    lines.append("T = " + " + ".join("m%d/2*(x%d'^2 + y%d'^2)" % (i, i, i)
                                      for i in range(1, n + 1)))
    lines.append("V = " + " + ".join("m%d*g*y%d" % (i, i) for i in range(1, n + 1)))
    return "\n".join(lines) + "\n"


def instructions(argv):
    r = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null"]
                       + argv, capture_output=True, text=True)
    m = re.search(r"refs:\s+([\d,]+)", r.stderr)
    if r.returncode != 0 or not m:
        raise SystemExit("callgrind %s failed: %s" % (argv, r.stderr[-500:]))
    return int(m.group(1).replace(",", ""))


def wall(argv, k=21):
    """The median wall time of k runs (seconds): the machine may be shared, so
    these are for the ratio of the three, measured alternately."""
    import time
    ts = []
    for _ in range(k):
        t0 = time.perf_counter()
        subprocess.run(argv, stdout=subprocess.DEVNULL, check=True)
        ts.append(time.perf_counter() - t0)
    return sorted(ts)[k // 2]


def libraries(path):
    out = subprocess.run(["ldd", path], capture_output=True, text=True, check=True).stdout
    return len([ln for ln in out.splitlines() if ln.strip()])


def main():
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    qdot = os.path.join(os.path.abspath(sys.argv[1]), "qdot")
    if not shutil.which("valgrind"):
        print("SKIP: valgrind is not installed (apt-get install valgrind)")
        return 0
    with tempfile.TemporaryDirectory(prefix="qdot-startup-") as d:
        src, ref = os.path.join(d, "ref.c"), os.path.join(d, "ref")
        with open(src, "w") as f:
            f.write(REF)
        subprocess.run(["cc", "-O2", "-I/usr/include/flint", src, "-o", ref,
                        "-Wl,--no-as-needed", "-lflint-arb", "-lflint", "-lsundials_cvode",
                        "-lquadmath", "-lgmp", "-llapack", "-lm"], check=True)
        model = os.path.join(d, "chain8.qd")
        with open(model, "w") as f:
            f.write(chain(8))
        q = instructions([qdot, "--version"])
        r = instructions([ref])
        e = instructions([qdot, "eom", model])
        nq, nr = libraries(qdot), libraries(ref)
        tq, tr, te = wall([qdot, "--version"]), wall([ref]), wall([qdot, "eom", model])
    print("start-up, instructions (callgrind, the whole process):")
    print("  qdot --version          %6.2fM   %d libraries mapped" % (q / 1e6, nq))
    print("  C reference (same libs) %6.2fM   %d libraries mapped" % (r / 1e6, nr))
    print("  ratio qdot / reference  %6.2f" % (q / r))
    print("  wall, median of 21: qdot --version %.2f ms, reference %.2f ms, qdot eom (8 links) "
          "%.2f ms" % (tq * 1e3, tr * 1e3, te * 1e3))
    print("  goal <= %.0fM: %s" % (GOAL / 1e6, "met" if q <= GOAL else "NOT MET"))
    print("qdot eom of the 8-link pendulum, a whole process: %.2fM instructions, "
          "%.0f%% of them the start-up" % (e / 1e6, 100.0 * q / e))
    return 0


if __name__ == "__main__":
    sys.exit(main())
