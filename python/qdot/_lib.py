# python/qdot/_lib.py - libqdot loaded with ctypes: where the shared library
# is found, the C structs the package reads, and every prototype it calls.
#
# Only the public API of include/qdot/*.h is declared here; the struct
# layouts mirror those headers field for field (a field added in C must be
# added here in the same place, or the offsets after it go wrong;
# python/tests/test_layout.py checks every offset against the compiler).
"""Low-level ctypes declarations of libqdot (internal to the package)."""

import ctypes
import ctypes.util
import os

from ctypes import (POINTER, Structure, c_bool, c_char, c_char_p, c_double, c_int,
                    c_size_t, c_void_p, c_long, c_uint)

_HERE = os.path.dirname(os.path.abspath(__file__))
# The soname: the ABI the package was written for (the unversioned
# libqdot.so is a development link, absent where only the runtime is).
_SONAME = "libqdot.so.0"
# The version of include/qdot/version.h this package was written with.
VERSION = "0.1.0"


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
    except AttributeError:
        raise ImportError("qdot: %s has no qd_version(): it is older than this package "
                          "(%s); rebuild libqdot from the same source tree, or reinstall "
                          "with `pip install .`" % (path, VERSION)) from None
    qd_version.restype = ctypes.c_char_p
    qd_version.argtypes = []
    have = qd_version().decode()
    if have != VERSION:
        raise ImportError("qdot: the package is %s but %s is libqdot %s; rebuild the library "
                          "from the same source tree (or point QDOT_LIB at a matching one)"
                          % (VERSION, path, have))
    return handle


def _load():
    """The first candidate that loads, else ImportError naming them all."""
    tried = []
    for path in _candidates():
        if os.path.isabs(path) and not os.path.exists(path):
            tried.append(path)
            continue
        try:
            handle = ctypes.CDLL(path)
        except OSError as err:
            tried.append("%s (%s)" % (path, err))
            continue
        return _checked(handle, path)
    raise ImportError("qdot: cannot find %s; install the package with `pip install .` at the "
                      "source tree's root, or set QDOT_LIB to the library or the build "
                      "directory (tried: %s)" % (_SONAME, ", ".join(tried) or "nothing"))


lib = _load()

Expr = c_void_p           # const qd_expr *, owned by its context

# Zeroed bytes after the structs Python allocates for C to read or fill: a
# field appended to one in C (options default to zero there) then reads 0
# or writes here instead of past the end, until this file learns of it.
_TAIL = [("_tail", c_char * 64)]
ExprArray = POINTER(c_void_p)


class Diag(Structure):
    """qd_diag (qdot/status.h): an error record."""
    _fields_ = [("status", c_int), ("subject", c_int), ("index", c_size_t),
                ("name", c_char * 64), ("reason", c_int), ("located", c_bool),
                ("line", c_size_t), ("col", c_size_t), ("offset", c_size_t),
                ("length", c_size_t), ("message", c_char * 256), ("hint", c_char * 256)]


class Buf(Structure):
    """qd_buf (qdot/print.h): a growable string the caller frees."""
    _fields_ = [("s", c_void_p), ("len", c_size_t), ("cap", c_size_t),
                ("failed", c_bool), ("alloc", c_void_p)]


class ParamValue(Structure):
    """qd_param_value (qdot/model.h)."""
    _fields_ = [("name", c_char_p), ("value", Expr)]


class ModelOpts(Structure):
    """qd_model_opts (qdot/model.h)."""
    _fields_ = [("params", POINTER(ParamValue)), ("nparams", c_size_t),
                ("fix_params", c_bool)] + _TAIL


class ReadOpts(Structure):
    """qd_read_opts (qdot/read.h)."""
    _fields_ = [("new_symbols", c_bool)] + _TAIL


class Con(Structure):
    """qd_con (qdot/mech.h)."""
    _fields_ = [("name", c_char_p), ("kind", c_int), ("expr", Expr), ("a", ExprArray),
                ("a0", Expr), ("integral", Expr), ("factor", Expr), ("lam", Expr)]


