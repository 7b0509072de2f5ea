#!/usr/bin/env python3
"""One vocabulary across the commands (issue 31), as docs/cli.md states it:

  - every command answers --help with exit 0, a usage line and a described
    line for each option; an option misspelt by one letter is refused with
    exit 2 and "did you mean" the option;
  - every command's JSON that reads a model starts with "model", the model
    file as given, and no JSON says "degeneracy", "M", "f", "source" or
    "file" (the picture's file under "plot" excepted) where the one word is
    "multiplicity", "mass_matrix", "forcing", "from" or "model";
  - "stable" is the tri-state true / false / null: a double pendulum hangs
    stably at the bottom (true) and not at the top (false), and two masses
    joined by a spring have the free translation x = y of w^2 = 0, whose
    linear terms cannot decide (null);
  - exit statuses: 0 an answer, 2 bad input (an unknown option, a model that
    does not read, a parameter with no value in any command, an unknown name
    in an option's expression), 1 a failure with nothing on stdout (no lob of energy
    E = m g h with h = 1 reaches y = 3: Desloge ch. 83, Byerly ch. IV, as
    examples/path_projectile.qd), 3 a certified "no" printed with its
    witness (Q = p, P = q has [Q, P] = -1: not canonical, Goldstein 9.4;
    a zero mass makes M singular: check's no);
  - poincare --format json holds simulate's document shape and the same
    rows as its CSV, each on the section (theta1 = 0, theta1' > 0) with the
    energy of the start (conserved: no forces, no damping);
  - diff --format json holds d(x^2 sin y)/dx = 2 x sin y (SymPy's), also in
    its LaTeX-free forms; a range written A..B is the box A:B.

    python3 tests/cli/check_vocabulary_cli.py --build BUILD_DIR
"""
import argparse
import csv
import io
import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / "examples"
results = {"passed": 0, "failed": 0}

ONE = """coordinates q
parameters m = 1, w = 1
T = m*q'^2/2
V = m*w^2*q^2/2
"""
SPRING = """coordinates x, y
parameters m = 1, k = 1
T = m*(x'^2 + y'^2)/2
V = k*(x - y)^2/2
"""
MASSLESS = """coordinates r
parameters m = 0, k = 1
T = m*r'^2/2
V = k*r^2/2
"""
# Words a JSON key must not be: the one word on the right (docs/cli.md).
FORBIDDEN = {"degeneracy": "multiplicity", "M": "mass_matrix", "f": "forcing",
             "source": "from", "file": "model"}


def check(name, ok, detail=""):
    if ok:
        results["passed"] += 1
    else:
        results["failed"] += 1
        print("FAIL %s %s" % (name, str(detail)[:600]))


def run(qdot, *args):
    return subprocess.run([str(qdot)] + [str(a) for a in args], capture_output=True, text=True,
                          timeout=300)


def commands(qdot):
    """The commands `qdot --help` lists."""
    r = run(qdot, "--help")
    return [m.group(1) for m in re.finditer(r"^  ([a-z][a-z-]*) ", r.stdout, re.M)]


def option_lines(text):
    """(line, the first long option) for each option line of a --help."""
    out = []
    for line in text.splitlines():
        m = re.match(r"^\s+(?:-\w, )?(--[\w-]+)", line)
        if m:
            out.append((line, m.group(1)))
    return out


