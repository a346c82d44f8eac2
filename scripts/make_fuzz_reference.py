#!/usr/bin/env python3
"""Independent references for the checker's fuzz test (tests/fuzz/truth.hpp, NOTES.md 8.8).

For every exact interval in claim.data and inputs of every certificate in proofs/, a rule that
judges a mutated interval without the checker:
  contains: the true values it must still enclose (mpmath, 50 digits; an exact value such as
            t = 1 as a short decimal), taken from the committed references in tests/data/
            (make_golden.py, make_crossover_reference.py, make_superdisk_golden.py,
            make_superdisk_vertices.py, make_lattice_data.py, make_d14_golden.py, make_s6_golden.py)
            or computed here from the paper's
            equations (derivatives of s and c at p = 1, witness norms of the audits), from the
            KKT system of a local optimum (its basis, multipliers and phi) or from a concave
            lattice's witness point x (g(x) and g(x - v), g = sum |x_i|^(2p));
  covers:   a list of intervals (argmin_t) that must hold each given value;
  within_original: a range the claim holds on (a piece of p), which may only shrink.
A periodic-packing claim (simulate, md) has no interval: every value must equal the original.
An audit piece claims its witness norm for every p of the piece: the rule lists the norm at both
ends of the piece (at its point for overlapping_at_point), which the true range contains.
Each value is checked against the committed certificate before it is written, so a wrong formula
here stops the script instead of weakening the test.

Usage: scripts/make_fuzz_reference.py > tests/data/fuzz_reference.json
"""
import glob
import json
import os
import sys
from fractions import Fraction

from mpmath import mp, mpf, diff, fabs, findroot, gamma

from make_golden import o1 as o1_family

mp.dps = 60
ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
DATA = os.path.join(ROOT, "tests", "data")


def load(name):
    with open(os.path.join(DATA, name)) as file:
        return json.load(file)


GOLDEN, CROSSOVER, SUPERDISK = load("golden.json"), load("crossover.json"), load("superdisk.json")
VERTICES, LATTICE = load("superdisk_vertices.json"), load("lattice.json")
D14, S6 = load("d14.json"), load("s6.json")


def text(x):
    return mp.nstr(x, 50, strip_zeros=False)


def exact(endpoint):
    """An endpoint "m*2^e", "m" or "a/b" as a Fraction."""
    if "/" in endpoint:
        return Fraction(endpoint)
    mantissa, _, exponent = endpoint.partition("*2^")
    return Fraction(int(mantissa)) * Fraction(2) ** int(exponent or 0)


def as_mpf(q):
    return mpf(q.numerator) / q.denominator


def golden(family, p):
    if family == "D14":
        return d14_golden(p)
    if family == "S6":
        return s6_golden(p)
    for entry in GOLDEN["families"]:
        if entry["family"] == family and Fraction(entry["p"]) == p:
            return entry
    raise KeyError((family, p))


def d14_golden(p):
    """D14 at p from tests/data/d14.json (make_d14_golden.py): x, y, z and phi, with the volume of
    the superball (q = 2p) computed here."""
    for entry in D14["d14"]:
        if Fraction(entry["p"]) == p:
            q = 2 * as_mpf(p)
            volume = (2 * gamma(1 + 1 / q)) ** 3 / gamma(1 + 3 / q)
            return {"volume": text(volume), "phi": entry["phi"],
                    "parameters": {name: entry[name] for name in ("x", "y", "z")}}
    raise KeyError(("D14", p))


def s6_golden(p):
    """S6 at p from tests/data/s6.json (make_s6_golden.py): the nine basis entries b00..b22, the six
    multipliers mu1..mu6 and phi, with the volume of the superball (q = 2p) computed here."""
    for entry in S6["s6"]:
        if Fraction(entry["p"]) == p:
            q = 2 * as_mpf(p)
            volume = (2 * gamma(1 + 1 / q)) ** 3 / gamma(1 + 3 / q)
            parameters = {"b%d%d" % (k, j): entry["basis"][k][j] for k in range(3) for j in range(3)}
            parameters.update({"mu%d" % (i + 1): mu for i, mu in enumerate(entry["multipliers"])})
            return {"volume": text(volume), "phi": entry["phi"], "parameters": parameters}
    raise KeyError(("S6", p))


