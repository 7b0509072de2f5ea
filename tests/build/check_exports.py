#!/usr/bin/env python3
"""tests/build/check_exports.py - libqdot.so exports exactly its public
surface, internal names carry their module's prefix, and no module of
src/ reaches above itself (docs/design.md, "Architecture").

1. Exports (nm -D of libqdot.so, built with -fvisibility=hidden): every
   exported symbol is a public `qd_` name declared QD_API in include/qdot,
   every such declaration is exported, and the library has a soname.
2. Internal names (nm of each module's objects, qdot_obj.dir/src/MODULE):
   every global symbol that is not QD_API starts with `qd__`, and with its
   module's own prefix `qd__TAG_` (PREFIX below).  The kernel (base, sym)
   owns the bare `qd__`: the allocation path and the expression internals
   every file calls.  No module is excepted (src/sim's were renamed in
   issue 31).
3. Layers: each module has a rank (RANK, the order docs/design.md writes
   down); a module may call (a symbol of its objects resolved in another
   module's) and include (`#include "M/x.h"` or "../M/x.h") only modules of
   lower rank.  A private header (src/M/x.h) is included only inside M,
   except base's (the bottom layer every module uses), the shared internal
   interfaces SHARED, and a module's interface header src/M/M_export.h:
   what M deliberately gives the modules above it when a public API would
   be wrong.  The interface headers and the modules that use them are an
   explicit list (INTERFACE): a new user, a new interface header, or an
   entry no longer used fails.  An interface header declares only M's
   internal names (its prefix), includes only public, base, SHARED or lower
   interface headers (so it cannot pass M's private headers on).  A type
   defined in src/ with the public prefix qd_ is a public one (an opaque
   type's body); internal types carry the internal prefix.
4. The program: cli/ includes only public headers (qdot/x.h) and its own,
   and stays within CLI_MAX_LINES (issue 31: a thin program over libqdot).

--layers-only runs 3 and 4 alone (no build needed): tests/build/
check_layers_selftest.py plants violations in a copy of the tree and
checks that each one fails here.
"""
import argparse, glob, os, re, subprocess, sys

# The module order: a module uses only modules of lower rank.
RANK = {
    "base": 0,
    "sym": 1,
    "num": 2, "form": 2,
    "model": 3, "group": 3, "plot": 3, "json": 3,
    "mech": 4, "codegen": 4, "field": 4, "rel": 4,
    "hj": 5, "impulse": 5, "linear": 5, "orbit": 5, "path": 5, "scatter": 5, "speeds": 5,
    "sim": 6, "render": 6,
    "action": 7, "lyap": 7, "scene": 7,
    "sweep": 8,
}
# One internal prefix per module: qd__TAG_ (base and sym: the bare qd__).
PREFIX = {
    "action": "act", "codegen": "cg", "field": "field", "form": "form", "group": "group",
    "hj": "hj", "impulse": "imp", "json": "json", "linear": "lin", "lyap": "lyap", "mech": "mech",
    "model": "mdl", "num": "num", "orbit": "orb", "path": "path", "plot": "plot",
    "rel": "rel", "render": "render", "scatter": "sct", "scene": "scene", "speeds": "spd",
    "sim": "sim", "sweep": "sweep",
}
KERNEL = {"base", "sym"}
# Private headers other modules may include: the dense linear algebra every
# numeric module shares, and the node layout the code generator walks.
SHARED = {"num/num.h", "sym/node.h"}
# A module's interface to the modules above it (docs/design.md,
# "Architecture"): src/M/M_export.h, and exactly the modules that include it.
INTERFACE = {
    "codegen/codegen_export.h": {"sim"},                    # angle sums, native loader
    "mech/mech_export.h": {"impulse", "linear", "speeds"},  # the system, Lagrange rows
    "model/model_export.h": {"field"},                      # the field statement as read
    "sim/sim_export.h": {"lyap"},                           # the compiled system, RK pairs
    "sym/sym_export.h": {"model", "sim"},                   # Taylor mode, as-written nodes
}
# cli/ at most this many lines (issue 31; docs/design.md, "The library's surface").
CLI_MAX_LINES = 7000


def interface(hdr):
    mod, name = hdr.split("/", 1)
    return name == f"{mod}_export.h"

ap = argparse.ArgumentParser()
ap.add_argument("--build")
ap.add_argument("--root", required=True)
ap.add_argument("--layers-only", action="store_true",
                help="only the include lines and cli/ (3, 4): no build needed")
a = ap.parse_args()
if not a.layers_only and not a.build:
    ap.error("--build is needed unless --layers-only")
problems = []


def nm(args):
    return subprocess.run(["nm"] + args, capture_output=True, text=True, check=True).stdout


