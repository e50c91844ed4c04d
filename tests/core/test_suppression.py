"""Suppression comments: ``REM mint: ignore[...]`` silences codes on its line, ``ignore-file`` in its file."""

from __future__ import annotations

from dataclasses import replace

import pytest

from mintlang import check, check_application, parse
from mintlang.analysis.suppression import suppression_fix
from mintlang.diagnostics import Diagnostic, LineIndex


def found(source: str, **options: object) -> list[tuple[str, int]]:
    return [(d.code, LineIndex(source).position(d.span.start).line) for d in check(source, **options)]  # type: ignore[arg-type]


def fixed(source: str, diagnostic: Diagnostic) -> str:
    [fix] = diagnostic.fixes
    for edit in sorted(fix.edits, key=lambda e: e.span.start, reverse=True):
        source = source[: edit.span.start] + edit.text + source[edit.span.end :]
    return source


@pytest.mark.parametrize(
    ("source", "left"),
    [
        pytest.param("DIM a : REM mint: ignore[W103]\nDIM b\n", [("W103", 2)], id="after-a-statement"),
        pytest.param("DIM a REM mint: ignore[W103]\n", [], id="without-a-colon"),
        pytest.param("DIM a : rem MINT: IGNORE[w103]\n", [], id="any-case"),
        pytest.param("DIM a : REM mint: ignore[W103] kept for the HMI\n", [], id="words-after-it"),
        pytest.param("DIM a : REM mint:ignore[ W111 , W103 ]\n", [("W117", 1)], id="several-codes"),
        pytest.param("REM mint: ignore[W103]\nDIM a\n", [("W117", 1), ("W103", 2)], id="not-the-next-line"),
        pytest.param("DIM a\nDIM b\nREM mint: ignore-file[W103]\n", [], id="whole-file"),
        pytest.param("DIM a : REM note mint: ignore[W103]\n", [("W103", 1)], id="not-the-first-words"),
        pytest.param('DIM a : PRINT "REM mint: ignore[W103]"\n', [("W103", 1)], id="in-a-string"),
        pytest.param("DIM a : REM mint: ignore[W1]\n", [("W117", 1), ("W103", 1)], id="no-prefixes"),
    ],
)
def test_what_a_comment_silences(source: str, left: list[tuple[str, int]]) -> None:
    assert sorted(found(source)) == sorted(left)


@pytest.mark.parametrize("written", ["E2", "E0002", "e2"])
def test_an_error_is_named_in_either_spelling(written: str) -> None:
    """E2 names error 2 exactly here: a suppression names codes, never prefixes."""
    assert found("SPEED.12 = 1\n", controller="nextmove-bx") == [("E0002", 1)]
    assert found(f"SPEED.12 = 1 : REM mint: ignore[{written}]\n", controller="nextmove-bx") == []


def test_a_configuration_files_comment_silences_its_own_findings() -> None:
    analysis = check_application("PRINT 1\n", config="DIM spare : REM mint: ignore[W103]\nDIM other\n")
    assert [d.code for d in analysis.configuration] == ["W103"]  # 'other' on line 2


@pytest.mark.parametrize(
    ("source", "message"),
    [
        ("DIM a : REM mint: ignore[W103]\nPRINT a\n", "unused suppression: no W103 on this line"),
        ("PRINT 1\nREM mint: ignore-file[W111]\n", "unused suppression: no W111 in this file"),
        ("PRINT 1 : REM mint: ignore[X9]\n", "unused suppression: 'X9' is no code"),
        ("SPEED[0] = 1 : REM mint: ignore[I201]\n", "unused suppression: I201 is not checked"),
    ],
)
def test_an_unused_suppression_says_why(source: str, message: str) -> None:
    [diagnostic] = [d for d in check(source) if d.code == "W117"]
    assert diagnostic.message == message
    assert diagnostic.fixes[0].safe is ("not checked" not in message)  # it may serve a wider selection


def test_a_comment_naming_no_code_is_reported_with_its_removal() -> None:
    """``ignore[]`` silences nothing (README, Suppression comments: a comment names codes): it goes."""
    source = "DIM a : REM mint: ignore[]\nPRINT a\n"
    [diagnostic] = [d for d in check(source) if d.code == "W117"]
    assert diagnostic.message == "unused suppression: it names no code"
    assert diagnostic.fixes[0].safe
    assert fixed(source, diagnostic) == "DIM a\nPRINT a\n"


def test_a_list_no_bracket_closes_silences_nothing_and_says_so() -> None:
    """``ignore[W103`` names no code: W103 stays, and the comment is reported without a fix (only its
    author knows where the list ends)."""
    source = "DIM a : REM mint: ignore[W103 for the HMI\n"
    assert sorted(found(source)) == [("W103", 1), ("W117", 1)]
    [diagnostic] = [d for d in check(source) if d.code == "W117"]
    assert diagnostic.message == "unused suppression: no ']' closes its list of codes, so it names none"
    assert diagnostic.fixes == ()


def test_the_editor_silences_a_code_on_a_line_with_a_list_left_open_by_a_comment_of_its_own() -> None:
    """Added inside the open list, the code would silence nothing; the comment it opens is read first."""
    source = "DIM a : REM mint: ignore[W111\n"
    [diagnostic] = [d for d in check(source) if d.code == "W103"]
    [edit] = suppression_fix(parse(source), diagnostic.span.start, diagnostic.code).edits
    changed = source[: edit.span.start] + edit.text + source[edit.span.end :]
    assert changed == "DIM a : REM mint: ignore[W103] mint: ignore[W111\n"
    assert found(changed) == []


