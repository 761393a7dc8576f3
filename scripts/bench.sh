#!/usr/bin/env bash
# Runs every benchmark executable of a build and prints its figures.
set -eu
build=${1:-build}
found=0
for b in "$build"/bench/bench_*; do
  [ -x "$b" ] || continue
  found=1
  echo "== $(basename "$b")"
  "$b"
done
[ "$found" = 1 ] || echo "bench: no benchmarks built in $build/bench"
