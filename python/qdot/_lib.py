# python/qdot/_lib.py - libqdot loaded with cffi in ABI mode: where the
# shared library is found, and the declarations the package calls it with.
#
# Nothing about a struct, a prototype or an enum value is written here: the
# declarations are the headers themselves, run through the C preprocessor
# (python/qdot/_cdef.py).  An installed package carries them as the module
# qdot._ffi (written by setup.py and make install from the headers of the
# tree it was built from); in a source tree they are its build's
# python/_ffi.py if that was made from the same headers (a digest of them is
# in it), else made at import from ../../include.  A field added to a header
# is therefore in the next import's layout, and lib.qd_... has the header's
# prototype.
"""Low-level cffi bindings of libqdot (internal to the package)."""

import ctypes.util
import os

_HERE = os.path.dirname(os.path.abspath(__file__))
# The soname: the ABI the package was written for (the unversioned
# libqdot.so is a development link, absent where only the runtime is).
_SONAME = "libqdot.so.0"
# The version of include/qdot/version.h this package was written with.
VERSION = "0.1.0"
_SOURCE_INCLUDE = os.path.normpath(os.path.join(_HERE, "..", "..", "include"))


def _build_dirs():
    """Build trees whose python/_ffi.py a source tree's package may use."""
    env = os.environ.get("QDOT_LIB")
    if env:
        yield env if os.path.isdir(env) else os.path.dirname(env)
    yield os.path.join(_HERE, "..", "..", "build")


def _built_for_source():
    """The module python/_ffi.py of a build tree (CMake's qdot_python_ffi)
    when it was made from exactly these headers (its HEADERS digest), else
    None: a header edited since the last make is read afresh."""
    import importlib.util
    from . import _cdef
    digest = None
    for d in _build_dirs():
        path = os.path.join(d, "python", "_ffi.py")
        if not os.path.exists(path):
            continue
        digest = digest or _cdef.headers_digest(_SOURCE_INCLUDE)
        with open(path) as f:
            if ("HEADERS = %r\n" % digest) not in f.read():
                continue
        spec = importlib.util.spec_from_file_location("qdot._ffi", path)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        return mod
    return None


def _make_ffi():
    """(FFI, floating #defines) of the headers: qdot._ffi when installed; in
    a source tree, its build's python/_ffi.py made from the same headers,
    else the cdef made now from ../../include."""
    try:
        from . import _ffi
        return _ffi.ffi, _ffi.FLOATS
    except ImportError:
        pass
    if not os.path.exists(os.path.join(_SOURCE_INCLUDE, "qdot", "qdot.h")):
        raise ImportError("qdot: the package has no qdot/_ffi.py (the declarations made "
                          "from the headers) and no source tree's include/ beside it; "
                          "install it with `pip install .` at the source tree's root")
    try:
        import cffi  # noqa: F401 (Debian: python3-cffi)
    except ImportError:
        raise ImportError("qdot: needs cffi (apt-get install python3-cffi)") from None
    from . import _cdef
    try:
        built = _built_for_source()
        if built:
            return built.ffi, built.FLOATS
        return _cdef.ffi_of(_SOURCE_INCLUDE), _cdef.floats(_SOURCE_INCLUDE)
    except (OSError, ValueError) as err:  # no cc, or the preprocessor failed
        raise ImportError("qdot: cannot read the headers in %s (%s); install the package "
                          "with `pip install .`" % (_SOURCE_INCLUDE, err)) from None


ffi, FLOATS = _make_ffi()  # FLOATS: {"QD_SS_RANK_TOL": 1e-9, ...}


def _candidates():
    """The paths tried for libqdot.so.0, in the documented order."""
    env = os.environ.get("QDOT_LIB")
    if env:
        # a directory (a build tree) or the library file itself
        yield os.path.join(env, _SONAME) if os.path.isdir(env) else env
        return
    # the package's own copy, put there by `pip install`
    yield os.path.join(_HERE, _SONAME)
    # python/qdot/ in a source tree: its build/ directory
    yield os.path.join(_HERE, "..", "..", "build", _SONAME)
    try:
        from . import _paths  # written by `make install`
        yield os.path.join(_paths.LIBDIR, _SONAME)
    except ImportError:
        pass
    found = ctypes.util.find_library("qdot")
    if found:
        yield found


def _checked(handle, path):
    """handle, once its qd_version() is VERSION; else ImportError saying what to do."""
    try:
        qd_version = handle.qd_version
    # a missing symbol: AttributeError from an in-line FFI, ffi.error from qdot._ffi
    except (AttributeError, getattr(ffi, "error", AttributeError)):
        raise ImportError("qdot: %s has no qd_version(): it is older than this package "
                          "(%s); rebuild libqdot from the same source tree, or reinstall "
                          "with `pip install .`" % (path, VERSION)) from None
    have = ffi.string(qd_version()).decode()
    if have != VERSION:
        raise ImportError("qdot: the package is %s but %s is libqdot %s; rebuild the library "
                          "from the same source tree (or point QDOT_LIB at a matching one)"
                          % (VERSION, path, have))
    return handle


def _load():
    """(lib, path): the first candidate that loads, else ImportError naming them all."""
    tried = []
    for path in _candidates():
        if os.path.isabs(path) and not os.path.exists(path):
            tried.append(path)
            continue
        try:
            handle = ffi.dlopen(path)
        except OSError as err:
            tried.append("%s (%s)" % (path, err))
            continue
        return _checked(handle, path), path
    raise ImportError("qdot: cannot find %s; install the package with `pip install .` at the "
                      "source tree's root, or set QDOT_LIB to the library or the build "
                      "directory (tried: %s)" % (_SONAME, ", ".join(tried) or "nothing"))


lib, path = _load()
NULL = ffi.NULL

# The destructors are resolved now, not at their first call: in ABI mode
# cffi builds a function on first access under its parser's lock, and a
# __del__ run by the garbage collector inside ffi.new (which holds that
# lock) would wait for it forever.
for _name in dir(lib):
    if _name.endswith(("_free", "_unload")):
        getattr(lib, _name)

QD_OK = lib.QD_OK
QD_FMT_TEXT, QD_FMT_LATEX, QD_FMT_C, QD_FMT_SYMPY = (lib.QD_FMT_TEXT, lib.QD_FMT_LATEX,
                                                     lib.QD_FMT_C, lib.QD_FMT_SYMPY)


def new(ctype, init=None):
    """ffi.new of one zeroed C object: new("qd_diag") is a qd_diag *."""
    return ffi.new(ctype + " *", init)


def exprs(seq):
    """A C array of expression pointers from a Python sequence."""
    return ffi.new("const qd_expr *[]", list(seq) or 1)


def doubles(seq):
    """A C array of doubles from a Python sequence."""
    return ffi.new("double[]", [float(x) for x in seq] or 1)


def cstr(p):
    """A C string as str (None for NULL)."""
    return ffi.string(p).decode() if p else None


def buf_text(buf):
    """The text in a qd_buf (a qd_buf *), then the buffer freed."""
    try:
        return ffi.string(buf.s).decode() if buf.s else ""
    finally:
        lib.qd_buf_free(buf)


def doubles_of(ptr, n):
    """n doubles at ptr as a numpy array (a copy)."""
    import numpy as np
    if n == 0 or not ptr:
        return np.zeros(n)
    return np.frombuffer(ffi.buffer(ptr, n * ffi.sizeof("double")), dtype=float).copy()
