#!/usr/bin/env bash
# Shows that two builds of superpack give the same results: a change meant to leave behaviour
# alone (a renovation of the code's structure) is shown to do so by running the same commands
# with the build before it (OLD_BUILD) and the build after it (NEW_BUILD) and comparing every
# output, instead of arguing it from the diff.
#
# Usage: scripts/same-results.sh OLD_BUILD NEW_BUILD OUT_DIR
#   OLD_BUILD, NEW_BUILD: build directories holding superpack and superpack-verify.
#   OUT_DIR: where each side's outputs go (OUT_DIR/old, OUT_DIR/new) and the normalised forms
#   that were compared (OUT_DIR/normalised/{old,new}, for `diff -r` by hand).
# Exit: 0 when every item is identical, 1 when any differs, 2 on bad usage or when the
# comparison itself fails.
#
# What is run, with each build, from a scratch working directory (OUT_DIR/<side>/work):
#   superpack report --json --output report.json   (stdout, and the file it writes)
#   superpack best --p 0.6 --json; --p 0.9; --p 2; --p 0.3
#   superpack critical --p 2 --gap 1e-4 --threads 2 --json   (the whole domain at p = 2,
#       2,061,472 boxes; 107 s on 1 thread and 55 s on 2 on an idle machine (NOTES 12.6 bench);
#       329 s on 1 thread and 225 to 305 s on 2 while other builds shared the 2 cores. The counts
#       are the same on any number of threads when the bound is proved: the leaves' reasons do not
#       depend on the order in which boxes are taken (the branch-and-bound engine, include/superpack/solve/branch_and_bound.hpp); the
#       document differs between 1 and 2 threads only in "threads", which echoes the option, and
#       "seconds". Both sides use 2, which only shortens the wall time.)
#   superpack audit --json --output-directory audit   (every family by default: C0, C1, O0, O1,
#       D14, S6; stdout, and each audit-<family>.json it writes)
#   superpack simulate --p 2 --n 2 --seed 1 --json
#   scripts/make-proofs.sh BUILD OUT_DIR/<side>/proofs   (every certificate of `make proofs`,
#       each replayed by that build's `superpack verify`; this checkout's make-proofs.sh is used
#       for both sides, so both write the same list, and no checkout's proofs/ is touched)
#   superpack verify --json CERTIFICATE   (each of those, into OUT_DIR/<side>/verified: the
#       checker's sentences and counts, with the exit status)
# and each command's exit status is compared too (stderr, progress and timings, is kept in
# OUT_DIR/<side>/json/NAME.stderr but not compared).
#
# What is normalised (python3 json, by key, never by a pattern over the whole text), and nothing
# else: in the JSON documents, the value of every key "seconds" (critical, simulate; also
# crossover and md), "search_seconds" and "total_seconds" (best's "timing") when it is a
# number: wall-clock time; in documents and certificates, every "commit" whose value is a commit
# stamp (12 hex digits, or "unknown", possibly with "-modified"): the build's commit. Each
# value is replaced by "<normalised>". The certificates get no timing normalisation (they hold
# no timing), so they are compared byte for byte apart from the commit stamp. Numbers are
# compared as the text printed, key order and repeated keys are kept, and the layout is checked
# as well: a file is re-serialised in the layout it was read in (indent, trailing newline) and
# must reproduce its own bytes, so two re-serialised normalised files are equal exactly when the
# two files are equal byte for byte apart from the normalised values.
#
# The OLD side is cached: OUT_DIR/old/binary.sha256 holds the sha256 of OLD_BUILD's superpack and
# superpack-verify, and OUT_DIR/old/recipe.sha256 that of the commands above (this script's
# recipe, the function that runs a side, and make-proofs.sh); when both match and
# OUT_DIR/old/complete exists, the old side is reused and only the new side runs. The sides run
# one after the other, not in parallel.
set -euo pipefail

