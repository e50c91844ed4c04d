"""The fixes the checker offers with its diagnostics, one table per fix: what each does to a program,
and that the fixed program no longer has the diagnostic (nor any new error).

Programs follow the Mint v4 programming guide (/work/shared/seeds/000_f3c82d19754128dd.txt).
"""

from __future__ import annotations

import pytest

import mintlang


def fixed(source: str, code: str, title: str) -> str:
    """``source`` with the fix called ``title`` of its first ``code`` diagnostic applied."""
    diagnostic = next(d for d in mintlang.check(source) if d.code == code)
    (fix,) = [fix for fix in diagnostic.fixes if fix.title == title]
    for edit in sorted(fix.edits, key=lambda e: e.span.start, reverse=True):
        source = source[: edit.span.start] + edit.text + source[edit.span.end :]
    return source


def errors(source: str) -> list[str]:
    return [d.code for d in mintlang.check(source) if d.severity.value == "error"]


# W106: code after END, RETURN, GOTO or EXIT that nothing reaches (GOTO entry, line 11194).
UNREACHABLE = [
    pytest.param(
        "GOTO label1\nPRINT 1\nPRINT 2\n#label1\nEND\n", "GOTO label1\n#label1\nEND\n", id="lines-up-to-a-label"
    ),
    pytest.param("PRINT 1\nEND : PRINT 2\n", "PRINT 1\nEND\n", id="after-a-colon"),
    pytest.param("END : PRINT 2 : REM kept\n", "END : REM kept\n", id="a-comment-stays"),
    pytest.param(  # a REM may follow a statement without a colon (000:15509-15515)
        "END\r\nPRINT 2 REM kept\r\n", "END\r\nREM kept\r\n", id="a-comment-without-a-colon-stays-on-its-line"
    ),
    pytest.param(
        "DIM a\nIF a DO\n  RETURN\n  PRINT 1\nELSE\n  PRINT 2\nENDIF\nEND\n",
        "DIM a\nIF a DO\n  RETURN\nELSE\n  PRINT 2\nENDIF\nEND\n",
        id="up-to-the-else-of-a-block-opened-before",
    ),
    pytest.param(
        "DIM i\nGOTO done\nFOR i = 1 TO 3\n  PRINT i\nNEXT\n#done\nEND\n",
        "DIM i\nGOTO done\n#done\nEND\n",
        id="a-loop-opened-in-the-run-goes-whole",
    ),
    pytest.param(
        "DIM a\nLOOP\n  IF a DO\n    EXIT\n    a = 2 : PRINT 3\n  ENDIF\nENDL\nEND\n",
        "DIM a\nLOOP\n  IF a DO\n    EXIT\n  ENDIF\nENDL\nEND\n",
        id="inside-blocks",
    ),
    pytest.param("GOTO done\r\nPRINT 1\r\n#done\r\nEND\r\n", "GOTO done\r\n#done\r\nEND\r\n", id="crlf"),
]


@pytest.mark.parametrize(("source", "expected"), UNREACHABLE)
def test_remove_unreachable_code(source: str, expected: str) -> None:
    assert fixed(source, "W106", "Remove unreachable code") == expected
    assert "W106" not in [d.code for d in mintlang.check(expected)]
    assert errors(expected) == errors(source)


def test_no_removal_when_a_label_stands_inside_a_block_of_the_run() -> None:
    # removing LOOP would leave its ENDL behind the label a GOTO may still reach
    source = "END\nLOOP\n  PRINT 1\n#again\nENDL\n"
    (dead,) = [d for d in mintlang.check(source) if d.code == "W106"]
    assert dead.fixes == ()


# E3001 on a name written with an index: an array, whose DIM reserves its elements (3.3, 000:1075-1080:
# DIM my_array(10) before my_array(4) is used), as many as the largest index written.
UNDECLARED_ARRAYS = [
    pytest.param("my_var(10) = 100.5\n", "DIM my_var(10)\nmy_var(10) = 100.5\n", id="its-index"),
    pytest.param(
        "DIM a\nmy_var(3) = 1\na = my_var(10)\n",
        "DIM a\nDIM my_var(10)\nmy_var(3) = 1\na = my_var(10)\n",
        id="the-largest",
    ),
]


@pytest.mark.parametrize(("source", "expected"), UNDECLARED_ARRAYS)
def test_an_undeclared_array_is_declared_with_its_size(source: str, expected: str) -> None:
    assert fixed(source, "E3001", "Declare 'my_var(10)' with DIM") == expected
    assert errors(expected) == []