def norm(v, p):
    return sum(fabs(x) ** (2 * p) for x in v) ** (1 / (2 * p))


def combine(basis, c):
    return [sum(c[i] * basis[i][j] for i in range(3)) for j in range(3)]


def o0_basis(p):
    c = (1 - mpf(2) ** (1 - 2 * p)) ** (1 / (2 * p))
    return [[2, 0, 0], [0, 2, 0], [1, 1, 2 * c]]


def o1_basis(l, q, s):
    return [[2 * l, 2 * l, -2 * l], [-2 * q, 2 * s, -2 * q], [2 * q, -2 * q, -2 * s]]


class O1Branch:
    """The Minkowski branch (q, s) of Eq. 12, continued from its exact root (1/6, 2/3) at p = 1/2 in
    steps of at most 0.005 (as make_golden.py does), so that findroot stays on the branch."""

    def __init__(self):
        self.p, self.root = mpf(1) / 2, [mpf(1) / 6, mpf(2) / 3]

    def basis(self, p):
        if p == mpf(1) / 2:
            return o1_basis(mpf(1) / 3, mpf(1) / 6, mpf(2) / 3)
        while True:
            step = p - self.p
            target = p if fabs(step) <= mpf("0.005") else self.p + mpf("0.005") * (1 if step > 0 else -1)
            parameters, _ = o1_family(target, self.root)
            self.p, self.root = target, [parameters["q"], parameters["s"]]
            if target == p:
                return o1_basis(parameters["l"], parameters["q"], parameters["s"])


def s_c0(p):
    t = mpf(2) ** (-1 / (2 * p))
    return findroot(lambda s: (s + t) ** (2 * p) + s ** (2 * p) + mpf(2) ** (-2 * p) - 1, mpf("0.15"), tol=mpf(10) ** -58)


def s_c1(p):
    t = mpf(2) ** (-1 / (2 * p))
    return findroot(lambda s: (s + t) ** (2 * p) + 2 * s ** (2 * p) - 1, mpf("0.2"), tol=mpf(10) ** -58)


def c_o0(p):
    return (1 - mpf(2) ** (1 - 2 * p)) ** (1 / (2 * p))


def family_lattice(data):
    p = Fraction(data["p"])
    entry = golden(data["family"], p)
    volume, phi = mpf(entry["volume"]), mpf(entry["phi"])
    sign = -1 if exact(data["determinant"]["hi"]) < 0 else 1
    values = {"/claim/data/volume": entry["volume"], "/claim/data/phi": entry["phi"],
              "/claim/data/determinant": text(sign * volume / phi)}
    for name, value in entry["parameters"].items():
        values["/claim/data/parameters/" + name] = value
    # A density certificate of a lattice that overlaps carries the witness of the lattice check.
    values.update(lattice_witness(data, None, data["family"]))
    return values


def cubic_crossover(data):
    return {"/claim/data/p": CROSSOVER["p_c"], "/claim/data/phi": CROSSOVER["phi_c"]}


def octahedral_crossover(data):
    return {"/claim/data/p": CROSSOVER["p_o"], "/claim/data/phi": CROSSOVER["phi_o"]}


