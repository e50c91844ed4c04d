"""The semantic model: symbols, configuration and program, blocks, events, controllers.

Line numbers in comments refer to the Mint v4 programming guide
(/work/shared/seeds/000_f3c82d19754128dd.txt).
"""

from __future__ import annotations

import pytest

import mintlang
from mintlang import Severity
from mintlang.controllers import ChannelRange, profile
from mintlang.semantic.blocks import BlockKind
from mintlang.semantic.events import Event, EventKind, event_of
from mintlang.semantic.symbols import SymbolKind, Unit


def codes_at(source: str, *, config: str | None = None, controller: str = "nextmove-pci") -> list[tuple[str, int]]:
    """The program's diagnostics as (code, 1-based line)."""
    analysis = mintlang.check_application(source, config=config, controller=controller)
    index = mintlang.LineIndex(source)
    return [(d.code, index.position(d.span.start).line) for d in analysis.program]


def model(source: str, *, config: str | None = None, controller: str = "nextmove-pci") -> mintlang.SemanticModel:
    return mintlang.check_application(source, config=config, controller=controller).model


# --------------------------------------------------------------- identities


def test_only_the_first_ten_characters_of_a_name_count() -> None:
    # line 887: DIM thisIsAVariable1 / DIM thisIsAVaraible2 "will only define one variable"
    source = "DIM thisIsAVariable1\nthisIsAVaraible2 = 1\nPRINT thisIsAVariable1\n"
    variables = model(source).symbols.variables
    assert list(variables) == ["THISISAVAR"]
    symbol = variables["THISISAVAR"]
    assert [occurrence.spelling for occurrence in symbol.occurrences()] == [
        "thisIsAVariable1",
        "thisIsAVaraible2",
        "thisIsAVariable1",
    ]
    assert codes_at(source) == [("W108", 2)]


def test_names_are_case_insensitive() -> None:
    source = "DIM MotorSpeed\nmotorspeed = 1\nPRINT MOTORSPEED\n"
    assert list(model(source).symbols.variables) == ["MOTORSPEED"]
    assert codes_at(source) == []


def test_a_variable_used_before_its_dim_counts_as_undeclared_there() -> None:
    # line 897: "All variables must be declared before being used"
    symbol = model("PRINT late\nDIM late\nPRINT late\n").symbols.variables["LATE"]
    assert [occurrence.declared_before for occurrence in symbol.references] == [False, True]


def test_an_array_records_its_size() -> None:
    symbol = model("DIM my_array(10)\nPRINT my_array(4)\n").symbols.variables["MY_ARRAY"]
    assert (symbol.kind, symbol.array_size) == (SymbolKind.ARRAY, 10)


# ----------------------------------------------- configuration and program


CONFIGURATION = "DIM jobCount = 1\nDEFINE announce = PRINT jobCount\nEND\n#setup\nRETURN\n"


def test_variables_of_the_configuration_are_visible_in_the_program() -> None:
    # line 189: the configuration file is executed first, then the program file
    application = model("PRINT jobCount\n", config=CONFIGURATION)
    assert application.symbols.variables["JOBCOUNT"].unit is Unit.CONFIGURATION
    assert codes_at("PRINT jobCount\n", config=CONFIGURATION) == []


def test_without_the_configuration_the_same_variable_is_undeclared() -> None:
    assert codes_at("PRINT jobCount\n") == [("E3001", 1)]


def test_macros_of_the_configuration_are_expanded_in_the_program() -> None:
    # line 1540: "Macros defined in the configuration file are carried over to the program file"
    source = "announce\n"
    assert codes_at(source, config=CONFIGURATION) == []
    assert codes_at(source) == [("E3007", 1)]
    statements = model(source, config=CONFIGURATION).program.lines[0].statements
    assert [type(statement).__name__ for statement in statements] == ["Print"]


def test_labels_of_the_configuration_are_not_visible_in_the_program() -> None:
    # line 1881: "A subroutine defined in a configuration file cannot be called from within a program file"
    assert codes_at("GOSUB setup\nEND\n", config=CONFIGURATION) == [("E3004", 1)]


def test_labels_of_the_program_are_not_visible_in_the_configuration() -> None:
    analysis = mintlang.check_application("END\n#later\nRETURN\n", config="GOSUB later\n")
    assert [d.code for d in analysis.configuration] == ["E3004"]


