"""A comma left at the end of a DIM list's last line takes the next line into the list, and the finding says so.

The last value on each line of a DIM list that goes on is followed by a comma, which tells the
compiler that more values follow on the next line (000:1093-1095); the values are numbers, not
expressions (000:9167-9171). So a comma left after the list's real last value makes the next
statement part of the list, and what is reported there (a keyword that is no variable, a value
that is no number) is explained by that comma, which the finding names.
"""

from __future__ import annotations

import pytest

import mintlang

NOTE = "the line before ends DIM's values with a comma, so this line is read as more of them"


@pytest.mark.parametrize(
    ("after", "code"),
    [
        pytest.param("PRINT t(1)", "E2006", id="a-statement-keyword"),
        pytest.param("GOSUB start", "E2006", id="a-jump"),
        pytest.param("SPEED = 5", "E2003", id="an-assignment-read-as-a-value"),
    ],
)
def test_the_finding_on_the_next_line_names_the_comma(after: str, code: str) -> None:
    source = f"DIM t(3) = 1, 2,\n{after}\n"
    findings = [finding for finding in mintlang.check(source) if finding.code.startswith("E")]
    first = findings[0]
    assert (first.code, mintlang.LineIndex(source).position(first.span.start).line) == (code, 2)
    assert first.message.endswith(f"({NOTE})")


def test_a_finding_on_the_dims_own_line_has_no_note() -> None:
    [finding] = mintlang.check("DIM t(3) = 1, PRINT\n")
    assert NOTE not in finding.message


def test_a_list_that_ends_where_it_should_has_nothing_to_say() -> None:
    assert mintlang.check("DIM t(3) = 1, 2,\n3\nPRINT t(1)\n") == []
