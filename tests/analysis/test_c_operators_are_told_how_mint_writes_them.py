"""C's comparison and logical operators are syntax errors (2003) told Mint's operator instead.

Mint compares with one ``=`` and writes "not equal to" as ``<>`` (000:1256-1263); ``!`` is its logical NOT
(000:1419), so ``!=`` is no operator. Its AND and OR are ``AND``/``&`` and ``OR``/``|``, which work bit by bit
(000:1286-1289, 1306-1307): ``&&`` and ``||`` are two of them in a row. A statement the controller cannot read
is a syntax error (000:18920-18924).

``!=`` and ``==`` have one meaning in Mint, so their fix is safe; AND on values other than 0 and 1 is not
C's ``&&`` (5 & 6 is 4, 000:1309-1311), so that fix is offered as unsafe.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.fixes import fix_text
from tests.analysis.checking import apply, covered

DECLARED = "DIM a = 1\nDIM b = 2\n"


def _only(line: str) -> tuple[str, mintlang.Diagnostic]:
    source = DECLARED + line + "\n"
    (diagnostic,) = [d for d in mintlang.check(source) if d.code == "E2003"]
    return source, diagnostic


@pytest.mark.parametrize(
    ("line", "written", "message", "fixed", "safe"),
    [
        pytest.param(
            "IF a != 2 THEN PRINT a", "!=", "Mint writes 'not equal to' as <>", "IF a <> 2 THEN PRINT a", True, id="!="
        ),
        pytest.param(
            "IF a == 2 THEN PRINT a", "==", "Mint compares with one '='", "IF a = 2 THEN PRINT a", True, id="=="
        ),
        pytest.param(
            "IF a = 1 && b = 2 THEN PRINT a",
            "&&",
            "Mint has no '&&': write AND, which works bit by bit",
            "IF a = 1 AND b = 2 THEN PRINT a",
            False,
            id="&&",
        ),
        pytest.param(
            "IF a = 1 || b = 2 THEN PRINT a",
            "||",
            "Mint has no '||': write OR, which works bit by bit",
            "IF a = 1 OR b = 2 THEN PRINT a",
            False,
            id="||",
        ),
    ],
)
def test_the_operator_is_a_syntax_error_told_mints(
    line: str, written: str, message: str, fixed: str, safe: bool
) -> None:
    source, diagnostic = _only(line)
    assert diagnostic.code == "E2003"
    assert covered(source, diagnostic) == written
    assert diagnostic.message == f"Syntax error: {message}"
    (fix,) = diagnostic.fixes
    assert fix.safe is safe
    assert apply(source, fix.edits) == DECLARED + fixed + "\n"


def test_an_operator_in_an_assignment_is_told_too() -> None:
    source, diagnostic = _only("b = a == 1")
    assert diagnostic.message == "Syntax error: Mint compares with one '='"
    assert apply(source, diagnostic.fixes[0].edits) == DECLARED + "b = a = 1\n"


def test_and_written_between_tokens_is_kept_apart_from_them() -> None:
    source, diagnostic = _only("IF a=1&&b=2 THEN PRINT a")
    assert apply(source, diagnostic.fixes[0].edits) == DECLARED + "IF a=1 AND b=2 THEN PRINT a\n"


@pytest.mark.parametrize(
    ("line", "fixed"),
    [
        ("IF a != 1 OR b != 2 THEN PRINT a", "IF a <> 1 OR b <> 2 THEN PRINT a"),
        ("IF a == 1 OR b == 2 THEN PRINT a", "IF a = 1 OR b = 2 THEN PRINT a"),
        ("IF a = 1 && b = 2 && a = b THEN PRINT a", "IF a = 1 AND b = 2 AND a = b THEN PRINT a"),
    ],
)
def test_an_operator_written_twice_in_a_statement_is_fixed_at_once(line: str, fixed: str) -> None:
    # one at a time, the second was the same finding again, which --fix took for a fix that failed: it fixed nothing
    source = DECLARED + line + "\n"
    assert fix_text(source, mintlang.check, unsafe=True).text == DECLARED + fixed + "\n"


def test_two_signs_apart_are_not_taken_for_one_operator() -> None:
    _, diagnostic = _only("IF a = = 2 THEN PRINT a")
    assert "compares with one" not in diagnostic.message
