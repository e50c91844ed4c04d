"""``mint test``: which programs are tests, how each is judged, and what the reports say."""

from __future__ import annotations

import json
from pathlib import Path
from xml.etree import ElementTree

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main
from mintlang.runtime.testing.discovery import discover

PASSING = "REM @expect a = 2\nDIM a\na = 1 + 1\n"
FAILING = "REM @expect a = 3\nDIM a\na = 1 + 1\n"
REFUSED = "REM @expect a = 1\nDIM a\nFOR a = 1 TO 2\n"  # a FOR without NEXT: the compiler refuses it (2009)


def _write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def _mint_test(*arguments: str | Path) -> Result:
    return CliRunner().invoke(main, ["test", "-j", "1", *(str(argument) for argument in arguments)])


def test_a_program_is_a_test_with_expectations_in_it_or_a_scenario_file_beside_it(tmp_path: Path) -> None:
    _write(tmp_path, "inline.mnt", PASSING)
    _write(tmp_path, "Beside.MNT", "DIM a\n")
    _write(tmp_path, "beside.scenario.toml", '[[expect]]\nwhat = "a"\nequals = 0\n')
    _write(tmp_path, "plain.mnt", "DIM a\n")
    _write(tmp_path, "cell.cfg", "REM @expect a = 1\n")  # a configuration file is never a test of its own
    cases, unreadable = discover([tmp_path])
    found = [(case.program.name, case.scenario.name if case.scenario else None) for case in cases]
    assert found == [("Beside.MNT", "beside.scenario.toml"), ("inline.mnt", None)]
    assert unreadable == []


def test_a_program_whose_only_expectation_is_misspelt_is_a_test_in_error(tmp_path: Path) -> None:
    """Taken for a plain program, it would drop out of the run without a word."""
    program = _write(tmp_path, "typo.mnt", "DIM a\nREM @expext a = 1\n")
    result = _mint_test(tmp_path, "--color", "never")
    assert result.exit_code == 1
    expected = f"ERROR  {program}  {program}:2:5: unknown directive '@expext'; did you mean '@expect'?"
    assert result.output.splitlines()[0] == expected


def test_each_test_is_passed_failed_or_an_error_and_the_summary_counts_them(tmp_path: Path) -> None:
    _write(tmp_path, "a_passes.mnt", PASSING)
    _write(tmp_path, "b_fails.mnt", FAILING)
    _write(tmp_path, "c_refused.mnt", REFUSED)
    result = _mint_test(tmp_path, "--color", "never")
    lines = result.output.splitlines()
    assert result.exit_code == 1
    assert lines[0] == f"PASSED {tmp_path / 'a_passes.mnt'}"
    assert lines[1] == f"FAILED {tmp_path / 'b_fails.mnt'}  1 of 1 expectations failed"
    assert lines[2].startswith("    a at end: expected = 3, got 2 (off by -1) [")
    assert lines[3].startswith(f"ERROR  {tmp_path / 'c_refused.mnt'}  ")
    assert lines[-1].startswith("1 passed, 1 failed, 1 error in ")


def test_junit_has_a_testcase_per_program_with_its_failure_or_error(tmp_path: Path) -> None:
    _write(tmp_path, "a_passes.mnt", PASSING)
    _write(tmp_path, "b_fails.mnt", FAILING)
    _write(tmp_path, "c_refused.mnt", REFUSED)
    suite = ElementTree.fromstring(_mint_test(tmp_path, "--format", "junit").output).find("testsuite")
    assert suite is not None
    assert (suite.get("tests"), suite.get("failures"), suite.get("errors")) == ("3", "1", "1")
    cases = {case.get("name"): case for case in suite.iter("testcase")}
    assert sorted(cases) == ["a_passes.mnt", "b_fails.mnt", "c_refused.mnt"]
    assert list(cases["a_passes.mnt"]) == []
    failure = cases["b_fails.mnt"].find("failure")
    assert failure is not None and failure.text is not None and "expected = 3, got 2" in failure.text
    assert cases["c_refused.mnt"].find("error") is not None
    assert cases["b_fails.mnt"].get("classname") == str(tmp_path)


