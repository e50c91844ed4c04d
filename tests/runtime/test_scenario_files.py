"""Scenario files: the TOML form of stimulus and expectations (``mint-run --stimulus/--expect FILE``)."""

from __future__ import annotations

import os
import re
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path
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
    ScenarioFileError,
    StoppedExpectation,
    TerminalExpectation,
    ValueExpectation,
    load_scenario,
    merge,
    parse_directives,
)
from mintlang.runtime.scenario.targets import Target

EVERY_CONSTRUCT = Path(__file__).parents[1] / "corpus" / "runtime" / "scenarios" / "every_construct.toml"


def write(directory: Path, text: str) -> Path:
    path = directory / "scenario.toml"
    path.write_text(text, encoding="utf-8")
    return path


def problems(directory: Path, text: str) -> list[tuple[int, str]]:
    """The (line, message) of every mistake in a scenario file."""
    with pytest.raises(ScenarioFileError) as raised:
        load_scenario(write(directory, text))
    return [(error.line, error.message) for error in raised.value.errors]


# ---------------------------------------------------------------- every construct


@pytest.fixture(scope="module")
def every() -> Scenario:
    return load_scenario(EVERY_CONSTRUCT)


def test_plant_chooses_a_model_per_axis_with_its_parameters(every: Scenario) -> None:
    assert every.plants == (
        PlantChoice(0, "ideal"),
        PlantChoice(1, "stalled"),
        PlantChoice(2, "velamp", MappingProxyType({"k": 40.0})),
        PlantChoice(3, "torque", MappingProxyType({"gain": 30000.0, "viscous": 5.0})),
    )


def test_inputs_are_timed_levels_in_time_order_or_follow_an_encoder(every: Scenario) -> None:
    assert every.inputs == (InputLevel(200, 3, 0), InputLevel(1500, 3, 1))
    assert every.position_inputs == (PositionInput(5, 0, ">=", 500),)


def test_index_pulses_are_one_count_wide_unless_told(every: Scenario) -> None:
    assert every.index_pulses == (IndexPulse(0, 4000, 1), IndexPulse(1, 2000, 4))


def test_fastin_adc_and_keys(every: Scenario) -> None:
    assert every.fast_inputs == (FastInput(300, 1),)
    assert every.adc == (AdcLevel(100, 0, -12.5),)
    assert every.keys == (Keys(200, "1\r"),)


def test_host_packets_are_built_for_node_2_unless_told(every: Scenario) -> None:
    assert every.host_packets == (
        HostPacket(100, encode_write(2, 10, "10,20")),
        HostPacket(110, encode_read(3, 10)),
        HostPacket(120, bytes.fromhex("04 32 32 02 31 30 05")),
    )


def test_expectations_keep_the_order_written_with_the_line_of_their_table(every: Scenario) -> None:
    source = str(EVERY_CONSTRUCT)
    lines = [n for n, text in enumerate(EVERY_CONSTRUCT.read_text().splitlines(), 1) if text == "[[expect]]"]
    assert every.expectations == (
        ValueExpectation(Target("POS.0", False), Comparison.EQUAL, 1000.0, 0.5, None, Origin(source, lines[0])),
        ValueExpectation(Target("AXISERROR", True), Comparison.EQUAL, 0.0, 0.0, None, Origin(source, lines[1])),
        ValueExpectation(
            Target("COUNT", False, "count"), Comparison.AT_LEAST, 3.0, 0.0, 1500, Origin(source, lines[2])
        ),
        ValueExpectation(Target("OUT.2", False), Comparison.NOT_EQUAL, 1.0, 0.0, None, Origin(source, lines[3])),
        ValueExpectation(
            Target("TABLE(3)", False, "table(3)"), Comparison.AT_MOST, 10.0, 1.0, None, Origin(source, lines[4])
        ),
        TerminalExpectation("Homed", 2000, Origin(source, lines[5])),
        StoppedExpectation("end", Origin(source, lines[6])),
    )