def sphere_slopes(data):
    one = mpf(1)
    slopes = CROSSOVER["slopes"]
    values = {}
    for family, parameter, function in [("C0", "s", s_c0), ("C1", "s", s_c1), ("O0", "c", c_o0)]:
        base = "/claim/data/%s/" % family
        values[base + parameter] = text(function(one))
        values[base + "d%s_dp" % parameter] = text(diff(function, one))
        values[base + "slope"] = slopes[family]["1"]
    values["/claim/data/C0/phi"] = golden("C0", 1)["phi"]
    values["/claim/data/C1/phi"] = golden("C1", 1)["phi"]
    values["/claim/data/O0/phi"] = golden("O0", 1)["phi"]
    values["/claim/data/a_minus/value"] = slopes["O0"]["1"]
    values["/claim/data/a_plus/value"] = slopes[data["a_plus"]["family"]]["1"]
    values["/claim/data/paper/a_minus/closed_form"] = CROSSOVER["closed_a_minus"]
    values["/claim/data/paper/a_plus/closed_form"] = CROSSOVER["closed_a_plus"]
    return values


def superdisk_optimum(data):
    key = str(Fraction(data["p"])) if Fraction(data["p"]).denominator == 1 else str(float(Fraction(data["p"])))
    reference = SUPERDISK[key]
    area, optimum = mpf(reference["area"]), mpf(reference["optimal_phi"])
    values = {"/claim/data/area": reference["area"], "/claim/data/optimal_phi": reference["optimal_phi"],
              "/claim/data/optimal_determinant": text(area / optimum)}
    for name, t in [("Lambda0", "1"), ("Lambda1", "0")]:
        phi = mpf(reference["phi_" + name])
        values["/claim/data/lattices/%s/t" % name] = t
        values["/claim/data/lattices/%s/phi" % name] = reference["phi_" + name]
        values["/claim/data/lattices/%s/determinant" % name] = text(area / phi)
    # The minimisers of D: the folded vertices of each optimal lattice (NOTES.md 7.2); at the
    # circle (p = 1) D is constant, and every t of [0, 1] is one (a sample of 1001 points).
    if Fraction(data["p"]) == 1:
        minimisers = ["0"] + [text(mpf(k) / 1000) for k in range(1, 1000)] + ["1"]
    else:
        optimal = [name for name in ("Lambda0", "Lambda1") if fabs(mpf(reference["phi_" + name]) - optimum) < mpf(10) ** -40]
        minimisers = [t for name in optimal for t in VERTICES[key][name]]
    return values, {"/claim/data/argmin_t": minimisers}


def lattice_witness(data, inputs, family):
    """The witness norm of a lattice-check (exact basis) or family-lattice-check certificate."""
    if "witness" not in data:
        return {}
    p = Fraction(data["p"])
    coefficients = data["witness"]["coefficients"]
    if family is None:
        basis = [[as_mpf(Fraction(x)) for x in row] for row in data["basis"]]
    elif family == "O1":
        basis = O1Branch().basis(as_mpf(p))
    elif family == "O0":
        basis = o0_basis(as_mpf(p))
    else:
        raise ValueError("a witness for family " + family)
    return {"/claim/data/witness/norm": text(norm(combine(basis, coefficients), as_mpf(p)))}


def audit(data):
    """Ranges may only shrink; a witness norm must hold the norm at the piece's ends (or point)."""
    family = data["family"]
    values = {}
    branch = O1Branch()
    order = sorted(range(len(data["pieces"])), key=lambda k: exact(data["pieces"][k]["p"]["lo"]))
    for k in order:
        piece = data["pieces"][k]
        if "witness" not in piece:
            continue
        if "at" in piece:
            points = [Fraction(piece["at"])]
        else:
            points = [exact(piece["p"]["lo"]), exact(piece["p"]["hi"])]
        norms = []
        for point in points:
            p = as_mpf(point)
            basis = branch.basis(p) if family == "O1" else o0_basis(p)
            norms.append(text(norm(combine(basis, piece["witness"]["coefficients"]), p)))
        values["/claim/data/pieces/%d/witness/norm" % k] = norms
    return values


