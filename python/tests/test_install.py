# python/tests/test_install.py - `make install` (cmake --install) puts the
# package where Debian's python3 looks, and the installed package loads the
# installed libqdot.so through the qdot/_paths.py the install writes.
import os
import shutil
import subprocess
import sys

import pytest

BUILD = os.environ.get("QDOT_BUILD", "")
CMAKE = shutil.which("cmake")

pytestmark = pytest.mark.skipif(not (CMAKE and os.path.exists(os.path.join(
    BUILD, "cmake_install.cmake"))), reason="needs cmake and QDOT_BUILD")


def install(dest, prefix):
    # cmake is not ours: the AddressSanitizer runtime that the sanitized
    # build preloads into Python must not be preloaded into it too (a
    # cmake under it was seen waiting on a futex for 20 minutes)
    env = {k: v for k, v in os.environ.items() if k not in ("LD_PRELOAD", "ASAN_OPTIONS")}
    env["DESTDIR"] = str(dest)
    subprocess.run([CMAKE, "--install", BUILD, "--prefix", prefix], env=env, check=True,
                   capture_output=True)


def test_prefix_usr_goes_to_debian_dist_packages(tmp_path):
    install(tmp_path, "/usr")
    pkg = tmp_path / "usr/lib/python3/dist-packages/qdot"
    assert (pkg / "__init__.py").exists() and (pkg / "_paths.py").exists()
    # Debian's python3 searches that directory
    path = subprocess.run(["/usr/bin/python3", "-c", "import sys; print(sys.path)"],
                          capture_output=True, text=True, check=True).stdout
    assert "'/usr/lib/python3/dist-packages'" in path


def test_installed_package_finds_installed_library(tmp_path):
    prefix = str(tmp_path / "prefix")
    install("", prefix)
    mm = "%d.%d" % sys.version_info[:2]
    site = os.path.join(prefix, "lib", "python" + mm, "dist-packages")
    env = {k: v for k, v in os.environ.items() if k not in ("QDOT_LIB", "PYTHONPATH")}
    env["PYTHONPATH"] = site
    code = ("import qdot; m = qdot.Model('coordinates x\\nT = x\\'^2/2\\nV = 2*x^2\\n');"
            "print(qdot._lib.path); print(m.modes()[0].omega)")
    out = subprocess.run([sys.executable, "-c", code], cwd=str(tmp_path), env=env,
                         capture_output=True, text=True, check=True).stdout.split()
    assert out[0].startswith(prefix) and out[0].endswith("libqdot.so.0")
    assert float(out[1]) == pytest.approx(2.0, rel=1e-12)


ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PKG = os.path.join(ROOT, "python")


def test_package_version_is_the_headers():
    import qdot
    with open(os.path.join(ROOT, "include", "qdot", "version.h")) as f:
        assert '#define QDOT_VERSION "%s"' % qdot.__version__ in f.read()
    assert qdot._lib.cstr(qdot._lib.lib.qd_version()) == qdot.__version__


def fake_library(tmp_path, body):
    """A shared library of one C body, standing in for another libqdot."""
    cc = shutil.which("gcc") or shutil.which("cc")
    if not cc:
        pytest.skip("needs a C compiler")
    src, so = tmp_path / "fake.c", tmp_path / "libqdot.so.0"
    src.write_text(body)
    subprocess.run([cc, "-shared", "-fPIC", "-o", str(so), str(src)], check=True)
    return str(so)


def import_with(lib):
    env = dict(os.environ, QDOT_LIB=lib, PYTHONPATH=PKG)
    return subprocess.run([sys.executable, "-c", "import qdot"], env=env, capture_output=True,
                          text=True)


@pytest.mark.parametrize("body,said", [
    ("int qd_something(void) { return 0; }\n", "has no qd_version()"),
    ('const char *qd_version(void) { return "9.9.9"; }\n', "is libqdot 9.9.9"),
])
def test_another_library_is_refused_at_import(tmp_path, body, said):
    p = import_with(fake_library(tmp_path, body))
    assert p.returncode != 0
    assert "ImportError" in p.stderr and said in p.stderr and "rebuild" in p.stderr
