#!/usr/bin/env python3
"""tests/cli/check_lorentz_cli.py - `qdot lorentz` and `qdot collide` against Desloge
vol. 2 ch. 86-91 (seed 000_46d037099a6cfcd7.txt; /work/shared/reference/seed-desloge-D.md
C6, C7, T11, T13, T15, T16, T17, T21, pitfalls P7, P8, P11).

    python3 tests/cli/check_lorentz_cli.py --build BUILD_DIR

Expected values are closed forms from the seed, worked out here:
  - T11: v = (0, 0.5, 0) seen from V = (0.6, 0, 0) is (-0.6, 0.4, 0), gamma' = 5 sqrt(3)/6;
  - T13 (twin paradox, ch. 87 Ex. 1): the turnaround (t, x) = (5, 4) seen from S'' moving with
    -0.8 is x'' = 40/3, t'' = 41/3; B's proper time over 10 at speed 0.8 is 6;
  - T15 (ch. 87 Prob. 2): V = sqrt(3)/2 c with c = 2 (values written with c), the event
    (0, -2a) goes to x' = -4a, t' = 2 sqrt(3) a/c;
  - T21: the boost matrix for V = 0.6 and O^T g O = g;
  - P7: V (+) v and v (+) V differ in direction, same speed;
  - T16 (ch. 88 Prob. 1): 1 at +0.6 and 2 at -0.8 merge into M = sqrt(2496)/12, V = -23/55;
  - elastic, threshold (6 m c^2 for p p -> p p p pbar) and decay (p* of pi -> mu nu);
  - T17 (ch. 88 Prob. 2), examples/relativistic_rocket.qd: V(t) against
    c tanh((U/c) ln(M0/M)), M = M0 - k t, to 1e-9; U = c/2 at M/M0 = 1/4 gives 0.6 c;
    at c = 1e4 (Newtonian) V = U ln(M0/M);
  - every speed >= c, a missing --frame, --acceleration without --velocity: exit 2, a message.
"""
import argparse
import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "util"))
from clicheck import check, run, close, finish  # noqa: E402  (tests/util/clicheck.py)


def js(qdot, name, *args):
    rc, out, err = run(qdot, *args, "--format", "json")
    check(f"{name} rc", rc == 0, err)
    return json.loads(out) if rc == 0 else None


def vec(name, got, want, tol=1e-13):
    check(name, got is not None and len(got) == len(want)
          and all(close(a, b, tol) for a, b in zip(got, want)), f"{got} != {want}")


def lorentz(qdot):
    d = js(qdot, "T11", "lorentz", "--frame", "0.6, 0, 0", "--velocity", "0, 0.5, 0")
    if d:
        vec("T11 v'", d["velocity"], [-0.6, 0.4, 0])
        check("T11 gamma'", close(d["particle_gamma"], 5 * math.sqrt(3) / 6, 1e-14))
        check("T11 gamma", close(d["gamma"], 1.25, 1e-15))
        vec("T21 boost", [x for row in d["boost"] for x in row],
            [1.25, 0, 0, -0.75, 0, 1, 0, 0, 0, 0, 1, 0, -0.75, 0, 0, 1.25])
        check("T21 O^T g O = g", d["metric_error"] == 0)
    d = js(qdot, "T13", "lorentz", "--frame", "-0.8, 0, 0", "--event", "5, 4, 0, 0")
    if d:
        vec("T13 turnaround", d["event"], [41 / 3, 40 / 3, 0, 0])
    d = js(qdot, "T13 tau", "lorentz", "--proper-time", "0.8, 0, 0", "--t", "0:10")
    if d:
        check("T13 twin B ages 6", close(d["proper_time"], 6, 1e-13))
    d = js(qdot, "hyperbolic tau", "lorentz", "--proper-time", "t/sqrt(1 + t^2), 0, 0", "--t",
           "0:2")
    if d:
        check("hyperbolic motion tau = asinh 2", close(d["proper_time"], math.asinh(2), 1e-12))
    d = js(qdot, "T15", "lorentz", "--c", "2", "--frame", "sqrt(3)/2*c, 0, 0", "--event",
           "0, -2, 0, 0", "--contract", "4, 1, 0")
    if d:
        vec("T15 event", d["event"], [2 * math.sqrt(3) / 2, -4, 0, 0])
        vec("T15 rod 4a -> 2a, perpendicular kept", d["contracted"], [2, 1, 0])
    d = js(qdot, "P7", "lorentz", "--frame", "0.6, 0, 0", "--compose", "0, 0.5, 0")
    if d:
        a, b = d["composed"], d["composed_reverse"]
        vec("P7 V+v", a, [0.6, 0.4, 0])
        check("P7 same speed", close(math.hypot(*a), math.hypot(*b), 1e-14))
        check("P7 directions differ", d["wigner_angle"] > 0.17)
    d = js(qdot, "momentum", "lorentz", "--frame", "0, 0.6, 0", "--momentum",
           "m=2, v=(0.3, 0.4, 0)")
    if d:
        g = 1 / math.sqrt(1 - 0.25)
        E, py = 2 * g, 2 * g * 0.4
        check("E' = G (E - p.V)", close(d["energy"], 1.25 * (E - py * 0.6), 1e-14))
        check("mass kept", close(d["invariant_mass"], 2, 1e-14))
    d = js(qdot, "acceleration", "lorentz", "--frame", "0.6, 0, 0", "--velocity", "0.6, 0, 0",
           "--acceleration", "1, 2, 0")
    if d:
        vec("rest-frame acceleration G^3, G^2", d["acceleration"], [1.25 ** 3, 2 * 1.25 ** 2, 0])


