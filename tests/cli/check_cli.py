#!/usr/bin/env python3
"""Tests of `qdot eom` and `qdot check`, run against the built program.

    python3 tests/cli/check_cli.py --build BUILD_DIR

Every check compares with mathematics computed here, never with output the
program produced before: the double pendulum's accelerations with the
textbook closed form, parameter overrides with the same formula at the new
values, the printed expressions (text, SymPy, C) by evaluating them.

Double pendulum (point masses m1, m2 on massless rods l1, l2, angles from
the downward vertical): Landau & Lifshitz, Mechanics, sec. 5, problem 1 gives
the Lagrangian
    L = (m1+m2)/2 l1^2 th1'^2 + m2/2 l2^2 th2'^2
        + m2 l1 l2 th1' th2' cos(th1 - th2) + (m1+m2) g l1 cos th1 + m2 g l2 cos th2,
and solving its two Lagrange equations for the accelerations gives the form
quoted by E. Neumann, myPhysicsLab "Double Pendulum" (with D = 2 m1 + m2 -
m2 cos(2 th1 - 2 th2)):
    th1'' = (-g (2 m1 + m2) sin th1 - m2 g sin(th1 - 2 th2)
             - 2 sin(th1 - th2) m2 (th2'^2 l2 + th1'^2 l1 cos(th1 - th2))) / (l1 D)
    th2'' = 2 sin(th1 - th2) (th1'^2 l1 (m1 + m2) + g (m1 + m2) cos th1
             + th2'^2 l2 m2 cos(th1 - th2)) / (l2 D)
The script prints "N passed, N failed" and exits 1 when a check failed.
"""
import argparse
import json
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import sympy as sp

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

DOUBLE_PENDULUM = """\
# Double pendulum
coordinates theta1, theta2
parameters m1 = 1, m2 = 1, l1 = 1, l2 = 1, g = 9.81

x1 = l1*sin(theta1)
y1 = -l1*cos(theta1)
x2 = x1 + l2*sin(theta2)
y2 = y1 - l2*cos(theta2)

T = m1/2*(x1'^2 + y1'^2) + m2/2*(x2'^2 + y2'^2)
V = m1*g*y1 + m2*g*y2

initial theta1 = 0.5, theta2 = 0, theta1' = 0, theta2' = 0
"""

# Kepler problem in polar coordinates: phi is cyclic, p_phi = m r^2 phi'
# (Goldstein ch. 3; Desloge ch. 58).
CENTRAL_FORCE = """\
coordinates r, phi
parameters m = 1, k = 2
T = m/2*(r'^2 + r^2*phi'^2)
V = -k/r
"""

# Bead on a straight wire turning uniformly in a horizontal plane: T2 = m r'^2/2,
# T1 = 0, T0 = m omega^2 r^2/2, and r'' = omega^2 r.
ROTATING_WIRE = """\
coordinates r
parameters m = 1, omega = 2
x = r*cos(omega*t)
y = r*sin(omega*t)
T = m/2*(x'^2 + y'^2)
V = 0
"""

# Free particle in spherical coordinates: M = diag(m, m r^2, m r^2 sin^2 theta),
# singular on the polar axis.
SPHERICAL = """\
coordinates r, theta, phi
parameters m = 1
T = m/2*(r'^2 + r^2*theta'^2 + r^2*sin(theta)^2*phi'^2)
"""

BAD_MODEL = """\
coordinates x
parameters m = 1
T = m/2*y'^2
"""

# Parameters named like the outputs: x'' = -f/M.
CLASH = """\
coordinates x
parameters M = 2, f = 3
T = M/2*x'^2
V = f*x
"""

PARAMS = {"m1": 1.0, "m2": 1.0, "l1": 1.0, "l2": 1.0, "g": 9.81}


