"""qdot.tour(): the kernel's tour (qd_tour_print) reaches the double
pendulum's mass matrix M = [[(m1 + m2) l1^2, m2 l1 l2 cos(theta1 - theta2)],
[., m2 l2^2]] (Goldstein 1.4, Desloge ch. 71), so at theta1 - theta2 = 0.5
and unit masses and lengths M = [[2, cos 0.5], [cos 0.5, 1]]."""
import math
import re

import qdot


def test_tour_mass_matrix():
    text = qdot.tour()
    m = re.search(r"M = \[\[([-\d.]+), ([-\d.]+)\], \[([-\d.]+), ([-\d.]+)\]\]", text)
    assert m, text
    got = [float(v) for v in m.groups()]
    assert abs(got[0] - 2) < 1e-6 and abs(got[3] - 1) < 1e-6
    assert abs(got[1] - math.cos(0.5)) < 1e-6 and got[1] == got[2]
    assert "M12 =      l1*l2*m2*cos(theta1 - theta2)" in text
