"""``count += 1``, C's compound assignment, is a syntax error (2003) told how Mint writes it.

Mint assigns with ``=`` alone (000:1418-1429, the precedence table) and its arithmetic is ``+ - * /`` and MOD
(000:1274-1282): there is no ``+=``. A statement the controller cannot read is a syntax error
(000:18920-18924); 3007 (000:19111) is for a command it does not know, and ``count`` is a declared variable.
The fix writes what the statement plainly meant: the target and the operator spelt out, a right-hand side
of more than one token in brackets, as ``*`` binds tighter than ``+`` (000:1418-1429).
"""

from __future__ import annotations

import mintlang
from tests.analysis.checking import apply, covered

DECLARED = "DIM count\ncount = 0\n"


def _only(line: str) -> tuple[str, mintlang.Diagnostic]:
    source = DECLARED + line + "\n"
    (diagnostic,) = mintlang.check(source)
    return source, diagnostic


def test_plus_equals_is_a_syntax_error_at_the_operator() -> None:
    source, diagnostic = _only("count += 1")
    assert diagnostic.code == "E2003"
    assert covered(source, diagnostic) == "+="


def test_the_message_says_how_mint_writes_it() -> None:
    _, diagnostic = _only("count += 1")
    assert diagnostic.message.endswith("Mint has no '+=': write count = count + 1")


def test_the_safe_fix_writes_the_assignment_out() -> None:
    source, diagnostic = _only("count += 1")
    (fix,) = diagnostic.fixes
    assert fix.safe
    assert apply(source, fix.edits) == DECLARED + "count = count + 1\n"


def test_each_operator_is_written_out() -> None:
    for operator in "-*/":
        _, diagnostic = _only(f"count {operator}= 2")
        assert diagnostic.message.endswith(f"Mint has no '{operator}=': write count = count {operator} 2")


def test_an_expression_on_the_right_is_bracketed() -> None:
    source, diagnostic = _only("count *= count + 1")
    assert diagnostic.message.endswith("write count = count * (count + 1)")
    assert apply(source, diagnostic.fixes[0].edits) == DECLARED + "count = count * (count + 1)\n"


def test_an_array_element_and_a_keyword_are_targets_too() -> None:
    source = "DIM a(3)\na(2) -= 1\nSPEED.0 += 10\n"
    first, second = mintlang.check(source)
    assert (first.code, second.code) == ("E2003", "E2003")
    assert first.message.endswith("write a(2) = a(2) - 1")
    assert second.message.endswith("write SPEED.0 = SPEED.0 + 10")
    assert apply(source, [*first.fixes[0].edits, *second.fixes[0].edits]) == (
        "DIM a(3)\na(2) = a(2) - 1\nSPEED.0 = SPEED.0 + 10\n"
    )


def test_an_operator_apart_from_the_equals_sign_is_not_told_so() -> None:
    _, diagnostic = _only("count + = 1")
    assert "Mint has no" not in diagnostic.message


def test_an_increment_is_told_the_assignment_too() -> None:
    source, diagnostic = _only("count++")
    assert (diagnostic.code, covered(source, diagnostic)) == ("E2003", "++")
    assert diagnostic.message.endswith("Mint has no '++': write count = count + 1")
    assert apply(source, diagnostic.fixes[0].edits) == DECLARED + "count = count + 1\n"
    _, diagnostic = _only("count--")
    assert diagnostic.message.endswith("Mint has no '--': write count = count - 1")


def test_an_array_element_is_incremented_too() -> None:
    source = "DIM a(3)\na(1)++\n"
    (diagnostic,) = mintlang.check(source)
    assert diagnostic.message.endswith("Mint has no '++': write a(1) = a(1) + 1")


def test_a_command_and_its_operand_are_no_target() -> None:
    for line in ("PRINT count += 1", "PRINT count++"):
        _, diagnostic = _only(line)
        assert "Mint has no" not in diagnostic.message
