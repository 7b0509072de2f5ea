#!/usr/bin/python3
"""bench/speeds_sympy.py - SymPy side of the generalized-speeds benchmark
(bench/run_speeds.py drives it; see bench/README.md).

The two systems of bench/run_speeds.py, written the way a SymPy user writes
them with sympy.physics.mechanics.KanesMethod, with the same speeds as the
qdot models:

  rolling_disk_speeds  the leaning disc of SymPy's own test_rolling_disc
                       (examples/rolling_disk_speeds.qd): built from the
                       contact point up, the contact point at rest, speeds
                       u1, u2, u3 the lean-frame components of the angular
                       velocity; 3 coordinates, no dependent speeds;
  bicycle_speeds       examples/bicycle_speeds.qd: frame, rear and steered front
                       wheel rolling upright; independent speeds v = r pr',
                       s = d', dependent x', y', th', pf' with the four
                       rolling constraints as velocity constraints.

A repetition: clear_cache() (untimed), frames, points, bodies, KanesMethod,
kanes_equations, mass_matrix and forcing with the kinematic differential
equations substituted (processor time).  Prints per system one
tab-separated line, as speeds_qdot does:
    model sympy reps median_s min_s ops
ops = count_ops summed over mass_matrix and forcing as KanesMethod returns
them; with --simplify also a line `model sympy:simplified 0 S S ops`: the
same after simplify() of every entry (S the seconds it took, or `timeout`).
Usage: speeds_sympy.py [--budget S] [--simplify] [--limit S] [model ...]
"""
import argparse
import signal
import statistics
import sys
import time

import sympy
from sympy import count_ops, symbols
from sympy.core.cache import clear_cache
from sympy.physics.mechanics import (KanesMethod, Point, ReferenceFrame, RigidBody,
                                     dynamicsymbols, inertia)


def rolling_disc():
    """SymPy's rolling disc (see finish)."""
    q1, q2, q3 = dynamicsymbols('q1 q2 q3')
    u1, u2, u3 = dynamicsymbols('u1 u2 u3')
    r, m, g = symbols('r m g')
    N = ReferenceFrame('N')
    yaw = N.orientnew('Y', 'Axis', [q1, N.z])
    lean = yaw.orientnew('L', 'Axis', [q2, yaw.x])
    disc = lean.orientnew('R', 'Axis', [q3, lean.y])
    w_qd = disc.ang_vel_in(N)
    disc.set_ang_vel(N, u1 * lean.x + u2 * lean.y + u3 * lean.z)
    contact = Point('C')
    contact.set_vel(N, 0)
    centre = contact.locatenew('Dmc', r * lean.z)
    centre.v2pt_theory(contact, N, disc)
    kd = [(disc.ang_vel_in(N) - w_qd).dot(e) for e in (lean.x, lean.y, lean.z)]
    body = RigidBody('disc', centre, disc, m,
                     (inertia(lean, m * r ** 2 / 4, m * r ** 2 / 2, m * r ** 2 / 4), centre))
    km = KanesMethod(N, q_ind=[q1, q2, q3], u_ind=[u1, u2, u3], kd_eqs=kd)
    km.kanes_equations([body], [(centre, -m * g * N.z)])
    return finish(km, [q1, q2, q3], [u1, u2, u3], [])


