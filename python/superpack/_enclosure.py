"""Enclosure: a real number known to lie in [lo, hi], with exact ends."""
import decimal
import math

from ._exact import exact_text, exact_value, parse_exact

_INFINITE = {"inf": math.inf, "-inf": -math.inf}


def _end(text):
    return _INFINITE[text] if text in _INFINITE else parse_exact(text)


def _decimal(value, digits, up):
    """`value` (a Fraction) as a decimal of `digits` significant digits, rounded down or up."""
    if value == 0:
        return "0"
    context = decimal.Context(prec=digits, rounding=decimal.ROUND_CEILING if up else decimal.ROUND_FLOOR)
    quotient = context.divide(decimal.Decimal(value.numerator), decimal.Decimal(value.denominator))
    return f"{quotient:.{digits - 1}e}"


class Enclosure:
    """A real number x known to lie in [lo, hi].

    `lo` and `hi` are exact Fractions: the interval's own ends, as the certificate writes them
    (an unbounded side is -math.inf or math.inf). Nothing converts an enclosure to a float on
    its own: call float(e) for the midpoint rounded to nearest, or to_mpmath() for an mpmath
    interval rounded outward."""

    __slots__ = ("_lo", "_hi", "_source")

    def __init__(self, lo, hi, source=None):
        self._lo = lo if isinstance(lo, float) and math.isinf(lo) else exact_value(lo, "lo")
        self._hi = hi if isinstance(hi, float) and math.isinf(hi) else exact_value(hi, "hi")
        if not self._lo <= self._hi:
            raise ValueError(f"an enclosure needs lo <= hi, got [{self._lo}, {self._hi}]")
        self._source = source

    @classmethod
    def from_json(cls, entry):
        """From a document's {"lo", "hi"} (exact rationals or outward decimals) or
        {"lo", "hi", "lo_exact", "hi_exact"} (decimals and the exact ends)."""
        lo = entry.get("lo_exact", entry["lo"])
        hi = entry.get("hi_exact", entry["hi"])
        return cls(_end(lo), _end(hi), source=entry)

    @property
    def lo(self):
        return self._lo

    @property
    def hi(self):
        return self._hi

    @property
    def bounded(self):
        return not (isinstance(self._lo, float) or isinstance(self._hi, float))

    @property
    def mid(self):
        """(lo + hi) / 2, exactly; None when unbounded."""
        return (self._lo + self._hi) / 2 if self.bounded else None

    @property
    def width(self):
        """hi - lo, exactly (math.inf when unbounded)."""
        return self._hi - self._lo if self.bounded else math.inf

    def contains(self, x):
        """Whether x (an exact number, or an Enclosure: all of it) lies in [lo, hi]."""
        if isinstance(x, Enclosure):
            return self._lo <= x._lo and x._hi <= self._hi
        value = exact_value(x, "x")
        return self._lo <= value <= self._hi

    def __contains__(self, x):
        return self.contains(x)

    def __float__(self):
        if not self.bounded:
            raise ValueError("float() of an unbounded enclosure")
        return float(self.mid)

    def to_mpmath(self):
        """An mpmath interval (mpmath.iv) at mpmath.iv.prec that contains [lo, hi]."""
        import mpmath
        from mpmath.libmp import from_rational, round_ceiling, round_floor

        prec = mpmath.iv.prec

        def end(value, rounding):
            if isinstance(value, float):
                return mpmath.mpf(value)._mpf_
            return from_rational(value.numerator, value.denominator, prec, rounding)

        return mpmath.iv.make_mpf((end(self._lo, round_floor), end(self._hi, round_ceiling)))

    def decimal(self, digits=17):
        """"[lo, hi]" with `digits` significant digits, lo rounded down and hi up."""
        def text(value, up):
            if isinstance(value, float):
                return "inf" if value > 0 else "-inf"
            return _decimal(value, digits, up)
        return f"[{text(self._lo, False)}, {text(self._hi, True)}]"

    def to_dict(self):
        """The document's entry this came from, or the exact ends as "n/d" texts."""
        if self._source is not None:
            return dict(self._source)
        return {"lo": exact_text(self._lo, "lo") if self.bounded else str(self._lo),
                "hi": exact_text(self._hi, "hi") if self.bounded else str(self._hi)}

    def __eq__(self, other):
        if not isinstance(other, Enclosure):
            return NotImplemented
        return self._lo == other._lo and self._hi == other._hi

    def __hash__(self):
        return hash((self._lo, self._hi))

    def __repr__(self):
        return f"Enclosure({self.decimal()})"
