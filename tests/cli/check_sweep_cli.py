#!/usr/bin/env python3
"""End-to-end checks of `qdot sweep` (issue 21).

    python3 tests/cli/check_sweep_cli.py --build BUILD_DIR

Expected values are closed forms or single `qdot simulate` runs, not output
of the code under test:
  - 1 and 2 threads write byte-identical CSVs (random draws of the double
    pendulum's initial angles and g: chaotic, so any difference shows);
  - the double pendulum's flip-time map (Goldstein ch. 1 ex. 22, seed 002;
    examples/double_pendulum.qd): on a 4 x 4 grid of initial angles the
    first time |theta2| reaches pi (--stop-at "theta2^2 = pi^2") equals,
    to round-off, what `qdot simulate --stop-at` finds from the same point;
    points without the energy to flip (V at rest below the flip's) never do;
  - the harmonic oscillator swept over m and k: the `event` measure (x = 0
    going up, from x = 0, x' = 1) is the period 2 pi sqrt(m/k), `final` is
    x = sin(w t)/w, x' = cos(w t), poincare-count the whole periods;
  - --random: the same seed the same runs, another seed others, inside
    the box; --list FILE.csv: the rows in the file's order;
  - the same period with gl4, yoshida4, dopri5, bdf and --native (each
    run's parameters reach every method's programs);
  - lyapunov and lyapunov-spectrum of x'' = a^2 x over a: +a and -a
    within the estimator's error, identical on 1 and 2 threads;
  - a run with a singular mass matrix is recorded in its row, the sweep
    goes on (exit 0);
  - --format json holds the same numbers as the CSV (NaN as null);
  - --map is titled by the model's name, not its path: the same model given
    with its directory and from inside it draws byte-identical PNGs, and
    the same text under another name a different one;
  - bad grids (N = 0, A > B with N > 1, unknown and duplicate names,
    malformed text), unknown measures and missing options exit 2.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import csv
import io
import json
import math
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


def check(name, ok, detail=""):
    if ok:
        results["passed"] += 1
    else:
        results["failed"] += 1
        print("FAIL %s %s" % (name, detail))


def close(name, got, want, tol):
    check(name, abs(got - want) <= tol * max(abs(want), 1e-300),
          "got %.17g want %.17g" % (got, want))


def qdot(build, *args):
    return subprocess.run([str(Path(build).resolve() / "qdot")] + [str(a) for a in args],
                          capture_output=True, text=True, timeout=300)


def sweep(build, *args):
    r = qdot(build, "sweep", *args)
    if r.returncode != 0:
        raise RuntimeError("qdot sweep %s: %s" % (" ".join(map(str, args)), r.stderr))
    return r.stdout


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def threads_identical(build):
    def args(seed):
        return [EX / "double_pendulum.qd", "--random", "theta1=-2:2, theta2=-2:2, g=5:15",
                "--runs", 24, "--seed", seed, "--t-end", 8, "--rtol", 1e-9,
                "--measure", "final, energy_error, max:theta2, min:y2"]
    one = sweep(build, *args(11), "--threads", 1)
    two = sweep(build, *args(11), "--threads", 2)
    check("1 and 2 threads: identical CSV", one == two and len(rows(one)) == 24)
    again = sweep(build, *args(11), "--threads", 2)
    check("same seed: same runs", again == one)
    other = sweep(build, *args(12))
    check("another seed: other runs", rows(other)[0]["theta1"] != rows(one)[0]["theta1"])
    ok = all(-2 <= float(r["theta1"]) < 2 and 5 <= float(r["g"]) < 15 for r in rows(one))
    check("random draws inside the box", ok)


def flip_map(build):
    stop = "theta2^2 = pi^2"
    out = sweep(build, EX / "double_pendulum.qd", "--grid", "theta1=-3:3:4, theta2=-3:3:4",
                "--t-end", 10, "--stop-at", stop, "--measure", "event", "--threads", 2)
    got = rows(out)
    check("flip map: 16 runs", len(got) == 16)
    flips = 0
    for r in got:
        th1, th2 = float(r["theta1"]), float(r["theta2"])
        s = qdot(build, "simulate", EX / "double_pendulum.qd", "--t-end", 10, "--initial",
                 "theta1=%r, theta2=%r" % (th1, th2), "--stop-at", stop)
        lines = [l.split(",") for l in s.stdout.strip().splitlines()]
        header, ev = lines[0], [l for l in lines[1:] if l[-1] != "0"]
        t_sim = float(ev[0][0]) if ev else math.nan
        t_sweep = float(r["event_t"])
        name = "flip time at (%g, %g)" % (th1, th2)
        if math.isnan(t_sim):
            check(name + ": no flip either way", math.isnan(t_sweep), "sweep %r" % t_sweep)
        else:
            flips += 1
            close(name, t_sweep, t_sim, 1e-12)
            close(name + ": |theta2| = pi there", abs(float(r["event_theta2"])), math.pi, 1e-9)
        # theta2 cannot flip without the energy: V(rest) >= V at theta2 = pi
        g = 9.81
        v0 = -2 * g * math.cos(th1) - g * math.cos(th2)
        if v0 < -2 * g + g:
            check(name + ": too little energy to flip", math.isnan(t_sweep))
    check("flip map: some points flip", flips >= 2, "%d" % flips)


def oscillator(build, tmp):
    model = tmp / "osc.qd"
    model.write_text(OSC)
    t_end = 10.3
    out = sweep(build, model, "--grid", "m=0.5:2:3, k=1:4:2", "--t-end", t_end,
                "--event", "x = 0, x' > 0", "--section", "x = 0, x' > 0",
                "--measure", "event, final, poincare-count, max:x, escape:x>0.3")
    got = rows(out)
    check("oscillator: 6 runs", len(got) == 6)
    for r in got:
        m, k = float(r["m"]), float(r["k"])
        w = math.sqrt(k / m)
        close("period at m=%g k=%g" % (m, k), float(r["event_t"]), 2 * math.pi * math.sqrt(m / k),
              1e-9)
        close("final x", float(r["final_x"]), math.sin(w * t_end) / w, 1e-7)
        close("final x'", float(r["final_x'"]), math.cos(w * t_end), 1e-7)
        check("crossings", float(r["poincare-count"]) == math.floor(t_end * w / (2 * math.pi)),
              r["poincare-count"])
        close("max x (at the steps)", float(r["max:x"]), 1 / w, 1e-2)
        # x = sin(w t)/w reaches 0.3 at asin(0.3 w)/w (if 1/w > 0.3)
        want = math.asin(0.3 * w) / w if 0.3 * w < 1 else math.nan
        if math.isnan(want):
            check("never escapes", r["escape:x>0.3"] == "nan")
        else:
            close("escape time", float(r["escape:x>0.3"]), want, 1e-9)
        check("status ok", r["status"] == "ok")
    js = json.loads(sweep(build, model, "--grid", "m=0.5:2:3, k=1:4:2", "--t-end", t_end,
                          "--event", "x = 0, x' > 0", "--section", "x = 0, x' > 0",
                          "--measure", "event, final, poincare-count, max:x, escape:x>0.3",
                          "--format", "json"))
    header = list(got[0].keys())
    check("json: the same columns", js["columns"] + ["status"] == header)
    same = all((v is None and r[c] == "nan") or (v is not None and float(r[c]) == v)
               for row, r in zip(js["rows"], got) for c, v in zip(js["columns"], row))
    check("json: the same numbers (NaN as null)", same and len(js["rows"]) == 6)


def methods(build, tmp):
    """Per-run parameters reach every method's programs and the native
    right-hand side: the period 2 pi/sqrt(k) for k = 1 and 4."""
    model = tmp / "osc.qd"
    for extra, tol in ((["--method", "gl4", "--dt", 0.001], 1e-9),
                       (["--method", "yoshida4", "--dt", 0.001], 1e-9),
                       (["--method", "dopri5"], 1e-9), (["--method", "bdf"], 1e-7),
                       (["--native"], 1e-9)):
        r = qdot(build, "sweep", model, "--grid", "k=1:4:2", "--t-end", 7, "--event",
                 "x = 0, x' > 0", "--measure", "event", *extra)
        if extra == ["--native"] and r.returncode != 0 and "compiler" in r.stderr:
            continue  # no C compiler here: --native is not available
        got = rows(r.stdout)
        check("%s: two runs" % extra[-1], r.returncode == 0 and len(got) == 2, r.stderr)
        for row in got:
            close("%s: period at k=%s" % (" ".join(map(str, extra)), row["k"]),
                  float(row["event_t"]), 2 * math.pi / math.sqrt(float(row["k"])), tol)


def lyapunov(build, tmp):
    """x'' = a^2 x: exponents +a and -a (Benettin's estimate within its error),
    the same rows on 1 and 2 threads."""
    model = tmp / "inverted.qd"
    model.write_text("coordinates x\nparameters a = 1\nT = x'^2/2\nV = -a^2*x^2/2\n"
                     "initial x = 0, x' = 1\n")
    args = [model, "--grid", "a=0.5:2:4", "--t-end", 20, "--measure",
            "lyapunov, lyapunov-spectrum"]
    one = sweep(build, *args, "--threads", 1)
    check("lyapunov: 1 and 2 threads identical", one == sweep(build, *args, "--threads", 2))
    for r in rows(one):
        a, lam, err = float(r["a"]), float(r["lyapunov"]), float(r["lyapunov_error"])
        check("lyapunov = a = %g" % a, abs(lam - a) <= err and err < 0.15 * a,
              "%r +- %r" % (lam, err))
        close("spectrum pairs", float(r["lyapunov_2"]), -float(r["lyapunov_1"]), 1e-9)


def listed(build, tmp):
    model = tmp / "osc.qd"
    lst = tmp / "runs.csv"
    lst.write_text("k, x'\n4, 1\n1, 2\n9, 0.5\n")
    got = rows(sweep(build, model, "--list", lst, "--t-end", 1, "--measure", "final"))
    check("list: the file's order", [(float(r["k"]), float(r["x'"])) for r in got] ==
          [(4, 1), (1, 2), (9, 0.5)])
    for r in got:
        w, v = math.sqrt(float(r["k"])), float(r["x'"])
        close("list: final x", float(r["final_x"]), v * math.sin(w) / w, 1e-8)
    # a NUL byte would end the text early: the runs after it would be lost
    # silently, so the file is refused where the byte is
    lst.write_bytes(b"k, x'\n4, 1\n\x001, 2\n")
    r = qdot(build, "sweep", model, "--list", lst, "--t-end", 1, "--measure", "final")
    check("list with a NUL byte: refused at it", r.returncode == 2 and not r.stdout and
          ":3:1: error: a NUL byte" in r.stderr, r.stderr)


def failure(build, tmp):
    model = tmp / "singular.qd"
    model.write_text("coordinates x\nT = x^2*x'^2/2\nV = x^2/2\ninitial x = 1\n")
    r = qdot(build, "sweep", model, "--grid", "x=-1:1:3", "--t-end", 0.5, "--measure", "final")
    got = rows(r.stdout)
    check("singular run: exit 0", r.returncode == 0, r.stderr)
    check("singular run: recorded in its row",
          len(got) == 3 and got[1]["status"] != "ok" and "singular" in got[1]["status"]
          and got[1]["final_x"] == "nan" and got[0]["status"] == "ok" and got[2]["status"] == "ok",
          r.stdout)
    check("singular run: counted", "1 failed" in r.stderr, r.stderr)
    # every run singular: the rows (with their reasons) and exit 1, said
    r = qdot(build, "sweep", model, "--grid", "x=0:0:1", "--t-end", 0.5, "--measure", "final")
    got = rows(r.stdout)
    check("every run failed: exit 1, said, rows kept",
          r.returncode == 1 and "every run failed (the first: singular" in r.stderr
          and len(got) == 1 and got[0]["status"] != "ok", "exit %d: %s" % (r.returncode, r.stderr))


def errors(build, tmp):
    model = tmp / "osc.qd"
    base = [model, "--t-end", 1, "--measure", "final"]
    cases = [
        ("N = 0", ["--grid", "x=0:1:0"], "at least one point"),
        ("A > B", ["--grid", "x=1:0:3"], "backwards"),
        ("unknown name", ["--grid", "y=0:1:3"], "unknown name 'y'"),
        ("duplicate", ["--grid", "k=0:1:3, k=1:2:2"], "given twice"),
        ("malformed", ["--grid", "x=0:1"], "expected A:B:N"),
        ("not a number", ["--grid", "x=0:z:3"], "not a number"),
        ("random A > B", ["--random", "x=1:0", "--runs", 3], "backwards"),
        ("random without --n", ["--random", "x=0:1"], "--runs"),
        ("two ways", ["--grid", "x=0:1:2", "--random", "x=0:1", "--runs", 2], "only"),
    ]
    for name, extra, words in cases:
        r = qdot(build, "sweep", *base, *extra)
        check("error " + name, r.returncode == 2 and words in r.stderr and not r.stdout,
              "exit %d: %s" % (r.returncode, r.stderr))
    r = qdot(build, "sweep", model, "--grid", "x=0:1:2", "--t-end", 1, "--measure", "final, peak")
    check("error unknown measure", r.returncode == 2 and "unknown measure 'peak'" in r.stderr,
          r.stderr)
    r = qdot(build, "sweep", model, "--grid", "x=0:1:2", "--t-end", 1)
    check("error no --measure", r.returncode == 2 and "--measure" in r.stderr, r.stderr)
    r = qdot(build, "sweep", model, "--grid", "x=0:1:2", "--t-end", 1, "--measure",
             "poincare-count")
    check("error poincare-count without --section", r.returncode == 2 and "section" in r.stderr,
          r.stderr)
    r = qdot(build, "sweep", model, "--grid", "x=0:1:2", "--t-end", 1, "--measure", "event")
    check("error event without --event", r.returncode == 2 and "--event" in r.stderr, r.stderr)


def map_title(build, tmp):
    where = tmp / "maps"
    where.mkdir()
    for name in ("osc.qd", "spring.qd"):
        (where / name).write_text(OSC)
    exe = str(Path(build).resolve() / "qdot")

    def draw(model, png, cwd):
        r = subprocess.run([exe, "sweep", model, "--grid", "m=0.5:2:3, k=1:4:3", "--t-end", "1",
                            "--measure", "final", "--map", png, "--map-measure", "final_x"],
                           capture_output=True, text=True, timeout=300, cwd=str(cwd))
        if r.returncode != 0:
            raise RuntimeError("qdot sweep --map: %s" % r.stderr)
        return Path(cwd, png).read_bytes()

    with_dir = draw(str(where / "osc.qd"), str(tmp / "with_dir.png"), tmp)
    inside = draw("osc.qd", "inside.png", where)
    other = draw("spring.qd", "other.png", where)
    check("map title: the model's name, not its directory", with_dir == inside)
    check("map title: another name, another title", other != inside)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        (tmp / "osc.qd").write_text(OSC)
        for part in (threads_identical, flip_map):
            try:
                part(args.build)
            except Exception as exc:
                check(part.__name__, False, "%s: %s" % (type(exc).__name__, exc))
        for part in (oscillator, methods, lyapunov, listed, failure, errors, map_title):
            try:
                part(args.build, tmp)
            except Exception as exc:
                check(part.__name__, False, "%s: %s" % (type(exc).__name__, exc))
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
