"""Enclosure: exact ends from the documents' texts, its arithmetic, and its outward conversions."""
import decimal
import math
from fractions import Fraction

import mpmath
import pytest
from mpmath.libmp import to_rational

from superpack import Enclosure
from superpack._exact import parse_exact


def test_dyadic_rational_and_decimal_texts_are_read_exactly():
    assert parse_exact("3*2^-3") == Fraction(3, 8)
    assert parse_exact("-3*2^1") == -6
    assert parse_exact("5") == 5
    assert parse_exact("0") == 0
    assert parse_exact("7/3") == Fraction(7, 3)
    assert parse_exact("6.0000000000000000e-01") == Fraction(3, 5)
    # Far beyond binary64's range both ways: a Fraction keeps every bit.
    assert parse_exact("1*2^-1100") == Fraction(1, 2**1100)
    assert parse_exact("3*2^2000") == 3 * 2**2000


def test_exact_ends_win_over_the_decimals():
    entry = {"lo": "3.3333333333333331e-01", "hi": "3.3333333333333338e-01",
             "lo_exact": "6004799503160661*2^-54", "hi_exact": "6004799503160662*2^-54"}
    x = Enclosure.from_json(entry)
    assert x.lo == Fraction(6004799503160661, 2**54)
    assert x.hi == Fraction(6004799503160662, 2**54)
    assert x.contains(Fraction(1, 3))
    assert x.mid == (x.lo + x.hi) / 2
    assert x.width == Fraction(1, 2**54)
    # The decimals enclose the exact ends: the command rounded them outward.
    assert parse_exact(entry["lo"]) <= x.lo and x.hi <= parse_exact(entry["hi"])
    assert x.to_dict() == entry


def test_contains_takes_exact_numbers_and_enclosures_only():
    x = Enclosure("1/2", "3/4")
    assert x.contains("0.5") and x.contains(Fraction(3, 4)) and x.contains(decimal.Decimal("0.6"))
    assert not x.contains(1) and not x.contains("0.4999999999999999999999")
    assert x.contains(Enclosure("0.6", "0.7")) and not x.contains(Enclosure("0.6", "0.8"))
    assert "5/8" in x
    with pytest.raises(ValueError, match="float"):
        x.contains(0.6)


def test_no_float_without_asking():
    x = Enclosure("1/3", "1/3")
    with pytest.raises(TypeError):
        x + 1
    assert float(x) == 1 / 3


def test_lo_above_hi_is_refused():
    with pytest.raises(ValueError, match="lo <= hi"):
        Enclosure("1", "1/2")


def test_unbounded_ends():
    x = Enclosure.from_json({"lo": "0", "hi": "inf", "lo_exact": "0", "hi_exact": "inf"})
    assert x.lo == 0 and x.hi == math.inf and not x.bounded
    assert x.mid is None and x.width == math.inf
    assert x.contains(10**400)
    with pytest.raises(ValueError, match="unbounded"):
        float(x)


def test_decimal_text_is_rounded_outward():
    x = Enclosure("1/3", "2/3")
    assert x.decimal(5) == "[3.3333e-1, 6.6667e-1]"
    assert Enclosure("-2/3", "-1/3").decimal(5) == "[-6.6667e-1, -3.3333e-1]"
    tiny = Enclosure(Fraction(1, 3 * 2**1074), Fraction(1, 2**1074))
    low, high = tiny.decimal(17)[1:-1].split(", ")
    assert Fraction(decimal.Decimal(low)) <= tiny.lo and tiny.hi <= Fraction(decimal.Decimal(high))
    assert repr(x) == "Enclosure([3.3333333333333333e-1, 6.6666666666666667e-1])"


@pytest.mark.parametrize("prec", [20, 53, 200])
def test_to_mpmath_rounds_outward(prec):
    x = Enclosure("1/3", "2/3")
    saved = mpmath.iv.prec
    try:
        mpmath.iv.prec = prec
        interval = x.to_mpmath()
        lo, hi = (Fraction(*to_rational(end)) for end in interval._mpi_)
    finally:
        mpmath.iv.prec = saved
    assert lo <= Fraction(1, 3) and Fraction(2, 3) <= hi
    assert hi - lo <= Fraction(1, 3) + Fraction(1, 2**(prec - 2))


def test_ends_longer_than_pythons_int_text_limit():
    # 10000 digits, as --digits 10000 prints: more than int() takes from a text.
    digits = "7" * 10000
    sevens = 7 * (10**10000 - 1) // 9
    assert parse_exact(digits + "*2^-3") == Fraction(sevens, 8)
    assert parse_exact("0." + digits) == Fraction(sevens, 10**10000)
    assert parse_exact("-" + digits + "/3") == -Fraction(sevens, 3)
    with pytest.raises(ValueError, match="not an exact number"):
        parse_exact("1.2.3")
