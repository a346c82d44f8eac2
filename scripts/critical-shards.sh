#!/usr/bin/env bash
# critical-shards.sh P GAP DIR [BUILD]: `superpack critical` at P and GAP as its 168 shards, one
# after another on all cores, one --json document per shard in DIR (a shard already there is kept,
# so a stopped run resumes), the wall and user seconds of each in DIR/times.txt, then the merge of
# all 168 in DIR/merged.json. On a cluster run the loop's body as a job array (shard i of 168 per
# task) and the last line once all tasks are done. Exit: the merge's (0 proved, 4 undecided).
set -uo pipefail
p=$1; gap=$2; dir=$3; build=$(cd "${4:-build}" && pwd)
shards=168
mkdir -p "$dir" && cd "$dir" || exit 2
for i in $(seq 0 $((shards - 1))); do
  [ -s "s$i.json" ] && continue
  /usr/bin/time -f "$i %e %U" -a -o times.txt "$build/superpack" critical --p "$p" --gap "$gap" --shard "$i/$shards" \
    --threads "$(nproc)" --json > "s$i.tmp" 2> "s$i.err"
  mv "s$i.tmp" "s$i.json"
done
"$build/superpack" critical --merge $(seq -f 's%g.json' 0 $((shards - 1))) --json > merged.tmp
status=$?
mv merged.tmp merged.json
exit $status
