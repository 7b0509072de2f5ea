# python/tests/test_scene.py - Model.scene and Model.scene_shape (qdot/scene.h,
# issue 36): the flagship double pendulum (Goldstein ch. 1 ex. 22), written
# with named positions, has the points (x1, y1) and (x2, y2); a bob swinging
# on a unit rod about the origin gives one rod of length 1 in the x-y plane.
import os

import numpy as np

import qdot

EX = os.path.join(os.path.dirname(__file__), "..", "..", "examples")


def test_named_positions_are_points():
    m = qdot.Model.load(os.path.join(EX, "double_pendulum.qd"))
    pts = m.scene()
    assert [p["name"] for p in pts] == ["x1,y1", "x2,y2"]
    assert all(p["kind"] == "position" for p in pts)
    assert pts[0]["position"] == ["l1*sin(theta1)", "-l1*cos(theta1)", "0"]
    assert m.scene(which=1) == []  # no particle


def test_rod_and_plane_from_frames():
    th = np.linspace(0, 1.5, 40)
    bob = np.stack([np.sin(th), -np.cos(th), 0 * th], axis=1)
    far = bob + np.stack([0 * th + 0.5, 0.3 * th, 0 * th], axis=1)  # a varying distance
    shape = qdot.Model.scene_shape(np.stack([bob, far], axis=1))
    assert shape["plane"] == (0, 1)
    assert [(a, b) for a, b, _ in shape["rods"]] == [(-1, 0)]
    assert abs(shape["rods"][0][2] - 1) < 1e-12


def test_bodies_drawn_as_their_shapes():
    # Desloge ch. 50 Problem 1: rods read off their inertia rod(m, l), meeting at
    # the hinge at every frame; Byerly Art. 9c: the disk of its shape line on the
    # incline its `rolls` names
    a = qdot.Model.load(os.path.join(EX, "double_rod_pendulum.qd")).animate(1)
    rods = a.json["points"]
    assert [(p["shape"], p["size"][0], p["axis"]) for p in rods] == [("rod", 1.2, 2),
                                                                     ("rod", 0.9, 2)]
    pos = np.array(a.json["pos"]).reshape(-1, 2, 3)
    rot = np.array(a.json["rot"]).reshape(-1, 2, 3, 3)
    ends = [pos[:, i] + s * rods[i]["size"][0] / 2 * rot[:, i, :, 2]
            for i in (0, 1) for s in (-1, 1)]
    hinge = np.min([np.linalg.norm(ends[i] - ends[j], axis=1) for i in (0, 1) for j in (2, 3)],
                   axis=0)
    assert hinge.max() < 1e-5  # the page's 7 digits
    d = qdot.Model.load(os.path.join(EX, "disk_incline_shape.qd")).animate(1).json["points"][0]
    assert d["shape"] == "disk" and d["size"][0] == 0.3 and not d["inferred"]
    assert np.allclose(d["ground"], [np.sin(0.3), np.cos(0.3), 0, 0, 0, 0], atol=1e-7)
