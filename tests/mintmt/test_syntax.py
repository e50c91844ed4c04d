"""How MintMT is written, read into the one syntax tree all dialects share (mintlang/MINTMT.md)."""

from __future__ import annotations

import mintlang
from mintlang.dialect import Dialect
from mintlang.semantic.units import Unit
from mintlang.syntax import nodes as n
from mintlang.syntax.lexer import lex
from mintlang.syntax.tokens import TokenKind as K


def _statements(source: str) -> list[n.Statement]:
    document = mintlang.parse(source, dialect="mintmt")
    assert document.diagnostics == ()
    return [statement for line in document.placed for statement in line.syntax.statements]


def _kinds(line: str) -> list[K]:
    ((_, lexed),) = lex(line, Dialect.MINTMT).lines
    return list(lexed.kinds)


def test_an_apostrophe_comments_the_rest_of_the_line_also_after_code() -> None:
    ((_, whole),) = lex("' Load a move\n", Dialect.MINTMT).lines
    ((_, after),) = lex("GO(0)   ' Trigger the motion\n", Dialect.MINTMT).lines
    assert (whole.kinds, whole.comment_start) == ((), 0)
    assert after.kinds == (K.KEYWORD, K.ADDRESS, K.NUMBER, K.RPAR) and after.comment_start == 8


def test_v4_keeps_its_character_constants() -> None:
    ((_, lexed),) = lex("a = 'A'\n", Dialect.V4).lines
    assert lexed.kinds == (K.NAME, K.EQUAL, K.CHAR)


def test_two_word_closers_are_one_token_in_any_case_and_spacing() -> None:
    assert _kinds("End Loop") == [K.ENDL]
    assert _kinds("end   if") == [K.ENDIF]
    assert _kinds("EndIf") == [K.ENDIF]
    assert _kinds("End Event") == [K.ENDEVENT]
    assert _kinds("END STARTUP") == [K.ENDSTARTUP]
    assert _kinds("End") == [K.END]


def test_a_then_ending_its_line_opens_a_block_and_one_followed_by_code_does_not() -> None:
    block, single = _statements("If a = 1 Then ' comment\nIf a = 2 Then b = 3\n")
    assert type(block) is n.IfDo
    assert type(single) is n.IfThen and len(single.body) == 1


def test_round_brackets_address_axes_with_a_square_list_inside_and_indices_after() -> None:
    (size, parameter, out, go) = _statements(
        "MOVEBUFFERSIZE([0,1]) = 4;\nCONTOURPARAMETER([0,1],0) = 10;\nMOVEOUT(0,2) = 7\nGO(0,1)\n"
    )
    values = [[item.value for item in s.keyword.selector.items] for s in (size, parameter, out, go)]
    assert values == [[0, 1], [0, 1, 0], [0, 2], [0, 1]]
    axes = [[item.value for item in s.keyword.selector.axes] for s in (size, parameter, out, go)]
    assert axes == [[0, 1], [0, 1], [0], [0, 1]]
    assert size.fill


def test_keywords_read_in_expressions_with_round_brackets_and_functions_keep_theirs() -> None:
    (statement,) = _statements("Pause MOVEBUFFERID(0) = 2\n")
    condition = statement.condition
    assert condition.left.keyword == "MOVEBUFFERID" and condition.left.selector.items[0].value == 0
    (comms,) = _statements("comms (3) = 0\n")
    assert type(comms) is n.FunctionStatement and comms.call.function == "COMMS"


def test_event_and_startup_blocks_match_their_closers() -> None:
    source = "Event MOVEBUFFERLOW\n  GO(0)\nEnd Event\nStartup\n  MOVEBUFFERSIZE(0) = 20\nEnd Startup\n"
    analysis = mintlang.check_application(source, dialect="mintmt")
    assert [
        (block.kind.value, block.opener.line, block.closer.line)
        for block in analysis.model.structures[Unit.PROGRAM].blocks
    ] == [
        ("Event", 1, 3),
        ("Startup", 4, 6),
    ]
    assert analysis.program == ()


def test_a_closer_without_its_block_is_a_syntax_error() -> None:
    analysis = mintlang.check_application("End Event\nStartup\n", dialect="mintmt")
    assert [(d.code, d.message) for d in analysis.program] == [
        ("E2003", "Syntax error: End Event without Event"),
        ("E2003", "Syntax error: this Startup block is never closed with End Startup"),
    ]


def test_code_after_an_endless_main_loop_in_an_event_block_is_reachable() -> None:
    source = "Loop\n  GO(0)\nEnd Loop\nEvent Comms1\n  JOG(0) = 1\nEnd Event\n"
    assert mintlang.check_application(source, dialect="mintmt").program == ()


EVENTS = "MOVEBUFFERLOW, ONERROR, TIMER, STOP, COMMS1..5, INx, FASTINx, CANx"


