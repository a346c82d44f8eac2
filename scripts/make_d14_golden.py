#!/usr/bin/env python3
"""Reference values for the D14 family (Dostert and Vallentin, Adv. Geom. 20 (2020), Thm. 4.2),
computed with mpmath at 60 digits and written to 50.

Independence: the root (x, y, z) comes from mpmath's findroot, followed by continuation from
Minkowski's (1/3, 1/6, 1/2) at p = 1/2 in small steps of p; the volume is the Beta-function form
of the paper of Jiao, Stillinger and Torquato (Eq. 4), not superpack's Gamma form; |det| is the
closed form of the circulant basis 2(-x, y, z), 2(z, -x, y), 2(y, z, -x),
8 |y^3 + z^3 - x^3 + 3xyz|, not a determinant of the basis. Nothing here is rigorous: the tests
ask that superpack's enclosures contain these values.

Usage: scripts/make_d14_golden.py > tests/data/d14.json
"""
import json

from mpmath import mp, mpf, beta, findroot, fabs

mp.dps = 60
DIGITS = 50
P_VALUES = ["0.52", "0.55", "0.6", "0.65", "0.7", "0.75", "0.79"]


def text(x):
    return mp.nstr(x, DIGITS, strip_zeros=False)


def volume(p):
    return 2 / p**2 * beta(1 / (2 * p), (2 * p + 1) / (2 * p)) * beta(1 / (2 * p), (p + 1) / p)


def equations(p):
    q = 2 * p

    def f(x, y, z):
        return [fabs(x) ** q + fabs(y) ** q + fabs(z) ** q - 1,
                fabs(x - y) ** q + fabs(z - x) ** q + fabs(y + z) ** q - 1,
                3 * fabs(y + z - x) ** q - 1]
    return f


def follow(p_end, steps=400):
    root = (mpf(1) / 3, mpf(1) / 6, mpf(1) / 2)
    start = mpf(1) / 2
    for k in range(1, steps + 1):
        p = start + (p_end - start) * k / steps
        root = tuple(findroot(equations(p), root))
    return root


def main():
    entries = []
    for p_text in P_VALUES:
        p = mpf(p_text)
        x, y, z = follow(p)
        assert max(fabs(v) for v in equations(p)(x, y, z)) < mpf(10) ** -55
        assert x > 0 and y > 0 and z > 0 and y < z
        det = 8 * fabs(y**3 + z**3 - x**3 + 3 * x * y * z)
        entries.append({"p": p_text, "x": text(x), "y": text(y), "z": text(z), "phi": text(volume(p) / det)})
    print(json.dumps({"generator": "scripts/make_d14_golden.py (mpmath, 60 digits)", "d14": entries}, indent=1))


if __name__ == "__main__":
    main()