def test_the_file_and_the_same_directives_script_the_same_world(every: Scenario) -> None:
    directives = (
        "plant 0 ideal",
        "plant 1 stalled",
        "plant 2 velamp 40",
        "plant 3 torque gain=30000 viscous=5",
        "input 3 1 at 1500",
        "input 5 when enc 0 >= 500",
        "input 3 0 at 200",
        "index 0 every 4000",
        "index 1 every 2000 width 4",
        "fastin 1 at 300",
        "adc 0 -12.5 at 100",
        'key "1\\r" at 200',
    )
    from_program, errors = parse_directives("".join(f"REM @sim {directive}\n" for directive in directives))
    assert errors == []
    assert from_program == replace(every, host_packets=(), expectations=())


# ---------------------------------------------------------------- program and file together


def test_merge_lets_the_file_choose_plants_and_adds_everything_else() -> None:
    program, _ = parse_directives("REM @sim plant 0 stalled\nREM @sim plant 1 stalled\nREM @sim input 1 1 at 50\n")
    file, _ = parse_directives("REM @sim plant 0 ideal\nREM @sim input 2 1 at 50\nREM @sim input 3 1 at 10\n")
    merged = merge(program, file)
    assert merged.plants == (PlantChoice(0, "ideal"), PlantChoice(1, "stalled"))
    assert [record.channel for record in merged.inputs] == [3, 1, 2]


def test_merge_puts_the_program_expectations_first() -> None:
    program, _ = parse_directives("REM @expect stopped end\n", source="a.mnt")
    file, _ = parse_directives("REM @expect no ERR\n", source="a.toml")
    assert [e.origin.source for e in merge(program, file).expectations] == ["a.mnt", "a.toml"]


# ---------------------------------------------------------------- mistakes, with their lines


def test_above_and_below_are_the_strict_comparisons(tmp_path: Path) -> None:
    text = '[[expect]]\nwhat = "count"\nabove = 2\n\n[[expect]]\nwhat = "count"\nbelow = 9\n'
    comparisons = [(e.comparison, e.value) for e in load_scenario(write(tmp_path, text)).expectations]
    assert comparisons == [(Comparison.ABOVE, 2.0), (Comparison.BELOW, 9.0)]


def test_an_empty_file_is_an_empty_scenario(tmp_path: Path) -> None:
    assert load_scenario(write(tmp_path, "# nothing yet\n")) == Scenario()


def test_a_toml_syntax_error_keeps_tomllib_line_and_column(tmp_path: Path) -> None:
    [(line, message)] = problems(tmp_path, "[[input]]\nchannel = \n")
    assert line == 2
    assert message.startswith("not valid TOML: ") and "(at line 2, column" in message


@pytest.mark.parametrize(
    ("make", "why"),
    [
        pytest.param(lambda path: None, "No such file or directory", id="missing"),
        pytest.param(os.mkfifo, "not a regular file", id="a-pipe-is-not-waited-on"),
        pytest.param(os.mkdir, "not a regular file", id="a-folder"),
    ],
)
def test_a_file_that_cannot_be_read_is_a_scenario_error(tmp_path: Path, make: Callable[[Path], None], why: str) -> None:
    path = tmp_path / "scenario.toml"
    make(path)
    with pytest.raises(ScenarioFileError) as raised:
        load_scenario(path)
    assert str(raised.value) == f"{path}: cannot read the file: {why}"


def test_unknown_tables_and_keys_are_named(tmp_path: Path) -> None:
    text = 'title = "x"\n\n[[input]]\nchannel = 3\nlvl = 1\nat_ms = 0\n\n[[outputs]]\nchannel = 1\n'
    assert problems(tmp_path, text) == [
        (1, "unknown entry 'title'; a scenario has drives, plant, input, index, fastin, adc, key, host, expect"),
        (5, "unknown key 'lvl' in [[input]]; it takes channel, level, at_ms"),
        (8, "unknown entry 'outputs'; a scenario has drives, plant, input, index, fastin, adc, key, host, expect"),
    ]


def test_a_misspelt_key_or_entry_is_named_with_the_word_meant(tmp_path: Path) -> None:
    text = "[[expect]]\nwhat = 'POS.0'\nequals = 1\ntolerence = 0.5\n\n[[expects]]\nstopped = 'end'\n"
    assert problems(tmp_path, text) == [
        (
            4,
            "unknown key 'tolerence' in [[expect]]; it takes what, equals, tolerance, at, at_ms; "
            "did you mean 'tolerance'?",
        ),
        (
            6,
            "unknown entry 'expects'; a scenario has drives, plant, input, index, fastin, adc, key, host, expect; "
            "did you mean 'expect'?",
        ),
    ]