def test_a_macro_of_the_configuration_cannot_be_redefined_in_the_program() -> None:
    # line 1537: "Macros cannot be redefined within a program if defined in the configuration file"
    assert codes_at("DEFINE mac = 2\nPRINT mac\n", config="DEFINE mac = 1\n") == [("E3005", 1)]


def test_a_macro_defined_twice_in_one_file_is_an_invalid_macro() -> None:
    assert codes_at("DEFINE mac = 2\nDEFINE mac = 3\nPRINT mac\n") == [("E3005", 2)]


def test_macro_names_equal_in_their_first_ten_characters_are_one_macro() -> None:
    # line 1480: DEFINE example_No1 / DEFINE example_No2 "will give the error 'invalid macro'"
    found = codes_at("DEFINE example_No1\nDEFINE example_No2\n")
    assert ("E3005", 2) in found
    assert ("E3005", 1) not in found


# --------------------------------------------------------- block matching


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        # line 18954: NEXT w/o FOR
        (
            'DIM index\nDIM master_dist\nFOR index = 1 TO 10\nREPEAT\nINPUT "Enter Master Distance", master_dist\n'
            "NEXT\nUNTIL master_dist > 100\n",
            ("E2009", 6),
        ),
        # line 18979: ELSE/ENDIF w/o IF DO - an IF .. THEN instead of IF .. DO
        ('DIM a\nDIM b\nIF (a > b) THEN\n?"a is greater than b"\nELSE\n?"a is less"\nENDIF\n', ("E2011", 5)),
        # line 18990: a second ELSE in one IF block
        ('DIM a\nDIM b\nIF (a > b) DO\n?"a"\nELSE\n?"b"\nELSE\n?"c"\nENDIF\nENDIF\n', ("E2011", 7)),
        # line 19000: ENDW w/o WHILE
        (
            'DIM master_dist\nWHILE master_dist = 0\nREPEAT\nINPUT "E", master_dist\nENDW\nUNTIL master_dist > 100\n',
            ("E2012", 5),
        ),
        # line 19011: UNTIL w/o REPEAT
        (
            'DIM master_dist\nREPEAT\nWHILE master_dist = 0\nINPUT "E", master_dist\nUNTIL master_dist > 100\nENDW\n',
            ("E2013", 5),
        ),
        # line 19022: ENDL w/o LOOP
        ('DIM master_dist\nLOOP\nWHILE master_dist = 0\nINPUT "E", master_dist\nENDL\nENDW\n', ("E2014", 5)),
    ],
    ids=["2009", "2011-then", "2011-else", "2012", "2013", "2014"],
)
def test_misplaced_block_closers_give_the_manuals_errors(source: str, expected: tuple[str, int]) -> None:
    errors = [(code, line) for code, line in codes_at(source) if code.startswith("E")]
    assert expected in errors
    assert [code for code, _ in errors] == [expected[0]] * len(errors)


def test_the_second_else_example_reports_both_the_else_and_the_extra_endif() -> None:
    source = 'DIM a\nDIM b\nIF (a > b) DO\n?"a"\nELSE\n?"b"\nELSE\n?"c"\nENDIF\nENDIF\n'
    assert codes_at(source) == [("E2011", 7), ("E2011", 10)]


@pytest.mark.parametrize(
    ("opener", "code"),
    [("FOR i = 1 TO 3", "E2009"), ("IF i DO", "E2011"), ("WHILE i", "E2012"), ("REPEAT", "E2013"), ("LOOP", "E2014")],
)
def test_a_block_never_closed_is_its_constructs_mismatch_error_at_its_opener(opener: str, code: str) -> None:
    # 000:4564-4570: the compiler traps a mismatched loop construct; the closers' numbers (000:18954-19037)
    # are the only ones the manual gives for each construct
    (error,) = mintlang.check_application(f"DIM i\nPRINT 1\n{opener}\nPRINT i\n").program
    assert (error.code, error.severity) == (code, Severity.ERROR)
    assert codes_at(f"DIM i\nPRINT 1\n{opener}\nPRINT i\n") == [(code, 3)]


