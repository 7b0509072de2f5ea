#!/usr/bin/python3
"""bench/chain_model.py - a 3-D chain of N rigid bodies joined by spherical
joints (issue 37's last workload), as a qdot model on stdout.

Body i is a slender box (mass m, length l, width w) hanging from the joint
P_{i-1} (P_0 fixed at the origin), its orientation R_i = rot_z(a_i)
rot_y(b_i) rot_x(c_i) in absolute angles (3 coordinates per body, no
constraint), its centre P_{i-1} + R_i (0, 0, -l/2), gravity along -z.  The
initial state is a twisted, tilted chain at rest, away from the angles'
singularity (b = +-pi/2), with some spin, so that every coupling is
exercised.  Energy is conserved (no forces but gravity).

Usage: chain_model.py [N]   (default 10)
"""
import sys


def model(n):
    out = ['# %d rigid bodies in a chain, spherical joints (bench/chain_model.py)' % n]
    coords = []
    for i in range(1, n + 1):
        coords += ['a%d' % i, 'b%d' % i, 'c%d' % i]
    out.append('coordinates ' + ', '.join(coords))
    out.append('parameters m = 1, l = 0.5, w = 0.05, g = 9.81')
    out.append('P0 = (0, 0, 0)')
    V = []
    for i in range(1, n + 1):
        out.append('R%d = rot_z(a%d)*rot_y(b%d)*rot_x(c%d)' % (i, i, i, i))
        out.append('C%d = P%d + R%d*(0, 0, -l/2)' % (i, i - 1, i))
        out.append('P%d = P%d + R%d*(0, 0, -l)' % (i, i - 1, i))
        out.append('body link%d mass m inertia (m*(l^2 + w^2)/12, m*(l^2 + w^2)/12, m*w^2/6) '
                   'at C%d orientation R%d' % (i, i, i))
        V.append('C%d.z' % i)
    out.append('V = m*g*(' + ' + '.join(V) + ')')
    init = []
    for i in range(1, n + 1):
        init += ['a%d = %.3f' % (i, 0.1 * i), 'b%d = %.3f' % (i, 0.3 - 0.05 * i),
                 'c%d = %.3f' % (i, 0.2 + 0.02 * i), "a%d' = %.3f" % (i, 0.5 if i == n else 0)]
    out.append('initial ' + ', '.join(init))
    return '\n'.join(out) + '\n'


if __name__ == '__main__':
    sys.stdout.write(model(int(sys.argv[1]) if len(sys.argv) > 1 else 10))
