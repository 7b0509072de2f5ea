#!/usr/bin/env python3
"""Reading a model file and what `qdot check` says of its numbers (issue 30):

  - /dev/zero and a file with a NUL byte: a located error at once (the file
    was read whole first, and /dev/zero ate all memory); a directory given
    as a model or as a CSV: "is a directory"; a file over 64 MiB refused;
  - an acceleration in L, T or V: exit 2 at the energy, with a caret
    (L = m/2*q'^2 - q*q'' gave M = m + 1);
  - two names of 130 bytes with a common 127-byte prefix: refused at the
    name, not merged;
  - CR-only and CRLF line ends: read as line ends, errors at the right
    LINE:COL;
  - invalid UTF-8 (an overlong 0xC0 0x80): "invalid UTF-8 at byte N";
  - an initial value given twice: an error at the second naming the first;
  - m = 0 and a negative inertia: the mass matrix is not positive definite;
    a constraint x^2 + y^2 = -1: no real solution; an initial state off the
    constraints: check notes it, simulate says how far the start moved.

    python3 tests/cli/check_model_input_cli.py --build BUILD_DIR

Prints "N passed, N failed"; exit 1 on failure."""
import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[2] / 'examples'

results = {'passed': 0, 'failed': 0}
HO = b"coordinates q\nparameters m = 1, k = 1\nT = m/2*q'^2\nV = k/2*q^2\n"
PENDULUM = (b"coordinates x, y\nparameters m = 1, l = 1\nT = m/2*(x'^2 + y'^2)\nV = m*9.81*y\n"
            b"constraint rod: x^2 + y^2 = l^2\n")


def check(name, ok, detail=''):
    results['passed' if ok else 'failed'] += 1
    print(('ok   ' if ok else 'FAIL ') + name + ('' if ok else ': ' + detail))


