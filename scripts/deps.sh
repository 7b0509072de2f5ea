#!/bin/sh
# Install the Debian packages qdot builds, tests and benchmarks with.
# Usage: scripts/deps.sh [build|test|bench]   (each includes the ones before)
# As root it runs apt-get; otherwise it prints the one line to run.
set -e
what=${1:-build}
pkgs="cmake make gcc pkg-config libgmp-dev libflint-dev libflint-arb-dev liblapack-dev libsundials-dev"
pkgs="$pkgs libcairo2-dev"  # plots (src/plot): Cairo, and its runtime library with it
pkgs="$pkgs libhdf5-dev"    # qdot sweep --format hdf5 (optional: built when found)
pkgs="$pkgs llvm-14-dev"    # the JIT (modules/llvm.c, optional: built when found)
# Tests: cmocka and SymPy/SciPy for the cross-checks, chromium for the animate
# page (tests/cli/check_animate_cli.py), numpy/cffi/pytest for python/tests, and
# OpenMPI for the 2-rank sweep test (the CLI is built with MPI when it is found);
# clang for make test's clang build (built with warnings as errors, not run).
case $what in
  test|bench) pkgs="$pkgs libcmocka-dev python3 python3-sympy python3-scipy chromium"
              pkgs="$pkgs python3-numpy python3-cffi python3-pytest libopenmpi-dev openmpi-bin clang"
              # pip install . of the Python package, offline (tests/python/check_pip_install.py)
              pkgs="$pkgs python3-pip python3-venv python3-setuptools python3-wheel"
              # examples/tour.ipynb run by nbconvert (tests/python/check_notebook.py)
              pkgs="$pkgs jupyter-nbconvert python3-nbconvert python3-ipykernel python3-matplotlib" ;;
esac
case $what in
  bench) pkgs="$pkgs g++ libginac-dev libgsl-dev" ;;
esac

missing=""
for p in $pkgs; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
  echo "qdot needs these Debian packages:$missing" >&2
  echo "run: sudo apt-get install -y$missing" >&2
  exit 1
fi
echo "installing:$missing"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
# shellcheck disable=SC2086
apt-get install -y -qq --no-install-recommends $missing >/dev/null