@pytest.mark.parametrize(
    ("entry", "line", "message"),
    [
        ("[[input]]\nchannel = 3\nlevel = 1", 2, "[[input]] needs at_ms"),
        ("[[input]]\nchannel = 3\nlevel = true\nat_ms = 0", 4, "level must be a whole number, not true"),
        ("[[input]]\nchannel = 3\nlevel = 2\nat_ms = 0", 4, "an input level is 0 or 1, not 2"),
        ("[[input]]\nchannel = -1\nlevel = 1\nat_ms = 0", 3, "a channel must be at least 0, not -1"),
        ("[[input]]\nchannel = 3\nlevel = 1\nat_ms = -5", 5, "a time in ms must be at least 0, not -5"),
        (
            "[[input]]\nchannel = 5\nwhen = 'enc 0 >= 5'\nlevel = 1",
            5,
            "unknown key 'level' in [[input]]; it takes channel, when",
        ),
        ("[[input]]\nchannel = 5\nwhen = 'enc x >= 5'", 4, "expected an axis as a whole number, not 'x'"),
        ("[[input]]\nchannel = 5\nwhen = 'enc -1 >= 5'", 4, "an axis must be at least 0, not -1"),
        ("[[index]]\naxis = 0\nevery = 0", 4, "the counts between index pulses must be at least 1, not 0"),
        ("[[index]]\naxis = 0\nevery = 4\nwidth = 4", 5, "an index pulse 4 counts wide does not fit in every 4 counts"),
        ("[[index]]\naxis = -2\nevery = 4", 3, "an axis must be at least 0, not -2"),
        ("[[fastin]]\nchannel = 0\nat_ms = -3", 4, "a time in ms must be at least 0, not -3"),
        ("[[adc]]\nchannel = 0\npercent = 150\nat_ms = 0", 4, "an ADC level is a percentage from -100 to 100, not 150"),
        ("[[host]]\nraw = '0g'\nat_ms = 0", 3, "raw host bytes are pairs of hex digits such as '04 32 32', not '0g'"),
        ("[[host]]\nread = 1\nat_ms = -1", 4, "a time in ms must be at least 0, not -1"),
        ("[[adc]]\nchannel = 0\npercent = 'half'\nat_ms = 0", 4, "percent must be a number, not 'half'"),
        ("[[key]]\ntext = 1\nat_ms = 0", 3, "text must be text in quotes, not 1"),
        ("[[host]]\nat_ms = 0", 2, "[[host]] needs one of write, read, raw (it has 'at_ms')"),
        ("[[host]]\nread = 1\nraw = '05'\nat_ms = 0", 4, "[[host]] has both read and raw"),
        (  # a packet's card ID is one character, 0-9 or A-F, so nodes 0 to 15 (000:2148-2149, 2479)
            "[[host]]\nread = 1\nnode = 16\nat_ms = 0",
            2,
            "cannot build the host packet: node 16 has no ID character (0-9 and A-F are nodes 0 to 15)",
        ),
        (
            '[[host]]\nwrite = 1\ndata = "1é"\nat_ms = 0',
            2,
            "cannot build the host packet: the data must be ASCII text; 'é' at position 1 is not",
        ),
        (
            "[[expect]]\nwaht = 'a'\nequals = 1",
            3,
            "unknown key 'waht' in [[expect]], which needs one of what, terminal_contains, terminal_is, stopped;"
            " did you mean 'what'?",
        ),
        (
            "[[expect]]\nvalue = 'a'\nequals = 1",
            2,
            "[[expect]] needs one of what, terminal_contains, terminal_is, stopped (it has 'value', 'equals')",
        ),
        ("[[expect]]\nwhat = 'POS.0'\nequals = 1\ntolerance = -1", 5, "a tolerance must be at least 0, not -1"),
        ("[[expect]]\nwhat = 'POS.0'\nequals = 1\nat_ms = -1", 5, "a time in ms must be at least 0, not -1"),
        ("[[expect]]\nterminal_contains = ''", 3, "the terminal text to look for is empty"),
        (
            "[[expect]]\nstopped = 'never'",
            3,
            "a run stops for one of end, error, until, deadlock, wall-limit, not 'never'",
        ),
        (
            "[[expect]]\nwhat = 'POS.0'",
            2,
            "[[expect]] needs one of equals, not_equal, at_least, at_most, above, below (it has 'what')",
        ),
        (
            "[[expect]]\nwhat = 'POS.0'\nequals = 1\nat = 'start'",
            5,
            "at is \"end\"; for a time write at_ms = <ms>, not at = 'start'",
        ),
        ("[[expect]]\nwhat = 'POS.0'\nequals = 1\nat = 'end'\nat_ms = 5", 6, "[[expect]] has both at and at_ms"),
        ("[[expect]]\nequals = 1\nwhat = 'SIN'", 4, "SIN is a function, not a value to expect"),
        ("[[expect]]\nstopped = 'end'\nat_ms = 5", 4, "unknown key 'at_ms' in [[expect]]; it takes stopped"),
        ("[plant]\nx = 'ideal'", 3, "the keys of [plant] are axis numbers, not 'x'"),
        ("[plant]\n0 = 'velamp'", 3, "plant velamp needs k"),
        (
            "[plant]\n0 = { model = 'torque', mass = 3 }",
            3,
            "plant torque has no parameter mass (it takes gain, viscous, coulomb)",
        ),
        ("[plant]\n0 = 3", 3, 'plant 0 is a model ("ideal") or a table ({ model = "velamp", k = 40 })'),
        (
            "[[index]]\naxis = 0\nevery = 10\n[[index]]\naxis = 0\nevery = 20",
            5,
            "axis 0 already has an index pulse (line 2)",
        ),
        ("[input]\nchannel = 3", 2, "input is a list of tables: write [[input]]"),
        ("plant = 3", 2, "plant is a table: write [plant]"),
    ],
)
def test_a_mistake_is_reported_at_its_line(tmp_path: Path, entry: str, line: int, message: str) -> None:
    assert problems(tmp_path, f"# scenario\n{entry}\n") == [(line, message)]


