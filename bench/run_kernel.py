#!/usr/bin/python3
"""Run the kernel benchmark: qdot, GiNaC and SymPy in one run, one table.

Usage: run_kernel.py BUILD_DIR [--quick] [--no-sympy] [--rounds N] [NAME...]

BUILD_DIR is a build configured with -DQDOT_BENCH=ON (Release), holding
bench/kernel_qdot and bench/kernel_ginac.  The programs run one after the
other (never at once, so they do not compete for the processor): qdot and
GiNaC alternately for a few rounds, keeping each one's best median, then
SymPy once.  Each prints tab-separated lines: name reps median_s min_s size value.  This script
joins them, prints the table and checks that the three agree: the value of
the result at the same point must match to 1e-9 relative.  It exits 1 when
they disagree or a program fails; missing the speed goal is reported, not
an error.
"""
import argparse
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON = "/usr/bin/python3"

DESCR = {
    "expand1": "expand (1+x+y+z)^20",
    "expand2": "e=expand((x+y+z+w)^15); expand(e*de/dx)",
    "diff10": "d^10/dx^10 sin(x)^4 cos(x) exp(x)",
    "trig200": "s=sum k sin(kx)cos(ky), k<=200; ds/dx, ds/dy",
}
SYSTEMS = ("qdot", "ginac", "sympy")
RTOL = 1e-9


def parse(text):
    rows = {}
    for line in text.splitlines():
        f = line.split("\t")
        if len(f) != 6:
            continue
        rows[f[0]] = {"reps": int(f[1]), "med": float(f[2]), "min": float(f[3]),
                      "size": int(f[4]), "value": float(f[5])}
    return rows


def run(label, cmd):
    print(f"running {label}: {' '.join(cmd)}", file=sys.stderr, flush=True)
    if not os.path.exists(cmd[0]):
        print(f"{label}: {cmd[0]} is missing (configure with -DQDOT_BENCH=ON and build)",
              file=sys.stderr)
        return {}, False
    p = subprocess.run(cmd, stdout=subprocess.PIPE, text=True)
    if p.returncode != 0:
        print(f"{label} failed (exit {p.returncode})", file=sys.stderr)
    return parse(p.stdout), p.returncode == 0


def merge(best, rows):
    """Per benchmark the row with the smallest median, repetitions summed."""
    out = dict(best)
    for n, r in rows.items():
        old = best.get(n)
        if old is None or r["med"] < old["med"]:
            out[n] = dict(r)
        if old is not None:
            out[n]["reps"] = old["reps"] + r["reps"]
    return out


def commands(a):
    bench = os.path.join(a.build, "bench")
    c_opts = ["--budget", "0.3", "--min-reps", "3"] if a.quick else ["--budget", "1", "--min-reps", "5"]
    py_opts = ["--budget", "1", "--min-reps", "1", "--slow", "2"] if a.quick \
        else ["--budget", "5", "--min-reps", "3", "--slow", "10"]
    cmds = {
        "qdot": [os.path.join(bench, "kernel_qdot")] + c_opts + a.names,
        "ginac": [os.path.join(bench, "kernel_ginac")] + c_opts + a.names,
        "sympy": [PYTHON, os.path.join(HERE, "kernel_sympy.py")] + py_opts + a.names,
    }
    if a.no_sympy:
        del cmds["sympy"]
    return cmds


def fmt_time(s):
    if s is None:
        return "-"
    if s >= 1:
        return f"{s:.2f} s"
    if s >= 1e-3:
        return f"{s * 1e3:.2f} ms"
    return f"{s * 1e6:.1f} us"


def ratio(num, den):
    if num is None or den is None or den["med"] <= 0:
        return None
    return num["med"] / den["med"]


def agree(vals):
    vals = [v for v in vals if v is not None]
    if len(vals) < 2:
        return True
    ref = vals[0]
    return all(abs(v - ref) <= RTOL * max(1.0, abs(ref)) for v in vals)