def closed_form(s, p):
    """(M, f, qdd) of the double pendulum at state s with parameters p."""
    t1, t2, w1, w2 = s["theta1"], s["theta2"], s["theta1'"], s["theta2'"]
    m1, m2, l1, l2, g = p["m1"], p["m2"], p["l1"], p["l2"], p["g"]
    d = t1 - t2
    den = 2 * m1 + m2 - m2 * math.cos(2 * t1 - 2 * t2)
    a1 = (-g * (2 * m1 + m2) * math.sin(t1) - m2 * g * math.sin(t1 - 2 * t2)
          - 2 * math.sin(d) * m2 * (w2 ** 2 * l2 + w1 ** 2 * l1 * math.cos(d))) / (l1 * den)
    a2 = (2 * math.sin(d) * (w1 ** 2 * l1 * (m1 + m2) + g * (m1 + m2) * math.cos(t1)
                             + w2 ** 2 * l2 * m2 * math.cos(d))) / (l2 * den)
    M = [[(m1 + m2) * l1 ** 2, m2 * l1 * l2 * math.cos(d)],
         [m2 * l1 * l2 * math.cos(d), m2 * l2 ** 2]]
    f = [-m2 * l1 * l2 * w2 ** 2 * math.sin(d) - (m1 + m2) * g * l1 * math.sin(t1),
         m2 * l1 * l2 * w1 ** 2 * math.sin(d) - m2 * g * l2 * math.sin(t2)]
    return M, f, [a1, a2]


def close(a, b, tol=1e-9):
    return abs(a - b) <= tol * max(1.0, abs(a), abs(b))


def all_close(xs, ys, tol=1e-9):
    return len(xs) == len(ys) and all(close(a, b, tol) for a, b in zip(xs, ys))


def random_state(rng):
    return {"theta1": rng.uniform(-3, 3), "theta2": rng.uniform(-3, 3),
            "theta1'": rng.uniform(-2, 2), "theta2'": rng.uniform(-2, 2)}


def at_arg(s):
    return ", ".join("%s=%r" % (k, v) for k, v in s.items())


class Runner:
    def __init__(self, qdot, tmp):
        self.qdot, self.tmp = qdot, tmp
        self.passed = self.failed = 0

    def model(self, name, text):
        path = os.path.join(self.tmp, name)
        with open(path, "w") as fp:
            fp.write(text)
        return path

    def run(self, *args):
        return subprocess.run([self.qdot] + list(args), capture_output=True, text=True,
                              timeout=60)

    def check(self, name, ok, detail=""):
        if ok:
            self.passed += 1
        else:
            self.failed += 1
            print("FAIL %s%s" % (name, ": " + detail if detail else ""))
        return ok


# ---- usage and model errors ------------------------------------------------------

def test_usage(r, dp):
    cases = [("eom",), ("eom", dp, "--format", "xml"), ("eom", dp, "--frobnicate"),
             ("eom", dp, dp), ("eom", dp, "--set"), ("eom", dp, "--set", "m1"),
             ("check",), ("check", dp, dp), ("eom", os.path.join(r.tmp, "missing.qd"))]
    for args in cases:
        p = r.run(*args)
        r.check("usage %s" % " ".join(args[:1] + args[2:]),
                p.returncode == 2 and "error" in p.stderr and p.stdout == "",
                "rc=%d stderr=%r" % (p.returncode, p.stderr))


def caret_line(lines, i):
    return i + 1 < len(lines) and re.fullmatch(r"\s*\^~*", lines[i + 1].rstrip()) is not None


def test_bad_model(r):
    path = r.model("bad.qd", BAD_MODEL)
    line = 3
    col = BAD_MODEL.splitlines()[2].index("y") + 1
    for cmd in ("eom", "check"):
        p = r.run(cmd, path)
        lines = p.stderr.splitlines()
        head = "%s:%d:%d: error:" % (path, line, col)
        ok = p.returncode == 2 and p.stdout == "" and len(lines) >= 3 and \
            lines[0].startswith(head) and caret_line(lines, 1)
        r.check("bad model (%s)" % cmd, ok, "rc=%d stderr=%r" % (p.returncode, p.stderr))
        # the caret stands under the unknown name
        if ok:
            src, caret = lines[1], lines[2]
            r.check("caret position (%s)" % cmd,
                    src.index("T = ") + col - 1 == caret.index("^"), p.stderr)


def test_singular(r):
    path = r.model("spherical.qd", SPHERICAL)
    p = r.run("eom", path, "--at", "r=1, theta=0")
    r.check("singular at the polar axis exits 1",
            p.returncode == 1 and "singular" in p.stderr and p.stdout == "",
            "rc=%d %r" % (p.returncode, p.stderr))
    p = r.run("eom", path, "--at", "r=2, theta=0.5, phi'=0.3", "--format", "json")
    ok = p.returncode == 0
    if ok:
        d = json.loads(p.stdout)
        # theta'' = sin(theta) cos(theta) phi'^2 (free particle, Lagrange's equation for theta)
        ok = close(d["accelerations"][1], math.sin(0.5) * math.cos(0.5) * 0.09)
    r.check("spherical theta''", ok, p.stdout + p.stderr)


