#!/usr/bin/env bash
# Regenerates the certificates in proofs/ with the superpack built in BUILD_DIR, and replays
# each with `superpack verify` before keeping it. `make proofs` calls this; `make test`
# replays every proofs/*.json (tests/test_proofs.cpp). OUT_DIR (default: this repository's
# proofs/) writes the same certificates elsewhere instead, leaving proofs/ untouched
# (scripts/same-results.sh regenerates them with two builds that way).
#
# Usage: scripts/make-proofs.sh BUILD_DIR [OUT_DIR]
set -euo pipefail
build=${1:?usage: scripts/make-proofs.sh BUILD_DIR [OUT_DIR]}
root=$(cd "$(dirname "$0")/.." && pwd)
superpack=$(cd "$build" && pwd)/superpack
if [ -n "${2:-}" ]; then
    mkdir -p "$2"
    out=$(cd "$2" && pwd)
    shown=$out
else
    out=$root/proofs
    shown=proofs
    mkdir -p "$out"
fi

# certify NAME COMMAND...: runs `superpack COMMAND... --certificate OUT_DIR/NAME.json`, stops on
# any exit but 0 (an undecided result writes nothing), and keeps the file only if verify accepts it.
# An audit with undecided pieces exits 4 after writing the certificate of its decided pieces, and
# a density whose packing check is undecided exits 4 after writing the certificate of phi alone
# (which then says it is no packing density).
certify() {
    local name=$1
    shift
    local file="$out/$name.json" status=0
    rm -f "$file"
    "$superpack" "$@" --certificate "$file" >/dev/null 2>&1 || status=$?
    if [ "$status" -eq 4 ] && { [ "$1" = audit ] || [ "$1" = density ]; } && [ -f "$file" ]; then status=0; fi
    if [ "$status" -ne 0 ]; then echo "superpack $* failed ($status) for $name" >&2; exit "$status"; fi
    "$superpack" verify "$file" >/dev/null
    echo "$shown/$name.json"
}

# The densities of the four families at one p each in their domains (binary64 intervals),
# Minkowski's octahedron lattice (O1 at p = 1/2, phi = 18/19), and two at 30 digits (Arb).
certify density-C0-p1.5 density --family C0 --p 3/2
certify density-C1-p3 density --family C1 --p 3
certify density-O0-p0.85 density --family O0 --p 0.85
certify density-O1-p0.6 density --family O1 --p 0.6
certify density-O1-p0.5-minkowski density --family O1 --p 1/2
certify density-C0-p1.5-30digits density --family C0 --p 3/2 --digits 30
certify density-O1-p0.5-minkowski-30digits density --family O1 --p 1/2 --digits 30
# D14 (Dostert and Vallentin 2020) at p = 0.6: a packing with 14 contacts, denser than O1 there.
certify density-D14-p0.6 density --family D14 --p 0.6
# S6 (superpack's six-pair family, NOTES 4.2) at p = 0.9: the KKT point of Minkowski's six pairs,
# a packing with 12 contacts, denser than O0 there.
certify density-S6-p0.9 density --family S6 --p 0.9

# Lattice checks of exact bases: Minkowski's octahedron lattice at p = 1/2 (a packing, 14
# contacts), 2Z^3 at p = 3 (a packing, 6 contacts), and an overlapping basis at p = 2 (witness
# e1 + e2 = (1.9, 0, 0), norm 1.9).
certify lattice-minkowski-p0.5 check-lattice --p 1/2 --basis "2/3,2/3,-2/3; -1/3,4/3,-1/3; 1/3,-1/3,-4/3"
certify lattice-2Z3-p3 check-lattice --p 3 --basis "2,0,0; 0,2,0; 0,0,2"
certify lattice-overlapping-p2 check-lattice --p 2 --basis "3.9,2,0; -2,-2,0; 0,0,2"

# Crossovers and slopes (NOTES 8.5): p*_c with its uniqueness partition of (1, 10] (binary64
# and 30 digits), p*_o with the O0 = O1 lattice identity, and the slopes at p = 1 (a_plus as
# certified, not as printed).
certify crossover-cubic crossover cubic
certify crossover-cubic-30digits crossover cubic --digits 30
certify crossover-octahedral crossover octahedral
certify crossover-octahedral-30digits crossover octahedral --digits 30
certify slopes-p1 slopes
certify slopes-p1-30digits slopes --digits 30

