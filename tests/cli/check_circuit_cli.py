#!/usr/bin/env python3
"""End-to-end checks of the circuit statements (`inductance`, `capacitance`,
`resistance`, `source`) through `qdot modes`, `simulate`, `stability`, `eom`.

    python3 tests/cli/check_circuit_cli.py --build BUILD_DIR

Expected values are closed forms, not output of the code under test:
  - the LC ladder of examples/circuit_lc_ladder.qd (input shorted, three
    series-L shunt-C sections): w_k = (2/sqrt(LC)) sin((2k-1) pi/(2(2N+1))),
    the closed form itself checked against SymPy's eigenvalues of the
    stiffness matrix written from the circuit;
  - two identical LC circuits coupled by M (Byerly ch. V Arts. 52-54, seed 001,
    with the usual self-inductance): w^2 = 1/(C (L + M)), 1/(C (L - M)), the
    exact forms qdot prints compared with SymPy;
  - the driven series RLC circuit (Goldstein sec. 1.5, (1.67)-(1.70), with
    m -> L, b -> R, k -> 1/C): the steady current E0/sqrt(R^2 + (wL - 1/(wC))^2)
    lagging by atan((wL - 1/(wC))/R), fitted from `qdot simulate` after the
    transient, to 1e-4;
  - two parallel wires (Byerly ch. V Art. 53): currents the same way attract,
    opposed ones repel, with Ampere's force mu0 l i1 i2/(2 pi x);
  - the loudspeaker: force Bl i and back-EMF Bl x' (the equations), the cone
    held at x = Bl E0/(Re k) by a steady voltage, at x = Bl i/k with
    w = sqrt(k/m) when the current is maintained (`stability --driven`), and
    the coupling creates no energy (conserved with no resistance, no damping);
  - Byerly Art. 54a's induced current, made in circuit 1: y2' = -M i/L with the
    usual L (`qdot impulse`, Thomson's theorem);
  - bad elements exit 2 with the place of the error.
Prints "N passed, N failed"; exit 1 on failure.
"""
import argparse
import json
import math
import sys
import tempfile
from pathlib import Path

import sympy as sp

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "util"))
from clicheck import check, run, close, finish  # noqa: E402  (tests/util/clicheck.py)

EX = Path(__file__).resolve().parents[2] / "examples"


def modes_json(qdot, name, *extra):
    rc, out, err = run(qdot, "modes", str(EX / name), "--format", "json", *extra)
    check(f"{name} modes rc", rc == 0, err)
    return json.loads(out) if rc == 0 else None


def ladder_closed_form(N, L, C):
    return [2 / math.sqrt(L * C) * math.sin((2 * k - 1) * math.pi / (2 * (2 * N + 1)))
            for k in range(1, N + 1)]


def ladder_sympy(N):
    """w^2 L C from the circuit: the shorted input loop has no capacitor of its
    own, each shunt capacitor is shared by two loops, the last closes loop N."""
    K = sp.zeros(N, N)
    for k in range(N - 1):  # the capacitor on q_k - q_(k+1)
        K[k, k] += 1
        K[k + 1, k + 1] += 1
        K[k, k + 1] -= 1
        K[k + 1, k] -= 1
    K[N - 1, N - 1] += 1  # the last one, on q_N alone
    lam = sp.Symbol("lam")
    return sorted(float(sp.re(r)) for r in sp.Poly(K.charpoly(lam).as_expr(), lam).nroots(n=30))


def ladder(qdot):
    sym = ladder_sympy(3)
    form = ladder_closed_form(3, 1, 1)
    check("ladder closed form = sympy eigenvalues",
          all(close(w * w, s, 1e-12) for w, s in zip(form, sym)), f"{form} {sym}")
    for L, C in ((1, 1), (3, 0.25), (2e-3, 5e-7)):
        d = modes_json(qdot, "circuit_lc_ladder.qd", "--set", f"L={L}", "--set", f"C={C}")
        if not d:
            continue
        got = sorted(d["frequencies"])
        want = ladder_closed_form(3, L, C)
        check(f"ladder L={L} C={C}", len(got) == 3 and
              all(close(g, w, 1e-9) for g, w in zip(got, want)), f"{got} {want}")


