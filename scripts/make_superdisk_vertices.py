#!/usr/bin/env python3
"""Independent reference for tests/test_certificate_superdisk.cpp (mpmath, 40 digits): the
parameters t in [0, 1] of ALL vertices of the hexagons of Lambda0 and Lambda1, folded into the
first octant. D depends on the lattice only (NOTES.md 7.2), so if a family is optimal each of
its vertices u, v, v - u is a minimiser of D, and a superdisk-optimum certificate must list
argmin_t intervals containing every one of these t.

Closed forms (NOTES.md 7.3), q = 2p:
  Lambda1: u = (1, 0), v = (1/2, y1), y1 = (1 - 2^-q)^(1/q); v - u = (-1/2, y1).
  Lambda0: u = c (1, 1), c = 2^(-1/q), v = (c/2 - s, c/2 + s), |c/2 - s|^q + |c/2 + s|^q = 1,
           s > 0; v - u = (-c/2 - s, -c/2 + s).
Folding a point (a, b) into the first octant (the symmetry group of the square) gives
t = min(|a|, |b|) / max(|a|, |b|).
Usage: python3 scripts/make_superdisk_vertices.py > tests/data/superdisk_vertices.json
"""
import json
from mpmath import mp, mpf, findroot, fabs

mp.dps = 40


def fold(point):
    a, b = fabs(point[0]), fabs(point[1])
    return min(a, b) / max(a, b)


def vertices(p):
    q = 2 * mpf(p)
    y1 = (1 - mpf(2) ** -q) ** (1 / q)
    lambda1 = [(mpf(1), mpf(0)), (mpf(1) / 2, y1), (-mpf(1) / 2, y1)]
    c = mpf(2) ** (-1 / q)
    s = findroot(lambda s: fabs(c / 2 - s) ** q + fabs(c / 2 + s) ** q - 1, c / 2)
    lambda0 = [(c, c), (c / 2 - s, c / 2 + s), (-c / 2 - s, -c / 2 + s)]
    as_text = lambda points: sorted({mp.nstr(fold(x), 35) for x in points}, key=mpf)
    return {"Lambda0": as_text(lambda0), "Lambda1": as_text(lambda1)}


print(json.dumps({p: vertices(p) for p in ["0.75", "1.25", "2", "1"]}, indent=2))
