"""The textbook audit's replayed cases (issue 33): each a qdot command on a
model of tests/audit/models/, the number it must print (read by a regular
expression from its text output) and the textbook's value for it, from the
verified worked examples of /work/shared/reference (the seed, its item and
formula cited).  No value here was taken from qdot's output.

A case is (name, citation, args, regex, expected, rel): args are the command
and its arguments, a model named by its file under models/; regex has one
group, the number; expected is the reference value (a formula in the model's
parameters, evaluated here); rel the relative tolerance (None: want is the
exact text).  A seventh entry, when there, is the exit status wanted (3: a
verdict "no"); else 0.
"""
from math import pi, sqrt, sin, cos, asin, atan, acos, atan2, exp, cosh

G = 9.8

# ---- Byerly (seed-byerly.md) ----------------------------------------------------
_byerly = [
    ("TC11 compound Atwood x''", "seed-byerly.md TC11: x'' = g/23",
     ["eom", "by_tc11.qd", "--at", "x=1,y=1"], r"x'' = (\S+)", G / 23, 1e-12),
    ("TC11 compound Atwood y''", "seed-byerly.md TC11: y'' = 8 g/23",
     ["eom", "by_tc11.qd", "--at", "x=1,y=1"], r"y'' = (\S+)", 8 * G / 23, 1e-12),
    ("TC13 hole x''", "seed-byerly.md TC13: x'' = 0.85 at x = 0.1, x' = 0.2, th' = 3",
     ["eom", "by_tc13.qd", "--at", "x=0.1,x'=0.2,th'=3"], r"x'' = (\S+)", 0.85, 1e-12),
    ("TC13 equivalent pendulum", "seed-byerly.md TC13: w^2 = 3 g/(2 a)",
     ["stability", "by_tc13.qd", "--ignore", "th", "--momentum", "p_th=m*a*sqrt(a*g)",
      "--guess", "x=0.01"], r"frequencies: (\S+)", sqrt(3 * G / 2), 1e-10),
    ("TC15 compound pendulum", "seed-byerly.md TC15: w^2 = g h/(h^2 + k^2)",
     ["modes", "by_tc15.qd"], r"mode 1: w\^2 = (\S+),", G * 0.3 / (0.3 ** 2 + 0.4 ** 2), 1e-12),
]

# ---- Desloge vol. 1 (seed-desloge-A.md) -----------------------------------------
_desloge_a = [
    ("A T17 tethered particle on a spinning disk", "seed-desloge-A.md T17: w^2 = b w^2/a",
     ["modes", "da_t17.qd"], r"mode 1: w\^2 = (\S+),", 1.5 * 4 / 0.5, 1e-12),
    ("A T27 particle on a sphere", "seed-desloge-A.md T27: N = m g (3 cos th - 2), "
     "th'^2 = 2 g (1 - cos th)/R (from rest at the top)",
     ["eom", "da_t27.qd", "--at", "r=2, th=0.5, th'=sqrt(2*9.81*(1 - cos(0.5))/2)"],
     r"lambda_sph = (\S+)", 1.2 * 9.81 * (3 * cos(0.5) - 2), 1e-9),
]

