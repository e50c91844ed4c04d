"""A block ``IF … DO`` followed on its line by ``:`` and a comment only becomes ``If … Then`` and the
comment: MintMT's ``Then`` opens a block when nothing but a comment follows it (``If a > 0 Then ' c``
checks clean as MintMT), so the ``:`` goes rather than the ``DO`` being kept and flagged."""

from __future__ import annotations

import mintlang
from mintlang.migrate.mintmt import to_mintmt


def test_the_colon_before_a_comment_goes_and_the_do_becomes_then() -> None:
    result = to_mintmt("DIM a\nIF a > 0 DO : REM c\n  a = 1\nENDIF\n")
    assert result.text == "DIM a\nIF a > 0 THEN ' c\n  a = 1\nEND IF\n"
    assert not result.manual


def test_a_colon_touching_the_do_leaves_a_space_before_the_comment() -> None:
    assert to_mintmt("DIM a\nif a > 0 do: rem c\nendif\n").text == "DIM a\nif a > 0 then ' c\nend if\n"


def test_the_result_checks_clean_as_mintmt() -> None:
    result = to_mintmt("DIM a\nIF a > 0 DO : REM c\n  a = 1\nENDIF\n")
    assert mintlang.check(result.text, dialect="mintmt") == []


def test_a_statement_after_the_colon_still_keeps_the_do_and_is_flagged() -> None:
    result = to_mintmt("DIM a\nIF a > 0 DO : a = 1 : REM c\nENDIF\n")
    assert "IF a > 0 DO : a = 1 : ' c" in result.text
    assert [item.rule for item in result.manual] == ["MT-BLOCK"]
