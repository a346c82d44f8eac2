#!/usr/bin/env python3
"""Independent reference values for tests/test_superdisk.cpp (mpmath, 50 digits).

Written from the closed forms of NOTES.md section 7, not from the C++ formulas:
  Lambda1: u = (1, 0), v = (1/2, (1 - 2^-q)^(1/q)), det(u, v) = v_y.
  Lambda0: u = c (1, 1), c = 2^(-1/q), v = (c/2 - s, c/2 + s) with
           |c/2 - s|^q + |c/2 + s|^q = 1, det(u, v) = 2 c s.
  optimum: min over the angle of u (any parametrisation) of det(u, v(u)), by a dense
           sample and a golden-section refinement, v(u) by findroot in polar form.
phi = area / (4 det), area = 4 Gamma(1 + 1/q)^2 / Gamma(1 + 2/q), q = 2p.
Usage: python3 scripts/make_superdisk_golden.py > tests/data/superdisk.json
"""
import json
from mpmath import mp, mpf, gamma, findroot, cos, sin, pi, fabs

mp.dps = 50


def radius(theta, q):
    # the boundary point of K in direction theta is r (cos, sin)
    return (fabs(cos(theta)) ** q + fabs(sin(theta)) ** q) ** (-1 / q)


def point(theta, q):
    r = radius(theta, q)
    return (r * cos(theta), r * sin(theta))


def det_at(theta, q):
    u = point(theta, q)
    # v = point(phi) with |v - u|_q = 1, phi in (theta, theta + pi)
    g = lambda phi: sum(fabs(a - b) ** q for a, b in zip(point(phi, q), u)) - 1
    # bracket: g < 0 near theta, > 0 near theta + pi (where v - u ~ -2u)
    lo, hi = theta + mpf('1e-6'), theta + pi - mpf('1e-6')
    for _ in range(200):
        mid = (lo + hi) / 2
        if g(mid) < 0:
            lo = mid
        else:
            hi = mid
    v = point((lo + hi) / 2, q)
    return u[0] * v[1] - u[1] * v[0]


def reference(p_text):
    p = mpf(p_text)
    q = 2 * p
    area = 4 * gamma(1 + 1 / q) ** 2 / gamma(1 + 2 / q)
    lambda1 = (1 - mpf(2) ** (-q)) ** (1 / q)
    c = mpf(2) ** (-1 / q)
    s = findroot(lambda s: fabs(c / 2 - s) ** q + fabs(c / 2 + s) ** q - 1, mpf('0.4'))
    lambda0 = 2 * c * s
    # the minimum over the angle of u in [0, pi/4]
    samples = 400
    values = [(det_at(pi / 4 * k / samples, q), k) for k in range(samples + 1)]
    best, k = min(values)
    a, b = pi / 4 * max(k - 1, 0) / samples, pi / 4 * min(k + 1, samples) / samples
    golden = (mp.sqrt(5) - 1) / 2
    for _ in range(120):
        x1, x2 = b - golden * (b - a), a + golden * (b - a)
        if det_at(x1, q) < det_at(x2, q):
            b = x2
        else:
            a = x1
    best = min(best, det_at((a + b) / 2, q))
    digits = lambda x: mp.nstr(x, 45)
    return {
        "area": digits(area),
        "phi_Lambda0": digits(area / (4 * lambda0)),
        "phi_Lambda1": digits(area / (4 * lambda1)),
        "optimal_phi": digits(area / (4 * best)),
    }


if __name__ == "__main__":
    ps = ["0.6", "0.75", "1", "1.1", "1.25", "1.5", "2", "3"]
    print(json.dumps({p: reference(p) for p in ps}, indent=2))