# ---- Desloge vol. 2, orbits and scattering (seed-desloge-B.md) --------------------
_desloge_b = [
    ("B T01 isotropic oscillator apsidal angle", "seed-desloge-B.md T01: apsidal angle pi/2",
     ["orbit", "db_t01.qd", "--ignore", "ph", "--at", "r=1, r'=0.4, ph'=0.8"],
     r"apsidal angle: ph (\S+)", pi / 2, 1e-10),
    ("B T01 isotropic oscillator radial period", "seed-desloge-B.md T01: radial period "
     "pi sqrt(m/k), half the orbital period 2 pi sqrt(m/k)",
     ["orbit", "db_t01.qd", "--ignore", "ph", "--at", "r=1, r'=0.4, ph'=0.8"],
     r"radial period: (\S+)", pi * sqrt(1.5 / 2), 1e-10),
    ("B T03 radial infall", "seed-desloge-B.md T03: fall time T/2^(5/2), T = 2 pi sqrt(m r0^3/k) "
     "the period of the circular orbit at r0 = 1",
     ["orbit", "db_t03.qd", "--ignore", "ph", "--at", "r=1, r'=0, ph'=0"],
     r"after time (\S+)", 2 * pi / 2 ** 2.5, 1e-10),
    ("B T11 elastic string apsidal angle", "seed-desloge-B.md T11: pi sqrt((b - a)/(4 b - 3 a))",
     ["orbit", "db_t11.qd", "--ignore", "ph", "--at", "r=2, ph'=sqrt(1.5)"],
     r"apsidal angle: ph (\S+)", pi * sqrt(1 / 5), 1e-10),
    ("B T15 Rutherford deflection", "seed-desloge-B.md T15: tan(Theta/2) = k/(2 E s), "
     "s = 0.5, E = 2",
     ["scatter", "db_t15.qd", "--energy", "2", "--b", "0.5"], r"Theta = (\S+)",
     2 * atan(1 / (2 * 2 * 0.5)), 1e-8),
    ("B T15 Rutherford cross section", "seed-desloge-B.md T15: k^2/(16 E^2 sin^4(Theta/2))",
     ["scatter", "db_t15.qd", "--energy", "2", "--b", "0.5"], r"dsigma/dOmega = (\S+) at",
     1 / (16 * 4 * sin(atan(0.5)) ** 4), 1e-8),
    ("B T19 capture, orbiting", "seed-desloge-B.md T19: a < r*: sigma = 2 pi at n = 4, k = E = 1",
     ["scatter", "db_t19.qd", "--energy", "1", "--b", "0.5"], r"cross section (\S+)\n",
     2 * pi, 1e-8),
    ("B T19 capture, absorbing sphere", "seed-desloge-B.md T19: a >= r*: sigma = pi a^2 "
     "(1 + k/(E a^n)), a = 1.5",
     ["scatter", "db_t19.qd", "--energy", "1", "--b", "0.5", "--core", "1.5", "--absorbing"],
     r"cross section (\S+)\n", pi * 1.5 ** 2 * (1 + 1 / 1.5 ** 4), 1e-8),
    ("B T23 proton-proton, both counted", "seed-desloge-B.md T23: Q = (k/E)^2 (sin^-4 + "
     "cos^-4) cos theta, E the lab energy (twice the relative energy 1 of mu = 1/2)",
     ["scatter", "db_t25.qd", "--energy", "1", "--lab-theta", "0.5", "--masses", "1,1",
      "--recoil"], r"lab_cross_section: (\S+)",
     (1 / 2) ** 2 * (sin(0.5) ** -4 + cos(0.5) ** -4) * cos(0.5), 1e-7),
    ("B T25 electron-electron lab angle", "seed-desloge-B.md T25: scattered at Theta/2, "
     "tan(Theta/2) = k/(2 E s)",
     ["scatter", "db_t25.qd", "--energy", "1", "--b", "0.5", "--masses", "1,1"],
     r"lab_angle: (\S+)", atan(1 / (2 * 1 * 0.5)), 1e-8),
    ("B T37 torque-free axis 1", "seed-desloge-B.md T37: lambda = Om^2 (A - B)(A - C)/(B C), "
     "A, B, C = 1, 2, 3, Om = 1: about axis 1 the frequency sqrt(1/3)",
     ["modes", "db_t37.qd", "--about", "theta=1, w1=1"], r"0 \+ (\S+)i", 1 / sqrt(3), 1e-9),
    ("B T49 coupled oscillators", "seed-desloge-B.md T49: w^2 = (1 + 2 eps) k/m",
     ["modes", "db_t49.qd"], r"mode 2: w\^2 = (\S+),", (1 + 2 * 0.05) * 4, 1e-12),
    ("B T53 beaded string", "seed-desloge-B.md T53: w^2 = tau/(a m)",
     ["modes", "db_t53.qd"], r"mode 3: w\^2 = (\S+),", 3 / 0.5, 1e-12),
    ("B T59 rod on an elastic string", "seed-desloge-B.md T59: equivalent length 7a/3",
     ["modes", "db_t59.qd"], r"mode 1: w\^2 = (\S+),", 3 * 9.81 / 7, 1e-10),
]

# ---- Desloge vol. 2, Hamiltonian mechanics (seed-desloge-C.md) --------------------
_h, _E, _m, _k, _b = 1.1, -0.8, 1.3, 2.0, 0.05
_Jr = -2 * pi * sqrt(_h ** 2 - 2 * _m * _b) + pi * _k * sqrt(2 * _m / -_E)
_Jph = 2 * pi * _h
_S = _Jr + sqrt(_Jph ** 2 - 8 * pi ** 2 * _m * _b)
_nur = 4 * pi ** 2 * _m * _k ** 2 / _S ** 3
_T53 = ["action", "dc_t53.qd", "--at", "r=1, ph=0, r'=sqrt(2*(-0.8 + 2 + 0.05)/1.3 - 1.1^2/1.3^2),"
        " ph'=1.1/1.3", "--angle", "ph"]
_desloge_c = [
    ("C T53 perturbed Kepler J_r", "seed-desloge-C.md T53: J_r = -2 pi sqrt(h^2 - 2 m beta) + "
     "pi k sqrt(2m/(-E))", _T53, r"J_r = (\S+)", _Jr, 1e-9),
    ("C T53 perturbed Kepler omega_r", "seed-desloge-C.md T53: nu_r = 4 pi^2 m k^2/[J_r + "
     "sqrt(J_ph^2 - 8 pi^2 m beta)]^3", _T53, r"omega_r = (\S+)", 2 * pi * _nur, 1e-9),
    ("C T53 perturbed Kepler omega_ph", "seed-desloge-C.md T53: nu_ph = nu_r J_ph/sqrt(J_ph^2 "
     "- 8 pi^2 m beta)", _T53, r"omega_ph = (\S+)",
     2 * pi * _nur * _Jph / sqrt(_Jph ** 2 - 8 * pi ** 2 * _m * _b), 1e-9),
    ("C T57 bracket with H", "seed-desloge-C.md T57: (x - p t/m, H) = p/m, H = p^2/(2m)",
     ["bracket", "dc_t57.qd", "x - p*t/m", "H"], r"\] = (.+)", "p/m", None),
    ("C T9 fall with the centrifugal term cancelled", "seed-desloge-C.md T9: V_eff = 2 lam r, "
     "fall time from r = a: sqrt(a/lam)",
     ["orbit", "dc_t9.qd", "--ignore", "th"], r"after time (\S+)", sqrt(2 / 0.8), 1e-9),
]