# ---- numbers: --at and --set ---------------------------------------------------------

def eom_json(r, path, *args):
    p = r.run("eom", path, "--format", "json", *args)
    if p.returncode != 0:
        return None, p.stderr
    try:
        return json.loads(p.stdout), ""
    except ValueError as e:
        return None, "not JSON: %s\n%s" % (e, p.stdout)


def solve2(M, f):
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    return [(M[1][1] * f[0] - M[0][1] * f[1]) / det, (M[0][0] * f[1] - M[1][0] * f[0]) / det]


def test_at(r, dp, rng):
    for i in range(5):
        s = random_state(rng)
        # the two textbook forms agree: the quoted accelerations solve M q'' = f
        M, f, a = closed_form(s, PARAMS)
        r.check("closed form is consistent (%d)" % i, all_close(solve2(M, f), a))
        d, err = eom_json(r, dp, "--at", at_arg(s))
        if not r.check("--at runs (%d)" % i, d is not None, err):
            continue
        M, f, a = closed_form(s, PARAMS)
        r.check("--at accelerations (%d)" % i, all_close(d["accelerations"], a),
                "%r vs %r at %r" % (d["accelerations"], a, s))
        r.check("--at mass matrix (%d)" % i,
                all_close(sum(d["mass_matrix"], []), sum(M, [])), repr(d["mass_matrix"]))
        r.check("--at forcing (%d)" % i, all_close(d["forcing"], f), repr(d["forcing"]))
    # not named: 0; values may be expressions
    d, err = eom_json(r, dp, "--at", "theta1=pi/4, theta2'=-1e-3")
    s = {"theta1": math.pi / 4, "theta2": 0.0, "theta1'": 0.0, "theta2'": -1e-3}
    r.check("--at with expressions and defaults",
            d is not None and all_close(d["accelerations"], closed_form(s, PARAMS)[2]), err)


def test_set(r, dp, rng):
    for i in range(3):
        p = {"m1": rng.uniform(0.5, 3), "m2": rng.uniform(0.5, 3), "l1": rng.uniform(0.5, 2),
             "l2": rng.uniform(0.5, 2), "g": rng.uniform(1, 20)}
        s = random_state(rng)
        sets = sum((["--set", "%s=%r" % kv] for kv in p.items()), [])
        d, err = eom_json(r, dp, "--at", at_arg(s), *sets)
        ok = d is not None and all_close(d["accelerations"], closed_form(s, p)[2])
        r.check("--set all parameters (%d)" % i, ok, err or repr(d))
        if d:
            r.check("--set shows the values (%d)" % i,
                    all(close(d["parameters"][k], v) for k, v in p.items()), repr(d))
    s = random_state(rng)
    d, err = eom_json(r, dp, "--at", at_arg(s), "--set", "m2=3", "--set", "l1=1/2")
    p = dict(PARAMS, m2=3.0, l1=0.5)
    r.check("--set m2=3 l1=1/2", d is not None and all_close(d["accelerations"],
                                                             closed_form(s, p)[2]), err)
    # symbolic: the set parameter is gone from the equations
    d, err = eom_json(r, dp, "--set", "m2=3")
    ok = d is not None and not any(re.search(r"\bm2\b", e) for e in
                                   sum(d["mass_matrix"], []) + d["forcing"])
    r.check("--set substitutes into the equations", ok, err or repr(d))
    p = r.run("eom", dp, "--set", "m3=2")
    r.check("--set unknown name", p.returncode == 2 and "m1" in p.stderr, p.stderr)
    p = r.run("eom", dp, "--set", "m1=g")
    r.check("--set value must be a number", p.returncode == 2, p.stderr)


def test_at_errors(r, dp):
    p = r.run("eom", dp, "--at", "theta3=1")
    r.check("--at unknown name", p.returncode == 2 and "theta1" in p.stderr and
            "theta2" in p.stderr and p.stdout == "", p.stderr)
    for bad in ("theta1=(1", "theta1", "theta1=x", "theta1''=1", "theta1=1, theta1=2",
                "theta1=1/0"):
        p = r.run("eom", dp, "--at", bad)
        r.check("--at %r" % bad, p.returncode == 2 and p.stdout == "", p.stderr)


