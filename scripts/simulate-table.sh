#!/usr/bin/env bash
# The runs behind NOTES.md 14.5 (issue 15, item 4): `superpack simulate` for N = 2..8
# particles per cell at p in {0.6, 0.8, 1.5, 2, 3}, from the best lattice and from random
# starts, several seeds, two runs at a time. Prints one CSV row per run:
#   p,n,init,seed,steps,certified,phi_lo,phi_hi,ratio_lo,ratio_hi,best_lattice,seconds
# Usage: scripts/simulate-table.sh BUILD [STEPS] [SEEDS] > table.csv   (about 20 min on 2 cores)
set -euo pipefail
build=${1:?usage: simulate-table.sh BUILD [STEPS] [SEEDS]}
steps=${2:-50000}
seeds=${3:-"1 2 3"}
export build steps
one() {
  local p=$1 n=$2 init=$3 seed=$4 start end
  start=$(date +%s.%N)
  local json
  json=$("$build/superpack" simulate --p "$p" --n "$n" --init "$init" --seed "$seed" --steps "$steps" --json 2>/dev/null || true)
  end=$(date +%s.%N)
  python3 -c '
import json, sys
p, n, init, seed, steps, start, end = sys.argv[1:8]
seconds = float(end) - float(start)
try:
    d = json.loads(sys.stdin.read())
except ValueError:
    d = {}
ok = d.get("certified", False)
phi = d.get("phi", {"lo": "", "hi": ""}); ratio = d.get("ratio_to_best_lattice", {"lo": "", "hi": ""})
best = d.get("best_lattice", {}).get("name", "")
print(",".join([p, n, init, seed, steps, str(ok).lower(), phi["lo"], phi["hi"], ratio["lo"], ratio["hi"], best, "%.1f" % seconds]))
' "$p" "$n" "$init" "$seed" "$steps" "$start" "$end" <<< "$json"
}
export -f one
echo "p,n,init,seed,steps,certified,phi_lo,phi_hi,ratio_lo,ratio_hi,best_lattice,seconds"
for p in 0.6 0.8 1.5 2 3; do
  for n in 2 3 4 5 6 7 8; do
    for init in lattice random; do
      for seed in $seeds; do echo "$p $n $init $seed"; done
    done
  done
done | xargs -P 2 -L 1 bash -c 'one "$@"' _
