#!/usr/bin/env python3
"""Independent reference values for tests/test_lattice.cpp and tests/test_audit.cpp (mpmath, 50 digits).

Norms of witness vectors and brute-force contact counts, computed here from the paper's equations
without any superpack code. Writes tests/data/lattice.json.
"""
import itertools
import json
import os
from mpmath import mp, mpf, findroot

mp.dps = 50


def norm(v, p):
    q = 2 * p
    return sum(abs(x) ** q for x in v) ** (1 / q)


def o1_parameters(p):
    q2 = 2 * p
    l = mpf(3) ** (-1 / q2)
    q, s = findroot(lambda a, b: [2 * a ** q2 + b ** q2 - 1, (l + a) ** q2 + (b - l) ** q2 + (l - a) ** q2 - 1],
                    (mpf("0.17"), mpf("0.75")))
    return l, q, s


def combine(basis, c):
    return [sum(c[i] * basis[i][j] for i in range(3)) for j in range(3)]


def short_vectors(basis, p, bound=4, below=mpf("2.0000001")):
    """Brute force over a generous box: coefficient triples (one per +-pair) with norm < below."""
    out = []
    for c in itertools.product(range(-bound, bound + 1), repeat=3):
        if c <= (0, 0, 0):
            continue
        if norm(combine(basis, c), p) < below:
            out.append(list(c))
    return out


data = {}
# O1 at p = 0.6: the vector e1 - e2 - e3 = (2l, 2l + 2q - 2s, 2(s + q - l)).
p = mpf("0.6")
l, q, s = o1_parameters(p)
basis = [[2 * l, 2 * l, -2 * l], [-2 * q, 2 * s, -2 * q], [2 * q, -2 * q, -2 * s]]
data["o1_p0.6_witness_norm"] = mp.nstr(norm(combine(basis, (1, -1, -1)), p), 45)
data["o1_p0.6_short"] = short_vectors(basis, p)
# O0 below p*_o, p = 0.75: 2 e3 - e1 - e2 = (0, 0, 4c).
p = mpf("0.75")
c = (1 - mpf(2) ** (1 - 2 * p)) ** (1 / (2 * p))
data["o0_p0.75_witness_norm"] = mp.nstr(4 * c, 45)
# FCC scaled by 7/5 at p = 1 (norm 7/5 sqrt 2 < 2) and by 3/2 (norm 3/2 sqrt 2 > 2).
data["fcc_7_5_min_norm"] = mp.nstr(mpf(7) / 5 * mp.sqrt(2), 45)
data["fcc_3_2_min_norm"] = mp.nstr(mpf(3) / 2 * mp.sqrt(2), 45)
# Minkowski's lattice at p = 1/2: the short vectors (norm 2 exactly).
minkowski = [[mpf(2) / 3, mpf(2) / 3, -mpf(2) / 3], [-mpf(1) / 3, mpf(4) / 3, -mpf(1) / 3],
             [mpf(1) / 3, -mpf(1) / 3, -mpf(4) / 3]]
data["minkowski_short"] = short_vectors(minkowski, mpf("0.5"))
# A skew basis at p = 2 with e1 + e2 = (1.9, 0, 0): its shortest vectors by brute force.
skew = [[mpf("3.9"), mpf(2), mpf(0)], [mpf(-2), mpf(-2), mpf(0)], [mpf(0), mpf(0), mpf(2)]]
norms = sorted((norm(combine(skew, c), mpf(2)), list(c)) for c in itertools.product(range(-5, 6), repeat=3)
               if c > (0, 0, 0))
data["skew_p2_min_norm"] = mp.nstr(norms[0][0], 45)
data["skew_p2_shortest"] = norms[0][1]

path = os.path.join(os.path.dirname(__file__), "..", "tests", "data", "lattice.json")
with open(path, "w") as out:
    json.dump(data, out, indent=1)
    out.write("\n")
