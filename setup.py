# setup.py - how `pip install .` builds the qdot package: CMake builds the
# shared libqdot (no tests, no CLI) in the build's temporary directory, and
# its soname, libqdot.so.0, is copied into the package next to _lib.py, which
# loads it from there first; beside it goes qdot/_ffi.py, the cffi
# declarations python/qdot/_cdef.py makes from include/qdot.  The version is
# read from include/qdot/version.h, the one place it is written.
import os
import re
import shutil
import subprocess
import sys

from setuptools import setup
from setuptools.command.build_py import build_py
from setuptools.dist import Distribution

ROOT = os.path.dirname(os.path.abspath(__file__))
SONAME = "libqdot.so.0"
# setuptools' own build directory (build/ is CMake's): made here, since
# egg_info refuses a base that does not exist yet
os.makedirs(os.path.join(ROOT, "build-python"), exist_ok=True)


def version():
    with open(os.path.join(ROOT, "include", "qdot", "version.h")) as f:
        return re.search(r'#define QDOT_VERSION "([0-9.]+)"', f.read()).group(1)


class BuildWithLibrary(build_py):
    """build_py, and libqdot built by CMake into the package."""

    def run(self):
        super().run()
        cmake = shutil.which("cmake")
        if not cmake:
            raise SystemExit("qdot: building the package needs cmake (apt-get install cmake)")
        temp = self.get_finalized_command("build").build_temp
        tree = os.path.join(os.path.abspath(temp), "libqdot")
        jobs = os.environ.get("QDOT_JOBS", str(os.cpu_count() or 2))
        subprocess.run([cmake, "-S", ROOT, "-B", tree, "-DCMAKE_BUILD_TYPE=Release",
                        "-DQDOT_TESTS=OFF"], check=True)
        # libqdot and its optional modules (src/base/module.h): those CMake
        # configured (Cairo always; MPI and HDF5 when found), which libqdot
        # finds in qdot-modules/ beside itself
        targets = ["qdot"] + [t for t in ("qdot_cairo", "qdot_hdf5", "qdot_mpi")
                              if os.path.isdir(os.path.join(tree, "CMakeFiles", t + ".dir"))]
        subprocess.run([cmake, "--build", tree, "-j", jobs, "--target"] + targets, check=True)
        # the declarations of libqdot for cffi, made from the headers by the
        # Python that will run the package (python/qdot/_cdef.py)
        subprocess.run([sys.executable, os.path.join(ROOT, "python", "qdot", "_cdef.py"),
                        os.path.join(ROOT, "include"),
                        os.path.join(self.build_lib, "qdot", "_ffi.py")], check=True)
        dest = os.path.join(self.build_lib, "qdot", SONAME)
        shutil.copyfile(os.path.realpath(os.path.join(tree, SONAME)), dest)
        os.chmod(dest, 0o755)
        mods = os.path.join(self.build_lib, "qdot", "qdot-modules")
        os.makedirs(mods, exist_ok=True)
        for t in targets[1:]:
            shutil.copyfile(os.path.join(tree, "qdot-modules", t + ".so"),
                            os.path.join(mods, t + ".so"))
            os.chmod(os.path.join(mods, t + ".so"), 0o755)


class BinaryDistribution(Distribution):
    """The package holds a compiled library: its wheel is for this platform."""

    def has_ext_modules(self):
        return True


setup(
    version=version(),
    packages=["qdot"],
    package_dir={"": "python"},
    cmdclass={"build_py": BuildWithLibrary},
    distclass=BinaryDistribution,
    # out of CMake's build/: setuptools' build/lib and build/temp.* go here
    options={"build": {"build_base": "build-python"}, "egg_info": {"egg_base": "build-python"}},
)
