#!/usr/bin/env bash
# scripts/sanitize.sh BUILD COUNT: the runs of `make sanitize`, with the executables of BUILD built
# with -fsanitize=address,undefined (cmake -DSUPERPACK_SANITIZE=ON):
#   1. a few commands of the instrumented command line, each writing a certificate that the
#      instrumented checker replays in-process (the producer's own replay) and as superpack verify;
#   2. every certificate in proofs/ replayed by the instrumented `superpack verify`;
#   3. the checker's mutation fuzz test (NOTES.md 8.8): COUNT mutations of each certificate in
#      proofs/, with no budget of time, so that the same seed runs the same mutations on any machine;
#      the seed is SUPERPACK_FUZZ_SEED or the date, and the fuzz test prints it.
# A sanitizer report ends its process with exit 99 (halt_on_error, and the code built with
# -fno-sanitize-recover=all), a leak at exit too (detect_leaks: the checker, the command line and
# the fuzz driver free what they allocate); any exit but the expected one fails the run, naming it.
# Exit 0 with "findings 0" at the end, 1 otherwise.
set -euo pipefail
build=$1
count=$2
cd "$(dirname "$0")/.."
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:exitcode=99:abort_on_error=0:check_initialization_order=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:exitcode=99
seed=${SUPERPACK_FUZZ_SEED:-$(date +%Y%m%d)}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/c"
start=$SECONDS

# The command's stderr (progress, or a sanitizer's report) is shown only when it fails.
fail() {
  [ -s "$scratch/err" ] && tail -n 60 "$scratch/err" >&2
  echo "sanitize: $1 (exit $2; 99 is a sanitizer report)" >&2
  echo "findings 1" >&2
  exit 1
}

# 1. The command line: certificates written (and so replayed in-process) and verified.
commands=(
  "density --family C0 --p 1.5 --certificate $scratch/c/density.json"
  "density --family O1 --p 0.6 --digits 30 --certificate $scratch/c/density-o1.json"
  "check-lattice --family O1 --p 0.6 --certificate $scratch/c/lattice.json"
  "check-lattice --p 0.3 --basis 2/3,2/3,-2/3;-1/3,4/3,-1/3;1/3,-1/3,-4/3 --certificate $scratch/c/star.json"
  "slopes --certificate $scratch/c/slopes.json"
  "crossover octahedral --certificate $scratch/c/crossover.json"
  "superdisk --p 1.25 --certificate $scratch/c/superdisk.json"
  "audit --family C0 --pieces 20 --output-directory $scratch --certificate $scratch/c/audit.json"
  "best --p 0.6 --certificate $scratch/c/best.json"
  "critical --p 2 --around 1e-5 --certificate $scratch/c/critical.json"
)
for command in "${commands[@]}"; do
  # shellcheck disable=SC2086 # the words of the command
  "$build/superpack" $command > /dev/null 2> "$scratch/err" || fail "superpack $command" $?
done
for certificate in "$scratch"/c/*.json; do
  "$build/superpack" verify "$certificate" > /dev/null 2> "$scratch/err" || fail "superpack verify $certificate" $?
done
echo "sanitize: ${#commands[@]} commands of the command line and their certificates verified ($((SECONDS - start)) s)"

# 2. Every committed certificate, through the instrumented command line and checker.
files=0
for certificate in proofs/*.json; do
  "$build/superpack" verify "$certificate" > /dev/null 2> "$scratch/err" || fail "superpack verify $certificate" $?
  files=$((files + 1))
done
echo "sanitize: $files certificates in proofs/ valid under superpack verify ($((SECONDS - start)) s)"

# 3. The mutation fuzz test.
SUPERPACK_FUZZ_SEED=$seed SUPERPACK_FUZZ_COUNT=$count SUPERPACK_FUZZ_SECONDS=0 \
  "$build/superpack_checker_fuzz" proofs tests/data/fuzz_reference.json 2> "$scratch/err" | tee "$scratch/fuzz.log" ||
  fail "superpack_checker_fuzz (seed $seed, count $count)" "${PIPESTATUS[0]}"
mutations=$(awk '$1 == "total" { print $2 }' "$scratch/fuzz.log")
[ "$mutations" = $((files * count)) ] || fail "the fuzz test ran $mutations mutations, not $files x $count" 1
echo "sanitize: $mutations mutations, seed $seed, findings 0 ($((SECONDS - start)) s in all)"