def test_json_counts_the_verdicts_and_keeps_each_check(tmp_path: Path) -> None:
    _write(tmp_path, "a_passes.mnt", PASSING)
    _write(tmp_path, "b_fails.mnt", FAILING)
    report = json.loads(_mint_test(tmp_path, "--format", "json").output)
    assert report["summary"] == {"passed": 1, "failed": 1, "error": 0}
    (check,) = report["tests"][1]["checks"]
    assert (check["what"], check["expected"], check["actual"], check["held"]) == ("a", "= 3", "2", False)


def test_a_scenario_file_gives_the_stimulus_and_the_expectations(tmp_path: Path) -> None:
    _write(tmp_path, "press.mnt", "DIM seen\nPAUSE IN.0 = 1\nseen = TIME\n")
    _write(
        tmp_path,
        "press.scenario.toml",
        '[[input]]\nchannel = 0\nat_ms = 40\nlevel = 1\n\n[[expect]]\nwhat = "seen"\nequals = 40\n',
    )
    result = _mint_test(tmp_path)
    assert result.exit_code == 0, result.output


def test_no_test_found_exits_5_and_a_missing_path_exits_2(tmp_path: Path) -> None:
    _write(tmp_path, "plain.mnt", "DIM a\n")
    nothing = _mint_test(tmp_path)
    assert nothing.exit_code == 5
    missing = _mint_test(tmp_path / "absent")
    assert missing.exit_code == 2
    assert f"mint test: {tmp_path / 'absent'}: no such file or folder" in missing.output


@pytest.mark.parametrize("controller", ["foo", "nextmove"], ids=["no controller", "a family, not a model"])
def test_an_unknown_controller_is_a_usage_error_as_for_mint_run(tmp_path: Path, controller: str) -> None:
    """The README's exit status 2 for a usage problem: not an error of every test found, then exit 1."""
    _write(tmp_path, "a_passes.mnt", PASSING)
    result = _mint_test(tmp_path, "--controller", controller)
    assert result.exit_code == 2
    assert f"Invalid value for '--controller': '{controller}' is not one of 'nextmove-pci'" in result.output


def test_a_controller_of_the_v3_guide_is_taken_with_dialect_v3(tmp_path: Path) -> None:
    _write(tmp_path, "a_passes.mnt", "REM @expect x = 1\nx = 1\nEND\n")  # v3 declares by assigning
    assert _mint_test(tmp_path, "--controller", "euroservo", "--dialect", "v3").exit_code == 0


def test_the_dialect_comes_from_the_settings_file_unless_given(tmp_path: Path) -> None:
    _write(tmp_path, "mint.toml", 'dialect = "mintmt"\n')
    _write(tmp_path, "blocks.mnt", 'REM @expect terminal is "a\\n"\nPrint "a"  \' MintMT\'s comment\n')
    assert _mint_test(tmp_path).exit_code == 0
    assert _mint_test(tmp_path, "--dialect", "v4").exit_code == 1


def test_an_entry_named_like_a_program_that_is_not_a_file_is_reported_and_exits_2(tmp_path: Path) -> None:
    _write(tmp_path, "a_passes.mnt", PASSING)
    (tmp_path / "gone.mnt").symlink_to(tmp_path / "nowhere.mnt")
    result = _mint_test(tmp_path)
    assert result.exit_code == 2
    assert f"mint test: {tmp_path / 'gone.mnt'}: a link to nothing" in result.output
    assert "1 passed" in result.output


