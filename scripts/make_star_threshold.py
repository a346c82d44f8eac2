#!/usr/bin/env python3
"""A translation v = (a, 1/2, 0) at which the concave superball K (p = 3/10, q = 3/5) and K + v
touch arm to arm, with mpmath at 160 digits, for tests/test_certificate_star_lattice.cpp.

With x_2 = 1/2 (x_2 = v_2) and x_3 = 0 the two bodies share the segment of x_1 where
|x_1|^q < 1 - (1/2)^q and |x_1 - a|^q < 1: they meet iff (1 - 2^-q)^(1/q) + 1 > a. So the
threshold is a* = 1 + (1 - 2^-q)^(1/q): just below it the interiors meet, just above they are
disjoint. The test takes rationals 10^-120 on either side, far inside a 128-bit interval's
rounding and far outside 512 bits'. Not rigorous: 150 digits written, the test needs 121.

Usage: scripts/make_star_threshold.py > tests/data/star_threshold.json
"""
import json

from mpmath import mp, mpf

mp.dps = 160
q = mpf(3) / 5
threshold = 1 + (1 - mpf(2) ** (-q)) ** (1 / q)
print(json.dumps({"p": "3/10", "v2": "1/2", "threshold": mp.nstr(threshold, 150, strip_zeros=False)}, indent=1))
