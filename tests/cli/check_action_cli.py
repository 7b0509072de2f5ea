#!/usr/bin/env python3
"""End-to-end checks of `qdot action`.

    python3 tests/cli/check_action_cli.py --build BUILD_DIR

Expected values are textbook results, not output of the code under test
(Desloge ch. 79, seed 004 / seed-desloge-D.md; Goldstein sec. 10.6-10.8,
seed 002):
  - the pendulum (examples/action_pendulum.qd, _rotation.qd): libration
    J = 16 m sqrt(g l^3) [E(k) - (1 - k^2) K(k)], k = sin(theta0/2), rotation
    J = 4 E(kr) sqrt(2 m l^2 (E + m g l)), K and E by the AGM here; the
    period 2 pi/omega against the return time `qdot simulate` measures with
    an event theta' = 0;
  - Kepler in polar coordinates (examples/kepler_polar.qd, through qd_hj):
    J_r + J_theta = 2 pi k sqrt(m/(-2E)), both frequencies 2 pi/T with
    T = 2 pi sqrt(m a^3/k), a = -k/(2E), the 1 : 1 degeneracy named;
  - Kepler in spherical coordinates (a model written here): J_r + J_theta +
    J_phi the same sum, the three frequencies equal, three 1 : 1 pairs;
  - a model given by H takes its momenta in --at (or its velocities, q' =
    dH/dp): the oscillator's J = 2 pi E/omega either way; Kepler's H in r,
    theta needs --angle theta (theta is in no sin or cos), then the Kepler sum;
  - Kepler in parabolic coordinates (examples/hj_stark.qd at F = 0, Liouville):
    the same sum and three equal frequencies; F = 0.1 splits them;
  - the quartic oscillator V = k x^4: J by the Beta function, omega from
    H homogeneous of degree 4/3 in J (no closed form claimed);
  - the Morse well: J = (2 pi/a) sqrt(2 m D) (1 - sqrt(1 - E/D)) and
    omega = a sqrt(2 D/m) sqrt(1 - E/D);
  - the anisotropic oscillator (examples/action_anisotropic.qd): J = 2 pi
    E_i/omega_i, no degeneracy at ky = 2 kx, 1 : 2 at ky = 4 kx;
  - the angle variables (0 at the lower turning point): at the state `qdot
    simulate` reaches after a time t every J is unchanged and every angle has
    moved on by omega t (mod 2 pi) (Goldstein sec. 10.6: w = nu t + beta), for
    Kepler in polar and spherical coordinates, the anisotropic oscillator and
    the rotating pendulum; the oscillator through its centre is at pi/2 or
    3 pi/2 by its sense;
  - adiabatic invariance (examples/action_pendulum_lengthening.qd,
    l = l0 (1 + eps t), Goldstein sec. 10.7 / Desloge ch. 79): the action of
    the pendulum frozen at t = 0 and at t = 250 (l 1.5 times longer) agree to
    1e-3 while its energy E + m g l changes by more than 10%;
  - errors, exit 2: a separatrix (E = m g l), rest at the bottom, an unbounded
    coordinate (Desloge ch. 78's H = p^2 - q), Kepler's radial orbit (r reaches
    the centre, a collision: no turning point), a non-separable quartic
    coupling (the hint names qdot poincare), a bad option, H depending on t
    (the hint names the adiabatic invariant), a damped oscillator.
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


def check(name, ok, detail=""):
    if ok:
        results["passed"] += 1
    else:
        results["failed"] += 1
        print("FAIL %s %s" % (name, detail))


def close(name, got, want, tol):
    check(name, abs(got - want) <= tol * abs(want), "got %.17g want %.17g" % (got, want))


def qdot(build, *args):
    return subprocess.run([str(Path(build).resolve() / "qdot")] + [str(a) for a in args],
                          capture_output=True, text=True, timeout=120)


def action(build, *args):
    r = qdot(build, "action", *args, "--format", "json")
    if r.returncode != 0:
        raise RuntimeError("qdot action %s: %s" % (" ".join(map(str, args)), r.stderr))
    return json.loads(r.stdout)


def ellip_KE(k):
    """K(k), E(k) by the arithmetic-geometric mean (A&S 17.6.3-4)."""
    a, b, c = 1.0, math.sqrt(1 - k * k), k
    s, pw = c * c / 2, 0.5
    while c > 1e-17:
        a, b, c = (a + b) / 2, math.sqrt(a * b), (a - b) / 2
        pw *= 2
        s += pw * c * c
    K = math.pi / (2 * a)
    return K, K * (1 - s)


def coord(res, name):
    return next(c for c in res["coordinates"] if c["coordinate"] == name)


def pendulum(build):
    m, l, g = 1.0, 1.0, 9.81
    for th0 in (0.2, 1.0, 2.9):
        res = action(build, EX / "action_pendulum.qd", "--at", "theta=%r, theta'=0" % th0)
        c = coord(res, "theta")
        k = math.sin(th0 / 2)
        K, E = ellip_KE(k)
        check("libration kind", c["kind"] == "libration")
        close("libration J (theta0 %g)" % th0, c["J"],
              16 * m * math.sqrt(g * l ** 3) * (E - (1 - k * k) * K), 1e-11)
        close("libration period", 2 * math.pi / c["omega"], 4 * K * math.sqrt(l / g), 1e-11)
    res = action(build, EX / "action_pendulum_rotation.qd")
    c = coord(res, "theta")
    En = res["energy"]
    cc = 2 * m * l * l * (En + m * g * l)
    K, E = ellip_KE(math.sqrt(2 * m * g * l / (En + m * g * l)))
    check("rotation kind", c["kind"] == "rotation")
    close("rotation J", c["J"], 4 * E * math.sqrt(cc), 1e-12)
    close("rotation period", 2 * math.pi / c["omega"], 4 * K * m * l * l / math.sqrt(cc), 1e-11)


def simulated_period(build, model, event):
    """The time of the first event row of `qdot simulate` from the initial state."""
    r = qdot(build, "simulate", model, "--t-end", 10, "--rtol", "1e-13", "--event", event)
    rows = [row for row in csv.DictReader(io.StringIO(r.stdout)) if row["event"] == "1"]
    return float(rows[0]["t"])


def period_by_simulation(build):
    """Each coordinate's 2 pi/omega against the return `qdot simulate` times:
    the pendulum both ways, and with two degrees of freedom Kepler's r (back
    at the apocentre r = 1) and theta (a turn), the anisotropic oscillator's
    x and y (back at the turning point, or through 0 the same way)."""
    for model, q, event in ((EX / "action_pendulum.qd", "theta", "theta' = 0, theta > 0"),
                            (EX / "action_pendulum_rotation.qd", "theta", "theta = 2*pi"),
                            (EX / "kepler_polar.qd", "r", "r' = 0, r > 0.8"),
                            (EX / "kepler_polar.qd", "theta", "theta = 2*pi"),
                            (EX / "action_anisotropic.qd", "x", "x' = 0, x > 0"),
                            (EX / "action_anisotropic.qd", "y", "y = 0, y' > 0")):
        res = action(build, model)
        close("period of %s by simulate (%s)" % (q, model.name),
              simulated_period(build, model, event), 2 * math.pi / res["frequencies"][q], 1e-10)


def kepler(build):
    m, k = 1.3, 4.0
    res = action(build, EX / "kepler_polar.qd")
    E = res["energy"]
    a = -k / (2 * E)
    close("Kepler sum J", sum(res["actions"].values()), 2 * math.pi * k * math.sqrt(m / (-2 * E)),
          1e-11)
    for q, w in res["frequencies"].items():
        close("Kepler omega_" + q, w, 1 / math.sqrt(m * a ** 3 / k), 1e-10)
    check("Kepler degeneracy", [d["ratio"] for d in res["degeneracies"]] == [[1, 1]],
          str(res["degeneracies"]))
    check("Kepler H(J)", res["H_of_J"] and abs(res["H_of_J"]["c"] - 2 * math.pi ** 2 * m * k * k)
          < 1e-9 * 2 * math.pi ** 2 * m * k * k, str(res["H_of_J"]))


def kepler_spherical(build):
    """In spherical coordinates: J_r + J_theta + J_phi, three equal frequencies."""
    m, k = 0.8, 2.5
    with tempfile.TemporaryDirectory() as tmp:
        model = Path(tmp) / "kepler3.qd"
        model.write_text("coordinates r, theta, phi\nparameters m = 0.8, k = 2.5\n"
                         "particle m at r*(sin(theta)*cos(phi), sin(theta)*sin(phi), "
                         "cos(theta))\nV = -k/r\n")
        res = action(build, model, "--at", "r=1.2, theta=1.1, r'=-0.3, theta'=0.9, phi'=1.1")
    E = res["energy"]
    a = -k / (2 * E)
    close("spherical Kepler sum J", sum(res["actions"].values()),
          2 * math.pi * k * math.sqrt(m / (-2 * E)), 1e-11)
    for q, w in res["frequencies"].items():
        close("spherical Kepler omega_" + q, w, 1 / math.sqrt(m * a ** 3 / k), 1e-10)
    check("three 1 : 1", [d["ratio"] for d in res["degeneracies"]] == [[1, 1]] * 3,
          str(res["degeneracies"]))


def given_by_h(build):
    """A model given by H takes its momenta in --at: the oscillator
    H = p^2/(2m) + k q^2/2 at q = 1, p = 0.5 has E = 0.625, J = 2 pi E/omega."""
    with tempfile.TemporaryDirectory() as tmp:
        model = Path(tmp) / "h.qd"
        model.write_text("coordinates q\nmomenta p\nparameters m = 2, k = 8\n"
                         "H = p^2/(2*m) + k*q^2/2\n")
        by_p = action(build, model, "--at", "q=1, p=0.5")
        by_v = action(build, model, "--at", "q=1, q'=0.25")
    E = 0.5 ** 2 / (2 * 2) + 8 * 1 ** 2 / 2
    close("H model energy", by_p["energy"], E, 1e-15)
    close("H model J", by_p["actions"]["q"], 2 * math.pi * E / 2, 1e-12)
    close("q' = p/m gives the same J", by_v["actions"]["q"], by_p["actions"]["q"], 1e-14)


def kepler_given_by_h(build):
    """Kepler's H in r, theta: theta enters H nowhere, so only --angle says
    it is an angle; then J_r + J_theta = 2 pi k sqrt(m/(-2E)) and the two
    frequencies are equal (Goldstein eq. 10.137); without it, an error that
    names --angle."""
    m, k = 1.3, 4.0
    with tempfile.TemporaryDirectory() as tmp:
        model = Path(tmp) / "kepler_h.qd"
        model.write_text("coordinates r, theta\nmomenta p_r, p_theta\nparameters m = 1.3, k = 4\n"
                         "H = p_r^2/(2*m) + p_theta^2/(2*m*r^2) - k/r\n")
        at = "r=1, theta=0.3, p_r=0.52, p_theta=1.95"
        r = qdot(build, "action", model, "--at", at)
        check("cyclic theta without --angle", r.returncode == 2 and "--angle" in r.stderr,
              "exit %d: %s" % (r.returncode, r.stderr))
        res = action(build, model, "--at", at, "--angle", "theta")
        r = qdot(build, "action", model, "--at", at, "--angle", "k")
        check("--angle k refused", r.returncode == 2 and "parameter" in r.stderr, r.stderr)
    E = res["energy"]
    a = -k / (2 * E)
    close("Kepler H sum J", sum(res["actions"].values()), 2 * math.pi * k * math.sqrt(m / (-2 * E)),
          1e-11)
    for q, w in res["frequencies"].items():
        close("Kepler H omega_" + q, w, 1 / math.sqrt(m * a ** 3 / k), 1e-10)


def parabolic(build):
    """Kepler in parabolic coordinates (examples/hj_stark.qd at F = 0, the
    Liouville form of Landau-Lifshitz §48 problem 2; phi named an angle):
    J_xi + J_eta + J_phi = 2 pi k sqrt(m/(-2E)), the three frequencies equal
    and H = -2 pi^2 m k^2/(sum J)^2, as in polar coordinates.  The field
    F = 0.1 lifts the degeneracy (the Stark effect): no pair is named."""
    m, k = 1.0, 1.0
    at = "xi=1, eta=1, p_xi=0.3, p_eta=-0.2, p_phi=0.4"
    res = action(build, EX / "hj_stark.qd", "--set", "F=0", "--angle", "phi", "--at", at)
    E = res["energy"]
    a = -k / (2 * E)
    close("parabolic Kepler sum J", sum(res["actions"].values()),
          2 * math.pi * k * math.sqrt(m / (-2 * E)), 1e-11)
    for q, w in res["frequencies"].items():
        close("parabolic Kepler omega_" + q, w, 1 / math.sqrt(m * a ** 3 / k), 1e-10)
    check("parabolic three 1 : 1", [d["ratio"] for d in res["degeneracies"]] == [[1, 1]] * 3,
          str(res["degeneracies"]))
    close("parabolic J_phi = 2 pi |p_phi|", res["actions"]["phi"], 2 * math.pi * 0.4, 1e-13)
    res = action(build, EX / "hj_stark.qd", "--angle", "phi", "--at", at)
    check("Stark field splits the frequencies", res["degeneracies"] == [] and
          abs(res["frequencies"]["xi"] / res["frequencies"]["eta"] - 1) > 1e-2,
          str(res["frequencies"]))


def quartic(build):
    """V = k x^4: J = 4 sqrt(2 m E) A (1/4) B(1/4, 3/2), A = (E/k)^(1/4), and,
    H being homogeneous of degree 4/3 in J, omega = 2 pi (4/3) E / J."""
    m, k = 1.5, 0.7
    with tempfile.TemporaryDirectory() as tmp:
        model = Path(tmp) / "quartic.qd"
        model.write_text("coordinates x\nparameters m = 1.5, k = 0.7\n"
                         "T = m/2*x'^2\nV = k*x^4\n")
        res = action(build, model, "--at", "x=0.4, x'=1.3")
    E = m / 2 * 1.3 ** 2 + k * 0.4 ** 4
    beta = math.gamma(0.25) * math.gamma(1.5) / math.gamma(1.75)
    J = 4 * math.sqrt(2 * m * E) * (E / k) ** 0.25 * beta / 4
    close("quartic J", res["actions"]["x"], J, 1e-12)
    close("quartic omega", res["frequencies"]["x"], 2 * math.pi * 4 / 3 * E / J, 1e-11)
    check("quartic H(J) not linear", res["H_of_J"] is None, str(res["H_of_J"]))


def morse(build):
    """The Morse well V = D (1 - e^(-a x))^2, asymmetric and not polynomial:
    oint p dq in closed form (the substitution u = e^(-a x)) is
    J = (2 pi/a) sqrt(2 m D) (1 - sqrt(1 - E/D)), so
    omega = 2 pi dE/dJ = a sqrt(2 D/m) sqrt(1 - E/D)."""
    m, D, a = 1.2, 3.0, 0.8
    with tempfile.TemporaryDirectory() as tmp:
        model = Path(tmp) / "morse.qd"
        model.write_text("coordinates x\nparameters m = 1.2, D = 3, a = 0.8\n"
                         "T = m/2*x'^2\nV = D*(1 - exp(-a*x))^2\n")
        res = action(build, model, "--at", "x=0.3, x'=1.5")
    E = m / 2 * 1.5 ** 2 + D * (1 - math.exp(-a * 0.3)) ** 2
    close("Morse J", res["actions"]["x"],
          2 * math.pi / a * math.sqrt(2 * m * D) * (1 - math.sqrt(1 - E / D)), 1e-12)
    close("Morse omega", res["frequencies"]["x"],
          a * math.sqrt(2 * D / m) * math.sqrt(1 - E / D), 1e-11)


KEPLER3 = ("coordinates r, theta, phi\nparameters m = 0.8, k = 2.5\n"
           "particle m at r*(sin(theta)*cos(phi), sin(theta)*sin(phi), cos(theta))\n"
           "V = -k/r\ninitial r = 1.2, theta = 1.1, phi = 0.2, r' = -0.3, theta' = 0.9, "
           "phi' = 1.1\n")


def angles_after(build, model, coords, t):
    """The actions and angles at the initial state and at the state `qdot
    simulate` reaches at t: J unchanged, each angle moved on by omega t."""
    r0 = action(build, model)
    r = qdot(build, "simulate", model, "--t-end", t, "--dt", t, "--method", "dop853",
             "--rtol", "1e-13")
    end = list(csv.DictReader(io.StringIO(r.stdout)))[-1]
    at = ", ".join("%s=%s, %s'=%s" % (q, end[q], q, end[q + "'"]) for q in coords)
    r1 = action(build, model, "--at", at)
    for q in coords:
        close("J_%s along the motion (%s)" % (q, Path(model).name), r1["actions"][q],
              r0["actions"][q], 1e-11)
        d = (r1["angles"][q] - r0["angles"][q] - r0["frequencies"][q] * t) / (2 * math.pi)
        check("angle_%s advances at omega_%s (%s)" % (q, q, Path(model).name),
              abs(d - round(d)) < 1e-11, "off by %g turns" % (d - round(d)))


def angles(build):
    with tempfile.TemporaryDirectory() as tmp:
        kepler3 = Path(tmp) / "kepler3.qd"
        kepler3.write_text(KEPLER3)
        angles_after(build, kepler3, ["r", "theta", "phi"], 1.3)
    angles_after(build, EX / "kepler_polar.qd", ["r", "theta"], 1.0)
    angles_after(build, EX / "action_anisotropic.qd", ["x", "y"], 2.3)
    angles_after(build, EX / "action_pendulum_rotation.qd", ["theta"], 0.9)
    # the oscillator through the centre moving right is a quarter turn on from x = -A
    res = action(build, EX / "action_anisotropic.qd", "--at", "x=0, x'=1, y=0, y'=-1")
    close("angle a quarter turn on", res["angles"]["x"], math.pi / 2, 1e-12)
    close("angle three quarters on", res["angles"]["y"], 3 * math.pi / 2, 1e-12)


def anisotropic(build):
    res = action(build, EX / "action_anisotropic.qd")
    # x = 1 at rest: E_x = 1/2; y' = 1 at y = 0: E_y = 1/2
    close("J_x", res["actions"]["x"], 2 * math.pi * 0.5 / 1, 1e-12)
    close("J_y", res["actions"]["y"], 2 * math.pi * 0.5 / math.sqrt(2), 1e-12)
    check("sqrt(2) is no degeneracy", res["degeneracies"] == [], str(res["degeneracies"]))
    res = action(build, EX / "action_anisotropic.qd", "--set", "ky=4")
    check("1 : 2 named", [d["ratio"] for d in res["degeneracies"]] == [[1, 2]],
          str(res["degeneracies"]))


def adiabatic(build):
    m, g, l0, eps, t1 = 1.0, 9.81, 1.0, 0.002, 250
    r = qdot(build, "simulate", EX / "action_pendulum_lengthening.qd", "--t-end", t1, "--dt", t1,
             "--method", "dop853", "--rtol", "1e-12")
    rows = list(csv.DictReader(io.StringIO(r.stdout)))
    first, last = rows[0], rows[-1]
    J, E = [], []
    for row, l in ((first, l0), (last, l0 * (1 + eps * t1))):
        res = action(build, EX / "action_pendulum.qd", "--set", "l=%r" % l, "--at",
                     "theta=%s, theta'=%s" % (row["theta"], row["theta'"]))
        J.append(res["actions"]["theta"])
        E.append(res["energy"] + m * g * l)
    close("adiabatic invariant J", J[1], J[0], 1e-3)
    check("energy not invariant", abs(E[1] - E[0]) > 0.1 * E[0], "E %s" % E)


def errors(build):
    with tempfile.TemporaryDirectory() as tmp:
        d78 = Path(tmp) / "d78.qd"
        d78.write_text("coordinates q\nmomenta p\nH = p^2 - q\n")
        quartic = Path(tmp) / "quartic.qd"
        quartic.write_text("coordinates x, y\nT = (x'^2 + y'^2)/2\n"
                           "V = (x^2 + y^2)/2 + x^2*y^2\n")
        # p enters beyond its square, not evenly, with no linear term: the hint
        # must not talk of a gyroscopic one (the relativistic oscillator, even
        # in p, is solved: tests/action/test_action.c)
        rel = Path(tmp) / "rel.qd"
        rel.write_text("coordinates x\nmomenta p\nH = exp(p) + x^2/2\ninitial x = 1\n")
        cases = [
            ("relativistic H", [rel], "beyond its square"),
            ("separatrix", [EX / "action_pendulum.qd", "--at", "theta=0, theta'=2*sqrt(9.81)"],
             "separatrix"),
            ("rest", [EX / "action_pendulum.qd", "--at", "theta=0, theta'=0"], "at rest"),
            ("unbounded", [d78, "--at", "q=1, q'=0.5"], "unbounded"),
            # Kepler's radial orbit: r reaches the centre, a pole of p_r^2 (was "separatrix")
            ("collision", [EX / "kepler_polar.qd", "--at", "r=1, r'=0.4, theta'=0"],
             "reaches r = "),
            ("not separable", [quartic, "--at", "x=0.3, y=0.2"], "qdot poincare"),
            ("bad option", [EX / "action_pendulum.qd", "--bogus"], "has no option"),
            ("time-dependent H", [EX / "action_pendulum_lengthening.qd"], "adiabatic invariant"),
            ("damping", [EX / "damped_oscillator.qd"], "dissipation"),
        ]
        for name, args, words in cases:
            r = qdot(build, "action", *args)
            check("error " + name, r.returncode == 2 and words in r.stderr and not r.stdout,
                  "exit %d: %s" % (r.returncode, r.stderr))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    args = ap.parse_args()
    for part in (pendulum, period_by_simulation, kepler, kepler_spherical, given_by_h,
                 kepler_given_by_h, parabolic, quartic,
                 morse, anisotropic, angles, adiabatic, errors):
        try:
            part(args.build)
        except Exception as exc:  # a crash or bad JSON is a failure, named
            check(part.__name__, False, "%s: %s" % (type(exc).__name__, exc))
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
