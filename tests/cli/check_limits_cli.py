#!/usr/bin/env python3
"""Inputs past qdot's limits and the messages that name them (issue 30).

    python3 tests/cli/check_limits_cli.py --build BUILD_DIR

- (x+1)^16777217 and a model with V = (q+1)^100000000 crashed (stack
  overflow in the expander): the power stays a power and derives to
  -1e8 (q+1)^99999999;
- V = (q+1)^100000 was expanded eagerly (5 GB): `check` now answers in a
  few MB, and under a 400 MB address-space limit `expand "(x+1)^100000"`
  gives the power back instead of GMP's abort (exit 134);
- a product over the 64 MiB bound is refused: "expression too large";
- V = 1e100000*q^2 gave "0 equilibria", exit 0: the overflow is named;
  a --box whose width overflows a double is refused, exit 2;
- messages: 1/0 is "division by zero"; 0^q and atan2(0,0) are located at
  FILE:LINE:COL; (1,2,3) is not "missing ')'"; --output q''' names the
  order.
Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import os
import resource
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "util"))
from clicheck import EXAMPLES, check, finish, run  # noqa: E402


# Under AddressSanitizer (QDOT_SANITIZED=1, set by tests/CMakeLists.txt) the
# shadow memory alone exceeds any address-space limit: the same commands run
# unlimited there (the answer is still checked), and the limit is said skipped.
SANITIZED = os.environ.get("QDOT_SANITIZED") == "1"


def limited(qdot, *args, kb=400000):
    """run under an address-space limit of kb kilobytes (none when sanitized)."""
    def lim():
        resource.setrlimit(resource.RLIMIT_AS, (kb * 1024, kb * 1024))
    p = subprocess.run([str(qdot), *args], capture_output=True, text=True, timeout=120,
                       preexec_fn=None if SANITIZED else lim)
    return p.returncode, p.stdout, p.stderr


def model(tmp, name, body):
    path = Path(tmp) / name
    path.write_text(body)
    return path


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build) / "qdot"
    with tempfile.TemporaryDirectory() as tmp:
        rc, out, err = run(qdot, "expand", "(x+1)^16777217")
        check("expand past 2^24", rc == 0 and out.strip() == "(x + 1)^16777217", f"{rc} {out} {err}")

        huge = model(tmp, "huge.qd", "coordinates q\nT = q'^2/2\nV = (q+1)^100000000\n")
        rc, out, err = run(qdot, "eom", huge)
        check("eom of (q+1)^1e8", rc == 0 and "f[q] = -100000000*(q + 1)^99999999" in out,
              f"{rc} {out[-300:]} {err}")

        if SANITIZED:
            print("skip: the 400 MB address-space limit (not under AddressSanitizer); "
                  "the two runs below go unlimited")
        big = model(tmp, "big.qd", "coordinates q\nT = q'^2/2\nV = (q+1)^100000\n")
        rc, out, err = limited(qdot, "check", str(big))
        check("check of (q+1)^100000 in 400 MB", rc == 0 and "ok" in out, f"{rc} {err}")
        rc, out, err = limited(qdot, "expand", "(x+1)^100000")
        check("expand (x+1)^100000 in 400 MB", rc == 0 and out.strip() == "(x + 1)^100000",
              f"{rc} {err}")
        rc, out, err = run(qdot, "expand", "(x+1)^3000*(y+1)^3000")
        check("a product too large", rc != 0 and "expression too large" in err
              and "64 MiB" in err, f"{rc} {err}")

        ov = model(tmp, "ov.qd", "coordinates q\nT = q'^2/2\nV = 1e100000*q^2\n")
        rc, out, err = run(qdot, "equilibria", ov)
        check("an overflowing coefficient is named", rc != 0 and "overflows a double" in err
              and "2e100000" in err and "equilibri" not in out, f"{rc} {out} {err}")
        pend = EXAMPLES / "double_pendulum.qd"
        rc, out, err = run(qdot, "equilibria", pend, "--box", "theta1=-1e308:1e308")
        check("--box too wide", rc == 2 and "too wide" in err and "overflows a double" in err,
              f"{rc} {out} {err}")

        div = model(tmp, "div.qd", "coordinates q\nparameters k = 1/0\nT = q'^2/2\nV = k*q^2\n")
        rc, out, err = run(qdot, "check", div)
        check("1/0 is a division by zero", rc == 2 and "division by zero\n" in err
              and "negative power" not in err, err)
        zq = model(tmp, "zq.qd", "coordinates q\nT = q'^2/2\nV = 0^q\n")
        rc, out, err = run(qdot, "check", zq)
        check("0^q located", rc == 2 and f"{zq}:3:5: error: 0 to a power that is not a number" in err,
              err)
        at = model(tmp, "at.qd", "coordinates q\nT = q'^2/2\nV = q^2 + atan2(0,0)\n")
        rc, out, err = run(qdot, "check", at)
        check("atan2(0,0) located", rc == 2 and f"{at}:3:11: error: atan2(0, 0) has no value" in err,
              err)
        rc, out, err = run(qdot, "print", "(1,2,3)")
        check("(1,2,3)", rc == 2 and "a vector or tuple is not an expression" in err
              and "missing" not in err, err)
        rc, out, err = run(qdot, "simulate", pend, "--t-end", "0.01", "--output", "theta1'''")
        check("--output q'''", rc == 2 and "derivative of order 3" in err
              and "not an input" not in err, err)
    return finish()


if __name__ == "__main__":
    sys.exit(main())