@pytest.mark.parametrize(
    ("source", "expected"),
    [
        # 000:1781: a WHILE loop ends with ENDW; WEND, as other BASICs write it, is its one error 3007 (naming
        # ENDW), not also a WHILE never closed
        pytest.param("DIM a\nWHILE a < 3\n  a = a + 1\nWEND\nEND\n", [("E3007", 4)], id="wend"),
        pytest.param("DIM a\nWHILE a < 3\n  a = a + 1\nENDWHILE\nEND\n", [("E3007", 4)], id="endwhile"),
        # it closes only the WHILE that ENDW would close: a REPEAT on top stays open (000:19011)
        pytest.param("DIM a\nREPEAT\n  a = a + 1\nWEND\nEND\n", [("E2013", 2), ("E3007", 4)], id="not-a-repeat"),
    ],
)
def test_another_basics_word_for_endw_closes_its_while(source: str, expected: list[tuple[str, int]]) -> None:
    assert codes_at(source) == expected


def test_matched_blocks_are_recorded_with_their_lines() -> None:
    source = "DIM a\nIF a DO\nGO\nELSE\nSTOP\nENDIF\nLOOP\nENDL\n"
    blocks = model(source).structures[Unit.PROGRAM].blocks
    assert [(b.kind, b.opener.line, b.closer.line, b.middle is not None) for b in blocks] == [
        (BlockKind.IF, 2, 6, True),
        (BlockKind.LOOP, 7, 8, False),
    ]


def nested_for_loops(depth: int) -> str:
    return "DIM i\n" + "FOR i = 1 TO 2\n" * depth + "NEXT\n" * depth


def test_fifty_nested_for_loops_are_allowed() -> None:
    # line 1731: "FOR .. NEXT loops may be nested, up to a level of 50 deep"
    assert codes_at(nested_for_loops(50)) == []


def test_the_fifty_first_nested_for_loop_is_a_stack_overflow() -> None:
    # line 1962 (3.9): FOR..NEXT blocks 50 levels; line 19033: #2015 Stack overflow
    assert codes_at(nested_for_loops(51)) == [("E2015", 52)]


def test_a_nesting_limit_crossed_once_is_one_error_not_one_per_deeper_block() -> None:
    # the controller's compiler stops at its first error (#2015, line 19033): the 52nd and 53rd
    # loops inside the 51st are the same overflow; a second crossing after it closed is another
    source = nested_for_loops(53) + "FOR i = 1 TO 2\n" * 51 + "NEXT\n" * 51
    # lines: DIM, 53 FORs (2-54), 53 NEXTs (55-107), then 51 FORs from line 108: the 51st on 158
    assert codes_at(source) == [("E2015", 52), ("E2015", 158)]


def test_nextmove_pc_allows_twenty_nested_for_loops() -> None:
    # line 1962 (3.9): NextMove PC: FOR..NEXT blocks 20 levels
    assert codes_at(nested_for_loops(20), controller="nextmove-pc") == []
    assert codes_at(nested_for_loops(21), controller="nextmove-pc") == [("E2015", 22)]


def test_while_loop_and_repeat_share_one_nesting_limit() -> None:
    # line 1973: "25 WHILE..ENDW blocks nested with 25 LOOP..ENDL blocks would reach the maximum"
    at_limit = "WHILE 1\n" * 25 + "LOOP\n" * 25 + "ENDL\n" * 25 + "ENDW\n" * 25
    over = "REPEAT\n" + at_limit + "UNTIL 1\n"
    assert codes_at(at_limit) == []
    assert codes_at(over) == [("E2015", 51)]


# ----------------------------------------------------------------- events


@pytest.mark.parametrize(
    ("label", "event"),
    [
        # line 1888, section 3.8.1: the reserved labels
        ("ONERROR", Event(EventKind.ONERROR, None)),
        ("onerror", Event(EventKind.ONERROR, None)),
        ("IN3", Event(EventKind.IN, 3)),
        ("FASTIN", Event(EventKind.FASTIN, None)),
        ("FASTIN2", Event(EventKind.FASTIN, 2)),
        ("TIMER", Event(EventKind.TIMER, None)),
        ("COMMS1", Event(EventKind.COMMS, 1)),
        ("CAN2", Event(EventKind.CAN, 2)),
        ("STOP", Event(EventKind.STOP, None)),
        ("IN0", Event(EventKind.IN, 0)),
        ("IN10", Event(EventKind.IN, 10)),
    ],
)
def test_reserved_labels_are_event_handlers(label: str, event: Event) -> None:
    assert event_of(label) == event


