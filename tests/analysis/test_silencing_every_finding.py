"""Silencing every finding of a program with suppression comments (``mint check --add-ignore``).

Each line holding findings gets one ``mint: ignore[...]`` comment naming its codes, sorted, in the form the
README's "Suppression comments" gives: after the statements with ``: REM``, at the head of a comment already
there, or added to a directive already there. A v4 line holds 255 characters (000:255), a v3 one 127
(001:5144): a comment that would make a line longer is not written, and that line's findings stay.
"""

from __future__ import annotations

import re

import pytest

import mintlang
from mintlang.analysis.silencing import silence
from mintlang.analysis.suppression import suppression_fix
from mintlang.diagnostics import Diagnostic
from tests.corpus_files import CorpusCase, cases

_DIRECTIVE = r"mint: ignore\[[^\]]*\]"
_ADDED = re.compile(rf"( :)? REM {_DIRECTIVE}$|(?<=REM ){_DIRECTIVE} |(?<=' ){_DIRECTIVE} ")  # what silencing adds


def _silenced(source: str, *, dialect: str = "v4", controller: str = "nextmove-pci") -> str:
    analysis = mintlang.check_application(source, dialect=dialect, controller=controller)
    return silence(analysis.model, analysis.program).text


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        pytest.param("DIM spare\n", "DIM spare : REM mint: ignore[W103]\n", id="after the statement"),
        pytest.param("x = 1 : REM note\n", "x = 1 : REM mint: ignore[E3001] note\n", id="at the head of a comment"),
        pytest.param(
            "IF x = 1 THEN PRINT “hi”\n",
            "IF x = 1 THEN PRINT “hi” : REM mint: ignore[E3001, W101]\n",
            id="every code of the line, sorted",
        ),
        pytest.param(
            "PRINT “hi” : REM mint: ignore[E3001]\n",
            "PRINT “hi” : REM mint: ignore[E3001, W101]\n",
            id="added to the directive there",
        ),
        pytest.param("SPEED.12 = 1\n", "SPEED.12 = 1 : REM mint: ignore[E0002]\n", id="an error too"),
        pytest.param("END\n#unused\nRETURN\n", "END\n#unused : REM mint: ignore[W104]\nRETURN\n", id="a label line"),
    ],
)
def test_each_line_gets_one_comment_naming_its_codes(source: str, expected: str) -> None:
    assert _silenced(source, controller="nextmove-bx") == expected


def test_a_mintmt_comment_takes_the_directive_after_its_quote() -> None:
    assert _silenced("x = 1 ' note\n", dialect="mintmt") == "x = 1 ' mint: ignore[E3001] note\n"


def test_a_mintmt_block_if_keeps_then_last_and_stays_a_block() -> None:
    # "If .. Then" ending its line opens a block; ": REM" after Then would make it a one-line If
    source = "Dim c\nIf x <> 0 Then\n  c = 1\nEnd If\n"
    assert _silenced(source, dialect="mintmt") == "Dim c\nIf x <> 0 Then REM mint: ignore[E3001]\n  c = 1\nEnd If\n"


def test_no_comment_goes_on_a_v3_protect_line_whose_password_it_would_join() -> None:
    # "Additional keywords such as REM cannot be placed on this line" (001:11089-11092): neither tool writes one
    source = "REM program 1\nPROTECT abc\n"
    analysis = mintlang.check_application(source, dialect="v3")
    result = silence(analysis.model, analysis.program)
    assert (result.text, [d.code for d in result.left]) == (source, ["W114"])
    assert suppression_fix(analysis.model.program, source.index("PROTECT"), "W114") is None


def test_a_line_the_comment_would_make_too_long_keeps_its_findings() -> None:
    line = f"PRINT “{'a' * 240}”"  # 248 characters: the comment would take it past 255
    analysis = mintlang.check_application(line + "\n")
    result = silence(analysis.model, analysis.program)
    assert result.text == line + "\n"
    assert [d.code for d in result.left] == ["W101"] and result.silenced == ()


def test_a_finding_left_is_placed_in_the_new_text() -> None:
    line = f"PRINT “{'a' * 240}”"
    analysis = mintlang.check_application(f"PRINT b\n{line}\n")
    result = silence(analysis.model, analysis.program)
    assert result.text == f"PRINT b : REM mint: ignore[E3001]\n{line}\n"
    (left,) = result.left
    assert left.code == "W101" and result.text[left.span.start : left.span.end] == line.removeprefix("PRINT ")


def test_an_unused_suppression_is_left_to_its_own_fix() -> None:
    assert _silenced("DIM a : REM mint: ignore[W101]\na = 1\nPRINT a\n") == (
        "DIM a : REM mint: ignore[W101]\na = 1\nPRINT a\n"
    )


CORPUS = [
    *cases("v4/invalid"),
    *cases("v4/valid"),
    *cases("v3/programs"),
    *cases("mintmt", "**/*.mnt"),
]


def _findings(case: CorpusCase, text: str) -> list[Diagnostic]:
    return list(mintlang.check(text, dialect=case.dialect, controller=case.controller, config=case.configuration))


@pytest.mark.parametrize("case", CORPUS, ids=lambda case: case.name)
def test_a_silenced_corpus_program_checks_clean_and_only_gains_comments(case: CorpusCase) -> None:
    analysis = mintlang.check_application(
        case.source, dialect=case.dialect, controller=case.controller, config=case.configuration
    )
    result = silence(analysis.model, analysis.program)
    assert [(d.code, d.span, d.message) for d in _findings(case, result.text)] == [
        (d.code, d.span, d.message) for d in result.left
    ]
    assert [_ADDED.sub("", line) for line in result.text.split("\n")] == case.source.split("\n")
    again = mintlang.check_application(
        result.text, dialect=case.dialect, controller=case.controller, config=case.configuration
    )
    assert silence(again.model, again.program).text == result.text  # nothing more to silence
