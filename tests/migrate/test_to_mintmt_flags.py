"""What ``--to mintmt`` leaves for a person: kept as v4 writes it (MintMT reads it, MT-1), with the
migrator's ``REM MIGRATE:`` line above it, indented as it, and listed as a manual item."""

from __future__ import annotations

import pytest

from mintlang.migrate.mintmt import to_mintmt

RUNS_INTO = "the code above it can run into it (v4 runs the handler's lines, MintMT steps over an Event block)"
KEPT = "is kept as v4 writes it: the notes show MintMT Event blocks only for MOVEBUFFERLOW and Comms1..Comms5"

FLAGS = [
    pytest.param(
        "#COMMS1\nRETURN\n", 1, "MT-EVENT", f"#COMMS1 is kept as a v4 handler: {RUNS_INTO}", id="handler-first-line"
    ),
    pytest.param(
        "PRINT 1\n#COMMS1\nRETURN\n", 2, "MT-EVENT", f"#COMMS1 is kept as a v4 handler: {RUNS_INTO}", id="falls-in"
    ),
    pytest.param(
        "DIM a\nEND\n#COMMS1\nIF a THEN RETURN\nRETURN\n",
        3,
        "MT-EVENT",
        "#COMMS1 is kept as a v4 handler: it does not end with one RETURN alone on its line before the next label",
        id="two-returns",
    ),
    pytest.param(
        "GOSUB COMMS1\nEND\n#COMMS1\nRETURN\n",
        3,
        "MT-EVENT",
        "#COMMS1 is kept as a v4 handler: the program names it in a GOSUB or GOTO",
        id="called",
    ),
    pytest.param(
        "GOTO comms1\nEND\n#COMMS1\nRETURN\n",
        3,
        "MT-EVENT",
        "#COMMS1 is kept as a v4 handler: the program names it in a GOSUB or GOTO",
        id="jumped-to-in-small-letters",
    ),
    pytest.param(
        "DIM a\nLOOP\nIF a THEN EXIT\nENDL\n#COMMS2\nRETURN\n",
        5,
        "MT-EVENT",
        f"#COMMS2 is kept as a v4 handler: {RUNS_INTO}",
        id="loop-with-exit-above",
    ),
    pytest.param("END\n#IN0\nRETURN\n", 2, "MT-EVENT", f"the handler #IN0 {KEPT}", id="in0"),
    pytest.param(
        "END\n#ONERROR\nRETURN\n",
        2,
        "MT-EVENT",
        f"the handler #ONERROR {KEPT}",
        id="onerror",
    ),
    pytest.param(
        "GOSUB start\nEND\n#start\nRETURN\n",
        3,
        "MT-EVENT",
        "#start is kept as v4 writes it: the notes show no MintMT subroutine",
        id="subroutine",
    ),
    pytest.param(
        "DIM a\nWHILE a\nENDW\n",
        2,
        "MT-BLOCK",
        "WHILE ... ENDW is kept as v4 writes it: the notes show no MintMT form of it",
        id="while",
    ),
    pytest.param(
        "DIM a\nREPEAT\nUNTIL a\n",
        2,
        "MT-BLOCK",
        "REPEAT ... UNTIL is kept as v4 writes it: the notes show no MintMT form of it",
        id="repeat",
    ),
    pytest.param(
        "DIM a\nIF a THEN REM later\n",
        2,
        "MT-BLOCK",
        "THEN ends its line: MintMT reads it as opening an If block; give it its statement",
        id="then-ends-its-line",
    ),
    pytest.param(
        "AXES[0,1]\n", 1, "MT-ADDRESS", "AXES is kept as v4 writes it: the notes show no MintMT form of it", id="axes"
    ),
    pytest.param(
        "DIM event\nevent = 1\n",
        1,
        "MT-NAME",
        "event is a MintMT keyword: rename it in the whole application",
        id="name-now-a-block-word",
    ),
]


@pytest.mark.parametrize(("v4", "line", "rule", "reason"), FLAGS)
def test_flags(v4: str, line: int, rule: str, reason: str) -> None:
    result = to_mintmt(v4)
    found = [(item.rule, item.original_line, item.reason) for item in result.manual]
    assert (rule, line, reason) in found
    lines = result.text.splitlines()
    marked = next(item for item in result.manual if (item.rule, item.reason) == (rule, reason))
    assert lines[marked.line - 2] == f"REM MIGRATE: {rule}: {reason}"
    assert lines[marked.line - 1] == v4.splitlines()[line - 1].replace("REM", "'")


def test_a_do_with_a_statement_after_it_is_kept_and_its_endif_still_rewritten() -> None:
    result = to_mintmt("DIM a, b\nIF a DO b = 1\nENDIF\n")
    reason = "DO is kept: MintMT's Then opens a block only at the end of its line; move what follows it"
    assert result.text == f"DIM a, b\nREM MIGRATE: MT-BLOCK: {reason}\nIF a DO b = 1\nEND IF\n"


@pytest.mark.parametrize(
    "v4", [pytest.param("DIM x\nx = POS (1)\n", id="keyword-bracket"), pytest.param("PRINT 'ab'\n", id="stray-quote")]
)
def test_a_form_that_reads_as_mintmt_makes_the_text_mintmt_already(v4: str) -> None:
    """MintMT reads the bracket as the keyword's axes, the quote as a comment: which of the two the
    author meant is for a person (``mintlang.detection`` reads such a text as MintMT)."""
    result = to_mintmt(v4)
    assert result.already_mintmt
    assert (result.text, result.changes) == (v4, ())


def test_the_marker_takes_the_lines_indentation_and_line_break() -> None:
    result = to_mintmt("DIM a\r\n  WHILE a\r\n  ENDW\r\n")
    reason = "WHILE ... ENDW is kept as v4 writes it: the notes show no MintMT form of it"
    assert result.text == f"DIM a\r\n  REM MIGRATE: MT-BLOCK: {reason}\r\n  WHILE a\r\n  ENDW\r\n"


def test_a_line_flagged_twice_for_one_reason_gets_one_marker() -> None:
    result = to_mintmt("DIM event\nevent = event + 1\n")
    assert result.text.count("REM MIGRATE") == 2  # the DIM line and the assignment, once each


def test_a_marker_already_above_its_line_is_not_written_again() -> None:
    once = to_mintmt("DIM a\nWHILE a\nENDW\n")
    twice = to_mintmt(once.text)
    assert (twice.text, twice.changes) == (once.text, ())
    assert [item.line for item in twice.manual] == [item.line for item in once.manual]


def test_a_marker_above_the_first_line_goes_after_the_byte_order_mark() -> None:
    result = to_mintmt("\ufeffWHILE a\nENDW\n")
    reason = "WHILE ... ENDW is kept as v4 writes it: the notes show no MintMT form of it"
    assert result.text == f"\ufeffREM MIGRATE: MT-BLOCK: {reason}\nWHILE a\nENDW\n"
    assert [(item.line, item.original_line) for item in result.manual] == [(2, 1)]
    assert to_mintmt(result.text).text == result.text
