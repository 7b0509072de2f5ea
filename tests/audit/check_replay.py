#!/usr/bin/env python3
"""Replay the textbook audit's cases that pass (issue 33; tests/audit/cases.py).

    python3 tests/audit/check_replay.py --build BUILD_DIR [--show]

Each case runs one qdot command on a model of tests/audit/models/ and reads
one number from its text output; it must equal the reference's value (the
textbook formula cited with the case) to the case's tolerance, with exit 0
(or the case's own exit status: 3 for a "no" verdict).
--show prints each command's output (to write a new case's regex).
"""
import argparse
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from cases import CASES  # noqa: E402


def run(build, args):
    argv = [os.path.join(build, "qdot")] + [
        os.path.join(HERE, "models", a) if a.endswith(".qd") else a for a in args]
    return subprocess.run(argv, capture_output=True, text=True, timeout=60)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--show", action="store_true")
    a = ap.parse_args()
    failed = 0
    for case in CASES:
        name, cite, args, rx, want, rel = case[:6]
        code = case[6] if len(case) > 6 else 0  # a "no" verdict exits 3
        r = run(a.build, args)
        if a.show:
            print(f"== {name}: qdot {' '.join(args)}\n{r.stdout}{r.stderr}")
        m = re.search(rx, r.stdout, re.M)
        why = None
        if r.returncode != code:
            why = f"exit {r.returncode} (want {code}): {r.stderr.strip()[:300]}"
        elif not m:
            why = f"no match for {rx!r}"
        elif rel is None:  # an exact expression, as printed
            if m.group(1).strip() != want:
                why = f"got {m.group(1).strip()!r}, want {want!r}"
        else:
            got = float(m.group(1))
            if not abs(got - want) <= rel * max(abs(want), 1e-300) + (rel if want == 0 else 0):
                why = f"got {got!r}, want {want!r} (rel {rel})"
        if why:
            failed += 1
            print(f"FAIL {name} [{cite}]: qdot {' '.join(args)}: {why}")
        else:
            print(f"ok   {name}")
    print(f"{len(CASES) - failed} passed, {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
