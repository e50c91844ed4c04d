"""Checking expectations against what a run shows, and the table ``mint-run --expect`` prints."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import pytest
from rich.console import Console

from mintlang.runtime.scenario import (
    Expectation,
    Observer,
    Outcome,
    Scenario,
    all_held,
    evaluate,
    expectations_at,
    parse_directives,
    render_outcomes,
)
from mintlang.runtime.scenario.expectations import NO_SUCH_THING


@dataclass(frozen=True, slots=True)
class FakeRun:
    """An ``Observer`` with fixed answers."""

    values: Mapping[str, float] = field(default_factory=dict)
    terminal: str = ""
    stopped: str = "end"
    axes: tuple[int, ...] = (0, 1, 2, 3)

    @property
    def printed(self) -> int:
        return len(self.terminal)

    def has_printed(self, text: str) -> bool:
        return text in self.terminal

    def value(self, target: str) -> float | None:
        return self.values.get(target)

    def why_unread(self, target: str) -> str:
        return NO_SUCH_THING


def expect(sentence: str) -> Expectation:
    """The expectation a ``REM @expect`` line states."""
    scenario, errors = parse_directives(f"REM @expect {sentence}\n")
    assert errors == []
    (expectation,) = scenario.expectations
    return expectation


def check(sentence: str, run: Observer) -> Outcome:
    return evaluate(expect(sentence), run)


def test_fake_run_is_an_observer() -> None:
    observer: Observer = FakeRun()
    assert observer.axes == (0, 1, 2, 3)


# ---------------------------------------------------------------- values


@pytest.mark.parametrize(
    ("actual", "held"),
    [(1000.0, True), (1000.5, True), (999.5, True), (1000.51, False), (999.4, False)],
)
def test_equality_holds_within_the_tolerance(actual: float, held: bool) -> None:
    assert check("POS.0 = 1000 ± 0.5", FakeRun({"POS.0": actual})).held is held


def test_equality_without_tolerance_is_exact() -> None:
    assert check("count = 3", FakeRun({"COUNT": 3.0})).held
    assert not check("count = 3", FakeRun({"COUNT": 3.000001})).held


@pytest.mark.parametrize(
    ("sentence", "held"),
    [
        ("count <> 3", False),
        ("count <> 2", True),
        ("count <> 2 ± 1", False),
        ("count >= 3", True),
        ("count >= 4", False),
        ("count >= 4 ± 1", True),
        ("count <= 3", True),
        ("count <= 2", False),
        ("count > 2", True),
        ("count > 3", False),
        ("count > 4 ± 1.5", True),
        ("count < 4", True),
        ("count < 3", False),
        ("count < 2 ± 1.5", True),
    ],
)
def test_comparisons(sentence: str, held: bool) -> None:
    assert check(sentence, FakeRun({"COUNT": 3.0})).held is held


def test_a_failed_equality_says_by_how_much() -> None:
    outcome = check("POS.0 = 1000 ± 0.5", FakeRun({"POS.0": 997.0}))
    assert (outcome.held, outcome.actual, outcome.detail) == (False, "997", "off by -3")


def test_an_axis_keyword_without_its_axis_must_hold_on_every_axis() -> None:
    run = FakeRun({"AXISERROR.0": 0, "AXISERROR.1": 4, "AXISERROR.2": 0}, axes=(0, 1, 2))
    outcome = check("no AXISERROR", run)
    assert not outcome.held
    assert outcome.actual == "AXISERROR.0 = 0, AXISERROR.1 = 4, AXISERROR.2 = 0"
    assert outcome.detail == "fails on AXISERROR.1"


def test_every_axis_holds_when_each_axis_holds_and_one_value_is_shown_once() -> None:
    run = FakeRun({"POS.0": 10, "POS.1": 10}, axes=(0, 1))
    outcome = check("POS = 10", run)
    assert (outcome.held, outcome.actual) == (True, "10 on every axis")


def test_a_channel_keyword_without_a_channel_is_the_whole_word() -> None:
    assert check("OUT = 5", FakeRun({"OUT": 5})).held


def test_targets_are_asked_for_in_one_spelling() -> None:
    run = FakeRun({"POS.1": 1, "OUT.3": 1, "COMMS(5)": 1, "TABLE(1,2)": 1, "COUNT": 1})
    for written in ("pos.1", "PS.1", "OUT3", "out.3", "comms( 5 )", "table(1, 2)", "Count"):
        assert check(f"{written} = 1", run).held, written


@pytest.mark.parametrize(
    ("written", "named"),
    [
        pytest.param("count = 3", "count", id="a variable, as the program spells it"),
        pytest.param("myTable(9) = 3", "myTable(9)", id="an array element, as the program spells it"),
        pytest.param("ps.40 = 3", "POS.40", id="a keyword, by its full name"),
    ],
)
def test_a_missing_target_fails_and_says_so_naming_it_as_the_report_does(written: str, named: str) -> None:
    """The report's line names the target as written (357772e); its detail named it in upper case too."""
    outcome = check(written, FakeRun())
    assert (outcome.held, outcome.actual, outcome.detail) == (False, "missing", f"no such thing in this run: {named}")


def test_a_missing_axis_fails_the_every_axis_expectation() -> None:
    outcome = check("POS = 0", FakeRun({"POS.0": 0}, axes=(0, 1)))
    assert (outcome.held, outcome.detail) == (False, "no such thing in this run: POS.1")