def coupled(qdot):
    d = modes_json(qdot, "circuit_coupled_lc.qd")
    if not d:
        return
    L, M, C = 2e-3, 5e-4, 1e-6
    want = sorted([1 / math.sqrt(C * (L + M)), 1 / math.sqrt(C * (L - M))])
    got = sorted(d["frequencies"])
    check("coupled frequencies", all(close(g, w, 1e-10) for g, w in zip(got, want)),
          f"{got} {want}")
    Ls, Ms, Cs = sp.symbols("L M C", positive=True)
    exact = {1 / (Cs * (Ls + Ms)), 1 / (Cs * (Ls - Ms))}
    printed = [sp.sympify(m["omega2_exact"], locals={"L": Ls, "M": Ms, "C": Cs})
               for m in d["modes"]]
    check("coupled exact w^2",
          len(printed) == 2 and all(any(sp.simplify(p - e) == 0 for e in exact) for p in printed),
          f"{printed}")
    # in step: y1 = y2; opposed: y1 = -y2
    shapes = {round(m["omega"]): m["shape"] for m in d["modes"]}
    s_in = shapes.get(round(want[0]))
    s_op = shapes.get(round(want[1]))
    check("coupled shapes", s_in and s_op and close(s_in["y1"], s_in["y2"], 1e-9) and
          close(s_op["y1"], -s_op["y2"], 1e-9), f"{shapes}")


def fit_amplitude(rows, col, w, t0):
    """Least squares i = A sin(w t) + B cos(w t) over t >= t0."""
    saa = sab = sbb = ra = rb = 0.0
    for row in rows:
        t = row[0]
        if t < t0:
            continue
        s, c = math.sin(w * t), math.cos(w * t)
        saa += s * s
        sab += s * c
        sbb += c * c
        ra += s * row[col]
        rb += c * row[col]
    det = saa * sbb - sab * sab
    A = (ra * sbb - rb * sab) / det
    B = (rb * saa - ra * sab) / det
    return math.hypot(A, B), math.atan2(B, A)


def rlc(qdot):
    L, R, C, E0 = 1, 2, 1, 10
    for w in (3, 1, 0.5):
        # the transient decays as exp(-R t/(2L)) = exp(-t): gone to 1e-13 by t = 30
        rc, out, err = run(qdot, "simulate", str(EX / "circuit_rlc_driven.qd"), "--t-end", "40",
                           "--dt", "0.01", "--rtol", "1e-12", "--method", "dop853",
                           "--set", f"w={w}", "--format", "json")
        check(f"rlc w={w} rc", rc == 0, err)
        if rc:
            continue
        d = json.loads(out)
        amp, phase = fit_amplitude(d["rows"], d["columns"].index("q'"), w, 30)
        X = w * L - 1 / (w * C)
        want = E0 / math.sqrt(R * R + X * X)
        check(f"rlc w={w} amplitude", abs(amp - want) <= 1e-4 * want, f"{amp} {want}")
        check(f"rlc w={w} phase", abs(phase + math.atan2(X, R)) <= 1e-4, f"{phase}")


def wires_dx(qdot, i2, E2, t):
    """x(t) - x(0) for wire 2 starting at rest, 1 cm from wire 1, 10 A in wire 1."""
    rc, out, err = run(qdot, "simulate", str(EX / "circuit_parallel_wires.qd"), "--t-end",
                       str(t), "--rtol", "1e-12", "--method", "dopri5", "--set", f"E2={E2}",
                       "--initial", f"x = 0.01, y1' = 10, y2' = {i2}",
                       "--format", "json", "--out", "/dev/null")
    check(f"wires i2={i2} rc", rc == 0, err)
    return json.loads(out)["final"]["x"] - 0.01 if rc == 0 else None


def wires(qdot):
    mu0, l, m, x, i, t = 4e-7 * math.pi, 1, 1e-3, 0.01, 10, 1e-3
    F = mu0 * l * i * i / (2 * math.pi * x)  # 2e-3 N, Ampere
    same = wires_dx(qdot, 10, 1, t)
    opposed = wires_dx(qdot, -10, -1, t)
    want = F / m * t * t / 2
    # over 1 ms the wire moves 1e-6 of its 1e-2 m: the force changes by 1e-4
    check("wires same way attract", same is not None and abs(same + want) <= 1e-3 * want,
          f"{same} {-want}")
    check("wires opposed repel", opposed is not None and abs(opposed - want) <= 1e-3 * want,
          f"{opposed} {want}")


