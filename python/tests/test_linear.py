# python/tests/test_linear.py - Model.equilibria and Model.modes take the
# point and search the places `qdot equilibria` and `qdot modes` do (the same
# library calls): each test checks the physics, then the JSON of the command
# on the same model.
#   The double pendulum (examples/double_pendulum.qd; Goldstein ch. 1 Ex. 22,
#   seed 002_3e07e211eebc00b9.txt): at rest at (theta1, theta2) the
#   generalized forces are -(m1 + m2) g l1 sin(theta1) and -m2 g l2 sin(theta2).
#   The linear triatomic molecule (examples/symmetric_triatomic.qd; Desloge
#   ch. 66, seed-desloge-B.md): w^2 = 0, k/m (even under the mirror) and
#   (k/m)(1 + 2m/M) (odd).
import math
import os
import subprocess
import warnings

import numpy as np
import pytest

import qdot
from conftest import EXAMPLES
from test_commands import BUILD, cli, same

DP = os.path.join(EXAMPLES, "double_pendulum.qd")
TRI = os.path.join(EXAMPLES, "symmetric_triatomic.qd")


@pytest.fixture
def dp():
    return qdot.Model.load(DP)


def test_modes_choice_is_the_librarys_and_the_clis(dp):
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # an equilibrium: no note
        modes = dp.modes()
    assert modes.about == {"theta1": 0.0, "theta2": 0.0}
    assert modes.equilibrium.kind == "minimum" and modes.residual < 1e-12
    assert "nearest the model's initial state" in modes.choice_note
    # w^2 = (g/l)(2 -+ sqrt 2) for equal masses and lengths
    assert [m.omega2 for m in modes] == pytest.approx(
        [9.81 * (2 - math.sqrt(2)), 9.81 * (2 + math.sqrt(2))], rel=1e-12)
    assert modes.verdict == "stable" and modes.choice.others == 3
    same(modes.json, cli("modes", DP))


def test_modes_at_equilibrium_n_is_the_listed_one(dp):
    listed = dp.equilibria()
    modes = dp.modes(at_equilibrium=2)
    assert modes.about == listed[1].q and listed[1].kind == "saddle"
    # one rod up: one stiffness negative, one positive
    assert sum(m.omega2 < 0 for m in modes) == 1 and modes.stable == 0
    same(modes.json, cli("modes", DP, "--at-equilibrium", "2"))
    with pytest.raises(qdot.ArgumentError, match="there are 4 equilibria"):
        dp.modes(at_equilibrium=9)
    with pytest.raises(ValueError, match="either about or at_equilibrium"):
        dp.modes(about={"theta1": 0}, at_equilibrium=1)


def test_modes_off_equilibrium_warn_with_the_clis_note(dp):
    with pytest.warns(UserWarning, match="not an equilibrium") as rec:
        modes = dp.modes(about={"theta1": 0.1})
    # the largest generalized force at rest: (m1 + m2) g l1 sin(0.1)
    assert modes.residual == pytest.approx(2 * 9.81 * math.sin(0.1), rel=1e-12)
    assert modes.equilibrium is None and modes.choice_note is None
    note = str(rec[0].message)[len("modes: "):]
    exe = os.path.join(BUILD, "qdot")
    if not os.access(exe, os.X_OK):
        pytest.skip("no build/qdot to compare with")
    text = subprocess.run([exe, "modes", DP, "--about", "theta1=0.1"], capture_output=True,
                          text=True, check=True).stdout
    assert "note: " + note in text
    with pytest.warns(UserWarning):
        same(dp.modes(about="theta1=0.1").json, cli("modes", DP, "--about", "theta1=0.1"))


def test_modes_initial_in_normal_coordinates(dp):
    modes = dp.modes(initial={"theta1": 0.1})
    # Q_j = a_j^T M0 (q - q0): M0 = [[2, 1], [1, 1]] at the bottom
    M0 = np.array([[2.0, 1.0], [1.0, 1.0]])
    for j, mode in enumerate(modes):
        a = np.array([mode.shape["theta1"], mode.shape["theta2"]])
        assert modes.modes[j].Q0 == pytest.approx(a @ M0 @ np.array([0.1, 0]), rel=1e-12)
    same(modes.json, cli("modes", DP, "--initial", "theta1=0.1"))