def table(names, res):
    hdr = ("benchmark", "qdot", "GiNaC", "SymPy", "SymPy/qdot", "GiNaC/qdot",
           "terms q/G/S", "goal")
    rows = []
    for n in names:
        r = {s: res.get(s, {}).get(n) for s in SYSTEMS}
        rs, rg = ratio(r["sympy"], r["qdot"]), ratio(r["ginac"], r["qdot"])
        goal = "-"
        if rs is not None and rg is not None:
            goal = "met" if rs >= 100 and rg >= 1 else "MISSED"
        rows.append((n, fmt_time(r["qdot"] and r["qdot"]["med"]),
                     fmt_time(r["ginac"] and r["ginac"]["med"]),
                     fmt_time(r["sympy"] and r["sympy"]["med"]),
                     "-" if rs is None else f"{rs:.0f}x",
                     "-" if rg is None else f"{rg:.2f}x",
                     "/".join(str(r[s]["size"]) if r[s] else "-" for s in SYSTEMS), goal))
    w = [max(len(str(x[i])) for x in rows + [hdr]) for i in range(len(hdr))]
    line = lambda x: "  ".join(str(c).rjust(w[i]) if i else str(c).ljust(w[i])
                               for i, c in enumerate(x))
    print(line(hdr))
    print("  ".join("-" * k for k in w))
    for x in rows:
        print(line(x))


def checks(names, res):
    """The value of each result at x,y,z,w = 1/8,1/4,3/8,1/2 in every system."""
    ok = True
    print("\nvalue at x,y,z,w = 1/8,1/4,3/8,1/2 (repetitions in brackets):")
    for n in names:
        r = {s: res.get(s, {}).get(n) for s in SYSTEMS}
        vals = [r[s]["value"] if r[s] else None for s in SYSTEMS]
        same = agree(vals)
        ok = ok and same
        verdict = "agree" if same else "DISAGREE"
        if sum(v is not None for v in vals) < 2:
            verdict = "-"
        cells = "  ".join(f"{s} {r[s]['value']:.15g} [{r[s]['reps']}]" if r[s] else f"{s} -"
                          for s in SYSTEMS)
        print(f"  {n:8} {cells}  {verdict}")
    return ok


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build", help="build directory configured with -DQDOT_BENCH=ON")
    ap.add_argument("names", nargs="*", help="benchmarks to run (default: all)")
    ap.add_argument("--quick", action="store_true", help="fewer repetitions, one round")
    ap.add_argument("--rounds", type=int, default=None,
                    help="rounds of qdot and GiNaC, best median kept (default 3)")
    ap.add_argument("--no-sympy", action="store_true", help="skip SymPy (its expand2 takes ~1 min)")
    a = ap.parse_intermixed_args()
    unknown = [n for n in a.names if n not in DESCR]
    if unknown:
        ap.error(f"unknown benchmark {unknown[0]}; known: {' '.join(DESCR)}")
    names = a.names or list(DESCR)
    if a.rounds is None:
        a.rounds = 1 if a.quick else 3
    res, ok = {}, True
    cmds = commands(a)
    # qdot and GiNaC alternate for a few rounds and keep their best median:
    # on a shared machine one unlucky round could otherwise flip a close race.
    for rnd in range(a.rounds):
        for label in ("qdot", "ginac"):
            rows, good = run(label, cmds[label])
            ok = ok and good
            res[label] = merge(res.get(label, {}), rows)
    if "sympy" in cmds:
        res["sympy"], good = run("sympy", cmds["sympy"])
        ok = ok and good
    print()
    for n in names:
        print(f"  {n:8} {DESCR[n]}")
    print(f"\nmedian processor time per repetition, fresh context each time\n(qdot and GiNaC: best median of {a.rounds} alternating rounds):\n")
    table(names, res)
    ok = checks(names, res) and ok
    if not ok:
        print("\nFAILED: a program failed or the systems disagree", file=sys.stderr)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