def check_layers():
    """3 and 4: the include lines, the types, the interface headers and cli/."""
    # ---- 3. include lines ----------------------------------------------------------
    inc = re.compile(r'^\s*#\s*include\s+"(?:\.\./)?([a-z_]+)/([\w.]+)"', re.M)
    inc_local = re.compile(r'^\s*#\s*include\s+"([\w.]+)"', re.M)
    used_by = {}  # interface header -> the modules above it that include it
    # A type named qd_... in src/ is a public one's (its body, an opaque type's):
    # internal types carry the internal prefix, as internal globals do.
    public_names = set()
    for h in glob.glob(os.path.join(a.root, "include/qdot/*.h")):
        public_names |= set(re.findall(r"\bqd_[a-z]\w*", open(h, encoding="utf-8").read()))
    typedef = re.compile(r"^\s*(?:typedef\s+)?(?:struct|union|enum)\s+(qd_[a-z]\w*)\s*\{"
                         r"|^\s*\}\s*(qd_[a-z]\w*)\s*;"
                         r"|^\s*typedef\b[^;{]*?\b(qd_[a-z]\w*)\s*;", re.M)
    for path in sorted(glob.glob(os.path.join(a.root, "src", "*", "*.[ch]"))):
        rel = os.path.relpath(path, a.root)
        mod = rel.split(os.sep)[1]
        text = open(path, encoding="utf-8").read()
        for t in sorted({n for m in typedef.finditer(text) for n in m.groups() if n}):
            if t not in public_names:
                own = "qd__" if mod in KERNEL else f"qd__{PREFIX.get(mod, '?')}_"
                problems.append(f"{rel}: internal type {t} has the public prefix qd_ "
                                f"(internal: {own}...)")
        for m in inc.finditer(text):
            to, hdr = m.group(1), f"{m.group(1)}/{m.group(2)}"
            if to == "qdot" or to == mod or to not in RANK or mod not in RANK:
                continue
            if RANK[to] >= RANK[mod]:
                problems.append(f"{rel} (rank {RANK[mod]}) includes {hdr} (rank {RANK[to]})")
            if to == "base" or hdr in SHARED:
                continue
            if hdr in INTERFACE and mod in INTERFACE[hdr]:
                used_by.setdefault(hdr, set()).add(mod)
            elif hdr in INTERFACE or interface(hdr):
                problems.append(f"{rel} includes {hdr}, an interface header src/{mod} is not "
                                f"listed for (add {mod} to INTERFACE[{hdr!r}] in tests/build/"
                                "check_exports.py and to docs/design.md, \"Architecture\")")
            else:
                problems.append(f"{rel} includes {hdr}, a private header of src/{to} "
                                f"(what a higher module needs is public API or {to}/{to}_export.h)")
    for hdr, users in sorted(INTERFACE.items()):
        for mod in sorted(users - used_by.get(hdr, set())):
            problems.append(f"INTERFACE lists src/{mod} for {hdr}, which it no longer includes "
                            "(drop it from the list; with no user left the header is private: "
                            "fold it back into its module's own headers)")

    # ---- 3b. the interface headers ---------------------------------------------------
    decl = re.compile(r"^[A-Za-z_][\w \t*]*?\b(qd_\w+)\s*\(", re.M)
    found = set()
    for path in sorted(glob.glob(os.path.join(a.root, "src", "*", "*_export.h"))):
        rel = os.path.relpath(path, a.root)
        mod, name = rel.split(os.sep)[1], os.path.basename(path)
        hdr = f"{mod}/{name}"
        found.add(hdr)
        if not interface(hdr):
            problems.append(f"{rel}: an interface header is named after its module "
                            f"({mod}_export.h)")
            continue
        if mod not in RANK:
            continue
        if hdr not in INTERFACE:
            problems.append(f"{rel}: an interface header not in INTERFACE (tests/build/"
                            "check_exports.py): list it with the modules that use it")
        text = open(path, encoding="utf-8").read()
        for m in inc.finditer(text):
            to, h = m.group(1), f"{m.group(1)}/{m.group(2)}"
            if not (to in ("qdot", "base") or h in SHARED or (interface(h) and h != hdr)):
                problems.append(f"{rel} includes {h}: an interface header passes on no "
                                "private header")
        for m in inc_local.finditer(text):
            problems.append(f"{rel} includes \"{m.group(1)}\": an interface header passes on "
                            "no private header")
        for m in decl.finditer(text):
            f = m.group(1)
            other = any(f.startswith(f"qd__{t}_") for t in PREFIX.values())
            ok = ((f.startswith("qd__") and not other) if mod in KERNEL
                  else f.startswith(f"qd__{PREFIX[mod]}_"))
            if not ok:
                problems.append(f"{rel} declares {f}: not src/{mod}'s internal prefix")
    for hdr in sorted(set(INTERFACE) - found):
        problems.append(f"INTERFACE lists src/{hdr}, which does not exist")

    # ---- 4. the program ----------------------------------------------------------------
    cli_lines = 0
    for path in sorted(glob.glob(os.path.join(a.root, "cli", "*.[ch]"))):
        rel = os.path.relpath(path, a.root)
        text = open(path, encoding="utf-8").read()
        cli_lines += text.count("\n")
        for m in re.finditer(r'^\s*#\s*include\s+"([^"]+)"', text, re.M):
            h = m.group(1)
            if "/" in h and not re.fullmatch(r"qdot/[\w.]+", h):
                problems.append(f"{rel} includes {h}: the program includes only public headers "
                                "(qdot/x.h) and its own")
            elif "/" not in h and not os.path.exists(os.path.join(a.root, "cli", h)):
                problems.append(f"{rel} includes \"{h}\", not a header of cli/")
    if cli_lines > CLI_MAX_LINES:
        problems.append(f"cli/ has {cli_lines} lines, more than {CLI_MAX_LINES} (issue 31): "
                        "what it decides belongs in libqdot")
    return used_by, cli_lines


