#!/usr/bin/env python3
"""`qdot sweep --format hdf5 -o FILE` on a full disk (issue 30): one message
"cannot write FILE: No space left on device", exit 1, no crash at exit
(HDF5 left with an open file id segfaulted), and no partial file left.

The full disk is a 64 KiB tmpfs mounted for the test, which needs root and
mount(8); without them, or in a qdot built without HDF5, the check is
skipped (exit 77, ctest's SKIP_RETURN_CODE).  A sweep that fits is written
there (an HDF5 file: its signature).

    python3 tests/cli/check_hdf5_full_disk_cli.py --build BUILD_DIR
"""
import argparse
import os
import subprocess
import sys
import tempfile
from pathlib import Path

SKIP = 77
OSC = """coordinates x
parameters m = 1, k = 1
T = m*x'^2/2
V = k*x^2/2
initial x = 0, x' = 1
"""
results = {"passed": 0, "failed": 0}


def check(name, ok, detail=""):
    if ok:
        results["passed"] += 1
    else:
        results["failed"] += 1
        print("FAIL %s %s" % (name, detail))


def sweep(qdot, osc, n, out):
    return subprocess.run([str(qdot), "sweep", str(osc), "--grid", "m=1:2:%d" % n, "--t-end",
                           "1", "--measure", "final", "--threads", "1", "--format", "hdf5",
                           "-o", str(out)], capture_output=True, text=True, timeout=300)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    qdot = Path(ap.parse_args().build).resolve() / "qdot"
    with tempfile.TemporaryDirectory(prefix="qdot-h5full-") as t:
        tmp = Path(t)
        osc = tmp / "osc.qd"
        osc.write_text(OSC)
        ref = tmp / "ref.h5"
        r = sweep(qdot, osc, 20, ref)
        if r.returncode != 0 and "without HDF5" in r.stderr:
            print("SKIP: qdot built without HDF5")
            return SKIP
        check("a sweep into HDF5 (precondition)", r.returncode == 0, r.stderr)
        mnt = tmp / "full"
        mnt.mkdir()
        if os.geteuid() != 0 or subprocess.run(
                ["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", str(mnt)],
                capture_output=True).returncode != 0:
            print("SKIP: cannot mount a small tmpfs (needs root and mount)")
            return SKIP
        try:
            out = mnt / "big.h5"
            r = sweep(qdot, osc, 3000, out)  # about 100 KiB: more than the disk holds
            check("full disk: exit 1", r.returncode == 1, "exit %d %r" % (r.returncode, r.stderr))
            check("full disk: one message naming the file",
                  r.stderr.strip() == "qdot: error: cannot write %s: %s" % (out, os.strerror(28)),
                  repr(r.stderr))
            check("full disk: no partial file", not out.exists(), str(os.listdir(mnt)))
            small = mnt / "small.h5"
            r = sweep(qdot, osc, 20, small)
            check("a sweep that fits: exit 0", r.returncode == 0, r.stderr)
            data = small.read_bytes() if small.exists() else b""
            check("a sweep that fits: an HDF5 file", data[:8] == b"\x89HDF\r\n\x1a\n", data[:8])
        finally:
            subprocess.run(["umount", str(mnt)], capture_output=True)
    print("%d passed, %d failed" % (results["passed"], results["failed"]))
    return 1 if results["failed"] else 0


if __name__ == "__main__":
    sys.exit(main())
