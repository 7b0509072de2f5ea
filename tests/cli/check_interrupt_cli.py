#!/usr/bin/env python3
"""SIGINT during `qdot simulate --out FILE` and `qdot poincare --out FILE`
(issue 30): the run stops after a whole row, says "interrupted at t = T"
on stderr and exits 130 (128 + SIGINT); every line of the file is a whole
row, the last one at t = T.  The signal is sent once the file has rows, so
the check does not depend on the machine's speed (the runs would take
hours).  `qdot animate` stops the same way and still writes its page, of
the motion up to T; its signal is sent once the process catches SIGINT
(/proc/PID/status SigCgt: the run has begun).

    python3 tests/cli/check_interrupt_cli.py --build BUILD_DIR
"""
import argparse
import re
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

EX = Path(__file__).resolve().parents[2] / "examples"
OSC = """coordinates x
parameters m = 1, k = 1
T = m*x'^2/2
V = k*x^2/2
initial x = 0, x' = 1
"""
results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    if ok:
        results["passed"] += 1
    else:
        results["failed"] += 1
        print("FAIL %s %s" % (name, detail))


def run_and_interrupt(name, argv, ready):
    """argv started, SIGINT sent once ready(p) holds; its exit 130 and its
    "interrupted at t = T" checked.  The match of T, or None (and False when
    the run could not be interrupted)."""
    p = subprocess.Popen([str(a) for a in argv], stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and p.poll() is None and not ready(p):
        time.sleep(0.01)
    if p.poll() is not None:
        check("%s: still running when interrupted (precondition)" % name, False, p.stderr.read())
        return False
    p.send_signal(signal.SIGINT)
    try:
        _, err = p.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        p.kill()
        p.communicate()
        check("%s: stops after SIGINT" % name, False)
        return False
    check("%s: exit 130" % name, p.returncode == 130, "exit %d %r" % (p.returncode, err))
    m = re.search(r"interrupted at t = (\S+?)[;, ]", err)
    check("%s: says where it was interrupted" % name, m is not None, repr(err))
    return m


def interrupt(name, argv, out, min_lines):
    m = run_and_interrupt(name, argv, lambda _p: out.exists() and
                          out.read_bytes().count(b"\n") >= min_lines)
    if m is False:
        return
    data = out.read_bytes().decode()
    check("%s: the file ends with a whole line" % name, data.endswith("\n"), repr(data[-80:]))
    lines = data.splitlines()
    header, rows = lines[0].split(","), lines[1:]
    whole = all(len(r.split(",")) == len(header) for r in rows)
    try:
        values = [[float(x) for x in r.split(",")] for r in rows]
    except ValueError:
        values, whole = [], False
    check("%s: every row whole" % name, whole and len(rows) >= 1, repr(data[-200:]))
    if m and values:
        check("%s: the last row is at the time said" % name,
              float(m.group(1)) == values[-1][0], "%s vs %r" % (m.group(1), values[-1][0]))


def catches_sigint(pid):
    try:
        for line in Path("/proc/%d/status" % pid).read_text().splitlines():
            if line.startswith("SigCgt:"):
                return int(line.split()[1], 16) & (1 << (signal.SIGINT - 1)) != 0
    except OSError:
        pass
    return False


def interrupt_animate(qdot, model, page):
    name = "animate -o"
    m = run_and_interrupt(name, [qdot, "animate", model, "--t-end", "1e7", "--rtol", "1e-12",
                                 "-o", page], lambda p: catches_sigint(p.pid))
    if m is False:
        return
    html = page.read_text() if page.exists() else ""
    check("%s: the page is written" % name, "</html>" in html.lower(), repr(html[-80:]))
    if m:
        check("%s: stopped long before the end" % name, 0 < float(m.group(1)) < 1e7, m.group(1))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build).resolve() / "qdot"
    with tempfile.TemporaryDirectory(prefix="qdot-int-") as t:
        tmp = Path(t)
        osc = tmp / "osc.qd"
        osc.write_text(OSC)
        out = tmp / "rows.csv"
        interrupt("simulate --out", [qdot, "simulate", osc, "--t-end", "1e9", "--dt", "0.001",
                                     "--method", "verlet", "--max-steps", "1e15",
                                     "--out", out], out, 2000)
        out2 = tmp / "rows2.csv"
        interrupt("simulate --out (adaptive)", [qdot, "simulate", osc, "--t-end", "1e9",
                                                "--max-steps", "1e15", "--out", out2], out2, 2000)
        sec = tmp / "section.csv"
        interrupt("poincare --out", [qdot, "poincare", EX / "double_pendulum.qd", "--section",
                                     "theta1=0, theta1' > 0", "--crossings", "100000000",
                                     "--t-end", "1e9", "--out", sec], sec, 3)
        drawn = tmp / "drawn.qd"
        drawn.write_text(OSC.replace("T = m*x'^2/2", "particle m at (x, 0)"))
        interrupt_animate(qdot, drawn, tmp / "page.html")
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
