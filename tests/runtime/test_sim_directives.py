"""``REM @sim`` and ``REM @expect`` lines in a Mint program script the world of a run (spec W-2)."""

from __future__ import annotations

from types import MappingProxyType

import pytest

from mintlang.runtime.comms.packets import encode_read, encode_write
from mintlang.runtime.scenario import (
    AdcLevel,
    Comparison,
    FastInput,
    HostPacket,
    IndexPulse,
    InputLevel,
    Keys,
    Origin,
    PlantChoice,
    PositionInput,
    Scenario,
    ScenarioError,
    StoppedExpectation,
    TerminalExpectation,
    ValueExpectation,
    parse_directives,
)
from mintlang.runtime.scenario.targets import Target


def scenario(program: str) -> Scenario:
    """The scenario of a program whose directives are all valid."""
    result, errors = parse_directives(program)
    assert errors == []
    return result


def errors(program: str) -> list[ScenarioError]:
    return parse_directives(program)[1]


# ---------------------------------------------------------------- where directives are found


def test_a_program_without_directives_scripts_nothing() -> None:
    assert scenario("JOG.0 = 10\nPAUSE IDLE.0\n") == Scenario()


def test_rem_is_case_insensitive_and_may_follow_a_statement() -> None:
    program = "rem @sim fastin 0 at 10\nJOG.0 = 1 : Rem @SIM fastin 1 at 20\n"
    assert scenario(program).fast_inputs == (FastInput(10, 0), FastInput(20, 1))


def test_text_inside_a_string_is_not_a_directive() -> None:
    assert scenario('PRINT "REM @sim fastin 0 at 10"\n') == Scenario()


def test_other_at_words_in_comments_are_left_alone() -> None:
    assert scenario("REM @author someone\nREM @simple\nREM sim input 1 1 at 0\n") == Scenario()


@pytest.mark.parametrize(
    ("comment", "meant"),
    [
        ("REM @expext a = 1", "@expect"),  # a letter changed
        ("REM @exepct a = 1", "@expect"),  # two neighbours swapped
        ("REM @expects a = 1", "@expect"),  # a letter added
        ("REM @Expected a = 1", "@expect"),
        ("REM @sims fastin 0 at 10", "@sim"),
        ("' @smi fastin 0 at 10", "@sim"),  # MintMT's comment
    ],
)
def test_a_misspelt_directive_is_an_error_at_its_at_sign_with_the_word_meant(comment: str, meant: str) -> None:
    word = comment.split()[1]
    problems = parse_directives(f"DIM a\n{comment}\n", dialect="mintmt" if comment[0] == "'" else "v4")[1]
    column = comment.index("@") + 1
    message = f"unknown directive '{word}'; did you mean '{meant}'?"
    assert problems == [ScenarioError("program", 2, message, column)]
    assert str(problems[0]) == f"program:2:{column}: {message}"


def test_a_misspelt_directive_after_a_statement_is_found_at_its_column() -> None:
    problems = errors("DIM a : REM @expekt a = 0\n")
    assert [(problem.line, problem.column) for problem in problems] == [(1, 13)]


# ---------------------------------------------------------------- every directive of W-2


@pytest.mark.parametrize(
    ("directive", "plant"),
    [
        ("plant 0 ideal", PlantChoice(0, "ideal")),
        ("plant 1 stalled", PlantChoice(1, "stalled")),
        ("plant 2 velamp 40", PlantChoice(2, "velamp", MappingProxyType({"k": 40.0}))),
        ("plant 2 velamp k=40", PlantChoice(2, "velamp", MappingProxyType({"k": 40.0}))),
        ("plant 3 torque", PlantChoice(3, "torque")),
        (
            "plant 3 torque gain = 30000 viscous=5",
            PlantChoice(3, "torque", MappingProxyType({"gain": 30000.0, "viscous": 5.0})),
        ),
    ],
)
def test_plant_chooses_the_model_of_an_axis(directive: str, plant: PlantChoice) -> None:
    assert scenario(f"REM @sim {directive}\n").plants == (plant,)