# ---- symbolic output, evaluated here ----------------------------------------------

def text_to_python(e):
    """An expression in qdot's text syntax as Python over math."""
    e = re.sub(r"([A-Za-z_]\w*)''", r"\1_dd", e)
    e = re.sub(r"([A-Za-z_]\w*)'", r"\1_d", e)
    return e.replace("^", "**")


def eval_text(e, s, p):
    env = {k: getattr(math, k) for k in ("sin", "cos", "tan", "sqrt", "exp", "log", "pi")}
    env.update(p)
    env.update({k.replace("'", "_d"): v for k, v in s.items()})
    env["t"] = 0.0
    return eval(text_to_python(e), {"__builtins__": {}}, env)


def test_json_symbolic(r, dp, rng):
    d, err = eom_json(r, dp, "--solve")
    if not r.check("json --solve", d is not None, err):
        return
    for key in ("coordinates", "parameters", "mass_matrix", "forcing", "accelerations",
                "T2", "T1", "T0"):
        r.check("json key %s" % key, key in d, repr(sorted(d)))
    r.check("json coordinates", d.get("coordinates") == ["theta1", "theta2"])
    r.check("json parameters", d.get("parameters") == PARAMS, repr(d.get("parameters")))
    r.check("json strings", all(isinstance(x, str) for x in
                                sum(d["mass_matrix"], []) + d["forcing"] + d["accelerations"]))
    p = {"m1": 1.3, "m2": 0.7, "l1": 1.1, "l2": 0.9, "g": 9.81}
    for i in range(3):
        s = random_state(rng)
        M, f, a = closed_form(s, p)
        got_a = [eval_text(x, s, p) for x in d["accelerations"]]
        got_M = [eval_text(x, s, p) for x in sum(d["mass_matrix"], [])]
        got_f = [eval_text(x, s, p) for x in d["forcing"]]
        r.check("json symbolic accelerations (%d)" % i, all_close(got_a, a), repr(got_a))
        r.check("json symbolic M, f (%d)" % i,
                all_close(got_M, sum(M, [])) and all_close(got_f, f))
        w1, w2 = s["theta1'"], s["theta2'"]
        T = 0.5 * (p["m1"] + p["m2"]) * p["l1"] ** 2 * w1 ** 2 + 0.5 * p["m2"] * p["l2"] ** 2 * \
            w2 ** 2 + p["m2"] * p["l1"] * p["l2"] * w1 * w2 * math.cos(s["theta1"] - s["theta2"])
        r.check("json T2 (%d)" % i, close(eval_text(d["T2"], s, p), T) and
                eval_text(d["T1"], s, p) == 0 and eval_text(d["T0"], s, p) == 0)


def test_text(r, dp):
    p = r.run("eom", dp, "--solve")
    out = p.stdout
    ok = p.returncode == 0 and "M[theta1,theta1] =" in out and "f[theta2] =" in out and \
        "theta1'' =" in out and "theta2'' =" in out
    r.check("text --solve", ok, out + p.stderr)
    p = r.run("eom", dp, "--format", "latex", "--solve")
    body = p.stdout.strip()
    ok = p.returncode == 0 and body.startswith("\\begin{align}") and \
        body.endswith("\\end{align}") and body.count("&=") == 4
    r.check("latex align", ok, p.stdout + p.stderr)


def test_rheonomic(r, rng):
    path = r.model("wire.qd", ROTATING_WIRE)
    p = r.run("eom", path)
    r.check("text T split", p.returncode == 0 and "T0 =" in p.stdout and "T1 =" in p.stdout,
            p.stdout + p.stderr)
    for _ in range(3):
        rr, v, om = rng.uniform(0.1, 3), rng.uniform(-2, 2), rng.uniform(0.5, 3)
        d, err = eom_json(r, path, "--at", "r=%r, r'=%r, t=%r" % (rr, v, rng.uniform(0, 5)),
                          "--set", "omega=%r" % om)
        ok = d is not None and close(d["accelerations"][0], om * om * rr) and \
            close(d["T2"], v * v / 2) and close(d["T1"], 0) and \
            close(d["T0"], om * om * rr * rr / 2)
        r.check("rotating wire r'' = omega^2 r, T split", ok, err or repr(d))


