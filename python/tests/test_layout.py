# python/tests/test_layout.py - the package's declarations of libqdot (cffi,
# python/qdot/_cdef.py) are the headers: every struct cffi knows is laid out
# as the C compiler lays it out, and a field added to a header moves the
# layout the package sees without anything in python/qdot changing.
#
# In ABI mode cffi computes sizeof and offsetof itself from the declarations
# (the C compiler never sees them together with the headers); this compiles
# one program printing offsetof() of every field of every struct in the
# cdef, and compares.  A disagreement would be cffi's layout rules against
# gcc's (bool, enums, nested arrays), not a hand-kept mirror.
import os
import re
import shutil
import subprocess

import pytest

from conftest import ROOT
from qdot import _lib, _cdef

CC = shutil.which("cc") or shutil.which("gcc")
INCLUDE = os.path.join(ROOT, "include")


def structs(ffi):
    """{typedef name: [field names]} of every complete struct of the cdef."""
    out = {}
    for name in ffi.list_types()[0]:
        t = ffi.typeof(name)
        if t.kind == "struct" and t.fields is not None:
            out[name] = [f for f, _ in t.fields]
    return out


def c_layout(tmp_path, items):
    """{C type: (sizeof, {field: offsetof})} from the compiler."""
    lines = ["#include <stdio.h>", "#include <stddef.h>", '#include "qdot/qdot.h"',
             "int main(void) {"]
    for ctype, fields in sorted(items.items()):
        lines.append('  printf("%s sizeof %%zu\\n", sizeof(%s));' % (ctype, ctype))
        for field in fields:
            lines.append('  printf("%s %s %%zu\\n", offsetof(%s, %s));'
                         % (ctype, field, ctype, field))
    lines += ["  return 0;", "}"]
    src = tmp_path / "layout.c"
    src.write_text("\n".join(lines) + "\n")
    exe = tmp_path / "layout"
    subprocess.run([CC, "-std=c11", "-I", INCLUDE, str(src), "-o", str(exe)], check=True)
    table = {}
    for line in subprocess.run([str(exe)], check=True, capture_output=True,
                               text=True).stdout.splitlines():
        ctype, field, value = line.split()
        entry = table.setdefault(ctype, [0, {}])
        if field == "sizeof":
            entry[0] = int(value)
        else:
            entry[1][field] = int(value)
    return table


@pytest.mark.skipif(not CC, reason="no C compiler")
def test_cffi_lays_out_every_struct_as_the_compiler(tmp_path):
    ffi = _lib.ffi
    items = structs(ffi)
    # the structs the package reads are among them (and about two hundred more)
    for name in ("qd_diag", "qd_eom", "qd_sim_stats", "qd_sim_opts", "qd_statespace",
                 "qd_collide_in", "qd_speeds_eom", "qd_scene_point"):
        assert name in items, name
    table = c_layout(tmp_path, items)
    wrong = []
    for ctype, fields in items.items():
        size, offsets = table[ctype]
        if ffi.sizeof(ctype) != size:
            wrong.append("%s: sizeof cffi %d, C %d" % (ctype, ffi.sizeof(ctype), size))
        for field in fields:
            if ffi.offsetof(ctype, field) != offsets[field]:
                wrong.append("%s.%s: cffi %d, C %d"
                             % (ctype, field, ffi.offsetof(ctype, field), offsets[field]))
    assert not wrong, "\n".join(wrong)


@pytest.mark.skipif(not CC, reason="no C compiler")
def test_a_field_added_to_a_header_reaches_the_package(tmp_path):
    """The drift ctypes mirrors allowed: a field added in C.  Here the next
    cdef has it, and every offset after it moves with the compiler's."""
    inc = tmp_path / "include"
    shutil.copytree(INCLUDE, inc)
    sim_h = inc / "qdot" / "sim.h"
    text = sim_h.read_text()
    head = re.search(r"typedef struct qd_sim_stats \{\n", text)
    assert head, "qd_sim_stats not found in sim.h"
    sim_h.write_text(text[:head.end()] + "    double added_in_c;\n" + text[head.end():])
    new = _cdef.ffi_of(str(inc))
    old = _lib.ffi
    assert [f for f, _ in new.typeof("qd_sim_stats").fields][0] == "added_in_c"
    assert new.sizeof("qd_sim_stats") == old.sizeof("qd_sim_stats") + 8
    assert new.offsetof("qd_sim_stats", "stop") == old.offsetof("qd_sim_stats", "stop") + 8


def test_enums_and_defines_are_the_headers():
    lib = _lib.lib
    with open(os.path.join(INCLUDE, "qdot", "scene.h")) as f:
        frames = int(re.search(r"#define QD_SCENE_MAX_FRAMES (\d+)", f.read()).group(1))
    assert lib.QD_SCENE_MAX_FRAMES == frames
    assert lib.QD_SCENE_ORIGIN == 2 ** (8 * _lib.ffi.sizeof("size_t")) - 1
    assert lib.QD_OK == 0 and lib.QD_FMT_SYMPY == 3
    assert _lib.FLOATS["QD_SS_RANK_TOL"] == 1e-9  # a floating #define, beside the cdef
    assert _lib.FLOATS == _cdef.floats(INCLUDE)


def test_every_exported_function_is_declared():
    """Each QD_API function of the headers is in the cdef (none lost to the
    filtering of the preprocessed text), and no static inline one."""
    cdef = _cdef.generate(INCLUDE)
    names = set()
    for h in os.listdir(os.path.join(INCLUDE, "qdot")):
        with open(os.path.join(INCLUDE, "qdot", h)) as f:
            text = re.sub(r"/\*.*?\*/", "", f.read(), flags=re.S)
        names |= set(re.findall(r"QD_API[^;{]*?\b(qd_\w+)\s*\(", text))
    assert len(names) > 300, len(names)
    missing = [n for n in sorted(names) if not re.search(r"\b%s\s*\(" % n, cdef)]
    assert not missing, missing
    assert "qd_slot_coord" not in cdef


@pytest.mark.skipif(not CC, reason="no C compiler")
def test_source_tree_uses_a_build_only_of_the_same_headers(tmp_path, monkeypatch):
    """A source tree's package takes its build's python/_ffi.py (no pycparser
    at import) only while the digest of the headers in it matches: after a
    header is edited, and until make runs again, the cdef is made afresh."""
    build = tmp_path / "build"
    (build / "python").mkdir(parents=True)
    _cdef.write_module(INCLUDE, str(build / "python" / "_ffi.py"))  # as make does
    monkeypatch.setenv("QDOT_LIB", str(build))
    mod = _lib._built_for_source()
    assert mod is not None and mod.ffi.sizeof("qd_eom") == _lib.ffi.sizeof("qd_eom")
    assert mod.FLOATS == _cdef.floats(INCLUDE)
    inc = tmp_path / "include"
    shutil.copytree(INCLUDE, inc)
    with open(inc / "qdot" / "modes.h", "a") as f:
        f.write("/* edited */\n")
    assert _cdef.headers_digest(str(inc)) != _cdef.headers_digest(INCLUDE)
    monkeypatch.setattr(_lib, "_SOURCE_INCLUDE", str(inc))
    assert _lib._built_for_source() is None