# ---- Desloge vol. 2, variational principles and relativity (seed-desloge-D.md) ----------
_desloge_d = [
    ("D T9 oscillator principal function", "seed-desloge-D.md T9: S = cot(1)/2",
     ["path", "dd_t9.qd", "--from", "q=0, t=0", "--to", "q=1, t=1"], r"action: (\S+)",
     cos(1) / sin(1) / 2, 1e-9),
    ("D T11 velocity addition", "seed-desloge-D.md T11: 0.5 (+) 0.5 = 0.8",
     ["lorentz", "--frame", "-0.5,0,0", "--velocity", "0.5,0,0"], r"\((\S+), 0, 0\)\s*$", 0.8,
     1e-12),
    ("D T19 relativistic Kepler precession", "seed-desloge-D.md T19: 2 pi (1/Gam - 1), "
     "Gam = sqrt(1 - k^2/(L^2 c^2)), L = gamma r^2 ph' at r = 1, ph' = 0.4",
     ["orbit", "dd_t19.qd", "--ignore", "ph"], r"precession per period: ph (\S+)",
     2 * pi * (1 / sqrt(1 - 0.2 ** 2 / (0.4 / sqrt(1 - 0.16)) ** 2) - 1), 1e-9),
    ("D T25 relativistic oscillator period", "seed-desloge-D.md T25: 7.38068454944",
     ["action", "dd_t25.qd"], r"period (\S+)", 7.38068454944, 1e-10),
    ("D T33 triangle of springs", "seed-desloge-D.md T33: w^2 = 3k/m",
     ["modes", "dd_t33.qd", "--about", "x1=0"], r"w\^2 = (3(?:\.0*)?),", 3.0, 1e-12),
]

# ---- Goldstein and Britannica (seed-goldstein-britannica.md) -----------------------
_m1, _m2, _l, _g = 1.5, 0.7, 3.0, 9.81
_r0 = (4 / (_m1 * _m2 * _g)) ** (1 / 3)   # ell = p_th = 2
_gb = [
    ("B17 principal function in uniform gravity", "seed-goldstein-britannica.md B17: S = "
     "m (x1 - x0)^2/(2 tau) - m g tau (x0 + x1)/2 - m g^2 tau^3/24",
     ["path", "gb_b17.qd", "--from", "x=1, t=0", "--to", "x=2, t=0.7"], r"action: (\S+)",
     1.3 * 1 / (2 * 0.7) - 1.3 * 9.8 * 0.7 * 3 / 2 - 1.3 * 9.8 ** 2 * 0.7 ** 3 / 24, 1e-9),
    ("G11 table and hanging mass radius", "seed-goldstein-britannica.md G11: r0 = (ell^2/(m1 m2 "
     "g))^(1/3)",
     ["stability", "gb_g11.qd", "--ignore", "th", "--momentum", "p_th=2", "--guess", "r=1"],
     r"  r = (\S+)", _r0, 1e-10),
    ("G11 table and hanging mass frequency", "seed-goldstein-britannica.md G11: w^2 = 3 m2 g/"
     "((m1 + m2) r0)",
     ["stability", "gb_g11.qd", "--ignore", "th", "--momentum", "p_th=2", "--guess", "r=1"],
     r"frequencies: (\S+)", sqrt(3 * _m2 * _g / ((_m1 + _m2) * _r0)), 1e-9),
    ("G13 double pendulum", "seed-goldstein-britannica.md G13: w^2 = (g/l)(2 + sqrt 2)",
     ["modes", "gb_g13.qd"], r"mode 2: w\^2 = (\S+),", 9.81 / 0.8 * (2 + sqrt(2)), 1e-12),
]