class Eom(Structure):
    """qd_eom (qdot/mech.h)."""
    _fields_ = [("n", c_size_t), ("q", ExprArray), ("qd", ExprArray), ("qdd", ExprArray),
                ("M", ExprArray), ("f", ExprArray), ("L", Expr),
                ("T2", Expr), ("T1", Expr), ("T0", Expr), ("acc", ExprArray),
                ("ncon", c_size_t), ("con", POINTER(Con)), ("A", ExprArray),
                ("b", ExprArray), ("mult", ExprArray), ("nelim", c_size_t),
                ("elim", c_void_p), ("priv", c_void_p)]


class MetricSingular(Structure):
    """qd_metric_singular (qdot/metric.h)."""
    _fields_ = [("lhs", Expr), ("rhs", Expr), ("period", Expr)]


class Metric(Structure):
    """qd_metric (qdot/metric.h)."""
    _fields_ = [("n", c_size_t), ("q", ExprArray), ("qd", ExprArray), ("qdd", ExprArray),
                ("source", Expr), ("from_L", c_bool), ("T2", Expr), ("T1", Expr),
                ("T0", Expr), ("g", ExprArray), ("ginv", ExprArray), ("det", Expr),
                ("first", ExprArray), ("second", ExprArray), ("Q", ExprArray),
                ("Qup", ExprArray), ("geodesic", ExprArray), ("constrained", c_bool),
                ("npos", c_size_t), ("pos", ExprArray), ("pos_particle", POINTER(c_size_t)),
                ("pos_axis", POINTER(c_uint)), ("jac", ExprArray), ("jac_det", Expr),
                ("e", ExprArray), ("e_det", Expr), ("nsing", c_size_t),
                ("sing", POINTER(MetricSingular)), ("sing_of", Expr), ("h", ExprArray),
                ("scale_geometric", c_bool), ("orthogonal", c_bool)]


class Ham(Structure):
    """qd_ham (qdot/hamilton.h)."""
    _fields_ = [("n", c_size_t), ("q", ExprArray), ("qd", ExprArray), ("p", ExprArray),
                ("pdef", ExprArray), ("vel", ExprArray), ("H", Expr), ("dq", ExprArray),
                ("dp", ExprArray), ("extra", ExprArray), ("H_minus_E", Expr),
                ("is_energy", c_bool), ("conserved", c_bool), ("H_given", c_bool),
                ("L_from_H", Expr), ("L_why", c_char * 256), ("implicit", c_bool)]


class Equilibrium(Structure):
    """qd_equilibrium (qdot/equilibria.h)."""
    _fields_ = [("q", POINTER(c_double)), ("exact", ExprArray), ("residual", c_double),
                ("kind", c_int), ("npos", c_size_t), ("nneg", c_size_t),
                ("nzero", c_size_t), ("symmetric", c_bool)]


class Equilibria(Structure):
    """qd_equilibria (qdot/equilibria.h)."""
    _fields_ = [("n", c_size_t), ("count", c_size_t), ("pts", POINTER(Equilibrium)),
                ("exact", c_bool), ("continuum", c_bool), ("method", c_char_p)]


class EquilibriaOut(Structure):
    """qd_equilibria as a call's result, with the zeroed tail."""
    _fields_ = Equilibria._fields_ + _TAIL


class EquilibriumChoice(Structure):
    """qd_equilibrium_choice (qdot/equilibria.h)."""
    _fields_ = [("found", Equilibria), ("from_initial", Equilibria),
                ("pt", POINTER(Equilibrium)), ("reason", c_int), ("others", c_size_t)] + _TAIL


class Linear(Structure):
    """qd_linear (qdot/modes.h)."""
    _fields_ = [("n", c_size_t), ("M", POINTER(c_double)), ("C", POINTER(c_double)),
                ("G", POINTER(c_double)), ("K", POINTER(c_double))] + _TAIL


