"""Numbers read from text: the one decimal-string parser of the package.

A number is written in plain ASCII decimal notation, ``[+-]digits[.digits][e[+-]digits]``;
no underscores (``"1_0"``), no hexadecimal, no ``inf``/``nan``, no non-ASCII digits.  The
text is kept exactly (:class:`decimal.Decimal`) so that a caller can form differences such as
180° − A without rounding, and converted to a double or an mpmath number only at the end.

>>> decimal("179.9999999999", "--amplitude-deg")
Decimal('179.9999999999')
>>> to_float("1e-300", "--complement-rad")
1e-300
>>> to_float("1_0", "--l")
Traceback (most recent call last):
...
quasicentral.notation.numbers.NumberError: --l must be a decimal number, not '1_0'
"""

from __future__ import annotations

import math
import re
from decimal import Decimal

import mpmath

MAX_CHARS = 1000  # a number longer than this is refused (the digits of --dps are bounded too)
MAX_EXPONENT = 100_000  # |decimal exponent|: beyond this mpmath's conversion takes seconds
_DECIMAL = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")


class NumberError(ValueError):
    """Text that is not a finite decimal number; ``name`` is the option or key it was given to."""

    def __init__(self, message: str, name: str):
        super().__init__(message)
        self.name = name


def decimal(text, name: str) -> Decimal:
    """``text`` as an exact Decimal (a float is taken at its exact binary value; an int as is)."""
    if isinstance(text, bool):
        raise NumberError(f"{name} must be a number, not {text!r}", name)
    if isinstance(text, int):
        text = str(text)
    elif isinstance(text, float):
        if not math.isfinite(text):
            raise NumberError(f"{name} must be finite, not {text!r}", name)
        return Decimal(text)
    elif isinstance(text, Decimal):
        if not text.is_finite():
            raise NumberError(f"{name} must be finite, not {text}", name)
        return text
    if not isinstance(text, str):
        raise NumberError(f"{name} must be a number, not {type(text).__name__}", name)
    s = text.strip()
    if len(s) > MAX_CHARS:
        raise NumberError(f"{name} has more than {MAX_CHARS} characters", name)
    if not _DECIMAL.fullmatch(s):
        low = s.lower().lstrip("+-")
        if low in ("nan", "inf", "infinity"):
            raise NumberError(f"{name} must be finite, not {text!r}", name)
        raise NumberError(f"{name} must be a decimal number, not {text!r}", name)
    d = Decimal(s)
    if d and abs(d.adjusted()) > MAX_EXPONENT:
        raise NumberError(f"{name} has a decimal exponent beyond ±{MAX_EXPONENT}", name)
    return d


def to_float(text, name: str) -> float:
    """``text`` rounded once to the nearest double; an overflow is an error naming ``name``."""
    val = float(decimal(text, name))
    if not math.isfinite(val):
        shown = str(text) if len(str(text)) <= 40 else f"{str(text)[:20]}…({len(str(text))} characters)"
        raise NumberError(f"{name} is too large for double precision: {shown}", name)
    return val


def to_mpf(text, name: str):
    """``text`` as an mpmath number at the current working precision (rounded once)."""
    if isinstance(text, mpmath.mpf):
        if not mpmath.isfinite(text):
            raise NumberError(f"{name} must be finite, not {text}", name)
        return +text
    if isinstance(text, float):
        decimal(text, name)  # finite
        return mpmath.mpf(text)
    return mpmath.mpf(str(decimal(text, name)))


def digits(text) -> int:
    """The number of significant decimal digits written in ``text`` (at least 1)."""
    d = decimal(text, "number")
    return max(1, len(d.as_tuple().digits))