def collide(qdot):
    d = js(qdot, "T16", "collide", "--particle", "m=1, v=(0.6, 0, 0)", "--particle",
           "m=2, v=(-0.8, 0, 0)", "--merge")
    if d:
        check("T16 M", close(d["invariant_mass"], math.sqrt(2496) / 12, 1e-14))
        vec("T16 V", d["velocity"], [-23 / 55, 0, 0])
        check("P11 M > m1 + m2", d["merged"]["mass"] > 3)
    d = js(qdot, "elastic", "collide", "--particle", "m=1, v=(0.8, 0, 0)", "--particle", "m=1",
           "--elastic", "--angle", "0.5")
    if d:
        check("elastic one solution", len(d["final"]) == 1)
        th = d["final"][0]["lab_angles"]
        check("elastic lab angle", close(th[0], 0.5, 1e-12))
        check("tan th1 tan th2 = 2/(gamma + 1)", close(math.tan(th[0]) * math.tan(th[1]),
                                                       2 / (5 / 3 + 1), 1e-11))
        check("four-momentum kept", d["conservation_error"] < 1e-14)
    d = js(qdot, "threshold", "collide", "--particle", "m=1, v=(0.99, 0, 0)", "--particle",
           "m=1", "--threshold", "1, 1, 1, 1")
    if d:
        check("antiproton threshold 6 m c^2", close(d["threshold"]["kinetic_energy"], 6, 1e-15))
        check("gamma 1/sqrt(1-0.99^2) > 7: allowed", d["threshold"]["allowed"])
    d = js(qdot, "decay", "collide", "--particle", "m=139.57039, v=(0.5, 0, 0)", "--decay",
           "105.6583755, 0", "--cm-angle", "pi/3")
    if d:
        check("pi -> mu nu p*", close(d["pstar"], (139.57039 ** 2 - 105.6583755 ** 2)
                                      / (2 * 139.57039), 1e-13))
        check("decay conserves", d["conservation_error"] < 1e-12)


def rocket(qdot):
    ex = Path(__file__).resolve().parents[2] / "examples" / "relativistic_rocket.qd"
    for sets, c, U in [([], 1, 0.5), (["--set", "U=0.9", "--set", "c=1"], 1, 0.9),
                       (["--set", "c=1e4"], 1e4, 0.5)]:
        rc, out, err = run(qdot, "simulate", ex, "--t-end", "0.75", "--rtol", "1e-12",
                           "--atol", "1e-14", "--format", "json", *sets)
        if not check(f"rocket {sets} rc", rc == 0, err):
            continue
        d = json.loads(out)
        rows = [dict(zip(d["columns"], r)) for r in d["rows"]]
        worst = max(abs(r["x'"] - c * math.tanh(U / c * math.log(1 / (1 - r["t"]))))
                    for r in rows)
        check(f"rocket {sets} V = c tanh((U/c) ln(M0/M))", worst < 1e-9 and len(rows) > 10,
              f"worst {worst}")
        if not sets:
            check("T17 V = 0.6 c at M/M0 = 1/4", close(rows[-1]["x'"], 0.6, 1e-10))
        if c == 1e4:
            check("Newtonian rocket U ln(M0/M)", close(rows[-1]["x'"], 0.5 * math.log(4), 1e-8))


def refusals(qdot):
    for name, args, text in [
            ("V = c", ["lorentz", "--frame", "c, 0, 0"], "not below c = 1"),
            ("v > c", ["lorentz", "--frame", "0.1, 0, 0", "--velocity", "0.8, 0.8, 0"],
             "not below c"),
            ("particle at c", ["collide", "--particle", "m=1, v=(2, 0, 0)", "--c", "2"],
             "not below c = 2"),
            ("no frame", ["lorentz", "--event", "0, 0, 0, 0"], "V is missing (--frame)"),
            ("acceleration alone", ["lorentz", "--frame", "0, 0, 0", "--acceleration", "1, 0, 0"],
             "with the particle's velocity (ch. 86 eq 44): give it (--acceleration)"),
            ("two values", ["lorentz", "--frame", "0.1, 0"], "needs 3 comma-separated"),
            ("unknown name", ["lorentz", "--frame", "q, 0, 0"], "does not evaluate"),
            ("no mass", ["collide", "--particle", "v=(0.1, 0, 0)"], "rest mass m=... is missing"),
            ("elastic three", ["collide", "--particle", "m=1", "--particle", "m=1", "--particle",
                               "m=1", "--elastic", "--cm-angle", "1"], "exactly two"),
            ("heavy products", ["collide", "--particle", "m=1", "--decay", "0.6, 0.6"],
             "a decay needs"),
            ("spacelike", ["lorentz", "--frame", "0, 0, 0", "--momentum", "1, 2, 0, 0"],
             "no particle has this four-momentum")]:
        rc, out, err = run(qdot, *args)
        check(f"refuse {name}", rc == 2 and text in err and out == "", f"rc={rc} err={err}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build) / "qdot"
    lorentz(qdot)
    collide(qdot)
    rocket(qdot)
    refusals(qdot)
    return finish()


if __name__ == "__main__":
    sys.exit(main())