# an orbit off the origin closes on itself: advance 0, precession 0 (REPORT section 5)
_extra = [
    ("B19 one path at the envelope", "seed-goldstein-britannica.md B19: at O' = (0.5773503, "
     "0.3333333), on the envelope for v^2/g = 1, the two paths of the energy coincide",
     ["path", "gb_b19.qd", "--from", "x=0, y=0", "--to", "x=1/sqrt(3), y=1/3", "--energy", "0.5",
      "--all"], r"paths: (\d+)", 1, 0),
    ("B19 two paths inside the envelope", "seed-goldstein-britannica.md B19 and G's projectile: "
     "inside y < v^2/(2g) - g x^2/(2 v^2) two paths of one energy, the low and the high lob",
     ["path", "gb_b19.qd", "--from", "x=0, y=0", "--to", "x=0.3, y=0.3", "--energy", "0.5",
      "--all"], r"paths: (\d+)", 2, 0),
    ("B19 the high lob 54 times longer", "the projectile's two flights at speed v through "
     "(X, Y): T^2 = 2 (v^2 - g Y +- sqrt((v^2 - g Y)^2 - g^2 (X^2 + Y^2)))/g^2 (the two roots "
     "of the seed's launch angles); here X = 2, Y = -1, v^2 = 60, g = 1 (issue 33)",
     ["path", "gb_b19.qd", "--from", "x=0, y=0", "--to", "x=2, y=-1", "--energy", "30",
      "--all"], r"time: \S+\n(?:.*\n)*?  time: (\S+)",
     sqrt(2 * (60 + 1 + sqrt(61 ** 2 - 5))), 1e-9),
    ("cyclotron circle off the origin", "Goldstein sec. 1.5 (the Lorentz force): a circle "
     "that does not enclose the origin sweeps no net angle",
     ["orbit", "x_cyc.qd", "--ignore", "th"], r"precession per period: th (\S+)", 0.0, 1e-12),
]


# ---- the second batch (issue 33): thirty more cases from the same notes ---------------
_al, _be, _ga = 0.3, 0.4, sqrt(0.75)          # A T19: the rod's ends, a = 1
_t19_th = acos(_ga)                           # the rod's polar angle: cos th = ga/a
_t19_ph = atan2(_be / sin(_t19_th), -_al / sin(_t19_th))
_t19_acc = 3 * 9.81 / 4 * (_al ** 2 + 4 * _be ** 2) / (_al ** 2 + 4 * _be ** 2 + _ga ** 2)


def _t37_accels():
    """Desloge A T37's two equations at y = 0.1, th = 0.4, y' = 0.2, th' = -0.5, solved for
    y'' and th'' (m, b, k, c, g as in da_t37.qd)."""
    m, b, k, c, g = 1.5, 0.8, 20.0, 0.3, 9.81
    y, th, yd, thd = 0.1, 0.4, 0.2, -0.5
    # m y'' - m b sin th th'' = -(-m b th'^2 cos th + k y + c (y' - b th' sin th))
    # -m b sin th y'' + m b^2 th'' = -(m g b sin th + c (b^2 th' - b y' sin th))
    a11, a12 = m, -m * b * sin(th)
    a21, a22 = -m * b * sin(th), m * b * b
    r1 = m * b * thd ** 2 * cos(th) - k * y - c * (yd - b * thd * sin(th))
    r2 = -(m * g * b * sin(th) + c * (b * b * thd - b * yd * sin(th)))
    det = a11 * a22 - a12 * a21
    return (r1 * a22 - a12 * r2) / det, (a11 * r2 - a21 * r1) / det


_t37_ydd, _t37_thdd = _t37_accels()
_t37_at = ["eom", "da_t37.qd", "--at", "y=0.1, th=0.4, y'=0.2, th'=-0.5"]
_yuk_x = 0.5                                   # B T07: x = b r0, r0 = 1, a = m = 1
_yuk_h = sqrt((1 + _yuk_x) * exp(-_yuk_x))
_tc19_den = 7 * (3 + 1) - 5 * 1 * cos(pi / 6) ** 2
_brach_a, _brach_th = 0.572917037532, 2.41201114391  # D T35's endpoint (1, 1)
_b23_th, _b23_thd = 0.7, 1.3                  # B23: the pendulum at th, th' (l = 1.5)
_b23_at = ["eom", "gb_b23.qd", "--at",
           "x=1.5*sin(0.7), y=-1.5*cos(0.7), x'=1.5*1.3*cos(0.7), y'=1.5*1.3*sin(0.7)"]
_t21 = ["stability", "da_t21.qd", "--ignore", "ph", "--momentum",
        "p_ph=%r" % ((4 / 3 + 0.5 * (4 / 3) ** 2) * 0.75 * sqrt(3 * 9.81 / 2))]
