# python/tests/test_jit.py - simulate's jit argument (qd_sim_opts.jit):
# the run on machine code (LLVM's ORC JIT) gives the interpreter's rows bit
# for bit, for the chaotic double pendulum of Goldstein ch. 1 (where any
# difference in one operation would grow to O(1) over the run), and the
# tier-up of a long run switches it on by itself.  Without the JIT module
# (a build without LLVM) the jit runs are interpreted: a skip.
import numpy as np
import pytest

import qdot

DOUBLE = """
coordinates a, b
parameters g = 9.81, l = 1
T = a'^2 + b'^2/2 + a'*b'*cos(a - b)
V = -2*g*cos(a) - g*cos(b)
initial a = 2, b = 1.5
"""


def test_jit_rows_are_the_interpreters_bit_for_bit():
    m = qdot.Model(DOUBLE)
    off = m.simulate(30, rtol=1e-11, jit=False)
    on = m.simulate(30, rtol=1e-11, jit=True)
    if not on.stats["jit"]:
        pytest.skip("no JIT module in this build")
    assert not off.stats["jit"]
    assert off.data.shape == on.data.shape and np.array_equal(off.data, on.data)
    assert off.energy_error_max < 1e-8   # the motion itself: energy conserved


def test_a_long_run_tiers_up_with_the_same_rows():
    m = qdot.Model(DOUBLE)
    auto = m.simulate(3000, rtol=1e-11, dt=1.0)  # ~2e6 evaluations: past QD_SIM_JIT_WORK
    off = m.simulate(3000, rtol=1e-11, dt=1.0, jit=False)
    if not m.simulate(0.1, jit=True).stats["jit"]:
        pytest.skip("no JIT module in this build")
    assert auto.stats["jit"] and not off.stats["jit"]
    assert np.array_equal(auto.data, off.data)
    assert not m.simulate(1, rtol=1e-11).stats["jit"]  # a short run never compiles


def test_a_run_predicted_long_tiers_up_early():
    # ~7e5 evaluations of a 44-instruction program (3e7 in all, under the
    # 5e7 done that the old rule waited for), but with the solve ~75 an
    # evaluation, predicted from the rate over the first seconds of
    # [0, 1000] past the price of compiling (QD_SIM_JIT_WORK +
    # QD_SIM_JIT_WORK_PER_INSTR per instruction)
    m = qdot.Model(DOUBLE)
    if not m.simulate(0.1, jit=True).stats["jit"]:
        pytest.skip("no JIT module in this build")
    auto = m.simulate(1000, rtol=1e-11, dt=1.0)
    off = m.simulate(1000, rtol=1e-11, dt=1.0, jit=False)
    assert auto.stats["jit"] and np.array_equal(auto.data, off.data)
    assert not m.simulate(100, rtol=1e-11, dt=1.0).stats["jit"]  # predicted short


def test_jit_argument_checked():
    with pytest.raises(TypeError, match="jit"):
        qdot.Model(DOUBLE).simulate(1, jit="yes")
