"""Exact numbers in and out: what the commands accept for p and a basis, and the texts their JSON
documents use for exact values ("m*2^e" dyadics, "n/d" rationals, decimals)."""
import decimal
import fractions
import numbers
import re

from ._errors import InputError

_DYADIC = re.compile(r"^(-?\d+)\*2\^(-?\d+)$")


def exact_text(value, name):
    """The command-line text of an exact number: a str is passed on as typed (the command parses
    it and names what is wrong); an int, Fraction or Decimal is written exactly; a float is
    refused, because 0.6 as a float is not 3/5."""
    if isinstance(value, bool):
        raise InputError(f"{name}: a bool is not a number")
    if isinstance(value, str):
        return value
    if isinstance(value, int):
        return integer_text(value, name)
    if isinstance(value, fractions.Fraction):
        numerator = integer_text(value.numerator, name)
        return numerator if value.denominator == 1 else f"{numerator}/{integer_text(value.denominator, name)}"
    if isinstance(value, decimal.Decimal):
        if not value.is_finite():
            raise InputError(f"{name}: {value} is not a finite number")
        return exact_text(fractions.Fraction(value), name)
    if isinstance(value, float):
        raise InputError(f"{name}: a float is not exact ({value!r} is {fractions.Fraction(value)}); "
                         f"pass a str such as '{value!r}', an int, a Fraction or a Decimal")
    if isinstance(value, numbers.Rational):
        return exact_text(fractions.Fraction(value.numerator, value.denominator), name)
    raise InputError(f"{name}: expected a str, int, Fraction or Decimal, got {type(value).__name__}")


def exact_value(value, name):
    """An exact number (str, int, Fraction or Decimal) as a Fraction; a float is refused as in exact_text."""
    if isinstance(value, fractions.Fraction):
        return value
    if isinstance(value, str):
        return parse_exact(value)
    return fractions.Fraction(exact_text(value, name))


def integer_text(value, name):
    """The decimal text of an int. Far beyond what a command takes (100 characters), and beyond
    what str() writes (ValueError above 4300 digits), a number is refused by its size."""
    if value.bit_length() > 10000:
        raise InputError(f"{name}: a number of more than 10000 bits")
    return str(value)


def whole_number(value, name):
    """An int option (digits, seed, counts) as its text; a bool or float is refused."""
    if isinstance(value, bool) or not isinstance(value, int):
        raise InputError(f"{name}: expected an int, got {type(value).__name__}")
    return integer_text(value, name)


_RATIONAL = re.compile(r"^(-?\d+)/(\d+)$")
_DECIMAL = re.compile(r"^([+-]?)(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?$")
# Python refuses int() of a text of more than 4300 digits (sys.get_int_max_str_digits); an end at
# --digits 10000 has more, so long texts are read in pieces.
_PIECE = 4000


def _integer(text):
    sign, digits = (-1, text[1:]) if text.startswith("-") else (1, text.lstrip("+"))
    value = 0
    for start in range(0, len(digits), _PIECE):
        piece = digits[start:start + _PIECE]
        value = value * 10**len(piece) + int(piece)
    return sign * value


def parse_exact(text):
    """A Fraction from an exact text of a JSON document: "m*2^e", "n/d" or a decimal such as
    "6.0000000000000000e-01" (a decimal end is already rounded outward by the command)."""
    match = _DYADIC.match(text)
    if match:
        mantissa, exponent = _integer(match.group(1)), int(match.group(2))
        return fractions.Fraction(mantissa * 2**exponent) if exponent >= 0 else fractions.Fraction(mantissa, 2**-exponent)
    match = _RATIONAL.match(text)
    if match:
        return fractions.Fraction(_integer(match.group(1)), _integer(match.group(2)))
    match = _DECIMAL.match(text)
    if match and (match.group(2) or match.group(3)):
        sign, whole, fraction, exponent = match.group(1), match.group(2), match.group(3) or "", int(match.group(4) or 0)
        mantissa = _integer(sign + (whole + fraction or "0"))
        exponent -= len(fraction)
        return fractions.Fraction(mantissa * 10**exponent) if exponent >= 0 else fractions.Fraction(mantissa, 10**-exponent)
    raise ValueError(f"not an exact number: {text[:40]!r}")
