#!/usr/bin/env python3
"""Every error the program shows goes through the library's one renderer:
FILE:LINE:COL, the source line, a caret under the spot and a hint, for model
files, state strings (--at) and expressions on the command line alike.  The
place and the hint come from the library's error record, not from searching
the message (issue 11).

    python3 tests/cli/check_diag_cli.py --build BUILD_DIR

Each row of CASES is (args, expected exit status, fragments that must all
appear in stderr, in order).  The rows marked "was:" failed before the error
records.  The brackets after the table are canonical, so the answer is
known: [x, p_x] = 1, hence [-x, p_x] = -1 and d(-x)/dt = -p_x/m for the
oscillator H = p_x^2/(2m) + k x^2/2 (Goldstein sec. 9.5).

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import subprocess
import sys
import tempfile
from pathlib import Path

results = {'passed': 0, 'failed': 0}

DEEP = 'coordinates x\nT = x\'^2/2\nV = ' + '(' * 10000 + 'x' + ')' * 10000 + '\n'
MODELS = {
    'deep.qd': DEEP.encode(),
    'ff.qd': b"coordinates x\xff\nT = x'^2/2\n",
    'theta.qd': "coordinates x\nparameters θ = 1\nT = x'^2/2\n".encode(),
    'unknown.qd': b"coordinates x\nT = x'^2/2\nfrobnicate x\n",
    'linear_l.qd': b"coordinates y, x\nL = x'*y - y'^4/4\n",
    'no.qd': b"coordinates x, y, z\nT = (x'^2 + y'^2 + z'^2)/2\nconstraint no: z = 0\n"
             b"constraint a: x' + y' = 0\nconstraint b: x' + y' = 1\n",
    'ho.qd': b"coordinates x\nparameters m = 2, k = 3\nT = m/2*x'^2\nV = k/2*x^2\n",
}

USAGE = 2
CASES = [
    # was: a segmentation fault (the model parser recursed without limit)
    (['eom', 'deep.qd'], USAGE,
     ['deep.qd:3:261: error: expression nested too deeply\n  ...(((',
      '\n' + ' ' * 55 + '^\n', 'hint: brackets and signs nest at most 256 deep']),
    (['simplify', '(' * 300 + 'x' + ')' * 300], USAGE,
     ['<expression>:1:257: error: expression nested too deeply', 'hint: brackets and signs']),
    # was: "unexpected an unexpected character after the statement"
    (['eom', 'ff.qd'], USAGE,
     ['ff.qd:1:14: error: invalid UTF-8 at byte 13: byte 0xff is not UTF-8 there\n  coordinates x?',
      '\n' + ' ' * 15 + '^\n', 'hint: ']),
    (['eom', 'theta.qd'], USAGE,
     ["theta.qd:2:12: error: 'θ' (U+03B8) cannot be used in a name; names are ASCII letters, "
      "digits and _\n  parameters θ = 1\n             ^\n", 'hint: ']),
    (['eom', '--at', b'x=\xff', 'ho.qd'], USAGE,
     ['--at:1:3: error: unexpected byte 0xff (not UTF-8 text)', '\n    ^\n']),
    # was: the hint listed neither reaction nor rolls
    (['eom', 'unknown.qd'], USAGE,
     ["unknown.qd:3:1: error: unknown statement 'frobnicate'", '  ^~~~~~~~~~\n',
      'hint: a statement starts with a keyword', 'rolls', 'reaction']),
    # was: "qdot: error: not linear in y'" with no place and no hint; a quartic L now has an
    # implicit H, and an L linear in a velocity is the error, at the coordinate
    (['hamiltonian', 'linear_l.qd'], USAGE,
     ["linear_l.qd:1:16: error: L is linear in x': its Hessian in the velocities is singular, "
      "so there is no Hamiltonian (p_x = y does not depend on x')",
      "\n  coordinates y, x\n                 ^\n", "hint: a Hamiltonian needs"]),
    # was: the caret under `no`, whose name occurs in "no motion satisfies them all"
    (['eom', 'no.qd'], USAGE,
     ['no.qd:4:12: error: constraints a and b are inconsistent',
      "\n  constraint a: x' + y' = 0\n             ^\n", 'hint: the constraints contradict']),
    (['check', 'no.qd'], USAGE, ['no.qd:4:12: error: constraints a and b are inconsistent']),
]


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    if not ok:
        print('FAIL %s %s' % (name, detail))


def run(qdot, cwd, args):
    return subprocess.run([qdot, *args], capture_output=True, timeout=60, cwd=cwd)


def in_order(text, fragments):
    at = 0
    for f in fragments:
        at = text.find(f, at)
        if at < 0:
            return False
        at += len(f)
    return True


def check_table(qdot, cwd):
    for args, code, fragments in CASES:
        name = ' '.join(a if isinstance(a, str) else repr(a) for a in args)[:60]
        p = run(qdot, cwd, args)
        err = p.stderr.decode('utf-8', 'replace')
        clean = 'Sanitizer' not in err and 'runtime error' not in err
        check(name, p.returncode == code and in_order(err, fragments) and clean,
              'exit %d, stderr: %s' % (p.returncode, err.strip()[:600]))


def check_negative_expressions(qdot, cwd):
    """An expression starting with '-' is an expression, not an option
    (was: "unknown option or missing value: '-x'")."""
    for args, want in [(['-x', 'p_x'], '[-x, p_x] = -1'), (['x', '-p_x'], '[x, -p_x] = -1'),
                       (['-2*x', 'p_x'], '[-2*x, p_x] = -2'),
                       (['--dt', '-x'], 'd/dt(-x) = -p_x/m'),
                       (['--', '-x', '-p_x'], '[-x, -p_x] = 1')]:
        p = run(qdot, cwd, ['bracket', 'ho.qd', *args])
        out = p.stdout.decode()
        check('bracket ' + ' '.join(args), p.returncode == 0 and want in out,
              'exit %d, out %r, err %r' % (p.returncode, out, p.stderr.decode()[:300]))
    p = run(qdot, cwd, ['bracket', 'ho.qd', '--nosuch', 'x'])
    check('bracket --nosuch is still an unknown option',
          p.returncode == USAGE and b"has no option '--nosuch'" in p.stderr,
          p.stderr.decode()[:300])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build).resolve() / 'qdot')
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in MODELS.items():
            (Path(tmp) / name).write_bytes(text)
        check_table(qdot, tmp)
        check_negative_expressions(qdot, tmp)
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())