def report_layers(used_by, cli_lines):
    for p in problems:
        print(p)
    edges = sum(len(u) for u in used_by.values())
    print(f"layers: {len(used_by)} module interface headers used above their module "
          f"({edges} module edges); cli/ {cli_lines} lines")
    sys.exit(1 if problems else 0)


if a.layers_only:
    report_layers(*check_layers())

# ---- 1. exports --------------------------------------------------------------
lib = os.path.join(a.build, "libqdot.so")
exported = {l.split()[-1] for l in nm(["-D", "--defined-only", lib]).splitlines()
            if re.match(r"^\S+ [TDBR] ", l)}
bad = sorted(s for s in exported if not re.match(r"^qd_[a-z0-9]", s))
declared = set()
for h in glob.glob(os.path.join(a.root, "include/qdot/*.h")):
    for m in re.finditer(r"^QD_API\b[^;(]*?\b(qd_\w+)\s*\(", open(h).read(), re.M):
        declared.add(m.group(1))
if bad:
    problems.append("exported names that are not public qd_ names: " + " ".join(bad))
if declared - exported:
    problems.append("declared QD_API but not exported: " + " ".join(sorted(declared - exported)))
if exported - declared:
    problems.append("exported but not declared in include/qdot: "
                    + " ".join(sorted(exported - declared)))
soname = subprocess.run(["objdump", "-p", lib], capture_output=True, text=True).stdout
if not re.search(r"SONAME\s+libqdot\.so\.\d+", soname):
    problems.append("libqdot.so has no soname")
if len(declared) < 100:
    problems.append(f"suspiciously few public functions found: {len(declared)}")

# ---- 2. internal names, and what each module's objects call ------------------
objdirs = glob.glob(os.path.join(a.build, "**", "qdot_obj.dir", "src"), recursive=True)
if len(objdirs) != 1:
    print("cannot find the library's objects (qdot_obj.dir/src) under", a.build, objdirs)
    sys.exit(1)
defined, undefined = {}, {}  # symbol -> module; module -> symbols it uses
modules = sorted(os.listdir(os.path.join(a.root, "src")))
for mod in modules:
    if mod not in RANK:
        problems.append(f"src/{mod}: a module without a rank (add it to RANK and docs/design.md)")
        continue
    for o in glob.glob(os.path.join(objdirs[0], mod, "*.o")):
        for l in nm(["-g", o]).splitlines():
            f = l.split()
            if len(f) == 2 and f[0] == "U":
                undefined.setdefault(mod, set()).add(f[1])
            elif len(f) == 3 and not f[2].startswith("__odr_asan"):
                defined[f[2]] = mod  # (AddressSanitizer's ODR indicators are its own)
for sym, mod in sorted(defined.items()):
    if sym in declared:
        continue
    if not sym.startswith("qd__"):
        problems.append(f"src/{mod}: internal global {sym} lacks the internal prefix qd__")
    elif mod not in KERNEL and not sym.startswith(f"qd__{PREFIX[mod]}_"):
        problems.append(f"src/{mod}: internal global {sym} lacks its module's prefix "
                        f"qd__{PREFIX[mod]}_")
    elif mod in KERNEL and any(sym.startswith(f"qd__{t}_") for t in PREFIX.values()):
        problems.append(f"src/{mod}: internal global {sym} has another module's prefix")
calls = {}
for mod, syms in undefined.items():
    for s in syms:
        to = defined.get(s)
        if to and to != mod:
            calls.setdefault((mod, to), []).append(s)
for (mod, to), syms in sorted(calls.items()):
    if RANK[to] >= RANK[mod]:
        problems.append(f"src/{mod} (rank {RANK[mod]}) calls src/{to} (rank {RANK[to]}): "
                        + " ".join(sorted(syms)[:5]))

used_by, cli_lines = check_layers()
for p in problems:
    print(p)
print(f"{len(exported)} exported, {len(declared)} declared; {len(defined)} globals in "
      f"{len(modules)} modules, {len({k for k in calls})} module-to-module call edges all "
      f"downward; {len(used_by)} module interface headers used above their module; "
      f"cli/ {cli_lines} lines")
sys.exit(1 if problems else 0)