def test_a_binary_file_is_unreadable_as_mint_check_and_mint_run_say_and_exits_2(tmp_path: Path) -> None:
    binary = tmp_path / "bin.mnt"
    binary.write_bytes(b"PRINT 1\n\0\0")  # the first NUL byte opens line 2
    alone = _mint_test(binary)
    assert alone.exit_code == 2
    assert f"mint test: {binary}:2:1: not Mint text (a NUL byte)\n" in alone.output
    _write(tmp_path, "a_passes.mnt", PASSING)
    beside_a_test = _mint_test(tmp_path)
    assert beside_a_test.exit_code == 2
    assert f"mint test: {binary}:2:1: not Mint text (a NUL byte)\n" in beside_a_test.output
    assert "1 passed" in beside_a_test.output


def test_mintmt_directives_may_be_written_with_its_quote_comment(tmp_path: Path) -> None:
    _write(tmp_path, "quoted.mnt", "' @expect a = 2\nDim a\na = 2  ' @expect terminal is \"\"\n")
    assert _mint_test(tmp_path, "--dialect", "mintmt").exit_code == 0


def test_collect_only_lists_the_tests_and_runs_none(tmp_path: Path) -> None:
    _write(tmp_path, "a_fails.mnt", FAILING)
    _write(tmp_path, "b.mnt", "DIM a\n")
    _write(tmp_path, "b.scenario.toml", '[[expect]]\nwhat = "a"\nequals = 0\n')
    _write(tmp_path, "plain.mnt", "DIM a\n")
    listed = _mint_test(tmp_path, "--collect-only")
    assert listed.exit_code == 0  # a failing test is listed, not run
    assert listed.output == f"{tmp_path / 'a_fails.mnt'}\n{tmp_path / 'b.mnt'} ({tmp_path / 'b.scenario.toml'})\n"
    data = json.loads(_mint_test(tmp_path, "--collect-only", "--format", "json").output)
    assert data == {
        "tests": [
            {"program": str(tmp_path / "a_fails.mnt"), "scenario": None},
            {"program": str(tmp_path / "b.mnt"), "scenario": str(tmp_path / "b.scenario.toml")},
        ]
    }
    refused = _mint_test(tmp_path, "--collect-only", "--format", "junit")
    assert refused.exit_code == 2 and "--collect-only lists the tests as text or json" in refused.output


def test_jobs_zero_runs_on_every_core_as_mint_check_takes_it(tmp_path: Path) -> None:
    program = _write(tmp_path, "passes.mnt", PASSING)
    result = CliRunner().invoke(main, ["test", str(program), "-j", "0", "--color", "never"])
    assert result.exit_code == 0, result.output
    assert result.output.splitlines()[0] == f"PASSED {program}"


def test_a_scenario_file_with_no_program_of_its_name_is_reported_and_the_other_tests_run(tmp_path: Path) -> None:
    # "conveyer" is misspelt: its scenario would otherwise never run, and the suite would pass without it.
    _write(tmp_path, "conveyor.mnt", PASSING)
    _write(tmp_path, "conveyer.scenario.toml", '[[expect]]\nwhat = "a"\nequals = 1\n')
    result = _mint_test(tmp_path, "--color", "never")
    assert result.exit_code == 2
    orphan = tmp_path / "conveyer.scenario.toml"
    assert f"mint test: {orphan}: no program conveyer.mnt beside it, so it runs nothing" in result.output
    assert f"PASSED {tmp_path / 'conveyor.mnt'}" in result.output


# Line 4 reads a(9) of a(3): R2016 ends the run there, before line 5 sets b, so the expectation fails too.
STOPPED_BY_AN_ERROR = "REM @expect b = 1\nDIM a(3)\nDIM b\nb = a(9)\nb = 1\n"
INVALID_INDEX = "R2016: PROGRAM Invalid index (index 9 outside 1 to 3) [line 4]"


