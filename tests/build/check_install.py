#!/usr/bin/env python3
"""tests/build/check_install.py - `make install PREFIX=...` as a user runs it:
the tree installed under a prefix other than the one it was configured for
(cmake --install BUILD --prefix TMP) still finds its optional modules
(src/base/module.h: PREFIX/bin/qdot looks in PREFIX/<libdir>/qdot-modules),
so the installed qdot draws a plot (Cairo) and writes an HDF5 sweep when
that module was built, and the PNG it writes is a PNG.

Usage: check_install.py --build BUILD_DIR --root SOURCE_DIR
"""
import argparse, os, subprocess, sys, tempfile


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    ap.add_argument("--root", required=True)
    a = ap.parse_args()
    failed = 0

    def check(name, ok, detail=""):
        nonlocal failed
        print("%s: %s%s" % ("ok" if ok else "FAIL", name, "" if ok else "\n  " + detail))
        failed += not ok

    model = os.path.join(a.root, "examples", "double_pendulum.qd")
    with tempfile.TemporaryDirectory(prefix="qdot-inst-") as tmp:
        prefix = os.path.join(tmp, "prefix")
        r = subprocess.run(["cmake", "--install", a.build, "--prefix", prefix],
                           capture_output=True, text=True)
        check("cmake --install to another prefix", r.returncode == 0, r.stderr[-2000:])
        qdot = os.path.join(prefix, "bin", "qdot")
        env = {k: v for k, v in os.environ.items() if k != "QDOT_MODULE_DIR"}
        png = os.path.join(tmp, "run.png")
        r = subprocess.run([qdot, "simulate", model, "--t-end", "1", "--plot", png],
                           capture_output=True, text=True, env=env, cwd=tmp)
        ok = r.returncode == 0 and os.path.exists(png)
        with open(png, "rb") if ok else open(os.devnull, "rb") as f:
            magic = f.read(8)
        check("the installed qdot draws through its Cairo module",
              ok and magic == b"\x89PNG\r\n\x1a\n", r.stderr[-2000:])
        mods = os.listdir(os.path.join(a.build, "qdot-modules"))
        if "qdot_hdf5.so" in mods:
            h5 = os.path.join(tmp, "runs.h5")
            r = subprocess.run([qdot, "sweep", model, "--grid", "theta1=0:1:3", "--t-end", "0.1",
                                "--measure", "final", "--format", "hdf5", "-o", h5],
                               capture_output=True, text=True, env=env, cwd=tmp)
            with open(h5, "rb") if os.path.exists(h5) else open(os.devnull, "rb") as f:
                magic = f.read(8)
            check("the installed qdot writes HDF5 through its module",
                  r.returncode == 0 and magic == b"\x89HDF\r\n\x1a\n", r.stderr[-2000:])
        else:
            print("skipped: the HDF5 module was not built")
    print("%d failed" % failed)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
