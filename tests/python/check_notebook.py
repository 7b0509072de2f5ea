#!/usr/bin/env python3
"""tests/python/check_notebook.py - examples/tour.ipynb, executed as a user
would run it (`jupyter nbconvert --to notebook --execute`, Debian's
jupyter-nbconvert and python3-ipykernel), with the package of this tree and
the library of the build (--build); then its outputs read back and checked
against the physics, computed here:

  - the double pendulum's modes, w^2 = (g/l)(2 -+ sqrt 2) (Goldstein ch. 6);
  - the pendulum's H with l set to 2, p^2/(2 m l^2) - m g l cos(theta), the
    value fixed in (qd_model_opts_for), compared by SymPy;
  - the chaotic run: the energy conserved, the Lyapunov exponent positive
    beyond twice its error estimate;
  - the equations shown as LaTeX, the plot as a PNG (with matplotlib), the
    animation as inline HTML;
  - the top: the version the package reports is include/qdot/version.h's,
    and the equations' LaTeX printed is what `qdot eom --format latex`
    prints for the same model (run here on the model's text);
  - the Kepler orbit (examples/kepler_polar.qd, m = 1.3, k = 4, from r = 1,
    theta' = 1.5): E = m r^2 theta'^2/2 - k/r, a = -k/(2E), e^2 = 1 + 2 E
    L^2/(m k^2), T = 2 pi sqrt(m a^3/k) (Desloge ch. 59), the apsidal angle
    pi, and the simulated particle back at r = 1 after T, theta = 2 pi;
  - the sleeping top (examples/sleeping_top.qd, A = 1, M g h = 1; Britannica
    1911, Dynamics, sec. 6): for nu = 3 the tilting frequencies
    (nu -+ sqrt(nu^2 - 4 A M g h))/(2 A), for nu = 1.5 unstable growing at
    sqrt(4 A M g h - nu^2)/(2 A); nudged at nu = 3 its tilt stays within twice
    the nudge, its energy kept.

Skips (77) when nbconvert or the kernel is missing.
"""
import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
NOTEBOOK = os.path.join(ROOT, "examples", "tour.ipynb")


def skip(why):
    print("SKIP: %s" % why)
    sys.exit(77)


def outputs(nb):
    """Per code cell, the list of its outputs."""
    return [c.get("outputs", []) for c in nb["cells"] if c["cell_type"] == "code"]


