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
    env = dict(os.environ, DESTDIR=str(dest))
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
            "print(qdot._lib.lib._name); print(m.modes()[0].omega)")
    out = subprocess.run([sys.executable, "-c", code], cwd=str(tmp_path), env=env,
                         capture_output=True, text=True, check=True).stdout.split()
    assert out[0].startswith(prefix) and out[0].endswith("libqdot.so")
    assert float(out[1]) == pytest.approx(2.0, rel=1e-12)
