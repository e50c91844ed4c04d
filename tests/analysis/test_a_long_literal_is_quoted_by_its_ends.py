"""A message quotes a long piece of source by its two ends and its length, not whole.

A literal of 400 nines is far past the largest Mint number (about 3.4e38, 000:714-716): error 3, "Data specified
out of range" (000:18518-18521). Its message named all 400 digits; a line holds at most 255 characters (000:18455),
so a message quoting a line's worth of digits is read by nobody. The code frame shows the place.
"""

from __future__ import annotations

import mintlang

NINES = "9" * 400


def test_a_literal_too_large_is_named_by_its_ends_and_length() -> None:
    (error,) = [d for d in mintlang.check(f"SPEED = {NINES}\n") if d.code == "E0003"]
    assert f"{'9' * 20}…{'9' * 20} (400 characters) is too large for a Mint number" in error.message


def test_an_operation_too_large_is_named_by_its_ends_and_length() -> None:
    # 16777215 multiplied by itself six times is about 2.2e43, past the largest number
    source = "PRINT " + " * ".join(["16777215"] * 6) + "\n"
    (error,) = [d for d in mintlang.check(source) if d.code == "E0003"]
    operation = " * ".join(["16777215"] * 6)
    assert f"{operation[:20]}…{operation[-20:]} ({len(operation)} characters) is too large" in error.message


def test_a_short_literal_is_named_whole() -> None:
    (error,) = [d for d in mintlang.check(f"SPEED = {'9' * 39}\n") if d.code == "E0003"]
    assert f"{'9' * 39} is too large for a Mint number" in error.message
