"""What ``--to mintmt`` rewrites, one table per kind of rewrite: a v4 text and the MintMT text worked out
by hand from the forms the notes show (``mintlang/MINTMT.md``), and the texts it must leave alone."""

from __future__ import annotations

import pytest

from mintlang.migrate.mintmt import to_mintmt

COMMENTS = [
    pytest.param("REM hello\n", "' hello\n", id="line-comment"),
    pytest.param("PRINT 1 REM after code\n", "PRINT 1 ' after code\n", id="after-code"),
    pytest.param("PRINT 1 : REM after a colon\n", "PRINT 1 : ' after a colon\n", id="after-colon"),
    pytest.param("rem  two  spaces\n", "'  two  spaces\n", id="lower-case-spacing-kept"),
    pytest.param("REM\n", "'\n", id="empty"),
    pytest.param("REM a\r\nREM b\r\n", "' a\r\n' b\r\n", id="crlf"),
    pytest.param('REM @expect terminal is "1"\n', '\' @expect terminal is "1"\n', id="simulator-directive"),
    pytest.param("DIM a REM mint: ignore[W103]\n", "DIM a ' mint: ignore[W103]\n", id="suppression-comment"),
]

CHARACTERS = [
    pytest.param("DIM a = 'A'\n", "DIM a = 65\n", id="capital"),
    pytest.param("DIM a = 'a'\n", "DIM a = 65\n", id="small-letter-is-its-capital"),  # v4 guide 3.2.3
    pytest.param("IF INKEY = 'y' THEN PRINT 1\n", "IF INKEY = 89 THEN PRINT 1\n", id="in-a-condition"),
]

ADDRESSING = [
    pytest.param("MOVER.0 = 10\n", "MOVER(0) = 10\n", id="dot"),
    pytest.param("MOVER[0] = 10\n", "MOVER(0) = 10\n", id="square"),
    pytest.param("GO[0,1]\n", "GO(0,1)\n", id="command-two-axes"),
    pytest.param("VECTORA[0,1] = 10, 10\n", "VECTORA(0,1) = 10, 10\n", id="a-value-per-axis"),
    pytest.param("MOVEBUFFERSIZE[0,1] = 4;\n", "MOVEBUFFERSIZE([0,1]) = 4;\n", id="one-value-for-all-axes"),
    pytest.param("SPEED[0, 1] = 10;\n", "SPEED([0, 1]) = 10;\n", id="spacing-inside-kept"),
    pytest.param("SPEED[0] = 10;\n", "SPEED(0) = 10;\n", id="one-axis-filled"),
    pytest.param("DIM x\nx = POS.1 + POS[2]\n", "DIM x\nx = POS(1) + POS(2)\n", id="reads"),
    pytest.param("DIM axis\nSPEED.axis = 5\n", "DIM axis\nSPEED(axis) = 5\n", id="variable"),
    pytest.param("speed.0 = 5\n", "speed(0) = 5\n", id="case-kept"),
    pytest.param("PAUSE IDLE.0 : JOG.1 = 5\n", "PAUSE IDLE(0) : JOG(1) = 5\n", id="several-on-a-line"),
    pytest.param("OUT.3 = 1\n", "OUTX(3) = 1\n", id="one-output-channel-is-outx"),  # 004:148
    pytest.param("DIM x\nx = ot.2\n", "DIM x\nx = outx(2)\n", id="one-output-channel-read-abbreviated"),
]

BLOCKS = [
    pytest.param("LOOP\n  GO.0\nENDL\n", "LOOP\n  GO(0)\nEND LOOP\n", id="loop"),
    pytest.param("loop\nendl\n", "loop\nend loop\n", id="loop-small-letters"),
    pytest.param("Loop\nEndL\n", "Loop\nEnd Loop\n", id="loop-mixed-case"),
    pytest.param("DIM a, b\nIF a DO\n  b = 1\nENDIF\n", "DIM a, b\nIF a THEN\n  b = 1\nEND IF\n", id="if-block"),
    pytest.param("DIM a\nIF a DO REM why\nENDIF\n", "DIM a\nIF a THEN ' why\nEND IF\n", id="if-block-comment"),
    pytest.param(
        "DIM a\nIF a DO\n  PRINT 1\nELSE\n  PRINT 2\nENDIF\n",
        "DIM a\nIF a THEN\n  PRINT 1\nELSE\n  PRINT 2\nEND IF\n",
        id="if-else",
    ),
    pytest.param("DIM a\nIf a Do\nEndIf\n", "DIM a\nIf a Then\nEnd If\n", id="if-mixed-case"),
]

EVENTS = [
    pytest.param(
        "END\n#COMMS1\nJOG.0 = COMMS(1)\nRETURN\n",
        "END\nEVENT COMMS1\nJOG(0) = COMMS(1)\nEND EVENT\n",
        id="comms1-after-end",
    ),
    pytest.param("END\n\n#Comms2\nReturn\n", "END\n\nEvent Comms2\nEnd Event\n", id="mixed-case-after-blank"),
    pytest.param("LOOP\nENDL\n#COMMS5\nRETURN\n", "LOOP\nEND LOOP\nEVENT COMMS5\nEND EVENT\n", id="after-endless-loop"),
    pytest.param(
        "END\n#COMMS3 REM host\nRETURN REM done\n",
        "END\nEVENT COMMS3 ' host\nEND EVENT ' done\n",
        id="comments-kept",
    ),
]