def test_sympy(r, dp, rng):
    try:
        import sympy
    except ImportError:
        print("skip sympy output (no sympy)")
        return
    p = r.run("eom", dp, "--format", "sympy", "--solve")
    if not r.check("sympy runs", p.returncode == 0, p.stderr):
        return
    env = {}
    try:
        exec(p.stdout, env)
    except Exception as e:  # the snippet must run as printed
        r.check("sympy snippet executes", False, "%s\n%s" % (e, p.stdout))
        return
    s = random_state(rng)
    t = env["t"]
    th1, th2 = env["theta1"](t), env["theta2"](t)
    # derivatives first, so that the functions are not replaced inside them
    sub = [(th1.diff(t), s["theta1'"]), (th2.diff(t), s["theta2'"]),
           (th1, s["theta1"]), (th2, s["theta2"])]
    sub += [(env[k], v) for k, v in PARAMS.items()]
    M, f, a = closed_form(s, PARAMS)
    got_M = [float(x) for x in env["M"].subs(sub)]
    got_f = [float(x) for x in env["f"].subs(sub)]
    got_a = [float(x) for x in env["qdd"].subs(sub)]
    r.check("sympy M, f, qdd", all_close(got_M, sum(M, [])) and all_close(got_f, f) and
            all_close(got_a, a), repr((got_M, got_f, got_a)))


def test_name_clash(r):
    """A model's M and f must not be overwritten by the outputs' names."""
    path = r.model("clash.qd", CLASH)
    try:
        import sympy
    except ImportError:
        sympy = None
    if sympy:
        p = r.run("eom", path, "--format", "sympy", "--solve")
        env = {}
        try:
            exec(p.stdout, env)
            M, f = env["M"], env["f"]
            acc = env["qdd"].subs({M: 2, f: 3})[0]
            ok = isinstance(M, sympy.Symbol) and acc == sympy.Rational(-3, 2)
        except Exception as e:
            ok, p.stdout = False, "%s\n%s" % (e, p.stdout)
        r.check("sympy output with a parameter named M", ok, p.stdout)
    cc = shutil.which("cc") or shutil.which("gcc")
    if not cc:
        return
    p = r.run("eom", path, "--format", "c", "--solve")
    src, exe = os.path.join(r.tmp, "clash.c"), os.path.join(r.tmp, "clash")
    with open(src, "w") as fp:
        fp.write("#include <stdio.h>\nint main(void) {\n double x = 0, x_d = 0, t = 0, M = 2, "
                 "f = 3;\n double M_[1][1], f_[1], qdd[1];\n (void)x; (void)x_d; (void)t;\n"
                 "%s\n printf(\"%%.17g\\n\", qdd[0]);\n return 0;\n}\n" % p.stdout)
    c = subprocess.run([cc, "-std=c11", "-Wall", "-o", exe, src, "-lm"], capture_output=True,
                       text=True)
    out = subprocess.run([exe], capture_output=True, text=True).stdout if c.returncode == 0 else ""
    r.check("c output with a parameter named M", out.strip() == "-1.5", c.stderr + p.stdout)


C_MAIN = """\
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
int main(int argc, char **argv) {
    (void)argc;
    double theta1 = atof(argv[1]), theta2 = atof(argv[2]), theta1_d = atof(argv[3]),
           theta2_d = atof(argv[4]), t = 0, m1 = 1, m2 = 1, l1 = 1, l2 = 1, g = 9.81;
    double M[2][2], f[2], qdd[2];
    (void)t;
%s
    printf("%%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g\\n",
           M[0][0], M[0][1], M[1][0], M[1][1], f[0], f[1], qdd[0], qdd[1]);
    return 0;
}
"""


def test_c(r, dp, rng):
    cc = shutil.which("cc") or shutil.which("gcc")
    if not cc:
        print("skip C output (no compiler)")
        return
    p = r.run("eom", dp, "--format", "c", "--solve")
    if not r.check("c runs", p.returncode == 0 and "qdd[1] =" in p.stdout, p.stderr):
        return
    src, exe = os.path.join(r.tmp, "eom.c"), os.path.join(r.tmp, "eom")
    with open(src, "w") as fp:
        fp.write(C_MAIN % p.stdout)
    c = subprocess.run([cc, "-std=c11", "-Wall", "-Werror", "-o", exe, src, "-lm"],
                       capture_output=True, text=True)
    if not r.check("c compiles", c.returncode == 0, c.stderr + p.stdout):
        return
    for i in range(3):
        s = random_state(rng)
        out = subprocess.run([exe] + ["%r" % s[k] for k in ("theta1", "theta2", "theta1'",
                                                            "theta2'")],
                             capture_output=True, text=True).stdout.split()
        got = [float(x) for x in out]
        M, f, a = closed_form(s, PARAMS)
        r.check("c values (%d)" % i, all_close(got, sum(M, []) + f + a), repr(got))