def test_a_test_failing_an_expectation_and_stopped_by_an_error_reports_both(tmp_path: Path) -> None:
    program = _write(tmp_path, "broken.mnt", STOPPED_BY_AN_ERROR)
    lines = _mint_test(program, "--color", "never").output.splitlines()
    assert lines[0] == f"FAILED {program}  1 of 1 expectations failed"
    assert lines[1].startswith("    b at end: expected = 1, got 0 (off by -1) [")
    assert lines[2] == f"    stopped error at {program}:4: {INVALID_INDEX}"
    suite = ElementTree.fromstring(_mint_test(program, "--format", "junit").output).find("testsuite")
    assert suite is not None
    failure = suite.find("testcase/failure")
    assert failure is not None and failure.text is not None
    assert failure.text.splitlines()[1] == f"stopped error at {program}:4: {INVALID_INDEX}"
    (test,) = json.loads(_mint_test(program, "--format", "json").output)["tests"]
    assert (test["place"], test["stop_failed"]) == (f"{program}:4", True)  # the editor's Testing view shows both


@pytest.mark.parametrize(
    ("program", "configuration", "at", "report"),
    [
        pytest.param(
            "REM @expect a = 1\nDIM a\nDIM t(3)\na = 1\nt(5) = 2\n",
            None,
            "cell.mnt:5",
            "FAILED {program}  stopped error at {place}: "
            "R2016: PROGRAM Invalid index (index 5 outside 1 to 3) [line 5]",
            id="a run-time error in the program: the program's line",
        ),
        pytest.param(
            "REM @expect x = 0\nDIM x\n",
            "DIM t2(2)\nt2(4) = 1\n",
            "cell.cfg:2",
            "FAILED {program}  stopped error at {place}: "
            "R2016: CONFIGURATION Invalid index (index 4 outside 1 to 2) [line 2]",
            id="a run-time error in the configuration file: that file's line, not the program's",
        ),
        pytest.param(
            "REM @expect a = 1\nDIM a\nFOR a = 1 TO 2\n",
            None,
            "cell.mnt:3",
            "ERROR  {program}  {place}: C2009: PROGRAM NEXT w/o FOR: this FOR block is never closed with NEXT [line 3]",
            id="a program the compiler refuses: the line it refuses",
        ),
        pytest.param(
            "REM @expect a = 1\nDIM a\n",
            "DIM q\nq = (1\n",
            "cell.cfg:2",
            "ERROR  {program}  {place}: C2003: CONFIGURATION Syntax error: a ')' is missing [line 2]",
            id="a configuration file the compiler refuses: its line",
        ),
        pytest.param(
            "REM @expect a = 1\nDIM a\na = 1\nINPUT a\n",
            None,
            "cell.mnt:4",
            "FAILED {program}  stopped deadlock at {place}: blocked, and nothing scheduled or moving can ever wake "
            "the program: INPUT waits for keys that no scenario types (a [[key]] entry, or REM @sim key)",
            id="a deadlock: the statement that waits for ever",
        ),
    ],
)
def test_a_run_stopped_short_is_reported_at_the_file_and_line_it_stopped(
    tmp_path: Path, program: str, configuration: str | None, at: str, report: str
) -> None:
    """The controller's message names only PROGRAM or CONFIGURATION and a line; the report names the file, as each
    expectation's [file:line] does, so a terminal, a CI server or an editor can go there."""
    tested = _write(tmp_path, "cell.mnt", program)
    if configuration is not None:
        _write(tmp_path, "cell.cfg", configuration)
    place = str(tmp_path / at)
    text = _mint_test(tested, "--color", "never").output.splitlines()
    assert text[0] == report.format(program=tested, place=place)
    (test,) = json.loads(_mint_test(tested, "--format", "json").output)["tests"]
    assert test["place"] == place
    suite = ElementTree.fromstring(_mint_test(tested, "--format", "junit").output)
    outcome = suite.find("testsuite/testcase/failure")
    outcome = outcome if outcome is not None else suite.find("testsuite/testcase/error")
    assert outcome is not None and place in (outcome.get("message") or "")


def test_a_run_that_ends_by_itself_has_no_place_to_point_at(tmp_path: Path) -> None:
    _write(tmp_path, "b_fails.mnt", FAILING)
    (test,) = json.loads(_mint_test(tmp_path, "--format", "json").output)["tests"]
    assert (test["stopped"], test["place"], test["stop_failed"]) == ("end", None, False)


