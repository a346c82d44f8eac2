"""Every function against independent values (mpmath), against the command line's own JSON, and
against the certificates it writes: the same numbers, to the last bit."""
import json
import shutil
from fractions import Fraction

import pytest

import superpack
from conftest import REPOSITORY, run_cli, without_timings


def test_the_documented_example():
    phi = superpack.density("C0", "3/2").phi
    assert isinstance(phi.lo, Fraction) and isinstance(phi.hi, Fraction)
    assert 0 < phi.width < Fraction(1, 10**14)


def certified_phi(family, p, digits=None):
    """phi, also where only the packing stays undecided (O1 next to p*_o): phi is certified there."""
    try:
        return superpack.density(family, p, digits=digits).phi
    except superpack.Undecided as undecided:
        assert undecided.result.status == "certified"
        return undecided.result.phi


def test_densities_enclose_mpmath_at_two_precisions_that_overlap(golden):
    checked = 0
    for entry in golden["families"]:
        if "phi" not in entry:
            continue
        reference = Fraction(entry["phi"])  # 50 digits: far inside any enclosure here
        binary64 = certified_phi(entry["family"], entry["p"])
        arb = certified_phi(entry["family"], entry["p"], digits=30)
        assert binary64.contains(reference), entry
        assert arb.contains(reference), entry
        assert arb.width < Fraction(1, 10**29)
        assert max(binary64.lo, arb.lo) <= min(binary64.hi, arb.hi)
        checked += 1
    assert checked >= 30


def test_the_o1_erratum_in_five_lines():
    result = superpack.density("O1", "0.6")
    assert result.packing.verdict == "overlapping"
    witness = result.packing.witness
    assert witness.norm.hi < 2  # a lattice vector of gauge below 2: two bodies overlap
    assert not superpack.density("C0", "3/2").packing.witness


def test_a_certified_impossibility_raises_impossible_with_its_document():
    with pytest.raises(superpack.Impossible, match="O1") as raised:
        superpack.density("O1", "1")
    assert raised.value.result.status == "no_lattice"
    assert len(raised.value.result.roots) == 1


def test_an_undecided_case_raises_undecided_with_the_hint():
    with pytest.raises(superpack.Undecided, match="try --digits 30"):
        superpack.density("O0", "0.5000000000000000001")
    with pytest.raises(superpack.Undecided) as raised:
        superpack.critical("2", max_boxes=50)
    assert raised.value.result.status == "undecided"
    assert raised.value.result.lower.lattice == "C1"


CALLS = [
    (("density", "--family", "C0", "--p", "3/2"), lambda: superpack.density("C0", "3/2")),
    (("density", "--family", "C1", "--p", "1.15", "--digits", "40"), lambda: superpack.density("C1", "1.15", digits=40)),
    (("check-lattice", "--p", "0.3", "--basis", "1,1,0;1,-1,0;0,0,2"),
     lambda: superpack.check_lattice("0.3", basis=[[1, 1, 0], [1, -1, 0], [0, 0, 2]])),
    (("check-lattice", "--p", "2", "--family", "C1"), lambda: superpack.check_lattice(2, family="C1")),
    (("audit", "--family", "C0", "--p-range", "1:1.1"), lambda: superpack.audit("C0", ("1", "1.1"))),
    (("crossover", "cubic"), lambda: superpack.crossover("cubic")),
    (("slopes",), lambda: superpack.slopes()),
    (("superdisk", "--p", "2"), lambda: superpack.superdisk(2)),
    (("superdisk", "--p", "0.3"), lambda: superpack.superdisk("0.3")),
    (("best", "--p", "2"), lambda: superpack.best(2)),
    (("simulate", "--p", "2", "--n", "2", "--steps", "200"), lambda: superpack.simulate(2, 2, steps=200)),
    (("md", "--p", "1", "--n", "16", "--growth", "0.1"), lambda: superpack.md(1, 16, "0.1")),
    (("report", "--p-values", "1.5,2"), lambda: superpack.report(p_values=["1.5", 2])),
]


@pytest.mark.parametrize("arguments, call", CALLS, ids=[" ".join(arguments) for arguments, _ in CALLS])
def test_each_function_gives_the_command_lines_document(arguments, call):
    code, document = run_cli(*arguments)
    assert code == 0
    result = call()
    assert type(result).__name__ in repr(result)
    assert without_timings(result.to_dict()) == without_timings(document)


def test_results_are_typed():
    result = superpack.best("2")
    assert isinstance(result, superpack.Best)
    assert isinstance(result.phi, superpack.Enclosure)
    assert isinstance(result.timing, superpack.Record)
    assert result.phi == result["phi"]
    with pytest.raises(AttributeError, match="no field"):
        result.no_such_field
    with pytest.raises(AttributeError, match="read only"):
        result.phi = None


def exact_end(text):
    return superpack._exact.parse_exact(text)


def test_fraction_ends_equal_the_certificates(tmp_path):
    for digits in (None, 50):
        path = tmp_path / f"density-{digits}.json"
        result = superpack.density("C0", "3/2", digits=digits, certificate=path)
        with open(path) as file:
            certificate = json.load(file)
        phi = certificate["claim"]["data"]["phi"]
        assert (result.phi.lo, result.phi.hi) == (exact_end(phi["lo"]), exact_end(phi["hi"]))
        verified = superpack.verify(path)
        assert verified.verdict == "valid"
        assert verified.claim == certificate["claim"]["text"]


def test_verify_replays_a_committed_proof_and_rejects_a_tampered_one(tmp_path):
    proof = REPOSITORY / "proofs" / "best-p2.json"
    assert superpack.verify(proof).verdict == "valid"
    with open(proof) as file:
        certificate = json.load(file)
    certificate["inputs"]["p"] = "3"
    tampered = tmp_path / "tampered.json"
    tampered.write_text(json.dumps(certificate))
    with pytest.raises(superpack.InvalidCertificate, match="inputs") as raised:
        superpack.verify(tampered)
    assert raised.value.result.verdict == "invalid"
    copy = tmp_path / "copy.json"
    shutil.copy(proof, copy)
    assert superpack.verify(copy, threads=1).verdict == "valid"


def test_simulate_and_md_write_their_files_and_certificates(tmp_path):
    result = superpack.md("1", 16, "0.1", seed=3, xyz=tmp_path / "md.xyz", certificate=tmp_path / "md.json")
    assert result.certified is True
    assert (tmp_path / "md.xyz").read_text().startswith("16\n")
    assert superpack.verify(tmp_path / "md.json").verdict == "valid"
    assert superpack.md("1", 16, "0.1", seed=3).phi == result.phi
    simulation = superpack.simulate("2", 2, steps=200, certificate=tmp_path / "simulate.json")
    assert simulation.ratio_to_best_lattice.hi <= 1
    assert superpack.verify(tmp_path / "simulate.json").verdict == "valid"
