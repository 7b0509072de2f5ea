#!/usr/bin/env python3
"""The manual's examples are tests (jq's habit).

- Every fenced block in docs/language.md that is a whole model (it declares
  coordinates) must pass `qdot check`.
- Every fenced block in docs/cli.md and README.md is replayed as a shell
  session: `$ cat NAME` followed by text creates that file; `$ qdot ...` runs
  the command (in a scratch directory where examples/ is the repository's)
  and must exit 0 (or 2 when the text shows an `error:`, or N when the
  command line ends with a comment `  # exit N`); the lines shown
  after it, when there are any, must be what the command prints (stdout, then
  stderr), where a line `...` stands for any number of lines.
- Every command `qdot --help` lists has a section in docs/cli.md with at
  least one worked example (a `$ qdot COMMAND` line).

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


def sessions(block):
    """(command line, shown output lines) pairs, in order."""
    out, cur = [], None
    for line in block.splitlines():
        if line.startswith('$ '):
            cur = [line[2:], []]
            out.append(cur)
        elif cur is not None:
            cur[1].append(line)
    return out


def clean(shown):
    """The shown output without the manual's own remarks (`  # ...` at the end
    of a line) and without trailing blank lines."""
    lines = [re.sub(r'\s{2,}# .*$', '', s) for s in shown]
    while lines and not lines[-1].strip():
        lines.pop()
    return lines


def matches(shown, got):
    """shown lines (with '...' wildcards) against got lines, exactly."""
    if not shown:
        return not got
    if shown[0].strip() == '...':
        return any(matches(shown[1:], got[k:]) for k in range(len(got) + 1))
    return bool(got) and same_line(shown[0], got[0]) and matches(shown[1:], got[1:])


def same_line(shown, got):
    """Equal, where '...' inside a line stands for any text (a wall time)."""
    shown, got = shown.rstrip(), got.rstrip()
    if '...' not in shown:
        return shown == got
    pattern = '.*'.join(re.escape(part) for part in shown.split('...'))
    return re.fullmatch(pattern, got) is not None


def check_models(root, qdot, tmp, failed):
    passed = 0
    lang = open(os.path.join(root, 'docs', 'language.md')).read()
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
    return passed


def check_sessions(name, text, qdot, work, failed):
    passed = 0
    for b in blocks(text):
        for cmd, shown in sessions(b):
            words = shlex.split(cmd.split('  #')[0])
            if words[:1] == ['cat'] and len(words) == 2:
                with open(os.path.join(work, words[1]), 'w') as f:
                    f.write('\n'.join(shown) + '\n')
                continue
            if words[:1] not in (['qdot'], ['build/qdot']):
                continue
            r = subprocess.run([qdot] + words[1:], capture_output=True, text=True, cwd=work,
                               timeout=120)
            note = re.search(r'  # exit (\d+)\s*$', cmd)
            want = int(note.group(1)) if note else 2 if any('error:' in s for s in shown) else 0
            got = (r.stdout + r.stderr).splitlines()
            where = '%s: $ %s' % (name, cmd)
            if r.returncode != want:
                failed.append('%s\n  exit %d, expected %d\n%s' % (where, r.returncode, want,
                                                                   r.stderr))
            elif clean(shown) and not matches(clean(shown), got):
                failed.append('%s\n  shown:\n%s\n  printed:\n%s' % (
                    where, '\n'.join('    ' + s for s in shown),
                    '\n'.join('    ' + g for g in got)))
            else:
                passed += 1
    return passed


def check_coverage(root, qdot, failed):
    """Each command of `qdot --help` has a section with a worked example."""
    cli = open(os.path.join(root, 'docs', 'cli.md')).read()
    help_text = subprocess.run([qdot, '--help'], capture_output=True, text=True).stdout
    commands = re.findall(r'^  ([a-z]+) ', help_text.split('commands:')[1].split('\n\n')[0],
                          re.M)
    passed = 0
    for c in commands:
        has_section = re.search(r'^#+ .*`qdot %s\b' % c, cli, re.M) or \
            re.search(r'^\| `qdot %s\b' % c, cli, re.M)
        has_example = re.search(r'^\$ (?:build/)?qdot %s\b' % c, cli, re.M)
        if has_section and has_example:
            passed += 1
        else:
            failed.append('docs/cli.md: command %s has no section with a worked example' % c)
    return passed


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--build', required=True)
    ap.add_argument('--root', required=True)
    args = ap.parse_args()
    root = os.path.abspath(args.root)
    qdot = os.path.abspath(os.path.join(args.build, 'qdot'))
    failed = []
    with tempfile.TemporaryDirectory() as tmp:
        passed = check_models(root, qdot, tmp, failed)
        work = os.path.join(tmp, 'work')
        os.mkdir(work)
        os.symlink(os.path.join(root, 'examples'), os.path.join(work, 'examples'))
        for name in ('docs/cli.md', 'README.md'):
            text = open(os.path.join(root, name)).read()
            passed += check_sessions(name, text, qdot, work, failed)
    passed += check_coverage(root, qdot, failed)
    for f in failed:
        print('FAIL ' + f)
    print('%d passed, %d failed' % (passed, len(failed)))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