# ---------------------------------------------------------------- terminal and stop


def test_terminal_contains_looks_anywhere_in_the_output() -> None:
    run = FakeRun(terminal="Homing\r\nHomed axis 0\r\nready\r\n")
    assert check('terminal contains "Homed"', run).held
    assert check('terminal contains "Homed axis 0\\r\\nready"', run).held


def test_terminal_that_lacks_the_text_fails_and_shows_the_last_line() -> None:
    outcome = check('terminal contains "Homed"', FakeRun(terminal="Homing\r\nfault 3\r\n"))
    assert (outcome.held, outcome.actual) == (False, "last line 'fault 3'")
    assert outcome.detail == "not among the 17 characters printed"


def test_stopped_compares_why_the_run_stopped() -> None:
    assert check("stopped end", FakeRun(stopped="end")).held
    outcome = check("stopped end", FakeRun(stopped="deadlock"))
    assert (outcome.held, outcome.actual) == (False, "deadlock")


# ---------------------------------------------------------------- when to check, and the verdict


def test_expectations_at_lists_each_time_to_pause_once_in_order() -> None:
    program = "REM @expect count = 1 at 50\nREM @expect count = 2 at 10\nREM @expect count = 3 at 50\n"
    scenario, _ = parse_directives(program + "REM @expect stopped end\n")
    assert expectations_at(scenario) == (10, 50)
    assert expectations_at(Scenario()) == ()


def test_all_held_needs_every_outcome() -> None:
    held = check("count = 1", FakeRun({"COUNT": 1}))
    failed = check("count = 2", FakeRun({"COUNT": 1}))
    assert all_held([held, held])
    assert not all_held([held, failed])
    assert all_held([])


def test_the_table_shows_each_expectation_and_a_summary() -> None:
    program = 'REM @expect POS.0 = 1000 ± 0.5 at end\nREM @expect terminal contains "Homed" at 1500\n'
    scenario, _ = parse_directives(program, source="conveyor.mnt")
    run = FakeRun({"POS.0": 1000.25}, terminal="Homing\n")
    console = Console(record=True, width=100)
    render_outcomes([evaluate(expectation, run) for expectation in scenario.expectations], console)
    text = console.export_text()
    header = [cell.strip() for cell in text.splitlines()[1].strip("┃").split("┃")]
    assert header == ["expectation", "when", "expected", "actual", "result"]
    assert "POS.0" in text and "conveyor.mnt:1" in text and "= 1000 ± 0.5" in text and "1000.25" in text
    assert "1500 ms" in text and "contains 'Homed'" in text and "last line 'Homing'" in text
    assert "✓" in text and "✗" in text
    assert text.rstrip().splitlines()[-1] == "1 of 2 expectations failed."


def test_a_narrow_table_folds_the_origin_and_keeps_its_line_number() -> None:
    scenario, _ = parse_directives('REM @expect terminal contains "a fairly long text"\n', source="x" * 40 + ".mnt")
    console = Console(record=True, width=60)
    render_outcomes([evaluate(expectation, FakeRun()) for expectation in scenario.expectations], console)
    rows = console.export_text().splitlines()[3:-2]  # between the header's rule and the closing rule and verdict
    first_column = "".join(row.split("│")[1].strip() for row in rows)
    assert first_column == "terminal" + "x" * 40 + ".mnt:1"


def test_an_origin_that_fits_in_a_third_of_the_width_is_shown_on_one_line() -> None:
    # 20 characters in an 80-column table (a third is 26), beside text that would otherwise take the room.
    scenario, _ = parse_directives(f'REM @expect terminal contains "{"word " * 12}"\n', source="cell.scenario.toml")
    console = Console(record=True, width=80)
    render_outcomes([evaluate(expectation, FakeRun()) for expectation in scenario.expectations], console)
    assert "│ cell.scenario.toml:1 " in console.export_text()


def test_the_summary_when_all_held() -> None:
    console = Console(record=True, width=100)
    render_outcomes([check("count = 1", FakeRun({"COUNT": 1}))], console)
    assert console.export_text().rstrip().splitlines()[-1] == "The expectation held."


def test_terminal_is_holds_only_for_the_whole_output_and_says_where_it_differs() -> None:
    assert check('terminal is "1\\n2\\n"', FakeRun(terminal="1\n2\n")).held
    assert not check('terminal is "1\\n"', FakeRun(terminal="1\n2\n")).held
    outcome = check('terminal is "1\\n3\\n"', FakeRun(terminal="1\n2\n"))
    assert (outcome.held, outcome.detail) == (False, "differs on line 2, column 1: expected '3\\n', printed '2\\n'")
    assert check('terminal is ""', FakeRun(terminal="")).held


def test_where_terminal_is_fails_shows_the_line_from_its_start_with_the_column() -> None:
    # "two" and "three" agree on "t": the second line parts at its column 2, and both lines are shown whole.
    outcome = check('terminal is "one\\nthree\\n"', FakeRun(terminal="one\ntwo\n"))
    assert outcome.detail == "differs on line 2, column 2: expected 'three\\n', printed 'two\\n'"
    # A long line is shown from 20 characters before the place where the two part.
    outcome = check(f'terminal is "{"x" * 30}a"', FakeRun(terminal=f"{'x' * 30}b"))
    assert outcome.detail == f"differs on line 1, column 31: expected '{'x' * 20}a', printed '{'x' * 20}b'"