def test_an_error_that_a_stopped_expectation_asks_for_is_not_reported_as_a_failure(tmp_path: Path) -> None:
    program = _write(
        tmp_path, "broken.mnt", STOPPED_BY_AN_ERROR.replace("b = 1\n", "b = 1\nREM @expect stopped error\n", 1)
    )
    lines = _mint_test(program, "--color", "never").output.splitlines()
    assert lines[0] == f"FAILED {program}  1 of 2 expectations failed"
    assert lines[1].startswith("    b at end: expected = 1, got 0 (off by -1) [")
    assert lines[2].startswith("1 failed in ")


def test_quiet_reports_only_the_tests_that_did_not_pass_and_no_count(tmp_path: Path) -> None:
    _write(tmp_path, "a_passes.mnt", PASSING)
    _write(tmp_path, "b_fails.mnt", FAILING)
    result = _mint_test(tmp_path, "--color", "never", "-q", "--coverage", "--lcov", tmp_path / "lcov.info")
    assert result.exit_code == 1
    assert result.output.splitlines() == [
        f"FAILED {tmp_path / 'b_fails.mnt'}  1 of 1 expectations failed",
        f"    a at end: expected = 3, got 2 (off by -1) [{tmp_path / 'b_fails.mnt'}:1]",
    ]
    assert (tmp_path / "lcov.info").is_file()  # the tracefile is still written, only the table is left out


def test_verbose_shows_every_expectation_under_its_test(tmp_path: Path) -> None:
    _write(tmp_path, "a_passes.mnt", PASSING)
    lines = _mint_test(tmp_path, "--color", "never", "--verbose").output.splitlines()
    assert lines[:2] == [
        f"PASSED {tmp_path / 'a_passes.mnt'}",
        f"    a at end: 2, as expected [{tmp_path / 'a_passes.mnt'}:1]",
    ]
    assert lines[2].startswith("1 passed in ")


def test_quiet_and_verbose_together_are_a_usage_error(tmp_path: Path) -> None:
    _write(tmp_path, "a_passes.mnt", PASSING)
    assert _mint_test(tmp_path, "-q", "-v").exit_code == 2


@pytest.mark.parametrize(
    ("program", "scenario", "at"),
    [
        pytest.param("PRINT 1\nREM @expect x >< 3\n", None, "cell.mnt:2", id="a directive that cannot be read"),
        pytest.param("PRINT 1\n", '[[expect]]\nwhat = "terminal\n', "cell.scenario.toml:2", id="a line of bad TOML"),
    ],
)
def test_a_test_whose_expectations_cannot_be_read_points_at_the_line(
    tmp_path: Path, program: str, scenario: str | None, at: str
) -> None:
    """The error names the file and line in its message; the JSON report's place, which the editor's Testing
    view follows, gives the same ``file:line``."""
    tested = _write(tmp_path, "cell.mnt", program)
    if scenario is not None:
        _write(tmp_path, "cell.scenario.toml", scenario)
    (test,) = json.loads(_mint_test(tested, "--format", "json").output)["tests"]
    assert (test["verdict"], test["place"]) == ("error", str(tmp_path / at))
    assert test["message"].startswith(str(tmp_path / at))


def test_a_target_the_simulator_has_no_value_for_says_why_not_that_it_is_missing(tmp_path: Path) -> None:
    # Mint v3's ERR before any error: the v3 guide gives it no value, and the simulator stops on reading it
    _write(tmp_path, "early.mnt", "REM @expect ERR = 0\nA = 1\n")
    result = _mint_test("--dialect", "v3", tmp_path)
    assert result.exit_code == 1
    reason = "ERR (read before any error, or after one on no axis: the guide gives no value) is not simulated"
    assert f"got missing ({reason} by mint-run)" in result.stdout
    assert "no such thing" not in result.stdout