def helps(qdot, names):
    for c in names:
        r = run(qdot, c, "--help")
        check("%s --help: exit 0" % c, r.returncode == 0, r.stderr)
        check("%s --help: a usage line" % c, r.stdout.startswith("usage: qdot %s" % c), r.stdout)
        lines = option_lines(r.stdout)
        check("%s --help: -h, --help listed" % c, any(o == "--help" for _, o in lines), r.stdout)
        for line, opt in lines:
            parts = re.split(r"\s{2,}", line.strip())
            # a description: after the option and its value's name (two spaces, or one
            # after a long value's name), with words in it
            desc = parts[-1] if len(parts) > 1 else line.split(opt, 1)[1]
            ok = re.search(r"[a-z]{2,}" if len(parts) > 1 else r"[a-z]{3,}", desc)
            check("%s --help: %s is described" % (c, opt), ok, line)
        for line, opt in lines:
            if opt == "--out":
                check("%s --help: -o is --out" % c, "-o, --out" in line, line)
        first = next((o for _, o in lines if o != "--help" and len(o) > 5), None)
        if first is None:
            continue
        typo = first[:-1]  # one letter short
        args = {"diff": ["x", "x"], "expand": ["x"], "simplify": ["x"], "print": ["x"],
                "form": ["x"], "lqr": [], "lorentz": [], "collide": []}.get(c, ["m.qd"])
        r = run(qdot, c, *args, typo)
        check("%s %s: exit 2" % (c, typo), r.returncode == 2, r.stderr)
        check("%s %s: did you mean %s" % (c, typo, first),
              "did you mean '%s'" % first in r.stderr, r.stderr)


def walk(x, path=""):
    """Every (path, key, value) of a JSON document."""
    if isinstance(x, dict):
        for k, v in x.items():
            yield path, k, v
            yield from walk(v, path + "/" + k)
    elif isinstance(x, list):
        for v in x:
            yield from walk(v, path + "[]")


def documents(qdot, t):
    """The JSON of every command that reads a model, on models whose
    answers the tests of each command check."""
    return [
        ("eom", EX / "double_pendulum.qd"),
        ("check", EX / "double_pendulum.qd"),
        ("hamiltonian", EX / "kepler_polar.qd"),
        ("bracket", EX / "kepler_polar.qd", "r", "p_r"),
        ("canonical", t / "one.qd", "--Q", "p_q", "--P", "-q"),
        ("routh", EX / "kepler_polar.qd", "--ignore", "theta"),
        ("integrals", EX / "kepler_cartesian.qd"),
        ("simulate", EX / "double_pendulum.qd", "--t-end", "0.1"),
        ("poincare", EX / "double_pendulum.qd", "--section", "theta1 = 0, theta1' > 0",
         "--crossings", "1", "--initial", "theta1=1, theta2=0.5"),
        ("lyapunov", EX / "henon_heiles.qd", "--t-end", "5"),
        ("equilibria", EX / "double_pendulum.qd"),
        ("linearize", EX / "cart_pendulum.qd", "--about", "th=0"),
        ("modes", EX / "double_pendulum.qd"),
        ("modes", EX / "ring_three_masses.qd", "--about",
         "x1=0, y1=0, x2=1, y2=0, x3=0.5, y3=sqrt(3)/2", "--symmetry"),
        ("modes", EX / "pendulum_cartesian.qd", "--independent", "x"),
        ("stability", EX / "spherical_pendulum.qd", "--ignore", "phi", "--at", "theta=pi/3"),
        ("orbit", EX / "kepler_polar.qd", "--ignore", "theta", "--at", "r=1, r'=0, theta'=0.9"),
        ("hj", EX / "hj_oscillator.qd", "--solve"),
        ("action", EX / "action_pendulum.qd"),
        ("action-of", EX / "hj_projectile.qd", "--path", "x = 0, y = -g*t^2/2", "--t", "0:2"),
        ("zvc", EX / "restricted_three_body.qd", "--box", "x=-1.5:1.5, y=-1.5:1.5",
         "--through", "x=0.848078712976"),
        ("impulse", EX / "circuit_induced_currents.qd"),
        ("scatter", EX / "hard_sphere.qd", "--energy", "1", "--b", "0.5"),
        ("path", EX / "catenary.qd", "--from", "x=0, y=0", "--to", "x=2, y=1"),
        ("metric", EX / "kepler_polar.qd"),
        ("sweep", t / "one.qd", "--grid", "w=1:2:2", "--t-end", "1", "--measure", "final"),
    ]