def test_plants_are_listed_by_axis() -> None:
    program = "REM @sim plant 2 stalled\nREM @sim plant 0 stalled\n"
    assert [plant.axis for plant in scenario(program).plants] == [0, 2]


def test_input_sets_an_electrical_level_from_a_time() -> None:
    program = "REM @sim input 3 1 at 1500\nREM @sim input 3 0 at 1600 ms\n"
    assert scenario(program).inputs == (InputLevel(1500, 3, 1), InputLevel(1600, 3, 0))


def test_a_time_may_carry_its_unit_with_or_without_a_space() -> None:
    """README: a time may be followed by ms; written on, as "at 50ms", it was refused as no whole number."""
    program = 'REM @sim input 3 1 at 50ms\nREM @sim key "1" at 60MS\nREM @expect IN.3 = 1 at 70ms\n'
    found = scenario(program)
    assert (found.inputs[0].time_ms, found.keys[0].time_ms, found.expectations[0].at_ms) == (50, 60, 70)


@pytest.mark.parametrize("operator", ["<=", ">=", "<", ">"])
def test_input_when_follows_the_physical_encoder_count(operator: str) -> None:
    program = f"REM @sim input 5 when enc 0 {operator} -500\n"
    assert scenario(program).position_inputs == (PositionInput(5, 0, operator, -500),)  # type: ignore[arg-type]


def test_index_gives_a_pulse_one_count_wide_unless_told() -> None:
    program = "REM @sim index 0 every 4000\nREM @sim index 1 every 2000 width 3\n"
    assert scenario(program).index_pulses == (IndexPulse(0, 4000, 1), IndexPulse(1, 2000, 3))


def test_fastin_and_adc_are_timed() -> None:
    program = "REM @sim fastin 2 at 40\nREM @sim adc 1 -12.5 at 30\n"
    result = scenario(program)
    assert result.fast_inputs == (FastInput(40, 2),)
    assert result.adc == (AdcLevel(30, 1, -12.5),)


def test_key_text_understands_carriage_return_and_line_feed_escapes() -> None:
    program = 'REM @sim key "1\\r" at 200\nREM @sim key "a\\nb" at 300\n'
    assert scenario(program).keys == (Keys(200, "1\r"), Keys(300, "a\nb"))


def test_host_write_and_read_become_packets_for_node_2() -> None:
    program = 'REM @sim host write 10 "10,20" at 100\nREM @sim host read 10 at 110\n'
    assert scenario(program).host_packets == (
        HostPacket(100, encode_write(2, 10, "10,20")),
        HostPacket(110, encode_read(2, 10)),
    )


def test_host_raw_sends_the_bytes_given_in_hex() -> None:
    program = "REM @sim host raw 04 32 32 02 31 30 05 at 120\n"
    assert scenario(program).host_packets == (HostPacket(120, b"\x0422\x0210\x05"),)


def test_timed_records_are_in_time_order_and_equal_times_keep_the_order_written() -> None:
    program = "REM @sim input 1 1 at 30\nREM @sim input 2 1 at 10\nREM @sim input 3 1 at 30\n"
    assert [record.channel for record in scenario(program).inputs] == [2, 1, 3]


# ---------------------------------------------------------------- REM @expect


def test_expect_compares_a_value_within_a_tolerance_at_the_end() -> None:
    (expectation,) = scenario("REM @expect POS.0 = 1000 ± 0.5 at end\n").expectations
    assert expectation == ValueExpectation(
        Target("POS.0", every_axis=False), Comparison.EQUAL, 1000.0, 0.5, None, Origin("program", 1)
    )