# Superdisk optima (NOTES 8.6; p = 1/2 tiles and p < 1/2 has no certificate of this kind):
# Lambda0 optimal at p = 3/4 and p = 2, Lambda1 at p = 5/4, and the circle (p = 1: both
# families are the hexagonal lattice, phi = pi / (2 sqrt 3); D is constant there, so the
# 1000-piece budget stops the branch and bound at width ~6e-6).
certify superdisk-optimum-p0.75 superdisk --p 0.75
certify superdisk-optimum-p1.25 superdisk --p 1.25
certify superdisk-optimum-p2 superdisk --p 2
certify superdisk-optimum-p1 superdisk --p 1

# Family lattice checks and audits (NOTES 8.4): C0 at p = 2 and O0 at p = 0.85 (packings,
# 12 contacts), O1 at p = 0.6 (not a packing, witness e1 - e2 - e3: NOTES 9), and the families
# over their claimed ranges (the audit's detail file goes to a scratch folder).
certify lattice-C0-p2 check-lattice --family C0 --p 2
certify lattice-O0-p0.85 check-lattice --family O0 --p 0.85
certify lattice-O1-p0.6-overlapping check-lattice --family O1 --p 0.6
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
certify audit-C0-p1-10 audit --family C0 --output-directory "$scratch"
certify audit-C1-p1-10 audit --family C1 --output-directory "$scratch"
certify audit-O0-p0.792481-1 audit --family O0 --output-directory "$scratch"
certify audit-O1-p0.5-0.792482 audit --family O1 --output-directory "$scratch"
certify audit-D14-p0.5-0.792482 audit --family D14 --output-directory "$scratch"
# S6 (NOTES 4.2) on its default range [0.89, 0.91] about its point proof at 9/10 (160 pieces, about
# 1 MB); `audit --family S6 --p-range 0.8:0.99` certifies more in about a minute, but its 2047
# pieces make a file ten times larger than any other here.
certify audit-S6-p0.89-0.91 audit --family S6 --output-directory "$scratch"

# The densest lattices `superpack best` certifies (NOTES 11.8), each a local-optimum certificate
# (NOTES 8.9: the critical lattice is admissible and a strict local minimiser of |det|): at
# p = 0.6, the 14-neighbour lattice, where no lattice of Jiao et al. is a packing; at p = 2, C1;
# at p = 0.9, S6, denser than O0 (NOTES 9, "O0 is not the densest lattice on (p*_o, 1)").
certify best-p0.6 best --p 0.6
certify best-p2 best --p 2
certify best-p0.9 best --p 0.9

# Concave superballs (NOTES 13.5, kind star-lattice-check): the paper's insertion at p = 3/10 (a
# packing), Minkowski's lattice scaled by 1/4 (an overlap, a rational witness point), the tips off
# the axes (a packing with tip contacts, decided by the closed form), and the best lattice at 0.3.
certify star-lattice-insertion-p0.3 check-lattice --p 3/10 --family minkowski-insertion
certify star-lattice-quarter-p0.3-overlapping check-lattice --p 3/10 --basis "1/6,1/6,-1/6; -1/12,1/3,-1/12; 1/12,-1/12,-1/3"
certify star-lattice-tips-p0.3 check-lattice --p 3/10 --basis "1,1,0; 1,-1,0; 0,0,2"
certify best-p0.3 best --p 0.3

# critical at p = 2, gap 0, on the chart boxes of half-width 1e-5 around C1's four images (NOTES
# 12.8): 82 boxes closed by the determinant bound or C1's closing region, each tree replayed by
# the checker. The whole domain's trees would exceed the checker's 256 MiB file limit.
certify critical-p2-around-C1 critical --p 2 --around 1e-5

# Periodic packings with N particles per cell (NOTES 14, 15; kind periodic-packing): the end state
# of a run rounded to exact rationals and proved a packing by separating planes, which the checker
# replays after enumerating the close pairs itself. simulate at p = 2, N = 2, seed 1 (about 2 s),
# from C1 2% expanded: the run ends 0.034% below C1 (it finds no two-particle cell denser than the
# lattice: evidence, not proof, NOTES 14.5); the proof needed the configuration scaled by
# 549755814453/549755813888 = 1 + 1.03e-9 (the rounding of the orientations), and the checker's
# support function takes its MPFI power path (s = 2p/(2p - 1) = 4/3). md at p = 0.6, N = 8,
# growth 0.1, seed 1 (about 3 s): eight growing near-octahedra jam from a random start at
# phi = 0.724, 82% of D14 (49 pairs, no scaling), and the support function takes its exact
# integer-exponent path (s = 6).
certify simulate-p2-n2 simulate --p 2 --n 2 --seed 1
certify md-p0.6-n8 md --p 0.6 --n 8 --growth 0.1 --seed 1