def vocabulary(qdot, t):
    for args in documents(qdot, t):
        r = run(qdot, *args, "--format", "json")
        name = " ".join(str(a) for a in args[:1] + args[2:3])
        try:
            d = json.loads(r.stdout)
        except ValueError:
            check("%s: JSON" % name, False, r.stdout[:300] + r.stderr)
            continue
        check("%s: exit 0" % name, r.returncode == 0, r.stderr)
        check("%s: \"model\" first, the file as given" % name,
              list(d)[:1] == ["model"] and d["model"] == str(args[1]), list(d)[:3])
        check("%s: \"model\" once (JSON would keep the last of two)" % name,
              r.stdout.count('\n  "model": ') == 1, r.stdout[:200])
        for path, k, v in walk(d):
            if k in FORBIDDEN and not (k == "file" and path.endswith("/plot")):
                check("%s: no key %r (the word is %r)" % (name, k, FORBIDDEN[k]), False,
                      path or "top")
            if k == "stable":
                check("%s: %s/stable is true, false or null" % (name, path),
                      v is None or isinstance(v, bool), repr(v))
    # the commands that read no model have no "model"
    r = run(qdot, "lorentz", "--frame", "0.6, 0, 0", "--format", "json")
    check("lorentz: no model, no \"model\"", r.returncode == 0 and
          "model" not in json.loads(r.stdout or "{}"), r.stdout[:200] + r.stderr)


def stable(qdot, t):
    def verdict(*args):
        r = run(qdot, "modes", *args, "--format", "json")
        return json.loads(r.stdout).get("stable", "missing") if r.returncode == 0 else r.stderr
    dp = EX / "double_pendulum.qd"
    check("stable: the double pendulum hangs stably (true)",
          verdict(dp, "--about", "theta1=0, theta2=0") is True)
    check("stable: upside down it falls (false)",
          verdict(dp, "--about", "theta1=pi, theta2=pi") is False)
    check("stable: a free translation, w^2 = 0, is undecided (null)",
          verdict(t / "spring.qd", "--about", "x=0, y=0") is None)
    doc = (ROOT / "docs" / "cli.md").read_text()
    check("docs: stable's three values", "`stable` is `true`, `false` or `null`" in doc)
    check("docs: exit 3 is a certified no", "3 a certified \"no\"" in doc)
    check("docs: the model key", "starts with `model`" in doc)


def exits(qdot, t):
    r = run(qdot, "canonical", t / "one.qd", "--Q", "p_q", "--P", "-q")
    check("exit 0: Q = p, P = -q is canonical", r.returncode == 0 and "canonical" in r.stdout,
          r.stdout + r.stderr)
    r = run(qdot, "canonical", t / "one.qd", "--Q", "p_q", "--P", "q")
    check("exit 3: Q = p, P = q is not canonical, [Q, P] = -1, said on stdout",
          r.returncode == 3 and "not canonical" in r.stdout and "-1" in r.stdout,
          "%d %r %r" % (r.returncode, r.stdout, r.stderr))
    r = run(qdot, "check", t / "massless.qd", "--format", "json")
    d = json.loads(r.stdout) if r.returncode == 3 else {}
    check("exit 3: a zero mass is check's no, code next to reason",
          d.get("ok") is False and d.get("code") == "mass_not_positive_definite" and
          "not positive definite" in d.get("reason", "") and d.get("witness") == 0,
          "%d %s" % (r.returncode, r.stdout[:300]))
    r = run(qdot, "path", EX / "path_projectile.qd", "--from", "x=0, y=0", "--to", "x=0, y=3",
            "--energy", "19.62")
    check("exit 1: no lob of E = m g (1 m) reaches y = 3, nothing on stdout",
          r.returncode == 1 and r.stdout == "" and "error" in r.stderr,
          "%d %r" % (r.returncode, r.stdout))
    for args in (["eom", t / "one.qd", "--formt", "json"], ["eom", t / "bad.qd"],
                 ["modes", EX / "double_pendulum.qd", "--about", "theta3=0"]):
        r = run(qdot, *args)
        check("exit 2: %s" % " ".join(str(a) for a in args[2:]) or args[1],
              r.returncode == 2 and r.stdout == "", "%d %r" % (r.returncode, r.stderr))