# ---- check -------------------------------------------------------------------------

def line_of(out, prefix):
    return next((l for l in out.splitlines() if l.startswith(prefix)), "")


def test_check(r, dp):
    path = r.model("central.qd", CENTRAL_FORCE)
    p = r.run("check", path)
    cyc = line_of(p.stdout, "cyclic coordinates:")
    r.check("check central force: phi cyclic",
            p.returncode == 0 and re.search(r"\bphi\b", cyc) is not None and
            re.search(r"\br\b(?!')", cyc.split("(")[0].split(":", 1)[1]) is None, p.stdout)
    r.check("check central force: p_phi", "m*phi'*r^2" in cyc or "m*r^2*phi'" in cyc, cyc)
    r.check("check degrees of freedom", "degrees of freedom: 2" in p.stdout, p.stdout)
    r.check("check V depends on r only",
            re.fullmatch(r"V:\s+coordinates r; parameters k", line_of(p.stdout, "V:")) is not None,
            p.stdout)
    p = r.run("check", dp)
    r.check("check double pendulum: no cyclic coordinate",
            p.returncode == 0 and line_of(p.stdout, "cyclic coordinates:").endswith("none"),
            p.stdout)
    p = r.run("check", r.model("wire.qd", ROTATING_WIRE))
    r.check("check rotating wire: rheonomic, L without explicit t",
            p.returncode == 0 and "rheonomic" in p.stdout and
            "L depends on t" not in p.stdout, p.stdout)


# ---- constraints -----------------------------------------------------------------
#
# Atwood machine (Goldstein sec. 1.6): x1, x2 down from the pulley, rope
# x1 + x2 = l; the tension is 2 m1 m2 g/(m1 + m2) and pulls each mass up, so
# with R_j = lambda a_j (docs/design.md) lambda_rope = -tension.  Bead on a
# wire turning at omega (seed-goldstein-britannica G03): the wire's force is
# 2 m omega r' across the wire.  Particle on a sphere from rest at the top
# (seed-desloge-A T27): N = m g (3 cos th - 2).

ATWOOD = """\
coordinates x1, x2
parameters m1 = 2, m2 = 1, g = 9.81, l = 5
T = m1/2*x1'^2 + m2/2*x2'^2
V = -m1*g*x1 - m2*g*x2
constraint rope: x1 + x2 = l
"""

BEAD = """\
coordinates x, y
parameters m = 1.5, omega = 2
T = m/2*(x'^2 + y'^2)
constraint wire: y*cos(omega*t) - x*sin(omega*t) = 0
"""

SPHERE = """\
coordinates r, theta
parameters m = 1, g = 9.81, a = 2
T = m/2*(r'^2 + r^2*theta'^2)
V = m*g*r*cos(theta)
constraint surface: r = a
"""

KNIFE = """\
coordinates x, y, z
parameters m = 1
T = m/2*(x'^2 + y'^2 + z'^2)
constraint knife: y' = z*x'
constraint hyper: x*y' + y*x' = 0
"""


