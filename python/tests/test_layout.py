# python/tests/test_layout.py - the ctypes mirrors of the C structs
# (python/qdot/_lib.py) against the headers, as the C compiler lays them out.
#
# A field inserted in C and not in _lib.py would silently shift every offset
# after it; this compiles a small program that prints offsetof() of each
# mirrored field and compares it with ctypes' offset of the same name.
import os
import re
import shutil
import subprocess
import ctypes

import pytest

from conftest import ROOT
from qdot import _lib

DOC = re.compile(r"^(qd_\w+) \((qdot/\w+\.h)\)")
# Python names for C fields that are Python keywords
C_NAME = {"lam": "lambda"}


def mirrors():
    """(Python class, C type, header) for every struct _lib.py mirrors."""
    out = []
    for name in dir(_lib):
        cls = getattr(_lib, name)
        if isinstance(cls, type) and issubclass(cls, ctypes.Structure) and cls.__doc__:
            m = DOC.match(cls.__doc__.strip())
            if m:
                out.append((cls, m.group(1), m.group(2)))
    return out


def c_layout(tmp_path, items):
    """{C type: (sizeof, {field: offsetof})} from the compiler."""
    headers = sorted({h for _, _, h in items})
    lines = ["#include <stdio.h>", "#include <stddef.h>"]
    lines += ['#include "%s"' % h for h in headers]
    lines.append("int main(void) {")
    for cls, ctype, _ in items:
        lines.append('  printf("%s sizeof %%zu\\n", sizeof(%s));' % (ctype, ctype))
        for field in cls._fields_:
            if not field[0].startswith("_"):
                lines.append('  printf("%s %s %%zu\\n", offsetof(%s, %s));'
                             % (ctype, field[0], ctype, C_NAME.get(field[0], field[0])))
    lines += ["  return 0;", "}"]
    src = tmp_path / "layout.c"
    src.write_text("\n".join(lines) + "\n")
    exe = tmp_path / "layout"
    subprocess.run([shutil.which("cc") or "gcc", "-std=c11", "-I",
                    os.path.join(ROOT, "include"), str(src), "-o", str(exe)], check=True)
    table = {}
    for line in subprocess.run([str(exe)], check=True, capture_output=True,
                               text=True).stdout.splitlines():
        ctype, field, value = line.split()
        size, fields = table.setdefault(ctype, [0, {}])
        if field == "sizeof":
            table[ctype][0] = int(value)
        else:
            fields[field] = int(value)
    return table


@pytest.mark.skipif(not (shutil.which("cc") or shutil.which("gcc")), reason="no C compiler")
def test_mirrors_match_the_headers(tmp_path):
    items = mirrors()
    # every Structure documented as a C struct is checked (there are 16 or so)
    assert len(items) >= 10, [c for _, c, _ in items]
    table = c_layout(tmp_path, items)
    wrong = []
    for cls, ctype, _ in items:
        size, fields = table[ctype]
        for field in cls._fields_:
            name = field[0]
            if name.startswith("_"):
                continue
            if getattr(cls, name).offset != fields[name]:
                wrong.append("%s.%s: ctypes %d, C %d"
                             % (ctype, name, getattr(cls, name).offset, fields[name]))
        named = [f for f in cls._fields_ if not f[0].startswith("_")]
        last = getattr(cls, named[-1][0])
        # the mirror covers the whole C struct: its last field ends where C's
        # does (up to padding), so no C field after it is missing
        if ctypes.sizeof(cls) < size or last.offset + last.size + 8 < size:
            wrong.append("%s: C sizeof %d, the mirror ends at %d (a field missing at the end?)"
                         % (ctype, size, last.offset + last.size))
    assert not wrong, "\n".join(wrong)
