"""A name at the start of a line followed by a colon, as other BASICs write a label, is told Mint's ``#``.

A Mint label is prefixed with a hash, placed as the first thing on its line but for spaces
(000:1843-1844, 1871-1872; 000:5732); ``Init:`` is the name ``Init`` alone as a
statement, then a statement separator, so the controller reports keyword not defined (3007,
000:19111-19116). The message says how the label is written. The fix writes the hash: safe when nothing
but a comment follows the colon (the line can mean nothing else), unsafe when statements follow it.
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang.diagnostics import Diagnostic
from mintlang.fixes import fix_text

_LABEL = "Keyword not defined: 'Init' is not a keyword (a label is written #Init, first on its line)"


def _not_defined(source: str, dialect: str = "v4") -> list[Diagnostic]:
    return [d for d in mintlang.check_application(source, dialect=dialect).program if d.code == "E3007"]


def _fixed(source: str, diagnostic: Diagnostic) -> str:
    (fix,) = diagnostic.fixes
    (edit,) = fix.edits
    return source[: edit.span.start] + edit.text + source[edit.span.end :]


@pytest.mark.parametrize("dialect", ["v4", "mintmt"])
def test_a_label_alone_on_its_line_is_told_the_hash_with_a_safe_fix(dialect: str) -> None:
    source = "GOSUB Init\nEND\n  Init:\nPRINT 1\nRETURN\n"
    (found,) = _not_defined(source, dialect)
    assert found.message == _LABEL
    assert found.fixes[0].safe
    assert _fixed(source, found) == "GOSUB Init\nEND\n  #Init\nPRINT 1\nRETURN\n"


def test_a_label_followed_by_a_comment_is_fixed_safely() -> None:
    source = "GOSUB Init\nEND\nInit: REM set up\nRETURN\n"
    (found,) = _not_defined(source)
    assert found.message == _LABEL
    assert found.fixes[0].safe
    assert _fixed(source, found) == "GOSUB Init\nEND\n#Init REM set up\nRETURN\n"


def test_a_label_followed_by_statements_is_fixed_only_as_an_unsafe_fix() -> None:
    source = "GOSUB Init\nEND\nInit: PRINT 1\nRETURN\n"
    (found,) = _not_defined(source)
    assert found.message == _LABEL
    assert not found.fixes[0].safe
    assert _fixed(source, found) == "GOSUB Init\nEND\n#Init: PRINT 1\nRETURN\n"


def test_a_statement_whose_name_begins_with_rem_is_no_comment() -> None:
    # REM comments only as a word of its own: 'remainder' is a variable (000:884-893), so a statement follows
    source = "DIM remainder\nGOSUB Init\nEND\nInit: remainder = 5\nRETURN\n"
    (found,) = _not_defined(source)
    assert not found.fixes[0].safe
    assert _fixed(source, found) == "DIM remainder\nGOSUB Init\nEND\n#Init: remainder = 5\nRETURN\n"


def test_a_name_alone_after_another_statement_is_no_label() -> None:
    (found,) = _not_defined("DIM a\na = 1 : Init : a = 2\n")
    assert "label" not in found.message


def test_every_fix_made_writes_the_label_once() -> None:
    # the jump's 3004 took 'Create label #Init' at the end of the file, a second #Init once the hash was written
    source = "Init: PRINT 1\nGOTO Init\n"
    fixed = fix_text(source, lambda text: mintlang.check_application(text).program, unsafe=True)
    assert fixed.text == "#Init: PRINT 1\nGOTO Init\n"
    assert not fixed.remaining