def local_optimum(data, proof):
    """The KKT point (B, mu) of min det B subject to ||c_i B||_(2p) = 2 (NOTES.md 8.9), solved
    here by Newton's method in mpmath from the middle of the certificate's root box, and its
    volume, determinant and phi."""
    p = as_mpf(Fraction(data["p"]))
    q = 2 * p
    contacts = data["contact_pairs"]

    def equations(*x):
        b = [[x[3 * k + j] for j in range(3)] for k in range(3)]
        f = [b[(k + 1) % 3][(j + 1) % 3] * b[(k + 2) % 3][(j + 2) % 3]
             - b[(k + 1) % 3][(j + 2) % 3] * b[(k + 2) % 3][(j + 1) % 3] for k in range(3) for j in range(3)]
        constraints = []
        for i, c in enumerate(contacts):
            v = combine(b, c)
            n = norm(v, p)
            for k in range(3):
                for j in range(3):
                    f[3 * k + j] -= x[9 + i] * c[k] * mp.sign(v[j]) * fabs(v[j]) ** (q - 1) * n ** (1 - q)
            constraints.append(n - 2)
        return f + constraints

    start = [(as_mpf(exact(x["lo"])) + as_mpf(exact(x["hi"]))) / 2 for x in proof["kkt"]["root"]]
    x = findroot(equations, start, tol=mpf(10) ** -50)
    b = [[x[3 * k + j] for j in range(3)] for k in range(3)]
    det = mp.det(mp.matrix(b))
    volume = (2 * gamma(1 + 1 / q)) ** 3 / gamma(1 + 3 / q)
    values = {"/claim/data/volume": text(volume), "/claim/data/determinant": text(det),
              "/claim/data/phi": text(volume / fabs(det))}
    for k in range(3):
        for j in range(3):
            values["/claim/data/basis/%d/%d" % (k, j)] = text(b[k][j])
    for i in range(len(contacts)):
        values["/claim/data/multipliers/%d" % i] = text(x[9 + i])
    return values


def critical_lattice(data):
    """The superball's volume at p and V(K) / T for the claim's threshold T (an exact point: the
    claim's bound is about that T, so only V(K) / T is a value to enclose)."""
    q = 2 * as_mpf(Fraction(data["p"]))
    volume = (2 * gamma(1 + 1 / q)) ** 3 / gamma(1 + 3 / q)
    threshold = as_mpf(exact(data["threshold"]["lo"]))
    return {"/claim/data/volume": text(volume), "/claim/data/upper_phi": text(volume / threshold)}


def star_lattice_check(data):
    """A concave superball's lattice (p < 1/2, NOTES.md 13.5): a packing states no interval; an
    overlap's witness states g(x) and g(x - v), g(y) = sum |y_i|^(2p), at its rational point x and
    its lattice vector v = coefficients B, both computed here from the exact point and basis."""
    if "witness" not in data:
        return {}
    p = as_mpf(Fraction(data["p"]))
    basis = [[as_mpf(Fraction(x)) for x in row] for row in data["basis"]]
    v = combine(basis, data["witness"]["coefficients"])
    x = [as_mpf(Fraction(t)) for t in data["witness"]["point"]]
    gauge = lambda y: sum(fabs(t) ** (2 * p) for t in y)
    return {"/claim/data/witness/values/0": text(gauge(x)),
            "/claim/data/witness/values/1": text(gauge([x[j] - v[j] for j in range(3)]))}


def periodic_packing(data):
    """Nothing to enclose: the claim (p, the cell rows, each particle's centre and quaternion, all
    exact rationals, and packing: true) states its density as N V_sb(p) / |det B| with |det B| exact,
    no interval, so every value must equal the original (the checker's sentence prints each one,
    and a file whose claim.text differs is rejected). Should an interval appear in claim.data or
    inputs, main() stops with "no reference for" it."""
    return {}


