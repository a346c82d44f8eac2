#!/usr/bin/env bash
# Runs every benchmark (bench/*.cpp, built as BUILD/bench_*). Each prints its goals as
# ratios against a reference measured in the same run; a missed goal prints FAIL.
set -euo pipefail
build=${1:-build}
status=0
for bench in "$build"/bench_*; do
  [ -x "$bench" ] || continue
  "$bench" || status=1
done
exit $status
