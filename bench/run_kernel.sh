#!/bin/sh
# make bench: the kernel benchmark against GiNaC and SymPy.
# Usage: bench/run_kernel.sh BUILD_DIR [--quick] [--no-sympy] [--rounds N] [NAME...]
# (the work is done by run_kernel.py; see bench/README.md)
set -e
[ $# -ge 1 ] || { echo "usage: $0 BUILD_DIR [--quick] [--no-sympy] [--rounds N] [NAME...]" >&2; exit 2; }
exec /usr/bin/python3 "$(dirname "$0")/run_kernel.py" "$@"