# the guide writes no handler with a leading zero (000:1888-1898), and a number with one is binary (000:744-760)
@pytest.mark.parametrize("label", ["main", "IN", "COMMS", "TIMER2", "ONERROR1", "INPUT3", "COMMS01", "IN00", "CAN02"])
def test_other_labels_are_plain_subroutines(label: str) -> None:
    assert event_of(label) is None


def test_event_handlers_need_no_gosub() -> None:
    source = "END\n#ONERROR\nRETURN\n#IN3\nRETURN\n#FASTIN2\nRETURN\n#TIMER\nRETURN\n#COMMS1\nRETURN\n#plain\nRETURN\n"
    assert codes_at(source) == [("W104", 12)]


def test_fastin_alone_is_an_event_handler_too() -> None:
    assert codes_at("END\n#FASTIN\nRETURN\n") == []


# ------------------------------------------------------ controller profiles


def channel_table(controller: str) -> dict[str, tuple[int, int] | None]:
    """A controller's channel ranges as (lowest, highest), None where it has none."""
    target = profile(controller)

    def pair(channels: ChannelRange | None) -> tuple[int, int] | None:
        return None if channels is None else (channels.low, channels.high)

    return {
        "axes": pair(target.axes),
        "inputs": pair(target.digital_inputs),
        "outputs": pair(target.digital_outputs),
        "adc": pair(target.adc),
        "dac": pair(target.dac),
        "aux dac": pair(target.auxiliary_dac),
        "encoders": pair(target.encoders),
        "aux encoders": pair(target.auxiliary_encoders),
    }


# line 5613, the Dot Parameters table, in the order of its columns. NextMove PCI inputs and outputs
# include the two expansion cards: inputs 20-59 (line 4078), outputs 12-35 (line 4126). MintDrive's DAC is
# its one axis, not N/A: footnote 7 (line 5666) and the DAC entry's MintDrive example (lines 8778-8793).
COLUMNS = ("axes", "inputs", "outputs", "adc", "dac", "aux dac", "encoders", "aux encoders")
DOT_PARAMETERS = {
    "nextmove-pci": ((0, 11), (0, 59), (0, 35), (0, 11), (0, 11), None, (0, 11), (0, 2)),
    "nextmove-pc": ((0, 7), (0, 23), (0, 11), (0, 7), (0, 7), None, (0, 7), (0, 0)),
    "nextmove-bx": ((0, 7), (0, 15), (0, 7), (0, 7), (0, 3), None, (0, 3), (0, 0)),
    "servonode51": ((0, 0), (0, 5), (0, 2), (0, 0), None, (0, 1), (0, 0), (0, 0)),
    "mintdrive": ((0, 0), (0, 17), (0, 8), (0, 3), (0, 0), (0, 3), (0, 0), (0, 0)),
}


@pytest.mark.parametrize("controller", DOT_PARAMETERS)
def test_controller_channel_ranges_follow_the_dot_parameters_table(controller: str) -> None:
    assert channel_table(controller) == dict(zip(COLUMNS, DOT_PARAMETERS[controller], strict=True))
    assert profile(controller).axis_count == DOT_PARAMETERS[controller][0][1] + 1


@pytest.mark.parametrize(
    ("controller", "names", "nesting"),
    [
        # line 1909 and line 1962 (3.9): NextMove PC has the smaller tables.
        # nesting: IF blocks, FOR loops, GOSUB, WHILE/LOOP/REPEAT together, loops and IFs together
        ("nextmove-pci", 255, (255, 50, 100, 50, 255)),
        ("nextmove-pc", 100, (100, 20, 50, 20, 255)),
        ("nextmove-bx", 255, (255, 50, 100, 50, 255)),
        ("mintdrive", 255, (255, 50, 100, 50, 255)),
        ("servonode51", 255, (255, 50, 100, 50, 255)),
    ],
)
def test_controller_table_and_nesting_limits_follow_section_3_9(
    controller: str, names: int, nesting: tuple[int, ...]
) -> None:
    target = profile(controller)
    assert (target.max_variables, target.max_labels, target.max_macros) == (names, names, names)
    limits = target.nesting
    assert (limits.if_blocks, limits.for_loops, limits.gosub, limits.other_loops, limits.loops_and_ifs) == nesting
    assert target.max_line_length == 255