def test_every_mistake_of_a_file_is_reported_at_once_in_line_order(tmp_path: Path) -> None:
    text = "[[expect]]\nstopped = 'never'\n\n[plant]\n0 = 'wobbly'\n"
    assert [line for line, _ in problems(tmp_path, text)] == [2, 5]


def test_the_error_message_lists_file_and_line(tmp_path: Path) -> None:
    path = write(tmp_path, "[[key]]\ntext = ''\nat_ms = 0\n")
    with pytest.raises(ScenarioFileError) as raised:
        load_scenario(path)
    assert raised.value.errors == (ScenarioError(str(path), 2, "the keys to type are empty"),)
    assert str(raised.value) == f"{path}:2: the keys to type are empty"


# ---------------------------------------------------------------- the documentation

README = Path(__file__).parents[2] / "runtime" / "scenario" / "README.md"


def readme_blocks(language: str) -> list[str]:
    return re.findall(rf"^```{language}\n(.*?)^```", README.read_text(encoding="utf-8"), re.MULTILINE | re.DOTALL)


def test_the_toml_example_of_the_readme_loads(tmp_path: Path) -> None:
    (example,) = readme_blocks("toml")
    assert load_scenario(write(tmp_path, example)).expectations


def test_the_directive_example_of_the_readme_reads_without_errors() -> None:
    (example,) = readme_blocks("mint")
    scenario, errors = parse_directives(example)
    assert errors == []
    assert len(scenario.records()) == example.count("REM @")


def test_drives_enabled_and_the_whole_terminal_output_can_be_written_in_a_file(tmp_path: Path) -> None:
    scenario = load_scenario(write(tmp_path, 'drives = "enabled"\n[[expect]]\nterminal_is = """\n1\n"""\n'))
    assert scenario.drives_enabled
    assert scenario.expectations == (TerminalExpectation("1\n", None, scenario.expectations[0].origin, exact=True),)


def test_drives_takes_only_enabled(tmp_path: Path) -> None:
    with pytest.raises(ScenarioFileError, match='drives is "enabled"'):
        load_scenario(write(tmp_path, 'drives = "on"\n'))
