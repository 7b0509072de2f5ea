#!/usr/bin/env python3
"""tests/build/check_layers_selftest.py - the layer rules of
tests/build/check_exports.py fail when broken (issue 31).

check_exports.py passing on the tree shows only that nothing is broken
today.  Here each rule is broken once, in a copy of src/, cli/ and include/, and
check_exports.py --layers-only must exit 1 naming that break, while the
untouched copy passes: a private header of mech included from hj (the
include the issue counted, mech/legendre.h), an interface header included
by a module its allow-list does not name, an include reaching above the
including module, an interface header passing on its module's private
header, an interface header the list does not know, a listed user that no
longer includes its interface, an internal type named with the public
prefix, a private header included from cli/, and cli/ grown past its line
budget.
"""
import argparse, os, re, shutil, subprocess, sys, tempfile

ap = argparse.ArgumentParser()
ap.add_argument("--root", required=True)
a = ap.parse_args()
checker = os.path.join(a.root, "tests", "build", "check_exports.py")
failures = []


def copy_tree(dst):
    for d in ("src", "cli", "include"):
        shutil.copytree(os.path.join(a.root, d), os.path.join(dst, d),
                        ignore=shutil.ignore_patterns("*.o", "__pycache__"))


def run(root):
    p = subprocess.run([sys.executable, checker, "--layers-only", "--root", root],
                       capture_output=True, text=True)
    return p.returncode, p.stdout + p.stderr


def add_include(root, rel, line):
    """line inserted after the first #include of rel (a new file when absent)."""
    path = os.path.join(root, rel)
    if not os.path.exists(path):
        open(path, "w").write(line + "\n")
        return
    text = open(path, encoding="utf-8").read()
    m = re.search(r"^#include[^\n]*\n", text, re.M)
    at = m.end() if m else 0
    open(path, "w").write(text[:at] + line + "\n" + text[at:])


def drop_include(root, rel, hdr):
    path = os.path.join(root, rel)
    text = open(path, encoding="utf-8").read()
    new = re.sub(r'^#include "(\.\./)?' + re.escape(hdr) + r'"\n', "", text, flags=re.M)
    assert new != text, f"{rel} does not include {hdr}"
    open(path, "w").write(new)


def users_of(root, hdr):
    """The files of src/ outside hdr's module that include it."""
    mod = hdr.split("/")[0]
    out = []
    for d in sorted(os.listdir(os.path.join(root, "src"))):
        if d == mod:
            continue
        for f in sorted(os.listdir(os.path.join(root, "src", d))):
            rel = os.path.join("src", d, f)
            if f.endswith((".c", ".h")) and re.search(
                    r'^#include "(\.\./)?' + re.escape(hdr) + '"',
                    open(os.path.join(root, rel), encoding="utf-8").read(), re.M):
                out.append(rel)
    return out


def pad_cli(root):
    open(os.path.join(root, "cli", "padding.c"), "w").write("int cli_pad;\n" * 7001)


# (what is broken, how, a phrase the checker's complaint must contain)
CASES = [
    ("a private header across modules",
     lambda r: add_include(r, "src/hj/hj.c", '#include "mech/legendre.h"'),
     "src/hj/hj.c includes mech/legendre.h, a private header of src/mech"),
    ("an interface header outside its allow-list",
     lambda r: add_include(r, "src/hj/hj.c", '#include "mech/mech_export.h"'),
     "an interface header src/hj is not listed for"),
    ("an include reaching above its module",
     lambda r: add_include(r, "src/mech/metric.c", '#include "../linear/linear.h"'),
     "src/mech/metric.c (rank 4) includes linear/linear.h (rank 5)"),
    ("an interface header passing on a private header",
     lambda r: add_include(r, "src/mech/mech_export.h", '#include "mech/legendre.h"'),
     "an interface header passes on no private header"),
    ("an interface header nobody listed",
     lambda r: add_include(r, "src/path/path_export.h", "/* path's interface */"),
     "src/path/path_export.h: an interface header not in INTERFACE"),
    ("a listed user that no longer includes its interface",
     lambda r: [drop_include(r, f, "mech/mech_export.h")
                for f in users_of(r, "mech/mech_export.h") if f.startswith("src/linear/")],
     "INTERFACE lists src/linear for mech/mech_export.h, which it no longer includes"),
    ("an internal type with the public prefix",
     lambda r: add_include(r, "src/sym/prec.h", "typedef struct qd_split { int n; } qd_split;"),
     "src/sym/prec.h: internal type qd_split has the public prefix qd_"),
    ("a private header included from the program",
     lambda r: add_include(r, "cli/main.c", '#include "../src/sim/simint.h"'),
     "cli/main.c includes ../src/sim/simint.h: the program includes only public headers"),
    ("the program over its line budget",
     pad_cli, "more than 7000 (issue 31)"),
]

with tempfile.TemporaryDirectory(prefix="qdot-layers-") as tmp:
    clean = os.path.join(tmp, "clean")
    copy_tree(clean)
    rc_clean, out = run(clean)
    if rc_clean != 0:
        failures.append(f"the untouched copy fails (rc {rc_clean}):\n{out}")
    caught = 0
    for i, (what, breaks, phrase) in enumerate(CASES):
        root = os.path.join(tmp, f"case{i}")
        copy_tree(root)
        breaks(root)
        rc, out = run(root)
        if rc != 1 or phrase not in out:
            failures.append(f"{what}: expected exit 1 with '{phrase}', got {rc}:\n{out}")
        else:
            caught += 1
            print(f"ok: {what}: {next(l for l in out.splitlines() if phrase in l)}")

for f in failures:
    print("FAIL:", f)
print(f"{caught}/{len(CASES)} breaks caught; the untouched copy "
      + ("fails" if rc_clean else "passes"))
sys.exit(1 if failures else 0)
