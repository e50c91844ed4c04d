"""``IF A NOT = B``, the guide's own invalid example, is a syntax error (2003) told Mint's ``<>``.

The NOT entry shows ``IF A NOT = B THEN`` as not valid and ``IF A <> B THEN`` as what to write instead
(000:14724-14729); ``<>`` is "not equal to" (000:1262). A statement the controller cannot read is a syntax
error (000:18920-18924). The two mean one thing, so the fix is safe.
"""

from __future__ import annotations

import pytest

import mintlang
from tests.analysis.checking import apply, covered

DECLARED = "DIM A = 1\nDIM B = 2\n"


@pytest.mark.parametrize(
    ("line", "fixed"),
    [
        ("IF A NOT = B THEN PRINT A", "IF A <> B THEN PRINT A"),
        ("PAUSE A not = B", "PAUSE A <> B"),
        ("WHILE A NOT=B\nA = B\nENDW", "WHILE A <>B\nA = B\nENDW"),
    ],
)
def test_not_before_equals_is_told_to_write_not_equal(line: str, fixed: str) -> None:
    source = DECLARED + line + "\n"
    (diagnostic,) = mintlang.check(source)
    assert diagnostic.code == "E2003"
    assert covered(source, diagnostic).upper().replace(" ", "") == "NOT="
    assert diagnostic.message == "Syntax error: Mint writes 'not equal to' as <>, with no NOT before the '='"
    (fix,) = diagnostic.fixes
    assert fix.safe
    assert apply(source, fix.edits) == DECLARED + fixed + "\n"


def test_not_before_a_value_stays_mints_logical_not() -> None:
    assert mintlang.check(DECLARED + "IF A = NOT B THEN PRINT A\n") == []