def bicycle():
    """examples/bicycle_speeds.qd (see finish)."""
    x, y, th, d, pr, pf = dynamicsymbols('x y th d pr pf')
    v, s, ux, uy, wth, wf = dynamicsymbols('v s ux uy wth wf')
    mf, If, mw, r, b, c, k, tau = symbols('mf If mw r b c k tau')
    N = ReferenceFrame('N')
    frame = N.orientnew('A', 'Axis', [th, N.z])
    rear = frame.orientnew('RW', 'Axis', [pr, frame.y])
    fork = frame.orientnew('Fk', 'Axis', [d, frame.z])
    front = fork.orientnew('FW', 'Axis', [pf, fork.y])
    frame.set_ang_vel(N, wth * N.z)
    rear.set_ang_vel(frame, v / r * frame.y)
    fork.set_ang_vel(frame, s * frame.z)
    front.set_ang_vel(fork, wf * fork.y)
    O = Point('O')
    O.set_vel(N, 0)
    P = O.locatenew('P', x * N.x + y * N.y)
    P.set_vel(N, ux * N.x + uy * N.y)
    rear_c = P.locatenew('Ro', r * N.z)
    rear_c.set_vel(N, ux * N.x + uy * N.y)
    frame_c = P.locatenew('Co', c * frame.x + sympy.Rational(3, 5) * N.z)
    frame_c.v2pt_theory(P, N, frame)
    contact = P.locatenew('Fc', b * frame.x)
    contact.v2pt_theory(P, N, frame)
    front_c = contact.locatenew('Fo', r * N.z)
    front_c.v2pt_theory(P, N, frame)
    vf = contact.vel(N)
    vc = [ux * sympy.cos(th) + uy * sympy.sin(th) - v,
          -ux * sympy.sin(th) + uy * sympy.cos(th),
          vf.dot(fork.x) - r * wf,
          vf.dot(fork.y)]
    kd = [x.diff() - ux, y.diff() - uy, th.diff() - wth, d.diff() - s, r * pr.diff() - v,
          pf.diff() - wf]
    wheel = (mw * r ** 2 / 4, mw * r ** 2 / 2, mw * r ** 2 / 4)
    bodies = [RigidBody('frame', frame_c, frame, mf, (inertia(frame, If, If, If), frame_c)),
              RigidBody('rear', rear_c, rear, mw, (inertia(rear, *wheel), rear_c)),
              RigidBody('front', front_c, front, mw, (inertia(front, *wheel), front_c))]
    loads = [(front, -k * d * N.z), (frame, k * d * N.z), (rear, tau * frame.y)]
    km = KanesMethod(N, q_ind=[x, y, th, d, pr, pf], u_ind=[v, s],
                     u_dependent=[ux, uy, wth, wf], kd_eqs=kd, velocity_constraints=vc)
    km.kanes_equations(bodies, loads)
    return finish(km, [x, y, th, d, pr, pf], [v, s, ux, uy, wth, wf], vc)


def finish(km, q, u, vc):
    """The system as a dict: M u' = forcing (u' of every speed, the
    independent first), q, u, the velocity constraints vc (= 0)."""
    kdd = km.kindiffdict()
    return dict(M=km.mass_matrix.subs(kdd), f=km.forcing.subs(kdd), q=q, u=u, vc=vc)


SYSTEMS = {'rolling_disk_speeds': rolling_disc, 'bicycle_speeds': bicycle}


def size(M, f):
    return sum(count_ops(e) for e in M) + sum(count_ops(e) for e in f)


class Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise Timeout()


def simplified_size(M, f, limit):
    """(seconds, ops) of simplify() on every entry, or (None, None) past limit."""
    signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(int(limit))
    t0 = time.process_time()
    try:
        Ms = M.applyfunc(sympy.simplify)
        fs = f.applyfunc(sympy.simplify)
    except Timeout:
        return None, None
    finally:
        signal.alarm(0)
    return time.process_time() - t0, size(Ms, fs)


def bench(name, budget, min_reps):
    build = SYSTEMS[name]
    times = []
    while len(times) < min_reps or sum(times) < budget:
        clear_cache()
        t0 = time.process_time()
        sys_ = build()
        times.append(time.process_time() - t0)
    return times, sys_['M'], sys_['f']


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--budget', type=float, default=5.0)
    ap.add_argument('--min-reps', type=int, default=3)
    ap.add_argument('--simplify', action='store_true')
    ap.add_argument('--limit', type=float, default=300)
    ap.add_argument('models', nargs='*', default=list(SYSTEMS))
    a = ap.parse_args()
    for name in a.models:
        times, M, f = bench(name, a.budget, a.min_reps)
        print('%s\tsympy\t%d\t%.6e\t%.6e\t%d' % (name, len(times), statistics.median(times),
                                                 min(times), size(M, f)), flush=True)
        if a.simplify:
            secs, ops = simplified_size(M, f, a.limit)
            if secs is None:
                print('%s\tsympy:simplified\ttimeout\t%g' % (name, a.limit), flush=True)
            else:
                print('%s\tsympy:simplified\t0\t%.6e\t%.6e\t%d' % (name, secs, secs, ops),
                      flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
