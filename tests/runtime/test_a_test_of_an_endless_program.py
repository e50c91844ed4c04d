"""A test of a program that never ends by itself (a machine's main loop) ends at its last check.

When every expectation is timed, nothing is left to check after the last one: ``mint test`` and
``mint-run --expect`` end the run there, as ``until``, a normal stop. Before, such a run went on to
the wall-clock limit and failed on it. An expectation at the end of the run (``stopped`` included)
still needs the program to end by itself, and ``--until-ms`` given is kept.

The program waits 250 ms per pass (WAIT takes milliseconds, 000:17336-17337), so by 1100 ms four passes
are done and ``count`` is 4.

A machine idle at its last check, waiting on an input for a part that never comes, is blocked for good
once the last part has passed; it too ends at its last check, as ``until``: it stopped there as a
deadlock and the test failed. Inputs are level from their ``at`` time on (the scenario README's stimulus
table) and a digital input is level triggered by default, so ``PAUSE IN.1`` passes while it is high
(000:4085-4086): two parts pass by 250 ms.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from click.testing import CliRunner, Result

from mintlang.cli import main
from tests.runtime.invoking import mint_run, write

ENDLESS = "DIM count = 0\nLOOP\n  WAIT = 250\n  count = count + 1\nENDL\n"
TIMED = "REM @expect count = 4 at 1100\n"
IDLE = (
    "REM @sim input 1 1 at 100\nREM @sim input 1 0 at 150\nREM @sim input 1 1 at 200\nREM @sim input 1 0 at 250\n"
    "DIM count = 0\nLOOP\n  PAUSE IN.1\n  count = count + 1\n  PAUSE IN.1 = 0\nENDL\n"
)


def _mint_test(folder: Path, text: str, *options: str) -> Result:
    program = write(folder, "machine.mnt", text)
    arguments = ["test", "-j", "1", "--format", "json", "--max-wall-s", "2", *options, str(program)]
    return CliRunner().invoke(main, arguments)


def _only_test(result: Result) -> dict[str, object]:
    (test,) = json.loads(result.output)["tests"]
    return test


def test_a_test_whose_expectations_are_all_timed_ends_at_the_last(tmp_path: Path) -> None:
    result = _mint_test(tmp_path, TIMED + "REM @expect OUT.0 = 0 at 600\n" + ENDLESS)
    test = _only_test(result)
    assert (result.exit_code, test["verdict"], test["stopped"], test["simulated_ms"]) == (0, "passed", "until", 1100)


def test_an_expectation_at_the_end_still_waits_for_the_program_to_end(tmp_path: Path) -> None:
    result = _mint_test(tmp_path, TIMED + "REM @expect count >= 1\n" + ENDLESS)
    test = _only_test(result)
    assert (result.exit_code, test["verdict"], test["stopped"]) == (1, "failed", "wall-limit")


def test_a_run_an_expectation_at_the_end_kept_going_says_which_and_what_ends_it(tmp_path: Path) -> None:
    """The wall-clock limit alone (60 s by default, each test) told nothing of why the program ran so long."""
    result = _mint_test(tmp_path, TIMED + "REM @expect count >= 1\n" + ENDLESS)
    test = _only_test(result)
    assert str(test["message"]).endswith(
        f" s of wall time; the program has not ended, and the expectation at {tmp_path / 'machine.mnt'}:2"
        " is checked at its end: give it a time, or set --until-ms"
    )


def test_until_ms_given_is_kept(tmp_path: Path) -> None:
    result = _mint_test(tmp_path, TIMED + ENDLESS, "--until-ms", "600")
    test = _only_test(result)
    assert (test["verdict"], test["stopped"], test["simulated_ms"]) == ("failed", "until", 600)


def test_a_test_of_a_machine_idle_at_its_last_check_ends_there(tmp_path: Path) -> None:
    result = _mint_test(tmp_path, "REM @expect count = 1 at 120\nREM @expect count = 2 at 300\n" + IDLE)
    test = _only_test(result)
    assert (result.exit_code, test["verdict"], test["stopped"], test["simulated_ms"]) == (0, "passed", "until", 300)


@pytest.mark.parametrize(("program", "count", "last"), [(ENDLESS, 4, 1100), (IDLE, 2, 300)])
def test_mint_run_expect_ends_at_the_last_check_and_says_so(
    tmp_path: Path, program: str, count: int, last: int
) -> None:
    machine = write(tmp_path, "machine.mnt", program)
    scenario = write(tmp_path, "checks.toml", f'[[expect]]\nwhat = "count"\nequals = {count}\nat_ms = {last}\n')
    result = mint_run(machine, "--expect", scenario, "--max-wall-s", "2")
    assert result.exit_code == 0
    assert f"every expectation was checked (the last at {last} ms)" in result.output


def test_a_machine_blocked_before_the_until_time_is_a_deadlock(tmp_path: Path) -> None:
    """--until-ms past the time it blocks for good: W-4 stops the run there (../shared/spec/runtime.md)."""
    result = mint_run(write(tmp_path, "machine.mnt", IDLE), "--until-ms", "1000", "--max-wall-s", "2")
    assert (result.exit_code, "deadlock after" in result.output) == (1, True)


def test_mint_run_without_expect_runs_on(tmp_path: Path) -> None:
    """A plain run is no test: the program's own timed checks do not end it."""
    program = write(tmp_path, "machine.mnt", TIMED + ENDLESS)
    result = mint_run(program, "--until-ms", "3000")
    assert "until after 3000 ms at program line 4: WAIT = 250 — reached --until-ms 3000" in result.output


def test_a_plain_run_past_its_last_check_says_what_ends_it(tmp_path: Path) -> None:
    """A plain run of a machine's main loop goes on to the wall-clock limit, its checks all done long before:
    the message says so, and what ends such a run there."""
    program = write(tmp_path, "machine.mnt", TIMED + ENDLESS)
    result = mint_run(program, "--max-wall-s", "0.5")
    assert result.exit_code == 1
    assert (
        "of wall time; every expectation was checked by 1100 ms, and a plain run goes on until the program "
        "ends: set --until-ms 1100, or run it as a test (mint test), which ends at the last check"
        in " ".join(result.output.split())
    )


def test_a_plain_run_stopped_before_its_last_check_says_nothing_of_it(tmp_path: Path) -> None:
    program = write(tmp_path, "machine.mnt", "REM @expect count = 4 at 100000000\n" + ENDLESS)
    result = mint_run(program, "--max-wall-s", "0.5")
    assert (result.exit_code, "every expectation was checked" in result.output) == (1, False)
