#!/usr/bin/env python3
"""tests/build/check_exports.py - libqdot.so exports exactly its public surface.

The shared library is built with -fvisibility=hidden; QD_API in the public
headers marks what is exported.  This checks both directions with `nm -D`:
every exported symbol is a public `qd_` name (no internal `qd__` helpers, no
unprefixed globals), every function the headers declare is exported, and the
library carries a soname.
"""
import argparse, glob, os, re, subprocess, sys

ap = argparse.ArgumentParser()
ap.add_argument("--build", required=True)
ap.add_argument("--root", required=True)
a = ap.parse_args()

lib = os.path.join(a.build, "libqdot.so")
out = subprocess.run(["nm", "-D", "--defined-only", lib], capture_output=True,
                     text=True, check=True).stdout
exported = {l.split()[-1] for l in out.splitlines() if re.match(r"^\S+ [TDBR] ", l)}
bad = sorted(s for s in exported if not re.match(r"^qd_[a-z0-9]", s))
declared = set()
for h in glob.glob(os.path.join(a.root, "include/qdot/*.h")):
    for m in re.finditer(r"^QD_API\b[^;(]*?\b(qd_\w+)\s*\(", open(h).read(), re.M):
        declared.add(m.group(1))
missing = sorted(declared - exported)
extra = sorted(exported - declared)
soname = subprocess.run(["objdump", "-p", lib], capture_output=True, text=True).stdout
ok = True
if bad:
    print("exported names that are not public qd_ names:", " ".join(bad)); ok = False
if missing:
    print("declared QD_API but not exported:", " ".join(missing)); ok = False
if extra:
    print("exported but not declared in include/qdot:", " ".join(extra)); ok = False
if not re.search(r"SONAME\s+libqdot\.so\.\d+", soname):
    print("libqdot.so has no soname"); ok = False
if len(declared) < 100:
    print("suspiciously few public functions found:", len(declared)); ok = False
print(f"{len(exported)} exported, {len(declared)} declared")
sys.exit(0 if ok else 1)
