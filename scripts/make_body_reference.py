#!/usr/bin/env python3
"""Reference support functions h_K(u) = max over the superball K of <u, x>, with mpmath at
60 digits, for tests/test_body.cpp.

Independence: superpack evaluates the dual norm ||u||_r, r = 2p / (2p - 1). Here the maximum
is found from the Lagrange condition instead: at the maximiser x_i = sign(u_i) (|u_i| / L)^(1/(q-1))
with q = 2p, where the multiplier L solves sum |x_i|^q = 1 (mpmath's findroot, in log L);
h is then <u, x>. Not rigorous: the tests ask only that the certified enclosures meet these
values to the 50 digits written.

Usage: scripts/make_body_reference.py > tests/data/body.json
"""
import json
from fractions import Fraction

from mpmath import mp, mpf, exp, findroot, log, fsum

mp.dps = 60
DIGITS = 50


def text(x):
    return mp.nstr(x, DIGITS, strip_zeros=False)


def support(p, u):
    q = 2 * p
    nonzero = [abs(c) for c in u if c != 0]

    def constraint(log_l):
        l = exp(log_l)
        return log(fsum((c / l) ** (q / (q - 1)) for c in nonzero))

    log_l = findroot(constraint, mpf(0))
    l = exp(log_l)
    return fsum(c * (c / l) ** (1 / (q - 1)) for c in nonzero)


CASES = [("3/4", ["1", "2", "3"]), ("3/2", ["1", "2", "3"]), ("3/2", ["-1/2", "0", "5"]),
         ("5", ["1", "1", "1"]), ("100", ["3", "-1", "2"]), ("23/20", ["1", "7/10"])]

rows = []
for p_text, u_text in CASES:
    p = mpf(Fraction(p_text).numerator) / Fraction(p_text).denominator
    u = [mpf(Fraction(c).numerator) / Fraction(c).denominator for c in u_text]
    rows.append({"p": p_text, "u": u_text, "support": text(support(p, u))})
print(json.dumps({"generator": "scripts/make_body_reference.py", "digits": DIGITS, "support": rows}, indent=1))
