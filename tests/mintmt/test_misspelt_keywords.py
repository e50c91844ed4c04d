"""A misspelt MintMT keyword is offered the keyword it resembles, as a misspelt v4 one is.

The move buffer note writes ``TRIGGERMODE(0) = 0`` (004:59), ``OUTX(0) = _ON`` (004:148) and
``MOVEBUFFERSIZE(0) = 2`` (004:70), each a keyword holding a value; the v4 guide lists MOVEBUFFERSIZE
without an attributes table. A name one slip from such a keyword, used as a variable, is error 3001
with "did you mean" and the rename. The words only MintMT has are offered in MintMT only.
"""

from __future__ import annotations

import pytest

import mintlang


def _undeclared(source: str, dialect: str) -> mintlang.Diagnostic:
    (diagnostic,) = [d for d in mintlang.check(source, dialect=dialect) if d.code == "E3001"]
    return diagnostic


@pytest.mark.parametrize(
    ("source", "meant"),
    [
        pytest.param("TRIGERMODE(0) = 0\n", "TRIGGERMODE", id="triggermode"),
        pytest.param("OUTXX(0) = 1\n", "OUTX", id="outx"),
        pytest.param("MOVEBUFERSIZE(0) = 2\n", "MOVEBUFFERSIZE", id="movebuffersize"),
        # read, as the note reads it (004:151): it is read only, and a name given a value is offered no such keyword
        pytest.param("PRINT MOVEBUFFERIDLST(0)\n", "MOVEBUFFERIDLAST", id="movebufferidlast"),
    ],
)
def test_a_name_one_slip_from_a_keyword_is_offered_it(source: str, meant: str) -> None:
    diagnostic = _undeclared(source, "mintmt")
    assert diagnostic.message.endswith(f"did you mean the keyword '{meant}'?")
    assert diagnostic.fixes[0].title == f"Replace with {meant}"


def test_a_keyword_only_mintmt_has_is_not_offered_in_v4() -> None:
    assert "did you mean" not in _undeclared("TRIGERMODE = 0\n", "v4").message


def test_a_misspelt_keyword_written_as_a_command_is_offered_the_mintmt_keyword() -> None:
    """``MOVEOUT(axis, bank) = value`` (004:293-297) written with one slip does not parse as a
    statement: error 3007 at the word, with the MintMT keyword it resembles."""
    (diagnostic,) = mintlang.check("MOVEOUTT(0,0) = 1\n", dialect="mintmt")
    assert diagnostic.code == "E3007"
    assert "did you mean 'MOVEOUT'?" in diagnostic.message