def unbound(qdot, t):
    """One rule from status to exit code: a parameter with no value is bad
    input (2) in every command, shown at its place in the model file, and so
    is an unknown name in an option's expression, shown in the option."""
    f = t / "unbound.qd"
    f.write_text("coordinates x\nparameters m, k = 1\nT = m*x'^2/2\nV = k*x^2/2\n"
                 "initial x = 1, x' = 0\n")
    for args in (["simulate", "--t-end", "1"], ["poincare", "--section", "x = 0", "--crossings",
                 "1"], ["lyapunov", "--t-end", "1"], ["equilibria"], ["modes"], ["linearize"],
                 ["action"], ["orbit", "--ignore", "x"], ["zvc", "--box", "x=-1:1",
                 "--level", "1"], ["impulse"], ["scatter", "--energy", "1", "--b", "1"],
                 ["sweep", "--grid", "k=1:2:2", "--t-end", "1", "--measure", "final"],
                 ["check"], ["eom"], ["hamiltonian"]):
        r = run(qdot, args[0], f, *args[1:])
        check("exit 2: %s with m unbound, at its place" % args[0], r.returncode == 2 and
              "unbound.qd:2:12: error: parameter 'm' has no value" in r.stderr,
              "%d %r" % (r.returncode, r.stderr[:200]))
    for opt, text, place in (("--output", "zz", "--output:1:1:"),
                             ("--event", "zz = 0", "--event:1:1:")):
        r = run(qdot, "simulate", t / "one.qd", "--t-end", "1", "--initial", "q=1", opt, text)
        check("exit 2: simulate %s %r, at its place" % (opt, text), r.returncode == 2 and
              place in r.stderr and r.stdout == "", "%d %r" % (r.returncode, r.stderr[:200]))


def poincare(qdot):
    args = [EX / "double_pendulum.qd", "--section", "theta1 = 0, theta1' > 0",
            "--crossings", "3", "--initial", "theta1=1, theta2=0.5"]
    rc = run(qdot, "poincare", *args)
    rj = run(qdot, "poincare", *args, "--format", "json")
    rows = list(csv.reader(io.StringIO(rc.stdout)))
    d = json.loads(rj.stdout) if rj.returncode == 0 else {}
    check("poincare json: exit 0", rj.returncode == 0, rj.stderr)
    check("poincare json: columns as the CSV header", d.get("columns") == rows[0], d.get("columns"))
    got = d.get("rows", [])
    check("poincare json: the CSV's rows", got == [[float(v) for v in r] for r in rows[1:]],
          got)
    cols = d.get("columns", [])
    if got and "theta1" in cols:
        i, j, e = cols.index("theta1"), cols.index("theta1'"), cols.index("energy")
        E0 = -19.20981617315526  # the energy at the start (docs/cli.md's run)
        check("poincare json: each row on the section", all(abs(r[i]) < 1e-12 and r[j] > 0
                                                            for r in got), got)
        check("poincare json: the energy of the start", all(abs(r[e] - E0) < 1e-8 for r in got),
              [r[e] for r in got])
    check("poincare json: 3 crossings of 3, simulate's summary keys",
          d.get("crossings") == 3 and d.get("wanted") == 3 and
          all(k in d for k in ("method", "steps", "evaluations", "energy_error_max")), list(d))
    stop = d.get("stop", {})
    check("poincare json: the run ends at the last crossing, a terminal event",
          stop.get("code") == "event" and got and stop.get("t") == got[-1][0], stop)


