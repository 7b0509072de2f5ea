#!/usr/bin/env python3
"""tests/python/check_pip_install.py - the Python package installed the way
Python users install it (issue 32): `pip install --no-build-isolation
--no-index .` at the root, with Debian's python3 and its setuptools, builds
libqdot with CMake and puts its own copy of the library in the package;
then `import qdot` works from another folder with nothing on the path:

  - inside a venv made with --system-site-packages (numpy from Debian);
  - outside one (pip install --target DIR, DIR then the only path given).

The installed package must load the copy inside it (its soname,
libqdot.so.0), say its version is the library's, and compute: the
oscillator T = x'^2/2, V = 2 x^2 has omega = 2; and draw a PNG through the
optional Cairo module the package carries (qdot-modules/).  Skips (77) when Debian's
pip, venv or setuptools are missing.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PY = "/usr/bin/python3"

CODE = r"""
import os, qdot
from qdot import _lib
m = qdot.Model("coordinates x\nT = x'^2/2\nV = 2*x^2\n")
print(os.path.realpath(qdot.__file__))
print(os.path.realpath(_lib.path))
print(qdot.__version__)
print(repr(m.modes()[0].omega))
# the plot module inside the package (qdot-modules/qdot_cairo.so beside the
# library): a PNG drawn through the library's own copy, with the package's
# declarations (qdot/_ffi.py, made from the headers when it was built)
L, ffi = _lib.lib, _lib.ffi
ctx = L.qd_ctx_new()
p = L.qd_plot_new(ctx, 0, 0)
xs = ffi.new("double[]", [0, 1, 2])
ys = ffi.new("double[]", [0, 1, 4])
assert L.qd_plot_add(p, b"y = x^2", 0, 3, xs, ys, ffi.NULL) == 0
print(L.qd_plot_write(p, b"plot.png"))
L.qd_plot_free(p)
print(os.path.exists(os.path.join(os.path.dirname(qdot.__file__), "_ffi.py")))
with open("plot.png", "rb") as f:
    print(f.read(8) == b"\x89PNG\r\n\x1a\n")
"""


def have(module):
    return subprocess.run([PY, "-c", "import " + module], capture_output=True).returncode == 0


def run(cmd, **kw):
    p = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if p.returncode:
        sys.stderr.write("$ %s\n%s%s" % (" ".join(cmd), p.stdout[-4000:], p.stderr[-4000:]))
        raise SystemExit("FAIL: exit %d" % p.returncode)
    return p.stdout


def check_import(python, where, env, tmp):
    out = run([python, "-c", CODE], cwd=tmp, env=env).split("\n")
    pkg, lib, version, omega = out[0], out[1], out[2], float(out[3])
    assert out[4] == "0" and out[6] == "True", ("no plot from the package's Cairo module", out)
    assert out[5] == "True", ("the package has no qdot/_ffi.py", out)
    assert pkg.startswith(os.path.realpath(where)), (pkg, where)
    assert os.path.dirname(lib) == os.path.dirname(pkg), ("not the package's own copy", lib)
    assert os.path.basename(lib) == "libqdot.so.0", lib
    with open(os.path.join(ROOT, "include", "qdot", "version.h")) as f:
        assert '"%s"' % version in f.read(), version
    assert abs(omega - 2.0) < 1e-12, omega
    print("ok: import qdot from %s (%s), omega = %r" % (where, lib, omega))


def main():
    argparse.ArgumentParser().parse_known_args()
    if not (os.path.exists(PY) and have("pip") and have("venv") and have("setuptools")
            and have("wheel") and have("numpy") and have("cffi")):
        print("SKIP: Debian's python3-pip, -venv, -setuptools, -wheel, -numpy and -cffi are needed")
        return 77
    env = {k: v for k, v in os.environ.items()
           if k not in ("PYTHONPATH", "QDOT_LIB", "PYTHONHOME", "VIRTUAL_ENV")}
    env.setdefault("QDOT_JOBS", "2")
    env["PIP_NO_INDEX"] = "1"  # offline: nothing may come from PyPI
    with tempfile.TemporaryDirectory() as tmp:
        venv = os.path.join(tmp, "venv")
        run([PY, "-m", "venv", "--system-site-packages", venv], env=env)
        vpy = os.path.join(venv, "bin", "python")
        run([vpy, "-m", "pip", "install", "--no-build-isolation", "--no-index", ROOT],
            env=env, cwd=tmp)
        site = run([vpy, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                   env=env).strip()
        check_import(vpy, site, env, tmp)

        target = os.path.join(tmp, "site")
        run([PY, "-m", "pip", "install", "--no-build-isolation", "--no-index", "--no-deps",
             "--target", target, ROOT], env=env, cwd=tmp)
        check_import(PY, target, dict(env, PYTHONPATH=target), tmp)
    return 0


if __name__ == "__main__":
    sys.exit(main())