def run(qdot, cwd, args, timeout=20):
    try:
        return subprocess.run([qdot, *args], cwd=cwd, capture_output=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None


def expect(qdot, cwd, name, args, code, fragments, timeout=20):
    p = run(qdot, cwd, args, timeout)
    if p is None:
        check(name, False, 'timed out')
        return None
    err = p.stderr.decode('utf-8', 'replace')
    missing = [f for f in fragments if f not in err]
    check(name, p.returncode == code and not missing and 'Sanitizer' not in err,
          'exit %d, missing %r, stderr: %s' % (p.returncode, missing, err[:500]))
    return p


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    qdot = str(Path(ap.parse_args().build).resolve() / 'qdot')
    with tempfile.TemporaryDirectory() as tmp:
        d = Path(tmp)
        files = {
            'nul.qd': HO[:20] + b'\0' + HO[20:],
            'accel_l.qd': b"coordinates q\nparameters m = 1\nL = m/2*q'^2 - q*q''\n",
            'accel_v.qd': b"coordinates q\nparameters k = 1\nT = q'^2/2\nV = k/2*q^2 + q''^2\n",
            'accel_t.qd': b"coordinates q\nT = q'^2/2 + q*q''\n",
            'long.qd': ("coordinates q\nparameters %s1 = 1, %s2 = 2\nT = q'^2/2\n"
                        % ('a' * 129, 'a' * 129)).encode(),
            'long_ok.qd': ("coordinates q\nparameters %s = 2\nT = %s/2*q'^2\n"
                           % ('b' * 127, 'b' * 127)).encode(),
            'cr.qd': b"coordinates q\rparameters m = 1\rT = m/2*q'^2\rV = nosuch*q\r",
            'cr_ok.qd': b"coordinates q\rparameters m = 1 # a comment\rT = m/2*q'^2\r",
            'crlf.qd': b"coordinates q\r\nparameters m = 1\r\nT = m/2*q'^2\r\nV = nosuch*q\r\n",
            'overlong.qd': b"coordinates q\nT = q'^2/2 # \xc0\x80\n",
            'dup.qd': HO + b"initial q = 1, q' = 0, q = 2\n",
            'dup2.qd': HO + b"initial q = 1\ninitial q' = 0\ninitial q' = 3\n",
            'm0.qd': b"coordinates q\nparameters m = 0\nT = m/2*q'^2\n",
            'neg.qd': b"coordinates q, r\nparameters m = 1, I = -2\nT = m/2*q'^2 + I/2*r'^2\n",
            'noreal.qd': b"coordinates x, y\nT = (x'^2 + y'^2)/2\nconstraint a: x^2 + y^2 = -1\n",
            'off.qd': PENDULUM + b"initial x = 3, y = 0\n",
            'on.qd': PENDULUM + b"initial x = 1, y = 0\n",
            'ramp.qd': HO + b"inputs F\nQ[q] = F\n",
        }
        for name, text in files.items():
            (d / name).write_bytes(text)
        (d / 'adir').mkdir()
        (d / 'adir.csv').mkdir()

        expect(qdot, tmp, 'check /dev/zero stops at the first NUL', ['check', '/dev/zero'], 2,
               ['/dev/zero:1:1: error: a NUL byte at byte 0'], timeout=10)
        expect(qdot, tmp, 'a NUL byte is located', ['check', 'nul.qd'], 2,
               ['nul.qd:2:7: error: a NUL byte at byte 20'])
        expect(qdot, tmp, 'a directory as a model', ['check', 'adir'], 2,
               ["cannot read adir: is a directory"])
        expect(qdot, tmp, 'a directory as a CSV',
               ['simulate', 'ramp.qd', '--t-end', '1', '--input', 'F=adir.csv'], 2,
               ["cannot read adir.csv: is a directory"])
        big = d / 'big.qd'
        with open(big, 'wb') as f:
            f.write(HO)
            f.write(b'#' * (64 << 20) + b'\n')
        expect(qdot, tmp, 'a model over 64 MiB', ['check', 'big.qd'], 2,
               ["'big.qd' is longer than 64 MiB"])
        big.unlink()

        for name, what, line in (('accel_l.qd', 'L', 3), ('accel_v.qd', 'V', 4),
                                 ('accel_t.qd', 'T', 2)):
            expect(qdot, tmp, 'an acceleration in ' + what, ['check', name], 2,
                   ["%s:%d:5: error: %s depends on the acceleration q''" % (name, line, what),
                    '^~~', 'hint: '])

        expect(qdot, tmp, 'a name of 130 bytes is refused, not cut', ['check', 'long.qd'], 2,
               ['long.qd:2:12: error: a name of 130 bytes; names are at most 127 bytes'])
        p = run(qdot, tmp, ['check', 'long_ok.qd'])
        check('a name of 127 bytes is kept whole', p.returncode == 0 and
              ('b' * 127 + ' = 2').encode() in p.stdout, p.stderr.decode()[:300])

        expect(qdot, tmp, 'CR-only line ends: LINE:COL', ['check', 'cr.qd'], 2,
               ["cr.qd:4:5: error: unknown name 'nosuch'", '\n  V = nosuch*q\n      ^~~~~~\n'])
        p = run(qdot, tmp, ['check', 'cr_ok.qd'])
        check('CR-only line ends and a comment', p.returncode == 0, p.stderr.decode()[:300])
        expect(qdot, tmp, 'CRLF line ends: LINE:COL', ['check', 'crlf.qd'], 2,
               ["crlf.qd:4:5: error: unknown name 'nosuch'", '\n  V = nosuch*q\n      ^~~~~~\n'])

        expect(qdot, tmp, 'an overlong UTF-8 encoding', ['check', 'overlong.qd'], 2,
               ['overlong.qd:2:14: error: invalid UTF-8 at byte 27: byte 0xc0 starts an '
                'overlong encoding', '# ??\n'])

        expect(qdot, tmp, 'initial q twice in one statement', ['check', 'dup.qd'], 2,
               ['dup.qd:5:24: error: the initial value of q is given twice (first on line 5)',
                'first is at line 5, column 9'])
        expect(qdot, tmp, "initial q' in two statements", ['check', 'dup2.qd'], 2,
               ["dup2.qd:7:9: error: the initial value of q' is given twice (first on line 6)"])

        # a model that reads but fails the numbers is a certified "no": exit 3
        expect(qdot, tmp, 'm = 0', ['check', 'm0.qd'], 3,
               ['m0.qd:3:1: error: the mass matrix is not positive definite',
                'its pivot for q is 0'])
        expect(qdot, tmp, 'a negative inertia', ['check', 'neg.qd'], 3,
               ['error: the mass matrix is not positive definite', 'its pivot for r is -2'])
        expect(qdot, tmp, 'x^2 + y^2 = -1', ['check', 'noreal.qd'], 3,
               ['noreal.qd:3:12: error: constraint a has no real solution'])
        # the same in JSON: the machine code next to the English, and the witness
        p = run(qdot, tmp, ['check', 'm0.qd', '--format', 'json'])
        out = json.loads(p.stdout.decode()) if p.returncode == 3 else {}
        check('check --format json: m = 0 is a no with its pivot', out.get('ok') is False and
              out.get('code') == 'mass_not_positive_definite' and out.get('witness') == 0 and
              out.get('reason') == 'the mass matrix is not positive definite' and
              'not positive definite' in out.get('message', ''), p.stdout.decode()[:300])
        p = run(qdot, tmp, ['check', 'noreal.qd', '--format', 'json'])
        out = json.loads(p.stdout.decode()) if p.returncode == 3 else {}
        check('check --format json: no real solution', out.get('code') ==
              'constraint_not_real' and out.get('about') == 'a' and out.get('witness', 0) > 0,
              p.stdout.decode()[:300])
        # Kepler: theta is cyclic and its momentum, the angular momentum m r^2 theta', is
        # conserved, and so is the energy (no t, no forces)
        p = run(qdot, tmp, ['check', str(EXAMPLES / 'kepler_polar.qd'), '--format', 'json'])
        out = json.loads(p.stdout.decode()) if p.returncode == 0 else {}
        cyc = out.get('cyclic', [{}])
        check('check --format json: Kepler', out.get('ok') is True and
              cyc[0].get('coordinate') == 'theta' and cyc[0].get('conserved') is True and
              cyc[0].get('momentum') == "m*r^2*theta'" and out.get('energy_conserved') is True and
              out['depends']['V']['coordinates'] == ['r'], p.stdout.decode()[:300])
        expect(qdot, tmp, 'check notes an initial state off the constraints',
               ['check', 'off.qd'], 0, ['note: the initial state is off constraint rod by 8'])
        p = run(qdot, tmp, ['check', 'on.qd'])
        check('no note on the constraints', p.returncode == 0 and b'note' not in p.stderr,
              p.stderr.decode()[:300])
        expect(qdot, tmp, 'simulate says how far the start moved',
               ['simulate', 'off.qd', '--t-end', '0.1'], 0,
               ["note: the initial state was off the constraints and was projected onto them: "
                "q moved by 2, q' by 0"])
        p = run(qdot, tmp, ['simulate', 'on.qd', '--t-end', '0.1'])
        check('simulate: no note on the constraints', p.returncode == 0 and
              b'note' not in p.stderr, p.stderr.decode()[:300])
    print('%d passed, %d failed' % (results['passed'], results['failed']))
    return 1 if results['failed'] else 0


if __name__ == '__main__':
    sys.exit(main())
