"""What the functions accept: exact numbers only, and bad input is an InputError (a ValueError)
naming the problem, never a crash."""
import decimal
from fractions import Fraction

import pytest

import superpack
from superpack._exact import exact_text


def test_exact_numbers_are_written_exactly():
    assert exact_text("1.15", "p") == "1.15"
    assert exact_text(2, "p") == "2"
    assert exact_text(Fraction(23, 20), "p") == "23/20"
    assert exact_text(Fraction(4, 2), "p") == "2"
    assert exact_text(decimal.Decimal("1.15"), "p") == "23/20"
    assert exact_text(decimal.Decimal("1E+1"), "p") == "10"


@pytest.mark.parametrize("value", [1.5, 0.6, True, None, [1], complex(1, 0), decimal.Decimal("NaN"),
                                   decimal.Decimal("Infinity")])
def test_inexact_or_odd_p_is_refused(value):
    with pytest.raises(ValueError):
        exact_text(value, "p")


def test_a_float_p_is_refused_with_the_reason():
    with pytest.raises(superpack.InputError, match="a float is not exact") as raised:
        superpack.density("C0", 1.5)
    assert isinstance(raised.value, ValueError)
    with pytest.raises(ValueError, match="float"):
        superpack.check_lattice("2", basis=[[2, 0, 0], [0, 2, 0], [0, 0, 2.0]])


def test_the_same_p_in_every_exact_type_gives_the_same_enclosure():
    results = [superpack.density("C1", p).phi for p in ("1.15", "23/20", Fraction(23, 20), decimal.Decimal("1.15"))]
    assert all(result == results[0] for result in results)


@pytest.mark.parametrize("call, message", [
    (lambda: superpack.density("C9", "2"), "C9"),
    (lambda: superpack.density("C0", "0"), "positive"),
    (lambda: superpack.density("C0", "1000001"), r"10\^6"),
    (lambda: superpack.density("C0", "abc"), "abc"),
    (lambda: superpack.density("C0", "2", digits=0), "--digits"),
    (lambda: superpack.density("C0", "2", digits=2.0), "digits"),
    (lambda: superpack.check_lattice("2", basis="1,2;3"), "basis"),
    (lambda: superpack.best("2", starts=True), "starts"),
    (lambda: superpack.md("1", 0, "0.1"), "--n"),
    (lambda: superpack.simulate("2", 2, steps=-1), "--steps"),
    (lambda: superpack.audit("C0", p_range=("0.5", "2")), "range"),
    (lambda: superpack.density("C0", "2", progress="yes"), "progress"),
    (lambda: superpack.verify("/nonexistent/certificate.json"), "unreadable"),
    # Values that look like options are values: a positional after "--", an option's as --flag=value.
    (lambda: superpack.crossover("--help"), "got '--help'"),
    (lambda: superpack.density("--help", "2"), "unknown family '--help'"),
    (lambda: superpack.critical(merge=["--json"]), "cannot open '--json'"),
    (lambda: superpack.critical(merge=[]), "merge: expected at least one file"),
    # A NUL would cut the value short (argv holds C strings).
    (lambda: superpack.density("C0", "2\x003"), "p: contains a NUL"),
    (lambda: superpack.density("C0\x00x", "2"), "family: contains a NUL"),
    (lambda: superpack.density("C0", "2", certificate="out.json\x00x"), "certificate: contains a NUL"),
    (lambda: superpack.crossover("cubic\x00x"), "kind: contains a NUL"),
    (lambda: superpack.verify("proof.json\x00x"), "path: contains a NUL"),
    (lambda: superpack.density("C0", 10**5000), "more than 10000 bits"),
    (lambda: superpack.density("C0", "2", digits=10**5000), "more than 10000 bits"),
    (lambda: superpack.density("C0", "\udcff"), "lone surrogate"),
    (lambda: superpack.report(p_values=["2,3"]), "separator ','"),
    (lambda: superpack.check_lattice("2", basis=[["2;0", 0, 0], [0, 2, 0], [0, 0, 2]]), "separator ';'"),
])
def test_bad_input_is_an_input_error_naming_it(call, message):
    with pytest.raises(superpack.InputError, match=message) as raised:
        call()
    assert "\n" not in str(raised.value)


def test_a_certificate_path_in_a_missing_directory_is_refused_before_any_work(tmp_path):
    with pytest.raises(superpack.InputError):
        superpack.density("C0", "2", certificate=tmp_path / "missing" / "c.json")
    assert not (tmp_path / "missing").exists()
