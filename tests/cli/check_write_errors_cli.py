#!/usr/bin/env python3
"""Lost output is a failure (issue 30): every command that prints, with its
standard output on /dev/full (a device whose every write fails with ENOSPC),
exits 1 saying "cannot write standard output: No space left on device"; the
files written by --out, -o and --plot on /dev/full say "cannot write
/dev/full: ..."; a directory given as a file to write or a CSV to read is
refused by name ("is a directory", exit 2); a standard output closed before
qdot runs (>&-) is an error for a command that prints.

    python3 tests/cli/check_write_errors_cli.py --build BUILD_DIR

Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

EX = Path(__file__).resolve().parents[2] / "examples"
results = {"passed": 0, "failed": 0}

OSC = """coordinates x
parameters m = 1, k = 1
T = m*x'^2/2
V = k*x^2/2
initial x = 0, x' = 1
"""

ENOSPC = os.strerror(28)  # "No space left on device"


def check(name, ok, detail=""):
    if ok:
        results["passed"] += 1
    else:
        results["failed"] += 1
        print("FAIL %s %s" % (name, detail))


def commands(osc):
    """One invocation of each command that prints to standard output."""
    dp, sph = EX / "double_pendulum.qd", EX / "spherical_pendulum.qd"
    return [
        ["tour"],
        ["diff", "x^2", "x"],
        ["expand", "(x+1)^2"],
        ["simplify", "sin(x)^2+cos(x)^2"],
        ["print", "x+1"],
        ["eom", osc],
        ["eom", osc, "--format", "json"],
        ["check", osc],
        ["hamiltonian", osc],
        ["bracket", osc, "x", "p_x"],
        ["canonical", osc, "--generator", "F2", "x*P"],
        ["routh", sph, "--ignore", "phi"],
        ["integrals", osc],
        ["simulate", osc, "--t-end", "1"],
        ["simulate", osc, "--t-end", "1", "--format", "json"],
        # more than a stdio buffer: the failure comes during the run
        ["simulate", osc, "--t-end", "100", "--dt", "0.01", "--method", "verlet"],
        ["poincare", dp, "--section", "theta1=0", "--crossings", "3"],
        ["lyapunov", osc, "--t-end", "10"],
        ["codegen", osc, "-o", osc.parent],  # prints "wrote FILE"
        ["equilibria", osc],
        ["linearize", osc],
        ["modes", osc],
        ["stability", sph, "--ignore", "phi", "--at", "theta=1"],
        ["lqr", "--A", "[[0,1],[0,0]]", "--B", "[[0],[1]]", "--weights", "Q=1,R=1"],
        ["orbit", EX / "kepler_polar.qd", "--ignore", "theta"],
        ["hj", osc],
        ["action", osc],
        ["action-of", osc, "--path", "x=sin(t)", "--t", "0:1"],
        ["zvc", dp, "--box", "theta1=-1:1, theta2=-1:1", "--level", "1"],
        ["scatter", EX / "central_areal.qd", "--energy", "1", "--b", "1"],
        ["path", osc, "--from", "x=0, t=0", "--to", "x=1, t=1"],
        ["sweep", osc, "--grid", "m=1:2:2", "--t-end", "1", "--measure", "final"],
        ["sweep", osc, "--grid", "m=1:2:2", "--t-end", "1", "--measure", "final",
         "--format", "json"],
        ["--help"],
        ["--version"],
        ["simulate", "--help"],
    ]


def run(qdot, args, stdout):
    return subprocess.run([str(qdot)] + [str(a) for a in args], stdout=stdout,
                          stderr=subprocess.PIPE, text=True, timeout=300)


def stdout_full(qdot, osc):
    for args in commands(osc):
        name = " ".join(str(a) for a in args[:2])
        ok = run(qdot, args, subprocess.DEVNULL)
        if ok.returncode != 0:
            check("%s: runs (precondition)" % name, False, ok.stderr[-300:])
            continue
        with open("/dev/full", "w") as full:
            r = run(qdot, args, full)
        check("%s > /dev/full: exit 1" % name, r.returncode == 1,
              "exit %d, stderr %r" % (r.returncode, r.stderr[-300:]))
        check("%s > /dev/full: says so" % name,
              "cannot write standard output: " + ENOSPC in r.stderr, repr(r.stderr[-300:]))


def stdout_closed(qdot, osc):
    r = subprocess.run([str(qdot), "eom", str(osc)], stdout=None, stderr=subprocess.PIPE,
                       text=True, timeout=60, pass_fds=(), close_fds=True,
                       preexec_fn=lambda: os.close(1))
    check("eom >&-: exit 1", r.returncode == 1, "exit %d %r" % (r.returncode, r.stderr))
    check("eom >&-: says so", "cannot write standard output" in r.stderr, repr(r.stderr))


def files_full(qdot, osc, tmp):
    dp = EX / "double_pendulum.qd"
    cases = [
        ["simulate", osc, "--t-end", "1", "--out", "/dev/full"],
        ["simulate", osc, "--t-end", "100", "--dt", "0.01", "--method", "verlet",
         "--out", "/dev/full"],
        ["poincare", dp, "--section", "theta1=0", "--crossings", "3", "--out", "/dev/full"],
        ["simulate", dp, "--t-end", "1", "--variational", "columns", "--out", "/dev/full"],
        ["sweep", osc, "--grid", "m=1:2:2", "--t-end", "1", "--measure", "final",
         "-o", "/dev/full"],
        ["animate", EX / "atwood.qd", "-o", "/dev/full"],
    ]
    for args in cases:
        name = " ".join(str(a) for a in args[:1] + args[-2:])
        r = run(qdot, args, subprocess.PIPE)
        check("%s: exit 1" % name, r.returncode == 1, "exit %d %r" % (r.returncode, r.stderr))
        check("%s: says so" % name, "cannot write /dev/full: " + ENOSPC in r.stderr,
              repr(r.stderr))
    # the rows stopped at the first failed write: not a run to the end
    r = run(qdot, cases[1], subprocess.PIPE)
    check("simulate --out /dev/full: no success summary", "energy error" not in r.stderr,
          repr(r.stderr))
    # a plot into a path through /dev/full cannot be made: its extension picks the format,
    # so write it where the disk is full by a symlink to /dev/full
    for ext in ("png", "svg", "pdf"):
        link = tmp / ("plot." + ext)
        if link.exists() or link.is_symlink():
            link.unlink()
        link.symlink_to("/dev/full")
        r = run(qdot, ["simulate", osc, "--t-end", "1", "--plot", link], subprocess.PIPE)
        check("--plot .%s on a full disk: exit 1" % ext, r.returncode == 1,
              "exit %d %r" % (r.returncode, r.stderr))
        check("--plot .%s on a full disk: says so" % ext,
              ("cannot write %s: %s" % (link, ENOSPC)) in r.stderr, repr(r.stderr))


def directories(qdot, osc, tmp):
    d = tmp / "adir"
    d.mkdir(exist_ok=True)
    cases = [
        (["simulate", osc, "--t-end", "1", "--out", d], "cannot write %s: is a directory"),
        (["poincare", EX / "double_pendulum.qd", "--section", "theta1=0", "--crossings", "1",
          "--out", d], "cannot write %s: is a directory"),
        (["sweep", osc, "--grid", "m=1:2:2", "--t-end", "1", "--measure", "final", "-o", d],
         "cannot write %s: is a directory"),
        (["animate", EX / "atwood.qd", "-o", d], "cannot write %s: is a directory"),
        (["sweep", osc, "--list", d, "--t-end", "1", "--measure", "final"],
         "cannot read %s: is a directory"),
    ]
    for args, want in cases:
        name = " ".join(str(a) for a in args[:1] + args[-2:])
        r = run(qdot, args, subprocess.PIPE)
        check("%s: exit 2" % name, r.returncode == 2, "exit %d %r" % (r.returncode, r.stderr))
        check("%s: names the directory" % name, want % d in r.stderr, repr(r.stderr))
    # codegen -o DIR where DIR holds a directory named as the file it writes
    out = tmp / "cg"
    (out / "atwood.c").mkdir(parents=True, exist_ok=True)
    r = run(qdot, ["codegen", EX / "atwood.qd", "-o", out], subprocess.PIPE)
    check("codegen onto a directory: exit 2", r.returncode == 2,
          "exit %d %r" % (r.returncode, r.stderr))
    check("codegen onto a directory: names it",
          "cannot write %s: is a directory" % (out / "atwood.c") in r.stderr, repr(r.stderr))
    # --input F=DIR.csv: a directory whose name ends in .csv
    forced = tmp / "forced.qd"
    forced.write_text("coordinates x\ninputs F\nT = x'^2/2\nV = x^2/2\nQ[x] = F\n"
                      "initial x = 0, x' = 1\n")
    dcsv = tmp / "table.csv"
    dcsv.mkdir(exist_ok=True)
    r = run(qdot, ["simulate", forced, "--t-end", "1", "--input", "F=%s" % dcsv],
            subprocess.PIPE)
    check("--input F=DIR.csv: exit 2", r.returncode == 2, "exit %d %r" % (r.returncode, r.stderr))
    check("--input F=DIR.csv: is a directory",
          ("cannot read %s: is a directory" % dcsv) in r.stderr, repr(r.stderr))


def out_option(qdot, osc, tmp):
    """-o FILE (issue 31: -o and --out everywhere): every command that prints
    writes to FILE exactly what it prints to standard output, and nothing to
    standard output; a full disk is said with FILE's name."""
    for args in commands(osc):
        if args[0].startswith("--") or args[0] == "codegen" or "--help" in args:
            continue  # the program's own help; codegen's -o is a directory
        if "write the rows to FILE" in run(qdot, [args[0], "--help"], subprocess.PIPE).stdout:
            continue  # simulate's rows (files_full); its summary stays on standard output
        name = " ".join(str(a) for a in args[:2])
        plain = run(qdot, args, subprocess.PIPE)
        f = tmp / "out.txt"
        if f.exists():
            f.unlink()
        r = run(qdot, args + ["-o", f], subprocess.PIPE)
        check("%s -o FILE: same exit" % name, r.returncode == plain.returncode,
              "exit %d, plain %d %r" % (r.returncode, plain.returncode, r.stderr[-300:]))
        check("%s -o FILE: nothing on standard output" % name, r.stdout == "", repr(r.stdout[:200]))
        check("%s -o FILE: FILE holds the output" % name,
              f.exists() and f.read_text() == plain.stdout and plain.stdout != "",
              repr((f.read_text() if f.exists() else None, plain.stdout[:200])))
        full = run(qdot, args + ["-o", "/dev/full"], subprocess.PIPE)
        check("%s -o /dev/full: exit 1" % name, full.returncode == 1,
              "exit %d %r" % (full.returncode, full.stderr[-300:]))
        check("%s -o /dev/full: says so" % name,
              "cannot write /dev/full: " + ENOSPC in full.stderr, repr(full.stderr[-300:]))
    # every command's help lists it
    top = run(qdot, ["--help"], subprocess.PIPE).stdout
    names = [ln.split()[0] for ln in top.split("commands:")[1].split("\n\n")[0].splitlines()
             if ln.strip()]
    check("qdot --help lists commands", len(names) > 20, repr(names))
    for c in names:
        h = run(qdot, [c, "--help"], subprocess.PIPE).stdout
        check("%s --help: -o, --out" % c, "-o, --out" in h, repr(h[-300:]))
    # a file that cannot be created is bad input, and no run starts
    r = run(qdot, ["eom", osc, "-o", tmp / "no" / "such" / "dir"], subprocess.PIPE)
    check("eom -o NODIR/FILE: exit 2", r.returncode == 2, "exit %d %r" % (r.returncode, r.stderr))
    # "-" is standard output
    r = run(qdot, ["eom", osc, "-o", "-"], subprocess.PIPE)
    plain = run(qdot, ["eom", osc], subprocess.PIPE)
    check("eom -o -: standard output", r.returncode == 0 and r.stdout == plain.stdout,
          repr(r.stdout[:200]))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    args = ap.parse_args()
    qdot = Path(args.build).resolve() / "qdot"
    if not os.path.exists("/dev/full"):
        print("SKIP: no /dev/full on this system")
        return 77
    with tempfile.TemporaryDirectory(prefix="qdot-write-") as t:
        tmp = Path(t)
        osc = tmp / "osc.qd"
        osc.write_text(OSC)
        stdout_full(qdot, osc)
        stdout_closed(qdot, osc)
        files_full(qdot, osc, tmp)
        directories(qdot, osc, tmp)
        out_option(qdot, osc, tmp)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
