#!/usr/bin/env bash
# critical-shards.sh P GAP DIR [BUILD [SPLIT [SHARDS]]]: `superpack critical` at P and GAP as SHARDS
# shards (default 168),
# one --json document per shard in DIR (a shard already there is kept, so a stopped run resumes),
# the wall and user seconds of each in DIR/times.txt, then the merge of all of them in
# DIR/merged.json. On a cluster run one shard per task of a job array and the merge once all
# tasks are done. Exit: the merge's (0 proved, 4 undecided).
#
# Without SPLIT the shards run one after another on all cores. With SPLIT K (0 to 8) each
# top-level box is bisected K times first and each shard also writes its critical-lattice
# certificate cert-i.json, which the checker replays as it is written; as many shards run at once
# as there are cores, one thread each; and once every shard is proved, `critical --cover` writes
# DIR/whole.json, the certificate of the whole domain, after the checker has replayed every
# shard's certificate again (NOTES.md 12.9).
set -uo pipefail
p=$1; gap=$2; dir=$3; build=$(cd "${4:-build}" && pwd); split=${5:-}; shards=${6:-168}
mkdir -p "$dir" && cd "$dir" || exit 2

shard() {  # shard i: its document s<i>.json (and certificate cert-<i>.json)
  local i=$1 threads=$2 extra=()
  [ -s "s$i.json" ] && return 0
  [ -n "$split" ] && extra=(--split "$split" --certificate "cert-$i.json")
  /usr/bin/time -f "$i %e %U" -a -o times.txt "$build/superpack" critical --p "$p" --gap "$gap" --shard "$i/$shards" \
    --threads "$threads" "${extra[@]}" --json > "s$i.tmp" 2> "s$i.err"
  local status=$?
  # Proved (0) or undecided (4) is a result to merge; anything else stays s<i>.tmp, and the merge
  # names the shard as missing.
  if [ "$status" = 0 ] || [ "$status" = 4 ]; then mv "s$i.tmp" "s$i.json"; fi
}

if [ -z "$split" ]; then
  for i in $(seq 0 $((shards - 1))); do shard "$i" "$(nproc)"; done
else
  export -f shard; export p gap build split shards
  seq 0 $((shards - 1)) | xargs -P "$(nproc)" -I{} bash -c 'shard {} 1'
fi
"$build/superpack" critical --merge $(seq -f 's%g.json' 0 $((shards - 1))) --json > merged.tmp
status=$?
mv merged.tmp merged.json
if [ "$status" = 0 ] && [ -n "$split" ]; then
  "$build/superpack" critical --cover $(seq -f 'cert-%g.json' 0 $((shards - 1))) --split "$split" --certificate whole.json \
    --threads "$(nproc)" > cover.txt 2> cover.err
  status=$?
fi
exit $status
