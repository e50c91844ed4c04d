"""How ``PRINT`` renders numbers (spec PR-1..PR-3).

The controller truncates rather than rounds: ``ATAN 0.1`` (5.71059…) prints
``5.7105`` and ``1.005103 USING 1,6`` prints ``1.005102`` because the stored
binary32 value is 1.00510299…. So every format here takes the exact decimal
expansion of the float and cuts it, using integer arithmetic on
``float.as_integer_ratio`` (exact, and free of decimal-context limits).
"""

from __future__ import annotations

from mintlang.runtime.numbers import bits24

DEFAULT_PLACES = 4
MAX_USING_DIGITS = 15


def truncated(value: float, places: int) -> tuple[bool, int, int]:
    """(negative, whole part, fraction digits as an integer) of ``value`` cut toward zero to ``places``."""
    numerator, denominator = value.as_integer_ratio()
    scale = 10**places
    whole, fraction = divmod(abs(numerator) * scale // denominator, scale)
    return numerator < 0 and (whole > 0 or fraction > 0), whole, fraction


def format_number(value: float, places: int = DEFAULT_PLACES) -> str:
    """``PRINT x``: 4 places (v3's 3), truncated, trailing zeros and a bare point dropped (PR-1 RC); never
    prints ``-0``."""
    if value.is_integer():
        return str(int(value))
    negative, whole, fraction = truncated(value, places)
    digits = f"{fraction:0{places}d}".rstrip("0")
    text = f"{whole}.{digits}" if digits else str(whole)
    return "-" + text if negative else text


def format_using(value: float, integer_digits: int, fraction_digits: int | None) -> str:
    """``PRINT x USING int{,frac}`` (PR-2): zero-padded to ``|int|`` digits, signed only when ``int`` is negative.

    Digit counts are clamped to 0..15, the manual's maximum. A positive ``int``
    prints the magnitude without any sign, as the manual states; the integer
    part widens when it needs more digits; the fraction is truncated, never rounded.
    """
    width = min(abs(integer_digits), MAX_USING_DIGITS)
    places = min(max(fraction_digits or 0, 0), MAX_USING_DIGITS)
    negative, whole, fraction = truncated(value, places)
    text = f"{whole:0{width}d}"
    if places:
        text += f".{fraction:0{places}d}"
    if integer_digits < 0:
        return ("-" if negative else "+") + text
    return text


def format_hex(value: float) -> str:
    """``PRINT HEX x``: upper case, no ``0x``, negatives as 24-bit two's complement (PR-3 RC)."""
    return f"{bits24(value):X}"


def format_bin(value: float) -> str:
    """``PRINT BIN x``: binary digits without leading zeros, negatives as 24-bit two's complement (PR-3 RC)."""
    return f"{bits24(value):b}"


def format_chr(value: float) -> str:
    """``PRINT CHR(n)``: the one byte ``n`` (low 8 bits), as the Latin-1 character of that code."""
    return chr(bits24(value) & 0xFF)
