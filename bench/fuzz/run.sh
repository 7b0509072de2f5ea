#!/bin/sh
# Fuzz the model parser with libFuzzer (clang), ASan and UBSan.
# Usage: bench/fuzz/run.sh [SECONDS]   (default 600); new inputs land in corpus/
# (or in $FUZZ_CORPUS: a scratch copy, to try without touching the kept corpus).
set -e
here=$(cd "$(dirname "$0")" && pwd)
root=$here/../..
secs=${1:-600}
out=${TMPDIR:-/tmp}/qdot-fuzz
mkdir -p "$out" "$here/corpus"
clang -g -O1 -std=c11 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all \
  -I"$root/include" -I"$root/src" -isystem /usr/include/flint \
  "$here/fuzz_model.c" $(ls "$root"/src/base/*.c "$root"/src/sym/*.c "$root"/src/model/*.c) -lflint -lgmp -lm -o "$out/fuzz_model"
"$out/fuzz_model" -max_total_time="$secs" -timeout=10 -max_len=4096 \
  -dict="$here/model.dict" "${FUZZ_CORPUS:-$here/corpus}" "$root/examples"