class ModesResult(Structure):
    """qd_modes_result (qdot/modes.h)."""
    _fields_ = [("n", c_size_t), ("conservative", c_bool), ("omega2", POINTER(c_double)),
                ("shapes", POINTER(c_double)), ("neig", c_size_t),
                ("eig_re", POINTER(c_double)), ("eig_im", POINTER(c_double)),
                ("stable", c_int)] + _TAIL


class SimOpts(Structure):
    """qd_sim_opts (qdot/sim.h)."""
    _fields_ = [("method", c_int), ("t0", c_double), ("t_end", c_double), ("dt", c_double),
                ("fixed", c_bool), ("rtol", c_double), ("atol", c_double),
                ("no_project", c_bool), ("max_steps", c_size_t),
                ("q0", POINTER(c_double)), ("qd0", POINTER(c_double)),
                ("p0", POINTER(c_double)), ("u0", POINTER(c_double)),
                ("par", POINTER(c_double)), ("precision", c_int), ("every", c_double)] + _TAIL


class SimSetupOpts(Structure):
    """qd_sim_setup_opts (qdot/simsetup.h): the numbers as text."""
    _fields_ = [("t_end", c_char_p), ("dt", c_char_p), ("rtol", c_char_p), ("atol", c_char_p),
                ("every", c_char_p), ("max_steps", c_char_p), ("method", c_char_p),
                ("precision", c_int), ("no_project", c_bool), ("fixed", c_bool)] + _TAIL


class SimStop(Structure):
    """qd_sim_stop (qdot/sim.h): why a run stopped, as data."""
    _fields_ = [("code", c_int), ("t", c_double), ("value", c_double)]


class SimStats(Structure):
    """qd_sim_stats (qdot/sim.h)."""
    _fields_ = [("steps", c_size_t), ("evals", c_size_t), ("rejected", c_size_t),
                ("energy_error_max", c_double), ("constraint_error_max", c_double),
                ("E0", c_double), ("events", c_size_t), ("t", c_double),
                ("impacts", c_size_t), ("impact_energy_lost", c_double),
                ("in_contact", c_bool), ("at_rest", c_bool), ("chattering", c_bool),
                ("contact", c_size_t), ("transitions", c_size_t),
                ("friction_dissipated", c_double), ("energy_balance_error", c_double),
                ("surface_work", c_double),
                ("initial_moved_q", c_double), ("initial_moved_qd", c_double),
                ("events_unresolved", c_size_t), ("events_unresolved_t", c_double),
                ("events_unresolved_spacing", c_double),
                ("events_unresolved_event", c_size_t),
                ("energy_error_steps", c_double), ("stop", SimStop)] + _TAIL


class ScenePoint(Structure):
    """qd_scene_point (qdot/scene.h)."""
    # an array C returns: no tail, the stride is C's
    _fields_ = [("name", c_char * 96), ("kind", c_int), ("mass", Expr), ("pos", Expr * 3),
                ("comp", (c_char * 32) * 3)]


class SceneRod(Structure):
    """qd_scene_rod (qdot/scene.h)."""
    _fields_ = [("a", c_size_t), ("b", c_size_t), ("length", c_double)]


class SceneShape(Structure):
    """qd_scene_shape (qdot/scene.h)."""
    _fields_ = [("plane", c_int * 2), ("lo", c_double * 3), ("hi", c_double * 3),
                ("scale", c_double), ("rods", POINTER(SceneRod)), ("nrods", c_size_t)] + _TAIL


class StateSpace(Structure):
    """qd_statespace (qdot/statespace.h)."""
    _fields_ = [("n", c_size_t), ("nx", c_size_t), ("nu", c_size_t), ("ny", c_size_t),
                ("states", ExprArray), ("inputs", ExprArray), ("outputs", POINTER(c_char_p)),
                ("A", POINTER(c_double)), ("B", POINTER(c_double)), ("C", POINTER(c_double)),
                ("D", POINTER(c_double)), ("xdot0", POINTER(c_double)),
                ("y0", POINTER(c_double)), ("Asym", ExprArray), ("Bsym", ExprArray),
                ("Csym", ExprArray), ("Dsym", ExprArray), ("eig_re", POINTER(c_double)),
                ("eig_im", POINTER(c_double)), ("vec_re", POINTER(c_double)),
                ("vec_im", POINTER(c_double)), ("rank_ctrb", c_size_t),
                ("rank_obsv", c_size_t), ("controllable", c_bool), ("observable", c_bool),
                ("nuncontrollable", c_size_t), ("nunobservable", c_size_t),
                ("uncontrollable", POINTER(c_size_t)),
                ("unobservable", POINTER(c_size_t))] + _TAIL