@pytest.mark.parametrize(
    ("sentence", "comparison", "tolerance", "at_ms"),
    [
        ("count <> 3", Comparison.NOT_EQUAL, 0.0, None),
        ("count >= 3 at 1500", Comparison.AT_LEAST, 0.0, 1500),
        ("count <= 3 +- 1 at 20 ms", Comparison.AT_MOST, 1.0, 20),
        ("count > 3 at 1500", Comparison.ABOVE, 0.0, 1500),
        ("count < 3", Comparison.BELOW, 0.0, None),
    ],
)
def test_expect_comparisons(sentence: str, comparison: Comparison, tolerance: float, at_ms: int | None) -> None:
    (expectation,) = scenario(f"REM @expect {sentence}\n").expectations
    assert isinstance(expectation, ValueExpectation)
    assert (expectation.comparison, expectation.tolerance, expectation.at_ms) == (comparison, tolerance, at_ms)


def test_expect_no_keyword_means_it_is_zero_on_every_axis() -> None:
    (expectation,) = scenario("REM @expect no AXISERROR\n").expectations
    assert isinstance(expectation, ValueExpectation)
    assert expectation.target == Target("AXISERROR", every_axis=True)
    assert (expectation.comparison, expectation.value) == (Comparison.EQUAL, 0.0)


def test_expect_terminal_contains_and_stopped() -> None:
    program = 'x = 1\nREM @expect terminal contains "Homed\\r\\n" at 50\nREM @expect stopped deadlock\n'
    assert scenario(program).expectations == (
        TerminalExpectation("Homed\r\n", 50, Origin("program", 2)),
        StoppedExpectation("deadlock", Origin("program", 3)),
    )


def test_expectations_keep_the_order_written() -> None:
    program = "REM @expect count = 1 at 50\nREM @expect count = 2 at 10\n"
    assert [e.at_ms for e in scenario(program).expectations] == [50, 10]


def test_the_source_name_is_used_in_positions() -> None:
    result, _ = parse_directives("REM @expect stopped end\n", source="conveyor.mnt")
    assert result.expectations[0].origin == Origin("conveyor.mnt", 1)


# ---------------------------------------------------------------- mistakes


@pytest.mark.parametrize(
    ("directive", "column", "message"),
    [
        ("bogus 1", 10, "expected a directive (drives, plant, input, index, fastin, adc, key, host), not 'bogus'"),
        ("plant 0 wobbly", 18, "expected a plant model (ideal, stalled, velamp, torque), not 'wobbly'"),
        ("plant 0 velamp", 5, "plant velamp needs k"),
        ("plant 0 ideal k=3", 5, "plant ideal has no parameter k (it takes none)"),
        ("plant 0 torque viscous=0", 5, "plant torque: viscous must be positive"),
        ("input 3 2 at 10", 18, "an input level is 0 or 1, not 2"),
        ("input 3 high at 10", 18, "expected a level (0 or 1) or 'when', not 'high'"),
        ("input 3 1.0 at 10", 18, "expected a level (0 or 1) or 'when', not '1.0'"),
        ("input 3 1", 19, "expected 'at' at the end"),
        ("input 3 1 at soon", 23, "expected a time in ms as a whole number, not 'soon'"),
        ("input 3 1 at 5s", 23, "expected a time in ms as a whole number, not '5s'"),
        ("input 3 1 at -5ms", 23, "a time in ms must be at least 0, not -5"),
        ("input 3 1 at -5", 23, "a time in ms must be at least 0, not -5"),
        ("input 5 when enc 0 => 500", 29, "expected a comparison (<=, >=, <, >), not '='"),
        ("input 5 when pos 0 >= 500", 23, "expected 'enc', not 'pos'"),
        ("index 0 every 0", 24, "the counts between index pulses must be at least 1, not 0"),
        ("index 0 every 10 width 10", 33, "an index pulse 10 counts wide does not fit in every 10 counts"),
        ("adc 0 150 at 0", 16, "an ADC level is a percentage from -100 to 100, not 150"),
        ("key 1 at 0", 14, "expected the keys in double quotes, not 1"),
        ('key "\\q" at 0', 14, 'unknown escape \\q in "\\q" (known: \\r \\n \\t \\" \\\\)'),
        ('host write 256 "1" at 0', 5, "cannot build the host packet: comms address 256 does not fit two digits"),
        ("host raw 0g at 0", 5, "raw host bytes are pairs of hex digits such as '04 32 32', not '0g'"),
        ("fastin 0 at 10 extra", 25, "unexpected 'extra' at the end"),
    ],
)
def test_a_bad_directive_is_an_error_at_its_line_and_column(directive: str, column: int, message: str) -> None:
    """At the word at fault (a value the world refuses once read too, at the word of the key a scenario file
    blames), or where the one missing was due; a plant's parameters or a host packet, wrong only together, at
    the ``@`` (the directive as a whole): columns from 1, with the ``@`` at 5 and the first word at 10."""
    assert errors(f"x = 1\nREM @sim {directive}\n") == [ScenarioError("program", 2, message, column)]


