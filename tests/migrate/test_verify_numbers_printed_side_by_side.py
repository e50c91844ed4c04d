"""``verify``: numbers printed side by side are compared digit for digit, not as one number.

``PRINT a, b`` prints b "directly after" a (001:10980), so ``PRINT a, b, c`` with 3000, 3000 and 66000
prints the run of digits 3000300066000. No v3 number is that large: v3 holds ±8388607.996 (001:1157),
so such a run is several numbers, and the allowance for one number printed to three places in 256ths
(v3) or four places in binary32 (v4), 2^-23 of its size, would let 357,000 of difference pass here:
67000 in place of 66000 is a difference the run must report.
"""

from __future__ import annotations

from dataclasses import replace

from mintlang.migrate import migrate
from mintlang.migrate.verification import Verdict, verify

PROGRAM = "a = 3000 : b = 3000 : c = 66000\nPRINT a, b, c\n"


def test_a_number_changed_among_numbers_printed_side_by_side_diverges() -> None:
    result = migrate(PROGRAM)
    altered = replace(result, text=result.text.replace("c = 66000", "c = 67000"))
    assert verify(altered, until_ms=100).verdict is Verdict.DIVERGES


def test_the_same_numbers_side_by_side_are_equivalent() -> None:
    assert verify(migrate(PROGRAM), until_ms=100).verdict is Verdict.EQUIVALENT