def test_modes_symmetry_labels_the_triatomic_modes():
    tri = qdot.Model.load(TRI)
    about = {"x1": -1, "x2": 0, "x3": 1}
    modes = tri.modes(about=about, symmetry=True)
    m, M, k = 1.0, 3.0, 2.0
    assert [x.omega2 for x in modes] == pytest.approx([0, k / m, k / m * (1 + 2 * m / M)],
                                                      abs=1e-12)
    assert modes.symmetry.group == "Cs" and modes.symmetry.order == 2
    # the symmetric stretch is the one even mode (A'); the translation and
    # the antisymmetric stretch are odd (A'')
    assert dict(modes.symmetry.multiplicities) == {"A'": 1, "A''": 2}
    same(modes.json, cli("modes", TRI, "--about", "x1=-1, x2=0, x3=1", "--symmetry"))


def test_modes_symmetry_none_is_a_warning(dp):
    with pytest.warns(UserWarning, match="no symmetry"):
        modes = dp.modes(symmetry=True)
    assert "symmetry" not in modes.json


def test_equilibria_guess_and_box_as_the_cli(dp):
    near = dp.equilibria(guess={"theta1": 3, "theta2": 0.2})
    # Newton from near the (pi, 0) saddle reaches it
    assert near.method == "newton" and len(near) == 1
    assert near[0].q["theta1"] == pytest.approx(math.pi, rel=1e-12)
    assert abs(near[0].q["theta2"]) < 1e-12 and near[0].kind == "saddle"
    same(near.json, cli("equilibria", DP, "--guess", "theta1=3, theta2=0.2"))
    # the old name of the same thing still works, with a warning (issue 31)
    with pytest.warns(DeprecationWarning, match="guess"):
        old = dp.equilibria(near={"theta1": 3, "theta2": 0.2})
    same(old.json, near.json)
    box = dp.equilibria(box={"theta1": (-1, 1), "theta2": "-1:1"})
    assert box.method == "multistart" and [e.kind for e in box] == ["minimum"]
    same(box.json, cli("equilibria", DP, "--box", "theta1=-1:1, theta2=-1:1"))
    with pytest.raises(qdot.ModelError, match="unknown name 'thetaa'") as err:
        dp.equilibria(guess="theta1=0.1, thetaa=2")
    assert (err.value.file, err.value.col) == ("guess", 13)
    with pytest.raises(TypeError):
        dp.equilibria(box={"theta1": 3})


DISK = os.path.join(EXAMPLES, "rolling_disk_speeds.qd")


def test_speeds_modes_of_the_rolling_disk():
    # the thin disk rolling upright at spin W (Neimark and Fufaev ch. III;
    # Routh, Advanced Rigid Dynamics art. 244): the lean's root
    # s^2 = -(4/5)(3 W^2 - g/a), stable iff W^2 > g/(3a)
    disk = qdot.Model.load(DISK)
    a, g = disk.params["r"], disk.params["g"]
    fast = disk.modes(about={"u2": 6})
    assert max(fast.eigenvalues.imag) == pytest.approx(math.sqrt(0.8 * (3 * 36 - g / a)),
                                                       rel=1e-10)
    assert fast.verdict == "stable" and fast.about["u2"] == 6 and len(fast) == 0
    slow = disk.modes(about="u2=2")
    assert max(slow.eigenvalues.real) == pytest.approx(math.sqrt(0.8 * (g / a - 12)), rel=1e-10)
    assert slow.stable == 0 and slow.json["stable"] is False
    same(fast.json, cli("modes", DISK, "--about", "u2=6"))
    with pytest.raises(ValueError, match="not available for a model with speeds"):
        disk.modes(symmetry=True)
    with pytest.raises(qdot.ModelError, match="unknown name 'theta'"):
        disk.modes(about="theta=1")


def test_speeds_equilibria_of_the_rolling_disk():
    # at rest the disk stands upright or upside down (q2 = 0, pi), anywhere
    # and at any heading and spin angle: x, y, q1, q3 free
    eqs = qdot.Model.load(DISK).equilibria()
    assert [e.exact["q2"] for e in eqs] == ["0", "pi"] and eqs.free == ["x", "y", "q1", "q3"]
    assert all(e.kind is None and e.residual < 1e-12 for e in eqs)
    same(eqs.json, cli("equilibria", DISK))
    with pytest.raises(ValueError, match="guess is not available"):
        qdot.Model.load(DISK).equilibria(guess="q2=0.1")


