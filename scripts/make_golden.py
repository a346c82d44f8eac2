#!/usr/bin/env python3
"""Independent reference values for superpack's tests, computed with mpmath at 60 digits.

Independence: the volume uses the paper's Beta-function form (Eq. 4), not the Gamma form
superpack evaluates; roots come from mpmath's findroot; densities use the paper's closed
forms for |det| (Eqs. 3, 10, 7, 13), not a determinant of the basis. Nothing here is
rigorous: the tests only ask that superpack's certified enclosures contain these values
(to the 50 digits written), so an agreement is evidence, and a disagreement is a bug in
one of the two.

Usage: scripts/make_golden.py > tests/data/golden.json
"""
import json
from fractions import Fraction

from mpmath import mp, mpf, beta, gamma, findroot, log, pi, sqrt

mp.dps = 60
DIGITS = 50


def text(x):
    return mp.nstr(x, DIGITS, strip_zeros=False)


def volume(p):
    return 2 / p**2 * beta(1 / (2 * p), (2 * p + 1) / (2 * p)) * beta(1 / (2 * p), (p + 1) / p)


def area(p):
    return 4 * gamma(1 + 1 / (2 * p)) ** 2 / gamma(1 + 1 / p)


# Large p: s ~ ln2/(2p) while s + t -> 1, so (s + t)^(2p) costs log10(2p) digits; the roots are
# computed with that many extra digits, and bracketed by [ln2/(4p), 1 - t] (f < 0 < f there),
# since findroot's secant from 0.15 would need about 2p steps.
def solve(f, p, t, small_p_start):
    if p <= 10:
        return findroot(f, small_p_start)
    return findroot(f, (log(2) / (4 * p), 1 - t), solver="anderson")


def c0(p):
    with mp.extradps(int(mp.log10(2 * p)) + 10):
        t = mpf(2) ** (-1 / (2 * p))
        s = solve(lambda s: (s + t) ** (2 * p) + s ** (2 * p) + mpf(2) ** (-2 * p) - 1, p, t, mpf("0.15"))
        det = mpf(2) ** (3 - 1 / (2 * p)) * (2 * s + t)
        return {"s": +s}, +(volume(p) / det)


def c1(p):
    with mp.extradps(int(mp.log10(2 * p)) + 10):
        t = mpf(2) ** (-1 / (2 * p))
        s = solve(lambda s: (s + t) ** (2 * p) + 2 * s ** (2 * p) - 1, p, t, mpf("0.2"))
        det = mpf(2) ** (3 - 1 / p) * (3 * s + t)
        return {"s": +s}, +(volume(p) / det)


def o0(p):
    c = (1 - mpf(2) ** (1 - 2 * p)) ** (1 / (2 * p))
    return {"c": c}, volume(p) / (8 * c)


def o1(p, start):
    l = mpf(3) ** (-1 / (2 * p))
    q, s = findroot(
        [lambda q, s: 2 * abs(q) ** (2 * p) + abs(s) ** (2 * p) - 1,
         lambda q, s: abs(l + q) ** (2 * p) + abs(s - l) ** (2 * p) + abs(l - q) ** (2 * p) - 1],
        start)
    return {"l": l, "q": q, "s": s}, volume(p) / (8 * l * (3 * q**2 + s**2))


def entry(family, p_text, parameters, phi):
    p = mpf(Fraction(p_text).numerator) / Fraction(p_text).denominator
    return {"family": family, "p": p_text, "volume": text(volume(p)),
            "parameters": {k: text(v) for k, v in parameters.items()}, "phi": text(phi)}


def main():
    families = []
    for p_text in ["1", "1.1", "1.15", "1.5", "2", "3", "5", "10", "150", "10000", "1000000"]:
        p = mpf(Fraction(p_text).numerator) / Fraction(p_text).denominator
        families.append(entry("C0", p_text, *c0(p)))
        families.append(entry("C1", p_text, *c1(p)))
    for p_text in ["0.55", "0.7", "0.8", "0.85", "0.9", "1"]:
        p = mpf(Fraction(p_text).numerator) / Fraction(p_text).denominator
        families.append(entry("O0", p_text, *o0(p)))
    # O1 (Minkowski branch) starts from the rational root (1/6, 2/3) at p = 1/2 and is
    # continued in small steps so findroot stays on the branch.
    # At p = 1/2 the equations are piecewise linear and the root is exact.
    q, s = mpf(1) / 6, mpf(2) / 3
    families.append(entry("O1", "0.5", {"l": mpf(1) / 3, "q": q, "s": s},
                          volume(mpf(1) / 2) / (8 * (3 * q**2 + s**2) / 3)))
    targets = {"0.55", "0.6", "0.7", "0.75", "0.79"}
    for k in range(1, 30):
        p = mpf(500 + 10 * k) / 1000
        parameters, phi = o1(p, [q, s])
        q, s = parameters["q"], parameters["s"]
        decimal = f"{(500 + 10 * k) / 1000:g}"
        if decimal in targets:
            families.append(entry("O1", decimal, parameters, phi))
    # The insertion (JST 2009, Eq. 10): the exact basis of Minkowski's octahedron lattice,
    # |det| = 38/27, for every 0 < p <= 1/2.
    for p_text in ["0.05", "0.1", "0.3", "0.45", "0.5"]:
        p = mpf(Fraction(p_text).numerator) / Fraction(p_text).denominator
        families.append(entry("minkowski-insertion", p_text, {}, volume(p) * 27 / 38))
    areas = [{"p": p_text, "area": text(area(mpf(Fraction(p_text).numerator) / Fraction(p_text).denominator))}
             for p_text in ["0.3", "0.5", "0.75", "1", "1.5", "2", "7/3"]]
    document = {"generator": "scripts/make_golden.py", "mpmath_dps": mp.dps, "digits": DIGITS,
                "families": families, "superdisk_areas": areas,
                "constants": {"pi_over_sqrt18": text(pi / sqrt(18)), "ln3_over_ln4": text(log(3) / log(4)),
                              "pi_over_6": text(pi / 6), "superball_volume_p2": text(volume(mpf(2)))}}
    print(json.dumps(document, indent=1))


if __name__ == "__main__":
    main()