_tc29 = ["impulse", "by_tc29.qd", "--prescribe", "major: z' - a*be' = U, minor: z' + b*al' = V"]
_tc31 = ["impulse", "by_tc31.qd", "--prescribe", "gx: x' - a*be' = 0, gy: y' + a*al' = 0"]
_g03 = ["eom", "gb_g03.qd", "--at", "r=1.5, th=0.7*0.4, r'=0.3, th'=0.7, t=0.4"]
_second = [
    ("B T53 beaded string, slowest mode", "seed-desloge-B.md T53: w^2 = tau/(6 a m)",
     ["modes", "db_t53.qd"], r"mode 1: w\^2 = (\S+),", 3 / (6 * 0.5), 1e-12),
    ("B T53 beaded string, middle mode", "seed-desloge-B.md T53: w^2 = tau/(2 a m)",
     ["modes", "db_t53.qd"], r"mode 2: w\^2 = (\S+),", 3 / (2 * 0.5), 1e-12),
    ("B T49 coupled oscillators, in phase", "seed-desloge-B.md T49: w^2 = k/m",
     ["modes", "db_t49.qd"], r"mode 1: w\^2 = (\S+),", 4.0, 1e-12),
    ("B T55 beads on a hoop, (1, 1, -2m/M)", "seed-desloge-B.md T55: w^2 = k (M + 2m)/(4 m M)",
     ["modes", "db_t55.qd"], r"mode 2: w\^2 = (\S+),", (2 + 2) / (4 * 2), 1e-12),
    ("B T55 beads on a hoop, (1, -1, 0)", "seed-desloge-B.md T55: w^2 = 3k/(4m)",
     ["modes", "db_t55.qd"], r"mode 3: w\^2 = (\S+),", 3 / 4, 1e-12),
    ("B T55 beads on a hoop, rigid rotation", "seed-desloge-B.md T55: w^2 = 0",
     ["modes", "db_t55.qd"], r"mode 1: w\^2 = (\S+),", 0.0, 1e-12),
    ("B T07 Yukawa near-circular apsidal angle", "seed-desloge-B.md T07: beta^2 = (1 + x - x^2)"
     "/(1 + x), x = b r0; apsidal angle pi/beta; the circle at r0 = 1 has h^2 = m a r0 (1 + x) "
     "e^-x", ["orbit", "db_t07.qd", "--ignore", "ph", "--at", "r=1, r'=0, ph'=%r" % _yuk_h],
     r"apsidal angle: ph (\S+)", pi / sqrt((1 + _yuk_x - _yuk_x ** 2) / (1 + _yuk_x)), 1e-9),
    ("B T37 torque-free, about the largest axis", "seed-desloge-B.md T37: lambda = Om^2 (C - A)"
     "(C - B)/(A B) about axis 3, A, B, C = 1, 2, 3, Om = 1: frequency 1",
     ["modes", "db_t37.qd", "--about", "theta=1, w3=1"], r"0 \+ (\S+)i", 1.0, 1e-9),
    ("A T19 rod on floor and wall", "seed-desloge-A.md T19: the centre's initial downward "
     "acceleration (3g/4)(al^2 + 4 be^2)/(al^2 + 4 be^2 + ga^2) = 3.6290, i.e. a sin(th) th''",
     ["eom", "da_t19.qd", "--at", "th=%r, ph=%r" % (_t19_th, _t19_ph)], r"^  th'' = (\S+)",
     _t19_acc / sin(_t19_th), 1e-10),
    ("A T39 support on a vertical circle", "seed-desloge-A.md T39: b th'' + g sin th - a w^2 "
     "cos(th - w t) = 0",
     ["eom", "da_t39.qd", "--at", "th=0.3, t=0.2"], r"^  th'' = (\S+)",
     (-9.81 * sin(0.3) + 0.3 * 4 * cos(0.3 - 0.4)) / 1.2, 1e-12),
    ("A T37 damped pendulum on a spring, y''", "seed-desloge-A.md T37: m (y'' - b th'' sin th - "
     "b th'^2 cos th) + k y + c (y' - b th' sin th) = 0 with the th equation",
     _t37_at, r"^  y'' = (\S+)", _t37_ydd, 1e-12),
    ("A T37 damped pendulum on a spring, th''", "seed-desloge-A.md T37: m b^2 th'' - m b y'' "
     "sin th + m g b sin th + c (b^2 th' - b y' sin th) = 0",
     _t37_at, r"^  th'' = (\S+)", _t37_thdd, 1e-12),
    ("C T27 Q = log p canonical", "seed-desloge-C.md T27: Q = ln p, P = -(1 + q + ln p) p is "
     "canonical", ["canonical", "dc_t27.qd", "--Q", "log(p_q)", "--P", "-(1 + q + log(p_q))*p_q"],
     r"^(canonical)", "canonical", None),
    ("C T29 Q = q + t e^p canonical", "seed-desloge-C.md T29: Q = q + t e^p, P = p is canonical",
     ["canonical", "dc_t27.qd", "--Q", "q + t*exp(p_q)", "--P", "p_q"], r"^(canonical)",
     "canonical", None),
    ("C T45 free fall K = P", "seed-desloge-C.md T45: Q = -p/(m g), P = p^2/(2m) + m g q, "
     "(Q, P) = 1", ["canonical", "dc_t27.qd", "--Q", "-p_q/(m*g)", "--P", "p_q^2/(2*m) + m*g*q"],
     r"^(canonical)", "canonical", None),
    ("C T33 completing Q1 = q1^2, Q2 = q1 + q2", "seed-desloge-C.md T33: P1 = (p1 - p2)/(2 q1), "
     "P2 = p2 + (q1 + q2)^2 completes it canonically",
     ["canonical", "dc_t33.qd", "--Q", "q1^2, q1 + q2", "--P",
      "(p_q1 - p_q2)/(2*q1), p_q2 + (q1 + q2)^2"], r"^(canonical)", "canonical", None),
    ("D T1 falling particle trial path", "seed-desloge-D.md T1: S(a) = m T^3 (a^2 + 2 g^2)/6 "
     "for z = -g t^2/2 + a t (t - T), a = 0.5, T = 1",
     ["action-of", "dd_t1.qd", "--path", "z = -g*t^2/2 + 0.5*t*(t - 1)", "--t", "0:1"],
     r"action: (\S+)", 1.3 * (0.25 + 2 * 9.8 ** 2) / 6, 1e-10),
    ("D T3 harmonic trial path", "seed-desloge-D.md T3: S(c) = sqrt(2) A^2/8 + (63 pi/32) A^2 c^2 "
     "on [0, pi/8], A = 1, c = 0.1",
     ["action-of", "dd_t3.qd", "--path", "x = sin(t) + 0.1*sin(8*t)", "--t", "0:pi/8"],
     r"action: (\S+)", sqrt(2) / 8 + 63 * pi / 32 * 0.01, 1e-10),
    ("D T35 brachistochrone from th = pi/3", "seed-desloge-D.md T35: the cycloid R = 1 to "
     "(pi, 2), time sqrt(R/g) (th_e - th0)",
     ["path", "dd_t35.qd", "--from", "x=pi/3 - sqrt(3)/2, y=1/2", "--to", "x=pi, y=2"],
     r"action: (\S+)", (pi - pi / 3) / sqrt(9.8), 1e-8),
    ("D T35 brachistochrone to (1, 1)", "seed-desloge-D.md T35: T = 0.583192782972 from the "
     "cusp; from th0 = 0.6 on the same cycloid, T - sqrt(R/g) 0.6",
     ["path", "dd_t35.qd", "--from", "x=%r, y=%r" % (_brach_a * (0.6 - sin(0.6)),
                                                     _brach_a * (1 - cos(0.6))),
      "--to", "x=1, y=1"], r"action: (\S+)", 0.583192782972 - sqrt(_brach_a / 9.8) * 0.6, 1e-8),
    ("G15 disk pushed at its centre", "seed-goldstein-britannica.md G15: x'' = 2F/(3M)",
     ["eom", "gb_g15.qd", "--at", "x=0"], r"^  x'' = (\S+)", 2 * 3 / (3 * 2), 1e-12),
    ("G13 double pendulum, slow mode", "seed-goldstein-britannica.md G13: w^2 = (g/l)(2 - "
     "sqrt 2)", ["modes", "gb_g13.qd"], r"mode 1: w\^2 = (\S+),", 9.81 / 0.8 * (2 - sqrt(2)),
     1e-12),
    ("B23 pendulum tension from the multiplier", "seed-goldstein-britannica.md B23: f = (x^2 + "
     "y^2 - l^2)/2, lambda = -(m v^2 + m g l cos th)/l^2",
     _b23_at, r"^  lambda_rod = (\S+)",
     -(1.2 * (1.5 * _b23_thd) ** 2 + 1.2 * 9.81 * 1.5 * cos(_b23_th)) / 1.5 ** 2, 1e-10),
    ("TC17 solid cylinder rolling down an incline", "seed-byerly.md TC17: rolling, k^2 = a^2/2: "
     "x'' = g sin(al) a^2/(a^2 + k^2) = (2/3) g sin(al)",
     ["eom", "by_tc17.qd", "--at", "x=0"], r"^  x'' = (\S+)", 2 / 3 * 9.8 * 0.5, 1e-12),
    ("TC17 rolling friction", "seed-byerly.md TC17: F = m g sin(al) k^2/(a^2 + k^2) = (1/3) m g "
     "sin(al), and lambda = -F (the multiplier of x = a th: m x'' = m g sin(al) + lambda)",
     ["eom", "by_tc17.qd", "--at", "x=0"], r"^  lambda_roll = (\S+)", -9.8 * 0.5 / 3, 1e-12),
    ("TC19 sphere on a movable wedge, y''", "seed-byerly.md TC19: y'' = 4.041237 (M = 3, m = 1, "
     "al = 30 deg)", ["eom", "by_tc19.qd", "--at", "x=0"], r"^  y'' = (\S+)",
     5 * 4 * 9.8 * 0.5 / _tc19_den, 1e-12),
    ("TC19 sphere on a movable wedge, x''", "seed-byerly.md TC19: x'' = 0.874954",
     ["eom", "by_tc19.qd", "--at", "x=0"], r"^  x'' = (\S+)", 5 * 9.8 * 0.5 * cos(pi / 6) / _tc19_den, 1e-12),
    ("TC09 whirling table: the cycloid, x", "seed-byerly.md TC09: w = 1, a = 4, t = pi/2: "
     "x = (a/4)(1 - cos 2wt) = 2",
     ["simulate", "by_tc09.qd", "--t-end", "pi/2", "--rtol", "1e-12"],
     r"^1\.57079632679\d*,(\S+?),", 2.0, 1e-9),
    ("TC09 whirling table: the cycloid, y", "seed-byerly.md TC09: y = -(a/4)(2wt - sin 2wt) = "
     "-pi", ["simulate", "by_tc09.qd", "--t-end", "pi/2", "--rtol", "1e-12"],
     r"^1\.57079632679\d*,[^,]*,(\S+?),", -pi, 1e-9),
    ("TC27 compound pulley jerked, x'", "seed-byerly.md TC27: x' = 3P/(23m)",
     ["impulse", "by_tc27.qd"], r"^  x'\+ = .* = (\S+)$", 3 / 23, 1e-10),
    ("TC27 compound pulley jerked, y'", "seed-byerly.md TC27: y' = P/(23m)",
     ["impulse", "by_tc27.qd"], r"^  y'\+ = .* = (\S+)$", 1 / 23, 1e-10),
    ("TC25 lamina struck, v_G", "seed-byerly.md TC25: v_G = P/m along P",
     ["impulse", "by_tc25.qd"], r"^  x'\+ = .* = (\S+)$", 1.5 / 2, 1e-10),
    ("TC25 lamina struck, w", "seed-byerly.md TC25: w = a P/(m k^2)",
     ["impulse", "by_tc25.qd"], r"^  th'\+ = .* = (\S+)$", 0.3 * 1.5 / (2 * 0.25), 1e-10),
    ("TC21 billiard ball struck without spin: rolling starts", "seed-byerly.md TC21 (D): "
     "t* = 2 u0/(7 mu g) (the first row whose mode_ball is 0, rolling)",
     ["simulate", "by_tc21.qd", "--t-end", "1"], r"^([^,]+),(?:[^,]*,){14}0,[^,]*,[^,]*$",
     2 * 1.4 / (7 * 0.2 * 9.81), 1e-8),
    ("TC21 billiard ball: distance slid", "seed-byerly.md TC21 (D): 12 u0^2/(49 mu g)",
     ["simulate", "by_tc21.qd", "--t-end", "1"], r"^[^,]+,([^,]+),(?:[^,]*,){13}0,[^,]*,[^,]*$",
     12 * 1.4 ** 2 / (49 * 0.2 * 9.81), 1e-8),
    ("TC21 billiard ball: final speed", "seed-byerly.md TC21 (D): 5 u0/7",
     ["simulate", "by_tc21.qd", "--t-end", "1"], r"^1,(?:[^,]*,){5}([^,]+),", 5 * 1.4 / 7,
     1e-9),
    ("A T21 rod with a sliding bead: the cone", "seed-desloge-A.md T21: th = pi/3, x = 4a/3 "
     "with n = 6 al, p_ph = (4/3 m a^2 + al m x^2) sin^2 th ph', no --guess (the model's start "
     "th = 0 is singular for V_eff)", _t21, r"^  th = (\S+)$", pi / 3, 1e-10),
    ("A T21 rod with a sliding bead: the bead", "seed-desloge-A.md T21: x = 4a/3", _t21,
     r"^  x = (\S+)$", 4 / 3, 1e-10),
    ("A T21 rod with a sliding bead: the rate", "seed-desloge-A.md T21: ph'^2 = 3 g/(2 a)", _t21,
     r"^  ph' = (\S+), p_ph", sqrt(3 * 9.81 / 2), 1e-10),
    ("TC29 elliptic disk, the centre", "seed-byerly.md TC29: v_G = (U + V)/6 = 0.5 (U = 1, "
     "V = 2, a = 3, b = 1)", _tc29, r"^  z'\+ = .* = (\S+)$", 0.5, 1e-10),
    ("TC29 elliptic disk, w1", "seed-byerly.md TC29: w1 = (5V - U)/(6b) = 1.5", _tc29,
     r"^  al'\+ = .* = (\S+)$", 1.5, 1e-10),
    ("TC29 elliptic disk, w2", "seed-byerly.md TC29: w2 = (V - 5U)/(6a) = -1/6", _tc29,
     r"^  be'\+ = .* = (\S+)$", -1 / 6, 1e-10),
    ("TC31 spinning sphere set down, x'", "seed-byerly.md TC31: x' = (2/7) a Omega2", _tc31,
     r"^  x'\+ = .* = (\S+)$", 2 / 7 * 0.5 * -2, 1e-10),
    ("TC31 spinning sphere set down, y'", "seed-byerly.md TC31: y' = -(2/7) a Omega1", _tc31,
     r"^  y'\+ = .* = (\S+)$", -2 / 7 * 0.5 * 3, 1e-10),
    ("TC31 spinning sphere set down, w1", "seed-byerly.md TC31: w1 = k^2 Omega1/(a^2 + k^2) = "
     "(2/7) Omega1", _tc31, r"^  al'\+ = .* = (\S+)$", 2 / 7 * 3, 1e-10),
    ("TC31 spinning sphere set down, w3", "seed-byerly.md TC31: w3 = Omega3", _tc31,
     r"^  ga'\+ = .* = (\S+)$", 5.0, 1e-10),
    ("B T51 rough sphere in a rocking bowl, slow", "seed-desloge-B.md T51: w^2 = x g/b, 156 x^2 "
     "- 260 x + 75 = 0, x = (65 - 10 sqrt 13)/78",
     ["modes", "db_t51.qd", "--about", "x=0, phi=0, th=0"], r"mode 2: w\^2 = (\S+),",
     9.81 * (65 - 10 * sqrt(13)) / 78, 1e-10),
    ("B T51 rough sphere in a rocking bowl, fast", "seed-desloge-B.md T51: x = (65 + 10 sqrt 13)"
     "/78", ["modes", "db_t51.qd", "--about", "x=0, phi=0, th=0"], r"mode 3: w\^2 = (\S+),",
     9.81 * (65 + 10 * sqrt(13)) / 78, 1e-10),
    ("B T51 rough sphere in a rocking bowl, the slide", "seed-desloge-B.md T51: a zero-frequency "
     "horizontal translation", ["modes", "db_t51.qd", "--about", "x=0, phi=0, th=0"],
     r"mode 1: w\^2 = (\S+),", 0.0, 1e-12),
    ("C T31 linear map, B = (A^-1)^T", "seed-desloge-C.md T31: Q = A q, P = B p is canonical "
     "iff B = (A^-1)^T; A = [[1, 1], [0, 1]], B = [[1, 0], [-1, 1]]",
     ["canonical", "dc_t33.qd", "--Q", "q1 + q2, q2", "--P", "p_q1, p_q2 - p_q1"],
     r"^(canonical)", "canonical", None),
    ("C T31 linear map, B = I", "seed-desloge-C.md T31: B = I is not (A^-1)^T: not canonical, "
     "[Q1, P2] = a_12 = 1 where 0 is needed (exit 3)",
     ["canonical", "dc_t33.qd", "--Q", "q1 + q2, q2", "--P", "p_q1, p_q2"],
     r"^not canonical: \[Q1, P2\] = (\S+) \(should be 0\)", 1.0, 1e-12, 3),
    ("A T57 hinged rods struck, PQ's centre", "seed-desloge-A.md T57: 5 J/(4 m) along J",
     ["impulse", "da_t57.qd"], r"^  y1'\+ = .* = (\S+)$", 5 * 2 / (4 * 1.5), 1e-10),
    ("A T57 hinged rods struck, PQ turns", "seed-desloge-A.md T57: 9 J/(4 m a) (P struck along "
     "+y turns PQ clockwise)", ["impulse", "da_t57.qd"], r"^  th1'\+ = .* = (\S+)$",
     -9 * 2 / (4 * 1.5 * 0.4), 1e-10),
    ("A T57 hinged rods struck, QR turns", "seed-desloge-A.md T57: 3 J/(4 m a), the opposite "
     "sense", ["impulse", "da_t57.qd"], r"^  th2'\+ = .* = (\S+)$", 3 * 2 / (4 * 1.5 * 0.4),
     1e-10),
    ("A T47 cylinder on a free wedge, the wedge", "seed-desloge-A.md T47: 2 m g sin al cos al/"
     "(3 (M + m) - 2 m cos^2 al), opposite to the cylinder's horizontal motion",
     ["eom", "da_t47.qd", "--at", "X=0"], r"^  X'' = (\S+)$",
     -2 * 2 * 9.81 * sin(0.6) * cos(0.6) / (15 - 4 * cos(0.6) ** 2), 1e-12),
    ("A T47 cylinder on a free wedge, the roll", "seed-desloge-A.md T47: s'' = 2 (M + m) g sin al"
     "/(3 (M + m) - 2 m cos^2 al)", ["eom", "da_t47.qd", "--at", "X=0"], r"^  s'' = (\S+)$",
     2 * 5 * 9.81 * sin(0.6) / (15 - 4 * cos(0.6) ** 2), 1e-12),
    ("A T53 hoop on a free incline", "seed-desloge-A.md T53: s'' = (M + m) g sin al/(2 (M + m) - "
     "m cos^2 al)", ["eom", "da_t53.qd", "--at", "x=0"], r"^  s'' = (\S+)$",
     5 * 9.81 * sin(0.6) / (10 - 2 * cos(0.6) ** 2), 1e-12),
    ("G03 bead on a turning wire, r''", "seed-goldstein-britannica.md G03: r'' = omega^2 r",
     _g03, r"^  r'' = (\S+)$", 0.7 ** 2 * 1.5, 1e-12),
    ("G03 bead on a turning wire, the torque", "seed-goldstein-britannica.md G03: the "
     "multiplier of th - omega t = 0 is the torque 2 m omega r r'", _g03,
     r"^  lambda_wire = (\S+)$", 2 * 1.3 * 0.7 * 1.5 * 0.3, 1e-12),
    ("TC07 particle in a turning tube", "seed-byerly.md TC07: r = a cosh(omega t)",
     ["simulate", "by_tc07.qd", "--t-end", "1", "--rtol", "1e-12"], r"^1,(\S+?),",
     0.5 * cosh(2), 1e-9),
]

CASES = _byerly + _desloge_a + _desloge_b + _desloge_c + _desloge_d + _gb + _extra + _second