class CareResult(Structure):
    """qd_care_result (qdot/control.h)."""
    _fields_ = [("n", c_size_t), ("m", c_size_t), ("X", POINTER(c_double)),
                ("K", POINTER(c_double)), ("eig_re", POINTER(c_double)),
                ("eig_im", POINTER(c_double)), ("residual", c_double), ("rcond", c_double),
                ("failure", c_int), ("mode_re", c_double), ("mode_im", c_double)] + _TAIL


SimSink = ctypes.CFUNCTYPE(c_int, c_void_p, c_int, POINTER(c_double))
# qd_sim_input_fn: u = fn(data, t, x), x = (q, q') in the equations' order
SimInputFn = ctypes.CFUNCTYPE(c_double, c_void_p, c_double, POINTER(c_double))

QD_OK = 0
QD_FMT_TEXT, QD_FMT_LATEX, QD_FMT_C, QD_FMT_SYMPY = 0, 1, 2, 3
DBL = POINTER(c_double)

_PROTOS = {
    # contexts, errors, printing (expr.h, status.h, print.h, read.h)
    "qd_ctx_new": (c_void_p, []),
    "qd_ctx_free": (None, [c_void_p]),
    "qd_ctx_status": (c_int, [c_void_p]),
    "qd_ctx_diag": (POINTER(Diag), [c_void_p]),
    "qd_ctx_clear_error": (None, [c_void_p]),
    "qd_status_str": (c_char_p, [c_int]),
    "qd_buf_free": (None, [POINTER(Buf)]),
    "qd_print": (c_int, [c_void_p, Expr, c_int, POINTER(Buf)]),
    "qd_print_time_name": (c_char_p, [c_void_p]),
    "qd_print_sympy_functions": (c_int, [c_void_p, c_size_t, ExprArray, POINTER(Buf)]),
    "qd_diag_format": (None, [POINTER(Diag), c_char_p, c_char_p, POINTER(Buf)]),
    "qd_read": (Expr, [c_void_p, c_char_p, POINTER(ReadOpts), POINTER(Diag)]),
    "qd_rat_str": (Expr, [c_void_p, c_char_p]),
    "qd_sub": (Expr, [c_void_p, Expr, Expr]),
    "qd_subs": (Expr, [c_void_p, Expr, c_size_t, ExprArray, ExprArray]),
    "qd_dt": (Expr, [c_void_p, Expr]),
    "qd_eval": (c_int, [c_void_p, Expr, c_size_t, ExprArray, DBL, DBL]),
    "qd_expr_name": (c_char_p, [Expr]),
    "qd_symbol_role": (c_int, [Expr]),
    "qd_free_symbols": (c_size_t, [c_void_p, Expr, ExprArray, c_size_t]),
    "qd_time": (Expr, [c_void_p]),
    "qd_jet": (Expr, [c_void_p, Expr, c_uint]),
    "qd_int": (Expr, [c_void_p, c_long]),
    "qd_is_number": (c_bool, [Expr]),
    # models (model.h)
    "qd_model_parse_opts": (c_void_p, [c_void_p, c_char_p, POINTER(ModelOpts), POINTER(Diag)]),
    "qd_model_free": (None, [c_void_p]),
    "qd_model_ncoords": (c_size_t, [c_void_p]),
    "qd_model_coord": (Expr, [c_void_p, c_size_t]),
    "qd_model_nparams": (c_size_t, [c_void_p]),
    "qd_model_param": (Expr, [c_void_p, c_size_t]),
    "qd_model_param_number": (c_int, [c_void_p, c_size_t, DBL]),
    "qd_model_initial": (Expr, [c_void_p, c_size_t, c_uint]),
    "qd_model_definition": (Expr, [c_void_p, c_char_p]),
    "qd_model_hamiltonian_given": (c_bool, [c_void_p]),
    "qd_model_momentum": (Expr, [c_void_p, c_size_t]),
    "qd_model_locate": (c_bool, [c_void_p, POINTER(Diag)]),
    "qd_model_nspeeds": (c_size_t, [c_void_p]),
    "qd_model_speed": (Expr, [c_void_p, c_size_t]),
    "qd_model_speed_definition": (Expr, [c_void_p, c_size_t]),
    "qd_model_speed_initial": (Expr, [c_void_p, c_size_t]),
    "qd_model_ninputs": (c_size_t, [c_void_p]),
    "qd_model_input": (Expr, [c_void_p, c_size_t]),
    "qd_model_noutputs": (c_size_t, [c_void_p]),
    "qd_model_output_name": (c_char_p, [c_void_p, c_size_t]),
    "qd_model_output": (Expr, [c_void_p, c_size_t]),
    # generalized speeds (speeds.h): only handed on, never read
    "qd_speeds_derive": (c_void_p, [c_void_p, c_void_p, c_void_p]),
    "qd_speeds_eom_free": (None, [c_void_p]),
    # equations (mech.h, hamilton.h)
    "qd_eom_derive": (POINTER(Eom), [c_void_p, c_void_p]),
    "qd_eom_free": (None, [POINTER(Eom)]),
    # the metric of the coordinates (metric.h)
    "qd_metric_new": (POINTER(Metric), [c_void_p, c_void_p]),
    "qd_metric_free": (None, [POINTER(Metric)]),
    "qd_eom_compile": (c_void_p, [c_void_p, POINTER(Eom)]),
    "qd_eom_prog_free": (None, [c_void_p]),
    "qd_eom_work_new": (c_void_p, [c_void_p, c_void_p]),
    "qd_eom_work_free": (None, [c_void_p]),
    "qd_eom_prog_eval": (c_int, [c_void_p, c_void_p, c_void_p, c_size_t, ExprArray, DBL,
                                 DBL, DBL, DBL, DBL, DBL]),
    "qd_ham_derive": (POINTER(Ham), [c_void_p, c_void_p, POINTER(Eom)]),
    "qd_ham_free": (None, [POINTER(Ham)]),
    # equilibria and modes (equilibria.h, modes.h)
    "qd_eq_kind_name": (c_char_p, [c_int]),
    "qd_equilibria_find": (c_int, [c_void_p, POINTER(Eom), c_void_p, c_size_t, ExprArray,
                                   DBL, c_void_p, POINTER(EquilibriaOut)]),
    "qd_equilibria_free": (None, [POINTER(EquilibriaOut)]),
    "qd_equilibria_choose": (c_int, [c_void_p, POINTER(Eom), c_void_p, c_size_t, ExprArray,
                                     DBL, POINTER(EquilibriumChoice)]),
    "qd_equilibrium_choice_free": (None, [POINTER(EquilibriumChoice)]),
    "qd_linear_about": (c_int, [c_void_p, POINTER(Eom), c_void_p, c_size_t, ExprArray, DBL,
                                POINTER(Linear)]),
    "qd_modes_solve": (c_int, [c_void_p, POINTER(Linear), POINTER(ModesResult)]),
    "qd_linear_free": (None, [POINTER(Linear)]),
    "qd_modes_result_free": (None, [POINTER(ModesResult)]),
    # state-space form and LQR (statespace.h, control.h)
    "qd_linearize": (c_int, [c_void_p, POINTER(Eom), c_void_p, c_size_t, ExprArray, ExprArray,
                             POINTER(StateSpace)]),
    "qd_statespace_free": (None, [POINTER(StateSpace)]),
    "qd_care_solve": (c_int, [c_void_p, c_size_t, c_size_t, DBL, DBL, DBL, DBL,
                              POINTER(CareResult)]),
    "qd_care_result_free": (None, [POINTER(CareResult)]),
    # simulation (sim.h)
    "qd_sim_new": (c_void_p, [c_void_p, c_void_p, POINTER(Eom)]),
    "qd_sim_new_hamilton": (c_void_p, [c_void_p, c_void_p]),
    "qd_sim_new_speeds": (c_void_p, [c_void_p, c_void_p, c_void_p]),
    "qd_sim_free": (None, [c_void_p]),
    "qd_sim_add_output": (c_int, [c_void_p, c_char_p, Expr]),
    "qd_sim_add_event": (c_int, [c_void_p, Expr, c_size_t, ExprArray, c_bool]),
    "qd_sim_method_from_name": (c_bool, [c_char_p, POINTER(c_int)]),
    "qd_sim_method_name": (c_char_p, [c_int]),
    "qd_stop_str": (c_char_p, [c_int]),
    "qd_stop_name": (c_char_p, [c_int]),
    "qd_stop_ok": (c_bool, [c_int]),
    "qd_sim_method_adaptive": (c_bool, [c_int]),
    "qd_sim_default_method": (c_int, [c_void_p, c_bool]),
    "qd_sim_columns": (c_size_t, [c_void_p, c_int, POINTER(c_char_p), c_size_t]),
    "qd_sim_check_opts": (c_int, [c_void_p, POINTER(SimOpts)]),
    "qd_sim_input_expr": (c_int, [c_void_p, c_char_p, Expr]),
    "qd_sim_input_callback": (c_int, [c_void_p, c_char_p, SimInputFn, c_void_p]),
    # the set-up the command line makes (simsetup.h)
    "qd_sim_setup_new": (c_void_p, [c_void_p, c_void_p, c_bool]),
    "qd_sim_setup_free": (None, [c_void_p]),
    "qd_sim_setup_sim": (c_void_p, [c_void_p]),
    "qd_sim_setup_form": (c_int, [c_void_p]),
    "qd_sim_setup_eom": (POINTER(Eom), [c_void_p]),
    "qd_sim_setup_initial": (c_int, [c_void_p, c_char_p]),
    "qd_sim_setup_output": (c_int, [c_void_p, c_char_p, c_char_p, c_size_t, c_size_t]),
    "qd_sim_setup_event": (c_int, [c_void_p, c_char_p, c_bool]),
    "qd_sim_setup_input": (c_int, [c_void_p, c_char_p, c_char_p, c_size_t, c_size_t]),
    "qd_sim_setup_options": (c_int, [c_void_p, POINTER(SimSetupOpts), POINTER(SimOpts)]),
    # scenes (scene.h)
    "qd_scene_points": (c_int, [c_void_p, c_void_p, c_uint, POINTER(POINTER(ScenePoint)),
                                POINTER(c_size_t)]),
    "qd_scene_points_free": (None, [POINTER(ScenePoint)]),
    "qd_scene_analyse": (c_int, [c_void_p, DBL, c_size_t, c_size_t, POINTER(c_size_t), c_size_t,
                                 POINTER(SceneShape)]),
    "qd_scene_shape_free": (None, [POINTER(SceneShape)]),
    "qd_sim_run": (c_int, [c_void_p, POINTER(SimOpts), SimSink, c_void_p, POINTER(SimStats),
                           DBL]),
}

for _name, (_res, _args) in _PROTOS.items():
    _fn = getattr(lib, _name)
    _fn.restype = _res
    _fn.argtypes = _args


def exprs(seq):
    """A C array of expression pointers from a Python sequence."""
    arr = (c_void_p * max(len(seq), 1))()
    for i, x in enumerate(seq):
        arr[i] = x
    return arr


def doubles(seq):
    """A C array of doubles from a Python sequence."""
    arr = (c_double * max(len(seq), 1))()
    for i, x in enumerate(seq):
        arr[i] = float(x)
    return arr


def buf_text(buf):
    """The text in a qd_buf, then the buffer freed."""
    try:
        return ctypes.string_at(buf.s).decode() if buf.s else ""
    finally:
        lib.qd_buf_free(ctypes.byref(buf))