def test_a_suppression_of_a_selected_hint_is_used() -> None:
    source = "SPEED[0] = 1 : REM mint: ignore[I201]\n"
    assert check_application(source, select=("E", "W", "I")).program == ()


def test_an_unused_suppression_can_itself_be_silenced() -> None:
    assert found("PRINT 1 : REM mint: ignore[W103, W117]\n") == []


@pytest.mark.parametrize(
    ("source", "after"),
    [
        pytest.param("DIM a : REM mint: ignore[W103]\nPRINT a\n", "DIM a\nPRINT a\n", id="after-a-statement"),
        pytest.param("  REM mint: ignore[W103]\nPRINT 1\n", "PRINT 1\n", id="own-line-goes-with-it"),
        pytest.param("PRINT 1\r\nREM mint: ignore[W103]\r\nPRINT 2\r\n", "PRINT 1\r\nPRINT 2\r\n", id="crlf"),
        pytest.param("PRINT 1\nREM mint: ignore-file[W103]", "PRINT 1\n", id="last-line-unended"),
        pytest.param("PRINT 1 : REM mint: ignore[W103] why\n", "PRINT 1 : REM why\n", id="words-stay"),
    ],
)
def test_the_fix_removes_a_comment_that_names_nothing_else(source: str, after: str) -> None:
    [diagnostic] = [d for d in check(source) if d.code == "W117"]
    assert fixed(source, diagnostic) == after


@pytest.mark.parametrize(
    ("comment", "after"),
    [
        pytest.param("ignore[W111, W103]", "ignore[W103]", id="first"),
        pytest.param("ignore[W103,W111]", "ignore[W103]", id="last"),
        pytest.param("ignore[W103, W111, W102]", "ignore[W103, W102]", id="middle"),
    ],
)
def test_the_fix_takes_one_code_out_of_a_list(comment: str, after: str) -> None:
    source = f"DIM a : REM mint: {comment}\n"
    [w111] = [d for d in check(source) if d.code == "W117" and "W111" in d.message]
    assert fixed(source, w111) == f"DIM a : REM mint: {after}\n"


PROGRAMS = [
    "DIM total\n",
    "DIM total : REM running sum\n",
    "count = 1\nPRINT count\n",
    "GOSUB missing\nEND\n",
    "SPEED[0] = 10 : REM mint: ignore[W111]\n",
    "#lbl\nRETURN\n",
    "PRINT “hi”\nDIM x\n",
]


@pytest.mark.parametrize("source", PROGRAMS)
def test_ignoring_each_finding_on_its_line_leaves_no_finding_of_its_code_there(source: str) -> None:
    """The editor's "Ignore ... on this line", applied finding by finding, silences each and is used."""
    for diagnostic in check(source):
        if diagnostic.code == "W117":
            continue
        line = LineIndex(source).position(diagnostic.span.start).line
        fix = suppression_fix(parse(source), diagnostic.span.start, diagnostic.code)
        changed = source
        for edit in fix.edits:
            changed = changed[: edit.span.start] + edit.text + changed[edit.span.end :]
        remaining = found(changed)
        assert (diagnostic.code, line) not in remaining, changed
        assert ("W117", line) not in remaining, changed


def test_after_an_edit_the_comments_above_and_below_it_silence_what_they_did() -> None:
    """The language server checks a keystroke from the version before: the suppressions outside the
    edited lines are carried over, moved, and one typed in is read."""
    source = "DIM a : REM mint: ignore[W103]\nREM notes\nDIM b : REM mint: ignore[W103]\nDIM c\n"

    def unused_after(edited: str) -> list[tuple[str, int]]:
        analysis = check_application(edited, previous=check_application(source))
        return [(d.code, LineIndex(edited).position(d.span.start).line) for d in analysis.program]

    assert unused_after(source.replace("notes", "longer notes")) == [("W103", 4)]  # c only
    assert unused_after(source.replace("DIM c", "DIM c : REM mint: ignore[W103]")) == []
    assert unused_after(source.replace("DIM b : REM mint: ignore[W103]", "DIM b")) == [("W103", 3), ("W103", 4)]


# MintMT writes a comment with ' as well as REM (004's listings; mintlang/MINTMT.md MT-19): a directive
# after either is read, and the fixes keep the comment's own opening.
@pytest.mark.parametrize(
    ("source", "left"),
    [
        pytest.param("Dim a ' mint: ignore[W103]\nDim b\n", [("W103", 2)], id="after-a-statement"),
        pytest.param("Dim a 'mint: ignore[W103]\n", [], id="no-space"),
        pytest.param("Dim a\nDim b\n' mint: ignore-file[W103]\n", [], id="whole-file"),
        pytest.param("Dim a ' note mint: ignore[W103]\n", [("W103", 1)], id="not-the-first-words"),
    ],
)
def test_a_mintmt_quote_comment_silences_as_rem_does(source: str, left: list[tuple[str, int]]) -> None:
    assert sorted(found(source, dialect="mintmt")) == sorted(left)


def test_the_removal_of_a_mintmt_quote_directive_keeps_the_quote_before_words_after_it() -> None:
    source = "Print 1 ' mint: ignore[W103] why\n"
    [diagnostic] = [d for d in check(source, dialect="mintmt") if d.code == "W117"]
    assert fixed(source, diagnostic) == "Print 1 ' why\n"


def test_ignoring_a_finding_on_a_line_with_a_quote_comment_keeps_the_comment() -> None:
    source = "Dim total ' running sum\n"
    [diagnostic] = check(source, dialect="mintmt")
    fix = suppression_fix(parse(source, dialect="mintmt"), diagnostic.span.start, diagnostic.code)
    assert fixed(source, replace(diagnostic, fixes=(fix,))) == "Dim total ' mint: ignore[W103] running sum\n"
