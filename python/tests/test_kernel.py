# python/tests/test_kernel.py - qdot.diff, expand, simplify, print_expr (the
# kernel's commands from Python), Model.action_of and Model.codegen: each
# checked by mathematics or physics (SymPy, a finite difference, a closed
# form, the compiled code's right-hand side), then against the command line
# on the same input.
import ctypes
import math
import os
import shutil
import subprocess

import pytest

import qdot
from conftest import EXAMPLES
from test_commands import BUILD, cli, model_file

sympy = pytest.importorskip("sympy")


def qdot_out(*args):
    """What `qdot ARGS` prints (skip without a build)."""
    exe = os.path.join(BUILD, "qdot")
    if not os.access(exe, os.X_OK):
        pytest.skip("no build/qdot to compare with")
    return subprocess.run([exe, *args], capture_output=True, text=True, check=True).stdout


def test_diff_is_sympys_derivative():
    f = "sin(x)*y^2 + x^3*exp(-x*y) + sqrt(x^2 + y^2)"
    x, y = sympy.symbols("x y")
    ref = sympy.sin(x) * y**2 + x**3 * sympy.exp(-x * y) + sympy.sqrt(x**2 + y**2)
    d = qdot.diff(f, "x", "y")
    assert sympy.simplify(d.sympy() - sympy.diff(ref, x, y)) == 0
    # a central finite difference of the first derivative at (0.7, -1.3)
    d1, h = qdot.diff(f, "x").sympy(), 1e-5
    fd = (ref.subs({x: 0.7 + h, y: -1.3}) - ref.subs({x: 0.7 - h, y: -1.3})) / (2 * h)
    assert float(d1.subs({x: 0.7, y: -1.3})) == pytest.approx(float(fd), rel=1e-8)
    assert str(d) == qdot_out("diff", f, "x", "y").strip()


def test_diff_by_a_rate():
    # d/dr' of r'^2 x + sin(r) is 2 r' x: r' is a symbol of its own
    d = qdot.diff("r'^2*x + sin(r)", "r'")
    assert str(d) == "2*r'*x" == qdot_out("diff", "r'^2*x + sin(r)", "r'").strip()
    with pytest.raises(qdot.ModelError, match="does not occur") as err:
        qdot.diff("x^2", "z")
    assert err.value.file == "<variable>" and "rate" in err.value.hint


def test_expand_and_simplify_are_identities():
    a, b, x = sympy.symbols("a b x")
    e = qdot.expand("(a + b)^3")
    assert sympy.expand(e.sympy() - (a + b)**3) == 0
    assert e == qdot.expand("(b + a)^3")  # one canonical form
    assert str(qdot.simplify("sin(x)^2 + cos(x)^2")) == "1"
    s = qdot.simplify("(x^2 - 1)/(x - 1)")
    assert sympy.simplify(s.sympy() - (x + 1)) == 0
    for fn, name, text in ((qdot.expand, "expand", "(a + b)^3"),
                           (qdot.simplify, "simplify", "(x^2 - 1)/(x - 1)")):
        assert str(fn(text)) == qdot_out(name, text).strip()


def test_a_power_too_large_to_expand_is_said():
    # docs/language.md: a power whose expansion would exceed 64 MiB stays a
    # power; it is said (issue 33), as the CLI says it, never handed back silently
    with pytest.warns(UserWarning, match=r"\(x \+ y\)\^100000 is kept as a power"):
        e = qdot.expand("(x + y)^100000*z + z")
    assert str(e) == "z + z*(x + y)^100000"
    r = subprocess.run([os.path.join(BUILD, "qdot"), "expand", "(x + y)^100000"],
                       capture_output=True, text=True)
    assert r.returncode == 0 and r.stdout == "(x + y)^100000\n"
    assert "(x + y)^100000 is kept as a power: its expansion would exceed 64 MiB" in r.stderr
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # nothing said when all is expanded
        assert str(qdot.expand("(x + y)^2")) == "2*x*y + x^2 + y^2"
    r = subprocess.run([os.path.join(BUILD, "qdot"), "simplify", "x^2 + 2*x*y + y^2"],
                       capture_output=True, text=True)
    assert r.stdout == "(x + y)^2\n" and r.stderr == ""  # simplify factors on purpose


@pytest.mark.parametrize("fmt", ["text", "latex", "c", "sympy"])
def test_print_expr_formats_as_the_cli(fmt):
    text = "sin(th)*l^2/2 + r'^2 + exp(2)"
    assert qdot.print_expr(text, fmt) == qdot_out("print", text, "--format", fmt).strip()


