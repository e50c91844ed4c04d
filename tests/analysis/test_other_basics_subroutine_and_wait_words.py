"""Other BASICs' words for subroutines and waits are told Mint's, not another keyword spelt alike.

A subroutine is a label, ``#name``, ended by RETURN and called with GOSUB (000:1841-1850): ``CALL work``
is GOSUB's place (3007 offered GOSUB), ``SUB work`` has none (3007 told how), and ``END SUB`` is RETURN's
(a syntax error, 000:18920-18924, with that as a safe fix). A wait of a time is ``WAIT = <expression>``
in milliseconds (000:17324, 17343): DELAY was offered RELAY, an output.
"""

from __future__ import annotations

import mintlang
from tests.analysis.checking import apply

PROGRAM = "{line}\nEND\n#work\nRETURN\n"


def _first(line: str) -> tuple[str, mintlang.Diagnostic]:
    source = PROGRAM.format(line=line)
    return source, next(d for d in mintlang.check(source) if d.severity.value == "error")


def test_call_is_offered_gosub() -> None:
    source, diagnostic = _first("CALL work")
    assert diagnostic.code == "E3007"
    assert diagnostic.message.endswith("'CALL' is not a keyword (did you mean 'GOSUB'?)")
    assert apply(source, diagnostic.fixes[0].edits) == PROGRAM.format(line="GOSUB work")


def test_sub_is_told_how_a_subroutine_is_written() -> None:
    _, diagnostic = _first("SUB work")
    assert diagnostic.message.endswith(
        "'SUB' is not a keyword (a subroutine begins with its label, #name, ends with RETURN "
        "and is called by GOSUB name)"
    )


def test_end_sub_is_told_return() -> None:
    source = "GOSUB work\nEND\n#work\n  PRINT 1\nEND SUB\n"
    (diagnostic,) = [d for d in mintlang.check(source) if d.code == "E2003"]
    assert diagnostic.message == "Syntax error: a subroutine ends with RETURN, not END SUB"
    (fix,) = diagnostic.fixes
    assert fix.safe
    assert apply(source, fix.edits) == "GOSUB work\nEND\n#work\n  PRINT 1\nRETURN\n"


def test_delay_and_sleep_are_told_wait() -> None:
    for word in ("DELAY", "SLEEP"):
        _, diagnostic = _first(f"{word} 100")
        assert diagnostic.message.endswith(f"'{word}' is not a keyword (a wait of a time is WAIT = milliseconds)")
        assert diagnostic.fixes == ()
