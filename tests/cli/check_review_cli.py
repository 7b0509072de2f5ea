#!/usr/bin/env python3
"""Bad input to the analysis commands (routh, integrals, equilibria, modes,
stability, codegen) and to models given by H: every case gets a clear error
and the right exit status (2 for bad input, 1 for a numerical failure),
never a crash, a sanitizer report or a silently wrong answer.

    python3 tests/cli/check_review_cli.py --build BUILD_DIR

Each row of CASES is (args, expected exit status, fragment of stderr); the
models not in examples/ are written to a temporary directory (MODELS).  The
cases that used to misbehave are marked "was:".

The values checked after the table are physics, not the program's own
output: the compound pendulum (examples/compound_pendulum.qd: the bar
pivoted at distance h from its centre, radius of gyration k) has, with the
pivot constraints eliminated, T = m (k^2 + h^2) theta'^2 / 2 and
V = -m g h cos(theta) (Desloge ch. 54; Goldstein sec. 1.4 for the
elimination), so linearized about theta0: M0 = m (k^2 + h^2), K0 = m g h
cos(theta0), and the force at rest is m g h sin(theta0).

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'
results = {'passed': 0, 'failed': 0}

MODELS = {
    'hkepler.qd': 'coordinates r, theta\nparameters m = 1.3, k = 4\nmomenta p_r, p_theta\n'
                  'H = p_r^2/(2*m) + p_theta^2/(2*m*r^2) - k/r\n',
    'hquartic.qd': 'coordinates x\nmomenta p\nH = p^4 + x^2\n',
    'one.qd': "coordinates x\nparameters m = 1, k = 2\nT = m/2*x'^2\nV = k/2*x^2\n",
    'empty.qd': '',
    'free.qd': "coordinates x\nT = x'^2/2\n",
    'bigparam.qd': "coordinates x\nparameters a = 1.5^(1.5e31)\nT = a*x'^2/2\n",
    'nanparam.qd': "coordinates x\nparameters a = sqrt(-1)\nT = x'^2/2\n",
    'badinit.qd': "coordinates x\nT = x'^2/2\nV = x^2/2\ninitial x = 1e400\n",
    'deep.qd': "coordinates x\nT = x'^2/2\nV = " + '(' * 10000 + 'x' + ')' * 10000 + '\n',
    'deepsign.qd': "coordinates x\nT = x'^2/2\nV = " + '-' * 10000 + 'x\n',
}

KEPLER = str(EXAMPLES / 'kepler_polar.qd')
KCART = str(EXAMPLES / 'kepler_cartesian.qd')
COMPOUND = str(EXAMPLES / 'compound_pendulum.qd')
POWER = str(EXAMPLES / 'power_law_orbit.qd')

USAGE, FAIL = 2, 1
CASES = [
    # options: missing values, repeated, unknown, bad --format
    (['routh', KEPLER, '--ignore'], USAGE, "--ignore needs a value"),
    # was: "bad, repeated or incomplete option 'theta'" (the value, not the option)
    (['routh', KEPLER, '--ignore', 'theta', '--ignore', 'theta'], USAGE, '--ignore is given twice'),
    (['routh', KEPLER, '--ignore', 'theta', '--format', 'c'], USAGE,
     "unknown value 'c' (one of text, json, latex, sympy)"),
    (['routh', KEPLER], USAGE, 'routh needs --ignore'),
    (['integrals', KCART, '--format'], USAGE, "--format needs a value"),
    (['integrals', KCART, '--format', 'sympy'], USAGE, "unknown value 'sympy' (one of text, json, latex)"),
    (['integrals', KCART, '--no-search=1'], USAGE, '--no-search takes no value'),
    (['equilibria', 'one.qd', '--guess', 'x=1', '--guess', 'x=2'], USAGE, '--guess is given twice'),
    (['equilibria', 'one.qd', '--format', 'yaml'], USAGE, "unknown value 'yaml' (one of text, json)"),
    (['modes', 'one.qd', '--about', 'x=0', '--at-equilibrium', '1'], USAGE, 'not both'),
    (['modes', 'one.qd', '--at-equilibrium', '0'], USAGE, "'0' is not a whole number >= 1"),
    (['modes', 'one.qd', '--at-equilibrium', '1', '--at-equilibrium', '1'], USAGE,
     'given twice'),
    (['stability', POWER, '--ignore', 'theta', '--format', 'latex'], USAGE,
     "unknown value 'latex' (one of text, json)"),
    (['stability', POWER, '--ignore', 'theta', '--at', 'r=1', '--at', 'r=2'], USAGE,
     '--at is given twice'),
    (['codegen', 'one.qd', '-o', '.', '-o', '.'], USAGE, '--out is given twice'),
    (['codegen', 'one.qd', '--prefix', '1abc'], USAGE, 'C identifier'),
    # lists with a name twice: was "every coordinate is ignored" / accepted, last one won
    (['routh', KEPLER, '--ignore', 'theta,theta'], USAGE, 'theta is listed twice'),
    (['stability', POWER, '--ignore', 'theta,theta', '--at', 'r=1'], USAGE,
     'theta is listed twice'),
    (['stability', POWER, '--ignore', 'theta', '--at', 'r=1, r=2'], USAGE, 'r is given twice'),
    (['stability', POWER, '--driven', "theta'=1", '--driven', "theta'=2"], USAGE,
     "rate theta' is given twice"),
    (['stability', POWER, '--ignore', 'theta', '--momentum', 'p_theta=1, p_theta=2'], USAGE,
     'p_theta is given twice'),
    (['equilibria', COMPOUND, '--box', 'theta=0:1, theta=1:2'], USAGE, "'theta' is given twice"),
    # was: --at r=r evaluated the coordinate at 0 ("equations not defined")
    (['stability', POWER, '--ignore', 'theta', '--at', 'r=r'], USAGE,
     "takes only pi, e and the model's parameters"),
    # values: not finite, too large for a double (was: 1e400 taken as inf, exit 0 or 1)
    (['routh', KEPLER, '--ignore', 'theta', '--set', 'm=1/0'], USAGE, 'division by zero'),
    (['routh', KEPLER, '--ignore', 'theta', '--set', 'm=1e400'], USAGE, 'too large'),
    (['modes', 'one.qd', '--set', 'k=1e400'], USAGE, 'too large'),
    (['codegen', 'one.qd', '-o', '.', '--set', 'k=1e999'], USAGE, 'too large'),
    (['modes', 'one.qd', '--set', 'k=nan'], USAGE, "unknown name 'nan'"),
    (['stability', POWER, '--ignore', 'theta', '--at', 'r=1/0'], USAGE, 'division by zero'),
    # eliminated coordinates (was: a heap overflow for --near/--about, and --box,
    # --initial silently applied to the wrong coordinate)
    (['equilibria', COMPOUND, '--guess', 'y=0.1'], USAGE, 'y is not an independent coordinate'),
    (['equilibria', COMPOUND, '--box', 'x=-1:1'], USAGE, 'x is not an independent coordinate'),
    (['modes', COMPOUND, '--about', 'x=0.5'], USAGE, 'x is not an independent coordinate'),
    (['modes', COMPOUND, '--initial', "theta=0.1, y'=1"], USAGE,
     'y is not an independent coordinate'),
    (['modes', COMPOUND, '--about', "theta'=1"], USAGE, 'a point at rest'),
    (['modes', COMPOUND, '--about', 'theta=1, m=3'], USAGE, 'm is a parameter'),
    (['modes', COMPOUND, '--about', 'theta=1, t=3'], USAGE, 'not the time t'),
    # errors name the option they come from (was: "--at:" for --near, --about, --initial)
    (['equilibria', 'one.qd', '--guess', 'x'], USAGE, "--guess:1:1: error: expected NAME=VALUE, not 'x'"),
    # --near was --guess's name in equilibria (issue 31): still taken, with a warning
    (['equilibria', 'one.qd', '--near', 'x'], USAGE, "qdot: warning: --near is now --guess"),
    (['modes', 'one.qd', '--about', 'x='], USAGE, '--about:1:3: error: empty expression'),
    (['modes', 'one.qd', '--initial', 'zz=1'], USAGE, "--initial:1:1: error: unknown name 'zz'"),
    (['modes', 'one.qd', '--at-equilibrium', '2'], USAGE, 'there is 1 equilibrium'),
    # was: -o "" wrote /NAME.c and /NAME.h
    (['codegen', 'one.qd', '-o', ''], USAGE, '-o takes a directory'),
    # --symmetry and --integral are read by the model's own parser (was: a
    # coordinate moved twice, eps in the field form, a constant integral and
    # a velocity in an H model's integral were accepted)
    (['integrals', KCART, '--symmetry', 'x -> x + eps, x -> x'], USAGE, "'x' is moved twice"),
    (['integrals', KCART, '--symmetry', 'delta x = eps'], USAGE, "unknown name 'eps'"),
    (['integrals', KCART, '--symmetry', 'delta q = 1'], USAGE, "'q' is not a coordinate"),
    (['integrals', KCART, '--symmetry', 'x -> y'], USAGE, 'at eps = 0'),
    (['integrals', KCART, '--symmetry', "delta x = x'"], USAGE, 'velocity'),
    (['integrals', KCART, '--symmetry', 'x -> x + 1/eps'], USAGE, '--symmetry:1:'),
    (['integrals', KCART, '--symmetry', 'delta x = 1 # note'], USAGE, 'one statement'),
    (['integrals', KCART, '--integral', '0'], USAGE, 'this integral is a constant'),
    (['integrals', KCART, '--integral', "x''"], USAGE, 'acceleration'),
    (['integrals', KCART, '--integral', 'J: x + zz'], USAGE, "--integral:1:8: error: unknown name 'zz'"),
    (['integrals', 'hkepler.qd', '--integral', "theta'"], USAGE, 'velocity theta'),
    # models given by H whose L has no closed form: shown at the H line
    # (was: a plain message without FILE:LINE:COL)
    (['routh', 'hquartic.qd', '--ignore', 'x'], USAGE, 'hquartic.qd:3:1: error: H is not quadratic'),
    (['integrals', 'hquartic.qd'], USAGE, 'hquartic.qd:3:1:'),
    (['modes', 'hquartic.qd'], USAGE, 'hquartic.qd:3:1:'),
    (['equilibria', 'hquartic.qd'], USAGE, 'hquartic.qd:3:1:'),
    (['codegen', 'hquartic.qd', '-o', '.'], USAGE, 'hquartic.qd:3:1:'),
    (['stability', 'hquartic.qd', '--ignore', 'x'], USAGE, 'hquartic.qd:3:1:'),
    (['hamiltonian', 'hquartic.qd'], 0, ''),
    # models given by H that have an L work in every command
    (['routh', 'hkepler.qd', '--ignore', 'theta'], 0, ''),
    (['integrals', 'hkepler.qd', '--integral', 'p_theta'], 0, ''),
    (['stability', 'hkepler.qd', '--ignore', 'theta', '--at', 'r=1'], 0, ''),
    (['codegen', 'hkepler.qd', '-o', '.'], 0, ''),
    (['check', 'hkepler.qd'], 0, ''),
    (['bracket', 'hkepler.qd', 'r', 'p_r'], 0, ''),
    # a parameter that is not a finite real number (was: accepted, printed as nan;
    # the fuzzer's input reached a float-to-long overflow in qd__pow_value)
    (['check', 'bigparam.qd'], USAGE, "bigparam.qd:2:16: error: a parameter's value must be a finite real number"),
    (['modes', 'nanparam.qd'], USAGE, 'nanparam.qd:2:16:'),
    # was: simulate ran from x = inf and printed inf and nan with exit 0
    (['check', 'badinit.qd'], USAGE, 'badinit.qd:4:13: error: an initial value must be a finite'),
    # 10,000 nested brackets or signs: the kernel reader's limit and message
    # (was: a segmentation fault, the model parser recursing without limit)
    (['eom', 'deep.qd'], USAGE, 'deep.qd:3:261: error: expression nested too deeply'),
    (['check', 'deepsign.qd'], USAGE, 'deepsign.qd:3:262: error: expression nested too deeply'),
    (['modes', 'deep.qd'], USAGE, 'hint: brackets and signs nest at most 256 deep'),
    # empty model, constraints where unsupported
    (['modes', 'empty.qd'], USAGE, 'no coordinates are declared'),
    (['routh', str(EXAMPLES / 'pendulum_cartesian.qd'), '--ignore', 'x'], USAGE,
     'constraints is not supported'),
    # on the manifold (issue 37): x is no cyclic coordinate of the pendulum's rest
    (['stability', str(EXAMPLES / 'pendulum_cartesian.qd'), '--ignore', 'x'], USAGE,
     "'x' is not cyclic"),
    (['equilibria', str(EXAMPLES / 'bead_wire_cartesian.qd')], USAGE,
     'constraint wire depends on t'),
]


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, detail))


def run(qdot, cwd, args):
    return subprocess.run([qdot, *args], capture_output=True, text=True, timeout=60, cwd=cwd)


def check_table(qdot, cwd):
    for args, code, fragment in CASES:
        name = ' '.join(args[:1] + [Path(a).name if '/' in a else a for a in args[1:]])
        p = run(qdot, cwd, args)
        clean = 'Sanitizer' not in p.stderr and 'runtime error' not in p.stderr
        check(name, p.returncode == code and fragment in p.stderr and clean,
              'exit %d, stderr: %s' % (p.returncode, p.stderr.strip()[:400]))


def check_eliminated_values(qdot, cwd):
    m, h, k, g = 2.5, 0.4, 0.3, 9.81
    th0 = 0.5
    p = run(qdot, cwd, ['modes', COMPOUND, '--about', 'theta=%r' % th0, '--initial',
                        "theta=0.6, theta'=2", '--format', 'json'])
    check('modes --about on an eliminated model: exit 0', p.returncode == 0, p.stderr)
    if p.returncode:
        return
    d = json.loads(p.stdout)
    M0, K0 = m * (k * k + h * h), m * g * h * math.cos(th0)
    check('about theta0', abs(d['equilibrium']['theta'] - th0) < 1e-12, d['equilibrium'])
    check('M0 = m (k^2 + h^2)', abs(d['mass_matrix'][0][0] - M0) < 1e-9, d['mass_matrix'])
    check('K0 = m g h cos(theta0)', abs(d['stiffness_matrix'][0][0] - K0) < 1e-9, d['stiffness_matrix'])
    check('residual = m g h sin(theta0)',
          abs(d['residual'] - m * g * h * math.sin(th0)) < 1e-9, d['residual'])
    # Q = a^T M0 (q - q0) with a = 1/sqrt(M0): Q = sqrt(M0) (0.6 - 0.5), Q' = sqrt(M0) 2
    mode = d['modes'][0]
    check('Q0', abs(mode['Q0'] - math.sqrt(M0) * 0.1) < 1e-9, mode)
    check('Q0_dot', abs(mode['Q0_dot'] - math.sqrt(M0) * 2) < 1e-9, mode)
    p = run(qdot, cwd, ['equilibria', COMPOUND, '--guess', 'theta=3', '--format', 'json'])
    ok = p.returncode == 0
    if ok:
        th = [e['equilibrium']['theta'] for e in json.loads(p.stdout)['equilibria']]
        ok = len(th) == 1 and abs(abs(th[0]) - math.pi) < 1e-9
    check('equilibria --guess theta=3 finds the inverted position', ok, p.stdout + p.stderr)


def check_free_particle(qdot, cwd):
    # no force anywhere: every x is an equilibrium (was: hundreds of "isolated" points)
    p = run(qdot, cwd, ['equilibria', 'free.qd', '--format', 'json'])
    check('free particle: a continuum of equilibria',
          p.returncode == 0 and json.loads(p.stdout)['continuum'] is True, p.stderr)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build).resolve() / 'qdot')
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in MODELS.items():
            (Path(tmp) / name).write_text(text)
        check_table(qdot, tmp)
        check_eliminated_values(qdot, tmp)
        check_free_particle(qdot, tmp)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())