def loudspeaker(qdot):
    name = str(EX / "circuit_loudspeaker.qd")
    Le, Re, Bl, m, k, E0 = 5e-4, 6, 7, 0.02, 2000, 1
    rc, out, err = run(qdot, "eom", name, "--format", "json")
    check("speaker eom rc", rc == 0, err)
    if rc == 0:
        d = json.loads(out)
        syms = {s: sp.Symbol(s) for s in ("Le", "Re", "Bl", "m", "k", "b", "E0", "x")}
        f = {q: sp.sympify(d["forcing"][j].replace("'", "_d"), locals=syms)
             for j, q in enumerate(d["coordinates"])}
        qd_, xd = sp.Symbol("q_d"), sp.Symbol("x_d")
        check("speaker back-EMF", sp.simplify(f["q"] - (syms["E0"] - syms["Re"] * qd_ - syms["Bl"] * xd)) == 0,
              f"{f['q']}")
        check("speaker force Bl i", sp.simplify(f["x"] - (syms["Bl"] * qd_ - syms["b"] * xd - syms["k"] * syms["x"])) == 0,
              f"{f['x']}")
    rc, out, err = run(qdot, "simulate", name, "--t-end", "0.5", "--rtol", "1e-12",
                       "--format", "json", "--out", "/dev/null")
    check("speaker simulate rc", rc == 0, err)
    if rc == 0:
        fin = json.loads(out)["final"]
        check("speaker steady cone", close(fin["x"], Bl * E0 / (Re * k), 1e-8), f"{fin}")
        check("speaker steady current", close(fin["q'"], E0 / Re, 1e-8), f"{fin}")
    i = 0.25
    rc, out, err = run(qdot, "stability", name, "--driven", f"q' = {i}", "--format", "json")
    check("speaker stability rc", rc == 0, err)
    if rc == 0:
        d = json.loads(out)
        text = json.dumps(d)
        check("speaker driven cone", close(d["steady"]["x"], Bl * i / k, 1e-9), text[:400])
        check("speaker driven frequency",
              any(close(w, math.sqrt(k / m), 1e-9) for w in d["frequencies"]), text[:400])
    rc, out, err = run(qdot, "simulate", name, "--t-end", "0.2", "--rtol", "1e-12",
                       "--set", "Re=0", "--set", "b=0", "--set", "E0=0",
                       "--initial", "x = 1e-3, q' = 0.1", "--format", "json", "--out", "/dev/null")
    check("speaker lossless rc", rc == 0, err)
    if rc == 0:
        e = json.loads(out)["energy_error_max"]
        check("speaker coupling conserves energy", e < 1e-9, f"{e}")


def induced(qdot):
    """Byerly Art. 54a with the usual self-inductance: y2' = -M i/L, the EMF's
    impulse (L^2 - M^2) i/L (his (4 L_B^2 - M^2) i/(2 L_B) with L = 2 L_B)."""
    rc, out, err = run(qdot, "impulse", str(EX / "circuit_induced_currents.qd"), "--format", "json")
    check("induced rc", rc == 0, err)
    if rc:
        return
    d = json.loads(out)
    L, M, i = 2, 0.5, 2
    check("induced current", close(d["velocities_after"]["y2'"], -M * i / L, 1e-12), out[:300])
    check("induced impulse", close(d["impulsive_multipliers"]["Lambda_make"],
                                   (L * L - M * M) * i / L, 1e-12), out[:300])
    Ls, Ms, Is = sp.symbols("L M i", positive=True)
    got = sp.sympify(d["exact"]["velocities_after"]["y2'"], locals={"L": Ls, "M": Ms, "i": Is})
    check("induced exact", sp.simplify(got + Ms * Is / Ls) == 0, str(got))


def errors(qdot, tmp):
    cases = [
        ("inductance -1 on q", ":3:12: error: an inductance must be positive"),
        ("capacitance C on q^2", ":3:18: error: a branch must be linear in the charges"),
        ("resistance 1 on qq", ":3:17: error: 'qq' is not a coordinate"),
    ]
    for k, (line, want) in enumerate(cases):
        f = tmp / f"bad{k}.qd"
        f.write_text(f"coordinates q\nparameters C = 1\n{line}\nT = q'^2\n")
        for cmd in ("check", "modes"):
            rc, out, err = run(qdot, cmd, str(f))
            check(f"error {line} {cmd}", rc == 2 and want in err and "^" in err, f"{rc} {err}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build) / "qdot"
    for f in (ladder, coupled, rlc, wires, loudspeaker, induced):
        f(qdot)
    with tempfile.TemporaryDirectory() as tmp:
        errors(qdot, Path(tmp))
    sys.exit(finish())


if __name__ == "__main__":
    main()
