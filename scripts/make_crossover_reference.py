#!/usr/bin/env python3
"""Independent reference values for the crossover and slope tests (mpmath, 60 digits).

Independence from superpack: the volume is the paper's Beta form (Eq. 4); |det| is the
paper's closed form (Eq. 3 for C0, 2^(3-1/p) (3s + t) for C1, Eq. 7 for O0); roots come from
mpmath's findroot; derivatives from mpmath's numerical differentiation of the composite
p -> phi(p) (no implicit function theorem). Nothing here is rigorous: the tests ask that
superpack's certified enclosures meet these values, so agreement is evidence.

Usage: scripts/make_crossover_reference.py > tests/data/crossover.json
"""
import json

import mpmath

from mpmath import mp, mpf, diff, digamma, findroot, log, pi, sqrt

from make_golden import text, volume  # the paper's Beta form, and 50-digit printing

mp.dps = 60


def phi_c0(p):
    t = mpf(2) ** (-1 / (2 * p))
    s = findroot(lambda s: (s + t) ** (2 * p) + s ** (2 * p) + mpf(2) ** (-2 * p) - 1, mpf("0.15"), tol=mpf(10) ** -58)
    return volume(p) / (mpf(2) ** (3 - 1 / (2 * p)) * (2 * s + t))


def phi_c1(p):
    t = mpf(2) ** (-1 / (2 * p))
    s = findroot(lambda s: (s + t) ** (2 * p) + 2 * s ** (2 * p) - 1, mpf("0.2"), tol=mpf(10) ** -58)
    return volume(p) / (mpf(2) ** (3 - 1 / p) * (3 * s + t))


def phi_o0(p):
    return volume(p) / (8 * (1 - mpf(2) ** (1 - 2 * p)) ** (1 / (2 * p)))


def main():
    crossover = findroot(lambda p: phi_c1(p) - phi_c0(p), mpf("1.15"), tol=mpf(10) ** -55)
    p_o = log(3) / log(4)
    # Eq. (6) solved by findroot, separately from the closed form ln3/ln4.
    root_6 = findroot(lambda p: 2 * (1 - mpf(2) ** (1 - 2 * p)) ** (1 / (2 * p)) - 1, mpf("0.79"), tol=mpf(10) ** -55)
    factor = -pi / (12 * sqrt(2))
    digammas = 4 * digamma(mpf(1) / 2) + 2 * digamma(mpf(3) / 2) - 6 * digamma(mpf(5) / 2)
    one = mpf(1)
    slopes = {}
    for name, function in [("C0", phi_c0), ("C1", phi_c1), ("O0", phi_o0)]:
        slopes[name] = {p: text(diff(function, mpf(p))) for p in ["1", "1.5", "3"] if not (name == "O0" and p != "1")}
    slopes["O0"]["0.8"] = text(diff(phi_o0, mpf("0.8")))
    difference = {p: text(phi_c1(mpf(p)) - phi_c0(mpf(p))) for p in ["1.001", "1.05", "1.12", "1.2", "2", "10"]}
    data = {
        "generator": "scripts/make_crossover_reference.py (mpmath %s, %d digits)" % (mpmath.__version__, mp.dps),
        "p_c": text(crossover),
        "phi_c": text(phi_c0(crossover)),
        "p_o": text(p_o),
        "eq6_root": text(root_6),
        "phi_o": text(phi_o0(p_o)),
        "slopes": slopes,
        "difference": difference,
        "closed_a_minus": text(factor * (log(64) + 8 + digammas)),
        "closed_a_plus": text(factor * (24 + log(8) + digammas)),
        "fcc": text(pi / sqrt(18)),
    }
    print(json.dumps(data, indent=2))


if __name__ == "__main__":
    main()
