"""The textbook audit's replayed cases (issue 33): each a qdot command on a
model of tests/audit/models/, the number it must print (read by a regular
expression from its text output) and the textbook's value for it, from the
verified worked examples of /work/shared/reference (the seed, its item and
formula cited).  No value here was taken from qdot's output.

A case is (name, citation, args, regex, expected, rel): args are the command
and its arguments, a model named by its file under models/; regex has one
group, the number; expected is the reference value (a formula in the model's
parameters, evaluated here); rel the relative tolerance.
"""
from math import pi, sqrt, sin, cos, asin, atan, acos

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

CASES = _byerly + _desloge_a + _desloge_b + _desloge_c + _desloge_d + _gb + _extra