# The whole script is one block, read before it runs: a checkout that changes this file during a
# run (it takes minutes) cannot change what the run does.
{

usage="usage: scripts/same-results.sh OLD_BUILD NEW_BUILD OUT_DIR"
if [ $# -ne 3 ]; then
    echo "$usage" >&2
    exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
for build in "$1" "$2"; do
    for exe in superpack superpack-verify; do
        if [ ! -x "$build/$exe" ]; then
            echo "same-results: $build/$exe is not an executable" >&2
            exit 2
        fi
    done
done
old_build=$(cd "$1" && pwd)
new_build=$(cd "$2" && pwd)
mkdir -p "$3"
out=$(cd "$3" && pwd)

now() { date +%s.%N; }
elapsed() { python3 -c 'import sys; print("%.1f" % (float(sys.argv[2]) - float(sys.argv[1])))' "$1" "$2"; }

# The commands, one a line: NAME ARGS... (no argument holds a space or a glob). Outputs are
# given relative to the working directory, so that the paths they print (audit's "file") are the
# same on both sides.
recipe='report report --json --output report.json
best-p0.6 best --p 0.6 --json
best-p0.9 best --p 0.9 --json
best-p2 best --p 2 --json
best-p0.3 best --p 0.3 --json
critical-p2-gap1e-4 critical --p 2 --gap 1e-4 --threads 2 --json
audit audit --json --output-directory audit
simulate-p2-n2-seed1 simulate --p 2 --n 2 --seed 1 --json'

# record DIR NAME START STATUS: one line of DIR/times.tsv, and on stdout.
record() {
    local seconds
    seconds=$(elapsed "$3" "$(now)")
    printf '%s\t%s\t%s\n' "$2" "$seconds" "$4" >>"$1/times.tsv"
    printf '  %-24s exit %s, %s s\n' "$2" "$4" "$seconds"
}

# run_side BUILD DIR: every command of the recipe with BUILD, into DIR (emptied first): stdout to
# DIR/json/NAME.json, the exit status to DIR/json/NAME.rc (a failing command is a result to
# compare, not a stop), then make-proofs.sh into DIR/proofs.
run_side() {
    local build=$1 dir=$2 start begin status words name
    rm -rf "$dir"
    mkdir -p "$dir/json" "$dir/work/audit"
    start=$(now)
    while read -r -a words; do
        name=${words[0]}
        begin=$(now)
        status=0
        (cd "$dir/work" && "$build/superpack" "${words[@]:1}" </dev/null >"$dir/json/$name.json" 2>"$dir/json/$name.stderr") || status=$?
        echo "$status" >"$dir/json/$name.rc"
        record "$dir" "$name" "$begin" "$status"
    done <<<"$recipe"
    begin=$(now)
    status=0
    "$root/scripts/make-proofs.sh" "$build" "$dir/proofs" >"$dir/make-proofs.log" 2>&1 || status=$?
    echo "$status" >"$dir/make-proofs.rc"
    record "$dir" make-proofs "$begin" "$status"
    # What that build's checker says of each certificate: its claim sentence and counts.
    begin=$(now)
    mkdir -p "$dir/verified"
    for certificate in "$dir"/proofs/*.json; do
        [ -e "$certificate" ] || continue
        name=$(basename "$certificate")
        status=0
        (cd "$dir/proofs" && "$build/superpack" verify --json "$name" </dev/null >"$dir/verified/$name" 2>/dev/null) || status=$?
        echo "$status" >"$dir/verified/${name%.json}.rc"
    done
    record "$dir" verify "$begin" 0
    elapsed "$start" "$(now)" >"$dir/seconds"
}

binary_stamp() { (cd "$1" && sha256sum superpack superpack-verify); }
recipe_stamp() { { echo "$recipe"; declare -f run_side; cat "$root/scripts/make-proofs.sh"; } | sha256sum; }

old_dir=$out/old
new_dir=$out/new
if [ -f "$old_dir/complete" ] && [ -f "$old_dir/binary.sha256" ] && [ -f "$old_dir/recipe.sha256" ] &&
    [ "$(cat "$old_dir/binary.sha256")" = "$(binary_stamp "$old_build")" ] &&
    [ "$(cat "$old_dir/recipe.sha256")" = "$(recipe_stamp)" ]; then
    echo "old side: reused from $old_dir (same binaries, same commands; it took $(cat "$old_dir/seconds") s)"
else
    echo "old side: $old_build"
    run_side "$old_build" "$old_dir"
    binary_stamp "$old_build" >"$old_dir/binary.sha256"
    recipe_stamp >"$old_dir/recipe.sha256"
    date -u +%Y-%m-%dT%H:%M:%SZ >"$old_dir/complete"
    echo "old side: $(cat "$old_dir/seconds") s"
fi
echo "new side: $new_build"
run_side "$new_build" "$new_dir"
binary_stamp "$new_build" >"$new_dir/binary.sha256"
echo "new side: $(cat "$new_dir/seconds") s"

status=0
python3 - "$out" <<'PY' || status=$?
import json, os, re, sys

sys.setrecursionlimit(100000)
# A failure of this comparison itself is no verdict: exit 2, not 1.
sys.excepthook = lambda kind, value, trace: (sys.stdout.flush(), sys.__excepthook__(kind, value, trace), os._exit(2))
out = sys.argv[1]
TIMING_KEYS = {"seconds", "search_seconds", "total_seconds"}
COMMIT = re.compile(r"(?:[0-9a-f]{7,40}|unknown)(?:-modified)?")
TOKEN = "<normalised>"


class Num:
    """A JSON number, kept as the text printed."""
    __slots__ = ("text",)

    def __init__(self, text):
        self.text = text


class Obj(list):
    """A JSON object as its (key, value) pairs in file order (repeated keys kept)."""


def load(text):
    return json.loads(text, object_pairs_hook=Obj, parse_float=Num, parse_int=Num, parse_constant=Num)


def normalise(value, timings):
    if isinstance(value, Obj):
        pairs = Obj()
        for key, item in value:
            if timings and key in TIMING_KEYS and isinstance(item, Num):
                item = TOKEN
            elif key == "commit" and isinstance(item, str) and COMMIT.fullmatch(item):
                item = TOKEN
            else:
                item = normalise(item, timings)
            pairs.append((key, item))
        return pairs
    if isinstance(value, list):
        return [normalise(item, timings) for item in value]
    return value


def dump(value, indent, level=0):
    """The layout of nlohmann::json's dump(indent) (indent None: dump())."""
    if isinstance(value, Obj) or isinstance(value, list):
        is_object = isinstance(value, Obj)
        open_, close = ("{", "}") if is_object else ("[", "]")
        if not value:
            return open_ + close
        if is_object:
            items = [json.dumps(k, ensure_ascii=False) + (": " if indent is not None else ":") + dump(v, indent, level + 1)
                     for k, v in value]
        else:
            items = [dump(v, indent, level + 1) for v in value]
        if indent is None:
            return open_ + ",".join(items) + close
        pad = " " * (indent * (level + 1))
        return open_ + "\n" + ",\n".join(pad + item for item in items) + "\n" + " " * (indent * level) + close
    if isinstance(value, Num):
        return value.text
    if value is True:
        return "true"
    if value is False:
        return "false"
    if value is None:
        return "null"
    return json.dumps(value, ensure_ascii=False)


def layout(text):
    body = text.rstrip("\n")
    lines = body.split("\n")
    indent = None if len(lines) == 1 else len(lines[1]) - len(lines[1].lstrip(" "))
    return indent, text[len(body):]


def short(value):
    text = dump(value, None)
    return text if len(text) <= 70 else text[:67] + "..."


def first_difference(a, b, path):
    if type(a) is not type(b):
        return "%s: %s vs %s" % (path, short(a), short(b))
    if isinstance(a, Obj):
        for i in range(min(len(a), len(b))):
            (ka, va), (kb, vb) = a[i], b[i]
            if ka != kb:
                return "%s: key %d is %s vs %s" % (path, i, json.dumps(ka), json.dumps(kb))
            found = first_difference(va, vb, path + "." + ka)
            if found:
                return found
        if len(a) != len(b):
            extra, side = (a[len(b)][0], "old") if len(a) > len(b) else (b[len(a)][0], "new")
            return "%s: key %s only in %s" % (path, json.dumps(extra), side)
        return None
    if isinstance(a, list):
        for i in range(min(len(a), len(b))):
            found = first_difference(a[i], b[i], "%s[%d]" % (path, i))
            if found:
                return found
        if len(a) != len(b):
            return "%s: %d vs %d elements" % (path, len(a), len(b))
        return None
    if isinstance(a, Num):
        return None if a.text == b.text else "%s: %s vs %s" % (path, a.text, b.text)
    return None if a == b else "%s: %s vs %s" % (path, short(a), short(b))


def first_line_difference(a, b):
    la, lb = a.split("\n"), b.split("\n")
    for i in range(max(len(la), len(lb))):
        x = la[i] if i < len(la) else "<end of file>"
        y = lb[i] if i < len(lb) else "<end of file>"
        if x != y:
            return "line %d: %r vs %r" % (i + 1, x[:70], y[:70])
    return "the same lines, different bytes"


def compare(item, old_path, new_path, timings):
    """None if identical, else the first difference."""
    a = open(old_path, "rb").read()
    b = open(new_path, "rb").read()
    try:
        ta, tb = a.decode("utf-8"), b.decode("utf-8")
        va, vb = load(ta), load(tb)
    except ValueError:
        return None if a == b else "not JSON; " + first_line_difference(a.decode("utf-8", "replace"), b.decode("utf-8", "replace"))
    na, nb = normalise(va, timings), normalise(vb, timings)
    written = []
    for side, text, value, normal in (("old", ta, va, na), ("new", tb, vb, nb)):
        indent, tail = layout(text)
        canonical = dump(value, indent) + tail == text
        normal_text = dump(normal, indent) + tail if canonical else dump(normal, 1) + "\n"
        target = os.path.join(out, "normalised", side, item)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "w", encoding="utf-8") as f:
            f.write(normal_text)
        written.append((canonical, normal_text))
    found = first_difference(na, nb, "$")
    if found:
        return found
    (ca, xa), (cb, xb) = written
    if ca and cb:
        return None if xa == xb else "layout: " + first_line_difference(xa, xb)
    # A layout this script cannot reproduce: equal only if the bytes are.
    return None if a == b else "layout not reproduced, bytes differ: " + first_line_difference(ta, tb)


def files(side, folder, suffix):
    path = os.path.join(out, side, folder)
    return {f for f in os.listdir(path) if f.endswith(suffix)} if os.path.isdir(path) else set()


def read_status(path):
    return open(path).read().strip() if os.path.exists(path) else "missing"


items = []  # (item, old path, new path, timings normalised, exit status file or None)
for name in sorted(files("old", "json", ".json") | files("new", "json", ".json")):
    items.append(("json/" + name, "json/" + name, True, "json/" + name[:-5] + ".rc"))
items.append(("files/report.json", "work/report.json", True, None))
for name in sorted(files("old", "work/audit", ".json") | files("new", "work/audit", ".json")):
    items.append(("files/audit/" + name, "work/audit/" + name, True, None))
for name in sorted(files("old", "proofs", ".json") | files("new", "proofs", ".json")):
    items.append(("proofs/" + name, "proofs/" + name, False, None))
for name in sorted(files("old", "verified", ".json") | files("new", "verified", ".json")):
    items.append(("verified/" + name, "verified/" + name, True, "verified/" + name[:-5] + ".rc"))

different = 0


def say(ok, item, detail):
    global different
    if not ok:
        different += 1
    print("%-9s %s%s" % ("identical" if ok else "DIFFERENT", item, detail))


for item, path, timings, status_file in items:
    old_path, new_path = os.path.join(out, "old", path), os.path.join(out, "new", path)
    status = ""
    if status_file:
        so = read_status(os.path.join(out, "old", status_file))
        sn = read_status(os.path.join(out, "new", status_file))
        if so != sn:
            say(False, item, ": exit status %s vs %s" % (so, sn))
            continue
        status = " (exit %s)" % so
    if not os.path.exists(old_path) or not os.path.exists(new_path):
        say(False, item, ": only on the %s side" % ("old" if os.path.exists(old_path) else "new"))
        continue
    found = compare(item, old_path, new_path, timings)
    say(found is None, item, status + ("" if found is None else ": " + found))

so, sn = read_status(os.path.join(out, "old", "make-proofs.rc")), read_status(os.path.join(out, "new", "make-proofs.rc"))
say(so == sn, "make-proofs.sh", " (exit %s)" % so if so == sn else ": exit status %s vs %s" % (so, sn))
print("%d items, %d different" % (len(items) + 1, different))
sys.exit(1 if different else 0)
PY
for side in old new; do
    parts=""
    while IFS=$'\t' read -r name seconds _; do
        parts+="${parts:+, }$name $seconds s"
    done <"$out/$side/times.tsv"
    echo "$side side took $(cat "$out/$side/seconds") s: $parts"
done
exit "$status"
}
