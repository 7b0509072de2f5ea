# python/tests/test_relativity.py - qdot.lorentz, qdot.proper_time and qdot.collide against
# Desloge vol. 2 ch. 86-91 (seed 000_46d037099a6cfcd7.txt; /work/shared/reference/
# seed-desloge-D.md T11, T13, T16, T21, pitfall P7): the same cases as tests/rel/test_lorentz.c,
# through the package.
import math

import numpy as np
import pytest

import qdot


def test_T11_velocity_and_T21_boost():
    r = qdot.lorentz((0.6, 0, 0), velocity=(0, 0.5, 0))
    assert r.velocity == pytest.approx([-0.6, 0.4, 0], abs=1e-15)
    assert r.particle_gamma == pytest.approx(5 * math.sqrt(3) / 6, rel=1e-15)
    g = np.diag([1, 1, 1, -1])
    assert np.abs(r.boost.T @ g @ r.boost - g).max() < 1e-15
    assert r.metric_error == 0


def test_T13_twin_paradox():
    r = qdot.lorentz((-0.8, 0, 0), event=(5, 4, 0, 0))
    assert r.event == pytest.approx([41 / 3, 40 / 3, 0, 0], rel=1e-14)
    assert qdot.proper_time([0.8, 0, 0], 0, 10).proper_time == pytest.approx(6, rel=1e-13)
    tau = qdot.proper_time(["t/sqrt(1 + t^2)", 0, 0], 0, 2)
    assert tau.proper_time == pytest.approx(math.asinh(2), rel=1e-12)


def test_P7_composition_is_ordered():
    r = qdot.lorentz((0.6, 0, 0), compose=(0, 0.5, 0))
    assert r.composed == pytest.approx([0.6, 0.4, 0])
    assert math.hypot(*r.composed) == pytest.approx(math.hypot(*r.composed_reverse))
    assert r.wigner_angle > 0.17


def test_momentum_invariant_mass():
    r = qdot.lorentz((0.1, -0.7, 0.3), momentum={"m": 2, "v": (0.3, 0.4, -0.2)})
    assert r.invariant_mass == pytest.approx(2, rel=1e-13)
    assert r.energy ** 2 - sum(p * p for p in r.momentum) == pytest.approx(4, rel=1e-12)


def test_T16_merge_elastic_threshold_decay():
    c = qdot.collide([(1, (0.6, 0, 0)), (2, (-0.8, 0, 0))], merge=True)
    assert c.invariant_mass == pytest.approx(math.sqrt(2496) / 12, rel=1e-14)
    assert c.velocity == pytest.approx([-23 / 55, 0, 0], rel=1e-14)
    assert c.merged.mass > 3
    e = qdot.collide([(2, (0.9, 0, 0)), {"m": 1}], elastic=True, angle=0.4)
    assert len(e.final) == 2 and all(f.lab_angles[0] == pytest.approx(0.4) for f in e.final)
    t = qdot.collide([(1, (0.99, 0, 0)), (1, (0, 0, 0))], threshold=[1, 1, 1, 1])
    assert t.threshold.kinetic_energy == pytest.approx(6) and t.threshold.allowed
    d = qdot.collide([(139.57039, (0.5, 0, 0))], decay=(105.6583755, 0), cm_angle=1.0)
    assert d.pstar == pytest.approx((139.57039 ** 2 - 105.6583755 ** 2) / (2 * 139.57039))


def test_refusals():
    with pytest.raises(qdot.Error, match="not below c = 1"):
        qdot.lorentz((1, 0, 0))
    with pytest.raises(qdot.Error, match="not below c = 2"):
        qdot.collide([(1, (0, 2, 0))], c=2)


def test_library_decides_what_goes_together():
    # qd_lorentz_run and qd_collide_run, the same rules as `qdot lorentz` and `qdot collide`
    with pytest.raises(qdot.Error, match="with the particle's velocity"):
        qdot.lorentz((0.6, 0, 0), acceleration=(1, 0, 0))
    with pytest.raises(qdot.Error, match="exactly two particles"):
        qdot.collide([(1, (0, 0, 0))], elastic=True, cm_angle=1)
    d = qdot.collide([(1, (0.5, 0, 0))], decay=(0.3, 0.3))
    assert d.conservation_error < 1e-14
