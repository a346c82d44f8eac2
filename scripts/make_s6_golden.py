#!/usr/bin/env python3
"""Reference values for the S6 family (superpack's six-pair lattice of (p*_o, 1), NOTES.md 4.2),
computed with mpmath at 60 digits and written to 50.

S6 at p is the KKT point of min det B subject to ||c_i B||_(2p) = 2 for the six triples
(1,0,0), (0,1,0), (0,0,1), (0,1,-1), (1,0,-1), (1,-1,0) (Minkowski's six pairs b1, b2, b3,
b2 - b3, b3 - b1, b1 - b2), unknowns the nine entries of B and six multipliers mu:
    cof(B)_kj = sum_i mu_i c_ik sign(u_ij) |u_ij|^(2p-1),  u_i = c_i B / ||c_i B||,   ||c_i B|| = 2.
Independence: the system is written here from that definition (not from superpack's code);
mpmath's findroot solves it at p = 9/10 from the rounded seed below (the same seed as
superpack's, a guess only) and then follows it in steps of p of at most 1/400; the volume is the
Beta-function form of Jiao, Stillinger and Torquato's Eq. 4 (superpack uses a Gamma form), det B
a cofactor expansion. Nothing here is rigorous: the tests ask that superpack's enclosures
contain these values.

Usage: scripts/make_s6_golden.py > tests/data/s6.json
"""
import json

from mpmath import mp, mpf, beta, findroot, fabs, sign, matrix, lu_solve

mp.dps = 60
DIGITS = 50
P_VALUES = ["0.8", "0.85", "0.9", "0.95", "0.99"]
TRIPLES = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (0, 1, -1), (1, 0, -1), (1, -1, 0)]
SEED_P = mpf(9) / 10
SEED_BASIS = [["1.908055484454950", "0.474758800239233", "-0.117629324180287"],
              ["0.805138657903992", "1.135175685042650", "1.275160957764070"],
              ["1.274935893636720", "-0.774565110291718", "1.158110802562870"]]


def text(x):
    return mp.nstr(x, DIGITS, strip_zeros=False)


def volume(p):
    return 2 / p**2 * beta(1 / (2 * p), (2 * p + 1) / (2 * p)) * beta(1 / (2 * p), (p + 1) / p)


def cofactor(b, k, j):
    k1, k2, j1, j2 = (k + 1) % 3, (k + 2) % 3, (j + 1) % 3, (j + 2) % 3
    return b[k1][j1] * b[k2][j2] - b[k1][j2] * b[k2][j1]


def determinant(b):
    return sum(b[0][j] * cofactor(b, 0, j) for j in range(3))


def slopes(b, c, p):
    """The vector v = c B, its 2p-norm and the gradient sign(u_j) |u_j|^(2p-1) of the norm."""
    v = [sum(c[k] * b[k][j] for k in range(3)) for j in range(3)]
    n = sum(fabs(x) ** (2 * p) for x in v) ** (1 / (2 * p))
    return n, [sign(x) * fabs(x / n) ** (2 * p - 1) for x in v]


def system(p):
    def f(*x):
        b = [list(x[0:3]), list(x[3:6]), list(x[6:9])]
        rows = [cofactor(b, k, j) for k in range(3) for j in range(3)]
        last = []
        for i, c in enumerate(TRIPLES):
            n, g = slopes(b, c, p)
            for k in range(3):
                for j in range(3):
                    rows[3 * k + j] -= x[9 + i] * c[k] * g[j]
            last.append(n - 2)
        return rows + last
    return f


def least_squares_multipliers(b, p):
    gradients = []
    for c in TRIPLES:
        _, g = slopes(b, c, p)
        gradients.append([c[k] * g[j] for k in range(3) for j in range(3)])
    cof = [cofactor(b, k, j) for k in range(3) for j in range(3)]
    normal = matrix(6, 6)
    right = matrix(6, 1)
    for a in range(6):
        right[a] = sum(gradients[a][r] * cof[r] for r in range(9))
        for e in range(6):
            normal[a, e] = sum(gradients[a][r] * gradients[e][r] for r in range(9))
    return list(lu_solve(normal, right))


def seed():
    b = [[mpf(x) for x in row] for row in SEED_BASIS]
    x0 = [b[k][j] for k in range(3) for j in range(3)] + least_squares_multipliers(b, SEED_P)
    return list(findroot(system(SEED_P), x0))


def follow(x, p_start, p_end):
    steps = max(1, int(fabs(p_end - p_start) * 400) + 1)
    for k in range(1, steps + 1):
        p = p_start + (p_end - p_start) * k / steps
        x = list(findroot(system(p), x))
    return x


def main():
    at_seed = seed()
    entries = []
    for p_text in P_VALUES:
        p = mpf(p_text)
        x = follow(at_seed, SEED_P, p)
        assert max(fabs(r) for r in system(p)(*x)) < mpf(10) ** -55
        assert all(mu > 0 for mu in x[9:])
        b = [x[0:3], x[3:6], x[6:9]]
        det = determinant(b)
        assert det > 0
        entries.append({"p": p_text,
                        "basis": [[text(v) for v in row] for row in b],
                        "multipliers": [text(mu) for mu in x[9:]],
                        "determinant": text(det),
                        "phi": text(volume(p) / det)})
    print(json.dumps({"generator": "scripts/make_s6_golden.py (mpmath, 60 digits)", "triples": TRIPLES, "s6": entries},
                     indent=1))


if __name__ == "__main__":
    main()