def test_constrained_modes_on_the_manifold():
    # the pendulum in (x, y) with x^2 + y^2 = l^2 kept by a multiplier:
    # w^2 = g/l about the bottom, and the rod's tension m g there
    # (lambda = -m g/(2 l) for the constraint written x^2 + y^2 - l^2;
    # Britannica (1911) Dynamics sec. 3 (28)-(30), seed-goldstein-britannica.md B23)
    path = os.path.join(EXAMPLES, "pendulum_cartesian.qd")
    pend = qdot.Model.load(path)
    p = pend.params
    modes = pend.modes()
    assert modes.about["y"] == pytest.approx(-p["l"], rel=1e-12)
    assert [m.omega2 for m in modes] == pytest.approx([p["g"] / p["l"]], rel=1e-12)
    assert modes.independent == ["x"] and modes.verdict == "stable"
    # at rest at the bottom the tension is S = m g: lambda_rod = -S/(2 l)
    assert modes.multipliers.lambda_rod == pytest.approx(-p["m"] * p["g"] / (2 * p["l"]),
                                                         rel=1e-12)
    same(modes.json, cli("modes", path))
    with pytest.raises(qdot.ArgumentError, match="choose other independent coordinates"):
        pend.modes(independent="y")
    with pytest.raises(ValueError, match="not yet on the constraint manifold"):
        pend.modes(symmetry=True)
    with pytest.raises(ValueError, match="keeps no constraints"):
        qdot.Model.load(DP).modes(independent="theta1")


def test_modes_scan_finds_the_hoops_threshold():
    # the bead on a hoop spinning at omega (Desloge ch. 50 ex. 1 eq. 39,
    # seed 000): the bottom's stiffness m a^2 (g/a - omega^2) changes sign at
    # omega = sqrt(g/a); below it w^2 = g/a - omega^2
    path = os.path.join(EXAMPLES, "bead_spinning_hoop.qd")
    hoop = qdot.Model.load(path)
    g, a = hoop.params["g"], hoop.params["a"]
    s = hoop.modes(scan="omega=1:6", about={"theta": 0}, steps=50)
    (t,) = s.transitions
    assert t.omega == pytest.approx(math.sqrt(g / a), rel=1e-12)
    assert (t["from"], t.to) == ("stable", "unstable")
    assert s.samples[0].min_omega2 == pytest.approx(g / a - 1, rel=1e-12)
    same(s.json, cli("modes", path, "--scan", "omega=1:6", "--about", "theta=0",
                     "--steps", "50"))
    assert hoop.modes(scan=("omega", 1, 6), about="theta=0", steps=50).json == s.json
    with pytest.raises(qdot.ModelError, match="unknown name") as err:
        hoop.modes(scan="omega=1:6", about="thta=0")
    assert err.value.file == "about"
    with pytest.raises(qdot.ArgumentError, match="assumed positive"):
        hoop.modes(scan="omega=-1:2")
    with pytest.raises(ValueError, match="steps is the number of steps of scan"):
        hoop.modes(steps=5)


def test_speeds_modes_scan_finds_the_disks_threshold():
    # the disk rolling upright is stable iff W^2 > g/(3a) (Neimark and
    # Fufaev ch. III): the scan along the spin u2 crosses at sqrt(g/(3a)),
    # where the lean's root is double (s = 0 twice: its eigenvalues move as
    # the square root of the error, so the verdict's place is good to ~1e-9,
    # the CLI's check_speeds_linear_cli allows 1e-8)
    disk = qdot.Model.load(DISK)
    a, g = disk.params["r"], disk.params["g"]
    s = disk.modes(about="u2=6", scan="u2=1:8")
    (t,) = s.transitions
    assert t.u2 == pytest.approx(math.sqrt(g / (3 * a)), rel=1e-8)
    assert (t["from"], t.to) == ("unstable", "stable")
    same(s.json, cli("modes", DISK, "--about", "u2=6", "--scan", "u2=1:8"))
    with pytest.raises(qdot.ArgumentError, match="not a parameter, coordinate or speed"):
        disk.modes(scan="t=0:1")