def test_parse_errors_are_located():
    with pytest.raises(qdot.ModelError) as err:
        qdot.parse("x +")
    assert (err.value.file, err.value.line, err.value.col) == ("<expression>", 1, 4)
    with pytest.raises(TypeError):
        qdot.expand(3)
    with pytest.raises(ValueError):
        qdot.print_expr("x", "fortran")


OSC = "coordinates x\nparameters m = 2, w = 3\nT = m/2*x'^2\nV = m/2*w^2*x^2\n"


def test_action_of_true_and_trial_paths(tmp_path):
    # x = cos(w t) is a true path: L = -(m w^2/2) cos(2 w t), so
    # S = -(m w/4) sin(2 w T) over [0, T], and the first variation is 0
    m = qdot.Model(OSC)
    T = 0.4
    true = m.action_of("x = cos(w*t)", (0, T))
    assert true.action == pytest.approx(-(2 * 3 / 4) * math.sin(2 * 3 * T), rel=1e-10)
    assert abs(true.first_variation) < 1e-9
    # x = 1 - (w t)^2/2: the residual m (x'' + w^2 x) = m w^4 t^2/2 - ... is not 0
    trial = m.action_of({"x": "1 - (w*t)^2/2"}, "0:0.4")
    w, mm = 3.0, 2.0
    res2 = sympy.integrate((mm * (-w**2 + w**2 * (1 - (w * sympy.Symbol("t"))**2 / 2)))**2,
                           (sympy.Symbol("t"), 0, T))
    assert trial.first_variation == pytest.approx(math.sqrt(float(res2)), rel=1e-10)
    path = model_file(tmp_path, OSC)
    out = qdot.Model.load(path).action_of("x = cos(w*t)", "0:0.4")
    ref = cli("action-of", path, "--path", "x = cos(w*t)", "--t", "0:0.4")
    assert list(out.json) == list(ref) and out.model == ref["model"]
    assert out.action == pytest.approx(ref["action"], rel=1e-14)
    with pytest.raises(qdot.ModelError, match="range"):
        m.action_of("x = t", "1")
    with pytest.raises(qdot.ArgumentError, match="after"):
        m.action_of("x = t", (1, 0))


def test_codegen_compiles_to_the_equations(tmp_path):
    cc = shutil.which("cc")
    src = os.path.join(EXAMPLES, "double_pendulum.qd")
    model = qdot.Model.load(src)
    code = model.codegen()
    assert code.prefix == "double_pendulum"
    # the files `qdot codegen` writes, byte for byte
    qdot_out("codegen", src, "-o", str(tmp_path / "cli"))
    for name, text in code.files.items():
        assert (tmp_path / "cli" / name).read_text() == text
    if not cc:
        pytest.skip("no C compiler")
    paths = code.save(str(tmp_path / "py"))
    so = str(tmp_path / "py" / "dp.so")
    subprocess.run([cc, "-O1", "-shared", "-fPIC", "-o", so, paths[0], "-lm"], check=True)
    lib = ctypes.CDLL(so)
    D = ctypes.c_double
    y = (D * 4)(0.5, -0.2, 0.3, 0.1)
    par = (D * 5)(*model.params.values())  # m1, m2, l1, l2, g in the model's order
    dydt = (D * 4)()
    assert lib.double_pendulum_rhs(D(0), y, par, dydt) == 0
    ref = model.compile()(0.0, list(y))
    assert list(dydt) == pytest.approx(list(ref), rel=1e-12, abs=1e-14)
    # one rod alone (theta2 = theta1, both at rest): the energy is T + V
    E = lib.double_pendulum_energy
    E.restype = D
    e = E(D(0), (D * 4)(0.5, 0.5, 0, 0), par)
    assert e == pytest.approx(-9.81 * (2 * math.cos(0.5) + math.cos(0.5)), rel=1e-12)
    with pytest.raises(ValueError, match="C identifier"):
        model.codegen(prefix="2x")


def test_eom_at_a_state_is_the_clis_request():
    # the double pendulum at rest at theta1 = 0.3, theta2 = 0 (Goldstein
    # ch. 1 Ex. 22): M = [[2, cos 0.3], [cos 0.3, 1]], the forcing
    # (-(m1 + m2) g l1 sin 0.3, 0)
    path = os.path.join(EXAMPLES, "double_pendulum.qd")
    e = qdot.Model.load(path).eom()
    j = e.json(at={"theta1": 0.3})
    assert j["mass_matrix"][0][1] == pytest.approx(math.cos(0.3), rel=1e-15)
    assert j["forcing"] == pytest.approx([-2 * 9.81 * math.sin(0.3), 0], rel=1e-15)
    assert j == cli("eom", path, "--at", "theta1=0.3")
    with pytest.raises(qdot.ModelError, match="unknown name") as err:
        e.json(at="theta3=1")
    assert err.value.file == "at"
