# python/qdot/_cdef.py - the declarations cffi reads (ffi.cdef), made from
# the real headers: the C preprocessor expands include/qdot/qdot.h, and only
# what its line markers place in a file under include/qdot is kept (stddef.h,
# stdbool.h and stdint.h stay out: cffi knows size_t, _Bool, uint64_t).
# static inline functions are dropped (libqdot does not export them) and the
# integer #defines of the headers (QD_SCENE_MAX_FRAMES 3600) are appended,
# since cffi takes "#define NAME 123" in a cdef; the floating ones
# (QD_SS_RANK_TOL 1e-9) go beside it, as FLOATS.
#
# Nothing here is written by hand about a struct, a field or an enum value:
# a field added to a header is in the next build's cdef.  Run as a program
# it prints the cdef (python3 python/qdot/_cdef.py include), or writes the
# module qdot._ffi that setup.py and make install put in the package
# (python3 python/qdot/_cdef.py include OUT/_ffi.py).
"""The cffi cdef of libqdot, generated from include/qdot (internal)."""

import contextlib
import hashlib
import io
import os
import re
import shutil
import subprocess
import sys

_MARKER = re.compile(r'^# (\d+) "([^"]*)"')
_INT_DEFINE = re.compile(r"^#define (QD_[A-Z0-9_]+) "
                         r"(\(\(size_t\)-?\d+\)|-?\d+u?|\(\(size_t\)\d+ << \d+\))$")
_FLOAT_DEFINE = re.compile(r"^#define (QD_[A-Z0-9_]+) "
                           r"(-?(?:\d+\.\d*|\d*\.\d+|\d+)(?:[eE][-+]?\d+)?)$")


def _compiler():
    cc = os.environ.get("CC") or shutil.which("cc") or shutil.which("gcc")
    if not cc:
        raise OSError("no C compiler (cc) to read the headers with")
    return cc.split()


def _run(args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def _drop_inline(text):
    """text without its static inline function definitions."""
    out = []
    i = 0
    for m in re.finditer(r"static\s+inline\b", text):
        if m.start() < i:
            continue
        out.append(text[i:m.start()])
        j = text.index("{", m.end())
        depth = 0
        while True:
            if text[j] == "{":
                depth += 1
            elif text[j] == "}":
                depth -= 1
                if depth == 0:
                    break
            j += 1
        i = j + 1
    out.append(text[i:])
    return "".join(out)


def _size_t_value(expr):
    """The value of a define like 3600, 4u, ((size_t)-1) or ((size_t)64 << 20)."""
    if not expr.startswith("((size_t)"):
        return int(expr.rstrip("u"))  # 4u: an unsigned flag
    body = expr[len("((size_t)"):-1]
    if "<<" in body:
        a, b = body.split("<<")
        return int(a) << int(b)
    return int(body) % (1 << 64)


def generate(include_dir):
    """The cdef text for the headers under include_dir (which holds qdot/)."""
    include_dir = os.path.abspath(include_dir)
    top = os.path.join(include_dir, "qdot", "qdot.h")
    ours = os.path.join(include_dir, "qdot") + os.sep
    cc = _compiler()
    # __attribute__((format(...))) and the like vanish; QDOT_BUILD stays
    # undefined, so QD_API is empty
    flags = ["-std=c11", "-E", "-D__attribute__(x)=", "-I", include_dir, top]
    keep = []
    current = top
    for line in _run(cc + flags).splitlines():
        m = _MARKER.match(line)
        if m:
            current = os.path.abspath(os.path.join(include_dir, m.group(2)))
            continue
        if line.startswith("#"):
            continue
        if current.startswith(ours):
            keep.append(line)
    text = _drop_inline("\n".join(keep))
    ints = _defines(include_dir)[0]
    defines = ["#define %s %d" % kv for kv in sorted(ints.items())]
    lines = [l for l in text.splitlines() if l.strip()]
    return "\n".join(lines + defines) + "\n"


def _defines(include_dir):
    """({name: int}, {name: float}) of the headers' QD_ #defines that are one
    number: cffi takes the integers in a cdef, not the floating ones."""
    include_dir = os.path.abspath(include_dir)
    top = os.path.join(include_dir, "qdot", "qdot.h")
    ints, floats = {}, {}
    for line in _run(_compiler() + ["-std=c11", "-E", "-dM", "-I", include_dir,
                                    top]).splitlines():
        m = _INT_DEFINE.match(line.strip())
        if m:
            ints[m.group(1)] = _size_t_value(m.group(2))
            continue
        m = _FLOAT_DEFINE.match(line.strip())
        if m:
            floats[m.group(1)] = float(m.group(2))
    return ints, floats


def floats(include_dir):
    """{name: value} of the floating #defines (QD_SS_RANK_TOL 1e-9)."""
    return dict(sorted(_defines(include_dir)[1].items()))


def headers_digest(include_dir):
    """sha256 of include_dir/qdot/*.h and of this file: what the cdef is made of."""
    h = hashlib.sha256()
    qdot = os.path.join(include_dir, "qdot")
    for name in sorted(os.listdir(qdot)) + [None]:
        path = os.path.abspath(__file__) if name is None else os.path.join(qdot, name)
        if name is not None and not name.endswith(".h"):
            continue
        with open(path, "rb") as f:
            data = f.read()
        h.update(b"%s %d\n" % ((name or "_cdef.py").encode(), len(data)))
        h.update(data)
    return h.hexdigest()


def ffi_of(include_dir):
    """A cffi.FFI holding the cdef of the headers under include_dir."""
    import cffi
    ffi = cffi.FFI()
    ffi.cdef(generate(include_dir))
    return ffi


def write_module(include_dir, path):
    """Write the out-of-line ABI module (cffi's "ffi = FFI(...)" with the
    types already parsed) to path: the package imports it as qdot._ffi,
    without a compiler or pycparser at import time."""
    ffi = ffi_of(include_dir)
    ffi.set_source("qdot._ffi", None)
    tmp = path + ".tmp"
    with contextlib.redirect_stdout(io.StringIO()):  # cffi says "generating ..."
        ffi.emit_python_code(tmp)
    with open(tmp, "a") as f:
        # the floating #defines, which a cdef cannot hold
        f.write("FLOATS = %r\n" % floats(include_dir))
        # a source tree uses the module only while this matches
        f.write("HEADERS = %r\n" % headers_digest(include_dir))
    os.replace(tmp, path)


def main(argv):
    """_cdef.py INCLUDE_DIR            prints the cdef
    _cdef.py INCLUDE_DIR OUT.py     writes the module qdot._ffi to OUT.py"""
    here = os.path.dirname(os.path.abspath(__file__))
    inc = argv[1] if len(argv) > 1 else os.path.join(here, "..", "..", "include")
    if len(argv) > 2:
        write_module(inc, argv[2])
    else:
        sys.stdout.write(generate(inc))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
