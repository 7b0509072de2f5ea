#!/usr/bin/env python3
"""tests/build/check_needed.py - what the qdot program and libqdot.so load
at start-up (issue 34): never OpenMPI, HDF5, Cairo (with X11) nor LLVM, which
only the optional modules qdot-modules/qdot_mpi.so, qdot_hdf5.so,
qdot_cairo.so and qdot_llvm.so need, opened by dlopen when a sweep runs under mpirun or
writes HDF5, a plot is drawn or a program is jitted (src/sweep/ext.h,
src/plot/canvas.h, src/sym/jit.h).

- `ldd` of build/qdot and of libqdot.so (every library the loader maps,
  not only the direct NEEDED entries) names no libmpi, libopen-*, libhdf5,
  libpmix, libhwloc, libcairo, libX11, libxcb nor libLLVM;
- each module that was built needs its own library (libmpi, libhdf5) and
  (libcairo) and no libqdot: a module calls nothing of libqdot's, so that a program
  holding libqdot as an archive never gets a second copy of it.

Usage: check_needed.py --build BUILD_DIR
"""
import argparse, glob, os, re, subprocess, sys

HEAVY = re.compile(r"lib(mpi|open-rte|open-pal|hdf5|pmix|hwloc|cairo|X11|xcb|LLVM)[^ ]*\.so")


def ldd(path):
    r = subprocess.run(["ldd", path], capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit("ldd %s: %s" % (path, r.stderr))
    return r.stdout


def needed(path):
    r = subprocess.run(["readelf", "-d", path], capture_output=True, text=True, check=True)
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", r.stdout)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--build", required=True)
    b = ap.parse_args().build
    failed = 0

    def check(name, ok, detail=""):
        nonlocal failed
        print("%s: %s%s" % ("ok" if ok else "FAIL", name, "" if ok else "\n  " + detail))
        failed += not ok

    lib = sorted(glob.glob(os.path.join(b, "libqdot.so.*")))
    for path in [os.path.join(b, "qdot")] + lib[:1]:
        heavy = sorted(set(HEAVY.findall(ldd(path))))
        check("%s loads no MPI, HDF5 nor Cairo" % os.path.basename(path), not heavy,
              "it maps lib%s" % ", lib".join(heavy))
    wants = {"mpi": "libmpi.so", "hdf5": "libhdf5", "cairo": "libcairo", "llvm": "libLLVM"}
    mods = sorted(glob.glob(os.path.join(b, "qdot-modules", "qdot_*.so")))
    for path in mods:
        name = os.path.basename(path)[5:-3]
        n = needed(path)
        check("%s needs %s" % (os.path.basename(path), wants.get(name, "?")),
              any(x.startswith(wants.get(name, "-")) for x in n), " ".join(n))
        check("%s needs no libqdot" % os.path.basename(path),
              not any(x.startswith("libqdot") for x in n), " ".join(n))
    if not mods:
        check("the Cairo module is built (Cairo is required)", False, "no qdot-modules/*.so")
    print("%d failed" % failed)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