def test_event_and_startup_blocks_stand_alone_and_an_event_names_an_event() -> None:
    source = "Loop\n  Event Comms1\n  End Event\nEnd Loop\nEvent Bogus\nEnd Event\nEvent MOVEBUFFERLOW\nEnd Event\n"
    analysis = mintlang.check_application(source, dialect="mintmt")
    assert [(d.code, d.message) for d in analysis.program] == [
        ("E2003", "Syntax error: Event blocks stand alone: this one is inside the LOOP block of line 1"),
        ("E2003", f"Syntax error: Bogus is no event ({EVENTS})"),
    ]


def test_block_errors_name_the_blocks_as_mintmt_writes_them() -> None:
    """The notes write If .. Then .. End If and Loop .. End Loop: so do the errors."""
    source = "Loop\n  If IN(1) Then\n    GO(0)\nEnd Loop\nIf IN(2) Then\n  GO(0)\n"
    errors = [d.message for d in mintlang.check_application(source, dialect="mintmt").program if d.code[0] == "E"]
    assert errors == [
        "Incorrect loop terminator: End Loop without Loop (the innermost open block is If on line 2)",
        "ELSE/ENDIF w/o IF DO: this If block is never closed with End If",
    ]


def test_a_misspelt_event_is_offered_the_event_it_resembles() -> None:
    """The move buffer note's handler is ``Event MOVEBUFFERLOW`` (004:119)."""
    (diagnostic,) = mintlang.check_application("Event MOVEBUFERLOW\nEnd Event\n", dialect="mintmt").program
    assert diagnostic.message == f"Syntax error: MOVEBUFERLOW is no event ({EVENTS}); did you mean 'MOVEBUFFERLOW'?"
    assert diagnostic.fixes[0].edits[0].text == "MOVEBUFFERLOW"


def test_only_comms_locations_1_to_5_raise_an_event_and_each_event_has_one_block() -> None:
    source = "Event Comms9\nEnd Event\nEvent Comms1\nEnd Event\nEvent COMMS1\nEnd Event\nEvent Comms5\nEnd Event\n"
    analysis = mintlang.check_application(source, dialect="mintmt")
    assert [(d.code, d.message) for d in analysis.program] == [
        ("E2003", f"Syntax error: Comms9 is no event ({EVENTS})"),
        ("E2003", "Syntax error: a second Event COMMS1 block: the event's handler is the block of line 3"),
    ]


def test_a_label_handler_beside_an_event_block_for_the_same_event_is_a_second_handler() -> None:
    """An Event block handles its event (MT-13): a #COMMS1 label for Comms1 is a second handler."""
    source = "Dim a\nEnd\n#COMMS1\n  a = 1\nReturn\nEvent Comms1\n  a = 2\nEnd Event\n"
    analysis = mintlang.check_application(source, dialect="mintmt")
    assert [(d.code, d.message, d.span.start) for d in analysis.program] == [
        (
            "E2003",
            "Syntax error: #COMMS1 handles the event of the Event block of line 6: one handler per event",
            10,
        ),  # "Dim a" and "End" with their line breaks before it
    ]


def test_a_label_handler_for_another_event_than_the_event_block_is_fine() -> None:
    source = "Dim a\nEnd\n#COMMS2\n  a = 1\nReturn\nEvent Comms1\n  a = 2\nEnd Event\n"
    assert mintlang.check_application(source, dialect="mintmt").program == ()


def test_a_program_has_one_startup_block() -> None:
    """The note's Startup block is the code run at power-up (004:128-133): a second one would never run."""
    source = "Startup\n  Print 1\nEnd Startup\nStartup\n  Print 2\nEnd Startup\n"
    analysis = mintlang.check_application(source, dialect="mintmt")
    assert [(d.code, d.message, d.span.start) for d in analysis.program] == [
        (
            "E2003",
            "Syntax error: a second Startup block: the controller runs the block of line 1 at power-up",
            30,
        ),  # 8 + 10 + 12 characters before it
    ]


def test_end_while_is_no_closer_but_is_told_the_closer_it_stands_for() -> None:
    # MT-23: neither the notes nor the v4 guide show End While; WHILE ends with ENDW (v4 guide §3.7.3)
    source = "Dim i\nWhile i < 3\n  i = i + 1\nEnd While\nPrint i\n"
    (error,) = mintlang.check(source, dialect="mintmt")
    assert (error.code, source[error.span.start : error.span.end]) == ("E2003", "End While")
    assert error.message.endswith("a WHILE loop ends with ENDW, not End While")
    (fix,) = error.fixes
    (edit,) = fix.edits
    fixed = source[: edit.span.start] + edit.text + source[edit.span.end :]
    assert fixed == "Dim i\nWhile i < 3\n  i = i + 1\nENDW\nPrint i\n"
    assert mintlang.check(fixed, dialect="mintmt") == []