def expressions(qdot):
    import sympy as sp
    x, y = sp.symbols("x y")
    for cmd, args, want in (("diff", ["x^2*sin(y)", "x"], sp.diff(x**2 * sp.sin(y), x)),
                            ("expand", ["(x + y)^3"], sp.expand((x + y)**3)),
                            ("simplify", ["sin(x)^2 + cos(x)^2"], sp.Integer(1)),
                            ("print", ["sin(pi/6) + y"], y + sp.Rational(1, 2))):
        r = run(qdot, cmd, *args, "--format", "json")
        d = json.loads(r.stdout) if r.returncode == 0 else {}
        check("%s json: operation, input, variables" % cmd, d.get("operation") == cmd and
              d.get("input") == args[0] and d.get("variables") == args[1:], r.stdout + r.stderr)
        ns = {"x": x, "y": y}
        for key, text in (("result", d.get("result", "").replace("^", "**")),
                          ("sympy", d.get("sympy", ""))):
            ok = False
            try:
                ok = sp.simplify(sp.sympify(text, locals=ns) - want) == 0
            except (sp.SympifyError, SyntaxError, TypeError):
                pass
            check("%s json: %s is %s" % (cmd, key, want), ok, text)


def ranges(qdot):
    dp = EX / "double_pendulum.qd"
    a = run(qdot, "equilibria", dp, "--box", "theta1=-1:1, theta2=-1:1", "--format", "json")
    b = run(qdot, "equilibria", dp, "--box", "theta1=-1..1, theta2=-1..1", "--format", "json")
    check("--box A..B is the box A:B", a.returncode == 0 and a.stdout == b.stdout,
          a.stderr + b.stderr)


def points(qdot, names):
    """One name for "the point" (issue 31): --at, --about, --guess and --initial,
    each only where docs/cli.md's rule says, and no other spelling (--near was
    equilibria's --guess)."""
    doc = (Path(__file__).resolve().parents[2] / "docs" / "cli.md").read_text()
    m = re.search(r"A point is named by one of four options.*?\n\n", doc, re.S)
    check("docs: the rule for the point's options", m is not None)
    rule = " ".join(m.group(0).split()) if m else ""
    where = {}
    for opt in ("--at", "--about", "--guess", "--initial"):
        part = re.search(r"`%s` [^(]*\(([^)]*)\)" % opt, rule)
        check("docs: %s has its commands" % opt, part is not None, rule)
        where[opt] = set(re.findall(r"[a-z][a-z-]+", part.group(1))) if part else set()
    for c in names:
        h = run(qdot, c, "--help").stdout
        have = set(re.findall(r"^\s+(--(?:at|about|guess|initial|near|point|from-state))\s",
                              h, re.M))
        check("%s --help: no --near (it is --guess)" % c, "--near" not in have, h)
        for opt in have - {"--near"}:
            check("%s %s: as the docs' rule says" % (c, opt), c in where.get(opt, ()),
                  "%s not among %s" % (c, sorted(where.get(opt, ()))))
    r = run(qdot, "equilibria", "m.qd", "--near", "x=1")
    check("equilibria --near: the new name said", "--near is now --guess" in r.stderr, r.stderr)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build).resolve() / "qdot"
    with tempfile.TemporaryDirectory(prefix="qdot-voc-") as d:
        t = Path(d)
        (t / "one.qd").write_text(ONE)
        (t / "spring.qd").write_text(SPRING)
        (t / "massless.qd").write_text(MASSLESS)
        (t / "bad.qd").write_text("coordinates q\nT = q'^2/2 +\n")
        helps(qdot, commands(qdot))
        points(qdot, commands(qdot))
        vocabulary(qdot, t)
        stable(qdot, t)
        exits(qdot, t)
        unbound(qdot, t)
        poincare(qdot)
        expressions(qdot)
        ranges(qdot)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