def test_an_array_indexed_by_no_number_gets_no_dim_whose_size_would_be_a_guess() -> None:
    (undeclared,) = [d for d in mintlang.check("DIM i\ni = 2\nmy_var(i) = 1\n") if d.code == "E3001"]
    assert undeclared.fixes == ()


# E3004: GOSUB or GOTO to a label the file does not define.
MISSING_LABELS = [
    pytest.param("GOSUB mian\nEND\n#main\nRETURN\n", "Change to #main", "GOSUB main\nEND\n#main\nRETURN\n", id="typo"),
    pytest.param(
        "GOSUB init\nEND\n", "Create subroutine #init", "GOSUB init\nEND\n\n#init\nRETURN\n", id="create-subroutine"
    ),
    pytest.param("GOTO label1\nEND", "Create label #label1", "GOTO label1\nEND\n\n#label1\n", id="create-goto-label"),
    pytest.param(  # the main program would run on into it (000:18968-18978): END first
        "GOSUB init\nPRINT 1", "Create subroutine #init", "GOSUB init\nPRINT 1\nEND\n\n#init\nRETURN\n", id="end-first"
    ),
    pytest.param(  # the file's line breaks, a lone carriage return as a terminal sends it
        "GOSUB init\rEND\r", "Create subroutine #init", "GOSUB init\rEND\r\r#init\rRETURN\r", id="cr-line-breaks"
    ),
]


@pytest.mark.parametrize(("source", "title", "expected"), MISSING_LABELS)
def test_a_missing_label(source: str, title: str, expected: str) -> None:
    assert fixed(source, "E3004", title) == expected
    assert "E3004" not in errors(expected)


def test_no_label_resembles_a_far_name() -> None:
    (missing,) = [d for d in mintlang.check("GOSUB setup\nEND\n#main\nRETURN\n") if d.code == "E3004"]
    assert [fix.title for fix in missing.fixes] == ["Create subroutine #setup"]


# E2011: ELSE or ENDIF without IF .. DO after an IF .. THEN with nothing after THEN (IF..THEN, IF..DO:
# "IF .. DO" opens the block, line 11875).
THEN_AS_A_BLOCK = [
    pytest.param("DIM a\nIF a THEN\n  PRINT 1\nENDIF\n", "DIM a\nIF a DO\n  PRINT 1\nENDIF\n", id="endif"),
    pytest.param(
        "DIM a\nIF a = 1 then\n  PRINT 1\nELSE\n  PRINT 2\nENDIF\n",
        "DIM a\nIF a = 1 DO\n  PRINT 1\nELSE\n  PRINT 2\nENDIF\n",
        id="else-and-endif",
    ),
]


@pytest.mark.parametrize(("source", "expected"), THEN_AS_A_BLOCK)
def test_then_used_as_a_block_becomes_do(source: str, expected: str) -> None:
    assert fixed(source, "E2011", "Change THEN to DO") == expected
    assert errors(expected) == []


def test_a_then_with_a_statement_is_not_the_stray_endifs_block() -> None:
    (stray,) = [d for d in mintlang.check("DIM a\nIF a THEN PRINT 1\nENDIF\n") if d.code == "E2011"]
    assert stray.fixes == ()


# 000:18983-18999: after an IF .. THEN block, a second ELSE, or an ENDIF after the one DO would pair with, is
# E2011 however the THEN is written: DO would give it no block, so it is offered no DO.
STRAYS_DO_CANNOT_PAIR = [
    pytest.param(
        "DIM a\nIF a THEN\n  PRINT 1\nENDIF\nIF a DO\n  PRINT 2\nELSE\n  PRINT 3\nELSE\n  PRINT 4\nENDIF\nENDIF\n",
        {4: True, 9: False, 12: False},
        id="the-guide's-second-else-after-a-then-block",
    ),
    pytest.param("DIM a\nIF a THEN\n  PRINT 1\nELSE\nELSE\nENDIF\n", {4: True, 5: False, 6: True}, id="second-else"),
    pytest.param(
        "DIM a\nFOR a = 1 TO 2\n  IF a THEN\nNEXT\nFOR a = 1 TO 2\n  ELSE\nNEXT\n", {6: False}, id="in-another-loop"
    ),
]


@pytest.mark.parametrize(("source", "offered"), STRAYS_DO_CANNOT_PAIR)
def test_do_is_offered_only_to_the_strays_its_block_would_take(source: str, offered: dict[int, bool]) -> None:
    index = mintlang.LineIndex(source)
    strays = {index.position(d.span.start).line: d for d in mintlang.check(source) if d.code == "E2011"}
    assert {line: any(fix.title == "Change THEN to DO" for fix in d.fixes) for line, d in strays.items()} == offered