UNCHANGED = [
    pytest.param("REMARK = 1\n", id="a-name-starting-with-rem"),
    pytest.param('PRINT "REM, [0] and .0 in a string"\n', id="string"),
    pytest.param("DIM a\nSPEED.(a+1) = 5\n", id="dot-expression-round-brackets-take-no-expression"),
    pytest.param("DIM x\nx = REMOTEIN.2.65\n", id="two-dot-values"),
    pytest.param("DIM x\nx = COMMS(1)\n", id="function"),
    pytest.param("DEFINE ax = 0\nSPEED.ax = 5\n", id="macro-after-dot"),
    pytest.param("DIM x(3)\nx(1) = 2\n", id="array"),
    pytest.param("DIM a, b\nIF a THEN b = 1\n", id="one-line-if"),
    pytest.param("DIM a\nIF a DO\n", id="if-block-never-closed"),  # IF a THEN would read back as a one-line IF
    pytest.param("SPEED = 5\nGO\n", id="default-axes"),
    pytest.param("OUT = 266\n", id="the-whole-output-bank"),
    pytest.param("", id="empty"),
]


@pytest.mark.parametrize(("v4", "mintmt"), [*COMMENTS, *CHARACTERS, *ADDRESSING, *BLOCKS, *EVENTS])
def test_rewrites(v4: str, mintmt: str) -> None:
    result = to_mintmt(v4)
    assert result.text == mintmt
    assert result.manual == ()


@pytest.mark.parametrize("v4", UNCHANGED)
def test_leaves_alone(v4: str) -> None:
    result = to_mintmt(v4)
    assert (result.text, result.changes, result.manual) == (v4, (), ())


def test_a_marker_of_the_v3_migration_stays_and_is_listed() -> None:
    v4 = "REM MIGRATE: X-UNITS: re-tune\nKPROP = 2\n"
    result = to_mintmt(v4)
    assert (result.text, result.changes) == (v4, ())
    assert [(item.rule, item.line, item.reason) for item in result.manual] == [("X-UNITS", 2, "re-tune")]


def test_each_change_names_its_rewrite_and_both_lines() -> None:
    result = to_mintmt("REM go\nGO.0\n")
    found = [(c.rule, c.line, c.original, c.replacement, c.migrated_line) for c in result.changes]
    assert found == [("MT-COMMENT", 1, "REM", "'", 1), ("MT-ADDRESS", 2, ".0", "(0)", 2)]
    assert result.rule_counts == {"MT-ADDRESS": 1, "MT-COMMENT": 1}


def test_the_restocking_loop_of_the_move_buffer_note() -> None:
    """004:96-105 written in v4 by hand: the migration is the note's listing, with the v4 file's
    capitals (MT-21) and End If for the note's EndIf (both are MintMT)."""
    v4 = (
        "LOOP\n"
        "REM Wait until data valid flag (Comms location 1) and there is space in the buffer\n"
        "IF (COMMS(1) = 1) AND (MOVEBUFFERFREE.0 > 0) DO\n"
        "  MOVER.0 = COMMS(2)           REM Load move with data (Comms location 2)\n"
        "  GO.0                         REM Trigger motion\n"
        "  COMMS(1) = 0                 REM Indicate to host that move is loaded\n"
        "ENDIF\n"
        'PRINT #3, "Pos = ", POS.0     REM Keypad is assigned to terminal 3\n'
        "ENDL\n"
    )
    mintmt = (
        "LOOP\n"
        "' Wait until data valid flag (Comms location 1) and there is space in the buffer\n"
        "IF (COMMS(1) = 1) AND (MOVEBUFFERFREE(0) > 0) THEN\n"
        "  MOVER(0) = COMMS(2)           ' Load move with data (Comms location 2)\n"
        "  GO(0)                         ' Trigger motion\n"
        "  COMMS(1) = 0                 ' Indicate to host that move is loaded\n"
        "END IF\n"
        'PRINT #3, "Pos = ", POS(0)     \' Keypad is assigned to terminal 3\n'
        "END LOOP\n"
    )
    assert to_mintmt(v4).text == mintmt


def test_a_configuration_file_is_migrated_with_its_program() -> None:
    result = to_mintmt("GO.0\n", config="REM axes\nSCALE.0 = 100\n")
    assert result.text == "GO(0)\n"
    assert result.configuration is not None
    assert result.configuration.text == "' axes\nSCALE(0) = 100\n"


def test_a_macro_of_the_configuration_file_is_left_after_the_dot_in_the_program() -> None:
    result = to_mintmt("SPEED.ax = 5\n", config="DEFINE ax = 1\n")
    assert result.text == "SPEED.ax = 5\n"


@pytest.mark.parametrize(
    "mintmt",
    [
        pytest.param("MOVER(0) = 10 ' load\n", id="quote-comment"),
        pytest.param("LOOP\nEnd Loop\n", id="two-word-closer"),
        pytest.param("Event Comms1\nEnd Event\n", id="event"),
    ],
)
def test_a_text_already_mintmt_is_left_as_it_was(mintmt: str) -> None:
    result = to_mintmt(mintmt + "GO.0\n")
    assert result.already_mintmt
    assert (result.text, result.changes) == (mintmt + "GO.0\n", ())


def test_a_byte_order_mark_stays_first_and_the_changes_are_placed_after_it() -> None:
    result = to_mintmt("\ufeffREM x\nGO.0\n")
    assert result.text == "\ufeff' x\nGO(0)\n"
    assert [(change.span.start, change.original) for change in result.changes] == [(1, "REM"), (9, ".0")]


def test_an_empty_configuration_file_beside_a_mintmt_program_is_left_too() -> None:
    result = to_mintmt("GO(0) ' go\n", config="")
    assert result.already_mintmt
    assert result.configuration is not None and result.configuration.text == ""