@pytest.mark.parametrize(
    ("sentence", "column", "message"),
    [
        ("POS.0 == 3", 20, "expected a value to compare with as a number, not '='"),
        ("POS.0 =", 20, "expected a value to compare with at the end"),
        ("GO = 1", 13, "GO is a command, not a value to expect"),
        ("stopped somewhere", 21, "a run stops for one of end, error, until, deadlock, wall-limit, not 'somewhere'"),
        ("count = 1 ± -1", 25, "a tolerance must be at least 0, not -1"),
        ('terminal has "x"', 22, "expected how the terminal is matched (contains, is), not 'has'"),
        (
            'terminal contians "x"',
            22,
            "expected how the terminal is matched (contains, is), not 'contians'; did you mean 'contains'?",
        ),
    ],
)
def test_a_bad_expectation_is_an_error_at_its_line_and_column(sentence: str, column: int, message: str) -> None:
    """At the word at fault, a value refused whole too: the first word of the sentence is at column 13."""
    assert errors(f"REM @expect {sentence}\n") == [ScenarioError("program", 1, message, column)]


def test_an_axis_given_two_plants_is_an_error_at_the_second() -> None:
    program = "REM @sim plant 0 ideal\nREM @sim plant 0 stalled\n"
    result, problems = parse_directives(program)
    assert problems == [ScenarioError("program", 2, "axis 0 already has a plant (line 1)", 5)]
    assert result.plants == (PlantChoice(0, "ideal"),)


def test_an_input_given_two_position_switches_is_an_error_at_the_second() -> None:
    # only one could decide the input's level: the second used to win silently
    program = "REM @sim input 9 when enc 0 <= -2000\nREM @sim input 9 when enc 0 >= -2100\n"
    _, problems = parse_directives(program)
    assert problems == [ScenarioError("program", 2, "input 9 already follows a position (line 1)", 5)]


def test_every_bad_line_is_reported_and_the_good_ones_are_kept() -> None:
    program = "REM @sim input 1 7 at 0\nREM @sim input 2 1 at 0\nREM @sim adc 0 at 1\n"
    result, problems = parse_directives(program)
    assert [problem.line for problem in problems] == [1, 3]
    assert result.inputs == (InputLevel(0, 2, 1),)


def test_drives_enabled_starts_the_run_with_every_drive_on() -> None:
    scenario, problems = parse_directives("REM @sim drives enabled\n")
    assert (scenario.drives_enabled, problems) == (True, [])
    assert parse_directives("PRINT 1\n")[0].drives_enabled is False


def test_terminal_is_expects_the_whole_output() -> None:
    scenario, _ = parse_directives('REM @expect terminal is "1\\n"\n')
    assert scenario.expectations == (TerminalExpectation("1\n", None, Origin("program", 1), exact=True),)