def rules(document):
    claim, data = document["claim"], document["claim"]["data"]
    kind = claim["kind"]
    covers, ranges = {}, []
    if kind == "family-lattice":
        values = family_lattice(data)
    elif kind == "cubic-crossover":
        values = cubic_crossover(data)
    elif kind == "octahedral-crossover":
        values = octahedral_crossover(data)
    elif kind == "sphere-slopes":
        values = sphere_slopes(data)
    elif kind == "superdisk-optimum":
        values, covers = superdisk_optimum(data)
    elif kind == "lattice-check":
        values = lattice_witness(data, document["inputs"], None)
    elif kind == "family-lattice-check":
        values = lattice_witness(data, document["inputs"], data["family"])
    elif kind == "local-optimum":
        values = local_optimum(data, document["proof"])
    elif kind == "critical-lattice":
        values = critical_lattice(data)
        ranges = ["/claim/data/threshold"]  # the bound the claim is about: it may only stay as it is
    elif kind == "star-lattice-check":
        values = star_lattice_check(data)
    elif kind == "periodic-packing":
        values = periodic_packing(data)
    elif kind == "audit":
        values = audit(data)
        ranges = ["/claim/data/range", "/inputs/range", "/claim/data/pieces/*/p"]
    else:
        raise ValueError("no references for claim kind " + kind)
    return values, covers, ranges


def at(document, pointer):
    node = document
    for segment in pointer.strip("/").split("/"):
        node = node[int(segment)] if isinstance(node, list) else node[segment]
    return node


def check(document, name, values, covers):
    """Every reference must lie in the committed certificate's interval (or one of its list)."""
    def inside(value, interval):
        v = mpf(value)
        margin = fabs(v) * mpf(10) ** -44 if len(value.replace("-", "").replace(".", "").lstrip("0")) >= 30 else 0
        return as_mpf(exact(interval["lo"])) <= v - margin and v + margin <= as_mpf(exact(interval["hi"]))
    for pointer, value in values.items():
        for v in value if isinstance(value, list) else [value]:
            if not inside(v, at(document, pointer)):
                sys.exit("%s %s: the reference %s is not in the certificate's %s" % (name, pointer, v, at(document, pointer)))
    for pointer, points in covers.items():
        for v in points:
            if not any(inside(v, interval) for interval in at(document, pointer)):
                sys.exit("%s %s: no interval holds the reference %s" % (name, pointer, v))


def intervals(node, pointer, found):
    if isinstance(node, dict):
        if "lo" in node and "hi" in node:
            found.append(pointer)
            return
        for key, value in node.items():
            intervals(value, pointer + "/" + key, found)
    elif isinstance(node, list):
        for k, value in enumerate(node):
            intervals(value, "%s/%d" % (pointer, k), found)


def main():
    certificates = {}
    for path in sorted(glob.glob(os.path.join(ROOT, "proofs", "*.json"))):
        name = os.path.basename(path)
        with open(path) as file:
            document = json.load(file)
        values, covers, ranges = rules(document)
        check(document, name, values, covers)
        entries = [{"pointer": pointer} for pointer in ranges]
        entries += [{"pointer": pointer, "covers": points} for pointer, points in covers.items()]
        entries += [{"pointer": pointer, "contains": value if isinstance(value, list) else [value]}
                    for pointer, value in values.items()]
        # Every interval of the claim and inputs has a rule (an audit piece without a witness
        # has only its range, which the wildcard covers).
        found = []
        intervals(document["claim"]["data"], "/claim/data", found)
        intervals(document["inputs"], "/inputs", found)
        judged = set(values) | set(covers) | set(ranges)
        wildcard = lambda pointer: "/".join("*" if s.isdigit() else s for s in pointer.split("/"))
        missing = [p for p in found if p not in judged and wildcard(p) not in judged
                   and not any(p.startswith(c + "/") for c in covers)]
        if missing:
            sys.exit("%s: no reference for %s" % (name, ", ".join(missing)))
        certificates[name] = entries
    document = {"generator": "scripts/make_fuzz_reference.py (mpmath, %d digits; values of tests/data/*.json)" % mp.dps,
                "certificates": certificates}
    print(json.dumps(document, indent=1))


if __name__ == "__main__":
    main()