def text_of(outs):
    return "".join("".join(o.get("text", "")) for o in outs if o["output_type"] == "stream")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    args = ap.parse_args()
    jupyter = shutil.which("jupyter")
    if not jupyter or subprocess.run([jupyter, "nbconvert", "--version"],
                                     capture_output=True).returncode != 0:
        skip("jupyter nbconvert is not installed (Debian's jupyter-nbconvert)")
    if not os.path.exists("/usr/share/jupyter/kernels/python3/kernel.json"):
        skip("no python3 kernel (Debian's python3-ipykernel)")
    env = dict(os.environ, PYTHONPATH=os.path.join(ROOT, "python"), QDOT_LIB=args.build,
               PYDEVD_DISABLE_FILE_VALIDATION="1", MPLBACKEND="module://matplotlib_inline"
               ".backend_inline")
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([jupyter, "nbconvert", "--to", "notebook", "--execute",
                              "--ExecutePreprocessor.timeout=600", NOTEBOOK, "--output-dir", out],
                             env=env, capture_output=True, text=True)
        if run.returncode != 0:
            print(run.stderr)
            return 1
        with open(os.path.join(out, "tour.ipynb")) as fh:
            nb = json.load(fh)
    cells = outputs(nb)
    errors = [o for outs in cells for o in outs if o["output_type"] == "error"]
    assert not errors, errors

    # the top: the version, and the LaTeX the command line prints
    with open(os.path.join(ROOT, "include", "qdot", "version.h")) as fh:
        version = re.search(r'#define QDOT_VERSION "([^"]+)"', fh.read()).group(1)
    assert text_of(cells[0]).split() == ["qdot", version], text_of(cells[0])
    source = next(src for src in ("".join(c["source"]) for c in nb["cells"]
                                  if c["cell_type"] == "code") if 'qdot.Model("""' in src)
    model = re.search(r'qdot.Model\("""(.*?)"""\)', source, re.S).group(1)
    with tempfile.NamedTemporaryFile("w", suffix=".qd") as fh:
        fh.write(model)
        fh.flush()
        cli = subprocess.run([os.path.join(args.build, "qdot"), "eom", fh.name, "--format",
                              "latex"], capture_output=True, text=True)
    assert cli.returncode == 0, cli.stderr
    assert text_of(cells[2]) == cli.stdout + "\n", (text_of(cells[2]), cli.stdout)

    # the equations, as LaTeX
    eom = cells[1][0]["data"]
    assert "\\ddot{\\theta}" in "".join(eom["text/latex"]), eom

    # H with l = 2 fixed in: p^2/(8 m) - 2 m g cos(theta)
    import sympy
    H_text = text_of(cells[4]).splitlines()[0]
    th, p, m, g = sympy.symbols("theta p_theta m g")
    H = sympy.sympify(H_text.replace("^", "**"), locals={"theta": th, "p_theta": p, "m": m,
                                                          "g": g})
    assert sympy.simplify(H - (p**2 / (2 * m * 4) - m * g * 2 * sympy.cos(th))) == 0, H_text
    assert "text/latex" in cells[3][0]["data"]

    # the modes
    text = text_of(cells[5])
    omega2 = [float(x) for x in re.search(r"omega\^2 = \[([^\]]*)\]", text).group(1).split(",")]
    want = [9.81 * (2 - math.sqrt(2)), 9.81 * (2 + math.sqrt(2))]
    assert all(abs(a - b) <= 1e-9 * b for a, b in zip(omega2, want)), (omega2, want)
    ratio = float(re.search(r"theta2/theta1 = (\S+)", text).group(1))
    assert abs(ratio - math.sqrt(2)) < 1e-9, ratio

    # the chaotic run
    text = text_of(cells[6])
    err = float(re.search(r"energy error over the run: (\S+)", text).group(1))
    lam, lam_err = map(float, re.search(r"exponent: (\S+) \+- (\S+)", text).groups())
    assert err < 1e-8, err
    assert lam > 2 * lam_err > 0, (lam, lam_err)

    # the plot (with matplotlib) and the animation
    plot = cells[7]
    try:
        import matplotlib  # noqa: F401
        assert any("image/png" in o.get("data", {}) for o in plot), plot
    except ImportError:
        assert "matplotlib is not installed" in text_of(plot)
    assert "<iframe srcdoc=" in "".join(cells[8][0]["data"]["text/html"])

    # the Kepler orbit, from the model's numbers
    m, k, r0, w0 = 1.3, 4.0, 1.0, 1.5
    E, L = m * r0**2 * w0**2 / 2 - k / r0, m * r0**2 * w0
    a, e = -k / (2 * E), math.sqrt(1 + 2 * E * L**2 / (m * k**2))
    T = 2 * math.pi * math.sqrt(m * a**3 / k)
    text = text_of(cells[9])
    got = lambda pat: float(re.search(pat, text).group(1))  # noqa: E731
    assert "kind: bound" in text, text
    assert abs(got(r"a = (\S+)") - a) < 1e-12 and abs(got(r" e = (\S+)") - e) < 1e-12, text
    assert abs(got(r"radial period T = (\S+)") - T) < 1e-9 * T, (text, T)
    assert abs(got(r"apsidal angle = (\S+)") - math.pi) < 1e-9, text
    assert abs(got(r"turning points r = \[(\S+),") - a * (1 - e)) < 1e-9, text
    assert any("text/html" in o.get("data", {}) for o in cells[9]), "no table of the orbit"
    text = text_of(cells[10])
    assert abs(got(r"after T: r = (\S+)") - r0) < 1e-8, text
    assert abs(got(r" r' = (\S+)")) < 1e-8, text
    assert abs(got(r"theta = (\S+)") - 2 * math.pi) < 1e-8, text

    # the sleeping top, from the model's numbers
    text = text_of(cells[11])
    nu, A, Mgh = 3.0, 1.0, 1.0
    want = sorted((nu + s * math.sqrt(nu**2 - 4 * A * Mgh)) / (2 * A) for s in (-1, 1))
    freqs = [float(x) for x in re.search(r"frequencies \[([^\]]*)\]", text).group(1).split(",")]
    assert all(abs(a - b) < 1e-9 for a, b in zip(sorted(freqs), want)), (freqs, want)
    assert "stable: True" in text.splitlines()[0], text
    assert "secularly unstable" in text, text  # V upright is a maximum: gyroscopic
    nu = 1.5
    assert "nu = 1.5: stable: False" in text, text
    assert abs(got(r"growth rate: (\S+)") - math.sqrt(4 * A * Mgh - nu**2) / (2 * A)) < 1e-9, text
    text = text_of(cells[12])
    assert got(r"largest tilt: (\S+)") < 2 * 0.05, text
    assert got(r"energy error: (\S+)") < 1e-8, text
    print("ok: omega^2 = %s, lambda = %.3g +- %.2g, energy error %.2g" % (omega2, lam, lam_err,
                                                                         err))
    return 0


if __name__ == "__main__":
    sys.exit(main())