def test_constraints(r, rng):
    atwood = r.model("atwood.qd", ATWOOD)
    for i in range(3):
        m1, m2, g = rng.uniform(0.5, 3), rng.uniform(0.5, 3), rng.uniform(1, 10)
        x1, v = rng.uniform(0, 5), rng.uniform(-1, 1)
        d, err = eom_json(r, atwood, "--set", "m1=%r" % m1, "--set", "m2=%r" % m2,
                          "--set", "g=%r" % g, "--at", "x1=%r, x2=%r, x1'=%r, x2'=%r" %
                          (x1, 5 - x1, v, -v))
        if not r.check("atwood --at runs (%d)" % i, d is not None, err):
            continue
        tension = 2 * m1 * m2 * g / (m1 + m2)
        a = (m1 - m2) * g / (m1 + m2)
        r.check("atwood tension (%d)" % i, close(d["multipliers"]["rope"], -tension),
                repr(d.get("multipliers")))
        r.check("atwood constraint forces (%d)" % i,
                all_close([d["constraint_forces"]["x1"], d["constraint_forces"]["x2"]],
                          [-tension, -tension]), repr(d.get("constraint_forces")))
        r.check("atwood accelerations (%d)" % i, all_close(d["accelerations"], [a, -a]))
    p = r.run("eom", atwood)
    r.check("atwood text names the multiplier",
            p.returncode == 0 and "x1: M[x1,x1]*x1'' = f[x1] + lambda_rope*(1)" in p.stdout,
            p.stdout + p.stderr)
    p = r.run("eom", atwood, "--at", "x1=1, x2=4")
    r.check("atwood text multipliers", p.returncode == 0 and
            re.search(r"lambda_rope = -13\.08\b", p.stdout) is not None, p.stdout + p.stderr)
    # --eliminate: (m1 + m2) x1'' = (m1 - m2) g
    d, err = eom_json(r, atwood, "--eliminate")
    ok = d is not None and d["coordinates"] == ["x1"]
    if r.check("atwood --eliminate", ok, err + repr(d)):
        vals = {"m1": 2.0, "m2": 1.0, "g": 9.81, "l": 5.0, "x1": 0.7}
        s = {"x1": 0.7}
        M = eval_text(d["mass_matrix"][0][0], s, vals)
        f = eval_text(d["forcing"][0], s, vals)
        r.check("atwood --eliminate equation", close(M, 3.0) and close(f, 9.81),
                "%r %r" % (M, f))
        r.check("atwood --eliminate records x2", "x2" in d.get("eliminated", {}), repr(d))

    bead = r.model("bead.qd", BEAD)
    for i in range(3):
        m, w = 1.5, 2.0
        t, rho, rd = rng.uniform(-2, 2), rng.uniform(0.1, 2), rng.uniform(-2, 2)
        c, sn = math.cos(w * t), math.sin(w * t)
        st = "x=%r, y=%r, x'=%r, y'=%r, t=%r" % (rho * c, rho * sn, rd * c - rho * w * sn,
                                                 rd * sn + rho * w * c, t)
        d, err = eom_json(r, bead, "--at", st)
        if not r.check("bead --at runs (%d)" % i, d is not None, err):
            continue
        R = d["constraint_forces"]
        r.check("bead force 2 m omega r' (%d)" % i,
                close(-R["x"] * sn + R["y"] * c, 2 * m * w * rd) and
                close(R["x"] * c + R["y"] * sn, 0), repr(R))

    sphere = r.model("sphere.qd", SPHERE)
    for th in (0.3, math.acos(2 / 3) - 0.01, math.acos(2 / 3) + 0.01, 1.2):
        thd = math.sqrt(2 * 9.81 * (1 - math.cos(th)) / 2)
        d, err = eom_json(r, sphere, "--at", "r=2, theta=%r, theta'=%r" % (th, thd))
        ok = d is not None and close(d["multipliers"]["surface"], 9.81 * (3 * math.cos(th) - 2))
        r.check("sphere normal force at theta=%.3f" % th, ok, err + repr(d))


def test_constraint_errors(r):
    text = ATWOOD + "constraint rope2: 2*x1 + 2*x2 = 2*l\n"
    p = r.run("eom", r.model("ropes.qd", text))
    # redundant but consistent (issue 33): left out by rank, with a note
    r.check("redundant constraint reduced by rank",
            p.returncode == 0 and "note: constraint rope is redundant" in p.stdout and
            "lambda_rope2" in p.stdout, p.stdout + p.stderr)
    p = r.run("eom", r.model("ropes2.qd", text.replace("= 2*l", "= 2*l + 1")))
    r.check("inconsistent constraints named",
            p.returncode == 2 and "rope and rope2 are inconsistent" in p.stderr, p.stderr)
    p = r.run("eom", r.model("speed.qd", BEAD + "constraint speed: x'^2 + y'^2 = 1\n"))
    r.check("nonlinear velocity constraint", p.returncode == 2 and "speed" in p.stderr and
            "not linear in the velocities" in p.stderr, p.stderr)


