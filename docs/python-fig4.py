"""Fig. 4 of Jiao, Stillinger & Torquato (2009) from superpack's Python package: the density of
the densest certified lattice packing against p, each point an enclosure (far thinner than the
line), with the family that attains it. Writes docs/python-fig4.png."""
import sys
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

import superpack

ps = [Fraction(1, 2) + Fraction(k, 20) for k in range(51)]  # 1/2, 11/20, ..., 3
rows = [superpack.best(p) for p in ps]
for p, row in zip(ps, rows):
    print(f"p = {float(p):5.2f}  {row.family:4}  phi in {row.phi.decimal(12)}", file=sys.stderr)

figure, axes = plt.subplots(figsize=(7, 4.2))
for family in sorted({row.family for row in rows}):
    points = [(float(p), float(row.phi)) for p, row in zip(ps, rows) if row.family == family]
    axes.plot(*zip(*points), "o-", markersize=3, label=family)
axes.set_xlabel("p")
axes.set_ylabel("certified lattice packing density phi")
axes.set_title("Densest certified lattice packings of superballs (superpack.best)")
axes.legend()
figure.tight_layout()
figure.savefig(sys.argv[1] if len(sys.argv) > 1 else "docs/python-fig4.png", dpi=110)
