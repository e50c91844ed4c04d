"""X-PRINT on INPUT: v3 printed ``?`` after an INPUT prompt, v4 does not (spec §12, INPUT row).

The v3 guide shows ``INPUT "Enter a number",a`` printing ``Enter a number ?`` (v3:2764-2775);
the v4 INPUT entry shows the statement and no query mark (v4:12213-12218). The spec's action for
INPUT is S-ECHO and X-PRINT, so every INPUT carries an X-PRINT item, whether or not it has USING.
"""

from __future__ import annotations

from mintlang.migrate import migrate
from mintlang.migrate.verification import Place, Verdict, verify
from tests.migrate.helpers import flagged

_PROMPT = "v3 INPUT printed ' ?' after its prompt (not after POFF), v4 does not; check what reads this output"


def test_every_input_is_flagged_once_for_its_query_mark() -> None:
    # v3:2769 (a prompt string), v3:2791 (USING), a bare INPUT after THEN as in v3:2986: each prints the
    # ' ?' (v3:2764-2775); USING lays out the number typed (v3:2777-2800), printing no number with 4 decimals
    source = 'INPUT "Enter a number",a\nINPUT a USING -5,2\nIF x THEN INPUT b : PRINT b\nPRINT a\n'
    assert flagged("X-PRINT", source) == [_PROMPT, _PROMPT, _PROMPT]


def test_the_query_mark_of_an_input_using_is_where_verify_finds_the_divergence() -> None:
    # the v3 run prints 'Length ?' before the number typed, the v4 run 'Length': the item says why
    result = migrate('INPUT "Length", len USING 4,1\n')
    found = verify(result, until_ms=100)
    assert found.divergence is not None and found.divergence.v3_line == Place("program", 1)
    assert [item.reason for item in result.manual] == [_PROMPT]


def test_the_v3_guide_example_marks_the_input_line() -> None:
    # v3:2769: the INPUT is line 1 of the original; DIM a (M-DIM) and the marker go above it
    result = migrate('INPUT "Enter a number",a\n')
    assert result.text == f'DIM a\nREM MIGRATE: X-PRINT: {_PROMPT}\nINPUT "Enter a number",a\n'
    assert [(item.rule, item.line, item.original_line) for item in result.manual] == [("X-PRINT", 3, 1)]


def test_the_divergence_verify_finds_on_the_prompt_sits_on_a_flagged_line() -> None:
    # v3 prints "Enter a number ?" and waits; v4 prints "Enter a number" and waits: the runs differ
    # at character 14, on the INPUT line, which the report lists as not verified
    result = migrate('INPUT "Enter a number",a\n')
    found = verify(result, until_ms=100)
    assert found.verdict is Verdict.DIVERGES
    assert found.divergence is not None and found.divergence.v3_line == Place("program", 1)
    assert [(unit, item.original_line) for unit, item in found.not_verified] == [("program", 1)]
