"""--verify: a number printed with another count of leading zeros is printed text that differs.

v3 BINARY prints up to 8 digits, zero padded (001:6209-6236: 12 prints 00001100); v4 PRINT BIN prints the digits
alone (000:764-767: PRINT BIN 27 prints 11011), which S-BINARY flags. The comparison read both as numbers,
equal in value, and called the runs equivalent; zeros before the digits are layout, not value.
"""

from __future__ import annotations

from mintlang.migrate import migrate
from mintlang.migrate.verification import Verdict, verify


def test_binary_padding_lost_under_print_bin_is_a_divergence() -> None:
    found = verify(migrate('BINARY "bits ", 51\nWAIT = 50\nPRINT "done"\n'), until_ms=100)
    assert found.verdict is Verdict.DIVERGES
    assert found.divergence is not None
    assert (found.divergence.what, found.divergence.v3, found.divergence.v4) == (
        "terminal",
        "'00110011'",
        "'110011'",
    )


def test_numbers_printed_alike_but_for_decimals_still_compare_by_value() -> None:
    # v3 prints three decimals, v4 four (X-PRINT): 12.855 and 12.8571 are one value
    assert verify(migrate("a = 90 / 7\nPRINT a\n"), until_ms=100).verdict is Verdict.EQUIVALENT