def test_check_constraints(r):
    p = r.run("check", r.model("atwood.qd", ATWOOD))
    r.check("check atwood: holonomic rope, 1 degree of freedom",
            p.returncode == 0 and "constraint rope: " in p.stdout and
            line_of(p.stdout, "constraint rope").endswith("holonomic") and
            "degrees of freedom: 1 configurational, 1 motional" in p.stdout, p.stdout)
    r.check("check atwood: x1 not conserved",
            "p_x1" not in line_of(p.stdout, "cyclic coordinates:"), p.stdout)
    p = r.run("check", r.model("knife.qd", KNIFE))
    out = p.stdout
    r.check("check knife: kinds and degrees of freedom",
            p.returncode == 0 and "nonholonomic" in line_of(out, "constraint knife") and
            "integrable" in line_of(out, "constraint hyper") and
            "x*y = const" in line_of(out, "constraint hyper") and
            "degrees of freedom: 1 configurational, 1 motional" in out, out + p.stderr)
    # together the knife and x y = const leave only z free (x' = y' = 0 where y + x z != 0):
    # 2 relations among x, y, z, though one constraint alone is nonholonomic
    r.check("check knife: the constraints together fix x and y",
            "integrable combinations: 1 " in out, out)
    # Desloge ch. 52 Problem 5 (p. 557): "four degrees of configurational freedom and two
    # degrees of motional freedom"; no constraint alone is integrable, their difference is
    p = r.run("check", str(EXAMPLES / "two_disks_axle.qd"))
    out = p.stdout
    r.check("check two disks on an axle: 4 configurational, 2 motional",
            p.returncode == 0 and "degrees of freedom: 4 configurational, 2 motional (5 "
            "coordinates; constraints: 0 holonomic, 0 integrable, 3 nonholonomic)" in out and
            "integrable combinations: 1 " in out, out + p.stderr)
    # the relation, up to a factor: a (phi - psi) - 2 b th (Goldstein ch. 1 Derivation 5:
    # th = C - (a/b)(phi - phi') for an axle of length b; the sign is the angles' convention)
    line = line_of(out, "  integral of a combination: ")
    syms = {n: sp.Symbol(n) for n in ("a", "b", "th", "phi", "psi")}
    ok = line.endswith(" = const")
    if ok:
        phi = sp.sympify(line.split(": ", 1)[1][:-len(" = const")].replace("^", "**"),
                         locals=syms)
        ratio = sp.simplify(phi / (syms["a"] * (syms["phi"] - syms["psi"]) - 2 * syms["b"] *
                                   syms["th"]))
        ok = ratio.is_number and ratio != 0
    r.check("check two disks on an axle: the relation th - a (phi - psi)/(2b)", ok, out)
    # Desloge ch. 49 Example 1 (p. 536): the rolling disk, 4 and 2, nothing integrable
    p = r.run("check", str(EXAMPLES / "rolling_disk.qd"))
    r.check("check rolling disk: 4 configurational, 2 motional",
            p.returncode == 0 and "degrees of freedom: 4 configurational, 2 motional" in p.stdout
            and "integrable combinations" not in p.stdout, p.stdout + p.stderr)
    # x' - y' = 0 split across two nonholonomic constraints (u' - v w' is a contact form)
    split = ("coordinates x, y, u, v, w\nparameters m = 1\n"
             "T = m/2*(x'^2 + y'^2 + u'^2 + v'^2 + w'^2)\n"
             "constraint c1: x' - y' + u' - v*w' = 0\nconstraint c2: u' - v*w' = 0\n")
    p = r.run("check", r.model("split.qd", split))
    r.check("check split x' = y': 4 configurational, 3 motional",
            p.returncode == 0 and "degrees of freedom: 4 configurational, 3 motional" in p.stdout
            and "integrable combinations: 1 " in p.stdout, p.stdout + p.stderr)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", required=True, help="the build directory holding qdot")
    ap.add_argument("--seed", type=int, default=20240603)
    args = ap.parse_args()
    qdot = os.path.join(args.build, "qdot")
    rng = random.Random(args.seed)
    with tempfile.TemporaryDirectory() as tmp:
        r = Runner(qdot, tmp)
        dp = r.model("double_pendulum.qd", DOUBLE_PENDULUM)
        for test in (test_usage, test_at_errors, test_text, test_check):
            test(r, dp)
        test_bad_model(r)
        test_singular(r)
        for test in (test_at, test_set, test_json_symbolic, test_sympy, test_c):
            test(r, dp, rng)
        test_rheonomic(r, rng)
        test_name_clash(r)
        test_constraints(r, rng)
        test_constraint_errors(r)
        test_check_constraints(r)
    print("%d passed, %d failed (seed %d)" % (r.passed, r.failed, args.seed))
    return 1 if r.failed else 0


if __name__ == "__main__":
    sys.exit(main())
