#!/usr/bin/env bash
# Regenerates the certificates in proofs/ with the superpack built in BUILD_DIR, and replays
# each with `superpack verify` before keeping it. `make proofs` calls this; `make test`
# replays every proofs/*.json (tests/test_proofs.cpp).
#
# Usage: scripts/make-proofs.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: scripts/make-proofs.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
superpack=$(cd "$build" && pwd)/superpack
mkdir -p "$root/proofs"

# density FAMILY P NAME [DIGITS]: the family-lattice certificate of one family at one p.
density() {
    local family=$1 p=$2 name=$3 digits=${4:-}
    local file="$root/proofs/$name.json"
    local arguments=(density --family "$family" --p "$p" --certificate "$file")
    if [ -n "$digits" ]; then arguments+=(--digits "$digits"); fi
    "$superpack" "${arguments[@]}" >/dev/null
    "$superpack" verify "$file" >/dev/null
    echo "proofs/$name.json"
}

# The densities of the four families at one p each in their domains (binary64 intervals),
# Minkowski's octahedron lattice (O1 at p = 1/2, phi = 18/19), and two at 30 digits (Arb).
density C0 3/2 density-C0-p1.5
density C1 3 density-C1-p3
density O0 0.85 density-O0-p0.85
density O1 0.6 density-O1-p0.6
density O1 1/2 density-O1-p0.5-minkowski
density C0 3/2 density-C0-p1.5-30digits 30
density O1 1/2 density-O1-p0.5-minkowski-30digits 30

# lattice P BASIS NAME: the lattice-check certificate of an exact basis at an exact p.
lattice() {
    local p=$1 basis=$2 name=$3
    local file="$root/proofs/$name.json"
    local status=0
    "$superpack" check-lattice --p "$p" --basis "$basis" --certificate "$file" >/dev/null || status=$?
    if [ "$status" -ne 0 ]; then echo "check-lattice failed ($status) for $name" >&2; exit "$status"; fi
    "$superpack" verify "$file" >/dev/null
    echo "proofs/$name.json"
}

# Minkowski's octahedron lattice at p = 1/2 (a packing, 14 contacts), 2Z^3 at p = 3 (a packing,
# 6 contacts), and an overlapping basis at p = 2 (witness e1 + e2 = (1.9, 0, 0), norm 1.9).
lattice 1/2 "2/3,2/3,-2/3; -1/3,4/3,-1/3; 1/3,-1/3,-4/3" lattice-minkowski-p0.5
lattice 3 "2,0,0; 0,2,0; 0,0,2" lattice-2Z3-p3
lattice 2 "3.9,2,0; -2,-2,0; 0,0,2" lattice-overlapping-p2

# crossover_slopes NAME COMMAND... : the certificate of a crossover or of the slopes (issue 7,
# NOTES 8.5): p*_c with its uniqueness partition of (1, 10] (binary64 and 30 digits), p*_o with
# the O0 = O1 lattice identity, and the slopes at p = 1 (a_plus as certified, not as printed).
crossover_slopes() {
    local name=$1
    shift
    local file="$root/proofs/$name.json"
    "$superpack" "$@" --certificate "$file" >/dev/null
    "$superpack" verify "$file" >/dev/null
    echo "proofs/$name.json"
}
crossover_slopes crossover-cubic crossover cubic
crossover_slopes crossover-cubic-30digits crossover cubic --digits 30
crossover_slopes crossover-octahedral crossover octahedral
crossover_slopes crossover-octahedral-30digits crossover octahedral --digits 30
crossover_slopes slopes-p1 slopes
crossover_slopes slopes-p1-30digits slopes --digits 30

# superdisk P NAME: the superdisk-optimum certificate (densest lattice packing of the superdisk
# |x|^(2p) + |y|^(2p) <= 1, by the branch and bound over t in [0, 1]; NOTES.md 8.6). p = 1/2
# (the square tiles) and p < 1/2 have no certificate of this kind.
superdisk() {
    local p=$1 name=$2
    local file="$root/proofs/$name.json"
    local status=0
    "$superpack" superdisk --p "$p" --certificate "$file" >/dev/null || status=$?
    if [ "$status" -ne 0 ]; then echo "superdisk failed ($status) for $name" >&2; exit "$status"; fi
    "$superpack" verify "$file" >/dev/null
    echo "proofs/$name.json"
}

# Lambda0 optimal (p = 3/4 and p = 2), Lambda1 optimal (p = 5/4), and the circle (p = 1:
# both families are the hexagonal lattice, phi = pi / (2 sqrt 3); D is constant there, so the
# 1000-piece budget stops the branch and bound at width ~6e-6).
superdisk 0.75 superdisk-optimum-p0.75
superdisk 1.25 superdisk-optimum-p1.25
superdisk 2 superdisk-optimum-p2
superdisk 1 superdisk-optimum-p1

# Issue 7, audit and family lattice-check certificates (NOTES.md 8.4).
# family_check FAMILY P NAME: the family-lattice-check certificate of one family at one p.
family_check() {
    local family=$1 p=$2 name=$3
    local file="$root/proofs/$name.json"
    local status=0
    "$superpack" check-lattice --family "$family" --p "$p" --certificate "$file" >/dev/null || status=$?
    if [ "$status" -ne 0 ]; then echo "check-lattice --family failed ($status) for $name" >&2; exit "$status"; fi
    "$superpack" verify "$file" >/dev/null
    echo "proofs/$name.json"
}

# audit FAMILY NAME: the audit certificate of one family over its claimed range (the audit's
# detail file goes to a temporary folder; the certificate is the file kept).
audit() {
    local family=$1 name=$2
    local file="$root/proofs/$name.json" scratch
    scratch=$(mktemp -d)
    "$superpack" audit --family "$family" --output-directory "$scratch" --certificate "$file" >/dev/null 2>&1
    rm -rf "$scratch"
    "$superpack" verify "$file" >/dev/null
    echo "proofs/$name.json"
}

# C0 at p = 2 and O0 at p = 0.85 (packings, 12 contacts), O1 at p = 0.6 (not a packing,
# witness e1 - e2 - e3: NOTES.md 9), and the four families over their claimed ranges.
family_check C0 2 lattice-C0-p2
family_check O0 0.85 lattice-O0-p0.85
family_check O1 0.6 lattice-O1-p0.6-overlapping
audit C0 audit-C0-p1-10
audit C1 audit-C1-p1-10
audit O0 audit-O0-p0.792481-1
audit O1 audit-O1-p0.5-0.792482
