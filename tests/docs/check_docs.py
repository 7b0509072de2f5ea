#!/usr/bin/env python3
"""The manual's examples are tests (jq's habit): every fenced block in
docs/language.md that is a whole model (it declares coordinates) must pass
`qdot check`, and every block in docs/cli.md that shows `$ qdot ...` on an
example file must run with exit status 0.

Usage: check_docs.py --build BUILD_DIR --root SOURCE_DIR
"""
import argparse
import os
import re
import shlex
import subprocess
import sys
import tempfile


def blocks(text):
    return re.findall(r"```[a-z]*\n(.*?)```", text, re.S)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.add_argument('--root', required=True)
    args = ap.parse_args()
    qdot = os.path.join(args.build, 'qdot')
    passed, failed = 0, []
    lang = open(os.path.join(args.root, 'docs', 'language.md')).read()
    with tempfile.TemporaryDirectory() as tmp:
        for i, b in enumerate(blocks(lang)):
            if not re.search(r'^coordinates\b', b, re.M):
                continue
            path = os.path.join(tmp, 'block%d.qd' % i)
            with open(path, 'w') as f:
                f.write(b)
            r = subprocess.run([qdot, 'check', path], capture_output=True, text=True)
            if r.returncode == 0:
                passed += 1
            else:
                failed.append('language.md block %d:\n%s\n%s' % (i, b, r.stderr))
    cli = open(os.path.join(args.root, 'docs', 'cli.md')).read()
    readme = open(os.path.join(args.root, 'README.md')).read()
    for b in blocks(cli) + blocks(readme):
        for line in b.splitlines():
            m = re.match(r'\$ (?:build/)?qdot (.*)', line)
            if not m:
                continue
            words = shlex.split(m.group(1).split('  #')[0])
            if any(w.endswith('.qd') and not w.startswith('examples/') for w in words):
                continue  # a file of the reader's own
            r = subprocess.run([qdot] + words, capture_output=True, text=True, cwd=args.root)
            want_fail = words[0] in ('expand',) and '(x + 1' in words[1:2]
            if (r.returncode == 0) != (not want_fail):
                failed.append('%s: exit %d\n%s' % (line, r.returncode, r.stderr))
            else:
                passed += 1
    for f in failed:
        print('FAIL ' + f)
    print('%d passed, %d failed' % (passed, len(failed)))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
